"""Rules over every detail window (局部放大图) of the gallery's sheets, read from the SVG: the window's heading
lies inside its frame (200-17's, "Detail 局部放大 1:1 μl = 1 mm/mm", ran out of a 35 mm window between "1:1" and
"μl"), and the drawing's texts keep clear below it (200-13's "αmax=34.51°" touched the heading, 1 mm under it)."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.render.labels import text_width

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
NS = "{http://www.w3.org/2000/svg}"
HEAD_GAP = 1.5
"""Paper mm between the heading's descent and the top of the highest text drawn in the window."""


def windows(svg: str) -> list[tuple[str, tuple[float, float, float, float], ET.Element, list[ET.Element]]]:
    """Each detail window of ``svg``: its id, its frame (x0, y0, x1, y1), its heading and its drawing's texts."""
    out = []
    for g in ET.fromstring(svg).iter(f"{NS}g"):
        name = g.get("id") or ""
        if not re.fullmatch(r"detail(-\d+)?", name):
            continue
        rect = g.find(f"{NS}rect")
        x, y, w, h = (float(rect.get(k)) for k in ("x", "y", "width", "height"))
        texts = list(g.iter(f"{NS}text"))
        head = next(t for t in texts if t.get("class") == "detail-head")
        out.append((name, (x, y, x + w, y + h), head, [t for t in texts if t is not head]))
    return out


def width(text: ET.Element) -> float:
    """The printed width of a text: each run at its own font size (a subscript's smaller)."""
    size = float(text.get("font-size"))
    runs = [(text.text or "", size)] + [(t.text or "", float(t.get("font-size") or size)) for t in text]
    return sum(text_width(s, sz) for s, sz in runs if s)


def _sheets() -> list[Path]:
    return [p for p in sorted(GALLERY.glob("*.svg")) if 'id="detail"' in p.read_text(encoding="utf-8")]


def test_the_gallery_has_detail_windows():
    assert len(_sheets()) >= 15


@pytest.mark.parametrize("path", _sheets(), ids=lambda p: p.stem)
def test_a_windows_heading_lies_inside_its_frame(path):
    for name, (x0, y0, x1, y1), head, _ in windows(path.read_text(encoding="utf-8")):
        left, base = float(head.get("x")), float(head.get("y"))
        size = float(head.get("font-size"))
        assert x0 < left and left + width(head) <= x1 - 0.5, (name, round(left + width(head) - x1, 2))
        assert y0 + 0.7 * size < base < y1, name


@pytest.mark.parametrize("path", _sheets(), ids=lambda p: p.stem)
def test_a_windows_texts_keep_clear_below_its_heading(path):
    for name, _, head, texts in windows(path.read_text(encoding="utf-8")):
        bottom = float(head.get("y")) + 0.2 * float(head.get("font-size"))        # its descent (μ)
        for t in texts:
            top = float(t.get("y")) - 0.7 * float(t.get("font-size"))             # a capital's, a digit's top
            assert top - bottom >= HEAD_GAP - 1e-9, (name, "".join(t.itertext()), round(top - bottom, 2))


def test_a_flat_face_is_no_link_a_window_enlarges():
    # 200-17's face, 7.7 mm at 1:2, ends in no joint: it asked for a window at 1:1 that held only the stem and
    # the face (nothing it resolved); the stem, which ends in the follower's B0, is a link
    from geomcon.problems import load_problem
    from geomcon.render.detail import mechanism_steps
    from geomcon.render.figure import shown_steps
    from geomcon.solve import solve
    sc = solve(load_problem(ROOT / "problems" / "200-17_cam_table_law.toml")).drawing_scene
    steps, _ = shown_steps(sc, None)
    values = sc.evaluate([s.key for _, s in steps])
    keys, _, lengths = mechanism_steps(steps, values)
    assert {"stem", "face_start"} <= keys and min(lengths) > 30.0
    assert 'id="detail"' not in (GALLERY / "200-17_cam_table_law.svg").read_text(encoding="utf-8")
