"""``crank_rocker.design_by_K`` with the rocker, its swing and the frame given (``K CD psi AD`` → AB, BC):
A on the θ-circles and the circle of radius AD about D; construction against the closed-form twin
(:mod:`geomcon.analytic.design_by_k_frame`) on random designs, every solution listed, back-substitution."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.design_by_k_frame import frame_points
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "crank_rocker.design_by_K"


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


def _random_crank_rocker(rng):
    while True:
        AB = rng.uniform(5, 60)
        BC, CD, AD = (rng.uniform(AB * 1.05, 300) for _ in range(3))
        s = sorted([BC, CD, AD])
        if AB + s[2] < s[0] + s[1] - 1e-3 * s[2]:
            return AB, BC, CD, AD


@pytest.mark.parametrize("i", range(40))
def test_random_designs_come_back(i):
    rng = random.Random(14600 + i)
    AB, BC, CD, AD = _random_crank_rocker(rng)
    ex = solve(problem_from_dict({"recipe": "crank_rocker.extremes",
                                  "given": dict(AB=AB, BC=BC, CD=CD, AD=AD)}, name="t")).answers
    if ex["theta"] < 0.1:
        return
    given = dict(K=ex["K"], CD=CD, psi=ex["psi"], AD=AD)
    sol = _solve(**given)
    for row in sol.checks:
        assert row["ok"], row
    assert any(math.isclose(s["AB"], AB, rel_tol=1e-7) and math.isclose(s["BC"], BC, rel_tol=1e-7)
               for s in sol.solution_values), (AB, BC, sol.solution_values)


def test_frame_points_see_the_chord_under_theta():
    rng = random.Random(7)
    for _ in range(200):
        c = rng.uniform(10, 100)
        a1, a2 = rng.uniform(0, 360), rng.uniform(0, 360)
        c1 = (c * math.cos(math.radians(a1)), c * math.sin(math.radians(a1)))
        c2 = (c * math.cos(math.radians(a2)), c * math.sin(math.radians(a2)))
        th, AD = math.radians(rng.uniform(1, 170)), rng.uniform(5, 300)
        for ax, ay in frame_points(c1, c2, th, AD):
            assert math.hypot(ax, ay) == pytest.approx(AD, rel=1e-9)
            u, v = (c1[0] - ax, c1[1] - ay), (c2[0] - ax, c2[1] - ay)
            seen = math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1])
            assert seen == pytest.approx(th, abs=1e-9)


def test_issue_example_design():
    a = _solve(K=10 / 9, CD=73.88, psi=80, AD=120).answers
    assert a["AB"] == pytest.approx(46.67, abs=5e-3) and a["BC"] == pytest.approx(116.16, abs=5e-3)
    assert a["gamma_min"] == pytest.approx(37.73, abs=5e-3)


def test_statement_form_psi_ad():
    from geomcon.worksheet.statements import template_form
    assert template_form(R, dict(K=1.4, CD=75, psi=45, AD=100)) == "psi+AD"
