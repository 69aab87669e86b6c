"""Label placement: the vectorised scoring (closed forms in numpy, what a box covers of an area by shapely)
chooses what scoring every candidate one by one by shapely chose (the reference below is the straightforward
placer it replaced), on random crowded figures with long polylines, filled areas, points, own markers,
allowances, rotated texts and explicit candidates; the closed forms agree with GEOS to rounding."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest
import shapely
from shapely import affinity

from geomcon.render.boxdisc import disc_gap, discs
from geomcon.render.symbols import MARK_DISTANCES
from geomcon.render.clearance import CROSS, NEAR, NEAR_WEIGHT
from geomcon.render.placement import AMBIGUOUS, DISTANCES, ENOUGH, LABEL_DISTANCES, FAR_PENALTY, Placer, Request, directions, half_extent


class ReferencePlacer:
    """Every candidate scored by its own shapely calls, in order (the placer before vectorisation); a marker's
    disc (GEOS's 32-gon) measured as the circle it stands for, by its centre's distance and the area shared
    (:func:`.boxdisc.disc_gap`, checked against a fine polygon by GEOS below)."""

    def __init__(self, obstacles, frame):
        self._geoms = np.array([o[0] for o in obstacles], dtype=object)
        self._owners = np.array([o[1] for o in obstacles], dtype=object)
        self._allow = np.array([o[2] for o in obstacles], dtype=float)
        self._weight = np.array([o[3] if len(o) > 3 else 0.0 for o in obstacles], dtype=float)
        self._own = np.array([o[4] if len(o) > 4 else w for o, w in zip(obstacles, self._weight)], dtype=float)
        self._halo = np.array([o[5] if len(o) > 5 else w >= NEAR_WEIGHT for o, w in zip(obstacles, self._weight)])
        self._tree = shapely.STRtree(self._geoms) if len(self._geoms) else None
        i, cx, cy, r = discs(self._geoms)
        self._discs = dict(zip(i.tolist(), zip(cx.tolist(), cy.tolist(), r.tolist())))
        self._placed = []
        self._frame = frame

    def _apart(self, box, i):
        """Distance from ``box`` to obstacle ``i`` (a disc's: to its circle, negative inside)."""
        return disc_gap(box, *self._discs[i])[0] if i in self._discs else box.distance(self._geoms[i])

    def _meets(self, box, i):
        return self._apart(box, i) <= 0.0 if i in self._discs else box.intersects(self._geoms[i])

    def _disc_gaps(self, box, idx):
        out = self._gaps(box, self._geoms[idx])
        for j, i in enumerate(idx.tolist()):
            if i in self._discs:
                apart, area = disc_gap(box, *self._discs[i])
                out[j] = apart if apart > 0.0 else -min(2.0, 0.3 * (2.0 * math.sqrt(area)))
        return out

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
                best = min(best, float(np.min(self._disc_gaps(box, idx) + self._allow[idx])))
        if self._placed:
            best = min(best, float(np.min(self._gaps(box, np.array(self._placed, dtype=object)))))
        crossed = [m if o == owner else w for i, (o, w, m) in enumerate(zip(self._owners, self._weight, self._own))
                   if (m if o == owner else w) > 0.0 and self._meets(box, i)]
        halo = [w for i, (o, w, h) in enumerate(zip(self._owners, self._weight, self._halo))
                if h and o != owner and not self._meets(box, i) and self._apart(box, i) <= NEAR]
        return best - CROSS * (sum(crossed) + max(halo, default=0.0))  # every line it crosses, its own step's
        # too, and the heaviest link, pin or ground of another step it comes within NEAR of (its halo into it)

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
        w = rng.choice([0.0, 1.0, 1.0, 2.0])
        obstacles.append((g, owner, allow, w, rng.choice([w, w, 0.0]), w >= NEAR_WEIGHT and rng.random() < 0.8))
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
        assert got[0] == want[0]               # the same centre
        assert got[1] == pytest.approx(want[1], rel=0.0, abs=1e-12)     # and score, to rounding
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
    """Each box's clearance from a layer, as measured many at once: the closed-form part and the bounds hold
    the clearance shapely gives (to rounding), and they equal it where nothing is left to shapely."""
    from geomcon.render.clearance import Boxes, Layer, Placed
    from geomcon.render.placement import _boxes

    rng = random.Random(100 + seed)
    obstacles, owners = random_figure(rng)
    ref = ReferencePlacer(obstacles, (0.0, 0.0, 60.0, 60.0))
    layer = Layer([o[0] for o in obstacles], [o[1] for o in obstacles], [o[2] for o in obstacles],
                  index=True, weight=[o[3] for o in obstacles], own=[o[4] for o in obstacles],
                  halo=[o[5] for o in obstacles])
    placed = Placed()
    for _ in range(10):
        req, owner = random_request(rng), rng.choice(owners)
        cx, cy = np.array([rng.uniform(0, 60) for _ in range(12)]), np.array([rng.uniform(0, 60) for _ in range(12)])
        boxes = _boxes(req, cx, cy, layer.code(owner))
        fixed, near = layer.measure(boxes), placed.measure(boxes)
        for k in range(12):
            box = req.box(cx[k], cy[k])
            want = ref.clearance(box, owner)
            cross = fixed.cross[k]                    # every line crossed, its own step's too
            assert cross == layer.crossing(box, owner)
            hi = min(fixed.hi[k], near.hi[k]) - cross
            lo = min(fixed.lo[k], near.lo[k]) - cross
            exact = min(fixed.known[k], near.known[k], layer.exact(box, fixed.pending_of(k)),
                        placed.exact(box, near.pending_of(k))) - cross
            assert lo - 1e-12 <= want <= hi + 1e-12
            assert exact == pytest.approx(want, rel=0.0, abs=1e-12)
            if not len(fixed.pending_of(k)) and not len(near.pending_of(k)):
                assert hi == lo == pytest.approx(want, rel=0.0, abs=1e-12)
        placed.append(req.box(cx[0], cy[0]))
        ref.commit(req.box(cx[0], cy[0]))


def test_placed_text_boxes_are_told_from_other_polygons():
    from geomcon.render.clearance import _rect_of

    bowtie = shapely.Polygon([(0, 0), (2, 1), (2, 0), (0, 1)])
    turned = affinity.rotate(shapely.box(0, 0, 2, 1), 30.0)
    geoms = [shapely.box(0, 0, 2, 1), shapely.box(0, 0, 2, 1, ccw=False), bowtie, turned, shapely.Point(1, 1),
             shapely.LineString([(0, 0), (5, 5)])]
    assert [_rect_of(g) for g in geoms] == [(0.0, 0.0, 2.0, 1.0), (0.0, 0.0, 2.0, 1.0), None, None, None, None]


def test_geometries_are_flattened_into_their_own_segments():
    """A line string into its segments, an area into its rings' (never joining two rings), a point into one
    of zero length."""
    from geomcon.render.clearance import Layer

    xy = np.c_[np.arange(50.0), np.sin(np.arange(50.0))]
    holed = shapely.Polygon([(0, 0), (10, 0), (10, 10), (0, 10)], [[(2, 2), (4, 2), (4, 4), (2, 4)]])
    layer = Layer([shapely.LineString(xy), holed, shapely.Point(7, 8)])
    ax, ay, bx, by, parent = layer.arrays()[:5]
    line = parent == 0
    assert np.array_equal(np.c_[ax[line], ay[line]], xy[:-1]) and np.array_equal(np.c_[bx[line], by[line]], xy[1:])
    assert (parent == 1).sum() == 8                      # four sides of each ring
    rings = {(float(a), float(b), float(c), float(d)) for a, b, c, d in zip(ax, ay, bx, by)}
    assert (0.0, 10.0, 0.0, 0.0) in rings and (2.0, 4.0, 2.0, 2.0) in rings and (0.0, 0.0, 2.0, 2.0) not in rings
    assert (7.0, 8.0, 7.0, 8.0) in rings


def test_box_and_segment_closed_forms_agree_with_geos():
    """Distance, meeting and the length inside, over random boxes and segments: points, axis-parallel
    segments, segments along an edge and through a corner."""
    from geomcon.render.boxgeom import box_segment, inside_length

    rng = np.random.default_rng(5)
    n = 20000
    c, w = rng.uniform(0, 10, (n, 2)), rng.uniform(0.5, 4, (n, 2))
    x0, y0, x1, y1 = c[:, 0] - w[:, 0], c[:, 1] - w[:, 1], c[:, 0] + w[:, 0], c[:, 1] + w[:, 1]
    a = rng.uniform(-3, 13, (n, 2))
    b = a + rng.normal(0, 3, (n, 2))
    b[:500] = a[:500]
    b[500:1500, 0] = a[500:1500, 0]
    b[1500:2500, 1] = a[1500:2500, 1]
    a[2500:3000, 1] = b[2500:3000, 1] = y0[2500:3000]
    a[3000:3500] = np.c_[x1[3000:3500], y1[3000:3500]]
    segs = shapely.linestrings(np.stack([a, b], axis=1))
    segs[:500] = shapely.points(a[:500])
    boxes = shapely.box(x0, y0, x1, y1)
    d, hit = box_segment(x0, y0, x1, y1, a[:, 0], a[:, 1], b[:, 0], b[:, 1])
    want = shapely.distance(boxes, segs)
    assert np.array_equal(hit, want == 0.0) and np.array_equal(d == 0.0, want == 0.0)
    assert np.max(np.abs(d - want)) < 1e-13
    inside = inside_length(x0, y0, x1, y1, a[:, 0], a[:, 1], b[:, 0], b[:, 1])
    assert np.max(np.abs(inside - shapely.length(shapely.intersection(boxes, segs)))) < 1e-13


def test_a_filled_disc_is_the_polygon_geos_buffers_a_point_into():
    """A marker's obstacle, written out, has GEOS's coordinates in GEOS's order (so the placer measures what
    it measured when the polygon came from ``buffer``)."""
    from geomcon.render.shapes import disc_polygon

    rng = np.random.default_rng(11)
    for x, y, r in zip(rng.uniform(-800, 800, 3000), rng.uniform(-800, 800, 3000),
                       np.r_[rng.uniform(1e-3, 100, 1000), rng.uniform(0.05, 3, 1999), 0.0]):
        mine, geos = disc_polygon(float(x), float(y), float(r)), shapely.Point(x, y).buffer(r, 8)
        assert shapely.get_coordinates(mine).tolist() == shapely.get_coordinates(geos).tolist()
        assert mine.equals_exact(geos, 0.0) or (mine.is_empty and geos.is_empty)


@pytest.mark.parametrize("seed", range(10))
def test_texts_laid_out_together_are_laid_out_as_one_at_a_time(seed):
    """The candidates of many texts at once (one set of arrays) are, bit for bit, those of each text alone and
    the centres and penalties of the straightforward loop; a placer that prepares every text in one pass
    chooses what one preparing each text as it is placed chooses."""
    from geomcon.render.candidates import candidates

    rng = random.Random(300 + seed)
    obstacles, owners = random_figure(rng)
    frame = (0.0, 0.0, 60.0, 60.0)
    jobs = [(random_request(rng), rng.choice(owners)) for _ in range(30)]
    together = candidates([r for r, _ in jobs], list(range(len(jobs))), frame)
    for i, (req, _) in enumerate(jobs):
        alone = candidates([req], [i], frame)
        a, b = together.starts[i], together.starts[i + 1]
        for f in ("cx", "cy", "cost", "framed", "rivalled"):
            assert np.array_equal(getattr(together, f)[a:b], getattr(alone, f))
        for f in ("x0", "y0", "x1", "y1", "hw", "hh", "cos", "sin", "owner"):
            assert np.array_equal(getattr(together.boxes, f)[a:b], getattr(alone.boxes, f))
        if not req.candidates:
            want = [((req.anchor[0] + math.cos(t) * (req.gap + extra + half_extent(math.cos(t), math.sin(t), req.width, req.height)),
                      req.anchor[1] + math.sin(t) * (req.gap + extra + half_extent(math.cos(t), math.sin(t), req.width, req.height))),
                     FAR_PENALTY * j + req.spread * rank)
                    for j, extra in enumerate(req.distances) for rank, t in enumerate(directions(req.prefer))]
            assert [((x, y), c) for x, y, c in zip(alone.cx.tolist(), alone.cy.tolist(), alone.cost.tolist())] == want
    batched, single = Placer(obstacles, frame), Placer(obstacles, frame)
    batched.prepare(jobs)
    for req, owner in jobs:
        got, want = batched.best(req, owner), single.best(req, owner)
        assert got == want
        batched.commit(req.box(*got[0]))
        single.commit(req.box(*want[0]))


def test_turned_text_boxes_are_measured_by_their_sides_and_the_rest_by_segments():
    """A turned box placed is a convex polygon, measured densely (its sides, and a candidate's centre inside it);
    a bow-tie or a polygon with a hole is not convex and leaves everything to the segments of a layer."""
    from geomcon.render.clearance import Boxes, Placed, _convex_of

    bowtie = shapely.Polygon([(0, 0), (2, 1), (2, 0), (0, 1)])
    holed = shapely.box(0, 0, 9, 9).difference(shapely.box(3, 3, 6, 6))
    turned = affinity.rotate(shapely.box(0, 0, 8, 3), 30.0)
    assert _convex_of(turned) is not None and _convex_of(affinity.rotate(turned, 180.0)) is not None
    assert _convex_of(bowtie) is None and _convex_of(holed) is None and _convex_of(shapely.Point(1, 1)) is None
    placed = Placed()
    placed.append(turned)
    assert not placed._general
    c = turned.centroid
    boxes = Boxes.aligned(np.array([c.x, c.x + 20.0, c.x]), np.array([c.y, c.y, c.y + 1.8]), 1.0, 0.5,
                          np.zeros(3, dtype=np.intp))
    m = placed.measure(boxes)
    assert m.touching.tolist() == [True, False, True]    # inside it (no side met), clear of it, across a side
    for k in range(3):
        box = boxes.geom(k)
        want = shapely.distance(box, turned)
        assert min(m.known[k], placed.exact(box, m.pending_of(k))) == pytest.approx(
            min(want, ENOUGH) if want > 0.0 else -min(2.0, 0.6 * math.sqrt(shapely.area(box & turned))), abs=1e-12)


@pytest.mark.parametrize("seed", range(10))
def test_a_texts_bound_is_never_below_the_score_it_gets(seed):
    """:meth:`Placer.bound` (what :func:`.figure._foresee` prepares fallbacks by) is at least the score
    :meth:`Placer.best` gives the text, whatever was placed before it; with nothing placed it is that score,
    or above it only by what GEOS finds a box covers of an area (never more than 2)."""
    rng = random.Random(700 + seed)
    obstacles, owners = random_figure(rng)
    placer = Placer(obstacles, (0.0, 0.0, 60.0, 60.0))
    jobs = [(random_request(rng), rng.choice(owners)) for _ in range(20)]
    placer.prepare(jobs)
    bounds = [placer.bound(req, owner) for req, owner in jobs]
    for (req, owner), bound in zip(jobs, bounds):
        fresh = Placer(obstacles, (0.0, 0.0, 60.0, 60.0)).best(req, owner)[1]
        assert fresh <= bound <= fresh + 2.0 + 1e-9
    for (req, owner), bound in zip(jobs, bounds):
        centre, score = placer.best(req, owner)
        assert score <= bound
        placer.commit(req.box(*centre))


def test_placed_measure_reads_turned_boxes_as_the_convex_test_does():
    """``Placed.measure``'s centres inside a turned box (:func:`.clearance._inside`, the sides kept as columns) are
    :func:`.clearance._within`'s, bit for bit, for random turned boxes and points on and near their edges."""
    from geomcon.render.clearance import _inside, _within

    rng = random.Random(11)
    for _ in range(300):
        box = affinity.rotate(shapely.box(0, 0, rng.uniform(1, 9), rng.uniform(1, 4)), rng.uniform(-90, 90))
        xy = shapely.get_coordinates(box)[:-1]
        e = np.roll(xy, -1, axis=0) - xy
        t = np.array([rng.random() for _ in range(40)])
        i = np.array([rng.randrange(4) for _ in range(40)])
        px = np.r_[xy[i, 0] + t * e[i, 0], np.array([rng.uniform(-2, 11) for _ in range(40)])]
        py = np.r_[xy[i, 1] + t * e[i, 1], np.array([rng.uniform(-2, 11) for _ in range(40)])]
        got = _inside(xy[:, :1], xy[:, 1:], e[:, :1], e[:, 1:], px, py)
        assert got.tolist() == _within(xy, px, py).tolist()


def test_a_text_a_hair_from_a_link_or_a_ground_counts_as_crossing_it():
    """200-05 printed α′max a hair under O's ground: the box touched no stroke, so it lost nothing, though its
    white halo cut into the hatch. A box within NEAR of a link, pin or ground of another step loses the heaviest
    one's crossing weight, once (a ground's hatch is many strokes), as if it crossed it; not so near a stroke of
    its own step, an area kept out of (halo False) or a thin line."""
    hatch = [shapely.LineString([(x, 10.0), (x + 1.0, 11.0)]) for x in (0.0, 1.0, 2.0, 3.0)]
    obstacles = [(h, "ground", 0.0, 2.0) for h in hatch] + [(shapely.LineString([(0, 20), (9, 20)]), "thin", 0.5, 1.0),
                                                           (shapely.box(0, 30, 9, 32), "keep", 0.0, 2.0, 2.0, False)]
    p = Placer(obstacles, (-20.0, -20.0, 40.0, 60.0))
    under = shapely.box(0.5, 11.0 + NEAR / 2, 3.5, 13.0)          # under the hatch, not touching it
    far = shapely.box(0.5, 11.0 + 2 * NEAR, 3.5, 13.0)
    assert p.clearance(under, "x") == pytest.approx(NEAR / 2 - CROSS * 2.0, abs=1e-12)
    assert p.clearance(far, "x") == pytest.approx(2 * NEAR, abs=1e-12)
    assert p.clearance(under, "ground") == ENOUGH                 # its own ground
    assert p.clearance(shapely.box(0, 20 + NEAR / 2, 3, 22), "x") == pytest.approx(NEAR / 2 + 0.5, abs=1e-12)
    assert p.clearance(shapely.box(0, 32 + NEAR / 2, 3, 34), "x") == pytest.approx(NEAR / 2, abs=1e-12)
    r = Request((2.0, 12.2), 3.0, 1.8, 0.1, math.pi / 2, candidates=((2.0, 11.0 + NEAR / 2 + 0.9), (2.0, 20.0)))
    assert p.best(r, "x")[0] == (2.0, 20.0)       # across a thin construction line rather than in the hatch's halo
