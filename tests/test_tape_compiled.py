"""Issue 10: a tape's own steps as one compiled function, and a compiled plan's steps of constants computed when
it is compiled, give exactly what the step-by-step forms give (by repr), on every bundled linkage problem's tape
and on random variants of its givens; a kernel marked pure reads no tolerance."""
from __future__ import annotations

import math
import random
from pathlib import Path

import pytest

from geomcon import tolerance
from geomcon.geometry.kernels import KERNELS, PURE
from geomcon.problems import load_problem
from geomcon.scene import compiled
from geomcon.scene.compiled import compile_plan
from geomcon.scene.tape import same_value
from geomcon.solve import solve
from geomcon.taped import _TAPES

from test_kernels import _flat, _value

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"
rnd = random.Random(20261127)


def _tapes() -> list:
    """Every tape recorded while solving the bundled problems that are not cams (three solves each: the plan
    learned, the tape recorded, then replayed)."""
    for path in sorted(PROBLEMS.glob("*.toml")):
        p = load_problem(path)
        if p.recipe.startswith("cam."):
            continue
        for _ in range(3):
            try:
                solve(p).answers
            except Exception:
                break
    return [(key, t) for key, entries in list(_TAPES.items()) for t, _, _ in entries if t is not None]


TAPES = _tapes()


def _variants(given: dict, n: int) -> list[dict]:
    """``given`` with each float moved by up to ±30 % (and sometimes negated or zeroed: the arithmetic and the
    guards must fail alike)."""
    out = []
    for _ in range(n):
        g = {}
        for k, v in given.items():
            if type(v) is float:
                u = rnd.random()
                v = -v if u < 0.05 else 0.0 if u < 0.08 else v * rnd.uniform(0.7, 1.3)
            g[k] = v
        out.append(g)
    return out


def _outcome(fn, *args) -> str:
    try:
        return repr(fn(*args))
    except Exception as exc:
        return type(exc).__name__


def test_tapes_found() -> None:
    assert len(TAPES) >= 20


def test_compiled_values_are_stepwise() -> None:
    """``Tape.values`` (compiled) and ``Tape.values_stepwise`` give the same memo, keys in the same order, or
    both None, or both raise."""
    n = 0
    for key, tape in TAPES:
        base = {name: 1.0 for name in tape.leaves}
        for g in _variants(base, 30) + [{}]:
            got, want = _outcome(tape.values, g), _outcome(tape.values_stepwise, g)
            assert got == want, (key, g)
            n += got != "None"
    assert n > 100


@pytest.mark.parametrize("kernel,kinds,out", [(k, kinds, out) for ks in KERNELS.values() for kinds, out, k in ks
                                              if k in PURE], ids=lambda x: getattr(x, "__name__", str(x)))
def test_pure_kernel_reads_no_tolerance(kernel, kinds, out, monkeypatch) -> None:
    """A pure kernel (folded into a compiled plan when its arguments are constants) gives the same outcome
    whatever the tolerance: circle_circle, line_circle or the circumcircle marked pure would fail here."""
    cases = []
    for _ in range(400):
        try:
            args = [v for k in kinds for v in _flat(_value(k), k)]
        except Exception:
            continue
        if rnd.random() < 0.2 and len(args) >= 4:          # near-degenerate: the second point near the first
            args[2], args[3] = args[0] * (1 + 1e-10), args[1] - 1e-10
        cases.append(args)
    before = [_outcome(kernel, *a) for a in cases]
    monkeypatch.setattr(tolerance, "REL_TOL", 0.3)
    assert [_outcome(kernel, *a) for a in cases] == before


def test_folded_plan_is_the_unfolded_plan(monkeypatch) -> None:
    """Every tape's compiled plan of all its steps, with the steps of constants folded and without (no kernel
    pure), stores the same values in the same order on random variants, or both raise."""
    folded_any = 0
    for key, tape in TAPES:
        keys = tuple(k for k in tape.rec if k[:1] != "§")
        run = compile_plan(tape.rec, keys, tape.inputs)
        with monkeypatch.context() as m:
            m.setattr(compiled, "PURE", frozenset())
            plain = compile_plan(tape.rec, keys, tape.inputs)
        if run is None:
            assert plain is None
            continue
        folded_any += run.__globals__.keys() != plain.__globals__.keys()
        given = {name: 1.0 for name in tape.leaves}
        for g in _variants(given, 10):
            memo = tape.values(g)
            if memo is None:
                continue
            memos = [dict(memo), dict(memo)]
            outs = []
            for fn, mm in zip((run, plain), memos):
                try:
                    pending = fn(mm)
                    if pending is not None:
                        pending[0](mm, pending[1])
                    outs.append([(k, repr(v)) for k, v in mm.items()])
                except Exception as exc:
                    outs.append(type(exc).__name__)
            assert outs[0] == outs[1], key
    assert folded_any >= 3


def test_fold_keeps_a_failing_constant_step() -> None:
    """A pure step of constants that raises is not folded: the plan raises at every replay, as before."""
    from geomcon.geometry import Point
    from geomcon.geometry.construct import line_through
    from geomcon.scene.step import Ref
    rec = {"a": (line_through, (Point(1.0, 2.0), Point(1.0, 2.0)), {}, 0, None, (), False, [], None),
           "b": (math.hypot, (Ref("a"), 1.0), {}, 1, None, (), False, ["a"], None)}
    run = compile_plan(rec, ("a",), frozenset())
    with pytest.raises(Exception, match="coincident"):
        run({})


@pytest.mark.parametrize("recipe,given,key", [
    ("crank_slider.design_by_K", {"K": 1.5, "H": 50.0, "e": 20.0}, "AB"),
    ("crank_rocker.extremes", {"AB": 50.0, "BC": 70.0, "CD": 80.0, "AD": 90.0}, "theta"),
])
def test_settle_computes_under_the_runs_tolerance(recipe, given, key, monkeypatch) -> None:
    """A replay's other steps are computed again when its memo is read further, under the tolerance of the run
    that computed the answers: a tolerance changed in between does not reach them (and is set back after)."""
    from geomcon.recipes import get_recipe
    from geomcon.taped import construct_taped
    r = get_recipe(recipe)
    for _ in range(3):
        construct_taped(r, given).scene.evaluate((key,))
    calm, moved = construct_taped(r, given).scene, construct_taped(r, given).scene
    calm.evaluate((key,))
    moved.evaluate((key,))
    assert calm._pending is not None and moved._pending is not None
    calm.settle()
    monkeypatch.setattr(tolerance, "REL_TOL", 0.5)
    moved.settle()
    assert tolerance.REL_TOL == 0.5
    assert [(k, repr(v)) for k, v in moved._memo.items()] == [(k, repr(v)) for k, v in calm._memo.items()]


def test_split_rules_are_their_kernels() -> None:
    """A rule split in two for a compiled plan (its set-up made once for several steps, SPLIT) chooses what its
    kernel chooses, and refuses where it refuses (a vertical or zero-length line, a tie), over random
    candidates and lines."""
    from geomcon.geometry.kernels import RULES, SPLIT
    n = 0
    for rule, (prep, choose, keep) in SPLIT.items():
        kernel = RULES[rule][1]
        for _ in range(3000):
            pts = [rnd.uniform(-100, 100) for _ in range(4)]
            u = rnd.random()
            if u < 0.1:
                pts[2] = pts[0]                                   # a vertical line
            elif u < 0.15:
                pts[2:] = pts[:2]                                 # a line of zero length
            x, y = rnd.uniform(-100, 100), rnd.uniform(-100, 100)
            c = rnd.choice([(x, y), (x, y, rnd.uniform(-100, 100), rnd.uniform(-100, 100)), (x, y, x, y),
                            (x, y, x + 1e-13, y)])

            def split(c=c, pts=pts):
                return choose(c, *pts[:keep], *prep(*pts))
            assert _outcome(split) == _outcome(kernel, c, *pts)
            n += 1
    assert n == 3000 * len(SPLIT)
