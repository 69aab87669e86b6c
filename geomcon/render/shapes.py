"""Drawing one step's value on paper: each function returns a list of svgwrite elements.

Every function takes the value, the :class:`~geomcon.render.geometry2d.View` and the style's attributes,
and draws nothing for ``None`` (a candidate that does not exist) or for numbers (measurements appear in the
protocol only).
"""
from __future__ import annotations

import math
from typing import Any

import svgwrite

from ..geometry.primitives import Arc, Circle, Line, Point, Ray, Segment
from ..scene.marks import AngleMark, Dimension, Ground, Guide, RightAngleMark, Slider
from .geometry2d import View, clip_line
from .style import INK, POINT_RADIUS

D = svgwrite.Drawing(profile="full", debug=False)   # an element factory only; never saved


def _attrs(style: dict) -> dict:
    return {k.replace("-", "_"): v for k, v in style.items()}


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n) if n else (1.0, 0.0)


def _pp(view: View, p: Point) -> tuple[float, float]:
    return view.p(p.x, p.y)


def _polyline(points, **kw):
    return D.polyline([(round(x, 3), round(y, 3)) for x, y in points], fill="none", **kw)


def point(p: Point, view: View, style_name: str) -> list:
    """A joint, pivot or construction point."""
    r = POINT_RADIUS.get(style_name, 0.5)
    x, y = _pp(view, p)
    if style_name in ("pivot", "joint", "candidate"):
        color = "#7d8590" if style_name == "candidate" else INK
        return [D.circle((x, y), r, fill="white", stroke=color, stroke_width=0.35)]
    return [D.circle((x, y), r, fill=INK, stroke="none")]


def segment(s: Segment, view: View, st: dict) -> list:
    """A link or a construction segment."""
    return [D.line(_pp(view, s.a), _pp(view, s.b), stroke_linecap="round", **_attrs(st))]


def line(value: Line | Ray, view: View, st: dict) -> list:
    """An infinite line or a ray, clipped to the view box."""
    p = value.origin if isinstance(value, Ray) else value.point
    part = clip_line(p.tuple(), value.direction.tuple(), view.box, ray=isinstance(value, Ray))
    if part is None:
        return []
    return [D.line(view.p(*part[0]), view.p(*part[1]), **_attrs(st))]


def circle(c: Circle, view: View, st: dict) -> list:
    """A full circle (clipped to the figure by the figure's clip path)."""
    return [D.circle(_pp(view, c.center), round(view.length(c.r), 3), fill="none", **_attrs(st))]


def arc_path(center: Point, r: float, start: float, sweep: float, view: View) -> str:
    """SVG path data of a model arc (counter-clockwise from ``start`` through ``sweep`` radians)."""
    if sweep >= 2 * math.pi - 1e-9:
        sweep = 2 * math.pi - 1e-6
    x0, y0 = view.p(center.x + r * math.cos(start), center.y + r * math.sin(start))
    x1, y1 = view.p(center.x + r * math.cos(start + sweep), center.y + r * math.sin(start + sweep))
    rp = round(view.length(r), 3)
    return f"M {x0} {y0} A {rp} {rp} 0 {1 if sweep > math.pi else 0} 0 {x1} {y1}"


def arc(a: Arc, view: View, st: dict) -> list:
    """An arc (e.g. the admissible arc of a θ-circle)."""
    return [D.path(d=arc_path(a.center, a.r, a.start, a.sweep, view), fill="none", stroke_linecap="round", **_attrs(st))]


def angle_mark(m: AngleMark, view: View, st: dict) -> list:
    """The arc of a marked angle and its value."""
    va, vb = m.a - m.vertex, m.b - m.vertex
    if abs(va) == 0 or abs(vb) == 0:
        return []
    a0 = math.atan2(va.y, va.x)
    sweep = math.atan2(va.cross(vb), va.dot(vb))
    if sweep < 0:
        a0, sweep = a0 + sweep, -sweep
    shortest = min(view.length(abs(va)), view.length(abs(vb)))
    r_paper = view.length(m.radius) if m.radius else max(3.0, min(8.0, 0.45 * shortest))
    r = r_paper * view.mu
    out = []
    if sweep > math.radians(0.2):
        out.append(D.path(d=arc_path(m.vertex, r, a0, sweep, view), fill="none", **_attrs(st)))
    mid = a0 + sweep / 2
    tx, ty = view.p(m.vertex.x + (r + 4.2 * view.mu) * math.cos(mid), m.vertex.y + (r + 4.2 * view.mu) * math.sin(mid))
    out.append(D.text(m.text, insert=(tx, round(ty + 1.0, 3)), text_anchor="middle", class_="mark-text"))
    return out


def right_angle(m: RightAngleMark, view: View, st: dict) -> list:
    """The little square of a right angle."""
    v = _pp(view, m.vertex)
    u = _unit((_pp(view, m.a)[0] - v[0], _pp(view, m.a)[1] - v[1]))
    w = _unit((_pp(view, m.b)[0] - v[0], _pp(view, m.b)[1] - v[1]))
    s = 2.0
    pts = [(v[0] + u[0] * s, v[1] + u[1] * s), (v[0] + (u[0] + w[0]) * s, v[1] + (u[1] + w[1]) * s),
           (v[0] + w[0] * s, v[1] + w[1] * s)]
    return [_polyline(pts, **_attrs(st))]


def _arrow(tip: tuple[float, float], toward: tuple[float, float]) -> Any:
    u = _unit((toward[0] - tip[0], toward[1] - tip[1]))
    n = (-u[1], u[0])
    L, W = 1.8, 0.5
    pts = [tip, (tip[0] + u[0] * L + n[0] * W, tip[1] + u[1] * L + n[1] * W),
           (tip[0] + u[0] * L - n[0] * W, tip[1] + u[1] * L - n[1] * W)]
    return D.polygon([(round(x, 3), round(y, 3)) for x, y in pts], fill=INK, stroke="none")


def dimension(m: Dimension, view: View, st: dict) -> list:
    """A linear dimension: extension lines, the dimension line with arrowheads, the value."""
    d = m.b - m.a
    if abs(d) == 0:
        return []
    n = d.unit().perp() * m.offset
    a2, b2 = m.a + n, m.b + n
    over = n.unit() * (1.2 * view.mu) if abs(n) else Point(0, 0)
    pa, pb = _pp(view, a2), _pp(view, b2)
    out = [D.line(_pp(view, m.a), _pp(view, a2 + over), **_attrs(st)),
           D.line(_pp(view, m.b), _pp(view, b2 + over), **_attrs(st)),
           D.line(pa, pb, **_attrs(st)), _arrow(pa, pb), _arrow(pb, pa)]
    ang = math.degrees(math.atan2(pb[1] - pa[1], pb[0] - pa[0]))
    if ang > 90 or ang <= -90:
        ang -= 180 * (1 if ang > 0 else -1)
    mx, my = (pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2
    nx, ny = math.sin(math.radians(ang)), -math.cos(math.radians(ang))
    t = D.text(m.text, insert=(round(mx + nx * 1.0, 3), round(my + ny * 1.0, 3)), text_anchor="middle", class_="mark-text")
    t.rotate(round(ang, 3), center=(round(mx + nx * 1.0, 3), round(my + ny * 1.0, 3)))
    return out + [t]


def ground(m: Ground, view: View, st: dict) -> list:
    """The hatched ground symbol of a fixed pivot: a triangle to a hatched base."""
    x, y = _pp(view, m.at)
    u = (math.cos(m.angle), -math.sin(m.angle))
    n = (-u[1], u[0])
    h, w = 3.2, 2.4
    bx, by = x + u[0] * h, y + u[1] * h
    e1, e2 = (bx + n[0] * w, by + n[1] * w), (bx - n[0] * w, by - n[1] * w)
    out = [_polyline([e1, (x, y), e2], **_attrs(st)),
           D.line((round(bx + n[0] * (w + 1), 3), round(by + n[1] * (w + 1), 3)),
                  (round(bx - n[0] * (w + 1), 3), round(by - n[1] * (w + 1), 3)), **_attrs(st))]
    for k in range(6):
        s = -(w + 1) + k * (2 * w + 2) / 5
        p0 = (bx + n[0] * s, by + n[1] * s)
        p1 = (p0[0] + (u[0] - n[0]) * 1.2, p0[1] + (u[1] - n[1]) * 1.2)
        out.append(D.line((round(p0[0], 3), round(p0[1], 3)), (round(p1[0], 3), round(p1[1], 3)), stroke=INK, stroke_width=0.2))
    return out


def slider(m: Slider, view: View, st: dict) -> list:
    """A slider block centred on its joint, aligned with its direction of motion."""
    x, y = _pp(view, m.at)
    u = _unit((m.direction.x, -m.direction.y))
    n = (-u[1], u[0])
    a, b = 3.5, 2.2
    pts = [(x + s * u[0] * a + t * n[0] * b, y + s * u[1] * a + t * n[1] * b) for s, t in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    return [D.polygon([(round(px, 3), round(py, 3)) for px, py in pts], fill="white", fill_opacity=0.85, **_attrs(st))]


def guide(m: Guide, view: View, st: dict) -> list:
    """A straight guide with hatching on one side."""
    pa, pb = _pp(view, m.a), _pp(view, m.b)
    u = _unit((pb[0] - pa[0], pb[1] - pa[1]))
    n = (u[1] * m.side, -u[0] * m.side)          # model left = paper right-hand normal (y flipped)
    off = 2.4
    out = [D.line((round(pa[0] + n[0] * off, 3), round(pa[1] + n[1] * off, 3)),
                  (round(pb[0] + n[0] * off, 3), round(pb[1] + n[1] * off, 3)), **_attrs(st))]
    L = math.hypot(pb[0] - pa[0], pb[1] - pa[1])
    k = 0.0
    while k <= L:
        p0 = (pa[0] + u[0] * k + n[0] * off, pa[1] + u[1] * k + n[1] * off)
        p1 = (p0[0] + (n[0] - u[0]) * 1.3, p0[1] + (n[1] - u[1]) * 1.3)
        out.append(D.line((round(p0[0], 3), round(p0[1], 3)), (round(p1[0], 3), round(p1[1], 3)), stroke=INK, stroke_width=0.2))
        k += 2.5
    return out


def draw(value: Any, view: View, style_name: str, st: dict) -> list:
    """Dispatch on the value's type."""
    if value is None or isinstance(value, (bool, int, float)):
        return []
    if isinstance(value, Point):
        return point(value, view, style_name)
    table = {Segment: segment, Line: line, Ray: line, Circle: circle, Arc: arc, AngleMark: angle_mark,
             RightAngleMark: right_angle, Dimension: dimension, Ground: ground, Slider: slider, Guide: guide}
    fn = table.get(type(value))
    if fn is None:
        if isinstance(value, tuple):
            return [e for v in value for e in draw(v, view, style_name, st)]
        return []
    return fn(value, view, st)
