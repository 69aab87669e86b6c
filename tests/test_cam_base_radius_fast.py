"""cam.base_radius for arm followers on the scalar path (issue 10): the search over a (Newton steps on the
crossing of two parts' bounds, secants of the slope) ends where plain bisection ends, the twin's float bounds
are its array bounds, the floats' refinement of the arcs matches the arrays', and the twin agrees with the
construction on random problems."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from geomcon.cam import base_radius as br
from geomcon.cam.arm_twin import ArmTwin, bounds1, bounds_of
from geomcon.cam.oscillating import segment_motion
from geomcon.cam.program import parse_program
from geomcon.fuzz.valid_base_radius import GENERATORS

P4 = [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
      {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]


def _kw(g):
    return dict(alpha_allow=g["alpha_allow"], rotation=g.get("rotation", "ccw"), arm=g.get("arm", "left"),
                alpha_allow_return=g.get("alpha_allow_return"))


def _bisected(g):
    """best_distance's answer by plain bisection (the search before issue 10), for comparison."""
    prog = parse_program(g["program"])
    arm = br.ArmProgram(g["h"], prog, g.get("rotation", "ccw"), g.get("arm", "left"))
    lims = br.limits(prog, g["alpha_allow"], g.get("alpha_allow_return"))
    parts = br.arm_parts(arm, lims)
    a_min = br.arm_a_min(arm, g["L"], lims)
    a_f = br.admissible_distance(arm, g["L"], parts, a_min)

    def sign(x):
        b = br.arc_bounds(arm, g["L"], x, parts)
        return (-1.0 if x < a_f else 1.0) if not b.feasible else br.grad_r0(g["L"], b)

    lo, hi = a_min * (1.0 + 1e-12), a_f
    if sign(lo) >= 0:
        return lo
    while sign(hi) <= 0:
        lo, hi = hi, 2.0 * hi
    lo, hi = br.sign_change(sign, lo, hi)
    ends = [b for b in (br.arc_bounds(arm, g["L"], x, parts) for x in (lo, hi)) if b.feasible]
    return min(ends, key=lambda b: (b.a - g["L"]) ** 2 + 4.0 * b.a * g["L"] * math.sin(b.lo / 2) ** 2).a


@pytest.mark.parametrize("g", [
    {"L": 100.0, "h": 20.0, "program": P4, "alpha_allow": 35.0, "alpha_allow_return": 45.0},   # 200-12: a kink
    {"L": 100.0, "h": 20.0, "program": P4, "alpha_allow": 35.0},                                # one part
    {"L": 80.0, "h": 25.0, "program": P4, "alpha_allow": 40.0, "rotation": "cw", "arm": "right"},
])
def test_search_over_a_ends_where_bisection_ends(g):
    got = br.arm_best(parse_program(g["program"]), g["h"], g["L"], **_kw(g))["a"]
    assert abs(got - _bisected(g)) <= 1e-13 * got


def test_search_over_a_random_problems():
    rng = random.Random(10)
    for _ in range(6):
        g = GENERATORS["cam.base_radius.oscillating"](rng).problem["given"]
        g.pop("a", None)
        try:
            got = br.arm_best(parse_program(g["program"]), g["h"], g["L"], **_kw(g))["a"]
        except Exception:                                          # a refusal: the bisection refuses it too
            continue
        assert abs(got - _bisected(g)) <= 1e-12 * got


def test_arc_root_takes_few_steps_at_a_kink():
    calls = []

    def ev(x):
        calls.append(x)
        first = 1 - x / 4 >= x / 2 - 0.5
        each = (("rise", 0.0, 1 - x / 4, -0.25), ("return", 0.0, x / 2 - 0.5, 0.5))
        b = br.ArcBounds(x, max(1 - x / 4, x / 2 - 0.5), 9.0, "rise" if first else "return", 0.0,
                         -0.25 if first else 0.5, tuple((p, v, d) for p, _, v, d in each))
        return b.dlo_da, b

    lo, hi = br.arc_root(ev, 0.5, 8.0, ev(0.5), ev(8.0))
    assert lo <= 2.0 <= hi and math.nextafter(lo, math.inf) == hi
    assert len(calls) < 12


def test_twin_float_bounds_are_the_array_bounds():
    rng = np.random.default_rng(3)
    phi = rng.uniform(-4.0, 4.0, 400)
    c = rng.choice([-1.0, 1.0], 400) * rng.uniform(0.0, 100.0, 400)
    c[:20] = 0.0
    for t in (0.2, 1.0, 5.0):
        low, high = bounds_of(phi, t, c)
        for i in range(phi.size):
            assert bounds1(float(phi[i]), t, float(c[i])) == (float(low[i]), float(high[i]))


def test_arc_refinement_on_floats_matches_arrays():
    """stationary_max with the float forms gives the maximum the array forms give (to rounding)."""
    prog = parse_program(P4)
    arm = br.ArmProgram(20.0, prog)
    for p in br.arm_parts(arm, br.limits(prog, 35.0, 45.0)):
        g = lambda m: np.sin(3.0 * m.psi) + m.d1
        s = lambda m: 3.0 * np.cos(3.0 * m.psi) * m.d1 + m.d2
        g1 = lambda mo: math.sin(3.0 * mo[1]) + mo[2]
        s1 = lambda mo: 3.0 * math.cos(3.0 * mo[1]) * mo[2] + mo[3]
        v_arr, x_arr = br.stationary_max(p.seg, p.level, 20.0, g, s, grid=p.grid)
        v_flt, x_flt = br.stationary_max(p.seg, p.level, 20.0, g, s, grid=p.grid, g1=g1, slope1=s1)
        assert abs(v_arr - v_flt) <= 1e-14 * max(1.0, abs(v_arr)) and abs(x_arr - x_flt) <= 1e-9
        m = segment_motion(p.seg, p.level, 20.0, np.linspace(0.0, 1.0, 20001))
        assert v_flt >= float(np.max(g(m))) - 1e-12


def test_twin_agrees_with_the_construction_on_random_problems():
    rng = random.Random(2026)
    for _ in range(8):
        g = GENERATORS["cam.base_radius.oscillating"](rng).problem["given"]
        prog = parse_program(g["program"])
        con = br.arm_best(prog, g["h"], g["L"], a=g.get("a"), **_kw(g))
        twin = ArmTwin(prog, g["h"], g["L"], **_kw(g)).best(g.get("a"))
        for key in ("r0", "a", "psi0"):
            assert abs(con[key] - twin[key]) <= 1e-10 * max(abs(con[key]), g["L"] if key != "psi0" else 1.0)
