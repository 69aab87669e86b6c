"""Where a text goes when its place by its point or arc meets a link (issue 11, hacross11l): a mark's value beyond the
view box, into the sheet's room about it (:func:`geomcon.render.figure.text_room`), and a point's label with a leader,
each only where that clears the links, grounds, blocks and pins. Built from the problems, not read from the gallery:
each test fails on the base (001-21 printed φ1 across the rocker DC2 and φ2 on D's ground; 100-04 K2 and C″ across
the coupler links; 004-02's detail C1 on its slider block), or guards the rule's limit (200-13's results in one
block)."""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import pytest

from gallery_pages import page_of
from geomcon.problems import load_problem
from geomcon.render.figure import text_room
from geomcon.render.view import View
from geomcon.solve import solve
from knots import knots
from test_gallery_text_across import across

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"


@lru_cache(maxsize=None)
def sheet_one(stem: str) -> str:
    return solve(load_problem(PROBLEMS / f"{stem}.toml")).sheets(page_of(stem))[0]


def test_the_room_is_the_view_widened_to_the_area_but_not_below():
    view = View((0.0, 0.0, 100.0, 50.0), 1.0, (50.0, 40.0))
    assert text_room(view, (20.0, 10.0, 270.0, 150.0)) == (20.0, 10.0, 270.0, 90.0)
    assert text_room(view, (60.0, 50.0, 120.0, 60.0)) == view.paper_box        # never narrower than the view


def test_a_marks_value_by_a_pivot_at_the_drawings_edge_leaves_the_view_to_clear_the_links():
    bad = across(sheet_one("001-21_cutter_drive_K1"))
    assert not bad, bad


def test_a_value_that_crosses_only_thin_lines_stays_in_the_view_and_leaves_the_results_one_block():
    svg = sheet_one("200-13_cam_valve_speeds")
    assert "Results  结果" in svg and "Results (1/2)" not in svg


@pytest.mark.parametrize("stem, names", [("100-04_four_bar_fixed_pivots_coupler_angles", {"K2", "C″"}),
                                         ("200-20_oscillating_base_radius_rho", {"K2*"})])
def test_a_label_across_a_link_takes_its_leader_when_that_is_clear(stem, names):
    assert not names & {t for t, _, _ in across(sheet_one(stem))}


def test_a_label_on_its_slider_block_in_a_detail_view_takes_its_leader():
    found = [k.figure + k.what for k in knots(sheet_one("004-02_best_by_K_1_2_offset_limit"))]
    assert not [k for k in found if "covers slider" in k], found


def test_a_label_still_on_a_link_with_its_leader_looks_between_its_sixteen_directions():
    # 001-31's E0, the contact point on the cam's profile, printed across the profile (by its point and in its
    # leader form's 16 directions alike); the slot below it inside the disc, between the profile and ω's arc,
    # lies 11° off straight down, between two of them: the halfway directions find it (hlast11)
    # (at 1:2 on A4 landscape: the gallery prints 001-31 on portrait at 1:1, where E0 finds room by its point)
    from geomcon.gallery import gallery_page
    svg = solve(load_problem(PROBLEMS / "001-31_eccentric_oscillating_roller.toml")).sheets(gallery_page())[0]
    assert "E0" not in {t for t, _, _ in across(svg)}
    assert '<text class="label fan"' in svg.split('id="step-E0"', 1)[1].split("</g>", 1)[0]
