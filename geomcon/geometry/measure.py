"""Measurements: distances and angles, in radians unless the name says degrees.

Examples
--------
>>> from geomcon.geometry.primitives import Point
>>> distance(Point(0, 0), Point(3, 4))
5.0
>>> round(math.degrees(angle_at(Point(0, 0), Point(1, 0), Point(0, 2))), 12)
90.0
>>> round(math.degrees(signed_angle(Point(1, 0), Point(0, -1))), 12)
-90.0
"""
from __future__ import annotations

import math

from ..errors import Degenerate
from .primitives import Line, Point


def distance(a: Point, b: Point) -> float:
    """Euclidean distance between two points."""
    return math.hypot(b.x - a.x, b.y - a.y)


def _half_open(a: float) -> float:
    """Map ``atan2``'s −π (a negative zero or a negative underflow over a negative abscissa) to π."""
    return math.pi if a == -math.pi else a


def signed_angle(u: Point, v: Point) -> float:
    """The angle turning vector ``u`` into vector ``v``, in (−π, π], counter-clockwise positive.

    >>> signed_angle(Point(-1, 0), Point(1, 0)) == math.pi      # a half turn is +π, never −π
    True
    """
    return _signed_angle_xy(u.x, u.y, v.x, v.y)


def _signed_angle_xy(ux: float, uy: float, vx: float, vy: float) -> float:
    if math.hypot(ux, uy) == 0.0 or math.hypot(vx, vy) == 0.0:
        raise Degenerate("angle of a zero-length vector")
    return _half_open(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy))


def angle_between(u: Point, v: Point) -> float:
    """The unsigned angle between two vectors, in [0, π]."""
    return abs(_signed_angle_xy(u.x, u.y, v.x, v.y))


def angle_at(vertex: Point, a: Point, b: Point) -> float:
    """The unsigned angle ∠a-vertex-b in [0, π].

    >>> round(math.degrees(angle_at(Point(0, 0), Point(1, 0), Point(1, 1))), 12)
    45.0
    """
    ox, oy = vertex.x, vertex.y
    return abs(_signed_angle_xy(a.x - ox, a.y - oy, b.x - ox, b.y - oy))


def line_angle(l1: Line, l2: Line) -> float:
    """The acute (or right) angle between two undirected lines, in [0, π/2]."""
    a = angle_between(l1.direction, l2.direction)
    return min(a, math.pi - a)


def signed_distance(line: Line, p: Point) -> float:
    """Distance of ``p`` from ``line``, positive on the line's left."""
    return line.direction.cross(p - line.point)


def polar_angle(center: Point, p: Point) -> float:
    """Polar angle of ``p`` seen from ``center``, in (−π, π].

    >>> polar_angle(Point(0, 0), Point(-1, -0.0)) == math.pi
    True
    """
    return _half_open(math.atan2(p.y - center.y, p.x - center.x))
