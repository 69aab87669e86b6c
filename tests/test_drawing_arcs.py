"""Issue 11 review (hlook11c): an angle mark's arc reads as an arc, over every gallery figure as its sheet 1 draws
it — long enough not to read as a tick (001-08's θ = 12.5° was a 2 mm stroke at 9 mm; 35 of 148 arcs were under
3 mm), and never drawn on a circle about its own vertex (200-01's αmax arc at B0 lay on the roller circle, 5 mm
both at 1:2, so no arc showed); arcs about one vertex lie apart (hlook11m: 001-21's φ1, φ2 arcs on its ψ arc)."""
from __future__ import annotations

import math

import pytest

from geomcon.render.draw import ARC_LENGTH, MIN_ANGLE_RADIUS, SMALL_ANGLE_RADIUS, least_arc_radius
from geomcon.geometry.primitives import Point
from geomcon.render.symbols import ARC_GAIN, POINT_CLEAR, SMALL_ANGLE_REACH
from geomcon.render.symbols import ARC_APART
from geomcon.render.shapes import ArcP, Disc

from test_drawing_defects import NAMES, angle_marks, figure

ON_CIRCLE = 0.6
"""Paper mm: an arc nearer a circle about its vertex than this is drawn over it (a stroke and a half)."""


def _mark_arcs(fig) -> list[tuple[str, ArcP]]:
    return [(g.key, s) for g in fig.groups if angle_marks(fig.values.get(g.key))
            for s in g.shapes if isinstance(s, ArcP) and abs(s.sweep) > math.radians(0.2)]


def _reach(fig, arc: ArcP) -> float:
    """SMALL_ANGLE_REACH of the shorter ray (of 4 mm or more), on paper, of the mark the arc belongs to (0: none)."""
    out = 0.0
    for g in fig.groups:
        for m in angle_marks(fig.values.get(g.key)):
            if math.dist(fig.view.p(m.vertex), arc.c) < 1e-6:
                rays = [x for x in (fig.view.length(abs(m.a - m.vertex)), fig.view.length(abs(m.b - m.vertex)))
                        if x >= 4.0]
                out = max(out, SMALL_ANGLE_REACH * min(rays, default=0.0))
    return out


@pytest.mark.parametrize("name", NAMES)
def test_every_angle_arc_is_long_enough_to_read_as_an_arc(name):
    """An arc is ARC_LENGTH (3.5 mm) long or more, unless the angle is so small that even SMALL_ANGLE_RADIUS
    (20 mm) cannot make it so, or its rays are too short to carry it that far (a pressure angle's rays of 5 mm)."""
    fig = figure(name)
    for key, arc in _mark_arcs(fig):
        phi = abs(arc.sweep)
        want = min(ARC_LENGTH, phi * max(MIN_ANGLE_RADIUS, min(SMALL_ANGLE_RADIUS, _reach(fig, arc))))
        assert phi * arc.r >= want - ARC_GAIN, \
            (key, round(arc.r, 3), round(phi * arc.r, 3))


@pytest.mark.parametrize("name", NAMES)
def test_no_angle_arc_lies_on_a_circle_about_its_vertex(name):
    fig = figure(name)
    circles = [(g.key, s.c, s.r) for g in fig.groups if not angle_marks(fig.values.get(g.key))
               for s in g.shapes if isinstance(s, (Disc, ArcP)) and s.r > 1.0]
    for key, arc in _mark_arcs(fig):
        on = [k for k, c, r in circles if math.dist(c, arc.c) < 0.3 and abs(r - arc.r) < ON_CIRCLE]
        assert not on, (key, round(arc.r, 3), on)


def test_the_review_s_arcs_read_as_arcs():
    """The cases the review named: 001-08's θ, 200-01's αmax at B0 off its roller."""
    theta = dict(_mark_arcs(figure("001-08_crank_rocker")))["mark_theta"]
    assert abs(theta.sweep) * theta.r >= 3.0            # was 1.96 mm at 9 mm
    alpha = dict(_mark_arcs(figure("200-01_cam_roller_offset")))["mark_alpha_rise"]
    assert alpha.r >= 5.0 + ON_CIRCLE


def _points(fig) -> list[tuple[str, tuple[float, float]]]:
    """The points a figure draws (a hinge or a dot), on paper."""
    return [(g.key, s.c) for g in fig.groups if isinstance(fig.values.get(g.key), Point)
            for s in g.shapes if isinstance(s, Disc) and s.r <= 2.0]


@pytest.mark.parametrize("name", NAMES)
def test_no_angle_arc_runs_through_a_point_inside_its_angle(name):
    """001-19's 180° − θ arc about A ran through the pin of C (10 mm below A at 1:5): an arc keeps POINT_CLEAR from
    every point drawn inside its angle, unless that would take it below least_arc_radius (5 mm, more for a small
    angle)."""
    fig = figure(name)
    pts = _points(fig)
    for key, arc in _mark_arcs(fig):
        for k, c in pts:
            d = math.dist(c, arc.c)
            if d < 1e-6 or d - POINT_CLEAR < least_arc_radius(arc.sweep) or abs(d - arc.r) >= POINT_CLEAR - 1e-6:
                continue
            t = (math.atan2(c[1] - arc.c[1], c[0] - arc.c[0]) - arc.start) * (1.0 if arc.sweep >= 0 else -1.0)
            assert t % math.tau > abs(arc.sweep) + 1e-9, (key, k, round(d, 2), round(arc.r, 2))


def test_the_slotter_s_arm_cd_prime_is_drawn_as_the_link_d_prime_e_prime_hangs_from():
    """001-19 drew D′E′ solid from a bare dot D′, its arm CD′ only as a grey dashed line through A: the coupler
    hung from nothing. The arm is a link and D′ a hinge."""
    fig = figure("001-19_slotter_rotating_guide_bar")
    styles = {g.key: g.classes for g in fig.groups}
    assert "style-link" in styles["CDt"].split() and "style-joint" in styles["Dt"].split()


@pytest.mark.parametrize("name", NAMES)
def test_the_angle_arcs_about_one_vertex_lie_apart(name):
    """001-21 drew its φ1 and φ2 arcs (made smaller to end on the 10 mm frame line through D) at 8.5 mm, on its ψ
    arc at 9 mm: one double line, which arc named ψ unclear. Arcs of marks about one vertex keep ARC_APART (2 mm)."""
    arcs = _mark_arcs(figure(name))
    for i, (k1, a1) in enumerate(arcs):
        for k2, a2 in arcs[i + 1:]:
            if math.dist(a1.c, a2.c) < 1e-6 and _overlap(a1, a2):
                assert abs(a1.r - a2.r) >= ARC_APART - 1e-6, (k1, k2, round(a1.r, 3), round(a2.r, 3))


def _overlap(a1, a2) -> bool:
    """Whether two arcs about one centre share directions (more than 0.5°): arcs of angles side by side (001-29's
    δ0 and δ0′, which make up the turn between them) may share a radius and read as two arcs all the same."""
    def span(a):
        lo = a.start if a.sweep >= 0 else a.start + a.sweep
        return lo % math.tau, abs(a.sweep)
    (lo1, w1), (lo2, w2) = span(a1), span(a2)
    eps = math.radians(0.5)
    return (lo2 - lo1) % math.tau < w1 - eps or (lo1 - lo2) % math.tau < w2 - eps
