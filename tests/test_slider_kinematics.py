"""``crank_slider.kinematics`` and ``guide_bar.kinematics``: the polygons (the guide-bar's with its Coriolis
component) against the complex-loop twins on random instances in every quadrant of the crank, both senses of ω,
with and without crank acceleration; refusals at a dead point."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.kinematics import crank_slider, guide_bar
from geomcon.errors import GeomconError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve


def _solve(recipe: str, g: dict):
    return solve(problem_from_dict({"recipe": recipe, "given": g}, name="t"))


def _motion(rng: random.Random, g: dict) -> dict:
    g["phi"] = rng.uniform(-180, 360)
    g["omega"] = rng.choice((-1, 1)) * rng.uniform(0.5, 50)
    if rng.random() < 0.6:
        g["epsilon"] = rng.uniform(-200, 200)
    return g


@pytest.mark.parametrize("seed", range(40))
def test_crank_slider_polygons_agree_with_the_twin(seed):
    rng = random.Random(seed)
    while True:
        g = _motion(rng, {"AB": rng.uniform(10, 100), "BC": rng.uniform(50, 300), "e": rng.uniform(-40, 40)})
        if abs(g["AB"] * math.sin(math.radians(g["phi"])) + g["e"]) < 0.9 * g["BC"]:
            break
    sol = _solve("crank_slider.kinematics", g)
    got = sol.answers
    ex = crank_slider(g["AB"], g["BC"], g["e"], g["phi"], g["omega"], g.get("epsilon", 0.0))
    w, e = abs(g["omega"]), abs(g.get("epsilon", 0.0))
    lever = 1 + g["AB"] / g["BC"]
    for n, scale in (("omega2", w), ("epsilon2", w * w + e), ("vC", w * g["AB"]), ("aC", (w * w + e) * g["AB"])):
        assert abs(got[n] - ex[n]) <= 1e-9 * scale * lever, (n, got[n], ex[n])
    assert sol.ok


@pytest.mark.parametrize("seed", range(40))
def test_guide_bar_polygons_agree_with_the_twin(seed):
    rng = random.Random(500 + seed)
    AB, AC = rng.uniform(10, 200), rng.uniform(10, 200)
    if abs(AB - AC) < 5:
        AC += 10
    g = _motion(rng, {"AB": AB, "AC": AC})
    sol = _solve("guide_bar.kinematics", g)
    got = sol.answers
    ex = guide_bar(AB, AC, g["phi"], g["omega"], g.get("epsilon", 0.0))
    w, e = abs(g["omega"]), abs(g.get("epsilon", 0.0))
    lever = 1 + AB / abs(AB - AC)
    for n, scale in (("omega3", w), ("epsilon3", w * w + e), ("v_slip", w * AB), ("a_slip", (w * w + e) * AB),
                     ("a_coriolis", (w * w + e) * AB)):
        assert abs(got[n] - ex[n]) <= 1e-9 * scale * lever ** 2, (n, got[n], ex[n])
    # the Coriolis term is 2·ω3·v_slip, read off the polygon
    assert math.isclose(got["a_coriolis"], 2 * got["omega3"] * got["v_slip"], rel_tol=1e-9, abs_tol=1e-9 * w * w * AB)
    assert sol.ok


@pytest.mark.parametrize("recipe, g, words", [
    ("crank_slider.kinematics", {"AB": 50, "BC": 60, "e": 10, "phi": 90, "omega": 1}, "not less than BC"),
    ("guide_bar.kinematics", {"AB": 50, "AC": 50, "phi": -90, "omega": 1}, "B lies on C"),
    ("guide_bar.kinematics", {"AB": 50, "AC": 80, "phi": 0, "omega": 0}, "omega = 0"),
])
def test_refusals(recipe, g, words):
    with pytest.raises(GeomconError, match=words):
        _solve(recipe, g)
