"""Step operations and drawing helpers shared by the linkage recipes.

Examples
--------
>>> from geomcon.geometry import Point
>>> round(angle_deg(Point(0, 0), Point(1, 0), Point(1, 1)), 12)
45.0
>>> round(transmission_deg(Point(0, 1), Point(0, 0), Point(1, 1)), 12)
45.0
>>> k_ratio(36.0)
1.5
"""
from __future__ import annotations

import math

from ..geometry import Point, angle_at, distance
from ..scene import Ref, Role, Scene
from ..scene import marks


def angle_deg(vertex: Point, a: Point, b: Point) -> float:
    """∠a-vertex-b in degrees, in [0, 180]."""
    return math.degrees(angle_at(vertex, a, b))


def transmission_deg(b: Point, c: Point, d: Point) -> float:
    """Transmission angle at joint ``c`` between links c–b and c–d: the acute form of ∠BCD, in degrees."""
    g = angle_deg(c, b, d)
    return min(g, 180.0 - g)


def pressure_on_guide_deg(b: Point, c: Point, guide_dir: Point) -> float:
    """Pressure angle at a slider ``c`` driven by the rod c–b, moving along ``guide_dir``: the acute angle
    between the rod and the guide's direction, in degrees."""
    a = math.degrees(angle_at(Point(0.0, 0.0), b - c, guide_dir))
    return min(a, 180.0 - a)


def complement_deg(x: float) -> float:
    """90° − x."""
    return 90.0 - x


def k_ratio(theta: float) -> float:
    """K = (180° + θ)/(180° − θ)."""
    return (180.0 + theta) / (180.0 - theta)


def length(a: Point, b: Point) -> float:
    """Distance ab (a measurement step operation)."""
    return distance(a, b)


def smallest(*values: float) -> float:
    """The smallest of the values."""
    return min(values)


def difference(a: float, b: float) -> float:
    """a − b (a helper number, e.g. the radius BC − AB)."""
    return a - b


def total(a: float, b: float) -> float:
    """a + b."""
    return a + b


def add_pivot(sc: Scene, key: str, at: Point, caption: tuple[str, str], *, ground_angle: float = -math.pi / 2) -> Ref:
    """A fixed pivot: the given point plus its hatched ground symbol."""
    ref = sc.given(key, at, caption=caption, style="pivot")
    sc.add(f"{key}_ground", marks.ground, ref, ground_angle, role=Role.ANNOTATION, style="ground",
           caption=(f"Ground symbol at {key}", f"在 {key} 处画固定铰链"), visible=True)
    return ref


def add_bar(sc: Scene, key: str, a: Ref, b: Ref, name: tuple[str, str], *, style: str = "link",
            role: Role = Role.RESULT) -> Ref:
    """A link drawn as a bar between two joints."""
    from ..geometry import segment
    return sc.add(key, segment, a, b, role=role, style=style, caption=name)


def add_angle_mark(sc: Scene, key: str, vertex: Ref, a: Ref, b: Ref, symbol: str, value: Ref,
                   radius: float | None = None) -> Ref:
    """The arc marking a measured angle, labelled with its value."""
    return sc.add(key, marks.angle_mark, vertex, a, b, symbol, value, radius, role=Role.ANNOTATION,
                  style="angle", caption=(f"Mark the angle {symbol}", f"标注角 {symbol}"))


def along_line(line, t: float) -> Point:
    """The point at signed distance ``t`` along a line from its reference point."""
    return line.at(t)


def pressure_deg(b: Point, c: Point, guide) -> float:
    """Pressure angle at a slider ``c`` pushed by the rod c–b along ``guide`` (a Line): the acute angle
    between the rod and the guide, in degrees."""
    return pressure_on_guide_deg(b, c, guide.direction)


def largest(*values: float) -> float:
    """The largest of the values."""
    return max(values)


def guide_angle_mark(c: Point, b: Point, guide, symbol: str, value: float, radius: float | None = None):
    """Angle mark at slider ``c`` between the rod c→b and the guide, on the side where the angle is acute."""
    d = guide.direction
    if (b - c).dot(d) < 0:
        d = -d
    return marks.AngleMark(c, b, c + d, symbol, value, radius)


def guide_between(p: Point, q: Point, guide, margin: float, side: int = -1):
    """A hatched guide along ``guide`` covering the projections of ``p`` and ``q`` plus ``margin``."""
    u = guide.direction
    t = sorted(((p - guide.point).dot(u), (q - guide.point).dot(u)))
    return marks.Guide(guide.at(t[0] - margin), guide.at(t[1] + margin), side)
