"""Label placement: the vectorised, bounded scoring chooses exactly what scoring every candidate one by one
chose (the reference below is the straightforward placer it replaced), on random crowded figures with long
polylines, filled areas, points, own markers, allowances, rotated texts and explicit candidates."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest
import shapely
from shapely import affinity

from geomcon.render.symbols import MARK_DISTANCES
from geomcon.render.placement import AMBIGUOUS, DISTANCES, ENOUGH, LABEL_DISTANCES, FAR_PENALTY, Placer, Request, directions, half_extent


class ReferencePlacer:
    """Every candidate scored by its own shapely calls, in order (the placer before vectorisation)."""

    def __init__(self, obstacles, frame):
        self._geoms = np.array([g for g, _, _ in obstacles], dtype=object)
        self._owners = np.array([o for _, o, _ in obstacles], dtype=object)
        self._allow = np.array([a for _, _, a in obstacles], dtype=float)
        self._tree = shapely.STRtree(self._geoms) if len(self._geoms) else None
        self._placed = []
        self._frame = frame

    @staticmethod
    def _gaps(box, geoms):
        d = shapely.distance(box, geoms)
        hit = d == 0.0
        if hit.any():
            inter = shapely.intersection(box, geoms[hit])
            area = shapely.area(inter)
            covered = np.where(area > 0.0, 2.0 * np.sqrt(area), shapely.length(inter))
            d[hit] = -np.minimum(2.0, 0.3 * covered)
        return d

    def clearance(self, box, owner):
        best = ENOUGH
        x0, y0, x1, y1 = box.bounds
        near = shapely.box(x0 - ENOUGH, y0 - ENOUGH, x1 + ENOUGH, y1 + ENOUGH)
        if self._tree is not None:
            idx = self._tree.query(near)
            idx = np.sort(idx[self._owners[idx] != owner])
            if len(idx):
                best = min(best, float(np.min(self._gaps(box, self._geoms[idx]) + self._allow[idx])))
        if self._placed:
            best = min(best, float(np.min(self._gaps(box, np.array(self._placed, dtype=object)))))
        return best

    def best(self, req, owner):
        if req.candidates:
            cands = [(c, req.spread * i) for i, c in enumerate(req.candidates)]
        else:
            cands = []
            for j, extra in enumerate(req.distances):
                for rank, a in enumerate(directions(req.prefer)):
                    ux, uy = math.cos(a), math.sin(a)
                    reach = req.gap + extra + half_extent(ux, uy, req.width, req.height)
                    cands.append(((req.anchor[0] + ux * reach, req.anchor[1] + uy * reach),
                                  FAR_PENALTY * j + req.spread * rank))
        best, best_score = req.anchor, -math.inf
        f = self._frame
        for centre, penalty in cands:
            box = req.box(*centre)
            x0, y0, x1, y1 = box.bounds
            outside = 0.0 if f[0] <= x0 and f[1] <= y0 and x1 <= f[2] and y1 <= f[3] else 50.0
            if any(box.intersects(g) for g in self._placed):     # on a text placed before: as bad as outside
                outside = 50.0
            if req.rivals and min(box.distance(shapely.Point(r)) for r in req.rivals) < box.distance(
                    shapely.Point(req.anchor)):
                outside += AMBIGUOUS                              # nearer another point than its own
            score = self.clearance(box, owner) - penalty - outside
            if score > best_score + 1e-12:
                best, best_score = centre, score
        return best, best_score

    def commit(self, geom):
        self._placed.append(geom)


def random_figure(rng: random.Random, size: float = 60.0):
    """Obstacles as the figure makes them: strokes, long sampled circles and profiles, filled discs, text
    boxes, single points; owners shared by several shapes, construction allowances."""
    obstacles = []
    owners = [f"s{i}" for i in range(12)]
    for _ in range(rng.randint(5, 40)):
        owner = rng.choice(owners)
        allow = rng.choice([0.0, 0.0, 0.5])
        kind = rng.random()
        cx, cy = rng.uniform(0, size), rng.uniform(0, size)
        if kind < 0.3:
            g = shapely.LineString([(cx, cy), (rng.uniform(0, size), rng.uniform(0, size))])
        elif kind < 0.5:
            r, n = rng.uniform(2, 30), rng.randint(20, 700)
            start, sweep = rng.uniform(0, 6.3), rng.uniform(0.5, 6.3)
            t = start + sweep * np.arange(n) / (n - 1)
            g = shapely.LineString(np.c_[cx + r * np.cos(t), cy + r * np.sin(t)])
        elif kind < 0.6:
            g = shapely.Point(cx, cy).buffer(rng.uniform(0.3, 1.5), 8)
        elif kind < 0.75:
            w, h = rng.uniform(1, 8), rng.uniform(1.5, 3)
            g = shapely.box(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
            if rng.random() < 0.3:
                g = affinity.rotate(g, rng.uniform(-90, 90), origin="center")
        elif kind < 0.85:
            g = shapely.Point(cx, cy)
        else:
            pts = [(cx + rng.uniform(-5, 5), cy + rng.uniform(-5, 5)) for _ in range(rng.randint(3, 40))]
            g = shapely.LineString(pts)
        obstacles.append((g, owner, allow))
    return obstacles, owners


def random_request(rng: random.Random, size: float = 60.0) -> Request:
    anchor = (rng.uniform(0, size), rng.uniform(0, size))
    w, h = rng.uniform(1.5, 9), rng.uniform(1.5, 3.5)
    if rng.random() < 0.15:
        cands = tuple((anchor[0] + rng.uniform(-6, 6), anchor[1] + rng.uniform(-6, 6))
                      for _ in range(rng.randint(1, 8)))
        return Request(anchor, w, h, 0.5, 0.0, 0.02, cands, rng.choice([0.0, 0.0, 30.0]))
    return Request(anchor, w, h, rng.uniform(0.2, 1.5), rng.uniform(-math.pi, math.pi),
                   rng.choice([0.004, 0.02]), (), rng.choice([0.0, 0.0, 0.0, -45.0]),
                   rng.choice([DISTANCES, LABEL_DISTANCES, MARK_DISTANCES]),
                   tuple((anchor[0] + rng.uniform(-8, 8), anchor[1] + rng.uniform(-8, 8))
                         for _ in range(rng.choice([0, 0, 1, 3]))))


@pytest.mark.parametrize("seed", range(40))
def test_vectorised_placement_chooses_what_scoring_every_candidate_chose(seed):
    rng = random.Random(seed)
    obstacles, owners = random_figure(rng)
    frame = (0.0, 0.0, 60.0, 60.0)
    new, ref = Placer(obstacles, frame), ReferencePlacer(obstacles, frame)
    for _ in range(25):
        req, owner = random_request(rng), rng.choice(owners)
        got, want = new.best(req, owner), ref.best(req, owner)
        assert got == want                     # the same centre and the same score, to the last bit
        box = req.box(*got[0])
        assert new.clearance(box, owner) == ref.clearance(box, owner)
        leader = rng.random() < 0.3            # and a leader line from the anchor
        for placer in (new, ref):
            placer.commit(box)
            if leader:
                placer.commit(shapely.LineString([req.anchor, got[0]]))


def test_a_long_polyline_is_as_far_as_its_nearest_piece():
    t = np.linspace(0.0, 2 * math.pi, 500)
    ring = shapely.LineString(np.c_[20 * np.cos(t), 20 * np.sin(t)])
    p = Placer([(ring, "k", 0.0)], (-50.0, -50.0, 50.0, 50.0))
    ref = ReferencePlacer([(ring, "k", 0.0)], (-50.0, -50.0, 50.0, 50.0))
    for x in np.linspace(-25.0, 25.0, 41):
        box = shapely.box(x, 19.0, x + 3.0, 20.5)
        assert p.clearance(box, "A") == ref.clearance(box, "A")


@pytest.mark.parametrize("seed", range(20))
def test_bounds_enclose_the_exact_clearance(seed):
    """Every candidate's bounds (first, and refined from what it covers) hold its exact clearance, which
    is the clearance of scoring it alone."""
    from geomcon.render.clearance import Layer, Measure

    rng = random.Random(100 + seed)
    obstacles, owners = random_figure(rng)
    ref = ReferencePlacer(obstacles, (0.0, 0.0, 60.0, 60.0))
    layer = Layer([g for g, _, _ in obstacles], [o for _, o, _ in obstacles], [a for _, _, a in obstacles],
                  split=True)
    placed = Layer([])
    for _ in range(10):
        req, owner = random_request(rng), rng.choice(owners)
        cands = [req.box(rng.uniform(0, 60), rng.uniform(0, 60)) for _ in range(12)]
        boxes = np.empty(len(cands), dtype=object)
        boxes[:] = cands
        bounds = shapely.bounds(boxes)
        rows = list(range(len(cands)))
        m = Measure(boxes, bounds, [(layer, *layer.near(bounds, owner).pairs(rows)),
                                    (placed, *placed.near(bounds, None).pairs(rows))], aligned=not req.rotate)
        for k, box in enumerate(cands):
            exact = m.exact(k)
            assert exact == ref.clearance(box, owner)
            lo, hi = m.bounds(k)
            assert lo <= exact <= m.refine(k) <= hi
        placed.append(cands[0])
        ref.commit(cands[0])


def test_rectangles_are_told_from_other_polygons():
    from geomcon.render.clearance import BOX, OTHER, SEGMENTS, Layer

    bowtie = shapely.Polygon([(0, 0), (2, 1), (2, 0), (0, 1)])
    turned = affinity.rotate(shapely.box(0, 0, 2, 1), 30.0)
    layer = Layer([shapely.box(0, 0, 2, 1), shapely.box(0, 0, 2, 1, ccw=False), bowtie, turned,
                   shapely.Point(1, 1), shapely.LineString([(0, 0), (5, 5)])])
    assert [p.kind for p in layer.pieces] == [BOX, BOX, OTHER, OTHER, SEGMENTS, SEGMENTS]


def test_a_long_line_string_is_cut_into_pieces_that_share_their_ends():
    from geomcon.render.clearance import PIECE, Layer

    xy = np.c_[np.arange(50.0), np.sin(np.arange(50.0))]
    layer = Layer([shapely.LineString(xy)], split=True)
    parts = [shapely.get_coordinates(p.geom) for p in layer.pieces]
    assert all(len(p) <= PIECE + 1 for p in parts)
    assert np.array_equal(np.vstack([parts[0]] + [p[1:] for p in parts[1:]]), xy)
