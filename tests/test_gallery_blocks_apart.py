"""No text line of one block of a gallery sheet prints over a text line of another block (issue 11): 001-24, 200-03
and 200-17 set the heading "Results 结果" over the s–δ chart's caption row ("δ: 360° = 82.5 mm;  s 1:2"), because
the Results were placed in the drawing's free room before the chart's caption was. A rule over every sheet of the
gallery: the blocks are the Results, the Warnings, the chart's caption row (degree ticks, h, scales), the step
captions, the figure's labels, the scale bar, the detail view (its caption and its labels apart), the title block
and every other top-level group or text (protocol, chart panels, headings); each text line's box
(:func:`geomcon.render.charts.text_boxes`) meets no box of a line of another block. Texts of one block are the
business of that block's own placement rule (tests/test_render_labels.py …)."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.render.charts import text_boxes

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
TOUCH = 0.1
"""Paper mm two boxes must share, across and down, to count as printed over each other."""
BLOCKS = ("Results", "Warnings", "chart caption", "step caption", "figure labels", "scale bar", "detail caption",
          "detail labels", "title block")
"""The blocks the rule names (any other top-level group or text is a block of its own, named by its id or class)."""


def _sheets() -> list[Path]:
    return sorted(GALLERY.glob("*.svg"))


def _block(top: ET.Element, el: ET.Element, parents: dict[ET.Element, ET.Element]) -> str:
    """The block of text element ``el`` under the top-level element ``top``."""
    name = top.get("id") or top.get("class") or "text"
    if name.startswith("info") or name == "warnings":
        return "Warnings" if (el.get("class") or "").startswith("warning") else "Results"
    if name == "detail" or re.fullmatch(r"detail-\d+", name):         # a sheet's first window, its second …
        p = el
        while p is not top:
            if (p.get("id") or "") == f"{name}-figure":
                return "detail labels"
            p = parents[p]
        return "detail caption"
    return {"diagram-axes": "chart caption", "captions": "step caption", "figure": "figure labels",
            "scale": "scale bar", "title-block": "title block"}.get(name, name)


def lines(svg: str) -> list[tuple[str, str, tuple[float, float, float, float]]]:
    """Every text line of ``svg``: (block, text, paper box)."""
    root = ET.fromstring(svg)
    parents = {c: p for p in root.iter() for c in p}
    out = []
    for top in root:
        for el in top.iter():
            if not el.tag.endswith("}text") and el.tag != "text":
                continue
            boxes = text_boxes(ET.tostring(el, encoding="unicode"))
            words = "".join(el.itertext()).strip()
            out += [(_block(top, el, parents), words, b) for b in boxes]
    return out


def offenders(svg: str) -> list[tuple[str, str, str, str]]:
    """The pairs of text lines of different blocks whose boxes overlap: (block, text, block, text)."""
    found = lines(svg)
    out = []
    for i, (ba, ta, a) in enumerate(found):
        for bb, tb, b in found[:i]:
            if ba != bb and min(a[2], b[2]) - max(a[0], b[0]) > TOUCH and min(a[3], b[3]) - max(a[1], b[1]) > TOUCH:
                out.append((bb, tb[:40], ba, ta[:40]))
    return out


def test_the_rule_sees_results_over_a_chart_caption():
    svg = (GALLERY / "200-01_cam_roller_offset.svg").read_text(encoding="utf-8")
    m = re.search(r'<text [^>]*class="diagram-scales"[^>]*\bx="([\d.]+)" y="([\d.]+)"', svg) or \
        re.search(r'<text [^>]*\bx="([\d.]+)" y="([\d.]+)"[^>]*class="diagram-scales"', svg)
    if m is None:                                # no chart beside the cam: put a caption row in by hand
        m = re.search(r'<text [^>]*\bx="([\d.]+)" y="([\d.]+)"', svg)
        svg = svg.replace("</svg>", f'<g id="diagram-axes"><text x="{m.group(1)}" y="{m.group(2)}" '
                                    f'font-size="3">δ: 360° = 90 mm</text></g></svg>')
    x, y = m.group(1), m.group(2)
    bad = svg.replace("</svg>", f'<g id="info-9"><text class="info-head" x="{x}" y="{y}" font-size="3.5">'
                                f'Results</text></g></svg>')
    assert any({p[0], p[2]} == {"Results", "chart caption"} for p in offenders(bad))


@pytest.mark.parametrize("path", _sheets(), ids=lambda p: p.stem)
def test_texts_of_different_blocks_do_not_overlap(path):
    assert offenders(path.read_text(encoding="utf-8")) == []
