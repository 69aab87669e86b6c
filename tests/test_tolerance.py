"""One tolerance policy, scale-relative, the same in every routine.

What this proves
----------------
- :func:`tol`, :func:`is_zero` and :func:`agree` do what they say (largest magnitude sets the scale,
  inclusive threshold, non-finite values never agree).
- Every routine that decides "zero or not" flips its decision at a gap of about ``REL_TOL`` times the
  largest length involved: circle–circle (external and internal contact), line–circle, line–line
  (parallelism and coincidence), ``circle_through3`` (collinearity) and the branch rules (ties, vertical
  lines). Each is probed at 0.3·REL_TOL (decided as zero) and at 3·REL_TOL (decided as not zero).
- There is no absolute floor: the same configurations, scaled by 1e-3 … 1e6 (and translated by a few
  times their size), take exactly the same decisions -- including the nearly degenerate ones.
- It is *one* policy: raising ``geomcon.tolerance.REL_TOL`` at run time moves the decisions of every
  routine together (no routine keeps a private threshold).
"""
from __future__ import annotations

import math

import pytest

import geomcon.tolerance as tolerance
from geomcon.errors import AmbiguousBranch, Coincident, Degenerate
from geomcon.geometry import (Above, Below, Line, LeftOf, NearestTo, Point, RightOf, circle_circle,
                              circle_through3, line_circle, line_line)
from geomcon.testing import internally_tangent, tangent_line, tangent_pair
from geomcon.tolerance import CHECK_REL, EPS, REL_TOL, agree, is_zero, tol


class TestPrimitives:
    def test_eps_is_the_double_epsilon(self):
        assert EPS == 2.0 ** -52

    def test_tol_is_relative_to_the_largest_magnitude(self):
        assert tol(1.0) == REL_TOL
        assert tol(3.0, -4.0, 0.5) == 4.0 * REL_TOL
        assert tol(0.0) == 0.0

    def test_is_zero_is_inclusive_and_scale_relative(self):
        assert is_zero(0.0, 1.0)
        assert is_zero(REL_TOL * 7.0, 7.0) and is_zero(-REL_TOL * 7.0, 7.0)
        assert not is_zero(REL_TOL * 7.0 * (1 + 1e-9), 7.0)
        assert is_zero(1e-20, 1e-6) and not is_zero(1e-17, 1e-6)      # no absolute floor
        assert not is_zero(1e-300, 0.0) and is_zero(0.0, 0.0)

    def test_agree(self):
        assert agree(1.0, 1.0 + 0.5 * CHECK_REL) and not agree(1.0, 1.0 + 2 * CHECK_REL)
        assert agree(1e6, 1e6 * (1 + 0.5 * CHECK_REL))
        assert agree(0.0, 1e-12, scale=1.0) and not agree(0.0, 1e-12)
        assert agree(2.0, 2.0 + 1e-3, rel=1e-3)
        assert not agree(math.nan, math.nan) and not agree(math.inf, math.inf) and not agree(1.0, math.nan)

    def test_rel_tol_is_about_450_ulp(self):
        assert 400 * EPS < REL_TOL < 500 * EPS


# ----------------------------------------------------------------------------------------------------
# Probes: (name, k → callable at relative gap k·REL_TOL and scale s, outcome when zero, outcome when not).

def outcome(f):
    try:
        out = f()
    except (AmbiguousBranch, Coincident, Degenerate) as exc:
        return type(exc).__name__
    return len(out) if isinstance(out, tuple) else "ok"


def at(s):
    """A placement a few times the configuration's size away from the origin, and turned."""
    return dict(scale=s, at=Point(2.5 * s, -1.5 * s), angle=0.4)


PROBES = {
    # circle–circle: d = (r1 + r2)(1 + g); the scale is d
    "external contact, apart": (lambda g, s: circle_circle(*tangent_pair(3, 2, gap=g, **at(s))), 1, 0),
    "external contact, crossing": (lambda g, s: circle_circle(*tangent_pair(3, 2, gap=-g, **at(s))), 1, 2),
    # internal: d = (r1 − r2)(1 + g), the scale is r1 = 3 (r1 − r2)/2, so a gap g is g·2/3 of the scale
    "internal contact, crossing": (lambda g, s: circle_circle(*internally_tangent(3, 1, gap=1.5 * g, **at(s))),
                                   1, 2),
    "internal contact, nested": (lambda g, s: circle_circle(*internally_tangent(3, 1, gap=-1.5 * g, **at(s))),
                                 1, 0),
    "line–circle, missing": (lambda g, s: line_circle(*tangent_line(2, gap=g, **at(s))), 1, 0),
    "line–circle, cutting": (lambda g, s: line_circle(*tangent_line(2, gap=-g, **at(s))), 1, 2),
    # two lines through anchors 1 apart, at an angle whose sine is g: parallel below the tolerance
    "line–line, nearly parallel": (lambda g, s: line_line(
        Line(Point(0, 0), Point(1, 0)), Line(Point(0, s), Point(math.sqrt(1 - g * g), g))), 0, 1),
    # parallel lines a relative distance g apart (anchors s apart along the line)
    "line–line, nearly coincident": (lambda g, s: line_line(
        Line(Point(s, s), Point(1, 0)), Line(Point(2 * s, s + g * s), Point(1, 0))), "Coincident", 0),
    # c at a relative height g over the chord ab of length s
    "circle_through3, nearly collinear": (lambda g, s: (circle_through3(
        Point(s, 0), Point(2 * s, 0), Point(1.5 * s, g * s)),), "Degenerate", 1),
    # candidates s apart along the line, at relative distances ±g/2 from it: scores differ by g·s
    "LeftOf, nearly on the line": (lambda g, s: (LeftOf(Point(0, 0), Point(s, 0)).choose(
        (Point(s, 0.5 * g * s), Point(2 * s, -0.5 * g * s))),), "AmbiguousBranch", 1),
    "RightOf, nearly on the line": (lambda g, s: (RightOf(Point(0, 0), Point(s, 0)).choose(
        (Point(s, 0.5 * g * s), Point(2 * s, -0.5 * g * s))),), "AmbiguousBranch", 1),
    # candidates 2s apart, the reference point g·s off their bisector: distances differ by g·2s
    "NearestTo, nearly equidistant": (lambda g, s: (NearestTo(Point(g * s, 0)).choose(
        (Point(-s, 0), Point(s, 0))),), "AmbiguousBranch", 1),
    # a line whose normal has a vertical component g (a nearly vertical line)
    "Above, nearly vertical line": (lambda g, s: (Above(Point(0, 0), Point(g * s, s)).choose(
        (Point(-s, 0), Point(s, 0))),), "AmbiguousBranch", 1),
    "Below, nearly vertical line": (lambda g, s: (Below(Point(0, 0), Point(g * s, s)).choose(
        (Point(-s, 0), Point(s, 0))),), "AmbiguousBranch", 1),
}

SCALES = [10.0 ** k for k in range(-3, 7)]


@pytest.mark.parametrize("s", SCALES, ids=[f"s={s:g}" for s in SCALES])
@pytest.mark.parametrize("name", PROBES)
def test_decision_flips_at_rel_tol_at_every_scale(name, s):
    probe, when_zero, when_not = PROBES[name]
    assert outcome(lambda: probe(0.3 * REL_TOL, s)) == when_zero
    assert outcome(lambda: probe(3.0 * REL_TOL, s)) == when_not
    assert outcome(lambda: probe(0.0, s)) == when_zero
    assert outcome(lambda: probe(1e-3, s)) == when_not


@pytest.mark.parametrize("name", PROBES)
def test_rel_tol_is_read_at_run_time_by_every_routine(name, monkeypatch):
    """One policy: with REL_TOL = 1e-6, a relative gap of 1e-7 is zero everywhere, and 1e-5 is not."""
    probe, when_zero, when_not = PROBES[name]
    assert outcome(lambda: probe(1e-7, 10.0)) == when_not
    monkeypatch.setattr(tolerance, "REL_TOL", 1e-6)
    assert outcome(lambda: probe(1e-7, 10.0)) == when_zero
    assert outcome(lambda: probe(1e-5, 10.0)) == when_not


@pytest.mark.parametrize("s", SCALES, ids=[f"s={s:g}" for s in SCALES])
def test_tiny_scenes_are_not_swallowed_by_an_absolute_floor(s):
    """At 1e-3 mm a chord of 1e-9 mm is still a chord: no decision depends on the unit."""
    c1, c2 = tangent_pair(3, 2, gap=-1e-9, scale=s)
    p, q = circle_circle(c1, c2)
    assert 0 < abs(p - q) < 1e-3 * s
