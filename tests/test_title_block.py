"""The title block's title reads at ISO 3098 sizes in every language (issue 11, hsmall11m): a sheet in both
languages set its two titles 2.8 mm high (5 mm for one language) because both had to share the 7 mm row of one,
and a title wider than the block shrank towards 2.5 mm on one line (88 of the 186 titles are wider than 177 mm at
5 mm). The title field is now 11 mm of the block's 28 (the three data rows 5.67 mm each): both languages print
their titles one line each at 3.5 mm, and one language prints its title at 5 mm on one line or, when longer,
wrapped to two lines of 3.5 mm."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.render.page import MIN_TEXT, TB_H, TB_TITLE_H, title_lines

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SVG = "{http://www.w3.org/2000/svg}"
SHEETS = sorted(p for p in GALLERY.glob("*.svg") if "title-block" in p.read_text(encoding="utf-8"))


def _titles(path: Path) -> list[tuple[str, float, float]]:
    """(text, font size, baseline y) of each title line of the sheet's title block."""
    root = ET.parse(path).getroot()
    block = root.find(f".//{SVG}g[@id='title-block']")
    return [("".join(t.itertext()), float(t.get("font-size")), float(t.get("y"))) for t in block.iter(f"{SVG}text")
            if "tb-0-0" in (t.get("class") or "").split()]


def test_the_sheets_are_found():
    assert len(SHEETS) > 150


@pytest.mark.parametrize("path", SHEETS, ids=lambda p: p.stem)
def test_a_title_in_both_languages_reads_at_3_5_mm(path: Path):
    lines = _titles(path)
    assert 1 <= len(lines) <= 2
    sizes = [size for _, size, _ in lines]
    assert min(sizes) >= MIN_TEXT
    if len(lines) == 2 and re.search("[\u4e00-\u9fff]", lines[1][0]) and not re.search("[\u4e00-\u9fff]", lines[0][0]):
        long = [t for t, size, _ in lines if size < 3.5]
        assert len(long) <= 1 and all(size >= 3.0 for size in sizes), (path.name, lines)   # the 8 longest: ≥ 3 mm
        assert sum(size == 3.5 for size in sizes) >= 1


def test_both_titles_fit_the_title_field():
    root = ET.parse(GALLERY / "001-08_crank_rocker.svg").getroot()
    rect = root.find(f".//{SVG}g[@id='title-block']/{SVG}rect")
    top = float(rect.get("y"))
    assert float(rect.get("height")) == TB_H
    lines = _titles(GALLERY / "001-08_crank_rocker.svg")
    assert [size for _, size, _ in lines] == [3.5, 3.5]
    for _, size, y in lines:
        assert top + size * 0.75 <= y <= top + TB_TITLE_H - 0.25 * size      # caps and descenders in the field


def test_one_language_wraps_a_long_title_rather_than_shrink_it():
    long = "Four-bar 50/50/30/90 driven by the rocker CD: type, pressure angle in the position shown, dead points"
    lines, size = title_lines(long, 177.0)
    assert size == 3.5 and len(lines) == 2 and "".join(lines) == long
    assert title_lines("Crank-rocker 50/70/80/90", 177.0) == (("Crank-rocker 50/70/80/90",), 5.0)
    zh, _ = title_lines("四杆机构 AB 160、CD 240、机架 AD 210：连杆 BC 取各种长度时的机构类型", 177.0)
    assert len(zh) == 2 and "".join(zh).endswith("机构类型")
