"""Issue 11 review: a product's dot prints as a dot operator. The CJK font that sets every text of a sheet draws
U+00B7 (middle dot) full-width, so 001-09's title read "S = 2・CD" with a Japanese middle dot; every text of a
sheet or player now prints U+22C5 instead (the JSON and the terminal keep the source's "·")."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.gallery import gallery_page
from geomcon.problems import load_problem
from geomcon.render.player import caption_html
from geomcon.render.serial import typeset
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
MIDDLE_DOT, DOT_OPERATOR = "\u00b7", "\u22c5"


def test_a_product_dot_is_typeset_as_the_dot_operator():
    assert typeset("S = 2·CD") == "S = 2⋅CD" and typeset("θ = 12.5°") == "θ = 12.5°"
    assert caption_html("vB = ω·AB") == "v<sub>B</sub> = ω⋅AB"


def test_the_slotter_title_prints_a_narrow_dot():
    sol = solve(load_problem(ROOT / "problems" / "001-09_slotter_rotating_guide_bar_stroke.toml"))
    sheet = sol.sheets(gallery_page())[0]
    assert "S = 2⋅CD" in sheet and MIDDLE_DOT not in sheet


@pytest.mark.parametrize("path", sorted(p for p in (ROOT / "gallery").glob("*") if p.suffix in (".svg", ".html")
                                        and p.name != "bench_cycle.svg"), ids=lambda p: p.name)
def test_no_gallery_sheet_or_player_prints_a_middle_dot(path):
    """bench_cycle.svg is the benchmark's chart, set in DejaVu Sans (its "·" separates figures, drawn narrow)."""
    assert MIDDLE_DOT not in path.read_text(encoding="utf-8")
