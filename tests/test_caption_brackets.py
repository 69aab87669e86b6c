"""An English caption ends in one bracket remark, as a Chinese one does (issue 11, hsmall11m): a branch rule or a
sheet note joins the caption's own closing bracket — 200-07 step 14 printed "(the arm's directions) (diagram on
sheet 2)" and 001-10 steps 13, 21 "(the other end) (the intersection farther from C2)"; they read "(the arm's
directions; diagram on sheet 2)", "(the other end; the intersection farther from C2)". A formula's closing
bracket is no remark and stays as it is."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.render.zh import en_remark, zh_remark

GALLERY = Path(__file__).resolve().parents[1] / "gallery"

WORDS = r"[^()]*[A-Za-z]{3}[^()]*"
TWO = re.compile(rf"\(({WORDS})\) \(({WORDS})\)")
"""Two bracket remarks in a row (each holding a word of three letters)."""


def _text(path: Path) -> str:
    """The sheet's text: each ``<text>`` element's runs joined, the elements joined by a space (a wrapped caption
    reads on across its lines)."""
    raw = path.read_text(encoding="utf-8")
    return " ".join(re.sub(r"<[^>]*>", "", t) for t in re.findall(r"<text\b.*?</text>", raw, flags=re.S))


def test_a_remark_joins_the_caption_s_bracket():
    assert en_remark("Draw the arm (the arm's directions)", "diagram on sheet 2") == \
        "Draw the arm (the arm's directions; diagram on sheet 2)"
    assert en_remark("They meet at P", "the nearer") == "They meet at P (the nearer)"


@pytest.mark.parametrize("formula", ["on OA0′ (A0′P = a/(1 − εψ′))", "K = (180° + θ)/(180° − θ)", "B (P12)"])
def test_a_formula_s_bracket_is_left_alone(formula: str):
    assert en_remark(formula, "nearer") == f"{formula} (nearer)"


def test_the_twins_agree():
    en = en_remark("meets C1 (crank and coupler folded)", "above AD")
    zh = zh_remark("交于 C1(曲柄与连杆重叠共线)", "位于 AD 上方")
    assert en.count("(") == zh.count("(") == 1 and en.endswith("above AD)") and zh.endswith("位于 AD 上方)")


def test_the_review_s_captions_read_with_one_bracket():
    assert "(the arm's directions; diagram on sheet 2)" in _text(GALLERY / "200-07_oscillating_flat_face-3.svg")
    assert "(the other end; the intersection farther from C2)" in \
        _text(GALLERY / "001-10_crank_rocker_design_coupler-2.svg")


@pytest.mark.parametrize("path", sorted(GALLERY.glob("*.svg")), ids=lambda p: p.stem)
def test_no_gallery_sheet_prints_two_remark_brackets_in_a_row(path: Path):
    found = TWO.findall(_text(path))
    assert not found, f"{path.name}: {found}"
