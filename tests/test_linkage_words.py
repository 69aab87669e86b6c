"""A linkage's words name the links it has and the quantity a value is (issue 11, session l's review of every
sheet as a teacher prints it).

Each test here failed on the gallery before the fix it guards:

- 400-05 (crank-slider, instant centres) printed "P13 … instant centre of crank and rocker / 曲柄与摇杆的瞬心":
  a crank-slider has no rocker, its link 3 is the slider (the recipe's own answer says so).
- 400-05's protocol step said "vC = ω1·P14P13 … = −116.862 mm", a velocity in mm: the value is vC/ω1, as the
  Results print it.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.recipes import RECIPES, get_recipe
from geomcon.render.results import name_of
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
SVG = "{http://www.w3.org/2000/svg}"


def _texts(path: Path) -> list[str]:
    root = ET.fromstring(path.read_text(encoding="utf-8"))
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]


SLIDER_RECIPES = sorted(n for n in RECIPES if n.startswith("crank_slider."))


@pytest.mark.parametrize("recipe", SLIDER_RECIPES)
def test_a_crank_slider_prints_no_rocker(recipe):
    """No printed meaning of a crank-slider's answer names a rocker, in either language."""
    for q in get_recipe(recipe).answers:
        nm = name_of(q.name, recipe)
        assert "rocker" not in nm.en and "摇杆" not in nm.zh, (recipe, q.name, nm)


def test_400_05_sheet_names_the_slider():
    texts = " ".join(_texts(GALLERY / "400-05_crank_slider_instant_centres.svg"))
    assert "曲柄与摇杆" not in texts and "crank and rocker" not in texts
    assert "曲柄与滑块的瞬心" in texts


def test_slider_rate_step_names_its_quantity():
    """The step that measures vC/ω1 ends in vC/ω1's formula (its value, a length per unit crank speed, printed
    after it), not in a velocity vC."""
    sol = solve(load_problem(ROOT / "problems" / "400-05_crank_slider_instant_centres.toml"))
    en, zh = sol.scene.caption("vC_w1")
    for text in (en, zh):             # the measured value is printed after the caption: after vC/ω1's formula
        assert "vC/ω1 = " in text and "vC = " not in text and text.endswith("P14P13"), (en, zh)
    protocol = " ".join(_texts(GALLERY / "400-05_crank_slider_instant_centres-2.svg"))
    assert "vC = ω1" not in protocol.replace("₁", "1")
