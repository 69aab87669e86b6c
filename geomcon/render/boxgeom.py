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
    t0, t1 = 0.0, 1.0
    if dx == 0.0:
        if ax < x0 or ax > x1:
            return 0.0
    else:
        ta, tb = (x0 - ax) / dx, (x1 - ax) / dx
        if ta > tb:
            ta, tb = tb, ta
        if ta > t0:
            t0 = ta
        if tb < t1:
            t1 = tb
    if dy == 0.0:
        if ay < y0 or ay > y1:
            return 0.0
    else:
        ta, tb = (y0 - ay) / dy, (y1 - ay) / dy
        if ta > tb:
            ta, tb = tb, ta
        if ta > t0:
            t0 = ta
        if tb < t1:
            t1 = tb
    return (t1 - t0) * math.hypot(dx, dy) if t1 > t0 else 0.0


def box_overlap(a: Box, b: Box) -> tuple[float, float]:
    """Width and height of the boxes' common part (negative where they miss each other)."""
    return min(a[2], b[2]) - max(a[0], b[0]), min(a[3], b[3]) - max(a[1], b[1])
