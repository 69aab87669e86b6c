"""Obstacles are made from the same coordinates as before they were made from arrays: an arc's points are
``ArcP.at`` of its fractions, a stroke's line string has the stroke's points."""
from __future__ import annotations

import math
import random

import shapely

from geomcon.render.shapes import ArcP, Disc, Pen, Poly, _arc_points, obstacle


def test_arc_points_are_the_arcs_own_points():
    rng = random.Random(1)
    for _ in range(2000):
        a = ArcP((rng.uniform(-100, 100), rng.uniform(-100, 100)), rng.uniform(0.1, 80), rng.uniform(-7, 7),
                 rng.uniform(-7, 7), Pen("#000", 0.3))
        n = max(2, int(abs(a.sweep) * a.r / 1.0) + 2)
        assert _arc_points(a) == [a.at(i / (n - 1)) for i in range(n)]


def test_obstacles_keep_the_strokes_coordinates():
    rng = random.Random(2)
    pen = Pen("#000", 0.35)
    for _ in range(500):
        pts = tuple((rng.uniform(0, 200), rng.uniform(0, 200)) for _ in range(rng.randint(1, 12)))
        closed = rng.random() < 0.3
        line = obstacle(Poly(pts, pen, closed))
        want = list(pts) + ([pts[0]] if closed else [])
        ref = shapely.LineString(want) if len(want) > 1 else shapely.Point(want[0])
        assert line.geom_type == ref.geom_type
        assert shapely.get_coordinates(line).tolist() == shapely.get_coordinates(ref).tolist()
    ring = obstacle(Disc((3.0, 4.0), 2.5, pen))
    assert shapely.get_coordinates(ring).tolist() == [list(p) for p in _arc_points(
        ArcP((3.0, 4.0), 2.5, 0.0, 2 * math.pi, Pen("", 0)))]
