"""``four_bar.kinematics``: the velocity and acceleration polygons against the complex-loop twin, on random
instances in both assemblies and every quadrant of the crank, with and without crank acceleration and a coupler
point; the refusals at a dead point; the drawing carries the polygons."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.kinematics import four_bar
from geomcon.errors import GeomconError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

NAMES = ("omega2", "omega3", "epsilon2", "epsilon3", "vC", "aC")


def _given(rng: random.Random, branch: str) -> dict:
    while True:
        AB, BC, CD, AD = (rng.uniform(10, 200) for _ in range(4))
        phi = rng.uniform(-180, 360)
        bx, by = AB * math.cos(math.radians(phi)), AB * math.sin(math.radians(phi))
        d = math.hypot(AD - bx, by)
        if abs(BC - CD) + 0.05 * d < d < BC + CD - 0.05 * d:
            g = {"AB": AB, "BC": BC, "CD": CD, "AD": AD, "phi": phi, "omega": rng.choice((-1, 1)) * rng.uniform(0.5, 50),
                 "branch": branch}
            if rng.random() < 0.6:
                g["epsilon"] = rng.uniform(-200, 200)
            if rng.random() < 0.6:
                g["BE"], g["angle_CBE"] = rng.uniform(5, 150), rng.uniform(-180, 180)
            return g


@pytest.mark.parametrize("seed", range(30))
@pytest.mark.parametrize("branch", ["above", "below"])
def test_polygons_agree_with_the_twin(seed, branch):
    g = _given(random.Random(seed), branch)
    sol = solve(problem_from_dict({"recipe": "four_bar.kinematics", "given": g}, name="t"))
    got = sol.answers
    exact = four_bar(g["AB"], g["BC"], g["CD"], g["AD"], g["phi"], g["omega"], g.get("epsilon", 0.0),
                     branch=branch, BE=g.get("BE"), angle_CBE=g.get("angle_CBE", 0.0))
    w, e = abs(g["omega"]), g.get("epsilon", 0.0)
    scale = {"omega2": w, "omega3": w, "epsilon2": w * w + abs(e), "epsilon3": w * w + abs(e),
             "vC": w * g["AB"], "aC": (w * w + abs(e)) * g["AB"]}
    lever = 1 + g["AB"] / min(g["BC"], g["CD"])          # the polygons magnify errors near a dead point (seen: 1.3e-14 of scale)
    for n in NAMES:
        assert abs(got[n] - exact[n]) <= 1e-9 * scale[n] * lever, (n, got[n], exact[n])
    if "BE" in g:
        assert math.isclose(got["vE"], exact["vE"], rel_tol=1e-9, abs_tol=1e-9 * scale["vC"] * lever)
        assert math.isclose(got["aE"], exact["aE"], rel_tol=1e-9, abs_tol=1e-9 * scale["aC"] * lever)
    else:
        assert "vE" not in got and "aE" not in got
    assert sol.ok, [r for r in sol.checks if not r["ok"]]


def test_bundled_problem_and_its_drawing():
    from geomcon.problems import load_problem
    sol = solve(load_problem("problems/400-01_four_bar_velocity_polygons.toml"))
    a = sol.answers
    assert sol.ok
    assert math.isclose(a["omega2"], -4.484900843303192, rel_tol=1e-12)
    assert math.isclose(a["omega3"], 3.3724399841045614, rel_tol=1e-12)
    svg = sol.svg()
    # the polygons' sides are drawn with arrowheads, and the poles are labelled
    assert svg.count("<polygon") >= 10 or svg.count("Z") >= 10
    for label in (">p<", ">c<", ">c′<", ">n", ">e′<"):
        assert label in svg, label
    frames = sol.frames()
    assert len(frames) == len(sol.drawing_scene.frames())


@pytest.mark.parametrize("g, words", [
    ({"AB": 50, "BC": 20, "CD": 15, "AD": 90, "phi": 0, "omega": 1}, "BD = 40 is outside"),
    ({"AB": 50, "BC": 70, "CD": 80, "AD": 90, "phi": 60, "omega": 0}, "omega = 0"),
])
def test_refusals(g, words):
    with pytest.raises(GeomconError, match=words):
        solve(problem_from_dict({"recipe": "four_bar.kinematics", "given": g}, name="t"))
