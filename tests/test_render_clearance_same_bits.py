"""The placer's faster forms give the numbers of the forms they replaced, bit for bit (issue 11: speed with the
gallery's bytes unchanged): the box–segment closed forms without ufuncs' ``where=`` nor ``np.clip``, a text box
against a placed text box in closed form instead of a GEOS intersection, the halo's pairs found on the sorted met
pairs instead of ``np.isin``, and the leaders across a bar tested by the prepared bars."""
from __future__ import annotations

import numpy as np
import pytest
import shapely

from geomcon.render import boxgeom
from geomcon.render.clearance import CROSS, Boxes, Placed, _near, covering, rect_covering
from geomcon.render.placement import Placer, Request, nudged
from geomcon.render.candidates import candidates


def _box_segment_before(x0, y0, x1, y1, ax, ay, bx, by):
    """:func:`.boxgeom._box_segment` as it was (masked ufuncs)."""
    dx, dy = bx - ax, by - ay
    gx = np.maximum(np.maximum(x0 - ax, ax - x1), 0.0)
    gy = np.maximum(np.maximum(y0 - ay, ay - y1), 0.0)
    near = gx * gx
    near += gy * gy
    gx = np.maximum(np.maximum(x0 - bx, bx - x1), 0.0)
    gy = np.maximum(np.maximum(y0 - by, by - y1), 0.0)
    gx *= gx
    gy *= gy
    gx += gy
    np.minimum(near, gx, out=near)
    over = (np.minimum(ax, bx) <= x1) & (x0 <= np.maximum(ax, bx)) & (np.minimum(ay, by) <= y1) & (y0 <= np.maximum(ay, by))
    side = dx * ((y0 + y1) * 0.5 - ay) - dy * ((x0 + x1) * 0.5 - ax)
    left = side >= 0.0
    ux = np.where((dy > 0.0) == left, x1, x0) - ax
    uy = np.where((dx > 0.0) == left, y0, y1) - ay
    cross = dx * uy - dy * ux
    np.negative(cross, out=cross, where=~left)
    hit = over & (cross <= 0.0)
    length2 = dx * dx + dy * dy
    t = ux * dx + uy * dy
    foot = (t > 0.0) & (t < length2)
    np.square(cross, out=cross)
    np.divide(cross, length2, out=cross, where=foot)
    np.minimum(near, cross, out=near, where=foot)
    np.sqrt(near, out=near)
    near[hit] = 0.0
    return near, hit


def _inside_length_before(x0, y0, x1, y1, ax, ay, bx, by):
    """:func:`.boxgeom.inside_length` as it was (``np.clip``)."""
    dx, dy = bx - ax, by - ay
    lo, hi = np.zeros(len(dx)), np.ones(len(dx))
    for a, d, a0, a1 in ((ax, dx, x0, x1), (ay, dy, y0, y1)):
        still = d == 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            ta, tb = (a0 - a) / d, (a1 - a) / d
        out = still & ((a < a0) | (a > a1))
        np.maximum(lo, np.where(still, 0.0, np.minimum(ta, tb)), out=lo)
        np.minimum(hi, np.where(still, np.where(out, -1.0, 1.0), np.maximum(ta, tb)), out=hi)
    ends = []
    for t, px, py in ((lo, ax, ay), (hi, bx, by)):
        inner = (t > 0.0) & (t < 1.0)
        ends.append((np.where(inner, np.clip(ax + t * dx, x0, x1), px), np.where(inner, np.clip(ay + t * dy, y0, y1), py)))
    (px, py), (qx, qy) = ends
    return np.where(hi > lo, np.sqrt((qx - px) ** 2 + (qy - py) ** 2), 0.0)


def _pairs(rng: np.random.Generator, n: int) -> tuple[np.ndarray, ...]:
    """Boxes and segments: random, on a coarse grid (ends on a box's sides and corners, axis-parallel and
    zero-length segments), and points."""
    x0, y0 = rng.uniform(-5, 5, n), rng.uniform(-5, 5, n)
    x1, y1 = x0 + rng.uniform(0.5, 6, n), y0 + rng.uniform(0.5, 3, n)
    ends = rng.uniform(-10, 10, (4, n))
    grid = rng.integers(-8, 9, (4, n)) * 0.5
    ends = np.where(rng.random((4, n)) < 0.4, grid, ends)
    ax, ay, bx, by = ends
    point = rng.random(n) < 0.1
    bx, by = np.where(point, ax, bx), np.where(point, ay, by)
    flat = rng.random(n) < 0.15
    by = np.where(flat, ay, by)
    return x0, y0, x1, y1, ax, ay, bx, by


@pytest.mark.parametrize("seed", range(4))
def test_box_segment_and_inside_length_are_the_former_numbers(seed):
    args = _pairs(np.random.default_rng(seed), 6000)
    d, hit = boxgeom.box_segment(*args)
    d0, hit0 = _box_segment_before(*args)
    assert hit.tolist() == hit0.tolist() and d.tobytes() == d0.tobytes()
    assert boxgeom.inside_length(*args).tobytes() == _inside_length_before(*args).tobytes()


@pytest.mark.parametrize("seed", range(4))
def test_a_box_on_a_placed_text_box_covers_what_geos_says(seed):
    rng = np.random.default_rng(seed)
    for _ in range(400):
        a = rng.integers(0, 20, 4) * 0.25 + rng.choice([0.0, 0.1, 1 / 3], 4)
        b = rng.integers(0, 20, 4) * 0.25 + rng.choice([0.0, 0.1, 1 / 3], 4)
        a = (min(a[0], a[2]), min(a[1], a[3]), max(a[0], a[2]) + 0.5, max(a[1], a[3]) + 0.5)
        b = (min(b[0], b[2]), min(b[1], b[3]), max(b[0], b[2]) + 0.5, max(b[1], b[3]) + 0.5)
        box, other = shapely.box(*a), shapely.box(*b)
        assert rect_covering(a, b) == covering(box, np.array([other], dtype=object))[0], (a, b)


def test_placed_exact_takes_text_boxes_in_closed_form_and_the_rest_by_geos():
    placed = Placed()
    for g in (shapely.box(0, 0, 4, 2), shapely.LineString([(1, -1), (3, 3)]), shapely.box(3.5, 1.5, 6, 4)):
        placed.append(g)
    box = shapely.box(0.75, 0.25, 3.75, 1.75)
    everything = np.array(placed.geoms, dtype=object)
    assert placed.exact(box, np.array([0, 1, 2])) == float(np.min(covering(box, everything)))
    assert placed.exact(box, np.array([2])) == float(covering(box, everything[2:])[0])


def test_the_halo_leaves_out_what_a_box_meets_as_isin_did():
    rng = np.random.default_rng(7)
    ng, n = 13, 40
    met = np.unique(rng.integers(0, n * ng, 150))
    k, p = rng.integers(0, n, 300), rng.integers(0, ng, 300)
    weight = rng.uniform(0, 3, ng)
    cross = np.zeros(n)
    _near(cross, k, p, weight, met, ng)
    keep = ~np.isin(k * ng + p, met)
    want = np.zeros(n)
    np.maximum.at(want, k[keep], weight[p[keep]])
    assert cross.tolist() == (CROSS * want).tolist()


def test_leaders_across_bars_are_those_geos_finds_unprepared():
    t = np.linspace(0.0, 2 * np.pi, 400)
    ring = shapely.LineString(np.stack([30 + 12 * np.cos(t), 30 + 9 * np.sin(t)], axis=1))   # a cam's profile
    link = shapely.LineString([(5, 5), (55, 40)])
    obstacles = [(ring, "profile", 0.0, 2.0), (link, "link", 0.0, 2.0), (shapely.box(20, 20, 24, 23), "block", 0.0, 2.0)]
    placer = Placer(obstacles, (0.0, 0.0, 60.0, 60.0))
    rng = np.random.default_rng(3)
    reqs = [Request((float(x), float(y)), 4.0, 2.0, 0.5, float(a), lead=1.0)
            for x, y, a in zip(rng.uniform(10, 50, 30), rng.uniform(10, 50, 30), rng.uniform(-3, 3, 30))]
    c = candidates(reqs, [-1] * len(reqs), (0.0, 0.0, 60.0, 60.0))
    barred, hard = placer._barred(c)
    assert hard.tolist() == barred.tolist()                 # no outlines given: every bar crossed is hard
    lines = shapely.linestrings(nudged(c.leader).reshape(-1, 2, 2))
    bars = np.array([o[0] for o in obstacles], dtype=object)
    meets = shapely.intersects(lines[:, None], bars[None, :])               # unprepared, pair by pair
    starts = shapely.contains_xy(bars[None, :], c.leader[:, :1], c.leader[:, 1:2])
    want = (meets & ~starts).any(axis=1)
    assert len(c.led) and want.any() and barred.tolist() == want.tolist()
    outlined = Placer(obstacles, (0.0, 0.0, 60.0, 60.0), [True, True, False])      # the block is no outline
    barred2, hard2 = outlined._barred(c)
    mine = shapely.contains_xy(bars[2], c.leader[:, 0], c.leader[:, 1])
    assert barred2.tolist() == barred.tolist() and hard2.tolist() == (meets[:, 2] & ~mine).tolist()


def test_layer_exact_takes_drawn_rectangles_in_closed_form_and_the_rest_by_geos():
    from geomcon.render.clearance import Layer
    from geomcon.render.shapes import disc_polygon
    geoms = [shapely.box(0, 0, 4, 2), disc_polygon(2.0, 1.0, 0.55), shapely.box(3.5, 1.5, 6, 4),
             shapely.Polygon([(1, 0), (3, 0), (2, 3)])]
    layer = Layer(geoms, ["a", "b", "c", "d"], [0.0, 0.5, 0.25, 0.0])
    box = shapely.box(0.75, 0.25, 3.75, 1.75)
    allow = np.array([0.0, 0.5, 0.25, 0.0])
    for parents in ([0, 1, 2, 3], [2], [0, 2], [1, 3]):
        p = np.array(parents)
        want = float(np.min(covering(box, np.array(geoms, dtype=object)[p]) + allow[p]))
        assert layer.exact(box, p) == want
    assert layer._rect(0) == (0.0, 0.0, 4.0, 2.0) and layer._rect(1) is None


def test_placed_measures_many_boxes_from_the_columns_near_them_as_one_box_from_all():
    from shapely import affinity
    rng = np.random.default_rng(11)
    placed = Placed()
    for x, y in rng.uniform(0, 100, (40, 2)):
        placed.append(shapely.box(x, y, x + 4, y + 2))
        placed.append(shapely.LineString([(x, y), (x + rng.uniform(-6, 6), y + rng.uniform(-6, 6))]))
    placed.append(affinity.rotate(shapely.box(20, 20, 26, 22), 30))        # a turned text box
    cx, cy = rng.uniform(15, 35, 120), rng.uniform(15, 35, 120)
    boxes = Boxes.aligned(cx, cy, 4.0, 2.0, np.zeros(120, dtype=np.intp))
    whole = placed.measure(boxes)                       # 120 boxes x 121 columns: only those near them
    rows, parents = [], []
    for i in range(120):
        one = placed.measure(boxes.take(np.array([i])))    # one box: every column
        for a, b in ((whole.known, one.known), (whole.hi, one.hi), (whole.lo, one.lo)):
            assert a[i] == b[0]
        assert whole.touching[i] == one.touching[0]
        rows += [i] * len(one.pending[0])
        parents += one.pending[1].tolist()
    assert whole.pending[0].tolist() == rows and whole.pending[1].tolist() == parents and len(rows)
