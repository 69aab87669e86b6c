"""A component's letter and its subscript (aʳB2B3, aᵏB3B2, aEDⁿ) are stacked, as the textbook prints them, in the
figures and in the player's caption bar: the letter raised over the subscript, never printed beside it."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.render.labels import rich_runs
from geomcon.render.player import caption_html
from geomcon.render.serial import Element
from geomcon.render.shapes import STACK_DROP, SUP_RISE, SUPERSCRIPTS, add_runs, stacked_runs

GALLERY = Path(__file__).parent.parent / "gallery"
MODIFIERS = "".join(SUPERSCRIPTS)
TSPAN = re.compile(r"<tspan([^>]*)>([^<]*)</tspan>")


def tspans(text: str, size: float = 3.5) -> list[tuple[dict[str, float], str]]:
    el = Element("text", "")
    add_runs(el, rich_runs(text), size)
    out = []
    for child in el.elements:
        attrs = {k: float(v) for k, v in child.attribs.items() if k in ("dx", "dy", "font-size")}
        out.append((attrs, child.text))
    return out


@pytest.mark.parametrize("text, top, low", [("aʳB2B3 = 1", "r", "B2B3"), ("2ω3·vB3B2 = aᵏB3B2", "k", "B3B2"),
                                             ("aEDⁿ = ω4²·DE", "n", "ED"), ("ε3 = aB3ᵗ/CB", "t", "B3")])
def test_a_component_letter_stands_over_its_subscript(text, top, low):
    spans = tspans(text)
    texts = [t for _, t in spans]
    assert not any(ch in t for t in texts for ch in MODIFIERS)
    i = texts.index(top)
    j = i + 1 if texts[i + 1] == low else i - 1
    assert texts[j] == low
    later = spans[max(i, j)][0]
    assert later["dx"] < 0                                   # shifted back under the other, not beside it
    rise = sum(a.get("dy", 0.0) for a, _ in spans[:i + 1])
    drop = sum(a.get("dy", 0.0) for a, _ in spans[:j + 1])
    assert rise == pytest.approx(-SUP_RISE * 3.5, abs=0.01) and drop == pytest.approx(STACK_DROP * 3.5, abs=0.01)
    if "font-size" not in spans[-1][0]:                       # what follows is back on the baseline
        assert sum(a.get("dy", 0.0) for a, _ in spans) == pytest.approx(0.0, abs=1e-9)


def test_text_without_component_letters_renders_as_before():
    assert [r[3] for r in stacked_runs(rich_runs("Join AC2, γmin"), 3.5)] == [0.0] * 4


def test_the_caption_bar_stacks_them_too():
    assert caption_html("aʳB3B2 (∥ CB)") == 'a<span class="stack"><span>r</span><span>B3B2</span></span> (∥ CB)'
    assert caption_html("aEDⁿ") == 'a<span class="stack"><span>n</span><span>ED</span></span>'


def test_no_gallery_page_prints_a_component_letter_beside_a_subscript():
    pages = sorted(GALLERY.glob("*.svg")) + sorted(GALLERY.glob("*.html"))
    hits = [p.name for p in pages if re.search(f"[{MODIFIERS}]</tspan><tspan[^>]*font-size|"
                                               f"font-size=\"[\\d.]+\">[^<]*</tspan><tspan[^>]*>[{MODIFIERS}]",
                                               p.read_text(encoding="utf-8"))]
    assert not hits
    html = (GALLERY / "000-03_slotter_velocity_polygons.html").read_text(encoding="utf-8")
    script = html[html.index("var STEPS"):html.index("var N")]
    assert 'class=\\"stack\\"' in script or 'class="stack"' in script
    assert not re.search(f"[{MODIFIERS}]", script)


CAP_EM = 0.714
"""Noto Sans's cap height (em): the top of a subscript's capitals and digits."""


def _stacks(page: str):
    """(size, superscript's foot, subscript's top) of every stacked pair on an SVG page, y down from the baseline."""
    for m in re.finditer(r'<text [^>]*font-size="([\d.]+)"[^>]*>(.*?)</text>', page):
        size, y, spans = float(m.group(1)), 0.0, []
        for attrs, text in TSPAN.findall(m.group(2)):
            dy = re.search(r' dy="([-\d.]+)"', attrs)
            y += float(dy.group(1)) if dy else 0.0
            fs = re.search(r' font-size="([\d.]+)"', attrs)
            spans.append((y, float(fs.group(1)) if fs else size, y < -1e-9))
        for a, b in zip(spans, spans[1:]):
            if a[2] != b[2] and a[1] < size and b[1] < size:
                (sup, sub) = (a, b) if a[2] else (b, a)
                yield size, sup[0], sub[0] - CAP_EM * sub[1]


def test_a_stacked_letter_stands_clear_of_its_subscript():
    """hlook11m: 000-03's aʳB2B3 / aᵏB2B3 (results, ~15 protocol steps) and 400-03's printed the letter touching
    the subscript (its foot 0.07 of the size above the subscript's capitals). Now a visible gap of ≥ 0.12."""
    gaps = {}
    for p in sorted(GALLERY.glob("*.svg")):
        for size, foot, top in _stacks(p.read_text(encoding="utf-8")):
            gaps[p.name] = min(gaps.get(p.name, 9.0), (top - foot) / size)
    assert "000-03_slotter_velocity_polygons.svg" in gaps and "400-03_guide_bar_coriolis.svg" in gaps
    assert min(gaps.values()) >= 0.12, gaps
