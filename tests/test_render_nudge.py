"""A point's label whose best place lies a hair from a link, ground, block or pin is tried nudged into the slot
beside it (geomcon/render/figure.py ``_nudged``, hjoin11): its places lie a millimetre apart and the free slot may
be narrower. 001-06b's C3 (under the guide with a leader: 0.18 mm from the hatch's foot, 0.28 mm from
H=101.74's text) and 100-04's B1 (a hair from AB1) came clear so; tests/test_gallery_text_across.py holds them."""
from __future__ import annotations

import math

import shapely

from geomcon.render.candidates import LEADER_MAX
from geomcon.render.figure import NUDGES, _nudged
from geomcon.render.placement import LABEL_REACH, Placer, Request, label_distances


def _reach(r: Request, c: tuple[float, float]) -> float:
    return r.box(*c).distance(shapely.Point(r.anchor))


def test_a_nudged_label_stays_by_its_point_and_off_its_marker():
    gap = 0.95
    r = Request((0.0, 0.0), 4.0, 3.4, gap, 0.0, distances=label_distances(gap))
    at = (gap + 2.0 + 2.05, 0.0)                       # right of its point, at its farthest distance
    near = _nudged(r, at, (1.0, 0.0))                  # away from a line left of it: not farther off
    assert near is None or all(_reach(r, c) <= LABEL_REACH + 1e-9 for c in near.candidates)
    near = _nudged(r, at, (0.0, 1.0))                  # down, and 45° either side
    assert near is not None and 0 < len(near.candidates) <= 3 * len(NUDGES)
    assert all(gap - 1e-9 <= _reach(r, c) <= LABEL_REACH + 1e-9 for c in near.candidates)
    assert max(math.dist(at, c) for c in near.candidates) <= max(NUDGES) + 1e-9
    assert all(c[1] > at[1] for c in near.candidates)                # never towards what it is a hair from


def test_a_leaders_text_may_go_as_far_as_its_leader():
    r = Request((0.0, 0.0), 4.0, 3.4, 0.95, 0.0, distances=(0.0, 1.0, 2.0), lead=0.95)
    near = _nudged(r, (0.95 + 2.0 + 8.0, 0.0), (1.0, 0.0))
    assert near is not None and len(near.candidates) == 3 * len(NUDGES)
    assert all(_reach(r, c) <= LEADER_MAX for c in near.candidates)


def test_the_slot_beside_a_line_is_found():
    """A label 0.1 mm under a link (its grid's places 1 mm apart) finds the place 0.1–0.5 mm lower clear of it."""
    link = shapely.LineString([(-20.0, -3.0), (20.0, -3.0)])
    placer = Placer([(link, "link", 0.0, 2.0)], (-50.0, -50.0, 50.0, 50.0))
    r = Request((0.0, 0.0), 4.0, 2.0, 0.5, math.pi / 2, distances=(0.0, 0.5))
    hair = (0.0, -3.0 + 0.1 + 1.0)                     # the box's top 0.1 mm under the link
    assert placer.clearance(r.box(*hair), "pt") < 0.2
    (cx, cy), score = placer.best(_nudged(r, hair, (0.0, 1.0)), "pt")
    assert placer.clearance(r.box(cx, cy), "pt") >= 0.2 and score > -1.0
