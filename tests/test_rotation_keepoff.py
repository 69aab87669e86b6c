"""The arrow ω of a cam's sense of rotation and the ground symbols keep off what they should (hlook11m's review,
session m): ω picks the side of its centre that crosses no dimension line (200-09, 200-19 and 001-30b drew it
across r0's or s's dimension), a ground keeps off the circles and wide bands drawn (the limit bands at 200-19's O,
the crank circle at 001-19's A)."""
from __future__ import annotations

import math
import re
from pathlib import Path

import shapely

from geomcon.geometry import Point
from geomcon.render.draw import Context
from geomcon.render.shapes import Disc, Pen, Poly
from geomcon.render.style import STYLES
from geomcon.render.symbols import draw_ground, rotation_arc
from geomcon.render.view import View
from geomcon.scene.marks import Ground, Rotation

GALLERY = Path(__file__).resolve().parent.parent / "gallery"
NUM = r"(-?[\d.]+)"


def _group(svg: str, key: str) -> str:
    m = re.search(rf'<g [^>]*id="step-{re.escape(key)}">(.*?)</g>', svg, flags=re.S)
    return m.group(1) if m else ""


def _omega_arc(svg: str, centre: tuple[float, float]) -> shapely.LineString:
    m = re.search(rf'd="M{NUM} {NUM}A[\d.]+ [\d.]+ 0 [01] ([01]) {NUM} {NUM}"', _group(svg, "omega"))
    x0, y0, sweep, x1, y1 = (float(v) for v in m.groups())
    a0 = math.atan2(y0 - centre[1], x0 - centre[0])
    d = (math.atan2(y1 - centre[1], x1 - centre[0]) - a0) % math.tau
    if sweep == 0:
        d -= math.tau
    r = math.hypot(x0 - centre[0], y0 - centre[1])
    return shapely.LineString([(centre[0] + r * math.cos(a0 + d * k / 40), centre[1] + r * math.sin(a0 + d * k / 40))
                               for k in range(41)])


def _dimension_strokes(svg: str) -> list[shapely.LineString]:
    out = []
    for key in re.findall(r'id="step-(dim_[^"]*)"', svg):
        for d in re.findall(r'd="(M[^"]*)"', _group(svg, key)):
            pts = [tuple(map(float, p)) for p in re.findall(rf"[ML]{NUM} {NUM}", d)]
            if len(pts) >= 2:
                out.append(shapely.LineString(pts))
    return out


def test_omega_crosses_no_dimension_line_at_o() -> None:
    """200-09's ω ran across r0's dimension line and s0's arrowhead, 200-19's across r0,α's, 001-30b's across
    the s dimension's arrowhead: on every sheet where ω turns about O, its arc keeps off every dimension."""
    for name in ("200-09_base_radius_cycloidal", "200-19_base_radius_alpha_and_rho", "001-30b_eccentric_flat_R60",
                 "200-10_base_radius_centred", "200-11_base_radius_rise_and_return"):
        svg = (GALLERY / f"{name}.svg").read_text(encoding="utf-8")
        c = re.search(rf'cx="{NUM}" cy="{NUM}"', _group(svg, "O"))
        arc = _omega_arc(svg, (float(c.group(1)), float(c.group(2))))
        near = [round(arc.distance(s), 2) for s in _dimension_strokes(svg) if arc.distance(s) < 0.3]
        assert not near, (name, near)


def test_rotation_turns_off_a_dimension() -> None:
    """A dimension line straight above the centre: the arrow turns to a side that keeps off it."""
    ctx = Context(View((-20.0, -20.0, 20.0, 20.0), 1.0, (0.0, 0.0)))
    ctx.dims = (((15.0, 14.0), (25.0, 14.0)),)                # 6 mm above the centre (20, 20)
    arc = rotation_arc(Rotation(Point(0, 0), 1.0), ctx)
    line = shapely.LineString([arc.at(k / 30) for k in range(31)])
    assert line.distance(shapely.LineString(ctx.dims[0])) >= 1.0


def test_ground_keeps_off_a_circle() -> None:
    """A circle about the hinge 6 mm out (a crank's circle at a small scale, a base circle): the ground hung
    straight down would hatch across it; it shrinks inside it instead."""
    ctx = Context(View((-20.0, -20.0, 20.0, 20.0), 1.0, (0.0, 0.0)))
    ctx.strokes = ((Disc((20.0, 20.0), 6.0, Pen("#000", 0.25)), 0.125),)
    out = draw_ground(Ground(Point(0, 0)), STYLES["ground"], ctx)
    ring = shapely.Point(20.0, 20.0).buffer(6.0, 64).exterior
    assert all(shapely.LineString(s.pts).distance(ring) > 0.3 for s in out.shapes)


def test_ground_keeps_off_a_band_through_its_hinge() -> None:
    """Two wide limit bands crossing at the hinge, 120° apart below it (200-09's and 200-19's O): the ground
    stands between them, its hatch across neither."""
    ctx = Context(View((-20.0, -20.0, 20.0, 20.0), 1.0, (0.0, 0.0)))
    bands = []
    for deg in (30.0, 150.0):
        u = (math.cos(math.radians(deg)), math.sin(math.radians(deg)))
        bands.append((Poly(((20 - 15 * u[0], 20 - 15 * u[1]), (20 + 15 * u[0], 20 + 15 * u[1])), Pen("#000", 1.6)), 0.8))
    ctx.strokes = tuple(bands)
    out = draw_ground(Ground(Point(0, 0)), STYLES["ground"], ctx)
    far = [shapely.LineString(s.pts).difference(shapely.Point(20, 20).buffer(3.0)) for s in out.shapes]
    assert all(f.is_empty or f.distance(shapely.LineString(b.pts)) > 0.8 for f in far for b, _ in bands)


def _arc_points(x0: float, y0: float, r: float, large: int, sweep: int, x1: float, y1: float
                ) -> list[tuple[float, float]]:
    """Points along an SVG circular arc (endpoint form) on paper."""
    mx, my, dx, dy = (x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2
    half = math.hypot(dx, dy)
    h = math.sqrt(max(r * r - half * half, 0.0)) * (1 if large != sweep else -1)
    cx, cy = mx - h * dy / half, my + h * dx / half
    a0, a1 = math.atan2(y0 - cy, x0 - cx), math.atan2(y1 - cy, x1 - cx)
    d = (a1 - a0) % math.tau if sweep else -((a0 - a1) % math.tau)
    n = max(8, int(abs(d) * r / 0.3))
    return [(cx + r * math.cos(a0 + d * k / n), cy + r * math.sin(a0 + d * k / n)) for k in range(n + 1)]


def _strokes_of(svg: str, styles: tuple[str, ...]) -> list[tuple[shapely.Geometry, float]]:
    """The paths and circles drawn by the steps of ``styles``, with half their stroke width."""
    out = []
    for m in re.finditer(r'<g class="step [^"]*style-([\w-]+)[^"]*"[^>]*>(.*?)</g>', svg, flags=re.S):
        if m.group(1) not in styles:
            continue
        for el in re.findall(r"<(?:path|circle) [^>]*>", m.group(2)):
            w = float(re.search(rf'stroke-width="{NUM}"', el).group(1)) / 2
            if el.startswith("<circle"):
                cx, cy, r = (float(re.search(rf' {k}="{NUM}"', el).group(1)) for k in ("cx", "cy", "r"))
                out.append((shapely.Point(cx, cy).buffer(r, 256).exterior, w))
                continue
            d = re.search(r'd="([^"]*)"', el).group(1)
            a = re.fullmatch(rf"M{NUM} {NUM}A{NUM} [\d.]+ 0 ([01]) ([01]) {NUM} {NUM}", d)
            if a:
                x0, y0, r, large, sweep, x1, y1 = (float(v) for v in a.groups())
                out.append((shapely.LineString(_arc_points(x0, y0, r, int(large), int(sweep), x1, y1)), w))
            else:
                pts = [tuple(map(float, p)) for p in re.findall(rf"[ML]{NUM} {NUM}", d)]
                if len(pts) >= 2:
                    out.append((shapely.LineString(pts), w))
    return out


def test_grounds_keep_off_circles_and_bands() -> None:
    """hlook11m's review: 001-12's A hatched across the green admissible arc, 001-19's A across the crank circle,
    200-19's and 200-09's O across the green limit bands. Beyond 3 mm of its hinge (where a circle or band through
    the hinge leaves it), no stroke of those grounds comes within half the band's width of it."""
    cases = (("001-12_crank_rocker_frame_line", "A", ("admissible", "theta-circle")),
             ("001-19_slotter_rotating_guide_bar", "A", ("theta-circle", "given", "link")),
             ("200-09_base_radius_cycloidal", "O", ("admissible",)),
             ("200-19_base_radius_alpha_and_rho", "O", ("admissible",)))
    for name, pivot, styles in cases:
        svg = (GALLERY / f"{name}.svg").read_text(encoding="utf-8")
        c = re.search(rf'cx="{NUM}" cy="{NUM}"', _group(svg, pivot))
        hinge = shapely.Point(float(c.group(1)), float(c.group(2))).buffer(3.0)
        ground = [shapely.LineString([tuple(map(float, p)) for p in re.findall(rf"[ML]{NUM} {NUM}", d)])
                  for d in re.findall(r'd="(M[^"]*)"', _group(svg, f"{pivot}_ground"))]
        ground = [g.difference(hinge) for g in ground]
        hits = [(round(g.distance(s), 2), w) for g in ground for s, w in _strokes_of(svg, styles)
                if not g.is_empty and g.distance(s) < w + 0.1]
        assert not hits, (name, hits)
