"""Ruler-and-compass constructions as free functions.

Examples
--------
>>> from geomcon.geometry.primitives import Point
>>> circle_through3(Point(1, 0), Point(0, 1), Point(-1, 0)).center
Point(x=0.0, y=0.0)
>>> perpendicular_bisector(Point(0, 0), Point(2, 0)).point
Point(x=1.0, y=0.0)
>>> point_along(Point(0, 0), Point(10, 0), 3.0)
Point(x=3.0, y=0.0)
>>> reflect(Point(1, 1), Line(Point(0, 0), Point(1, 0)))
Point(x=1.0, y=-1.0)
"""
from __future__ import annotations

import math

from ..errors import Degenerate
from .. import tolerance as _tolerance
from .primitives import Circle, Line, Point, Ray, Segment, unit_xy


def line_through(a: Point, b: Point) -> Line:
    """The line through ``a`` and ``b``, directed from ``a`` to ``b``."""
    return Line.through(a, b)


def segment(a: Point, b: Point) -> Segment:
    """The segment ``ab``."""
    return Segment(a, b)


def circle(center: Point, r: float) -> Circle:
    """The circle about ``center`` with radius ``r``."""
    return Circle(center, r)


def midpoint(a: Point, b: Point) -> Point:
    """Midpoint of ``ab``."""
    return Point((a.x + b.x) / 2.0, (a.y + b.y) / 2.0)


def perpendicular_bisector(a: Point, b: Point) -> Line:
    """The perpendicular bisector of ``ab``, directed to the left of ``a → b``."""
    if a == b:
        raise Degenerate(f"perpendicular bisector of a zero-length chord at ({a.x:.6g}, {a.y:.6g})")
    return Line(midpoint(a, b), (b - a).perp())


def perpendicular(line: Line, through: Point) -> Line:
    """The perpendicular to ``line`` through ``through``, directed to the line's left."""
    d = line.direction
    return Line(through, Point(-d.y, d.x))                  # line.normal, without the property


def parallel(line: Line, through: Point) -> Line:
    """The parallel to ``line`` through ``through``, with the same direction."""
    return Line(through, line.direction)


def foot(line: Line, p: Point) -> Point:
    """The foot of the perpendicular from ``p`` to ``line``."""
    return line.at((p - line.point).dot(line.direction))


def rotate(p: Point, center: Point, angle: float) -> Point:
    """``p`` turned about ``center`` by ``angle`` radians (counter-clockwise positive)."""
    c, s = math.cos(angle), math.sin(angle)
    v = p - center
    return Point(center.x + c * v.x - s * v.y, center.y + s * v.x + c * v.y)


def rotate_ray(ray: Ray, angle: float) -> Ray:
    """The ray turned about its origin by ``angle`` radians (counter-clockwise positive)."""
    c, s = math.cos(angle), math.sin(angle)
    d = ray.direction
    return Ray(ray.origin, Point(c * d.x - s * d.y, s * d.x + c * d.y))


def ray_at_angle(origin: Point, toward: Point, angle: float) -> Ray:
    """The ray from ``origin`` making the signed ``angle`` (radians) with the ray ``origin → toward``.

    >>> d = ray_at_angle(Point(1, 1), Point(1, 5), -math.pi / 2).direction
    >>> round(d.x, 12), round(d.y, 12)
    (1.0, 0.0)
    """
    # rotate_ray(Ray.toward(origin, toward), angle) on floats: the same unit vector, turned, made unit again
    if origin == toward:
        raise Degenerate("ray toward its own origin")
    dx, dy = unit_xy(toward.x - origin.x, toward.y - origin.y)
    c, s = math.cos(angle), math.sin(angle)
    return Ray(origin, Point(c * dx - s * dy, s * dx + c * dy))


def point_along(origin: Point, toward: Point, dist: float) -> Point:
    """The point at signed distance ``dist`` from ``origin`` on the ray towards ``toward``.

    >>> point_along(Point(1, 1), Point(4, 5), 10)
    Point(x=7.0, y=9.0)
    """
    if origin.x == toward.x and origin.y == toward.y:           # origin == toward, without the tuples
        raise Degenerate("ray toward its own origin")
    ux, uy = unit_xy(toward.x - origin.x, toward.y - origin.y)     # Ray.toward(origin, toward).at(dist)
    return Point(origin.x + ux * dist, origin.y + uy * dist)


def point_on_ray(ray: Ray, dist: float) -> Point:
    """The point at distance ``dist`` along ``ray``."""
    return ray.at(dist)


def reflect(p: Point, line: Line) -> Point:
    """Mirror image of ``p`` in ``line``."""
    f = foot(line, p)
    return f * 2.0 - p


def circle_through3(a: Point, b: Point, c: Point) -> Circle:
    """The circle through three points (circumcircle), from two perpendicular bisectors.

    Raises
    ------
    Degenerate
        When the three points are collinear within tolerance (the bisectors do not meet).
    """
    # plain float arithmetic in the order of the vector formulas (perpendicular bisectors met by line_line):
    # the same bits, a tenth of the objects
    abx, aby = b.x - a.x, b.y - a.y
    cbx, cby = c.x - b.x, c.y - b.y
    cax, cay = c.x - a.x, c.y - a.y
    span = max(math.hypot(abx, aby), math.hypot(cbx, cby), math.hypot(cax, cay))
    # Decide collinearity first: two coincident points (a == c) are collinear with any third, and their
    # bisectors would coincide rather than fail to meet.
    if abs(abx * cay - aby * cax) <= _tolerance.REL_TOL * span * span:     # tol(span)·span in place: span ≥ 0
        raise Degenerate(_collinear(a, b, c))
    d1x, d1y = unit_xy(-aby, abx)                       # bisector of ab: through its midpoint, (b − a) turned
    d2x, d2y = unit_xy(-cby, cbx)
    m1x, m1y = (a.x + b.x) / 2.0, (a.y + b.y) / 2.0
    m2x, m2y = (b.x + c.x) / 2.0, (b.y + c.y) / 2.0
    wx, wy = m2x - m1x, m2y - m1y
    sine = d1x * d2y - d1y * d2x
    if abs(sine) <= _tolerance.REL_TOL:                 # tol(1.0): parallel (or coincident) bisectors, collinear
        raise Degenerate(_collinear(a, b, c))
    t = (wx * d2y - wy * d2x) / sine
    o = Point(m1x + d1x * t, m1y + d1y * t)
    return Circle(o, math.hypot(a.x - o.x, a.y - o.y))


def _collinear(a: Point, b: Point, c: Point) -> str:
    return (f"circle through collinear points ({a.x:.6g}, {a.y:.6g}), ({b.x:.6g}, {b.y:.6g}), "
            f"({c.x:.6g}, {c.y:.6g})")


def thales_circle(a: Point, b: Point) -> Circle:
    """The circle on ``ab`` as diameter (every point of it sees ``ab`` under a right angle)."""
    return Circle(midpoint(a, b), math.hypot(b.x - a.x, b.y - a.y) / 2.0)      # abs(b − a), without the Point
