"""Axis-parallel boxes against segments, many pairs at once: the distance between them and the length of the
segment inside the box, in closed form with numpy.

They agree with what shapely (GEOS) computes for ``shapely.box`` and a line string to rounding (a few units in
the last place): the label placer scores thousands of candidate boxes of a figure by them in one pass instead
of one GEOS call per box. A box is ``x0 ≤ x ≤ x1, y0 ≤ y ≤ y1`` (closed); a segment ``(ax, ay)–(bx, by)``, a
point when both ends coincide. The arguments are arrays of one length, one pair per element.

Examples
--------
>>> d, hit = box_segment(*np.array([[0.0, 0.0, 4.0, 2.0, -1.0, 1.0, 5.0, 1.0],      # across it
...                                 [0.0, 0.0, 4.0, 2.0, 6.0, 1.0, 9.0, 1.0],       # 2 mm beside it
...                                 [0.0, 0.0, 4.0, 2.0, 1.0, 1.0, 1.0, 1.0],       # a point in it
...                                 [0.0, 0.0, 4.0, 2.0, 5.0, 3.0, 5.0, 6.0],       # off its corner
...                                 [0.0, 0.0, 4.0, 2.0, 6.0, 1.0, 3.0, 4.0]]).T)   # past its corner
>>> d.tolist(), hit.tolist()
([0.0, 2.0, 0.0, 1.4142135623730951, 0.7071067811865476], [True, False, True, False, False])
>>> inside_length(*np.array([[0.0, 0.0, 4.0, 2.0, -1.0, 1.0, 5.0, 1.0]]).T).tolist()
[4.0]
"""
from __future__ import annotations

import numpy as np

CHUNK = 4096
"""Pairs measured at once: the temporaries stay in the processor's cache."""


def box_point(x0, y0, x1, y1, px, py) -> np.ndarray:
    """Distance from each box to each point (0 inside).

    >>> box_point(0.0, 0.0, 4.0, 2.0, np.array([7.0, 2.0]), np.array([6.0, 1.0])).tolist()
    [5.0, 0.0]
    """
    gx = np.maximum(np.maximum(x0 - px, px - x1), 0.0)
    gy = np.maximum(np.maximum(y0 - py, py - y1), 0.0)
    return np.sqrt(gx * gx + gy * gy)


def box_segment(x0, y0, x1, y1, ax, ay, bx, by) -> tuple[np.ndarray, np.ndarray]:
    """Distance between each box and each segment, and whether they meet (the distance is then 0).

    They meet when their bounds overlap and the box does not lie wholly on one side of the segment's line (the
    separating axes of a box and a segment). Apart, two convex sets are nearest at a vertex of one of them: an
    end of the segment (its distance to the box) or the box corner nearest the segment's line (its distance to
    the line, when its foot lies on the segment; else an end is nearer).
    """
    n = len(ax)
    d, hit = np.empty(n), np.empty(n, dtype=bool)
    for i in range(0, n, CHUNK):
        s = slice(i, i + CHUNK)
        d[s], hit[s] = _box_segment(x0[s], y0[s], x1[s], y1[s], ax[s], ay[s], bx[s], by[s])
    return d, hit


def _box_segment(x0, y0, x1, y1, ax, ay, bx, by) -> tuple[np.ndarray, np.ndarray]:
    dx, dy = bx - ax, by - ay
    gx = np.maximum(x0 - ax, ax - x1)
    np.maximum(gx, 0.0, out=gx)
    gy = np.maximum(y0 - ay, ay - y1)
    np.maximum(gy, 0.0, out=gy)
    near = gx * gx
    near += gy * gy                                         # squared, from the end a
    gx = np.maximum(x0 - bx, bx - x1)
    np.maximum(gx, 0.0, out=gx)
    gy = np.maximum(y0 - by, by - y1)
    np.maximum(gy, 0.0, out=gy)
    gx *= gx
    gy *= gy
    gx += gy
    np.minimum(near, gx, out=near)                          # and from the end b
    over = np.minimum(ax, bx) <= x1
    over &= x0 <= np.maximum(ax, bx)
    over &= np.minimum(ay, by) <= y1
    over &= y0 <= np.maximum(ay, by)
    side = dx * ((y0 + y1) * 0.5 - ay) - dy * ((x0 + x1) * 0.5 - ax)
    left = side >= 0.0                                      # the box's centre lies left of a → b
    ux = np.where((dy > 0.0) == left, x1, x0) - ax          # the corner nearest the line, from a
    uy = np.where((dx > 0.0) == left, y0, y1) - ay
    cross = dx * uy - dy * ux
    cross = np.where(left, cross, -cross)                   # > 0: the whole box lies on one side of the line
    hit = over & (cross <= 0.0)
    length2 = dx * dx + dy * dy
    t = ux * dx + uy * dy
    foot = (t > 0.0) & (t < length2)
    np.square(cross, out=cross)                 # (np.where, not a ufunc's where=: several times faster)
    cross /= np.where(foot, length2, 1.0)
    np.minimum(near, np.where(foot, cross, np.inf), out=near)
    np.sqrt(near, out=near)
    near[hit] = 0.0
    return near, hit


def inside_length(x0, y0, x1, y1, ax, ay, bx, by) -> np.ndarray:
    """The length of each segment inside its box (0 for one that misses it): the segment clipped by
    Liang–Barsky, its clipped ends put on the box (as GEOS puts the points where it crosses an edge)."""
    dx, dy = bx - ax, by - ay
    lo, hi = np.zeros(len(dx)), np.ones(len(dx))
    with np.errstate(divide="ignore", invalid="ignore"):
        for a, d, a0, a1 in ((ax, dx, x0, x1), (ay, dy, y0, y1)):
            still = d == 0.0
            ta, tb = (a0 - a) / d, (a1 - a) / d
            out = still & ((a < a0) | (a > a1))
            np.maximum(lo, np.where(still, 0.0, np.minimum(ta, tb)), out=lo)
            np.minimum(hi, np.where(still, np.where(out, -1.0, 1.0), np.maximum(ta, tb)), out=hi)
    ends = []
    for t, px, py in ((lo, ax, ay), (hi, bx, by)):     # np.clip's numbers, by maximum and minimum (faster)
        inner = (t > 0.0) & (t < 1.0)
        ends.append((np.where(inner, np.minimum(np.maximum(ax + t * dx, x0), x1), px),
                     np.where(inner, np.minimum(np.maximum(ay + t * dy, y0), y1), py)))
    (px, py), (qx, qy) = ends
    return np.where(hi > lo, np.sqrt((qx - px) ** 2 + (qy - py) ** 2), 0.0)
