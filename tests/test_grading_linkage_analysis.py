"""The declared mistakes of issue 14's analysis recipes replay on their scenes (grading's contract)."""
from __future__ import annotations

import pytest

from geomcon.grading.mistakes import mistakes_of
from geomcon.problems import problem_from_dict
from geomcon.solve import solve


@pytest.mark.parametrize("recipe, given", [
    ("four_bar.analysis", dict(AB=50, BC=70, CD=80, AD=90, phi=60)),
    ("rotating_guide_bar.extremes", dict(AB=75, AC=50, CD=150)),
])
def test_declared_mistakes_name_steps_of_the_scene(recipe, given):
    sol = solve(problem_from_dict({"recipe": recipe, "given": given}, name="t"))
    scene = sol.scene.complete() if hasattr(sol.scene, "complete") else sol.scene
    ms = mistakes_of(recipe)
    assert ms
    for m in ms:
        for key in (m.step, m.answer):
            if key:
                assert key in scene, (m.code, key)
