"""Value objects, constructions and measures.

What this proves
----------------
- Point, Line, Ray, Segment, Circle and Arc are frozen (assignment raises), hashable and compared by
  value, and refuse to exist when degenerate: non-finite coordinates, a zero direction, a radius ≤ 0,
  NaN or infinite, a negative or non-finite sweep -- always with :class:`Degenerate`.
- Directions are stored as unit vectors, even for huge or subnormal inputs.
- Each construction has the defining property of its name (the perpendicular bisector is equidistant
  from the chord's ends and directed to its left, the foot is on the line and perpendicular to it,
  reflection is an isometric involution fixing the line, rotation turns counter-clockwise for positive
  angles, ``point_along`` measures a signed distance, the circle through three points passes through all
  three, Thales' circle sees its diameter under a right angle...), on worked examples and on random
  cases (hypothesis, derandomized); degenerate inputs raise :class:`Degenerate`.
- Measures: distance, unsigned and signed angles (counter-clockwise positive, range (−π, π]), the angle
  of two undirected lines, signed distance (positive on the left), polar angle.
"""
from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geomcon.errors import Degenerate
from geomcon.geometry import (Arc, Circle, Line, Point, Ray, Segment, angle_at, angle_between, circle,
                              circle_through3, distance, foot, line_angle, line_through, midpoint, parallel,
                              perpendicular, perpendicular_bisector, point_along, point_on_ray, polar_angle,
                              ray_at_angle, reflect, rotate, rotate_ray, segment, signed_angle, signed_distance,
                              thales_circle)
from geomcon.testing import assert_points_close, collinear3, zero_chord

DERANDOMIZED = settings(derandomize=True, max_examples=200, deadline=None)
NAN, INF = math.nan, math.inf
O = Point(0, 0)


# ----------------------------------------------------------------------------------------------------
# Value objects.

VALUES = {
    "Point": (Point(1, 2), "x", 5.0),
    "Line": (Line(Point(1, 2), Point(3, 4)), "point", O),
    "Ray": (Ray(Point(1, 2), Point(0, 1)), "direction", Point(1, 0)),
    "Segment": (Segment(Point(1, 2), Point(3, 4)), "a", O),
    "Circle": (Circle(Point(1, 2), 3), "r", 4.0),
    "Arc": (Arc(Point(1, 2), 3, 0.0, 1.0), "sweep", 2.0),
}


@pytest.mark.parametrize("name", VALUES)
def test_value_objects_are_frozen_and_compare_by_value(name):
    obj, field, new = VALUES[name]
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(obj, field, new)
    twin = dataclasses.replace(obj)
    assert twin == obj and hash(twin) == hash(obj)
    assert dataclasses.replace(obj, **{field: new}) != obj


DEGENERATE = {
    "Point NaN": lambda: Point(NAN, 0),
    "Point +inf": lambda: Point(0, INF),
    "Point -inf": lambda: Point(-INF, 1),
    "Point overflow": lambda: Point(1e308, 0) + Point(1e308, 0),      # an overflow is non-finite too
    "Line zero direction": lambda: Line(O, Point(0, 0)),
    "Line -0 direction": lambda: Line(O, Point(-0.0, 0.0)),
    "Line.through same point": lambda: Line.through(Point(1, 1), Point(1, 1)),
    "Ray zero direction": lambda: Ray(O, Point(0, 0)),
    "Ray.toward its origin": lambda: Ray.toward(Point(2, 3), Point(2, 3)),
    "Circle r=0": lambda: Circle(O, 0),
    "Circle r=-0": lambda: Circle(O, -0.0),
    "Circle r<0": lambda: Circle(O, -1),
    "Circle r=NaN": lambda: Circle(O, NAN),
    "Circle r=inf": lambda: Circle(O, INF),
    "Circle NaN centre": lambda: Circle(Point(NAN, 0), 1),
    "Arc r=0": lambda: Arc(O, 0, 0, 1),
    "Arc r<0": lambda: Arc(O, -1, 0, 1),
    "Arc r=NaN": lambda: Arc(O, NAN, 0, 1),
    "Arc sweep<0": lambda: Arc(O, 1, 0, -0.1),
    "Arc start=NaN": lambda: Arc(O, 1, NAN, 1),
    "Arc sweep=inf": lambda: Arc(O, 1, 0, INF),
    "unit of zero": lambda: Point(0, 0).unit(),
    "line of a zero segment": lambda: Segment(O, O).line(),
}


@pytest.mark.parametrize("build", DEGENERATE.values(), ids=DEGENERATE.keys())
def test_degenerate_values_refuse_to_exist(build):
    with pytest.raises(Degenerate):
        build()


def test_points_are_floats_and_vectors():
    p = Point(3, 4)
    assert isinstance(p.x, float) and abs(p) == 5.0
    assert p + Point(1, 1) == Point(4, 5) and p - Point(1, 1) == Point(2, 3) and -p == Point(-3, -4)
    assert 2 * p == p * 2 == Point(6, 8) and p / 2 == Point(1.5, 2)
    assert p.dot(Point(1, 0)) == 3 and Point(1, 0).cross(Point(0, 1)) == 1 and Point(0, 1).cross(Point(1, 0)) == -1
    assert Point(1, 0).perp() == Point(0, 1) and p.tuple() == (3.0, 4.0)


@pytest.mark.parametrize("v", [Point(3, 4), Point(-1e-310, 2e-310), Point(5e-324, 5e-324), Point(1.5e308, -1.6e308),
                               Point(1e300, 1e-300), Point(0, -7)])
def test_directions_are_unit_vectors(v):
    for d in (v.unit(), Line(O, v).direction, Ray(O, v).direction):
        assert abs(math.hypot(d.x, d.y) - 1) <= 2 ** -51
        assert math.copysign(1, d.x) == math.copysign(1, v.x) or d.x == 0
        assert abs(d.cross(v)) <= 4 * math.ulp(max(abs(v.x), abs(v.y)))     # same direction as v


def test_line_ray_segment_circle_arc_accessors():
    line = Line(Point(1, 1), Point(0, 2))
    assert line.direction == Point(0, 1) and line.normal == Point(-1, 0) and line.at(3) == Point(1, 4)
    ray = Ray.toward(Point(1, 1), Point(4, 5))
    assert ray.at(5) == Point(4, 5) and ray.line() == Line(Point(1, 1), Point(3, 4))
    seg = Segment(Point(0, 0), Point(6, 8))
    assert seg.length == 10 and seg.midpoint() == Point(3, 4) and seg.line().direction == Point(0.6, 0.8)
    c = Circle(Point(1, 1), 2)
    assert_points_close(c.at(math.pi / 2), Point(1, 3), atol=1e-15)
    arc = Arc(Point(1, 1), 2, 0.0, math.pi)
    assert arc.circle == c and arc.at(0) == Point(3, 1)
    assert_points_close(arc.at(1), Point(-1, 1), atol=1e-15)


# ----------------------------------------------------------------------------------------------------
# Constructions: worked examples.

def test_line_through_segment_circle():
    assert line_through(Point(1, 1), Point(1, -3)) == Line(Point(1, 1), Point(0, -1))
    assert segment(Point(1, 1), Point(4, 5)).length == 5
    assert circle(Point(1, 2), 3) == Circle(Point(1, 2), 3)
    with pytest.raises(Degenerate):
        circle(Point(1, 2), 0)


def test_perpendicular_bisector():
    b = perpendicular_bisector(Point(0, 0), Point(4, 2))
    assert b.point == Point(2, 1)
    assert_points_close(b.direction, Point(-2, 4).unit(), atol=1e-16)        # to the left of a → b


@pytest.mark.parametrize("place", [dict(), dict(at=Point(1e6, -3.5)), dict(at=Point(-0.0, 5e-324))])
def test_perpendicular_bisector_of_a_zero_chord_is_degenerate(place):
    with pytest.raises(Degenerate):
        perpendicular_bisector(*zero_chord(**place))


def test_perpendicular_parallel_foot_reflect():
    line = Line(Point(0, 1), Point(1, 1))
    perp = perpendicular(line, Point(5, 0))
    assert perp.point == Point(5, 0)
    assert_points_close(perp.direction, line.normal, atol=2 ** -52)       # normalised again: within 1 ulp
    par = parallel(line, Point(5, 0))
    assert par.point == Point(5, 0)
    assert_points_close(par.direction, line.direction, atol=2 ** -52)
    assert_points_close(foot(line, Point(2, -1)), Point(0, 1), atol=1e-15)
    assert_points_close(reflect(Point(2, -1), line), Point(-2, 3), atol=1e-15)
    assert reflect(Point(1, 1), Line(Point(0, 0), Point(1, 0))) == Point(1, -1)


def test_rotations_are_counter_clockwise_for_positive_angles():
    assert_points_close(rotate(Point(2, 1), Point(1, 1), math.pi / 2), Point(1, 2), atol=1e-15)
    assert_points_close(rotate(Point(2, 1), Point(1, 1), -math.pi / 2), Point(1, 0), atol=1e-15)
    r = rotate_ray(Ray(Point(3, 3), Point(1, 0)), math.radians(30))
    assert r.origin == Point(3, 3)
    assert_points_close(r.direction, Point(math.sqrt(3) / 2, 0.5), atol=1e-15)
    r = ray_at_angle(Point(1, 1), Point(1, 5), -math.pi / 2)        # from "up", turned clockwise: "right"
    assert r.origin == Point(1, 1)
    assert_points_close(r.direction, Point(1, 0), atol=1e-15)


def test_points_along_rays():
    assert point_along(Point(1, 1), Point(4, 5), 10) == Point(7, 9)
    assert point_along(Point(1, 1), Point(4, 5), -5) == Point(-2, -3)     # a signed distance
    assert point_on_ray(Ray(Point(1, 1), Point(0, 3)), 2) == Point(1, 3)
    assert midpoint(Point(1, 2), Point(-3, 7)) == Point(-1, 4.5)
    with pytest.raises(Degenerate):
        point_along(Point(1, 1), Point(1, 1), 3)


def test_circle_through3_and_thales():
    c = circle_through3(Point(1, 0), Point(0, 1), Point(-1, 0))
    assert c == Circle(Point(0, 0), 1)
    c = circle_through3(Point(7, 2), Point(1, 10), Point(1, 2))          # right angle at (1, 2)
    assert_points_close(c.center, Point(4, 6), atol=1e-14)
    assert c.r == pytest.approx(5, rel=1e-15)
    t = thales_circle(Point(1, 2), Point(7, 10))
    assert t == Circle(Point(4, 6), 5)
    p = t.at(1.234)
    assert (Point(1, 2) - p).dot(Point(7, 10) - p) == pytest.approx(0, abs=1e-12)


@pytest.mark.parametrize("points", [
    collinear3(), collinear3(scale=1e6, angle=0.3), collinear3(scale=1e-3, at=Point(0.01, 0.02), angle=-2),
    (Point(0, 0), Point(1, 1), Point(0, 0)),           # two coincident points: a == c
    (Point(0, 0), Point(0, 0), Point(1, 1)),           # a == b
    (Point(2, 2), Point(2, 2), Point(2, 2)),
], ids=["collinear3", "collinear3-big-turned", "collinear3-small", "a==c", "a==b", "all-equal"])
def test_circle_through_collinear_or_coincident_points_is_degenerate(points):
    with pytest.raises(Degenerate):
        circle_through3(*points)


# ----------------------------------------------------------------------------------------------------
# Constructions: random cases.

coord = st.floats(-100.0, 100.0, allow_nan=False, allow_infinity=False)
pt = st.builds(Point, coord, coord)
turn = st.floats(-math.pi, math.pi, allow_nan=False)


def slack(*points: Point) -> float:
    return 32 * math.ulp(max(1.0, *(max(abs(p.x), abs(p.y)) for p in points)))


@DERANDOMIZED
@given(a=pt, b=pt)
def test_perpendicular_bisector_is_equidistant(a, b):
    if distance(a, b) < 1e-6:
        return
    bis = perpendicular_bisector(a, b)
    assert signed_distance(Line.through(a, b), bis.at(1.0)) > 0            # directed to the left of a → b
    assert abs(bis.direction.dot(b - a)) <= slack(a, b) * abs(b - a)
    for t in (-50.0, 0.0, 3.0):
        p = bis.at(t)
        assert abs(distance(p, a) - distance(p, b)) <= 4 * slack(a, b, p)


@DERANDOMIZED
@given(a=pt, b=pt, p=pt)
def test_foot_and_reflection(a, b, p):
    if distance(a, b) < 1e-6:
        return
    line = Line.through(a, b)
    f = foot(line, p)
    assert abs(signed_distance(line, f)) <= slack(a, b, p)
    assert abs((p - f).dot(line.direction)) <= slack(a, b, p)
    q = reflect(p, line)
    assert signed_distance(line, q) == pytest.approx(-signed_distance(line, p), abs=4 * slack(a, b, p))
    assert_points_close(reflect(q, line), p, atol=4 * slack(a, b, p))
    assert distance(q, a) == pytest.approx(distance(p, a), abs=4 * slack(a, b, p))


@DERANDOMIZED
@given(p=pt, c=pt, angle=turn)
def test_rotation_is_an_isometry_turning_by_the_signed_angle(p, c, angle):
    q = rotate(p, c, angle)
    assert distance(q, c) == pytest.approx(distance(p, c), abs=slack(p, c))
    assert_points_close(rotate(q, c, -angle), p, atol=2 * slack(p, c))
    if distance(p, c) > 1e-3 and abs(abs(angle) - math.pi) > 1e-9:
        assert signed_angle(p - c, q - c) == pytest.approx(angle, abs=1e-12)


@DERANDOMIZED
@given(o=pt, t=pt, angle=turn, dist=st.floats(-100, 100))
def test_rays_and_points_along_them(o, t, angle, dist):
    if distance(o, t) < 1e-6:
        return
    ray = ray_at_angle(o, t, angle)
    assert ray.origin == o
    if abs(abs(angle) - math.pi) > 1e-9:
        assert signed_angle(t - o, ray.direction) == pytest.approx(angle, abs=1e-12)
    q = point_along(o, t, dist)
    assert distance(o, q) == pytest.approx(abs(dist), abs=slack(o, t))
    assert abs(signed_distance(Line.through(o, t), q)) <= slack(o, t, q)
    assert (q - o).dot(t - o) * dist >= 0                                  # ahead for dist > 0, behind for < 0
    assert point_on_ray(ray, dist) == ray.at(dist)
    assert_points_close(rotate_ray(ray, -angle).direction, Ray.toward(o, t).direction, atol=1e-15)


@DERANDOMIZED
@given(o=pt, r=st.floats(1e-2, 1e3), a0=turn, g1=st.floats(0.05, 3.0), g2=st.floats(0.05, 3.0))
def test_circle_through3_passes_through_all_three(o, r, a0, g1, g2):
    a, b, c = (Circle(o, r).at(t) for t in (a0, a0 + g1, a0 + g1 + g2))
    got = circle_through3(a, b, c)
    for p in (a, b, c):
        assert distance(got.center, p) == pytest.approx(got.r, rel=1e-9)
    for p, q in ((a, b), (b, c), (a, c)):
        t = thales_circle(p, q)
        assert distance(t.center, p) == pytest.approx(t.r, rel=1e-14)


# ----------------------------------------------------------------------------------------------------
# Measures.

def test_distance_and_angles():
    assert distance(Point(1, 1), Point(4, 5)) == 5
    assert angle_at(Point(0, 0), Point(1, 0), Point(0, 2)) == pytest.approx(math.pi / 2, abs=1e-15)
    assert signed_angle(Point(1, 0), Point(0, 1)) == pytest.approx(math.pi / 2, abs=1e-15)
    assert signed_angle(Point(1, 0), Point(0, -1)) == pytest.approx(-math.pi / 2, abs=1e-15)
    assert signed_angle(Point(1, 0), Point(-1, 0)) == math.pi                 # (−π, π]: π, not −π
    assert signed_angle(Point(-1, 0), Point(1, 0)) == math.pi                 # even when atan2 sees −0.0
    assert polar_angle(O, Point(-1, -0.0)) == math.pi
    assert signed_angle(Point(1, 0), Point(3, 0)) == 0
    assert angle_between(Point(1, 0), Point(-1, -1)) == pytest.approx(3 * math.pi / 4, abs=1e-15)
    assert line_angle(Line(O, Point(1, 0)), Line(O, Point(-1, 1))) == pytest.approx(math.pi / 4, abs=1e-15)
    assert line_angle(Line(O, Point(1, 0)), Line(O, Point(-1, 0))) == 0       # undirected
    assert signed_distance(Line(O, Point(1, 0)), Point(5, 2)) == 2
    assert signed_distance(Line(O, Point(-1, 0)), Point(5, 2)) == -2          # left of the direction
    assert polar_angle(Point(1, 1), Point(1, 3)) == pytest.approx(math.pi / 2, abs=1e-15)


@pytest.mark.parametrize("f", [lambda: signed_angle(O, Point(1, 0)), lambda: angle_between(Point(1, 0), O),
                               lambda: angle_at(Point(1, 1), Point(1, 1), Point(2, 2))])
def test_angles_of_zero_vectors_are_degenerate(f):
    with pytest.raises(Degenerate):
        f()


@DERANDOMIZED
@given(u=pt, v=pt)
def test_signed_angle_range_and_antisymmetry(u, v):
    if abs(u) == 0 or abs(v) == 0:
        return
    a = signed_angle(u, v)
    assert -math.pi < a <= math.pi
    assert abs(a) == angle_between(u, v) <= math.pi
    if abs(abs(a) - math.pi) > 1e-12:
        assert signed_angle(v, u) == -a
    assert 0 <= line_angle(Line(O, u), Line(O, v)) <= math.pi / 2
