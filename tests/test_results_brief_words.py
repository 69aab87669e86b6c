"""Sheet 1's brief Results say where their Chinese words are (hlook11m's review: 000-05 and 100-07 printed
English-only lines under "Results 结果", 000-04/000-08 the words, with no word of why). Brief lines leave the words
off to find room on sheet 1 (kept, 000-05's results went to a sheet of their own and 100-07 fell back to 1:2); the
heading now says "结果（释义见第 N 张）" and sheet N prints the lines with their words."""
from __future__ import annotations

import re

import pytest

from cam_sheets import GALLERY

CJK = re.compile(r"[\u4e00-\u9fff]")


def _block(path) -> tuple[str, list[str]]:
    """The Results heading of a sheet and its result lines, markup stripped."""
    svg = path.read_text(encoding="utf-8")
    head = [re.sub(r"<[^>]*>", "", t) for t in re.findall(r'<text class="info-head"[^>]*>(.*?)</text>', svg, re.S)]
    lines = [re.sub(r"<[^>]*>", "", t) for t in re.findall(r'<text class="info"[^>]*>(.*?)</text>', svg, re.S)]
    return (head[0] if head else ""), lines


SHEETS = sorted(p for p in GALLERY.glob("*.svg") if re.fullmatch(r"\d{3}-\d\d\w*", p.stem) and _block(p)[1])


def test_the_review_s_sheets_are_brief():
    names = {p.stem for p in SHEETS if not any(CJK.search(ln) for ln in _block(p)[1])}
    assert {"000-05_slotter_cam_motion_law", "100-07_rocker_slider_three_positions"} <= names


@pytest.mark.parametrize("path", SHEETS, ids=lambda p: p.stem)
def test_results_without_their_words_point_to_the_sheet_that_has_them(path):
    head, lines = _block(path)
    m = re.search(r"结果（(?:\d+/\d+；)?释义见第 (\d+) 张）", head)
    if any(CJK.search(ln) for ln in lines):
        assert m is None, head
        return
    assert m is not None, (path.stem, head)
    head2, lines2 = _block(GALLERY / f"{path.stem}-{m[1]}.svg")
    assert head2.startswith("Results") and any(CJK.search(ln) for ln in lines2), (path.stem, m[1])
