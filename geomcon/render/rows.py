"""Numbered rows: the labels of crowded division points (1′, 2′, … of a cam; the ticks 1, 2, … of its s–δ axis)
spread out in a line beside the row, in order, each tied to its point by a leader, as a textbook numbers every
division of a crowded row rather than leaving numbers out.

A *cluster* is a run of consecutive points of one row whose labels cannot sit side by side at their points.
Its labels go on one line parallel to the cluster's chord, beyond its farthest point: each as near its own
point's foot on that line as the labels' widths allow (order kept; the least squared shift, by pooling
adjacent violators), so no two boxes overlap.

Examples
--------
>>> spread([0.0, 0.5, 1.0], [1.0, 1.0, 1.0], 0.5)      # three 2 mm wide labels with 0.5 mm between them
[-2.0, 0.5, 3.0]
>>> clusters([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (20.0, 0.0), (20.0, 5.0)], [(2.0, 2.0)] * 5, 0.5)
[[0, 1, 2]]
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

XY = tuple[float, float]

SEP = 0.6
"""Room (paper mm) kept between two labels of a spread-out cluster."""
OFFSETS = (1.2, 2.5, 4.0, 6.0)
"""Distances (paper mm) beyond the cluster's farthest point marker at which its line of labels is tried."""
FAN_REACH = 16.0
"""The most (paper mm) a spread-out label's box lies from its point (it has a leader; checked over the gallery)."""


def spread(t: Sequence[float], half: Sequence[float], sep: float) -> list[float]:
    """Centres along a line for boxes wanted at ``t`` (sorted) with half widths ``half``: consecutive boxes at
    least ``sep`` apart, order kept, the sum of squared shifts least (isotonic regression of ``t`` less the
    widths before each, by pooling adjacent violators)."""
    need = [0.0]
    for a, b in zip(half, half[1:]):
        need.append(need[-1] + a + b + sep)
    blocks: list[list[float]] = []                     # [mean, count] of pooled targets
    for ti, ni in zip(t, need):
        blocks.append([ti - ni, 1.0])
        while len(blocks) > 1 and blocks[-2][0] > blocks[-1][0]:
            m2, c2 = blocks.pop()
            m1, c1 = blocks.pop()
            blocks.append([(m1 * c1 + m2 * c2) / (c1 + c2), c1 + c2])
    out: list[float] = []
    for m, c in blocks:
        out += [m] * int(c)
    return [y + ni for y, ni in zip(out, need)]


def clusters(anchors: Sequence[XY], sizes: Sequence[tuple[float, float]], sep: float) -> list[list[int]]:
    """Runs (indices, two or more) of consecutive anchors closer than their labels need (``sizes``: width,
    height; the labels' half extents along the line joining the two anchors, plus ``sep``): the crowded parts
    of a row. Labels stacked in rows further apart than their height are not crowded, however wide."""
    out: list[list[int]] = []
    run: list[int] = []
    for i in range(len(anchors) - 1):
        (x0, y0), (x1, y1) = anchors[i], anchors[i + 1]
        d = math.hypot(x1 - x0, y1 - y0)
        ux, uy = ((x1 - x0) / d, (y1 - y0) / d) if d > 0 else (1.0, 0.0)
        need = sum(abs(ux) * w / 2 + abs(uy) * h / 2 for w, h in (sizes[i], sizes[i + 1])) + sep
        if d < need:
            run = run or [i]
            run.append(i + 1)
        elif run:
            out.append(run)
            run = []
    if run:
        out.append(run)
    return out


def thinned(anchors: Sequence[XY], sizes: Sequence[tuple[float, float]], sep: float) -> list[int]:
    """The indices of a row of counting numbers on a line to print: in each crowded run (:func:`clusters`), its
    first and every 2nd after it, or every 4th, 8th, … where every 2nd still would not fit side by side (the
    numbers left out are counted on from those printed, as on a textbook's crowded axis).

    >>> thinned([(float(x), 0.0) for x in (0, 1, 2, 3, 4, 20, 21)], [(1.5, 2.0)] * 7, 0.4)
    [0, 2, 4, 5]
    >>> thinned([(0.5 * x, 0.0) for x in range(6)], [(1.5, 2.0)] * 6, 0.4)
    [0, 4]
    """
    keep = set(range(len(anchors)))
    for run in clusters(anchors, sizes, sep):
        step = 2
        while step < len(run) and clusters([anchors[k] for k in run[::step]], [sizes[k] for k in run[::step]], sep):
            step *= 2
        keep -= set(run) - set(run[::step])
    return sorted(keep)


def row_centre(anchors: Sequence[XY]) -> XY | None:
    """The centre of the circle best fitting a row's points (least squares on x² + y² + Dx + Ey + F = 0): a cam's
    centre O, as its divisions go round it; None for fewer than three points, or points that do not go round a
    centre (on a line, or on an arc of less than 90°), whose labels keep the drawing's directions.

    >>> c = row_centre([(10.0 + 5 * math.cos(a), 20.0 + 5 * math.sin(a)) for a in (0.0, 1.5, 3.0, 4.5)])
    >>> round(c[0], 9), round(c[1], 9)
    (10.0, 20.0)
    >>> row_centre([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]) is None
    True
    """
    if len(anchors) < 3:
        return None
    import numpy as np
    a = np.array([[x, y, 1.0] for x, y in anchors])
    b = -np.array([x * x + y * y for x, y in anchors])
    if np.linalg.matrix_rank(a, tol=1e-9 * max(1.0, float(np.abs(a).max()))) < 3:
        return None
    (d, e, _), *_ = np.linalg.lstsq(a, b, rcond=None)
    cx, cy = -d / 2, -e / 2
    turns = sorted(math.atan2(y - cy, x - cx) for x, y in anchors)
    gaps = [b2 - b1 for b1, b2 in zip(turns, turns[1:])] + [turns[0] + 2 * math.pi - turns[-1]]
    return (float(cx), float(cy)) if 2 * math.pi - max(gaps) >= math.pi / 2 else None


@dataclass(frozen=True, slots=True)
class Fan:
    """One way of laying out a cluster's labels: their box centres (paper mm), in the cluster's order."""

    centres: tuple[XY, ...]
    side: int
    offset: float


def fans(anchors: Sequence[XY], sizes: Sequence[tuple[float, float]], marker: float, away: XY,
         sides: Sequence[int] = (1, -1)) -> list[Fan]:
    """The layouts to try for one cluster: its labels (``sizes``: width, height) on a line parallel to the chord
    from its first to its last anchor, beyond every anchor (``marker``: the dots' radius) by each of
    :data:`OFFSETS`, on the side towards ``away`` first (``sides``: 1 that side, -1 the other)."""
    (x0, y0), (x1, y1) = anchors[0], anchors[-1]
    d = math.hypot(x1 - x0, y1 - y0)
    ux, uy = ((x1 - x0) / d, (y1 - y0) / d) if d > 0 else (1.0, 0.0)
    nx, ny = -uy, ux
    if nx * away[0] + ny * away[1] < 0:
        nx, ny = -nx, -ny
    cx = sum(p[0] for p in anchors) / len(anchors)
    cy = sum(p[1] for p in anchors) / len(anchors)
    t = [(p[0] - cx) * ux + (p[1] - cy) * uy for p in anchors]
    order = sorted(range(len(anchors)), key=lambda i: t[i])
    half_u = [abs(ux) * w / 2 + abs(uy) * h / 2 for w, h in sizes]
    half_n = max(abs(nx) * w / 2 + abs(ny) * h / 2 for w, h in sizes)
    xs = spread([t[i] for i in order], [half_u[i] for i in order], SEP)
    along = [0.0] * len(anchors)
    for i, x in zip(order, xs):
        along[i] = x
    out = []
    for side in sides:
        sx, sy = nx * side, ny * side
        beyond = max((p[0] - cx) * sx + (p[1] - cy) * sy for p in anchors) + marker
        for off in OFFSETS:
            k = beyond + off + half_n
            out.append(Fan(tuple((cx + ux * a + sx * k, cy + uy * a + sy * k) for a in along), side, off))
    return out


__all__ = ["FAN_REACH", "Fan", "OFFSETS", "SEP", "clusters", "fans", "row_centre", "spread", "thinned"]
