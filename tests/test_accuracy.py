"""Accuracy of the intersections and constructions against an independent 50-digit reference.

What this proves
----------------
Every case is computed twice: by geomcon in doubles, and by mpmath (``mp.dps = 50``) from the *exact
float inputs* the routine received (the stored, already normalised directions, the rounded centres...),
with an independent formula: absolute coordinates, the two curve equations solved directly -- no local
frame, no Heron product, no unit vectors. The error is the Euclidean distance between the two answers,
and each family of cases has its own bound (ε = 2.2e-16, ``ulp`` = :func:`math.ulp`):

well-conditioned cases (hypothesis, derandomized, 200 examples each)
    error ≤ 16 ulp(scale), scale = the largest of |coordinates| (inputs and answer), radii, distances.

circle–circle near external tangency, δ = 1 − d/(r1 + r2) from 1e-2 down to 1e-12
    error ≤ 4 ε R/√δ + ulp(m), R = max(r1, r2), m = the answer's largest |coordinate|.
    The half chord satisfies h² ≈ 2 r1 r2 δ; its Heron factor (r1 + r2) − d has an absolute error of a
    few ε R, a relative error of ~ε/δ, halved by the square root: h is off by ~ε R/√δ. The exact answer
    is moved by that much along the common tangent, and by ε R across it. ``ulp(m)`` is the last rounding
    when the scene is translated far from the origin (it dominates at 1e6 mm).

circle–circle near internal tangency, δ = 1 − |r1 − r2|/d (d just above |r1 − r2|)
    the same bound. Again h² ≈ 2 r1 r2 δ, and the small factor d − (r1 − r2) must be known to a few
    ε·d -- which needs r1 − r2 to be formed before d is subtracted (see the "small d" family). Cases keep
    δ·d above the decision tolerance REL_TOL·R, otherwise the pair is (rightly) declared tangent.

line–circle near tangency, δ = 1 − p/r (p = distance from the centre to the line)
    error ≤ 4 ε r/√δ + ulp(m), the line's anchor lying within about r of the tangent point (p itself is
    computed from the anchor, so its error grows with the anchor's distance from the circle).

line–line near parallel, angle θ between the lines from 1e-1 down to 1e-12 rad
    error ≤ 4 ε (|X − P1| + |X − P2|)/sin θ + ulp(m), with X the intersection and P1, P2 the anchors.
    Why this bound: rounding a direction by a relative ε turns its line about its anchor P by ε rad, which
    slides the intersection along the other line by |X − P|·ε/sin θ. Even a backward-stable method is only
    that good, and no method working in doubles can be better; so the relative error, measured against
    the distances from the anchors, is of order ε/sin θ. The factor 4 covers the roundings of P2 − P1, of
    the two cross products and of the final P1 + t·u1.

Scenes are translated by offsets up to 1e6 mm (the translated coordinates, not the local ones, are the
exact inputs). Set ``GEOMCON_RATIOS=1`` to print the worst error/bound ratio of each family at the end.
"""
from __future__ import annotations

import math
import os
import random
from collections import defaultdict

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from mpmath import mp, mpf
from mpmath import sqrt as msqrt

from geomcon.geometry import (Circle, Line, Point, angle_at, circle_circle, circle_through3, distance, foot,
                              line_circle, line_line, midpoint, point_along, reflect, rotate, signed_angle)
from geomcon.tolerance import EPS

mp.dps = 50

WORST: dict[str, float] = defaultdict(float)
"""Worst error/bound ratio measured per family (printed with GEOMCON_RATIOS=1)."""

DERANDOMIZED = settings(derandomize=True, max_examples=200, deadline=None)

DELTAS = [10.0 ** -k for k in range(2, 13)]
OFFSETS = [(0.0, 0.0), (1e6, -7.3e5), (-999_999.5, 1e6), (123_456.789, 654_321.123)]


@pytest.fixture(scope="module", autouse=True)
def _report_ratios(request):
    yield
    if os.environ.get("GEOMCON_RATIOS"):
        capture = request.config.pluginmanager.get_plugin("capturemanager")
        with capture.global_and_fixture_disabled():
            print("\nworst error/bound ratios:")
            for family in sorted(WORST):
                print(f"  {family:<62} {WORST[family]:.3g}")


def check(family: str, error: float, bound: float, case: object) -> None:
    """Record error/bound for ``family`` and fail when the bound is exceeded."""
    ratio = error / bound
    WORST[family] = max(WORST[family], ratio)
    assert ratio <= 1.0, f"{family}: error {error:.3g} > bound {bound:.3g} (ratio {ratio:.3g}) for {case}"


# ----------------------------------------------------------------------------------------------------
# The reference: exact float inputs, 50 digits, formulas independent of the implementation.

def M(p: Point) -> tuple[mpf, mpf]:
    return mpf(p.x), mpf(p.y)


def err(p: Point, q: tuple[mpf, mpf]) -> float:
    return float(msqrt((mpf(p.x) - q[0]) ** 2 + (mpf(p.y) - q[1]) ** 2))


def ref_circle_circle(c1: Circle, c2: Circle) -> list[tuple[mpf, mpf]]:
    """Subtract the two circle equations (the radical line), then cut the first circle with it."""
    (x1, y1), (x2, y2) = M(c1.center), M(c2.center)
    r1, r2 = mpf(c1.r), mpf(c2.r)
    a, b = 2 * (x2 - x1), 2 * (y2 - y1)
    c = r1 ** 2 - r2 ** 2 + x2 ** 2 + y2 ** 2 - x1 ** 2 - y1 ** 2      # a X + b Y = c
    n2 = a * a + b * b
    px, py = a * c / n2, b * c / n2                                    # the radical line's point nearest O
    dx, dy = -b / msqrt(n2), a / msqrt(n2)
    wx, wy = px - x1, py - y1
    half_b, cc = wx * dx + wy * dy, wx * wx + wy * wy - r1 * r1
    disc = half_b ** 2 - cc
    assert disc > 0, "reference: the circles do not cross"
    pts = [(px + dx * t, py + dy * t) for t in (-half_b + msqrt(disc), -half_b - msqrt(disc))]
    pts.sort(key=lambda q: -((x2 - x1) * (q[1] - y1) - (y2 - y1) * (q[0] - x1)))   # left of c1→c2 first
    return pts


def ref_line_circle(line: Line, c: Circle) -> list[tuple[mpf, mpf]]:
    """Solve |P + t u − C|² = r² for t (u as stored, not assumed unit), points by increasing t."""
    (px, py), (ux, uy), (cx, cy) = M(line.point), M(line.direction), M(c.center)
    r = mpf(c.r)
    a = ux * ux + uy * uy
    b = 2 * (ux * (px - cx) + uy * (py - cy))
    k = px * px + py * py - 2 * (px * cx + py * cy) + cx * cx + cy * cy - r * r
    disc = b * b - 4 * a * k
    assert disc > 0, "reference: the line misses the circle"
    ts = sorted([(-b - msqrt(disc)) / (2 * a), (-b + msqrt(disc)) / (2 * a)])
    return [(px + ux * t, py + uy * t) for t in ts]


def ref_line_line(l1: Line, l2: Line) -> tuple[mpf, mpf]:
    """Cramer's rule on P1 + t u1 = P2 + s u2."""
    (p1x, p1y), (u1x, u1y) = M(l1.point), M(l1.direction)
    (p2x, p2y), (u2x, u2y) = M(l2.point), M(l2.direction)
    det = -u1x * u2y + u1y * u2x
    t = (-(p2x - p1x) * u2y + (p2y - p1y) * u2x) / det
    return p1x + u1x * t, p1y + u1y * t


def ref_circumcentre(a: Point, b: Point, c: Point) -> tuple[mpf, mpf]:
    """Solve |X − a|² = |X − b|² = |X − c|² as two linear equations in absolute coordinates."""
    (ax, ay), (bx, by), (cx, cy) = M(a), M(b), M(c)
    a11, a12, r1 = 2 * (bx - ax), 2 * (by - ay), bx ** 2 + by ** 2 - ax ** 2 - ay ** 2
    a21, a22, r2 = 2 * (cx - ax), 2 * (cy - ay), cx ** 2 + cy ** 2 - ax ** 2 - ay ** 2
    det = a11 * a22 - a12 * a21
    return (r1 * a22 - a12 * r2) / det, (a11 * r2 - r1 * a21) / det


def mdist(p: Point, q: Point) -> mpf:
    (px, py), (qx, qy) = M(p), M(q)
    return msqrt((px - qx) ** 2 + (py - qy) ** 2)


def biggest(*values) -> float:
    """The largest magnitude among numbers, points and mpmath pairs."""
    out = 0.0
    for v in values:
        if isinstance(v, Point):
            out = max(out, abs(v.x), abs(v.y))
        elif isinstance(v, tuple):
            out = max(out, *(abs(float(x)) for x in v))
        else:
            out = max(out, abs(float(v)))
    return out


# ----------------------------------------------------------------------------------------------------
# Well-conditioned random cases.

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
turn = st.floats(-math.pi, math.pi, allow_nan=False)
magnitude = st.integers(-3, 6).map(lambda k: 10.0 ** k)       # the scene's size, 1e-3 … 1e6 mm


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, r1=st.floats(0.5, 10.0), k=st.floats(0.25, 4.0),
       f=st.floats(0.15, 0.85), theta=turn)
def test_circle_circle_well_conditioned(s, x, y, r1, k, f, theta):
    r1, r2 = r1 * s, r1 * k * s
    d = abs(r1 - r2) + f * (r1 + r2 - abs(r1 - r2))        # strictly between internal and external contact
    c1 = Circle(Point(x * s, y * s), r1)
    c2 = Circle(Point(c1.center.x + d * math.cos(theta), c1.center.y + d * math.sin(theta)), r2)
    got, ref = circle_circle(c1, c2), ref_circle_circle(c1, c2)
    assert len(got) == 2
    scale = biggest(c1.center, c2.center, r1, r2, d, *ref)
    for p, q in zip(got, ref):
        check("circle_circle well-conditioned", err(p, q), 16 * math.ulp(scale), (c1, c2))


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, r=st.floats(0.5, 10.0), q=st.floats(-0.9, 0.9), along=st.floats(-2, 2),
       phi=turn)
def test_line_circle_well_conditioned(s, x, y, r, q, along, phi):
    c = Circle(Point(x * s, y * s), r * s)
    u = Point(math.cos(phi), math.sin(phi))
    anchor = c.center + u.perp() * (q * c.r) + u * (along * c.r)
    line = Line(anchor, u)
    got, ref = line_circle(line, c), ref_line_circle(line, c)
    assert len(got) == 2
    scale = biggest(c.center, anchor, c.r, *ref)
    for p, w in zip(got, ref):
        check("line_circle well-conditioned", err(p, w), 16 * math.ulp(scale), (line, c))


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, x2=coord, y2=coord, phi=turn, cross=st.floats(0.5, math.pi - 0.5),
       flip=st.booleans())
def test_line_line_well_conditioned(s, x, y, x2, y2, phi, cross, flip):
    psi = phi + (cross if not flip else -cross)
    l1 = Line(Point(x * s, y * s), Point(math.cos(phi), math.sin(phi)))
    l2 = Line(Point(x2 * s, y2 * s), Point(math.cos(psi), math.sin(psi)))
    (got,), ref = line_line(l1, l2), ref_line_line(l1, l2)
    scale = biggest(l1.point, l2.point, ref)
    check("line_line well-conditioned", err(got, ref), 16 * math.ulp(scale), (l1, l2))


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, r=st.floats(0.5, 10.0), a0=turn, g1=st.floats(0.7, 2.79),
       g2=st.floats(0.7, 2.79))
def test_circle_through3_well_conditioned(s, x, y, r, a0, g1, g2):
    """Every inscribed angle is at least 20° (arcs between the points of at least 40°)."""
    o, r = Point(x * s, y * s), r * s
    a, b, c = (Circle(o, r).at(t) for t in (a0, a0 + g1, a0 + g1 + g2))
    got = circle_through3(a, b, c)
    ref = ref_circumcentre(a, b, c)
    ref_r = float(msqrt((M(a)[0] - ref[0]) ** 2 + (M(a)[1] - ref[1]) ** 2))
    scale = biggest(a, b, c, ref, ref_r)
    check("circle_through3 well-conditioned", err(got.center, ref), 16 * math.ulp(scale), (a, b, c))
    check("circle_through3 well-conditioned", abs(got.r - ref_r), 16 * math.ulp(scale), (a, b, c))


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, x2=coord, y2=coord, x3=coord, y3=coord, angle=turn, t=st.floats(-3, 3))
def test_point_constructions(s, x, y, x2, y2, x3, y3, angle, t):
    """midpoint, foot, reflect, rotate, point_along, distance: a few roundings each, 16 ulp(scale)."""
    a, b, p = Point(x * s, y * s), Point(x2 * s, y2 * s), Point(x3 * s, y3 * s)
    if a == b:
        return
    line = Line.through(a, b)
    (ax, ay), (bx, by), (px, py) = M(a), M(b), M(p)
    (ux, uy) = M(line.direction)
    un = ux * ux + uy * uy
    k = ((px - ax) * ux + (py - ay) * uy) / un
    ref_foot = (ax + k * ux, ay + k * uy)
    ref_rot = (ax + mp.cos(angle) * (px - ax) - mp.sin(angle) * (py - ay),
               ay + mp.sin(angle) * (px - ax) + mp.cos(angle) * (py - ay))
    ab = mdist(a, b)
    dist = t * s
    cases = [
        ("midpoint", midpoint(a, b), ((ax + bx) / 2, (ay + by) / 2)),
        ("foot", foot(line, p), ref_foot),
        ("reflect", reflect(p, line), (2 * ref_foot[0] - px, 2 * ref_foot[1] - py)),
        ("rotate", rotate(p, a, angle), ref_rot),
        ("point_along", point_along(a, b, dist), (ax + (bx - ax) * dist / ab, ay + (by - ay) * dist / ab)),
    ]
    for name, got, ref in cases:
        scale = biggest(a, b, p, ref, dist)
        check(f"{name} (hypothesis)", err(got, ref), 16 * math.ulp(scale), (a, b, p, angle, dist))
    scale = biggest(a, b)
    check("distance (hypothesis)", abs(distance(a, b) - float(ab)), 16 * math.ulp(scale), (a, b))


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, x2=coord, y2=coord, x3=coord, y3=coord)
def test_angles(s, x, y, x2, y2, x3, y3):
    """signed_angle and angle_at within 16 ulp(π) radians whenever both vectors are not tiny."""
    v, a, b = Point(x * s, y * s), Point(x2 * s, y2 * s), Point(x3 * s, y3 * s)
    u, w = a - v, b - v
    # The vectors are themselves rounded differences; measure from the rounded vectors, and keep them
    # away from zero relative to the coordinates so that this rounding cannot turn them.
    if min(abs(u), abs(w)) < 1e-3 * s:
        return
    (ux, uy), (wx, wy) = M(u), M(w)
    ref = mp.atan2(ux * wy - uy * wx, ux * wx + uy * wy)
    got = signed_angle(u, w)
    gap = abs(mpf(got) - ref)
    gap = min(gap, abs(gap - 2 * mp.pi))                      # −π and π are the same angle
    check("signed_angle (hypothesis)", float(gap), 16 * math.ulp(math.pi), (u, w))
    check("angle_at (hypothesis)", abs(angle_at(v, a, b) - abs(float(ref))), 16 * math.ulp(math.pi), (v, a, b))


# ----------------------------------------------------------------------------------------------------
# Near tangency and near parallelism, in translated scenes.

def _rng(*key) -> random.Random:
    return random.Random(repr(key))


def _radius(rng: random.Random) -> float:
    return 10.0 ** rng.uniform(-3, 4)                       # 1 µm … 10 m


def _near_external(rng, delta, offset):
    r1 = _radius(rng)
    r2 = r1 * rng.uniform(0.25, 4.0)
    theta = rng.uniform(-math.pi, math.pi)
    c1 = Point(offset[0] + rng.uniform(-1, 1) * r1, offset[1] + rng.uniform(-1, 1) * r1)
    dn = (r1 + r2) * (1 - delta)
    c2 = Point(c1.x + dn * math.cos(theta), c1.y + dn * math.sin(theta))
    d = mdist(c1, c2)                                      # the rounded centres are the inputs:
    r2 = float(d / (1 - mpf(delta)) - r1)                  # let r2 absorb their rounding
    c1, c2 = Circle(c1, r1), Circle(c2, r2)
    return c1, c2, float(1 - d / (mpf(r1) + mpf(r2)))


def _near_internal(rng, delta, offset, *, big_first, d_over_r=(0.2, 0.8)):
    r1 = _radius(rng)
    theta = rng.uniform(-math.pi, math.pi)
    c1 = Point(offset[0] + rng.uniform(-1, 1) * r1, offset[1] + rng.uniform(-1, 1) * r1)
    dn = r1 * rng.uniform(*d_over_r)
    c2 = Point(c1.x + dn * math.cos(theta), c1.y + dn * math.sin(theta))
    d = mdist(c1, c2)
    m = d * (1 - mpf(delta))                               # |r1 − r2| = d (1 − δ)
    r2 = float(mpf(r1) - m) if big_first else float(mpf(r1) + m)
    return Circle(c1, r1), Circle(c2, r2), float(1 - abs(mpf(r1) - mpf(r2)) / d)


def _where(offset) -> str:
    return "at the origin" if offset == (0.0, 0.0) else "translated"


def _assert_circle_circle_near_tangent(family, c1, c2, delta):
    got = circle_circle(c1, c2)
    assert len(got) == 2, f"{family}: {len(got)} point(s) at δ = {delta:.3g} for {c1}, {c2}"
    ref = ref_circle_circle(c1, c2)
    big = max(c1.r, c2.r)
    for p, q in zip(got, ref):
        bound = 4 * EPS * big / math.sqrt(delta) + math.ulp(biggest(q))
        check(family, err(p, q), bound, (c1, c2, delta))


@pytest.mark.parametrize("offset", OFFSETS)
@pytest.mark.parametrize("delta", DELTAS)
def test_circle_circle_near_external_tangency(delta, offset):
    rng = _rng("external", delta, offset)
    for _ in range(25):
        c1, c2, actual = _near_external(rng, delta, offset)
        assert actual == pytest.approx(delta, rel=1e-2)
        _assert_circle_circle_near_tangent(f"circle_circle near external tangency, {_where(offset)}", c1, c2,
                                           actual)


@pytest.mark.parametrize("big_first", [True, False], ids=["inner-second", "inner-first"])
@pytest.mark.parametrize("offset", OFFSETS)
@pytest.mark.parametrize("delta", DELTAS)
def test_circle_circle_near_internal_tangency(delta, offset, big_first):
    rng = _rng("internal", delta, offset, big_first)
    for _ in range(25):
        c1, c2, actual = _near_internal(rng, delta, offset, big_first=big_first)
        assert actual == pytest.approx(delta, rel=1e-2)
        _assert_circle_circle_near_tangent(f"circle_circle near internal tangency, {_where(offset)}", c1, c2,
                                           actual)


@pytest.mark.parametrize("offset", OFFSETS[:2])
@pytest.mark.parametrize("delta", DELTAS[:-2])
def test_circle_circle_near_internal_tangency_small_d(delta, offset):
    """Nearly equal radii, centres 0.5–1 % of a radius apart: the factor d − (r1 − r2) must be formed
    from the already exact r1 − r2, or its error is ε·r instead of ε·d (a hundredfold here)."""
    rng = _rng("internal-small-d", delta, offset)
    for _ in range(25):
        c1, c2, actual = _near_internal(rng, delta, offset, big_first=rng.random() < 0.5,
                                        d_over_r=(0.005, 0.01))
        _assert_circle_circle_near_tangent(f"circle_circle near internal tangency, small d, {_where(offset)}",
                                           c1, c2, actual)


def _near_tangent_line(rng, delta, offset):
    r = _radius(rng)
    phi = rng.uniform(-math.pi, math.pi)
    center = Point(offset[0] + rng.uniform(-1, 1) * r, offset[1] + rng.uniform(-1, 1) * r)
    u = Point(math.cos(phi), math.sin(phi))
    side = rng.choice((-1.0, 1.0))
    anchor = center + u.perp() * (side * r * (1 - delta)) + u * (rng.uniform(-1, 1) * r)
    line = Line(anchor, u)
    (px, py), (ux, uy), (cx, cy) = M(anchor), M(line.direction), M(center)
    p = abs(ux * (py - cy) - uy * (px - cx)) / msqrt(ux * ux + uy * uy)
    r = float(p / (1 - mpf(delta)))                        # the radius absorbs the anchor's rounding
    return line, Circle(center, r), float(1 - p / mpf(r))


@pytest.mark.parametrize("offset", OFFSETS)
@pytest.mark.parametrize("delta", DELTAS)
def test_line_circle_near_tangency(delta, offset):
    rng = _rng("line", delta, offset)
    for _ in range(25):
        line, c, actual = _near_tangent_line(rng, delta, offset)
        got = line_circle(line, c)
        assert len(got) == 2, f"{len(got)} point(s) at δ = {actual:.3g} for {line}, {c}"
        ref = ref_line_circle(line, c)
        for p, q in zip(got, ref):
            bound = 4 * EPS * c.r / math.sqrt(actual) + math.ulp(biggest(q))
            check(f"line_circle near tangency, {_where(offset)}", err(p, q), bound, (line, c, actual))


ANGLES = [10.0 ** -k for k in range(1, 13)]


@pytest.mark.parametrize("offset", OFFSETS)
@pytest.mark.parametrize("theta", ANGLES)
@pytest.mark.parametrize("crossing", ["near", "far"])
def test_line_line_near_parallel(theta, offset, crossing):
    """near: the lines cross between their anchors' neighbourhood (anchors 0.5–2 L from the crossing);
    far: the anchors are L apart across the lines, so the crossing is about L/θ away."""
    rng = _rng("lines", theta, offset, crossing)
    for _ in range(25):
        size = _radius(rng)
        phi = rng.uniform(-math.pi, math.pi)
        psi = phi + rng.choice((-1.0, 1.0)) * theta
        u1, u2 = Point(math.cos(phi), math.sin(phi)), Point(math.cos(psi), math.sin(psi))
        if crossing == "near":
            x = Point(offset[0] + rng.uniform(-1, 1) * size, offset[1] + rng.uniform(-1, 1) * size)
            p1, p2 = x - u1 * (size * rng.uniform(0.5, 2)), x + u2 * (size * rng.uniform(0.5, 2))
        else:
            p1 = Point(offset[0] + rng.uniform(-1, 1) * size, offset[1] + rng.uniform(-1, 1) * size)
            p2 = p1 + u1.perp() * (size * rng.uniform(0.5, 2)) + u1 * (size * rng.uniform(-1, 1))
        l1, l2 = Line(p1, u1), Line(p2, u2)
        (got,) = line_line(l1, l2)
        ref = ref_line_line(l1, l2)
        (a1, b1), (a2, b2) = M(l1.direction), M(l2.direction)
        sine = float(abs(a1 * b2 - b1 * a2) / msqrt((a1 * a1 + b1 * b1) * (a2 * a2 + b2 * b2)))
        (rx, ry) = ref
        reach = float(msqrt((rx - M(p1)[0]) ** 2 + (ry - M(p1)[1]) ** 2)
                      + msqrt((rx - M(p2)[0]) ** 2 + (ry - M(p2)[1]) ** 2))
        # Turning either line about its anchor by ε rad (a rounded direction) slides the crossing by
        # |X − P|·ε/sin θ: the bound is that conditioning, with 4 for the roundings (module docstring).
        bound = 4 * EPS * reach / sine + math.ulp(biggest(ref))
        check(f"line_line near parallel ({crossing}), {_where(offset)}", err(got, ref), bound, (l1, l2, sine))
