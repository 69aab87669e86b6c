"""Helpers for testing code built on geomcon: comparing points, and named degenerate configurations.

:func:`assert_points_close` compares two points, or two intersection results point by point, with an
absolute and a scale-relative allowance. The fixture builders return the *operands* of one geometric
operation in a named degenerate (or nearly degenerate) configuration, so that a test reads
``circle_circle(*tangent_pair())`` and a failure names the configuration it broke on.

Every builder takes the same placement keywords:

``scale``
    multiplies every length (the same configuration drawn at 1e-3 mm or at 1e6 mm);
``at``
    translates the configuration (its first point or centre is ``at``);
``angle``
    turns the configuration about ``at`` (radians, counter-clockwise).

Placing a configuration rounds its coordinates. The builders that promise an exact relation (tangency,
a relative ``gap``) let one free length -- a radius -- absorb that rounding, so that the relation holds
to a few ulp of the configuration's scale wherever it is put.

Examples
--------
>>> from geomcon.geometry import circle_circle, line_circle, line_line
>>> circle_circle(*tangent_pair(3.0, 2.0))
(Point(x=3.0, y=0.0),)
>>> circle_circle(*concentric())
()
>>> len(line_circle(*tangent_line(scale=1e6, at=Point(-4e6, 2.5e6), angle=0.3)))
1
>>> line_line(*parallel_lines())
()
>>> assert_points_close(Point(1.0, 2.0), Point(1.0, 2.0 + 1e-15), rel=1e-12)
>>> assert_points_close((Point(0, 0),), (), atol=1.0)
Traceback (most recent call last):
...
AssertionError: 1 point(s) against 0 point(s)
"""
from __future__ import annotations

import math
from typing import Sequence, Union

from .geometry.primitives import Circle, Line, Point
from .tolerance import CHECK_REL

__all__ = [
    "ORIGIN", "assert_points_close", "coincident_circles", "coincident_lines", "collinear3", "concentric",
    "internally_tangent", "parallel_lines", "tangent_line", "tangent_pair", "zero_chord",
]

ORIGIN = Point(0.0, 0.0)
"""The default placement."""

Points = Union[Point, Sequence[Point]]


def _magnitude(p: Point) -> float:
    return max(abs(p.x), abs(p.y))


def assert_points_close(a: Points, b: Points, *, atol: float = 0.0, rel: float = CHECK_REL) -> None:
    """Assert that two points, or two sequences of points taken in order, agree.

    Each pair passes when ``|a - b| <= atol + rel * m``, where ``m`` is the largest coordinate magnitude of
    the pair (so ``rel`` is relative to the position, as coordinate rounding is).

    Parameters
    ----------
    a, b : Point or sequence of Point
        Two points, or two intersection results (tuples of points) compared element by element; a
        sequence never matches a single point.
    atol : float
        Absolute allowance, in the unit of the coordinates.
    rel : float
        Allowance relative to the largest coordinate magnitude of the pair.

    Raises
    ------
    AssertionError
        With the offending pair, their distance and the allowance.

    Examples
    --------
    >>> assert_points_close(Point(1e6, 0.0), Point(1e6 + 1e-7, 0.0), rel=1e-12)
    >>> assert_points_close(Point(0, 0), Point(0, 1e-9))
    Traceback (most recent call last):
    ...
    AssertionError: points differ by 1e-09 > 1e-18 allowed: Point(x=0.0, y=0.0) vs Point(x=0.0, y=1e-09)
    """
    if isinstance(a, Point) and isinstance(b, Point):
        pairs = [(a, b)]
    elif isinstance(a, Point) or isinstance(b, Point):
        raise AssertionError(f"a point against a sequence: {a!r} vs {b!r}")
    else:
        a, b = tuple(a), tuple(b)
        if len(a) != len(b):
            raise AssertionError(f"{len(a)} point(s) against {len(b)} point(s)")
        pairs = list(zip(a, b))
    for p, q in pairs:
        gap = math.hypot(p.x - q.x, p.y - q.y)
        allowed = atol + rel * max(_magnitude(p), _magnitude(q))
        if not gap <= allowed:
            raise AssertionError(f"points differ by {gap:.6g} > {allowed:.6g} allowed: {p!r} vs {q!r}")


def _place(x: float, y: float, at: Point, angle: float, scale: float) -> Point:
    """The local point ``(x, y)`` scaled, turned by ``angle`` and moved to ``at`` (one rounding per step)."""
    c, s = math.cos(angle), math.sin(angle)
    x, y = x * scale, y * scale
    return Point(at.x + (c * x - s * y), at.y + (s * x + c * y))


def _direction(angle: float) -> Point:
    return Point(math.cos(angle), math.sin(angle))


def tangent_pair(r1: float = 3.0, r2: float = 2.0, *, gap: float = 0.0, at: Point = ORIGIN,
                 angle: float = 0.0, scale: float = 1.0) -> tuple[Circle, Circle]:
    """Two circles touching from outside: ``circle_circle`` gives one point, ``r1`` from the first centre.

    ``gap`` makes them nearly tangent: the centre distance is ``(1 + gap)`` times the sum of the radii
    (``gap > 0`` apart, ``gap < 0`` crossing). The second radius absorbs the rounding of the second centre.

    Examples
    --------
    >>> tangent_pair()
    (Circle(center=Point(x=0.0, y=0.0), r=3.0), Circle(center=Point(x=5.0, y=0.0), r=2.0))
    """
    c1 = Point(at.x, at.y)
    c2 = _place(r1 + r2, 0.0, at, angle, scale)
    d = abs(c2 - c1)
    return Circle(c1, r1 * scale), Circle(c2, d / (1.0 + gap) - r1 * scale)


def internally_tangent(r1: float = 3.0, r2: float = 1.0, *, gap: float = 0.0, at: Point = ORIGIN,
                       angle: float = 0.0, scale: float = 1.0) -> tuple[Circle, Circle]:
    """A circle of radius ``r2`` inside one of radius ``r1 > r2``, touching it from inside (one point).

    ``gap`` makes them nearly tangent: the centre distance is ``(1 + gap)`` times ``r1 - r2`` (``gap > 0``
    crossing in two points, ``gap < 0`` nested without contact). The second radius absorbs the rounding.
    Swap the two circles to test the other order.

    Examples
    --------
    >>> internally_tangent()
    (Circle(center=Point(x=0.0, y=0.0), r=3.0), Circle(center=Point(x=2.0, y=0.0), r=1.0))
    """
    if not r1 > r2:
        raise ValueError("internally_tangent needs r1 > r2")
    c1 = Point(at.x, at.y)
    c2 = _place(r1 - r2, 0.0, at, angle, scale)
    d = abs(c2 - c1)
    return Circle(c1, r1 * scale), Circle(c2, r1 * scale - d / (1.0 + gap))


def concentric(r1: float = 3.0, r2: float = 1.5, *, at: Point = ORIGIN, angle: float = 0.0,
               scale: float = 1.0) -> tuple[Circle, Circle]:
    """Two circles about the same centre with different radii: no intersection, ``()``.

    Examples
    --------
    >>> concentric(scale=2.0)
    (Circle(center=Point(x=0.0, y=0.0), r=6.0), Circle(center=Point(x=0.0, y=0.0), r=3.0))
    """
    c = Point(at.x, at.y)
    return Circle(c, r1 * scale), Circle(c, r2 * scale)


def coincident_circles(r: float = 2.0, *, at: Point = ORIGIN, angle: float = 0.0,
                       scale: float = 1.0) -> tuple[Circle, Circle]:
    """The same circle built twice: ``circle_circle`` raises :class:`~geomcon.errors.Coincident`."""
    c = Point(at.x, at.y)
    return Circle(c, r * scale), Circle(Point(c.x, c.y), r * scale)


def tangent_line(r: float = 2.0, *, gap: float = 0.0, at: Point = ORIGIN, angle: float = 0.0,
                 scale: float = 1.0) -> tuple[Line, Circle]:
    """A line touching a circle of radius ``r`` about ``at`` (one point, the foot from the centre).

    The line runs in direction ``angle`` with the centre on its left, ``r`` away; its anchor lies ``r``
    before the tangent point, so the anchor is not the answer. ``gap`` makes it nearly tangent: the
    centre's distance from the line is ``(1 + gap)`` times the radius (``gap > 0`` missing, ``gap < 0``
    cutting). The radius absorbs the rounding of the anchor.

    Examples
    --------
    >>> tangent_line()
    (Line(point=Point(x=-2.0, y=-2.0), direction=Point(x=1.0, y=0.0)), Circle(center=Point(x=0.0, y=0.0), r=2.0))
    """
    c = Point(at.x, at.y)
    u = _direction(angle)
    p = _place(-r, -r, at, angle, scale)
    line = Line(p, u)
    dist = abs(line.direction.cross(p - c))
    return line, Circle(c, dist / (1.0 + gap))


def collinear3(*, at: Point = ORIGIN, angle: float = 0.0, scale: float = 1.0) -> tuple[Point, Point, Point]:
    """Three distinct points on one line: ``circle_through3`` raises :class:`~geomcon.errors.Degenerate`.

    Exactly collinear when ``angle`` is 0; otherwise collinear within the rounding of the placed
    coordinates, which is far inside the tolerance as long as ``|at|`` is not much larger than ``scale``.

    Examples
    --------
    >>> collinear3()
    (Point(x=0.0, y=0.0), Point(x=1.0, y=0.0), Point(x=3.0, y=0.0))
    """
    return (Point(at.x, at.y), _place(1.0, 0.0, at, angle, scale), _place(3.0, 0.0, at, angle, scale))


def parallel_lines(gap: float = 1.0, *, at: Point = ORIGIN, angle: float = 0.0,
                   scale: float = 1.0) -> tuple[Line, Line]:
    """Two distinct parallel lines ``gap`` apart, same direction: ``line_line`` gives ``()``."""
    u = _direction(angle)
    return Line(Point(at.x, at.y), u), Line(_place(2.0, gap, at, angle, scale), u)


def coincident_lines(*, at: Point = ORIGIN, angle: float = 0.0, scale: float = 1.0) -> tuple[Line, Line]:
    """One line given twice, by different anchors and opposite directions: ``line_line`` raises
    :class:`~geomcon.errors.Coincident`."""
    u = _direction(angle)
    return Line(Point(at.x, at.y), u), Line(_place(5.0, 0.0, at, angle, scale), -u)


def zero_chord(*, at: Point = ORIGIN, angle: float = 0.0, scale: float = 1.0) -> tuple[Point, Point]:
    """A chord whose two ends coincide: ``perpendicular_bisector`` raises
    :class:`~geomcon.errors.Degenerate`."""
    return Point(at.x, at.y), Point(at.x, at.y)
