"""Instant centres by Kennedy's theorem against the velocities of the vector loop: P13, P24 and the ratios, on
random instances in both assemblies and every quadrant; the crank-slider's P34 at infinity; centres at infinity
of a parallelogram refused with their meaning."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.errors import GeomconError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve


def _solve(recipe: str, g: dict):
    return solve(problem_from_dict({"recipe": recipe, "given": g}, name="t"))


def _close(a, b, scale, rel=1e-9):
    if isinstance(a, tuple):
        return all(abs(x - y) <= rel * scale for x, y in zip(a, b))
    return abs(a - b) <= rel * scale


@pytest.mark.parametrize("seed", range(30))
@pytest.mark.parametrize("branch", ["above", "below"])
def test_four_bar_centres(seed, branch):
    rng = random.Random(seed)
    while True:
        AB, BC, CD, AD = (rng.uniform(10, 200) for _ in range(4))
        phi = rng.uniform(-180, 360)
        bx, by = AB * math.cos(math.radians(phi)), AB * math.sin(math.radians(phi))
        d = math.hypot(AD - bx, by)
        if abs(BC - CD) + 0.05 * d < d < BC + CD - 0.05 * d:
            break
    g = {"AB": AB, "BC": BC, "CD": CD, "AD": AD, "phi": phi, "branch": branch}
    try:
        sol = _solve("four_bar.instant_centres", g)
        got, exact = sol.answers, sol.analytic[0]
    except GeomconError as exc:                  # a centre near infinity: refused, never a wrong number
        assert "infinity" in str(exc) or "infinite" in str(exc)
        return
    # a centre far away is ill-conditioned in its position: compare at its own distance
    for n in ("P13", "P24"):
        far = max(AD, math.hypot(*got[n]))
        assert _close(got[n], exact[n], far * far / AD), (n, got[n], exact[n])
    for n in ("w3_w1", "w2_w1"):
        assert _close(got[n], exact[n], 1.0 + abs(exact[n])), (n, got[n], exact[n])
    # the same ratios as the velocity polygons of four_bar.kinematics at ω = 1
    kin = _solve("four_bar.kinematics", {**g, "omega": 1.0}).answers
    assert _close(got["w3_w1"], kin["omega3"], 1.0 + abs(kin["omega3"]))
    assert _close(got["w2_w1"], kin["omega2"], 1.0 + abs(kin["omega2"]))
    assert sol.ok


@pytest.mark.parametrize("seed", range(30))
def test_crank_slider_centres(seed):
    rng = random.Random(700 + seed)
    while True:
        g = {"AB": rng.uniform(10, 100), "BC": rng.uniform(50, 300), "e": rng.uniform(-40, 40), "phi": rng.uniform(-180, 360)}
        if abs(g["AB"] * math.sin(math.radians(g["phi"])) + g["e"]) < 0.9 * g["BC"] and \
                abs(math.cos(math.radians(g["phi"]))) > 0.05:
            break
    sol = _solve("crank_slider.instant_centres", g)
    got = sol.answers
    kin = _solve("crank_slider.kinematics", {**g, "omega": 1.0}).answers
    assert _close(got["vC_w1"], kin["vC"], g["AB"] + abs(kin["vC"]))
    assert _close(got["w2_w1"], kin["omega2"], 1.0 + abs(kin["omega2"]))
    assert got["P13"][0] == pytest.approx(0.0, abs=1e-9 * g["BC"])     # on the perpendicular through A
    assert sol.ok


def test_parallelogram_puts_a_centre_at_infinity():
    """The open parallelogram has BC ∥ AD (and AB ∥ CD): P13 at infinity, refused with what it means."""
    g = {"AB": 50, "BC": 90, "CD": 50, "AD": 90, "phi": 60}
    words = set()
    for branch in ("above", "below"):
        try:
            _solve("four_bar.instant_centres", {**g, "branch": branch}).answers
        except GeomconError as exc:
            words.add(str(exc))
    assert any("P13 lies at infinity" in w and "the crank's rate" in w for w in words), words
