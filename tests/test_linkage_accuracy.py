"""Accuracy of the linkage constructions where the issue-9 study found real inaccuracies: each case is
compared with a 40-digit reference (mpmath) computed by its own route, to ~1e-9 relative or better."""
from __future__ import annotations

import math

import mpmath
import pytest

from geomcon.geometry import Circle, Point, circle_circle
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

mpmath.mp.dps = 40


def _solve(recipe: str, **given):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="t"))


@pytest.mark.parametrize("r1, R", [(1e-6, 1e3), (1e-6, 1e4), (3e-3, 2.9e6), (1.0, 1e9)])
def test_a_tiny_circle_on_a_large_one_keeps_its_relative_accuracy(r1, R):
    # the tiny circle about A = (0, 0) meets the circle through A about (0, −R): the points lie r1²/(2R)
    # below A, a distance the old a = (d + (r1 − r2)(r1 + r2)/d)/2 lost entirely (ε·R ≫ r1²/R)
    p, q = circle_circle(Circle(Point(0, 0), r1), Circle(Point(0, -R), R))
    y = -mpmath.mpf(r1) ** 2 / (2 * R)
    x = mpmath.sqrt(mpmath.mpf(r1) ** 2 - y * y)
    for pt, sx in ((p, 1), (q, -1)):            # left of the centre line downwards first: +x
        assert abs(pt.y - y) <= 4e-16 * abs(y)
        assert abs(pt.x - sx * x) <= 4e-16 * x


@pytest.mark.parametrize("AB, AC", [(1e-6, 1e3), (1e-6, 1e4), (1e-6, 47.4), (0.0029337, 2927550.03)])
def test_guide_bar_with_a_tiny_crank(AB, AC):
    sol = _solve("guide_bar.extremes", AB=AB, AC=AC)
    exact = float(2 * mpmath.degrees(mpmath.asin(mpmath.mpf(AB) / AC)))
    assert sol.ok
    for name in ("theta", "psi"):
        assert sol.answers[name] == pytest.approx(exact, rel=1e-12)
