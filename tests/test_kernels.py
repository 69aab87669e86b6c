"""Issue 10: the float kernels of the taped replay are the step operations themselves (same bits, same refusals),
and a replay on kernels gives a solve's values and stats exactly as the object path does."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.geometry import Circle, Line, Point, Ray
from geomcon.geometry.branch import (Above, Below, FarthestFrom, LeftOf, Leftmost, NearestTo, OtherThan, RightOf,
                                     Rightmost, ToLeftOf, ToRightOf)
from geomcon.geometry.kernels import FIELDS, KERNELS, MAKERS, RULES, Fallback
from geomcon.problems import problem_from_dict
from geomcon.recipes import get_recipe
from geomcon.scene.tape import same_value
from geomcon.solve import solve
from geomcon.taped import construct_taped

rnd = random.Random(20261126)


def _num() -> float:
    k = rnd.random()
    if k < 0.7:
        return rnd.uniform(-300.0, 300.0)
    if k < 0.85:
        return rnd.uniform(-1.0, 1.0) * 10 ** rnd.uniform(-12, 12)
    return float(rnd.randint(-20, 20))


def _point() -> Point:
    return Point(_num(), _num())


def _value(kind: str):
    if kind == "P":
        return _point()
    if kind == "L":
        return Line(_point(), _point())
    if kind == "R":
        return Ray(_point(), _point())
    if kind == "C":
        return Circle(_point(), rnd.choice([rnd.uniform(0.01, 300.0), 10 ** rnd.uniform(-9, 9)]))
    return rnd.choice([_num(), rnd.uniform(-200.0, 200.0), 90.0, 1.0, -1.0])


def _flat(x, kind: str) -> list:
    if kind == "x":
        return [x]
    out = []
    for f in FIELDS[kind]:
        v = x
        for part in f.split(".")[1:]:
            v = getattr(v, part)
        out.append(v)
    return out


def _outcome(fn, *args) -> str:
    try:
        return repr(fn(*args))
    except Exception:
        return "raises"


def _kernel_outcome(kernel, out: str, args: list) -> str | None:
    """The kernel's value as the object form's repr, 'raises', or None when it leaves the case to the object."""
    try:
        r = kernel(*args)
    except Fallback:
        return None
    except Exception:
        return "raises"
    return repr(r if out == "x" else (MAKERS["T"](r) if out == "T" else MAKERS[out](*r)))


CASES = [(op, kinds, out, kernel) for op, ks in KERNELS.items() for kinds, out, kernel in ks]


@pytest.mark.parametrize("op,kinds,out,kernel", CASES, ids=[f"{getattr(c[0], '__name__', c[0])}-{c[1]}" for c in CASES])
def test_kernel_is_the_operation(op, kinds, out, kernel) -> None:
    """Random arguments (and near-degenerate ones: coincident points, a circle pair near tangency): whenever the
    kernel answers, its value is the object form's to the last bit; when the object form refuses, so does it."""
    n = 0
    for _ in range(1500):
        try:
            args = [_value(k) for k in kinds]
        except Exception:                        # a line through two equal points: no such argument
            continue
        if rnd.random() < 0.1 and kinds[:2] == "PP":
            args[1] = args[0]
        if kinds == "CC" and rnd.random() < 0.5:
            c1 = args[0]
            d, a = rnd.uniform(0.1, 2.0) * c1.r, rnd.uniform(0.0, 6.3)
            r2 = d + c1.r if rnd.random() < 0.5 else abs(d - c1.r) or 1.0
            args[1] = Circle(Point(c1.center.x + d * math.cos(a), c1.center.y + d * math.sin(a)),
                             r2 * (1 + rnd.choice([-1, 1]) * 10 ** rnd.uniform(-16, -9)))
        want = _outcome(op, *args)
        got = _kernel_outcome(kernel, out, [v for a, k in zip(args, kinds) for v in _flat(a, k)])
        if got is None:
            continue
        n += 1
        assert got == want, (op, args)
    assert n > 1000


RULE_CASES = [(Above, 2), (Below, 2), (LeftOf, 2), (RightOf, 2), (ToLeftOf, 1), (ToRightOf, 1), (NearestTo, 1),
              (FarthestFrom, 1), (OtherThan, 1), (Leftmost, 0), (Rightmost, 0)]


@pytest.mark.parametrize("cls,n", RULE_CASES, ids=[c[0].__name__ for c in RULE_CASES])
def test_rule_kernel_is_the_rule(cls, n) -> None:
    """A branch rule's kernel picks the rule's candidate, and refuses (a tie, a dividing line of zero length,
    a vertical line for above/below) where the rule does."""
    _, kernel = RULES[cls.rule]
    for _ in range(1500):
        p = _point()
        cands = rnd.choice([(p, _point()), (p,), (p, Point(p.x + 1e-15, p.y)), (p, Point(p.x, -p.y))])
        pts = [_point() if rnd.random() < 0.85 else p for _ in range(n)]
        if n == 2 and rnd.random() < 0.1:
            pts[1] = Point(pts[0].x, pts[0].y + 1.0)
        want = _outcome(lambda: cls(*pts).choose(cands))
        try:
            got = repr(MAKERS["P"](*kernel(tuple(v for c in cands for v in (c.x, c.y)),
                                           *[v for q in pts for v in (q.x, q.y)])))
        except Exception:
            got = "raises"
        assert got == want, (cls, cands, pts)


@pytest.mark.parametrize("recipe,variant", [
    ("crank_slider.design_by_K", lambda: {"K": rnd.uniform(1.01, 2.5), "H": rnd.uniform(10.0, 400.0),
                                          "e": rnd.uniform(0.0, 1.0)}),
    ("crank_rocker.design_by_K", lambda: {"K": rnd.uniform(1.01, 1.8), "CD": rnd.uniform(50.0, 400.0),
                                          "psi": rnd.uniform(15.0, 70.0), "BC": rnd.uniform(50.0, 600.0)}),
    ("crank_rocker.extremes", lambda: {"AB": rnd.uniform(10.0, 60.0), "BC": rnd.uniform(60.0, 120.0),
                                       "CD": rnd.uniform(60.0, 120.0), "AD": rnd.uniform(60.0, 120.0)}),
])
def test_replay_on_kernels_is_the_scene(recipe, variant) -> None:
    """Replayed on kernels (the compiled plan), every step of a taped construction has the value the lean scene
    computes step by step on objects, to the last bit, and a solve's stats do not change; a variant that one
    refuses, both refuse."""
    r = get_recipe(recipe)
    for _ in range(40):
        g = {k: float(v) for k, v in variant().items()}
        if recipe == "crank_slider.design_by_K":
            from geomcon.recipes.crank_slider_design import feasible_range
            lo, hi = feasible_range(g["K"], g["H"], "e")
            g["e"] = lo + g["e"] * (hi - lo) * 0.999
        try:
            p = problem_from_dict({"recipe": recipe, "given": g}, name="kernels")
        except Exception:
            continue
        for _ in range(3):                                   # learn the plan, record the tape
            try:
                solve(p).answers
            except Exception:
                break
        c = construct_taped(r, p.given)
        keys = tuple(k for k in c.scene._rec if k[:1] != "§")
        try:
            replayed = c.scene.evaluate(keys)                # the compiled plan, on kernels
        except Exception:
            replayed = None
        from geomcon.plan import planned
        ref = planned(r.name, r.construct, p.given).scene
        try:
            want = ref.evaluate(keys)
        except Exception:
            want = None
        assert (replayed is None) == (want is None)
        if want is not None:
            assert all(same_value(want[k], replayed[k]) for k in keys)
            assert c.scene.stats["steps_evaluated"] >= len(keys)


@pytest.mark.parametrize("recipe,given,key", [
    ("crank_slider.design_by_K", {"K": 1.5, "H": 50.0, "e": 20.0}, "AB"),
    ("crank_rocker.design_by_K", {"K": 1.25, "CD": 290.0, "psi": 32.0, "BC": 260.0}, "AB_1"),
    ("crank_slider.extremes", {"AB": 120.0, "BC": 250.0, "e": 60.0}, "H"),
])
def test_objects_made_when_read(recipe, given, key) -> None:
    """A replay asked for one answer leaves the other steps' objects unmade; when the scene is read further
    they are stored, in the plan's order, with the values of the step-by-step path on objects."""
    r = get_recipe(recipe)
    for _ in range(3):
        construct_taped(r, given).scene.evaluate((key,))
    sc = construct_taped(r, given).scene
    got = sc.evaluate((key,))[key]
    assert sc._pending is not None and key in sc._memo          # the rest not stored yet
    assert sc.is_evaluated(key) and sc._pending is None          # a read of the memo settles it
    from geomcon.plan import planned
    ref = planned(r.name, r.construct, given).scene
    assert same_value(ref.evaluate((key,))[key], got)
    mine = [(k, v) for k, v in sc._memo.items() if k[:1] != "§"]
    assert [k for k, _ in mine] == list(ref._memo)
    assert all(same_value(ref._memo[k], v) for k, v in mine)
