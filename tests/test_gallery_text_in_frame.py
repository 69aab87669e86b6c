"""No text of a gallery sheet runs out of the drawing frame or over the title block (issue 11, review item 2):
000-06's third sheet set the Results and Warnings block 350 mm tall on a sheet 190 mm high, so that its lines ran
over the title block and off the paper. A rule over every sheet of the gallery (drawing sheets, the s–δ diagram's
sheet, the protocol's sheets): each text line's box (:func:`geomcon.render.charts.text_boxes`: the width as the
font's advance estimates it) outside the title block lies inside the frame and meets no part of the title block."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.render.charts import text_boxes
from geomcon.render.page import PageSpec, frame_box, title_block_box

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
SLACK = 0.3
"""Paper mm a text box may reach past the frame's inner line (the width is an estimate)."""


def _sheets() -> list[Path]:
    return [p for p in sorted(GALLERY.glob("*.svg")) if 'class="sheet"' in p.read_text(encoding="utf-8")[:2000]]


def _page(svg: str) -> PageSpec:
    w, h = (float(v) for v in re.search(r'viewBox="0 0 ([\d.]+) ([\d.]+)"', svg).groups())
    for paper in ("A4", "A3"):
        for orient in ("landscape", "portrait"):
            sh = PageSpec(paper, orient).sheet
            if abs(sh.width - w) < 0.01 and abs(sh.height - h) < 0.01:
                return PageSpec(paper, orient)
    raise AssertionError(f"no paper of {w} × {h} mm")


def offenders(svg: str) -> list[tuple[str, tuple[float, float, float, float]]]:
    """The text lines of ``svg`` (outside the title block group) that leave the frame or meet the title block."""
    sheet = _page(svg).sheet
    fx0, fy0, fx1, fy1 = frame_box(sheet)
    tx0, ty0, tx1, ty1 = title_block_box(sheet)
    body = re.sub(r'<g [^>]*id="title-block".*?</g>', "", svg, flags=re.S)
    out = []
    texts = re.findall(r"<text\b.*?</text>", body, flags=re.S)
    for t in texts:
        boxes = text_boxes(f'<g xmlns="http://www.w3.org/2000/svg">{t}</g>')
        for b in boxes:
            outside = b[0] < fx0 - SLACK or b[1] < fy0 - SLACK or b[2] > fx1 + SLACK or b[3] > fy1 + SLACK
            over = b[0] < tx1 and tx0 < b[2] and b[1] < ty1 and ty0 < b[3]
            if outside or over:
                out.append((re.sub(r"<[^>]+>", "", t)[:60], tuple(round(v, 1) for v in b)))
    return out


def test_the_rule_sees_a_line_over_the_title_block():
    svg = next(p for p in _sheets() if p.name.endswith("-2.svg")).read_text(encoding="utf-8")
    tb = title_block_box(_page(svg).sheet)
    bad = svg.replace("</svg>", f'<text x="{tb[0] + 5}" y="{tb[1] + 5}" font-size="3.5">over it</text></svg>')
    assert any(s.startswith("over it") for s, _ in offenders(bad))


@pytest.mark.parametrize("path", _sheets(), ids=lambda p: p.stem)
def test_no_text_leaves_the_frame_or_meets_the_title_block(path):
    assert offenders(path.read_text(encoding="utf-8")) == []
