"""A whole-cycle chart's later sheet says it continues in both languages of its title: "(continued, 2/2)" after
the English, "（续，2/2）" after the Chinese (hlook11m: 000-09's sheet 2 said it in English only)."""
from __future__ import annotations

import re
from pathlib import Path

from geomcon.kinematics.plots import _heads

GALLERY = Path(__file__).parent.parent / "gallery"


def test_the_heading_continues_in_both_languages():
    assert _heads("Slotting machine\n插床", 1, 2) == ["Slotting machine (continued, 2/2)", "插床（续，2/2）"]
    assert _heads("Slotting machine\n插床", 0, 2) == ["Slotting machine", "插床"]
    assert _heads("Whole cycle", 2, 3) == ["Whole cycle (continued, 3/3)"]


def test_every_later_cycle_sheet_says_so_in_chinese():
    sheets = sorted(GALLERY.glob("*_cycle_motion-*.svg"))
    assert sheets
    for p in sheets:
        heads = [re.sub(r"<[^>]+>", "", h) for h in
                 re.findall(r'<text [^>]*class="chart-head"[^>]*>.*?</text>', p.read_text(encoding="utf-8"))]
        if any(re.search(r"[\u4e00-\u9fff]", h) for h in heads):
            assert any("（续，" in h for h in heads), (p.name, heads)
