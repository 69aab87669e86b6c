"""The text sheets of the gallery (review item 45): a block heading under the results keeps the gap the Warnings
heading keeps, and a protocol starts under the results only when at least MIN_FIRST of its steps fit there;
else it starts on the next sheet."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.render.protocol import MIN_FIRST

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SHEETS = sorted(p for p in GALLERY.glob("*-[0-9].svg"))


def _ys(svg: str, cls: str) -> list[float]:
    return [float(y) for y in re.findall(rf'<text[^>]*class="{cls}"[^>]*\by="([\d.]+)"', svg)
            + re.findall(rf'<text[^>]*\by="([\d.]+)"[^>]*class="{cls}"', svg)]


def _info_lines(svg: str) -> list[float]:
    return sorted(_ys(svg, "info") + _ys(svg, "warning"))


def test_the_gallery_has_text_sheets_with_results_and_a_protocol():
    """The gap rules below are exercised: since the Results stand in a drawing's free room on sheet 1 (hsheet11c),
    only a drawing with its results in brief there (100-07 at 1:1, set aside; 200-15 until its results went whole
    beside it) still carries Results and a protocol on one text sheet."""
    both = [p.stem for p in SHEETS if "proto-head" in p.read_text() and 'class="info-head"' in p.read_text()]
    assert "100-07_rocker_slider_three_positions-2" in both


@pytest.mark.parametrize("path", SHEETS, ids=lambda p: p.stem)
def test_the_protocol_heading_stands_as_far_below_the_results_as_warnings_do(path):
    svg = path.read_text()
    head = _ys(svg, "proto-head")
    lines = _info_lines(svg)
    if not head or not lines:
        return
    gap = head[0] - max(lines)
    assert gap >= 12.0, (path.name, gap)                 # a line (4.55) + 4 mm + a heading (3.5): as Warnings'
    warn = _ys(svg, "warning-head")
    results = _ys(svg, "info")
    if warn and results:
        assert gap == pytest.approx(warn[0] - max(results), abs=0.01), path.name


@pytest.mark.parametrize("path", SHEETS, ids=lambda p: p.stem)
def test_a_protocol_under_the_results_starts_with_enough_steps(path):
    svg = path.read_text()
    if "proto-head" not in svg or 'class="info-head"' not in svg:
        return
    here = len(re.findall(r'<g class="proto" ', svg))
    stem = path.stem.rsplit("-", 1)[0]
    total = sum(len(re.findall(r'<g class="proto" ', p.read_text())) for p in GALLERY.glob(f"{stem}-[0-9].svg"))
    assert here >= min(MIN_FIRST, total), (path.name, here, total)
