"""The gallery's words as a teacher reads them (issue 11, session j's review of every sheet): a figure names a
point, an entry of a list and an unbounded range the way the rest of the sheet does, and an English line is
English.

Each test here failed on the gallery before the fix it guards:

- 001-02's step 8 and protocol printed Python's ``[610, inf]`` for "not a mechanism" (the Results say
  ``[610.000, ∞)``).
- 001-10 … 001-16, 004-03: every candidate's step said "It meets the θ-circle again at A" (and "They meet at
  E", "Join C2E") while the drawing labels the candidates A1, A2 …, E1, E2 …, Fn, Ff.
- 000-05 … 000-07: the warnings named a list's entry by its Python index (``ψ[2]``, sheet 1: ``ψ[2…4]``),
  which a student reads as ψ at δ = 2°; the Results line prints the list as ``ψ(2°, 4°, 6°, 8°, 10°)``.
- 000-04 … 000-08, 200-03: the English undercut warning ended in Chinese ("distorted there（增大基圆或减小滚子
  半径）"), the Chinese line under it saying the same.
- 001-10 … 004-03: "其D 所在一侧" (no space between the ideograph and the letter, as everywhere else), and
  001-10c, 004-03 printed the formula "AB = （AC远 − AC近）/2" with full-width brackets.
"""
from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.render.warning_words import warning_lines
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
SVG = "{http://www.w3.org/2000/svg}"
HAN = "\u4e00-\u9fff"


def _texts(path: Path) -> list[str]:
    root = ET.fromstring(path.read_text(encoding="utf-8"))
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]


@pytest.fixture(scope="module")
def sheets() -> dict[str, list[str]]:
    """Every gallery SVG's text lines, by file name."""
    return {p.name: _texts(p) for p in sorted(GALLERY.glob("*.svg"))}


def test_no_sheet_prints_python_s_words_for_numbers(sheets):
    bad = [(name, t) for name, lines in sheets.items() for t in lines if re.search(r"\b(inf|nan|None)\b", t)]
    assert not bad, bad[:5]
    assert any("[610, ∞)" in t for t in sheets["001-02_four_bar_link_ranges-2.svg"])


def test_a_list_s_entry_is_named_as_its_results_line_names_it(sheets):
    """No Python index after a symbol (``ψ[2]``, ``xp[0…4]``) where the Results print ``ψ(2°, 4°, …)``."""
    bad = [(name, t) for name, lines in sheets.items() for t in lines if re.search(r"[A-Za-zα-ω′]\[\d", t)]
    assert not bad, bad[:5]
    sheet1 = " ".join(sheets["000-05_slotter_cam_motion_law.svg"])
    assert "printed ψ(6°, 8°, 10°) doubtful" in sheet1
    assert any(t.startswith("published ψ(10°) (swing of the arm) = 40 is doubtful")
               for t in sheets["000-05_slotter_cam_motion_law-3.svg"])


def test_an_english_warning_line_is_english():
    """Every warning of the gallery, as a figure's English line prints it, holds no Chinese (JSON keeps the
    sentence as the recipe words it)."""
    seen = 0
    for j in sorted(GALLERY.glob("*.json")):
        data = json.loads(j.read_text(encoding="utf-8"))
        for w in data.get("warnings", []) if isinstance(data, dict) else []:
            seen += 1
            for line in warning_lines([w], "en"):
                assert not re.search(f"[{HAN}]", line), (j.name, line)
    assert seen >= 30
    text = " ".join(_texts(GALLERY / "200-03_cam_roller_undercut.svg"))
    assert "(enlarge the base circle or use a smaller roller)" in " ".join(text.split())


def test_chinese_text_spaces_a_latin_letter_from_an_ideograph(sheets):
    """A letter or digit next to an ideograph has a space between (``其 D 所在一侧``), as every caption writes it;
    a subscript in words (``AC远``) is part of its symbol."""
    pat = re.compile(f"[{HAN}][A-Za-z0-9]|[A-Za-z0-9][{HAN}]")
    bad = [(name, t) for name, lines in sheets.items() for t in lines
           if pat.search(re.sub(f"AC[远近]", "AC", t))]
    assert not bad, bad[:5]


def test_a_formula_keeps_its_ascii_brackets_in_chinese_text(sheets):
    bad = [(name, t) for name, lines in sheets.items() for t in lines if re.search(r"）/|=\s*（", t)]
    assert not bad, bad[:5]


@pytest.mark.parametrize("stem", ["001-10_crank_rocker_design_coupler", "001-11_jaw_crusher_design",
                                  "001-12_crank_rocker_frame_line", "001-16_jaw_crusher_AC1"])
def test_a_candidate_s_step_names_the_point_as_the_drawing_labels_it(stem):
    """A step that makes a labelled point and says where (``… at A1``, ``They meet at E2``) names it by its
    label, in both languages; a step joining to it too (``Join C2E1``)."""
    scene = solve(load_problem(ROOT / "problems" / f"{stem}.toml")).drawing_scene
    named = 0
    labels = {s.label for s in scene.steps if s.label}
    for s in scene.steps:
        en, zh = s.caption
        if s.label and re.fullmatch(r"[A-Z]\w*", s.label) and s.label != s.label[:1]:
            m = re.search(r"\b(?:at|meet at) ([A-Z][\w′]*)", en)
            if m:
                named += 1
                assert m.group(1) == s.label, (s.key, en, s.label)
                assert re.search(rf"于 {s.label}(?![\w′])", zh), (s.key, zh, s.label)
        m = re.fullmatch(r"Join (C\d)(?: and )?([A-Z]\w*)", en)
        if m:
            assert m.group(2) in labels, (s.key, en, sorted(labels))
    assert named >= 2


def test_a_four_bar_analysis_names_the_link_at_each_pivot_of_its_frame(sheets):
    """001-03, 001-03b, 001-03c, 300-01 printed "the link at the first pivot is a crank" (which pivot? 001-03b's
    frame AB lists it after "the link at the second pivot"): the link is named as a textbook names it."""
    assert not [(n, t) for n, lines in sheets.items() for t in lines if "pivot is a crank" in t]
    frame_ab = sheets["001-03b_four_bar_frame_AB.svg"]
    assert any(t.startswith("AD is a crank: yes") for t in frame_ab)
    assert any(t.startswith("BC is a crank: yes") for t in frame_ab)
    assert any(t.startswith("AD is a crank: no") for t in sheets["001-03c_four_bar_frame_CD.svg"])


def test_an_angle_s_gloss_names_an_angle(sheets):
    """001-01, 001-08, 001-17 glossed ∠C1AD "重叠共线极限位置" (the folded extreme position: a position, not the
    angle the crank line makes with the frame there)."""
    assert not [(n, t) for n, lines in sheets.items() for t in lines if t.rstrip().endswith("共线极限位置")]
    assert "重叠共线位置 AC1 与机架的夹角" in sheets["001-08_crank_rocker.svg"]


def test_link_3_is_named_as_its_mechanism_has_it(sheets):
    """400-01 (a four-bar's rocker CD), 400-03 and 000-03 (a guide bar) glossed ω3, ε3 "构件 3（摇杆或导杆）的角速度":
    the drawing knows which it is."""
    assert not [(n, t) for n, lines in sheets.items() for t in lines if "摇杆或导杆" in t or "rocker or guide" in t]
    assert any("摇杆 CD 的角速度" in t for t in sheets["400-01_four_bar_velocity_polygons.svg"])
    assert any("导杆角加速度" in t for t in sheets["400-03_guide_bar_coriolis.svg"])


def test_a_chinese_caption_takes_its_branch_remark_into_its_own_brackets(sheets):
    """001-08 …: "交摇杆圆于 C1（曲柄与连杆重叠共线）（位于直线 AD 上方的交点）", two brackets in a row; the remark
    joins the caption's own: "（曲柄与连杆重叠共线；位于直线 AD 上方的交点）"."""
    assert not [(n, t) for n, lines in sheets.items() for t in lines if "）（" in t]
    assert any("曲柄与连杆重叠共线；位于直线" in t for t in sheets["001-08_crank_rocker-2.svg"])


def test_a_branch_is_said_in_words_not_by_a_helper_point(sheets):
    """001-25 … 001-30b said "the intersection farther along D→D + ↑" (a point "D + ↑" the drawing never
    shows): the follower's point is "the upper intersection"."""
    assert not [(n, t) for n, lines in sheets.items() for t in lines if "↑" in t]
    assert any("the upper intersection" in t for t in sheets["001-27_eccentric_roller_offset-2.svg"])


def test_every_full_size_run_sits_on_its_line_s_baseline():
    """A protocol line ending in a subscript (``Measure θ = ∠C1AC2``) printed its bold measured value
    "= 12.506°" on the subscript's baseline, 0.77 mm low (68 protocol sheets): after the subscripts and
    superscripts of a line, a full-size run is back on the baseline."""
    low = []
    for path in sorted(GALLERY.glob("*.svg")):
        for t in ET.parse(path).iter(f"{SVG}text"):
            shift = 0.0
            for run in t.iter(f"{SVG}tspan"):
                shift += float(run.get("dy") or 0.0)
                if run.get("font-size") is None and (run.text or "").strip() and abs(shift) > 1e-6:
                    low.append((path.name, "".join(t.itertext())))
                    break
    assert not low, low[:5]


def test_the_link_range_chart_names_its_quantity(sheets):
    """001-02's number lines named no variable (the title says "coupler length BC"; the chart did not): the top
    row's end reads "BC (mm)", as an s–δ chart names its δ axis."""
    assert "BC (mm) 杆长" in sheets["001-02_four_bar_link_ranges.svg"]
