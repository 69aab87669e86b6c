"""Issue 10: crank_rocker.grashof, run by every crank-rocker solve, is written on its four numbers by position
for speed; it refuses, warns and words exactly as the dictionary form it replaced (kept here as the reference),
over random lengths with many ties (small integers), floats, and the boundary cases."""
from __future__ import annotations

import random

from geomcon.errors import NotAMechanism
from geomcon.recipes.crank_rocker import grashof
from geomcon.tolerance import is_zero


def _reference(AB: float, BC: float, CD: float, AD: float) -> list[str]:
    lengths = {"AB": AB, "BC": BC, "CD": CD, "AD": AD}
    longest = max(lengths, key=lambda k: lengths[k])
    rest = sum(lengths.values()) - lengths[longest]
    if lengths[longest] >= rest:
        raise NotAMechanism(f"the links cannot be assembled: {longest} = {lengths[longest]:g} ≥ sum of the "
                            f"other three = {rest:g}")
    names = sorted(lengths, key=lambda k: lengths[k])
    sn, pn, qn, ln = names
    s, p, q, l_ = (lengths[n] for n in names)
    if s + l_ > p + q and not is_zero(s + l_ - (p + q), p + q):
        raise NotAMechanism(
            f"AB is not a crank (Grashof): {sn} + {ln} > {pn} + {qn} ({s:g} + {l_:g} > "
            f"{p:g} + {q:g}, {s + l_:g} > {p + q:g}): no link turns fully")
    if AB > min(BC, CD, AD) or AB == AD:
        raise NotAMechanism(
            f"AB = {AB:g} is not the strictly shortest link adjacent to the frame (BC = {BC:g}, CD = {CD:g}, "
            f"AD = {AD:g}): no crank-rocker with crank AB")
    if longest == "AB":
        longest = "BC"
    others = [k for k in ("BC", "CD", "AD") if k != longest]
    s_l = AB + lengths[longest]
    p_q = lengths[others[0]] + lengths[others[1]]
    if AB == BC:
        raise NotAMechanism(f"BC = AB = {AB:g}: the folded position puts C1 on A, θ is undefined")
    if is_zero(s_l - p_q, p_q):
        return [f"Grashof equality AB + {longest} = {others[0]} + {others[1]} = {p_q:g}: a change-point "
                "linkage (links can all be collinear, γmin = 0)"]
    return []


def _outcome(fn, *args) -> str:
    try:
        return repr(fn(*args))
    except NotAMechanism as exc:
        return "refused: " + str(exc)


def test_grashof_is_the_reference() -> None:
    rnd = random.Random(20261127)
    kinds = {"ok": 0, "warn": 0, "refused": 0}
    for i in range(40_000):
        u = i % 4
        if u == 0:
            args = [rnd.randint(1, 9) for _ in range(4)]                    # ties everywhere
        elif u == 1:
            args = [float(rnd.randint(1, 12)) * 5.0 for _ in range(4)]
        elif u == 2:
            args = [rnd.uniform(10.0, 120.0) for _ in range(4)]
        else:                                                              # on the Grashof boundary
            a, b, c = (rnd.uniform(10.0, 120.0) for _ in range(3))
            args = [a, b, c, a + b - c] if rnd.random() < 0.5 else [a, b, c, (a + b - c) * (1 + 1e-14)]
        got, want = _outcome(grashof, *args), _outcome(_reference, *args)
        assert got == want, args
        kinds["refused" if want.startswith("refused") else "warn" if want != "[]" else "ok"] += 1
    assert min(kinds.values()) > 500, kinds
