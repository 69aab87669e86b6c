"""Regression tests for defects the hostile fuzz found in the linkage designs: a subnormal rocker angle
(excess_by_foot divided by |PQ|² underflowing to 0) and crank_rocker.design_by_K's frame form at K = 1 (the line
AC1 meeting the rocker circle at C1 itself gave a crank of length 0 whose C1_folded was a coin toss)."""
from __future__ import annotations

import math

import mpmath
import pytest

from geomcon.errors import GeomconError
from geomcon.geometry import Point
from geomcon.problems import problem_from_dict
from geomcon.recipes.common import excess_by_foot
from geomcon.solve import solve


def _solve(recipe: str, given: dict):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="test"))


@pytest.mark.parametrize("d", [1e-100, 1e-200, 1e-300, 5e-324])
def test_excess_by_foot_with_p_and_q_a_subnormal_distance_apart(d):
    """|VP| + |VQ| − |PQ| with |PQ| so small that |PQ|² underflows: no division by zero, and the value is the
    plain sum (the foot of V lies outside PQ: the excess is |VP| + |VQ| − |PQ| ≈ 2|VP|)."""
    V, P, Q = Point(0.0, 500.0), Point(500.0, 0.0), Point(500.0, -d)
    assert excess_by_foot(V, P, Q) == pytest.approx(2 * math.hypot(500.0, 500.0), rel=1e-15)
    # V right above the middle of a tiny PQ: h²/(|VP| + |PF|) twice, |PF| = d/2
    V = Point(500.0, -d / 2 + 0.0) + Point(1.0, 0.0)
    with mpmath.workdps(40):
        exact = 2 * mpmath.sqrt(1 + (mpmath.mpf(d) / 2) ** 2) - mpmath.mpf(d)
    assert excess_by_foot(V, P, Q) == pytest.approx(float(exact), rel=1e-15)


@pytest.mark.parametrize("phi2", [-1e-300, 1e-300, -1e-200, 0.0, -1e-100])
def test_frame_line_design_with_a_subnormal_rocker_angle_is_refused_not_crashed(phi2):
    """C2 within 1e-300 of the frame line (and of the candidate A): no valid design, as for phi2 = 0 — a refusal
    naming the rule, never an internal error."""
    given = dict(K=1.4, CD=500, phi1=90, phi2=phi2, frame_line=True)
    with pytest.raises(GeomconError, match="no valid crank-rocker"):
        _solve("crank_rocker.design_by_K", given).answers


def _mp_frame_k1(AD: float, CD: float, phi: float) -> tuple[float, float, float]:
    """(AB, ψ, AC1 < AC2) of the frame form at K = 1 at 40 digits: C2 the second meeting of the line AC1 with
    the rocker circle, |AC2| = (AD² − CD²)/|AC1|."""
    with mpmath.workdps(40):
        AD, CD, p = mpmath.mpf(AD), mpmath.mpf(CD), mpmath.radians(mpmath.mpf(phi))
        c1 = mpmath.matrix([AD - CD * mpmath.cos(p), CD * mpmath.sin(p)])
        w1 = mpmath.norm(c1)
        w2 = (AD - CD) * (AD + CD) / w1
        c2 = c1 * (w2 / w1)
        d = mpmath.matrix([AD, 0])
        u, v = c1 - d, c2 - d
        psi = mpmath.degrees(mpmath.acos((u[0] * v[0] + u[1] * v[1]) / (mpmath.norm(u) * mpmath.norm(v))))
        return float(abs(w2 - w1) / 2), float(psi), float(w1 < w2)


@pytest.mark.parametrize("AD,CD,phi", [(120, 85, 45), (120, 85, 60), (100, 99, 30), (1e6, 3e5, 80), (0.012, 0.0085, 45)])
def test_frame_form_at_K_1_has_one_design_per_line(AD, CD, phi):
    """K = 1 with the frame given: the only candidate is the line AC1's second meeting with the rocker circle;
    both routes agree on every answer, C1_folded included, and AB is not 0."""
    sol = _solve("crank_rocker.design_by_K", dict(K=1, CD=CD, AD=AD, phi=phi))
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    AB, psi, folded = _mp_frame_k1(AD, CD, phi)
    assert len(sol.analytic) == 1
    for values in (sol.answers, sol.analytic[0]):
        assert values["AB"] == pytest.approx(AB, rel=1e-9)
        assert values["psi"] == pytest.approx(psi, rel=1e-9)
        assert values["C1_folded"] == folded
        assert values["A_near"] == 1.0


@pytest.mark.parametrize("recipe,given", [("slotter.design_by_K", dict(K=1.5, H=154, B1B2=308)),
                                          ("shaper.design_by_K", dict(K=2, H=300, AB=75))])
def test_alpha_allow_below_its_documented_minimum_is_refused(recipe, given):
    """alpha_allow = 5e-324 (subnormal: sin α = 0, DE a division by zero) is refused naming the limit; just
    above the limit DE = x / sin α is 1e10·x at most and both routes agree."""
    from geomcon.recipes.common import ALPHA_ALLOW_MIN

    for alpha in (5e-324, 1e-300, ALPHA_ALLOW_MIN / 2):
        with pytest.raises(GeomconError, match="below 5.72958e-09"):
            _solve(recipe, {**given, "alpha_allow": alpha}).answers
    sol = _solve(recipe, {**given, "alpha_allow": ALPHA_ALLOW_MIN * 1.01})
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    assert sol.answers["DE"] == pytest.approx(sol.analytic[0]["DE"], rel=1e-9)
