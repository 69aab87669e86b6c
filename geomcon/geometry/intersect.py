"""The three intersections, under one contract.

Contract
--------
- The result is always a tuple of 0, 1 or 2 :class:`Point`.
- Two points come in a documented order: for circle–circle the point left of the directed line from the
  first centre to the second comes first; for line–circle the point met first along the line's direction
  comes first. Constructions never rely on this order: they choose with a named rule (:mod:`.branch`).
- Tangency within the tolerance policy (:func:`geomcon.tolerance.tol`) gives exactly one point.
- Coincident lines or coincident circles raise :class:`~geomcon.errors.Coincident`.

Numerics
--------
Coordinates are taken relative to a local centre (the first circle's centre, the circle's centre, the first
line's point) before anything is squared, and the half-chord comes from Heron's product of four
differences, each computed directly from the distances, so that near tangency (relative gap δ) the error is
of order ε·r/√δ and a scene translated far from the origin keeps its accuracy.

Examples
--------
>>> from geomcon.geometry.primitives import Circle, Line, Point
>>> circle_circle(Circle(Point(0, 0), 5), Circle(Point(8, 0), 5))
(Point(x=4.0, y=3.0), Point(x=4.0, y=-3.0))
>>> circle_circle(Circle(Point(0, 0), 1), Circle(Point(2, 0), 1))
(Point(x=1.0, y=0.0),)
>>> line_circle(Line(Point(-9, 0), Point(1, 0)), Circle(Point(0, 0), 2))
(Point(x=-2.0, y=0.0), Point(x=2.0, y=0.0))
>>> line_line(Line(Point(0, 0), Point(1, 1)), Line(Point(2, 0), Point(0, 1)))
(Point(x=2.0, y=2.0),)
"""
from __future__ import annotations

import math

from ..errors import Coincident, Degenerate
from .. import tolerance as _tolerance
from ..tolerance import tol
from .primitives import Circle, Line, Point

_hypot = math.hypot


def _sum_less(x: float, y: float, z: float) -> float:
    """x + y − z for x, y, z ≥ 0, z subtracted from the larger of x, y first: exact (Sterbenz) when z is
    near it, so a Heron factor keeps its relative accuracy when one radius is tiny beside the others.

    >>> _sum_less(1e-9, 500.0, 500.0)
    1e-09
    """
    big, small = (x, y) if x >= y else (y, x)
    return (big - z) + small


def line_line(l1: Line, l2: Line) -> tuple[Point, ...]:
    """Intersect two lines: ``()`` if parallel, one point otherwise.

    Lines are parallel when the sine of their angle is below ``REL_TOL``; parallel lines closer than the
    tolerance coincide and raise :class:`Coincident`.
    """
    w = l2.point - l1.point
    s = l1.direction.cross(l2.direction)
    if abs(s) <= tol(1.0):
        offset = l1.direction.cross(w)
        if abs(offset) <= tol(abs(w), 1e-300):
            raise Coincident("the two lines coincide")
        return ()
    t = w.cross(l2.direction) / s
    return (l1.point + l1.direction * t,)


def line_circle(line: Line, circle: Circle) -> tuple[Point, ...]:
    """Intersect a line and a circle: 0, 1 (tangent) or 2 points, ordered along the line's direction."""
    d, p = line.direction, line.point
    return _points(line_circle_xy(p.x, p.y, d.x, d.y, circle.center.x, circle.center.y, circle.r))


def line_circle_xy(px: float, py: float, ux: float, uy: float, cx: float, cy: float, r: float) -> tuple:
    """The float core of :func:`line_circle` (shared with :mod:`.kernels`): the candidates as flat floats
    ``(x1, y1[, x2, y2])``, ordered along the unit direction (ux, uy)."""
    wx, wy = px - cx, py - cy               # w: local frame, the circle's centre at the origin
    t0 = -(wx * ux + wy * uy)                # −w·u: parameter of the foot of the perpendicular from the centre
    p = ux * wy - uy * wx                    # u × w: signed distance of the centre's foot
    ap = abs(p)
    gap = ap - r
    if abs(gap) <= _tolerance.REL_TOL * (ap if ap > r else r):     # tol(r, ap) in place: r > 0, ap ≥ 0; max()
        return _finite(px + ux * t0, py + uy * t0)
    if gap > 0:
        return ()
    h = math.sqrt((r - ap) * (r + ap))
    t1, t2 = t0 - h, t0 + h
    x1, y1, x2, y2 = px + ux * t1, py + uy * t1, px + ux * t2, py + uy * t2
    if x1 - x1 != 0.0 or y1 - y1 != 0.0:
        raise _bad(x1, y1)
    if x2 - x2 != 0.0 or y2 - y2 != 0.0:
        raise _bad(x2, y2)
    return x1, y1, x2, y2


def circle_circle(c1: Circle, c2: Circle) -> tuple[Point, ...]:
    """Intersect two circles: 0, 1 (tangent) or 2 points, the one left of ``c1.center → c2.center`` first.

    Raises
    ------
    Coincident
        When the circles coincide (same centre and radius within tolerance).
    """
    o, q = c1.center, c2.center
    return _points(circle_circle_xy(o.x, o.y, c1.r, q.x, q.y, c2.r))


def circle_circle_xy(ox: float, oy: float, r1: float, qx: float, qy: float, r2: float) -> tuple:
    """The float core of :func:`circle_circle` (shared with :mod:`.kernels`): the candidates as flat floats
    ``(x1, y1[, x2, y2])``; coincident circles raise :class:`~geomcon.errors.Coincident`."""
    vx, vy = qx - ox, qy - oy                # local frame: the first centre at the origin
    d = _hypot(vx, vy)
    scale = d                                # max(d, r1, r2) as its comparisons: the first of equal values
    if r1 > scale:                           # kept, a NaN never taken after the first (the same float)
        scale = r1
    if r2 > scale:
        scale = r2
    eps = _tolerance.REL_TOL * scale         # tol(scale) in place: d ≥ 0 and the radii > 0
    if d <= eps:
        if abs(r1 - r2) <= eps:
            raise Coincident(f"the two circles coincide (radius {r1:.6g})")
        return ()
    outer = d - (r1 + r2)                    # > 0: apart
    inner = abs(r1 - r2) - d                 # > 0: one inside the other
    ux, uy = vx / d, vy / d
    if abs(outer) <= eps or abs(inner) <= eps:
        a = r1 if abs(outer) <= eps else (r1 if r1 > r2 else -r1)
        return _finite(ox + ux * a, oy + uy * a)
    if outer > 0 or inner > 0:
        return ()
    # a = (d² + r1² − r2²)/(2d): the cancellation is between r2² and the larger of d², r1², so that
    # difference is formed as a product of a near-exact difference (a tiny circle on a large one keeps its
    # relative accuracy: a ≈ r1²/2d, not ε·d)
    big, small = (d, r1) if d >= r1 else (r1, d)
    a = ((big - r2) * (big + r2) + small * small) / (2.0 * d)
    # _sum_less(r1, r2, d) · _sum_less(d, r2, r1) · _sum_less(d, r1, r2) · (d + r1 + r2), the three in place
    h2 = (((r1 - d) + r2 if r1 >= r2 else (r2 - d) + r1) * ((d - r1) + r2 if d >= r2 else (r2 - r1) + d)
          * ((d - r2) + r1 if d >= r1 else (r1 - r2) + d) * (d + r1 + r2))
    h = math.sqrt(h2) / (2.0 * d)
    fx, fy = ux * a, uy * a                  # the foot, still local: translated once, at the very end
    nx, ny = -uy * h, ux * h                 # u turned by +90°, times h
    x1, y1, x2, y2 = ox + (fx + nx), oy + (fy + ny), ox + (fx - nx), oy + (fy - ny)
    if x1 - x1 != 0.0 or y1 - y1 != 0.0:
        raise _bad(x1, y1)
    if x2 - x2 != 0.0 or y2 - y2 != 0.0:
        raise _bad(x2, y2)
    return x1, y1, x2, y2


def _points(c: tuple) -> tuple[Point, ...]:
    """The Points of flat candidates ``(x1, y1, x2, y2, …)``."""
    return tuple(Point(c[i], c[i + 1]) for i in range(0, len(c), 2))


def _finite(x: float, y: float) -> tuple[float, float]:
    """``(x, y)`` as floats, refused when not finite (as :class:`~.primitives.Point` refuses them)."""
    x, y = float(x), float(y)
    if x - x != 0.0 or y - y != 0.0:
        raise _bad(x, y)
    return x, y


def _bad(x: float, y: float) -> Degenerate:
    return Degenerate(f"point with a non-finite coordinate ({x}, {y})")
