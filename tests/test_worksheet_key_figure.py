"""The key's construction as a teacher lays it over a sheet: drawn at the sheet's scale (labels as high as the
sheet's), nothing of it cut away, nothing beyond the frame below the answer boxes (review item 43)."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
import shapely

from geomcon.geometry.primitives import Circle, Point, Segment
from geomcon.render.draw import COMPASS_HALF, compass_parts
from geomcon.render.style import resolve_style
from geomcon.render.shapes import Text, obstacle, text_polygon
from geomcon.worksheet import _assigned
from geomcon.worksheet.key_pages import key_figure, key_keep, key_room
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.sheets import make_pages
from geomcon.worksheet.spec import load_spec

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "tests" / "data" / "worksheet_class.toml"
U = 100.0
EPS = 1e-6


@pytest.fixture(scope="module")
def pages():
    spec = load_spec(SPEC)
    return [p for p in make_pages(spec, _assigned(spec, numbered(6), "A4", "both", None), "both") if p.part != "sd"]


def _font_sizes(svg: str, pattern: str) -> set[float]:
    return {float(x) for x in re.findall(pattern, svg)}


def test_the_key_s_labels_are_as_high_as_the_sheet_s():
    """Paper mm of a point label: the sheet's (page units / 100) and the key's (the nested figure's font size
    times its paper mm per view unit) are one size, on every page of the gallery's worksheet."""
    folder = ROOT / "gallery" / "worksheet"
    keys = sorted((folder / "key").glob("*.svg"))
    assert keys
    for key in keys:
        sheet = (folder / "sheets" / key.name).read_text()
        svg = key.read_text()
        m = re.search(r'<svg height="(\d+)" id="construction" viewBox="0 0 ([\d.]+) ([\d.]+)" width="(\d+)"', svg)
        assert m, key
        per_unit = float(m.group(4)) / U / float(m.group(2))  # paper mm per view unit (width in 0.01 mm: ±1e-5)
        inner = svg[m.start():]
        key_sizes = {round(s * per_unit, 3) for s in _font_sizes(inner, r'<text class="label"[^>]*font-size="([\d.]+)"')}
        givens = sheet[sheet.index('id="givens"'):]
        givens = givens[:givens.find('id="sd-axes"')] if 'id="sd-axes"' in givens else givens     # not the axes' texts
        sheet_sizes = {round(s / U, 6) for s in _font_sizes(givens, r'<text fill="#000" font-size="(\d+)" stroke="none"')}
        sheet_sizes.discard(3.0)                                     # the scale note "1:1" under the figure
        assert key_sizes and sheet_sizes, key
        assert key_sizes == sheet_sizes, (key.name, key_sizes, sheet_sizes)


def _inside(b: tuple[float, float, float, float], box: tuple[float, float, float, float]) -> bool:
    return b[0] >= box[0] - EPS and b[1] >= box[1] - EPS and b[2] <= box[2] + EPS and b[3] <= box[3] + EPS


def _beyond_the_frame(q: tuple[float, float], box, rect, room) -> bool:
    """Whether the model point ``q`` outside the view ``box`` (paper ``rect``) lies beyond a side of it that is
    the frame line (left, right or bottom: the top is the answer boxes' edge)."""
    return ((q[0] < box[0] and abs(rect[0] - room[0]) < EPS) or (q[0] > box[2] and abs(rect[2] - room[2]) < EPS)
            or (q[1] < box[1] and abs(rect[3] - room[3]) < EPS)) and not q[1] > box[3] + EPS


def test_nothing_of_the_key_s_construction_is_cut_away(pages):
    """Every drawn point and segment of the key's construction lies inside its view, so nothing the student
    constructs is clipped; a circle (whole or a compass arc) leaves the view only through the frame line (a
    θ-circle too large for the sheet runs on beyond it, as the sheet's given circles do); every shape and text lies inside the view, and the
    view inside the frame below the answer boxes. Six students' pages: all three recipes, several variants."""
    for p in pages:
        rect, fig = key_figure(p)
        room = key_room(p)
        assert _inside(rect, room), (p.name, rect, room)
        box = fig.view.box
        sc = p.sol.drawing_scene
        keep = key_keep(p.sol)
        pts = tuple(v for v in fig.values.values() if isinstance(v, Point))
        for s in sc.visible_steps():
            if not keep(s) or s.key not in fig.values:
                continue
            v = fig.values[s.key]
            for x in (v if isinstance(v, (tuple, list)) else (v,)):
                if isinstance(x, Point):
                    assert _inside((x.x, x.y, x.x, x.y), box), (p.name, s.key)
                elif isinstance(x, Segment):
                    b = (min(x.a.x, x.b.x), min(x.a.y, x.b.y), max(x.a.x, x.b.x), max(x.a.y, x.b.y))
                    assert _inside(b, box), (p.name, s.key)
                elif isinstance(x, Circle):
                    if resolve_style(s.style, s.role, "curve").compass:     # the short arcs through its points
                        half = max(math.radians(6.0), min(math.pi, COMPASS_HALF / fig.view.length(x.r)))
                        angles = [start + sweep * i / 64 for start, sweep in compass_parts(x, pts, half)
                                  for i in range(65)]
                    else:
                        angles = [math.tau * i / 256 for i in range(256)]
                    for a in angles:
                        q = (x.center.x + x.r * math.cos(a), x.center.y + x.r * math.sin(a))
                        assert _inside(q + q, box) or _beyond_the_frame(q, box, rect, room), (p.name, s.key, q)
        vw, vh = fig.view.size
        for sd in fig.groups:
            for shape in sd.shapes:
                geom = text_polygon(shape) if isinstance(shape, Text) else obstacle(shape)
                if geom is None or shapely.is_empty(geom):
                    continue
                assert _inside(geom.bounds, (0.0, 0.0, vw, vh)), (p.name, sd.key, geom.bounds)


def test_the_key_draws_the_chosen_solution_alone(pages):
    """The key of a design by K draws the textbook's choice's construction (its θ-circle, F and A candidate),
    not the other solution's (whose θ-circle and F run far beyond the sheet)."""
    p = next(p for p in pages if p.ex.recipe == "crank_rocker.design_by_K")
    _, fig = key_figure(p)
    keys = {g.key for g in fig.groups}
    assert {"nkTheta", "F_1", "A_1", "A", "B1", "B2"} <= keys
    assert not keys & {"fkTheta", "F_2", "A_2", "farcs_ok", "other_designs"}
