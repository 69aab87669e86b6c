"""Drawing: valid SVG, one group per visible step with its protocol number, frame k computes nothing after
k, deterministic bytes, labels kept off the lines, a self-contained HTML player, frames sharing a view box."""
from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest

from geomcon.geometry import Point, circle, segment
from geomcon.recipes import RECIPES
from geomcon.render import model_extent, render_html, render_svg, write_frames
from geomcon.render.labels import best_offset
from geomcon.scene import Role, Scene, marks

NS = {"svg": "http://www.w3.org/2000/svg"}
CASES = [
    ("crank_rocker.extremes", {"AB": 50.0, "BC": 70.0, "CD": 80.0, "AD": 90.0, "branch": "above"}),
    ("crank_slider.extremes", {"AB": 120.0, "BC": 250.0, "e": 60.0}),
    ("guide_bar.extremes", {"AB": 145.0, "AC": 290.0}),
    ("crank_slider.design_by_K", {"K": 1.5, "H": 50.0, "e": 20.0, "AB": None, "BC": None, "gamma_allow": 20.0}),
]


def _scene(i: int) -> Scene:
    name, given = CASES[i]
    return RECIPES[name].construct(given).scene


@pytest.mark.parametrize("i", range(len(CASES)))
def test_svg_is_xml_with_one_group_per_visible_step(i):
    sc = _scene(i)
    root = ET.fromstring(render_svg(sc))
    groups = {g.get("id"): g for g in root.iter("{http://www.w3.org/2000/svg}g") if (g.get("id") or "").startswith("step-")}
    assert set(groups) == {f"step-{s.key}" for s in sc.visible_steps()}
    for s in sc.visible_steps():
        assert groups[f"step-{s.key}"].get("data-step") == str(sc.number(s.key))


@pytest.mark.parametrize("i", range(len(CASES)))
def test_frame_k_computes_no_later_step(i):
    sc = _scene(i)
    frames = sc.frames()
    k = len(frames) // 2
    render_svg(sc, upto=k)
    later = {s.key for group in frames[k:] for s in group}
    earlier_deps = set(sc.closure([s.key for group in frames[:k] for s in group]))
    assert not any(sc.is_evaluated(key) for key in later - earlier_deps)
    assert sc.stats["steps_evaluated"] < sc.stats["steps_total"]


@pytest.mark.parametrize("i", range(len(CASES)))
def test_output_is_deterministic(i):
    a = render_svg(_scene(i)), render_html(_scene(i))
    b = render_svg(_scene(i)), render_html(_scene(i))
    assert a == b


def test_html_player_is_self_contained_and_has_every_step():
    sc = _scene(0)
    page = render_html(sc, title="t")
    urls = re.findall(r"https?://[^\"' )]+", page)
    assert all(u.startswith(("http://www.w3.org/", "http://www.w3.org")) for u in urls), urls
    assert "<script src" not in page and "<link" not in page and "@import" not in page
    for s in sc.visible_steps():
        assert f'id="step-{s.key}"' in page
    assert f"const N = {len(sc.frames())};" in page


def test_frames_share_the_full_view_box(tmp_path):
    sc = _scene(1)
    files = write_frames(sc, tmp_path)
    assert len(files) == len(sc.frames())
    boxes = {ET.parse(f).getroot().get("viewBox") for f in files}
    widths = {ET.parse(f).getroot().get("width") for f in files}
    assert len(widths) == 1 and len(boxes) == 1
    last = ET.parse(files[-1]).getroot()
    assert any("current" in (g.get("class") or "") for g in last.iter("{http://www.w3.org/2000/svg}g"))


def test_labels_keep_clear_of_the_lines_through_their_point():
    # a point on a horizontal and a vertical line: the label goes into a quadrant, not onto a line
    dx, dy = best_offset((50.0, 50.0), [((0.0, 50.0), (100.0, 50.0)), ((50.0, 0.0), (50.0, 100.0))], [], [], 3.4)
    assert abs(dx) > 1.5 and abs(dy) > 1.5


def test_labels_in_a_recipe_drawing_are_off_their_links():
    sc = _scene(0)
    svg = render_svg(sc)
    root = ET.fromstring(svg)
    # every label of a joint lies at least 1.2 mm of paper from the segments drawn through that joint
    lines = [(float(e.get("x1")), float(e.get("y1")), float(e.get("x2")), float(e.get("y2")))
             for e in root.iter("{http://www.w3.org/2000/svg}line")]
    for t in root.iter("{http://www.w3.org/2000/svg}text"):
        if t.get("class") != "label":
            continue
        x, y = float(t.get("x")), float(t.get("y")) - 1.2
        near = [ln for ln in lines if _dist((x, y), ln) < 1.2]
        assert not near, (t[0].text if len(t) else t.text, near)


def _dist(p, ln):
    x1, y1, x2, y2 = ln
    dx, dy = x2 - x1, y2 - y1
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - x1) * dx + (p[1] - y1) * dy) / L2))
    return math.hypot(p[0] - x1 - t * dx, p[1] - y1 - t * dy)


def test_every_mark_kind_draws():
    sc = Scene("marks")
    A = sc.given("A", Point(0, 0))
    B = sc.given("B", Point(40, 0))
    C = sc.given("C", Point(40, 30))
    sc.add("AB", segment, A, B, caption=("AB", "AB"), style="link", role=Role.RESULT)
    sc.add("k", circle, A, 10.0, caption=("k", "k"), style="path")
    sc.add("ang", marks.angle_mark, A, B, C, "α", 36.87, None, caption=("α", "α"), role=Role.ANNOTATION, style="angle")
    sc.add("ra", marks.right_angle, B, A, C, caption=("⊥", "⊥"), role=Role.ANNOTATION, style="right-angle")
    sc.add("dim", marks.dimension, A, B, "L", 40.0, -5.0, caption=("L", "L"), role=Role.ANNOTATION, style="dim")
    sc.add("gr", marks.ground, A, -math.pi / 2, caption=("g", "g"), role=Role.ANNOTATION, style="ground")
    sc.add("sl", marks.slider, C, Point(1, 0), caption=("s", "s"), role=Role.ANNOTATION, style="slider")
    sc.add("gu", marks.guide, Point(0, -10), Point(40, -10), -1, caption=("gu", "gu"), role=Role.ANNOTATION, style="guide")
    root = ET.fromstring(render_svg(sc))
    for key in ("ang", "ra", "dim", "gr", "sl", "gu", "k", "AB"):
        g = root.find(f".//svg:g[@id='step-{key}']", NS)
        assert g is not None and len(list(g)) >= 1, key
    box = model_extent(sc)
    assert box[0] < -10 + 1e-9 and box[2] > 40
