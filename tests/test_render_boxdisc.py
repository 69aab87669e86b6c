"""A point's marker (a filled disc, handed to the placer as GEOS's 32-gon) is measured as the circle it stands for,
in closed form, one pair a box instead of 32 box–side pairs (issue 11: speed): the distance and the area a box
shares with it agree with GEOS on a fine polygon of the circle (to 1e-5 mm, mm²), turned boxes too."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from shapely import affinity

from geomcon.render.boxdisc import box_disc, box_disc_area, disc_gap, discs
from geomcon.render.clearance import Boxes, Layer
from geomcon.render.shapes import disc_polygon

FINE = 2048
"""Segments a quadrant of the fine polygon the closed forms are checked against (its sides lie within
r · (1 − cos(π / 4096)) ≈ 3e-7 r of the circle)."""


def _fine(cx, cy, r):
    return shapely.buffer(shapely.points(cx, cy), r, quad_segs=FINE)


def test_discs_are_found_among_other_geometries():
    geoms = np.array([disc_polygon(3.7, -1.2, 0.55), shapely.Point(100.0, 40.0).buffer(1.3, 8),
                      shapely.box(0, 0, 1, 1), shapely.Point(0, 0).buffer(1.0, 4),      # a square, an 16-gon
                      shapely.Point(0, 0).buffer(1.0, 8).exterior,                         # a ring: a line
                      affinity.scale(shapely.Point(0, 0).buffer(1.0, 8), 2.0, 1.0),        # an ellipse
                      shapely.Point(5, 5), shapely.LineString([(0, 0), (1, 1)])], dtype=object)
    i, cx, cy, r = discs(geoms)
    assert i.tolist() == [0, 1]
    assert cx.tolist() == [3.7, 100.0] and cy.tolist() == [-1.2, 40.0]
    assert r == pytest.approx([0.55, 1.3], abs=1e-12)


def test_box_and_disc_agree_with_geos_on_a_fine_circle():
    rng = np.random.default_rng(5)
    n = 4000
    x0, y0 = rng.uniform(-3, 3, n), rng.uniform(-3, 3, n)
    x1, y1 = x0 + rng.uniform(0.2, 4, n), y0 + rng.uniform(0.2, 3, n)
    cx, cy, r = rng.uniform(-2, 2, n), rng.uniform(-2, 2, n), rng.uniform(0.1, 2, n)
    d, area = box_disc(x0, y0, x1, y1, cx, cy, r)
    boxes, circles = shapely.box(x0, y0, x1, y1), _fine(cx, cy, r)
    assert np.max(np.abs(d - shapely.distance(boxes, circles))) < 1e-5
    want = shapely.area(shapely.intersection(boxes, circles))
    assert np.max(np.abs(area - want)) < 1e-5
    assert 500 < np.count_nonzero(area) < n and np.count_nonzero(d == 0.0) == np.count_nonzero(area)


def test_the_area_shared_in_special_places():
    one = lambda *v: float(box_disc_area(*[np.array([t]) for t in v])[0])
    assert one(-5, -5, 5, 5, 0, 0, 2) == pytest.approx(4 * math.pi, abs=1e-12)        # the whole disc
    assert one(0, -5, 5, 5, 0, 0, 2) == pytest.approx(2 * math.pi, abs=1e-12)         # half of it
    assert one(0, 0, 5, 5, 1, 1, 1) == pytest.approx(math.pi, abs=1e-12)              # inside, touching 2 sides
    assert one(-0.5, -0.5, 0.5, 0.5, 0, 0, 2) == pytest.approx(1.0, abs=1e-12)        # the box inside the disc
    assert one(2, -1, 3, 1, 0, 0, 2) == 0.0                                           # tangent: no area
    assert one(0, 0, 5, 5, 0, 0, 2) == pytest.approx(math.pi, abs=1e-12)              # a quadrant
    assert one(-5, 1, 5, 5, 0, 0, 2) == pytest.approx(4 * math.pi / 3 - math.sqrt(3), abs=1e-12)   # a segment


@pytest.mark.parametrize("angle", [0.0, 30.0, -45.0, 90.0])
def test_a_layer_measures_a_marker_as_its_circle_one_pair_a_box(angle):
    """Clearance and crossing of boxes, turned or not, about a marker: as GEOS measures them against a fine
    circle, not against the 32-gon (whose sides lie 0.5 % of the radius inside the circle)."""
    cx, cy, r = 10.0, 10.0, 1.2
    layer = Layer([disc_polygon(cx, cy, r)], ["pin"], [0.0], index=True, weight=[2.0])
    rng = np.random.default_rng(7)
    px, py = rng.uniform(6, 14, 400), rng.uniform(7, 13, 400)
    boxes = Boxes.turned_by(px, py, 3.0, 1.6, angle, np.full(400, -1, dtype=np.intp))
    assert len(layer.pairs(boxes)[0]) <= 400                # one pair a box near it, never one a side
    m = layer.measure(boxes)
    fine = _fine(cx, cy, r)
    for k in range(400):
        box = boxes.geom(k)
        d = float(shapely.distance(box, fine))
        if d > 0.0:
            want = min(1.6, d)
        else:
            want = -min(2.0, 0.6 * math.sqrt(float(shapely.area(shapely.intersection(box, fine)))))
        assert m.known[k] == pytest.approx(want, abs=1e-5)
        assert m.hi[k] == m.lo[k] == m.known[k]             # nothing left to GEOS
        if abs(d) > 1e-5 and abs(d - 0.2) > 1e-5:       # met, or within the halo's 0.2 mm: crossed
            assert m.cross[k] == (2.0 if d <= 0.2 else 0.0)
        assert m.known[k] == pytest.approx(min(1.6, layer.gaps(box, np.array([0]))[0]), abs=1e-12)
        assert m.cross[k] == layer.crossing(box, None)


def test_a_box_between_two_corners_of_the_polygon_measures_from_the_circle():
    """Midway between two corners the 32-gon's side lies r(1 − cos(π/32)) ≈ 0.0048 r inside the circle: a box
    0.004 mm off a 1 mm marker there is 0.004 mm from it, not 0.0088."""
    a = math.pi / 32                                       # between the corners at 0 and −2π/32
    r, gap = 1.0, 0.004
    x, y = (r + gap) * math.cos(a), -(r + gap) * math.sin(a)
    layer = Layer([disc_polygon(0.0, 0.0, r)], ["pin"], [0.0])
    # a tiny box just outside, its nearest corner at (x, y) facing the centre
    boxes = Boxes.aligned(np.array([x + 0.05]), np.array([y - 0.05]), 0.1, 0.1, np.array([-1]))
    d = float(layer.measure(boxes).known[0])
    assert d == pytest.approx(gap, abs=1e-9)
    assert disc_gap(boxes.geom(0), 0.0, 0.0, r)[0] == pytest.approx(gap, abs=1e-9)
