"""An eccentric cam's translating follower marks its pressure angle α where its value finds room (issue 11,
hacross11c): 001-29 (roller, the normal running down to O's side of the guide) marked α below B, inside the disc,
and printed α=36.87° across the cam's profile; it is marked above B now, between the stem and the normal beyond B,
clear of the guide's bearing, and its value meets neither the profile nor the roller."""
from __future__ import annotations

import math

import pytest
import shapely

from geomcon.render.shapes import ArcP, Poly, Text
from geomcon.scene.marks import AngleMark

from test_drawing_defects import box, figure


def _group(fig, key):
    return next(g for g in fig.groups if g.key == key and not g.arc)


@pytest.mark.parametrize("name", ["001-29_eccentric_roller_offset_ccw", "001-29_eccentric_roller_offset_cw"])
def test_a_roller_s_alpha_on_o_s_side_is_marked_above_b_clear_of_the_profile(name):
    fig = figure(name)
    mark = fig.values["mark_alpha"]
    assert isinstance(mark, AngleMark)
    assert mark.a.y > mark.vertex.y and mark.b.y > mark.vertex.y          # both rays up: above B, outside the disc
    arc = next(s for s in _group(fig, "mark_alpha").shapes if isinstance(s, ArcP))
    ink = shapely.LineString([arc.at(k / 16) for k in range(17)])
    disc = next(s for s in _group(fig, "disc").shapes if not isinstance(s, Text))
    bearing = shapely.MultiLineString([s.pts for s in _group(fig, "guide_mark").shapes if isinstance(s, Poly)])
    profile = shapely.Point(fig.view.p(fig.values["disc"].center)).buffer(disc.r, 256).exterior
    assert ink.distance(profile) > 1.0 and ink.distance(bearing) > 0.5      # the arc off the disc and the bearing
    text = next(t for t in _group(fig, "mark_alpha").texts)
    assert "".join(s for s, _ in text.runs) == "α=36.87°"
    roller = fig.values["roller"]
    wheel = shapely.Point(fig.view.p(roller.center)).buffer(fig.view.length(roller.r), 256).exterior
    assert box(text).distance(profile) > 0.2 and box(text).distance(wheel) > 0.2
    assert box(text).distance(shapely.Point(arc.at(1.0))) < 3.0 or box(text).distance(shapely.Point(arc.at(0.0))) < 3.0
    assert math.isclose(mark.value, 36.8698976, rel_tol=1e-6)
