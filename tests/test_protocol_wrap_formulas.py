"""Protocol lines keep a formula and an interval whole (hlook11m's review): 001-06b's Chinese step 32 broke as
"…：cos" / "α = √(g(2BC − g))/BC" (a function apart from its argument), 001-02's steps 5, 7–9 as "BC in" /
"[190, 290]" (room kept for a value an interval step never prints)."""
from __future__ import annotations

import re

from cam_sheets import GALLERY

FUNCTION_LAST = re.compile(r"(?<![A-Za-z])(?:arc)?(?:cos|sin|tan|cot)$")


def _texts(path) -> list[str]:
    svg = path.read_text(encoding="utf-8")
    return [re.sub(r"<[^>]*>", "", t).strip() for t in re.findall(r"<text\b[^>]*>(.*?)</text>", svg, re.S)]


def test_no_line_of_the_gallery_ends_in_a_function_s_name():
    ends = [(p.name, t) for p in sorted(GALLERY.glob("[0-9]*.svg")) for t in _texts(p) if FUNCTION_LAST.search(t)]
    assert ends == []


def test_001_06b_step_32_keeps_its_formula_on_one_line():
    texts = [t for p in sorted(GALLERY.glob("001-06b_crank_slider_redesign_K-*.svg")) for t in _texts(p)]
    assert any(t.endswith("：cos α = √(g(2BC − g))/BC") for t in texts)


def test_001_02_keeps_each_interval_on_the_line_of_its_step():
    texts = _texts(GALLERY / "001-02_four_bar_link_ranges-2.svg")
    for line in ("crank-rocker: BC in [190, 290]", "not a mechanism: BC in [610, ∞)",
                 "double-rocker: BC in [0, 190], [290, 610]", "Grashof: BC in [0, 130], [190, 290]"):
        assert line in texts, line
