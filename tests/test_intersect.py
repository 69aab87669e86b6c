"""The one intersection contract of ``line_line``, ``line_circle`` and ``circle_circle``.

What this proves
----------------
- Every result is a tuple of 0, 1 or 2 :class:`Point` -- never a list, never ``None``.
- Two points come in the documented order: for circle–circle the point left of the directed line from
  the first centre to the second comes first; for line–circle the points are ordered along the line's
  direction (reversing the line reverses them).
- Tangency gives exactly one point, at the right place: circles touching from outside, from inside (in
  both argument orders), a line touching a circle.
- No intersection gives ``()``; coincident lines or circles raise :class:`Coincident`.
- The named degenerate fixtures of :mod:`geomcon.testing` take the documented outcome for every
  operation × case × placement (scale 1e-3 … 1e6, translated, turned).
- Random cases (hypothesis, derandomized) keep the invariants that can fail: each returned point lies on
  both curves within 16 ulp of the scene's scale (within the tolerance itself for a tangent point), the
  order is the documented one, and the number of points agrees with the exact (50-digit) classification
  whenever the exact relative gap is clearly outside the tolerance band.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from mpmath import mp, mpf
from mpmath import sqrt as msqrt

from geomcon.errors import Coincident, Degenerate
from geomcon.geometry import (Circle, Line, Point, circle_circle, circle_through3, line_circle, line_line,
                              perpendicular_bisector)
from geomcon.testing import (ORIGIN, assert_points_close, coincident_circles, coincident_lines, collinear3,
                             concentric, internally_tangent, parallel_lines, tangent_line, tangent_pair,
                             zero_chord)
from geomcon.tolerance import REL_TOL

mp.dps = 50
DERANDOMIZED = settings(derandomize=True, max_examples=200, deadline=None)


def is_result(out) -> bool:
    return isinstance(out, tuple) and len(out) <= 2 and all(isinstance(p, Point) for p in out)


def off_circle(p: Point, c: Circle) -> float:
    """How far ``p`` is from the circle ``c`` (exactly, from the float inputs)."""
    return float(abs(msqrt((mpf(p.x) - mpf(c.center.x)) ** 2 + (mpf(p.y) - mpf(c.center.y)) ** 2) - mpf(c.r)))


def off_line(p: Point, line: Line) -> float:
    (px, py), (ax, ay) = (mpf(p.x), mpf(p.y)), (mpf(line.point.x), mpf(line.point.y))
    ux, uy = mpf(line.direction.x), mpf(line.direction.y)
    return float(abs(ux * (py - ay) - uy * (px - ax)) / msqrt(ux * ux + uy * uy))


def left_of(p: Point, a: Point, b: Point) -> float:
    """Exact sign-carrying cross product (b − a) × (p − a)."""
    return float((mpf(b.x) - mpf(a.x)) * (mpf(p.y) - mpf(a.y)) - (mpf(b.y) - mpf(a.y)) * (mpf(p.x) - mpf(a.x)))


# ----------------------------------------------------------------------------------------------------
# Worked examples of the contract.

class TestCircleCircle:
    def test_two_points_left_of_first_to_second_first(self):
        c1, c2 = Circle(Point(0, 0), 5), Circle(Point(8, 0), 5)
        assert circle_circle(c1, c2) == (Point(4, 3), Point(4, -3))
        assert circle_circle(c2, c1) == (Point(4, -3), Point(4, 3))      # the order follows c1 → c2

    def test_order_for_a_vertical_centre_line(self):
        c1, c2 = Circle(Point(0, 0), 5), Circle(Point(0, 8), 5)
        p, q = circle_circle(c1, c2)
        assert p.x < 0 < q.x                                             # left of "up" is −x
        assert_points_close((p, q), (Point(-3, 4), Point(3, 4)), atol=1e-14)

    def test_unequal_radii(self):
        p, q = circle_circle(Circle(Point(1, 1), 5), Circle(Point(1, 10), math.sqrt(88)))
        # about (1, 1): 25 = x² + y², 88 = x² + (y − 9)²  →  y = 1, x = ±√24; left of "up" is −x
        assert_points_close((p, q), (Point(1 - math.sqrt(24), 2), Point(1 + math.sqrt(24), 2)), atol=1e-14)

    def test_external_tangency_gives_one_point(self):
        assert circle_circle(Circle(Point(0, 0), 1), Circle(Point(2, 0), 1)) == (Point(1, 0),)
        assert circle_circle(Circle(Point(0, 0), 3), Circle(Point(0, -5), 2)) == (Point(0, -3),)

    def test_internal_tangency_gives_one_point_in_both_orders(self):
        big, small = Circle(Point(0, 0), 3), Circle(Point(2, 0), 1)
        assert circle_circle(big, small) == (Point(3, 0),)
        assert circle_circle(small, big) == (Point(3, 0),)

    @pytest.mark.parametrize("c1, c2", [
        (Circle(Point(0, 0), 1), Circle(Point(3, 0), 1)),        # apart
        (Circle(Point(0, 0), 3), Circle(Point(0.5, 0), 1)),      # nested
        (Circle(Point(0.5, 0), 1), Circle(Point(0, 0), 3)),      # nested, other order
        (Circle(Point(0, 0), 3), Circle(Point(0, 0), 1)),        # concentric
    ], ids=["apart", "nested", "nested-swapped", "concentric"])
    def test_no_intersection_is_empty(self, c1, c2):
        assert circle_circle(c1, c2) == ()

    def test_coincident_circles_raise(self):
        with pytest.raises(Coincident):
            circle_circle(Circle(Point(1, 2), 3), Circle(Point(1, 2), 3))


class TestLineCircle:
    def test_two_points_along_the_direction(self):
        c = Circle(Point(0, 0), 2)
        assert line_circle(Line(Point(-9, 0), Point(1, 0)), c) == (Point(-2, 0), Point(2, 0))
        assert line_circle(Line(Point(9, 0), Point(-1, 0)), c) == (Point(2, 0), Point(-2, 0))

    def test_order_does_not_depend_on_the_anchor(self):
        c = Circle(Point(1, 1), 5)
        for anchor in (Point(1, -20), Point(1, 1), Point(1, 3), Point(1, 40)):
            p, q = line_circle(Line(anchor, Point(0, 1)), c)
            assert_points_close((p, q), (Point(1, -4), Point(1, 6)), atol=1e-13)

    def test_tangent_line_gives_the_foot(self):
        assert line_circle(Line(Point(-5, 2), Point(1, 0)), Circle(Point(0, 0), 2)) == (Point(0, 2),)
        assert line_circle(Line(Point(7, 3), Point(0, -1)), Circle(Point(4, 0), 3)) == (Point(7, 0),)

    def test_missing_line_is_empty(self):
        assert line_circle(Line(Point(-5, 2.5), Point(1, 0)), Circle(Point(0, 0), 2)) == ()


class TestLineLine:
    def test_crossing(self):
        assert line_line(Line(Point(0, 0), Point(1, 1)), Line(Point(2, 0), Point(0, 1))) == (Point(2, 2),)
        assert line_line(Line(Point(0, 1), Point(1, 0)), Line(Point(3, -4), Point(0, 2))) == (Point(3, 1),)

    def test_parallel_is_empty(self):
        assert line_line(Line(Point(0, 0), Point(1, 2)), Line(Point(1, 0), Point(-2, -4))) == ()

    @pytest.mark.parametrize("other", [
        Line(Point(0, 0), Point(1, 2)), Line(Point(2, 4), Point(1, 2)), Line(Point(-1, -2), Point(-3, -6)),
    ], ids=["same", "other-anchor", "opposite-direction"])
    def test_coincident_raise(self, other):
        with pytest.raises(Coincident):
            line_line(Line(Point(0, 0), Point(1, 2)), other)


# ----------------------------------------------------------------------------------------------------
# Named degenerate fixtures: operation × case × placement.

def _touch_external(c1, c2):
    return [c1.center + (c2.center - c1.center).unit() * c1.r]


def _touch_internal(c1, c2):
    big, small = (c1, c2) if c1.r > c2.r else (c2, c1)
    return [big.center + (small.center - big.center).unit() * big.r]


CASES = [
    # id, operation, builder, expected: int (number of points) or exception class
    ("tangent_pair", circle_circle, tangent_pair, 1),
    ("tangent_pair-swapped", circle_circle, lambda **kw: tangent_pair(**kw)[::-1], 1),
    ("internally_tangent", circle_circle, internally_tangent, 1),
    ("internally_tangent-swapped", circle_circle, lambda **kw: internally_tangent(**kw)[::-1], 1),
    ("concentric", circle_circle, concentric, 0),
    ("coincident_circles", circle_circle, coincident_circles, Coincident),
    ("tangent_line", line_circle, tangent_line, 1),
    ("collinear3", circle_through3, collinear3, Degenerate),
    ("collinear3-middle-first", circle_through3, lambda **kw: (lambda a, b, c: (b, a, c))(*collinear3(**kw)),
     Degenerate),
    ("parallel_lines", line_line, parallel_lines, 0),
    ("coincident_lines", line_line, coincident_lines, Coincident),
    ("zero_chord", perpendicular_bisector, zero_chord, Degenerate),
]

PLACEMENTS = [
    pytest.param(dict(scale=s, at=Point(k * s * 3.0, -k * s * 2.0), angle=a), id=f"s={s:g}-at={k}-turn={a}")
    for s in (1e-3, 1.0, 1e6) for k in (0, 1, 10) for a in (0.0, 0.7, -2.5)
]


@pytest.mark.parametrize("place", PLACEMENTS)
@pytest.mark.parametrize("name, op, build, expected", CASES, ids=[c[0] for c in CASES])
def test_degenerate_fixture(name, op, build, expected, place):
    operands = build(**place)
    if isinstance(expected, type):
        with pytest.raises(expected):
            op(*operands)
        return
    out = op(*operands)
    assert is_result(out) and len(out) == expected
    scale = place["scale"] * 10
    for p in out:                                 # a tangent point lies on both curves (within tolerance)
        for curve in operands:
            gap = off_circle(p, curve) if isinstance(curve, Circle) else off_line(p, curve)
            assert gap <= REL_TOL * scale + 16 * math.ulp(scale + abs(p))
    if name.startswith("tangent_pair"):
        assert_points_close(out, _touch_external(*operands), atol=16 * math.ulp(scale + abs(out[0])))
    if name.startswith("internally_tangent"):
        assert_points_close(out, _touch_internal(*operands), atol=16 * math.ulp(scale + abs(out[0])))


# ----------------------------------------------------------------------------------------------------
# Random cases: invariants that can fail.

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
turn = st.floats(-math.pi, math.pi, allow_nan=False)
magnitude = st.integers(-3, 6).map(lambda k: 10.0 ** k)
# relative gaps: clearly crossing / clearly tangent / clearly apart, down to the edge of the tolerance band
gaps = st.one_of(st.floats(-0.9, 2.0), st.sampled_from([0.0, 1e-14, -1e-14, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6]))


def _exact_count_circles(c1: Circle, c2: Circle) -> int | None:
    """The exact number of intersections, or None inside [REL_TOL/4, 4 REL_TOL] of relative gap."""
    (x1, y1), (x2, y2) = (mpf(c1.center.x), mpf(c1.center.y)), (mpf(c2.center.x), mpf(c2.center.y))
    r1, r2 = mpf(c1.r), mpf(c2.r)
    d = msqrt((x2 - x1) ** 2 + (y2 - y1) ** 2)
    scale = max(d, r1, r2)
    gaps = (d - (r1 + r2), abs(r1 - r2) - d)            # > 0: apart, nested
    if any(REL_TOL / 4 < abs(g) / scale < 4 * REL_TOL for g in gaps):
        return None
    if any(abs(g) / scale <= REL_TOL / 4 for g in gaps):
        return 1
    return 0 if any(g > 0 for g in gaps) else 2


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, r1=st.floats(0.1, 10.0), k=st.floats(0.1, 10.0), gap=gaps, theta=turn,
       internal=st.booleans())
def test_circle_circle_invariants(s, x, y, r1, k, gap, theta, internal):
    r1, r2 = r1 * s, r1 * k * s
    if internal and r1 == r2:
        return
    contact = abs(r1 - r2) if internal else r1 + r2
    c1 = Circle(Point(x * s, y * s), r1)
    d = contact * (1 + gap)
    c2 = Circle(Point(c1.center.x + d * math.cos(theta), c1.center.y + d * math.sin(theta)), r2)
    out = circle_circle(c1, c2)
    assert is_result(out)
    expected = _exact_count_circles(c1, c2)
    if expected is not None:
        assert len(out) == expected, (c1, c2, out)
    scale = max(abs(c1.center.x), abs(c1.center.y), abs(c2.center.x), abs(c2.center.y), r1, r2, d)
    slack = 16 * math.ulp(scale) + (REL_TOL * scale if len(out) == 1 else 0.0)
    for p in out:
        assert off_circle(p, c1) <= slack and off_circle(p, c2) <= slack, (c1, c2, p)
    if len(out) == 2:
        assert out[0] != out[1]
        assert left_of(out[0], c1.center, c2.center) > 0 > left_of(out[1], c1.center, c2.center)


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, r=st.floats(0.1, 10.0), gap=gaps, along=st.floats(-3, 3), phi=turn)
def test_line_circle_invariants(s, x, y, r, gap, along, phi):
    c = Circle(Point(x * s, y * s), r * s)
    u = Point(math.cos(phi), math.sin(phi))
    line = Line(c.center + u.perp() * (c.r * (1 + gap)) + u * (along * c.r), u)
    out = line_circle(line, c)
    assert is_result(out)
    p_exact = off_line(c.center, line)
    rel = (p_exact - c.r) / max(p_exact, c.r)
    if not REL_TOL / 4 < abs(rel) < 4 * REL_TOL:
        assert len(out) == (1 if abs(rel) <= REL_TOL / 4 else 0 if rel > 0 else 2), (line, c, out)
    scale = max(abs(c.center.x), abs(c.center.y), abs(line.point.x), abs(line.point.y), c.r)
    slack = 16 * math.ulp(scale) + (REL_TOL * scale if len(out) == 1 else 0.0)
    for p in out:
        assert off_circle(p, c) <= slack and off_line(p, line) <= slack, (line, c, p)
    if len(out) == 2:
        assert (out[1] - out[0]).dot(line.direction) > 0                   # ordered along the direction
        reverse = line_circle(Line(line.point, -line.direction), c)
        assert reverse == out[::-1] or all(
            abs(a - b) <= 16 * math.ulp(scale) for a, b in zip(reverse, out[::-1]))


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, x2=coord, y2=coord, phi=turn, cross=st.floats(1e-6, math.pi - 1e-6))
def test_line_line_invariants(s, x, y, x2, y2, phi, cross):
    l1 = Line(Point(x * s, y * s), Point(math.cos(phi), math.sin(phi)))
    l2 = Line(Point(x2 * s, y2 * s), Point(math.cos(phi + cross), math.sin(phi + cross)))
    out = line_line(l1, l2)
    assert is_result(out) and len(out) == 1
    (p,) = out
    # a point on both lines; the distance off either line grows with the distance along it over sin θ
    reach = abs(p - l1.point) + abs(p - l2.point)
    slack = 16 * math.ulp(max(abs(l1.point.x), abs(l1.point.y), abs(l2.point.x), abs(l2.point.y), reach))
    assert off_line(p, l1) <= slack and off_line(p, l2) <= slack
    assert line_line(l2, l1) == out or abs(line_line(l2, l1)[0] - p) <= 4 * slack / math.sin(cross)
