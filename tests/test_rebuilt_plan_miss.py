"""A back-substitution asks the analysis recipe for steps that the plan learned so far may have left out: the
rebuilt scene completes itself instead of raising PlanMiss. Found by hsolve11n: the doctest of
``rebuilt_values`` failed (PlanMiss('theta')) when it ran after tests that had taught guide_bar.extremes's plan
only ψ."""
from __future__ import annotations

from geomcon.recipes import get_recipe
from geomcon.recipes.common import rebuilt, rebuilt_values
from geomcon.scene.scene import LeanScenes


def _teach_only_psi(given):
    r = get_recipe("guide_bar.extremes")
    with LeanScenes(r.name, learn=True):
        c = r.construct(given)
        c.scene.evaluate((c.answers["psi"],))


def test_a_step_outside_the_learned_plan_is_computed():
    g = {"AB": 145.0, "AC": 290.0}
    _teach_only_psi(g)
    assert round(rebuilt_values("guide_bar.extremes", g, ("theta",))["theta"], 9) == 60.0
    assert round(rebuilt("guide_bar.extremes", {"AB": 100.0, "AC": 200.0}).value("theta"), 9) == 60.0
