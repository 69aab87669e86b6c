"""A flat-faced cam's figure states its profile condition once (issue 11, hsmall11m): a flat face's condition is
convexity (ρ > 0 everywhere), and its ``undercut`` is only ``not convex`` — 200-02, 200-07 and 200-17 printed
"undercut (motion distorted): no" beside "profile convex: yes", one idea twice. The figure prints "profile
convex" alone; the JSON keeps ``undercut`` (a public contract, = not ``convex``)."""
from __future__ import annotations

import json

import pytest
from cam_sheets import GALLERY, PROBLEMS, printed_off_sheet, text as _text, with_follower

OFF_SHEET = ("undercut", "运动失真", "根切")
"""What no flat-face figure prints (text as read with the SVG's markup stripped)."""

FLATS = with_follower("flat")


def _convex_stems() -> list[str]:
    return [s for s in FLATS if "convex" in json.loads((GALLERY / f"{s}.json").read_text(encoding="utf-8"))["answers"]]


def test_the_flat_face_figures_that_print_convexity_are_all_found():
    assert {"200-02_cam_flat_face", "200-07_oscillating_flat_face", "200-17_cam_table_law"} <= set(_convex_stems())


@pytest.mark.parametrize("stem", FLATS)
def test_no_flat_face_sheet_prints_undercut(stem: str):
    assert not printed_off_sheet(stem, OFF_SHEET)


@pytest.mark.parametrize("stem", _convex_stems())
def test_a_flat_face_sheet_prints_its_convexity_and_the_json_keeps_undercut(stem: str):
    assert "profile convex: yes" in _text(GALLERY / f"{stem}.svg")
    ans = json.loads((GALLERY / f"{stem}.json").read_text(encoding="utf-8"))["answers"]
    assert ans["undercut"] is (not ans["convex"])


def test_the_terminal_summary_leaves_undercut_off_a_flat_face():
    from geomcon.problems import load_problem
    from geomcon.solve import solve

    sol = solve(load_problem(PROBLEMS / "200-02_cam_flat_face.toml"))
    names = [q.name for q in sol.sheet_answers()]
    assert "convex" in names and "undercut" not in names and "undercut" in sol.answers


def test_a_flat_face_answer_the_textbook_printed_stays_on_the_sheet():
    from geomcon.render.results import on_sheet
    assert not on_sheet("undercut", "cam.oscillating", {"follower": "flat"})
    assert on_sheet("undercut", "cam.oscillating", {"follower": "flat"}, printed=True)
    assert on_sheet("undercut", "cam.oscillating", {"follower": "roller"})
