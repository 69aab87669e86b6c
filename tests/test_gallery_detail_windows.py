"""Rules over every detail window (局部放大图) of the gallery's sheets, read from the SVG: the window's heading
lies inside its frame (200-17's, "Detail 局部放大 1:1 μl = 1 mm/mm", ran out of a 35 mm window between "1:1" and
"μl"), and the drawing's texts keep clear below it (200-13's "αmax=34.51°" touched the heading, 1 mm under it)."""
from __future__ import annotations

import math
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


def _points(group: ET.Element, prefix: str) -> dict[str, tuple[tuple[float, float], str]]:
    """The points a figure's group draws (a step's marker: a circle of a point's size), by step key: the
    marker's centre and radius."""
    out = {}
    for g in group.iter(f"{NS}g"):
        key = (g.get("id") or "").removeprefix(prefix)
        c = g.find(f"{NS}circle")
        if key != g.get("id") and c is not None and float(c.get("r")) <= 2.0 and g.get("class", "").startswith("step"):
            out[key] = ((float(c.get("cx")), float(c.get("cy"))), float(c.get("r")))
    return out


def _with_windows() -> list[str]:
    return [p.stem for p in _sheets()]


@pytest.mark.parametrize("pid", _with_windows())
def test_every_named_point_in_a_window_is_drawn_and_labelled_there(pid):
    # 001-06b's and 004-02's M, C4 lay in the mechanism's window at 1:2.5 and were left out; a point the window
    # draws carries its name there (the main view's joined "M, C4" is two names apart in the window)
    from geomcon.problems import load_problem
    from geomcon.solve import solve
    sc = solve(load_problem(ROOT / "problems" / f"{pid}.toml")).drawing_scene
    labels = {s.key: s.label for s in sc.steps if s.label}
    root = ET.fromstring((GALLERY / f"{pid}.svg").read_text(encoding="utf-8"))
    main = _points(next(g for g in root.iter(f"{NS}g") if g.get("id") == "figure"), "step-")
    for name, _, _, texts in windows(ET.tostring(root, encoding="unicode")):
        group = next(g for g in root.iter(f"{NS}g") if g.get("id") == name)
        inside = _points(group, f"{name}-step-")
        both = sorted(k for k in inside if k in main)
        assert len(both) >= 2, name                           # a window shows a knot of the main view
        (p, q), (a, b) = (main[both[0]][0], main[both[-1]][0]), (inside[both[0]][0], inside[both[-1]][0])
        k = math.dist(a, b) / math.dist(p, q)                 # main → window: a scale and a shift
        written = " ".join("".join(t.itertext()) for t in texts)
        pins = [c for c, r in inside.values() if r >= 1.2]     # the mechanism's extent: its hinges (not the margin)
        x0, y0 = min(c[0] for c in pins), min(c[1] for c in pins)
        x1, y1 = max(c[0] for c in pins), max(c[1] for c in pins)
        for key, ((x, y), _) in main.items():
            u, v = a[0] + k * (x - p[0]), a[1] + k * (y - p[1])
            if key in labels and x0 <= u <= x1 and y0 <= v <= y1:
                assert key in inside, (name, key, labels[key])
        for key in inside:
            if key in labels:
                assert labels[key] in written, (name, key, labels[key])


@pytest.mark.parametrize("pid, marks", [("001-06b_crank_slider_redesign_K", ("M", "C4", "αmax=49.08°", "H=101.74")),
                                        ("004-02_best_by_K_1_2_offset_limit", ("M", "C4", "αmax=48.45°", "H=100.00"))])
def test_the_mechanisms_window_carries_the_points_and_marks_in_it(pid, marks):
    # on A4 landscape (the gallery turns both to portrait, at 1:2 without a window; `solve --landscape` keeps
    # them) the main view's knot at 1:5 held M, C4, αmax (at C3) and H (C1–C2): the window at 1:2.5 left them
    # out (001-06b's window grows to hold H's line and value)
    from geomcon.problems import load_problem
    from geomcon.render.page import PageSpec
    from geomcon.solve import solve
    svg = solve(load_problem(ROOT / "problems" / f"{pid}.toml")).sheets(PageSpec("A4", "landscape", "both"))[0]
    (_, _, head, texts), = windows(svg)
    assert "1:2.5" in "".join(head.itertext())
    written = ["".join(t.itertext()) for t in texts]
    assert all(m in written for m in marks), written


def test_a_hinge_by_another_hinges_block_is_a_knot_read_in_a_window():
    # 004-02 (K = 1.5) at 1:2: A* 2 mm off C1's block, θ's and αmax's arcs cut by the block, E's label on it, and
    # no window (A* and C1 6.6 mm apart, two hinges no nearer than a knot's 6 mm): a window at 1:1 now
    from geomcon.render.detail import BLOCK_KNOT, _off_block
    from geomcon.scene.marks import Slider
    from geomcon.geometry.primitives import Point
    assert _off_block(Point(6.0, 3.0), Slider(Point(0, 0), Point(1, 0)), 1.0) == pytest.approx(math.hypot(2.0, 0.5))
    assert abs(_off_block(Point(-12.0, 4.0), Slider(Point(0, 0), Point(1, 0)), 2.0) - 2.0) < 1e-9 and 2.0 < BLOCK_KNOT
    svg = (GALLERY / "004-02_best_by_K_1_5.svg").read_text(encoding="utf-8")
    (name, _, head, texts), = windows(svg)
    assert "1:1" in "".join(head.itertext())
    assert {"A*", "C1", "E", "C3", "θ=36.00°", "αmax=67.68°"} <= {"".join(t.itertext()) for t in texts}
