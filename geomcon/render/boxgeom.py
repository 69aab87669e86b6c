"""Axis-parallel boxes against segments and boxes: how much of a segment lies in a box, how much two boxes
overlap.

These are estimates for bounding what shapely (GEOS) computes exactly, to within rounding: the label
placer uses them to rule candidates out, never as scores. A box is ``(x0, y0, x1, y1)``, closed; a segment
``(ax, ay, bx, by)``.

Examples
--------
>>> inside_length((-1.0, 1.0, 5.0, 1.0), (0.0, 0.0, 4.0, 2.0))     # straight across
4.0
>>> inside_length((6.0, 5.0, 9.0, 5.0), (0.0, 0.0, 4.0, 2.0))      # beside it
0.0
>>> inside_length((1.0, 1.0, 1.0, 1.0), (0.0, 0.0, 4.0, 2.0))      # a point
0.0
>>> box_overlap((0.0, 0.0, 4.0, 2.0), (3.0, 1.5, 8.0, 9.0))
(1.0, 0.5)
"""
from __future__ import annotations

import math

Box = tuple[float, float, float, float]


def inside_length(seg: tuple[float, float, float, float], box: Box) -> float:
    """The length of the segment inside the box (Liang–Barsky clipping)."""
    ax, ay, bx, by = seg
    x0, y0, x1, y1 = box
    dx, dy = bx - ax, by - ay
    span = _clip(ax, dx, x0, x1, 0.0, 1.0)
    span = span and _clip(ay, dy, y0, y1, *span)
    if not span:
        return 0.0
    t0, t1 = span
    return (t1 - t0) * math.hypot(dx, dy) if t1 > t0 else 0.0


def _clip(a: float, d: float, lo: float, hi: float, t0: float, t1: float) -> tuple[float, float] | None:
    """One axis of Liang–Barsky: the parameter range [t0, t1] of a + t·d narrowed to lo ≤ a + t·d ≤ hi
    (None when a still segment lies outside)."""
    if d == 0.0:
        return None if a < lo or a > hi else (t0, t1)
    ta, tb = (lo - a) / d, (hi - a) / d
    if ta > tb:
        ta, tb = tb, ta
    return (ta if ta > t0 else t0), (tb if tb < t1 else t1)


def box_overlap(a: Box, b: Box) -> tuple[float, float]:
    """Width and height of the boxes' common part (negative where they miss each other)."""
    return min(a[2], b[2]) - max(a[0], b[0]), min(a[3], b[3]) - max(a[1], b[1])
