"""Issue 11 review: cam.base_radius's h is a stroke in mm for a translating follower and the arm's angular stroke
in degrees for an oscillating one, but every listing named it "mm" (`geomcon recipes`, its JSON), a drafted
worksheet varied an arm's h by half a paper mm as a length, and the checks' length scale counted its degrees
as millimetres. Its unit now follows the givens (``Quantity.unit_when``, ``unit_in``)."""
from __future__ import annotations

import json
import subprocess
import sys
import tomllib
from pathlib import Path

from geomcon.recipes import get_recipe
from geomcon.recipes.base import unit_in
from geomcon.solve import solve
from geomcon.problems import load_problem
from geomcon.worksheet.drafting import DEGREES, PAPER_MM, drafted

ROOT = Path(__file__).resolve().parents[1]
ARM = ROOT / "problems" / "200-12_oscillating_base_radius.toml"


def _h():
    return next(q for q in get_recipe("cam.base_radius").givens if q.name == "h")


def test_an_arm_s_stroke_is_in_degrees_a_guide_s_in_mm():
    assert unit_in(_h(), {"motion": "oscillating"}) == "deg"
    assert unit_in(_h(), {"motion": "translating"}) == unit_in(_h(), {}) == "mm"


def test_geomcon_recipes_lists_both_units_of_h():
    run = [sys.executable, "-m", "geomcon", "recipes"]
    text = subprocess.run(run, capture_output=True, text=True, check=True).stdout
    line = next(ln for ln in text.splitlines()[text.splitlines().index(next(
        ln for ln in text.splitlines() if ln.startswith("cam.base_radius"))):] if ln.strip().startswith("h "))
    assert "° if motion = oscillating" in line
    data = json.loads(subprocess.run(run + ["--json"], capture_output=True, text=True, check=True).stdout)
    assert data["cam.base_radius"]["given"]["h"]["unit_when"] == [{"given": "motion", "is": "oscillating", "unit": "deg"}]


def test_a_drafted_arm_stroke_varies_by_degrees_not_paper_millimetres():
    given = tomllib.loads(ARM.read_text(encoding="utf-8"))["given"]
    assert given["motion"] == "oscillating"
    h = next(d for d in drafted("cam.base_radius", given, 0.5) if d.name == "h")
    assert h.plus["h"] - given["h"] == DEGREES
    translating = {**given, "motion": "translating"}
    h = next(d for d in drafted("cam.base_radius", translating, 0.5) if d.name == "h")
    assert h.plus["h"] - given["h"] == PAPER_MM / 0.5


def test_an_arm_s_stroke_is_no_length_of_its_checks():
    """The checks compare lengths relative to the largest given length: an arm's h (degrees) is not one."""
    from geomcon.solve import _length_givens
    recipe = get_recipe("cam.base_radius")
    assert "h" not in {name for name, _ in _length_givens(recipe)}
    sol = solve(load_problem(ARM))
    sizes = [abs(v) for q in recipe.givens if q.unit == "mm" and q.name != "h"
             for v in [sol.problem.given.get(q.name)] if isinstance(v, (int, float))]
    assert sol.length_scale == max(sizes)
    moved = solve(load_problem(ROOT / "problems" / "200-10_base_radius_centred.toml"))
    assert moved.length_scale >= moved.problem.given["h"]           # a translating stroke is a length
