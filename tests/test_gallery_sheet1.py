"""Sheet 1 of every gallery drawing holds its Results block, and its Warnings block when the problem has
warnings (issue 11, hlook11 item A1): the answer the title asks for is read beside the drawing, never only on a
later sheet. The drawing keeps the standard scale it gets with the whole frame to itself: the blocks go into the
drawing's free room (:func:`geomcon.render.svg.results_in_free_room`), where they meet no drawn element."""
from __future__ import annotations

import json
import re
from functools import lru_cache
from pathlib import Path

import pytest
import shapely

from gallery_pages import page_of
from geomcon.paper import Scale
from geomcon.problems import load_problem
from geomcon.render.free_area import CLEAR
from geomcon.render.shapes import obstacle
from geomcon.render.svg import (_boxes, _layouts, _not_diagram, aside_views, place_figure, results_in_free_room,
                                 sheet_one, split)
from geomcon.render.warning_words import warning_lines
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
NO_ROOM: dict[str, str] = {}
"""Drawings whose free room holds no box for their results, not even for their brief lines (one per result, the
doubtful printed answers in one warning: :func:`geomcon.render.results.brief_warnings`): they would keep a sheet of
their own. Empty since 000-03, 000-05, 000-06, 000-07 and 100-07 print their results in brief on sheet 1 (their
full lines 206, 106 + 8 warnings, 356, 338 and 60 mm tall found no box there; 100-07's went whole into a band at
1:2, now in brief at 1:1; 200-15's went in brief, now whole beside it set aside); the list may only stay empty."""
FREE_ROOM = ["000-04_slotter_cam_psi0", "001-01_crank_rocker_change_point", "001-04_guide_bar_offset",
             "001-06_crank_slider", "001-07_crank_slider_strokes", "001-13_radar_antenna_K1",
             "001-14_crank_rocker_K1_frame_angles", "001-15_crank_rocker_frame_and_position",
             "001-17_crank_rocker_theta", "001-24_cam_displacement_at_100",
             "200-03_cam_roller_undercut", "200-16_cam_poly_4567", "200-17_cam_table_law",
             "200-20_oscillating_base_radius_rho", "400-05_crank_slider_instant_centres"]
"""The drawings that kept their results off sheet 1 before (hlook11 item A1) and now set them in free room at
the scale they get with the frame to themselves (000-04: results and warnings apart)."""
ASIDE = {"100-04_four_bar_fixed_pivots_coupler_angles": "1:1", "200-14_oscillating_arm_speeds": "1:2",
         "200-15_cam_handbook_laws": "1:2"}
"""Drawings whose results no one box of the free room holds with the drawing centred in its area: the drawing set
against a side of it (:func:`geomcon.render.svg.aside_views`), one box holds them whole at the scale the drawing
gets with the frame to itself. 100-04 was drawn at 1:2 with its results in a column reserved for them, half the
sheet empty (at 1:1 centred it left 41 mm either side); 200-14 split them in two boxes; 200-15 printed them in
brief, in full on a sheet of their own."""
RESERVED = {"300-01_four_bar_double_rocker_pressure_angle": "1:1"}
"""Drawings whose results no box of the free room holds at their scale, whole, in two boxes or in brief, the drawing
centred or set aside: one block in room reserved for it (a column at the right, a band above the title block), the
drawing at that layout's scale, the last resort: 300-01 at 2.5:1 → 1:1 (it had them in three boxes, the third
inside the four-bar). 100-04 and 100-07 were here at 1:1 → 1:2 while a drawing kept half its scale to keep one
block: the sheet half empty, 100-07's three rods EF one thick line; they keep 1:1 now (:data:`ASIDE`, :data:`BRIEF`)."""
BRIEF = {"000-03_slotter_velocity_polygons": "1:5", "100-07_rocker_slider_three_positions": "1:1",
         "200-01_cam_roller_offset": "1:1"}
"""Drawings whose results no one box holds at their scale, centred or set aside, nor two boxes outside the figure
in reading order: their brief lines in one box of the free room at that scale (100-07 set aside, at 1:1 where it was
drawn at 1:2; 000-03 whole instead of split in two boxes; 200-01 on A4 portrait at 1:1, where landscape drew it at 1:2
with its results in full),
in full on the next sheet (200-15 set "Results" touching its s–δ chart's caption row)."""
BRIEF_CENTRED = {"200-01_cam_roller_offset"}
"""Drawings of :data:`BRIEF` whose brief lines one box holds beside the figure centred (not set aside)."""


def _heads(svg: str, cls: str) -> list[str]:
    """The texts of the block headings of class ``cls`` (``info-head``: Results, ``warning-head``: Warnings)."""
    return re.findall(rf'<text [^>]*class="{cls}"[^>]*>(?:<tspan>)?([^<]*)<', svg)


def _drawings() -> list[tuple[Path, Path]]:
    return [(j, j.with_suffix(".svg")) for j in sorted(GALLERY.glob("*.json")) if j.with_suffix(".svg").exists()]


def test_sheet_one_of_every_drawing_holds_its_results_and_warnings():
    drawings = _drawings()
    assert len(drawings) > 80
    missing = {}
    for js, svg in drawings:
        data = json.loads(js.read_text(encoding="utf-8"))
        text = svg.read_text(encoding="utf-8")
        if 'class="sheet"' not in text:
            continue                                       # not a drawing sheet (a chart)
        lost = []
        if not any("Results" in h for h in _heads(text, "info-head")):
            lost.append("Results")
        if data.get("warnings") and not any("Warnings" in h for h in _heads(text, "warning-head")):
            lost.append("Warnings")
        if lost:
            missing[js.stem] = lost
    assert set(missing) <= set(NO_ROOM), {k: v for k, v in missing.items() if k not in NO_ROOM}


@lru_cache(maxsize=None)
def _solution(pid: str):
    return solve(load_problem(ROOT / "problems" / f"{pid}.toml"))


def _scale(svg: str) -> Scale:
    return Scale.parse(re.search(r'class="tb tb-2-0"[^>]*>[^<]*?(\d+(?:\.\d+)?:\d+(?:\.\d+)?)<', svg).group(1))


def _sheet_one(pid: str):
    sol = _solution(pid)
    page = page_of(pid)
    sc = sol.drawing_scene
    info, warnings = sol.figure_lines(page.lang), warning_lines(sol.warnings, page.lang)
    from geomcon.render.results import brief_warnings
    brief = (sol.figure_lines(page.lang, brief=True), brief_warnings(sol.warnings, page.lang, "{sheet}"))
    one = sheet_one(sc, page, info, warnings, sol.info_steps(), brief=brief)
    keep = _not_diagram if one.apart else None                # a cam's s–δ diagram on a sheet of its own
    _, free_scale, _ = place_figure(sc, page, (), (), keep=keep)
    return sol, page, info, warnings, one, free_scale


@pytest.mark.parametrize("pid", FREE_ROOM + sorted(ASIDE) + sorted(BRIEF))
def test_results_in_free_room_meet_no_drawn_element_and_cost_no_scale(pid):
    """The Results (and Warnings) box, grown by the clearance, meets none of the figure's strokes, marks,
    symbols or texts; the drawing is at the scale it gets with no room reserved for the results; the SVG sets the
    block where the box is (:data:`BRIEF`: the brief lines)."""
    sol, page, info, warnings, one, free_scale = _sheet_one(pid)
    placed, scale, fig = one.layout, one.scale, one.fig
    assert placed.info_here and placed not in _layouts(page, info, warnings)      # in free room, none reserved
    assert scale == free_scale
    assert (one.info is not info) == (pid in BRIEF)
    info, warnings = one.info, one.warnings
    assert not split(placed)
    from geomcon.render.protocol import info_height
    x, y = placed.info_at
    if not placed.pieces:
        boxes = [(x, y + 4.0, x + placed.info_w, y + info_height(info, placed.info_w, warnings))]
        shown = len(info)
    else:
        boxes = [(pc.x, pc.y + 4.0, pc.x + pc.w,
                  pc.y + info_height([info[i] for i in pc.rows], pc.w, warnings if pc.warnings else ()))
                 for pc in placed.pieces]
        rows = [i for pc in placed.pieces for i in pc.rows]
        assert sorted(rows) == list(range(len(info)))         # every result once
        assert sum(pc.warnings for pc in placed.pieces) == bool(warnings)
        shown = len(rows)
    assert shown == len(info)
    for a in range(len(boxes)):                               # the pieces do not overlap
        for b in range(a):
            assert not shapely.box(*boxes[a]).intersects(shapely.box(*boxes[b])), pid
    drawn = [obstacle(s) for g in fig.groups for s in g.shapes]
    assert len(drawn) > 10
    for b in boxes:
        grown = shapely.box(b[0] - CLEAR, b[1] - CLEAR, b[2] + CLEAR, b[3] + CLEAR)
        assert not any(grown.intersects(d) for d in drawn), (pid, b)
    svg = sol.sheets(page)[0]
    assert _scale(svg) == scale
    first = re.search(r'<g id="info">.*?<text class="info-head"[^>]*\bx="([\d.]+)"', svg, re.S)
    assert first and abs(float(first.group(1)) - x) < 0.01


@pytest.mark.parametrize("pid", sorted(RESERVED))
def test_results_that_no_box_holds_whole_go_into_reserved_room(pid):
    """One Results block in a layout that reserves room for it, at the scale named (:data:`RESERVED`)."""
    sol, page, info, warnings, one, free_scale = _sheet_one(pid)
    assert one.layout in _layouts(page, info, warnings) and one.layout.info_here and not one.layout.pieces
    assert str(one.scale) == RESERVED[pid] and one.scale < free_scale
    assert one.info is info
    fig, sl, page, lines, warned, scale, avoid = _at_free_scale(pid)       # the last resort, the drawing centred or
    for f in [fig] + _aside_figures(pid):                                  # set aside: no box, nor two, holds the
        assert results_in_free_room(f, sl, page, info, warnings, scale, sol.info_steps(), avoid) is None   # results,
        brief = results_in_free_room(f, sl, page, lines, warned, scale, sol.info_steps(), avoid)     # no one box
        assert brief is None or split(brief)                                                             # the brief
    svg = sol.sheets(page)[0]
    assert _scale(svg) == one.scale
    assert [h for h in _heads(svg, "info-head")] == ["Results  结果"]


@pytest.mark.parametrize("pid", sorted(ASIDE) + sorted(set(BRIEF) - BRIEF_CENTRED))
def test_a_drawing_is_set_aside_when_centred_it_leaves_no_box_for_its_results(pid):
    """:data:`ASIDE`, :data:`BRIEF` (100-07): at the scale the drawing gets with the frame to itself (100-04 and
    100-07 at 1:1, were 1:2), set against a side of its area, not centred; centred, no one box held the lines it
    prints (the brief ones of :data:`BRIEF`)."""
    sol, page, info, warnings, one, free_scale = _sheet_one(pid)
    assert str(one.scale) == (ASIDE | BRIEF)[pid] and one.scale == free_scale
    sl, scale, view = place_figure(sol.drawing_scene, page, info, warnings, keep=_not_diagram if one.apart else None)
    assert one.view.mu == view.mu and one.view.box == view.box and one.view.origin != view.origin
    assert one.view.origin in [v.origin for v in aside_views(view, sl.area)]
    fig, sl, page, lines, warned, scale, avoid = _at_free_scale(pid)
    if pid in ASIDE:
        lines, warned = info, warnings
    centred = results_in_free_room(fig, sl, page, lines, warned, scale, sol.info_steps(), avoid)
    assert centred is None or split(centred)
    assert _scale(sol.sheets(page)[0]) == one.scale


def _aside_figures(pid: str):
    """The figure of ``pid`` at the scale it gets with the frame to itself, set against each side of its area."""
    from geomcon.render.figure import build_figure, text_room
    sol, page, info, warnings, one, _ = _sheet_one(pid)
    sc, keep = sol.drawing_scene, _not_diagram if one.apart else None
    sl, _, view = place_figure(sc, page, info, warnings, keep=keep)
    return [build_figure(sc, None, v.box, v.origin, mu=v.mu, keep=keep, room=text_room(v, sl.area))
            for v in aside_views(view, sl.area)]


def _at_free_scale(pid: str):
    """The figure at the scale it gets with the frame to itself, its layout, the page and its brief lines, the
    scale and the chart marks' boxes: the arguments of ``results_in_free_room``."""
    from geomcon.render.figure import build_figure, text_room
    from geomcon.render.page import document
    from geomcon.render.results import brief_warnings
    from geomcon.render.svg import _figure_and_marks
    sol, page, info, warnings, one, _ = _sheet_one(pid)
    sc, keep = sol.drawing_scene, _not_diagram if one.apart else None
    sl, scale, view = place_figure(sc, page, info, warnings, keep=keep)
    fig = build_figure(sc, None, view.box, view.origin, mu=view.mu, keep=keep, room=text_room(view, sl.area))
    _, marks = _figure_and_marks(document(page.sheet), sc, fig, scale, not one.apart)
    lines = [ln.replace("{sheet}", "2") for ln in sol.figure_lines(page.lang, brief=True)]
    warned = [ln.replace("{sheet}", "2") for ln in brief_warnings(sol.warnings, page.lang, "{sheet}")]
    return fig, sl, page, lines, warned, scale, _boxes(marks)


def _split_sheets() -> list[str]:
    return [svg.stem for _, svg in _drawings() if "Results (1/" in svg.read_text(encoding="utf-8")]


SPLIT_CENTRED = ("000-03_slotter_velocity_polygons", "200-14_oscillating_arm_speeds")
"""Drawings whose results (000-03's in brief) two boxes of the free room hold with the drawing centred: the
gallery printed them so until the drawing was set aside (:data:`ASIDE`, :data:`BRIEF`), where one box holds them.
The split is checked on these centred drawings, as no gallery sheet splits its results now."""


def _centred_split(pid: str):
    """The centred figure of ``pid`` at the scale it gets with the frame to itself and its results (in brief when
    the full ones find no room) in the boxes of its free room."""
    fig, sl, page, lines, warned, scale, avoid = _at_free_scale(pid)
    sol, _, info, warnings, _, _ = _sheet_one(pid)
    placed = results_in_free_room(fig, sl, page, info, warnings, scale, sol.info_steps(), avoid)
    return fig, placed or results_in_free_room(fig, sl, page, lines, warned, scale, sol.info_steps(), avoid)


def test_no_sheet_splits_its_results_in_more_than_two_boxes():
    """A reader reads one block; when the free room has no box for it, two at most (300-01 had three)."""
    for _, svg in _drawings():
        text = svg.read_text(encoding="utf-8")
        assert not re.search(r"Results \(\d+/([3-9]|\d\d)\)", text), svg.stem


@pytest.mark.parametrize("pid", sorted(set(_split_sheets()) | set(SPLIT_CENTRED)))
def test_a_piece_of_split_results_lies_outside_the_figure(pid):
    """No box of a split Results block meets the convex hull of the figure's drawn elements (300-01's third box
    lay inside the four-bar ABCD, between its links)."""
    if pid in SPLIT_CENTRED:
        fig, sl = _centred_split(pid)
    else:
        sol, page, _, _, one, _ = _sheet_one(pid)
        fig, sl = one.fig, one.layout
    assert split(sl)
    hull = shapely.convex_hull(shapely.GeometryCollection([obstacle(s) for g in fig.groups for s in g.shapes]))
    for pc in sl.pieces:
        assert not hull.intersects(shapely.box(pc.x, pc.y + 4.0, pc.x + pc.w, pc.y + pc.h)), (pid, pc)


@pytest.mark.parametrize("pid", SPLIT_CENTRED)
def test_the_pieces_of_a_centred_split_read_in_order(pid):
    """The results' pieces in reading order: the first piece's rows before the second's, and the first above the
    second, or side by side to its left."""
    _, sl = _centred_split(pid)
    a, b = [pc for pc in sl.pieces if pc.rows]
    assert max(a.rows) < min(b.rows) or not set(a.rows) & set(b.rows)
    above = a.y + a.h <= b.y or b.y + b.h <= a.y
    assert (a.y < b.y) if above else (a.x < b.x), (pid, a, b)


def _parts(svg: str) -> dict[int, tuple[float, float, float]]:
    """The numbered parts of a split Results block: k -> (x, top, bottom) of its lines (paper mm)."""
    out = {}
    for m in re.finditer(r'<g id="info(?:-\d+)?">(.*?)</g>', svg, re.S):
        head = re.search(r'class="info-head"[^>]*\bx="([\d.]+)"[^>]*\by="([\d.]+)"[^>]*>(?:<tspan>)?Results \((\d+)/\d+\)',
                         m.group(1))
        if head:
            ys = [float(y) for y in re.findall(r'<text [^>]*\by="([\d.]+)"', m.group(1))]
            out[int(head.group(3))] = (float(head.group(1)), min(ys) - 3.5, max(ys))
    return out


def test_the_parts_of_a_split_results_block_read_in_order():
    """Results (1/3), (2/3), (3/3) read in that order: top to bottom, then, side by side, left to right (100-04 and
    300-01 had (2/3) above (1/3))."""
    split = 0
    for _, svg in _drawings():
        parts = _parts(svg.read_text(encoding="utf-8"))
        if not parts:
            continue
        split += 1
        assert sorted(parts) == list(range(1, len(parts) + 1)), svg.stem
        for k in range(1, len(parts)):
            (xa, ta, ba), (xb, tb, bb) = parts[k], parts[k + 1]
            above = ba <= tb or bb <= ta
            assert (ta < tb) if above else (xa < xb), (svg.stem, k, parts)
