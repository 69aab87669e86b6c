"""Named branch rules: LeftOf, RightOf, Above, Below, NearestTo, FarthestFrom, OtherThan.

What this proves
----------------
- Each rule chooses the right one of two candidates, whatever order the candidates come in.
- A single (tangent) candidate is returned as it is -- even when it lies on the rule's dividing line.
- A case the rule cannot decide raises :class:`AmbiguousBranch`: both candidates on the dividing line
  (or equidistant from the reference point), Above/Below of a vertical line, a dividing line of zero
  length, a number of candidates other than 1 or 2.
- ``describe()`` gives an English and a Chinese phrase naming the rule's points (by coordinates, by the
  ``key`` of a scene reference, or through a ``label`` callable); ``refs``/``with_points`` round-trip.
- On random circle–circle intersections (hypothesis, derandomized) the rules agree with the documented
  order and with each other: LeftOf(c1, c2) takes the first point, RightOf the second, NearestTo and
  FarthestFrom of the same point differ, OtherThan(one) gives the other, Above and Below differ.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geomcon.errors import AmbiguousBranch
from geomcon.geometry import (Above, Below, Branch, Circle, FarthestFrom, LeftOf, NearestTo, OtherThan, Point,
                              RightOf, circle_circle)
from geomcon.scene import Ref

DERANDOMIZED = settings(derandomize=True, max_examples=200, deadline=None)

UP, DOWN = Point(4, 3), Point(4, -3)           # the intersections of |P| = 5 and |P − (8, 0)| = 5
A, B = Point(0, 0), Point(8, 0)

CHOICES = [
    (LeftOf(A, B), UP), (RightOf(A, B), DOWN), (LeftOf(B, A), DOWN), (RightOf(B, A), UP),
    (Above(A, B), UP), (Below(A, B), DOWN), (Above(B, A), UP), (Below(B, A), DOWN),   # undirected
    (Above(Point(0, 0), Point(8, 1)), UP), (Below(Point(0, 0), Point(-8, 1)), DOWN),   # slanted lines
    (NearestTo(Point(4, -10)), DOWN), (NearestTo(Point(-100, 0.1)), UP),
    (FarthestFrom(Point(4, -10)), UP), (FarthestFrom(Point(-100, 0.1)), DOWN),
    (OtherThan(UP), DOWN), (OtherThan(DOWN), UP), (OtherThan(Point(4, 2.9)), DOWN),
]


@pytest.mark.parametrize("rule, expected", CHOICES, ids=[f"{type(r).__name__}-{i}" for i, (r, _) in enumerate(CHOICES)])
def test_rule_chooses_whatever_the_candidate_order(rule, expected):
    assert rule.choose((UP, DOWN)) == expected
    assert rule.choose((DOWN, UP)) == expected


@pytest.mark.parametrize("rule", [r for r, _ in CHOICES] + [LeftOf(A, Point(4, 3)), NearestTo(Point(4, 3)),
                                                          OtherThan(Point(4, 3))],
                         ids=lambda r: type(r).__name__)
def test_single_tangent_candidate_is_returned_as_is(rule):
    touch = Point(4, 3)                            # for the last three it lies on the dividing line / is p
    assert rule.choose((touch,)) is touch


@pytest.mark.parametrize("rule, cands", [
    (LeftOf(A, B), (Point(1, 0), Point(5, 0))),                    # both on the dividing line
    (RightOf(A, B), (Point(-3, 0), Point(5, 0))),
    (Above(A, B), (Point(1, 2), Point(5, 2))),                     # the same height
    (Below(Point(0, 0), Point(2, 1)), (Point(2, 2), Point(4, 3))),  # a parallel to a slanted line
    (NearestTo(Point(0, 7)), (Point(-1, 0), Point(1, 0))),          # on the candidates' bisector
    (FarthestFrom(Point(0, -7)), (Point(-1, 0), Point(1, 0))),
    (OtherThan(Point(0, 0)), (Point(-1, 0), Point(1, 0))),          # neither, equally far from both
    (LeftOf(A, B), (UP, UP)),                                       # two equal candidates
    (LeftOf(A, B), ()), (LeftOf(A, B), (UP, DOWN, UP)),             # not 1 or 2 candidates
], ids=lambda x: type(x).__name__ if isinstance(x, Branch) else "")
def test_undecidable_cases_raise(rule, cands):
    with pytest.raises(AmbiguousBranch):
        rule.choose(cands)


@pytest.mark.parametrize("rule", [Above, Below])
@pytest.mark.parametrize("a, b", [(Point(1, 0), Point(1, 5)), (Point(1, 5), Point(1, 0)),
                                  (Point(1e6, -3), Point(1e6, 4e-3))])
@pytest.mark.parametrize("cands", [(Point(0, 1), Point(2, 1)), (Point(0, 1),)], ids=["two", "one"])
def test_above_below_of_a_vertical_line_raise(rule, a, b, cands):
    """The rule itself is undefined, so it refuses even a single candidate: a construction must not
    succeed at its tangent position and fail everywhere else."""
    with pytest.raises(AmbiguousBranch, match="vertical"):
        rule(a, b).choose(cands)


@pytest.mark.parametrize("rule", [LeftOf, RightOf, Above, Below])
@pytest.mark.parametrize("cands", [(UP, DOWN), (UP,)], ids=["two", "one"])
def test_a_zero_length_dividing_line_raises(rule, cands):
    with pytest.raises(AmbiguousBranch, match="zero length"):
        rule(Point(2, 2), Point(2, 2)).choose(cands)


def test_describe_in_english_and_chinese():
    assert LeftOf("A", "D").describe() == ("left of the directed line A→D", "位于有向线 A→D 左侧的交点")
    assert RightOf(Ref("A"), Ref("D")).describe() == ("right of the directed line A→D", "位于有向线 A→D 右侧的交点")
    assert Above(Ref("A"), Ref("D")).describe() == ("above the line AD", "位于直线 AD 上方的交点")
    assert Below("A", "D").describe() == ("below the line AD", "位于直线 AD 下方的交点")
    assert NearestTo(Ref("D")).describe() == ("the intersection nearer to D", "离 D 较近的交点")
    assert FarthestFrom("D").describe() == ("the intersection farther from D", "离 D 较远的交点")
    assert OtherThan(Ref("C1")).describe() == ("the intersection other than C1", "异于 C1 的另一交点")
    assert NearestTo(Point(1.5, -2)).describe()[0] == "the intersection nearer to (1.5, -2)"
    assert LeftOf(Ref("A"), Ref("B")).describe(label=lambda r: r.key.lower())[1] == "位于有向线 a→b 左侧的交点"


@pytest.mark.parametrize("rule", [LeftOf(A, B), RightOf(A, B), Above(A, B), Below(A, B), NearestTo(A),
                                  FarthestFrom(A), OtherThan(A)], ids=lambda r: type(r).__name__)
def test_every_rule_describes_itself_in_both_languages(rule):
    en, zh = rule.describe()
    def cjk(text):
        return any("\u4e00" <= ch <= "\u9fff" for ch in text)

    assert not cjk(en) and en.strip() == en and "(0, 0)" in en
    assert cjk(zh) and "(0, 0)" in zh


def test_refs_and_with_points_round_trip():
    rule = LeftOf(Ref("A"), Ref("D"))
    assert rule.refs() == (Ref("A"), Ref("D"))
    resolved = rule.with_points((A, B))
    assert resolved == LeftOf(A, B) and resolved.choose((DOWN, UP)) == UP
    assert OtherThan(Ref("C")).with_points((UP,)).choose((UP, DOWN)) == DOWN


# ----------------------------------------------------------------------------------------------------
# Random intersections: the rules agree with the documented order and with each other.

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
magnitude = st.integers(-3, 6).map(lambda k: 10.0 ** k)


@DERANDOMIZED
@given(s=magnitude, x=coord, y=coord, r1=st.floats(0.5, 10.0), k=st.floats(0.3, 3.0), f=st.floats(0.05, 0.95),
       theta=st.floats(-math.pi, math.pi), px=coord, py=coord)
def test_rules_on_random_intersections(s, x, y, r1, k, f, theta, px, py):
    r1, r2 = r1 * s, r1 * k * s
    d = abs(r1 - r2) + f * (r1 + r2 - abs(r1 - r2))
    c1 = Circle(Point(x * s, y * s), r1)
    c2 = Circle(Point(c1.center.x + d * math.cos(theta), c1.center.y + d * math.sin(theta)), r2)
    first, second = cands = circle_circle(c1, c2)
    assert LeftOf(c1.center, c2.center).choose(cands) == first
    assert RightOf(c1.center, c2.center).choose(cands) == second
    assert OtherThan(first).choose(cands) == second and OtherThan(second).choose(cands) == first
    p = Point(px * s, py * s)
    dist = (abs(first - p), abs(second - p))
    if abs(dist[0] - dist[1]) > 1e-9 * max(dist):
        near = NearestTo(p).choose(cands)
        assert near == (first if dist[0] < dist[1] else second)
        assert FarthestFrom(p).choose(cands) != near
    if abs(first.y - second.y) > 1e-9 * s and abs(math.cos(theta)) > 1e-6:
        # the centre line is not vertical: Above picks the higher point relative to it
        up = Above(c1.center, c2.center).choose(cands)
        assert Below(c1.center, c2.center).choose(cands) != up
        assert up == (first if math.cos(theta) > 0 else second)           # left of a rightward line is up
