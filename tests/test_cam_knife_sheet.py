"""A knife-edge cam's figure prints what a textbook prints for a knife edge (issue 11, hcam11k): its profile IS the
pitch curve, so ρmin is the profile's and is printed once, with no ρa,min (001-23a printed "ρa,min = 29.180 mm"
beside "ρmin = 29.180 mm"), no r0′ beside r0 (001-25) and no "undercut: no" (a knife has no roller to undercut
with). The JSON keeps every answer (a public contract): ρa,min = ρmin, r0′ = r0, undercut false."""
from __future__ import annotations

import json

import pytest
from cam_sheets import GALLERY, printed_off_sheet, text as _text, with_follower

OFF_SHEET = ("ρa,min", "ρₐ", "r0′", "undercut", "运动失真", "根切", "实际廓线最小曲率半径", "实际廓线基圆半径")
"""What no knife-edge figure prints (text as read with the SVG's markup stripped: subscripts join their base)."""

KNIVES = with_follower("knife")


def test_the_review_s_knife_figures_are_all_found():
    assert {"001-23a_cam_knife_uniform", "001-23b_cam_knife_parabolic", "001-23c_cam_knife_cosine",
            "001-24_cam_displacement_at_100", "200-06_oscillating_knife_same_sense", "200-16_cam_poly_4567",
            "001-25_eccentric_knife_centred"} <= set(KNIVES)


@pytest.mark.parametrize("stem", KNIVES)
def test_no_knife_edge_sheet_prints_the_actual_profile_or_undercut(stem: str):
    assert not printed_off_sheet(stem, OFF_SHEET)


@pytest.mark.parametrize("stem", KNIVES)
def test_a_knife_edge_s_json_keeps_its_answers(stem: str):
    ans = json.loads((GALLERY / f"{stem}.json").read_text(encoding="utf-8"))["answers"]
    if "rho_min_actual" in ans:
        assert ans["rho_min_actual"] == ans["rho_min_pitch"]
        assert ans["undercut"] is False
    if "r0_actual" in ans:
        assert ans["r0_actual"] == pytest.approx(ans["r0"], abs=1e-9)


def test_a_knife_edge_prints_rho_min_as_its_profile_s():
    from geomcon.render.results import result_line
    knife = result_line("rho_min_pitch", 29.18, "mm", lang="zh", recipe="cam.translating",
                        given={"follower": "knife"})
    roller = result_line("rho_min_pitch", 29.18, "mm", lang="zh", recipe="cam.translating",
                         given={"follower": "roller"})
    assert knife.startswith("凸轮廓线最小曲率半径 ρmin") and roller.startswith("理论廓线最小曲率半径 ρmin")


def test_a_roller_figure_still_prints_them():
    text = _text(GALLERY / "200-03_cam_roller_undercut.svg")
    assert "ρa,min" in text and "undercut (motion distorted): yes" in text


def test_a_knife_answer_the_textbook_printed_stays_on_the_sheet():
    from geomcon.render.results import on_sheet
    assert not on_sheet("undercut", "cam.oscillating", {"follower": "knife"})
    assert on_sheet("undercut", "cam.oscillating", {"follower": "knife"}, printed=True)
