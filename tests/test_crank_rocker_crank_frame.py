"""``crank_rocker.design_by_K`` with the crank, the frame and the swing given (``K AB AD psi`` → BC, CD):
random crank-rockers designed back from their own K, AB, AD, ψ (all solutions listed, the original among
them), construction against the twin, the issue's example."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "crank_rocker.design_by_K"


def _solve(recipe=R, **given):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="t"))


@pytest.mark.parametrize("i", range(60))
def test_random_designs_come_back(i):
    rng = random.Random(14900 + i)
    while True:
        AB = rng.uniform(5, 60)
        BC, CD, AD = (rng.uniform(AB * 1.05, 300) for _ in range(3))
        s = sorted([BC, CD, AD])
        if AB + s[2] < s[0] + s[1] - 1e-3 * s[2]:
            break
    ex = _solve("crank_rocker.extremes", AB=AB, BC=BC, CD=CD, AD=AD).answers
    if ex["theta"] < 0.1:
        return
    sol = _solve(K=ex["K"], AB=AB, AD=AD, psi=ex["psi"])
    for row in sol.checks:
        assert row["ok"], row
    assert any(math.isclose(x["BC"], BC, rel_tol=1e-7) and math.isclose(x["CD"], CD, rel_tol=1e-7)
               for x in sol.solution_values)


def test_issue_example_has_two_designs():
    sol = _solve(K=10 / 9, AB=46.6717, AD=120, psi=80)
    got = sorted((round(x["BC"], 2), round(x["CD"], 2)) for x in sol.solution_values)
    assert got == [(98.95, 73.47), (116.16, 73.88)]
    assert all(r["ok"] for r in sol.checks)


def test_statement_form():
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    g = dict(K=1.25, AB=30, AD=120, psi=60)
    assert template_form(R, g) == "crank_frame"
    en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
    assert "AB = 30 mm" in en and "AD = 120 mm" in zh and "{" not in en + zh


@pytest.mark.parametrize("i", [88, 162])
def test_no_design_from_the_arc_that_sees_180_minus_theta(i):
    """The θ-circles' other arcs see C1C2 under 180° − θ: a root of the ratio there is a design of another K
    (88: θ = 122.7°, the extra design came back with K = 1.934 instead of 5.283), never listed."""
    test_random_designs_come_back(i)


@pytest.mark.xfail(strict=True, reason="known defect: the twin's grid in CD (4000 samples over 1e-3..100 frames) "
                   "misses a valid design whose CD window is narrower than one cell (seed 183: about 2e-3 of CD wide), "
                   "so the solver reports a failed 'number of solutions' check for a right construction")
@pytest.mark.parametrize("i", [183])
def test_known_twin_misses(i):
    test_random_designs_come_back(i)
