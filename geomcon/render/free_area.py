"""Room on sheet 1 for the Results and Warnings blocks inside the drawing's own area: a free box that meets no
drawn element, found after the figure is drawn, so that the answer the title asks for is read on sheet 1
without shrinking the drawing to a smaller standard scale (issue 11, review item A1).

The drawing is centred in its area, so its free room is in the corners: a box is tried at every position of a
2 mm grid over the frame (less the title block, the scale bar and the step captions' box), each width of
:data:`WIDTHS` (the lines wrap to it, so the height follows), and the free one nearest a corner of the frame is
taken (the narrowest width on a tie). A box is free when, grown by :data:`CLEAR`, it meets no stroke, mark,
symbol or text of the figure (:func:`geomcon.render.shapes.obstacle`).

Examples
--------
>>> from geomcon.render.shapes import Pen, Poly
>>> line = Poly(((30.0, 30.0), (250.0, 30.0)), Pen("#000", 0.35))
>>> free_box([line], (24.0, 14.0, 283.0, 160.0), [], [(95.0, 30.0)])
(24.0, 130.0, 95.0, 30.0)
>>> free_box([line], (24.0, 14.0, 283.0, 60.0), [], [(95.0, 30.0)]) is None
True
"""
from __future__ import annotations

from typing import Iterable, Sequence

import numpy as np
import shapely

from .shapes import Shape, obstacle
from .view import Box

CLEAR = 2.0
"""Paper mm kept free between the results block and any drawn element."""
STEP = 2.0
"""Grid step (paper mm) of the positions tried."""
WIDTHS = (95.0, 125.0, 80.0, 160.0, 65.0, 55.0)
"""Widths of the results block tried (paper mm): the right column's, a wider one for many results, the margin
beside the title block, a wide band, and two narrow columns for a drawing whose free room is a strip."""


def _positions(lo: float, hi: float) -> np.ndarray:
    """Grid positions from ``lo`` to ``hi`` (both ends kept), :data:`STEP` apart."""
    if hi < lo:
        return np.empty(0)
    n = int((hi - lo) // STEP) + 1
    xs = lo + STEP * np.arange(n)
    return xs if xs[-1] == hi else np.append(xs, hi)


def free_box(shapes: Iterable[Shape], region: Box, keepouts: Sequence[Box], sizes: Sequence[tuple[float, float]]
             ) -> tuple[float, float, float, float] | None:
    """The free box ``(x, y, w, h)`` nearest a corner of ``region`` (paper mm) among ``sizes`` (tried in order:
    the first size wins a tie), clear of every shape by :data:`CLEAR` and meeting no ``keepouts`` box; None
    when no size fits anywhere.

    >>> free_box([], (0.0, 0.0, 50.0, 50.0), [(0.0, 0.0, 27.0, 30.0)], [(20.0, 10.0)])
    (30.0, 0.0, 20.0, 10.0)
    """
    geoms = [obstacle(s) for s in shapes] + [shapely.box(*k) for k in keepouts]
    tree = shapely.STRtree(geoms)
    x0, y0, x1, y1 = region
    best: tuple[float, int, tuple[float, float, float, float]] | None = None
    for rank, (w, h) in enumerate(sizes):
        xs, ys = _positions(x0, x1 - w), _positions(y0, y1 - h)
        if not (len(xs) and len(ys)):
            continue
        gx, gy = (a.ravel() for a in np.meshgrid(xs, ys))
        boxes = shapely.box(gx - CLEAR, gy - CLEAR, gx + w + CLEAR, gy + h + CLEAR)
        hit = np.zeros(len(boxes), dtype=bool)
        if geoms:
            hit[tree.query(boxes, predicate="intersects")[0]] = True
        free = np.flatnonzero(~hit)
        if not len(free):
            continue
        # distance of the box to the nearest corner of the region: the larger of its x and y gaps to that corner
        dx = np.minimum(gx[free] - x0, x1 - (gx[free] + w))
        dy = np.minimum(gy[free] - y0, y1 - (gy[free] + h))
        d = np.maximum(dx, dy)
        k = int(np.argmin(d))                      # the first (row-major: top-left first) on a tie
        cand = (float(d[k]), rank, (float(gx[free][k]), float(gy[free][k]), w, h))
        if best is None or cand[:2] < best[:2]:
            best = cand
    return None if best is None else best[2]


__all__ = ["CLEAR", "STEP", "WIDTHS", "free_box"]
