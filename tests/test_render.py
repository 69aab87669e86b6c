"""Drawing: valid SVG with one group per visible step, frame k computes nothing after k, deterministic bytes,
labels kept off the lines, every value and mark type drawn, a self-contained HTML player, frames sharing
one view box."""
from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest
import shapely

from geomcon.geometry import Arc, Line, Point, Ray, circle, segment
from geomcon.recipes import RECIPES
from geomcon.recipes.crank_rocker import construct
from geomcon.render import model_extent, render_html, render_svg, write_frames
from geomcon.render.svg import render_sheets
from geomcon.render.svg import frame_of
from geomcon.render.figure import build_figure
from geomcon.render.placement import Placer, Request
from geomcon.render.shapes import Poly
from geomcon.render.style import HIGHLIGHT, STYLES, resolve_style
from geomcon.render.view import choose_scale
from geomcon.scene import Role, Scene, marks

SVG = "{http://www.w3.org/2000/svg}"
GIVEN = {"AB": 50, "BC": 70, "CD": 80, "AD": 90, "branch": "above"}
OTHERS = [
    ("crank_slider.extremes", {"AB": 120.0, "BC": 250.0, "e": 60.0}),
    ("guide_bar.extremes", {"AB": 145.0, "AC": 290.0}),
    ("crank_slider.design_by_K", {"K": 1.5, "H": 50.0, "e": 20.0, "gamma_allow": 20.0}),
]


def crank_rocker() -> Scene:
    return construct(GIVEN).scene


def marks_scene() -> Scene:
    """A tiny hand-built scene with every value and mark type."""
    sc = Scene("every mark")
    A = sc.given("A", Point(0, 0), caption=("Take A", "取 A"), style="pivot")
    sc.add("A_ground", marks.ground, A, -math.pi / 2, role=Role.ANNOTATION, style="ground",
           caption=("Ground at A", "A 处机架"))
    B = sc.given("B", Point(40, 0), caption=("Take B", "取 B"))
    C = sc.given("C", Point(40, 30), caption=("Take C", "取 C"), style="joint")
    sc.add("AB", segment, A, B, caption=("Join AB", "连接 AB"), style="link", role=Role.RESULT)
    sc.add("BC", segment, B, C, caption=("Join BC", "连接 BC"), style="link-alt", role=Role.RESULT)
    sc.add("AC", Line.through, A, C, caption=("The line AC", "直线 AC"))
    sc.add("ray", Ray.toward, B, A, caption=("The ray from B through A", "射线 BA"), style="given")
    sc.add("k", circle, A, 10.0, caption=("Circle about A", "以 A 为圆心作圆"), style="path")
    sc.add("arc", Arc, B, 12.0, 0.5, 1.5, caption=("An arc about B", "以 B 为圆心作弧"), style="construction")
    sc.add("ang", marks.angle_mark, A, B, C, "α", 36.87, None, caption=("Mark α", "标注 α"),
           role=Role.ANNOTATION, style="angle")
    sc.add("ra", marks.right_angle, B, A, C, caption=("Right angle at B", "B 处直角"), role=Role.ANNOTATION,
           style="right-angle")
    sc.add("dim", marks.dimension, A, B, "L", 40.0, -8.0, caption=("Dimension AB", "标注 AB"),
           role=Role.ANNOTATION, style="dim")
    sc.add("sl", marks.slider, C, Point(1, 0), caption=("Slider at C", "C 处滑块"), role=Role.ANNOTATION,
           style="slider")
    sc.add("gu", marks.guide, Point(20, 30), Point(60, 30), -1, caption=("Guide", "导路"), role=Role.ANNOTATION,
           style="guide")
    sc.add("len", lambda p, q: abs(q - p), A, C, caption=("Measure AC", "量得 AC"), role=Role.MEASUREMENT, unit="mm")
    return sc


def step_groups(root: ET.Element) -> dict[str, list[ET.Element]]:
    out: dict[str, list[ET.Element]] = {}
    for g in root.iter(f"{SVG}g"):
        if (g.get("id") or "").startswith("step-"):
            out.setdefault(g.get("id"), []).append(g)
    return out


def text_of(el: ET.Element) -> str:
    return "".join(el.itertext())


# ---------------------------------------------------------------------------------------------- structure
@pytest.mark.parametrize("build", [crank_rocker, marks_scene])
def test_svg_parses_with_exactly_one_group_per_visible_step(build):
    sc = build()
    root = ET.fromstring(render_svg(sc))
    assert root.get("width").endswith("mm") and root.get("viewBox").startswith("0 0 ")
    groups = step_groups(root)
    assert set(groups) == {f"step-{s.key}" for s in sc.visible_steps()}
    for s in sc.visible_steps():
        (g,) = groups[f"step-{s.key}"]
        assert g.get("data-step") == str(sc.number(s.key))
        assert "step" in g.get("class").split() and f"role-{s.role.value}" in g.get("class")


@pytest.mark.parametrize("name, given", OTHERS)
def test_other_recipes_draw_every_visible_step(name, given):
    sc = RECIPES[name].construct(given).scene
    groups = step_groups(ET.fromstring(render_svg(sc)))
    assert set(groups) == {f"step-{s.key}" for s in sc.visible_steps()}


def test_every_value_and_mark_type_draws_something():
    sc = marks_scene()
    sheets = render_sheets(sc)
    root = ET.fromstring(sheets[0])
    groups = step_groups(root)
    for key in ("A", "A_ground", "AB", "AC", "ray", "k", "arc", "ang", "ra", "dim", "sl", "gu"):
        assert len(list(groups[f"step-{key}"][0])) >= 1, key
    assert len(list(groups["step-len"][0])) == 0              # a measurement draws nothing...
    proto = ET.fromstring(sheets[1]).find(f".//{SVG}g[@id='proto-len']")     # the protocol is on sheet 2
    assert "Measure AC = 50.000 mm" in text_of(proto)        # ...but is printed with its value
    assert "α=36.87°" in text_of(groups["step-ang"][0])


def test_measurement_value_is_appended_to_its_protocol_line():
    sc = crank_rocker()
    root = ET.fromstring(render_sheets(sc)[1])
    line = text_of(root.find(f".//{SVG}g[@id='proto-theta']"))
    assert "θ = ∠C1AC2 = 12.506°" in line
    assert "量得极位夹角" in line


def test_point_labels_use_subscripts_and_keep_primes():
    root = ET.fromstring(render_svg(crank_rocker()))
    label = next(t for t in step_groups(root)["step-C1"][0].iter(f"{SVG}text"))
    spans = list(label)
    assert [s.text for s in spans] == ["C", "1"] and spans[1].get("dy") and spans[1].get("font-size")
    prime = next(t for t in step_groups(root)["step-Bg2"][0].iter(f"{SVG}text"))
    assert text_of(prime) == "B′′"


def test_infinite_lines_are_clipped_to_the_figure():
    sc = marks_scene()
    fig = build_figure(sc)
    x0, y0, x1, y1 = fig.view.paper_box
    for key in ("AC", "ray"):
        (shape,) = next(g for g in fig.groups if g.key == key).shapes
        for x, y in shape.pts:
            assert x0 - 1e-9 <= x <= x1 + 1e-9 and y0 - 1e-9 <= y <= y1 + 1e-9
        assert max(abs(shape.pts[1][0] - shape.pts[0][0]), abs(shape.pts[1][1] - shape.pts[0][1])) > 10


# ---------------------------------------------------------------------------------------------- determinism
def test_output_is_deterministic():
    sc = crank_rocker()
    a, b = render_svg(sc, info=["x = 1"]), render_svg(sc, info=["x = 1"])
    assert a == b
    assert render_svg(crank_rocker(), info=["x = 1"]) == a          # a fresh scene of the same problem
    assert render_html(sc) == render_html(crank_rocker())
    assert render_svg(sc, upto=7) == render_svg(crank_rocker(), upto=7)


def test_no_counter_based_or_random_ids():
    svg = render_svg(crank_rocker())
    ids = re.findall(r' id="([^"]+)"', svg)
    assert len(ids) == len(set(ids))
    assert not [i for i in ids if re.fullmatch(r"[a-z]+\d+", i) and not i.startswith(("step-", "proto-"))], ids


# ---------------------------------------------------------------------------------------------- laziness
@pytest.mark.parametrize("k", [1, 5, 8, 14])
def test_frame_k_evaluates_no_later_step(k):
    sc = crank_rocker()
    frames = sc.frames()
    shown = [s.key for group in frames[:k] for s in group]
    svg = render_svg(sc, upto=k)
    need = set(sc.closure(shown))
    assert sc.stats["steps_evaluated"] == len(need)
    assert not any(sc.is_evaluated(s.key) for group in frames[k:] for s in group if s.key not in need)
    groups = step_groups(ET.fromstring(svg))
    assert set(groups) == {f"step-{key}" for key in shown}
    current = [gid for gid, (g,) in groups.items() if "current" in g.get("class").split()]
    assert sorted(current) == sorted(f"step-{s.key}" for s in frames[k - 1])
    assert f'data-step="{k + 1}"' not in svg


def test_current_step_is_drawn_in_the_highlight_colour():
    sc = crank_rocker()
    k = sc.number("C1")
    (g,) = step_groups(ET.fromstring(render_svg(sc, upto=k)))["step-C1"]
    assert HIGHLIGHT in ET.tostring(g, encoding="unicode")
    (g,) = step_groups(ET.fromstring(render_svg(sc, upto=k + 1)))["step-C1"]
    assert HIGHLIGHT not in ET.tostring(g, encoding="unicode")


def test_viewbox_none_is_the_model_extent():
    sc = crank_rocker()
    box = model_extent(sc)
    assert box[0] < -50 and box[2] > 90                        # B'' at x = -50, D at x = 90
    assert render_svg(sc, viewbox=box) == render_svg(sc)


# ---------------------------------------------------------------------------------------------- labels
def test_labels_keep_clear_of_the_segments_through_their_point():
    sc = crank_rocker()
    fig = build_figure(sc)
    segs = [sh for g in fig.groups for sh in g.shapes if isinstance(sh, Poly) and len(sh.pts) == 2
            and g.layer in ("links", "construction", "given")]
    checked = 0
    for g in fig.groups:
        value = fig.values[g.key]
        if not isinstance(value, Point) or not g.texts:
            continue
        p = fig.view.p(value)
        (label,) = g.texts
        box = shapely.box(*label.box)
        through = [s for s in segs if min(math.dist(p, q) for q in s.pts) < 1e-6]
        for s in through:
            assert box.distance(shapely.LineString(s.pts)) >= 0.3, (g.key, label.runs)
        checked += len(through)
    assert checked >= 10


def test_placer_puts_a_label_into_a_free_quadrant():
    lines = [(shapely.LineString([(0, 50), (100, 50)]), "h", 0.0), (shapely.LineString([(50, 0), (50, 100)]), "v", 0.0)]
    cx, cy = Placer(lines, (0, 0, 100, 100)).place(Request((50.0, 50.0), 3.0, 2.6, 1.0, 0.0), "p")
    assert abs(cx - 50) > 1.5 + 0.3 and abs(cy - 50) > 1.3 + 0.3


def test_labels_do_not_overlap_each_other():
    fig = build_figure(crank_rocker())
    boxes = [shapely.box(*t.box) for g in fig.groups for t in g.texts if t.cls == "label"]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a.intersection(b).area == 0.0


# ---------------------------------------------------------------------------------------------- HTML, frames
def test_html_player_is_self_contained_and_has_every_step():
    sc = crank_rocker()
    page = render_html(sc, title="t", info=["θ = 12.5°"])
    urls = re.findall(r"https?://[^\"'\s<>)]+", page)
    assert set(urls) <= {"http://www.w3.org/2000/svg", "http://www.w3.org/1999/xlink", "http://www.w3.org/1999/xhtml",
                         "http://www.w3.org/2001/xml-events"}, urls
    assert "<script src" not in page and "<link" not in page and "@import" not in page and "url(" not in page
    for s in sc.visible_steps():
        assert page.count(f'id="step-{s.key}"') == 1
    for i, group in enumerate(sc.frames(), 1):
        assert f'id="proto-{group[0].key}" data-step="{i}"' in page or (
            f'data-step="{i}"' in page and f'id="proto-{group[0].key}"' in page)
    for word in ('id="prev"', 'id="next"', 'id="play"', 'type="range"', "ArrowLeft", "ArrowRight", ".future"):
        assert word in page
    assert "作图步骤" in page and "Circle about D" in page


def test_write_frames_writes_one_file_per_step_with_one_view_box(tmp_path):
    sc = crank_rocker()
    files = write_frames(sc, tmp_path / "frames", title="t")
    n = len(sc.frames())
    assert [f.name for f in files] == [f"step-{k:03d}.svg" for k in range(1, n + 1)]
    roots = [ET.parse(f).getroot() for f in files]
    assert len({r.get("viewBox") for r in roots}) == 1 and len({r.get("width") for r in roots}) == 1
    assert files[4].read_text(encoding="utf-8") == frame_of(render_svg(sc, title="t"), 5)   # the full drawing, cut
    assert not list((tmp_path / "frames").glob(".*"))          # no temporary left behind


# ---------------------------------------------------------------------------------------------- styles, scale
def test_style_table_and_defaults():
    for name in ("pivot", "joint", "point", "given", "frame", "construction", "link", "link-alt", "ghost", "path",
                 "ground", "slider", "guide", "angle", "dim", "right-angle"):
        assert name in STYLES
    assert resolve_style("", Role.RESULT, "curve").name == "link"
    assert resolve_style("nonsense", Role.CONSTRUCTION, "curve").name == "construction"
    assert resolve_style("", Role.ANNOTATION, "Slider").name == "slider"


@pytest.mark.parametrize("size", [0.37, 3.0, 48.0, 160.0, 900.0, 12345.0])
def test_scale_is_nice_and_the_figure_about_150_mm_wide(size):
    mu = choose_scale(size, size / 2, margin=10.0)
    mantissa = mu / 10 ** math.floor(math.log10(mu))
    assert any(math.isclose(mantissa, m) for m in (1.0, 2.0, 2.5, 5.0))
    assert 95.0 <= size / mu + 20.0 <= 215.0


def test_supplementary_angle_mark_is_drawn_at_its_value():
    # γ = 40° marked on rays whose angle is 140°: the arc spans the extension of the first ray
    sc = Scene("supplement")
    V = sc.given("V", Point(0, 0))
    a = sc.given("a", Point(-30, 0))
    b = sc.given("b", Point(30 * math.cos(math.radians(40)), 30 * math.sin(math.radians(40))))
    sc.add("m", marks.angle_mark, V, a, b, "γ", 40.0, None, role=Role.ANNOTATION, style="angle",
           caption=("γ", "γ"))
    fig = build_figure(sc)
    arc = next(s for s in next(g for g in fig.groups if g.key == "m").shapes if type(s).__name__ == "ArcP")
    assert math.isclose(abs(arc.sweep), math.radians(40.0))


def test_the_results_of_frame_k_are_only_those_of_steps_up_to_k():
    """Issue 11: each result appears at the step that produces it; nothing later shows early (frames and the
    player carry the step of each result line; the full figure shows them all)."""
    import re
    from pathlib import Path
    from geomcon.problems import load_problem
    from geomcon.solve import solve

    root = Path(__file__).resolve().parents[1]
    for name in ("001-08_crank_rocker.toml", "001-10_crank_rocker_design_coupler.toml", "200-01_cam_roller_offset.toml"):
        sol = solve(load_problem(root / "problems" / name))
        sheets = "".join(sol.sheets())             # the results are on sheet 1 or, beside a larger drawing, 2
        n = len(sol.frames())
        frames = [frame_of(sheets, k) for k in range(1, n + 1)]
        n_results = len(sol.info_lines())
        shown = re.compile(r'<text class="info" data-step="(\d+)"')
        for k, frame in enumerate(frames, 1):
            steps = [int(s) for s in shown.findall(frame)]
            assert all(s <= k for s in steps), (name, k, steps)
        full = shown.findall(sheets)
        assert len(full) >= n_results and max(map(int, full)) <= len(frames)
        assert len(shown.findall(frames[0])) < len(full)
