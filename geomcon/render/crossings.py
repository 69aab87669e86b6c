"""Where a mark's value crosses the fewest drawn lines: the rescue of a value the placer could only put across
lines.

The placer scores a candidate by the *worst* thing it covers (:mod:`.clearance`), so in a thicket of thin
construction lines a box across six of them scores like one across a single line, and a mark's value can land
on the mark's own normal (200-20: ``α=35.00°`` across its normal and six construction lines). A value the
placer leaves covering something is therefore tried again here on a finer ring of spots near its arc, and goes
to the one that crosses the fewest lines (links counting double), nearest first; spots that would touch a text
placed before or leave the figure are never taken. A point's label is rescued likewise, at the distances a label
may take and never nearer another point than its own.

Examples
--------
>>> import shapely
>>> from geomcon.render.placement import Request
>>> lines = [shapely.LineString([(x, -20), (x, 20)]) for x in (-6.0, -3.0, 3.0, 6.0)]
>>> c = Crossings(lines, [False] * 4, (-30.0, -30.0, 30.0, 30.0))
>>> req = Request((0.0, 0.0), 2.0, 2.0, 0.5, 0.0)
>>> x, y = c.fewest(req, [])[:2]
>>> abs(x) < 2.0                       # between the middle lines, off them
True
"""
from __future__ import annotations

import math
from typing import Any, Sequence

import numpy as np
import shapely

from .placement import Request, half_extent, nearer_rival

RING = 32
"""Directions tried around a value's anchor."""

NEAR = (0.0, 1.0, 2.0, 3.0, 4.5, 6.0, 8.0)
"""Distances (paper mm beyond the gap and the box's half extent) tried, nearest first: a value stays by its arc."""


class Crossings:
    """The drawn lines of a figure, to count how many a text box crosses.

    Parameters
    ----------
    geoms : sequence of shapely geometries
        The strokes the box must not cross.
    hard : sequence of bool
        Which of them are links or point markers (a crossing counts double).
    frame : (x0, y0, x1, y1)
        The box must stay inside it.
    """

    def __init__(self, geoms: Sequence[Any], hard: Sequence[bool], frame: tuple[float, float, float, float]):
        g = np.empty(len(geoms), dtype=object)
        g[:] = list(geoms)
        self._geoms = g
        self._weight = np.where(np.asarray(hard, dtype=bool), 2, 1) if len(hard) else np.zeros(0, dtype=int)
        self._tree = shapely.STRtree(g)
        self._frame = frame

    def count(self, boxes: Sequence[Any]) -> np.ndarray:
        """The weighted number of lines each box crosses."""
        out = np.zeros(len(boxes), dtype=int)
        if not len(boxes) or not len(self._geoms):
            return out
        b = np.empty(len(boxes), dtype=object)
        b[:] = list(boxes)
        k, j = self._tree.query(b, predicate="intersects")
        np.add.at(out, k, self._weight[j])
        return out

    def fewest(self, req: Request, placed: Sequence[Any], distances: Sequence[float] = NEAR
               ) -> tuple[float, float, int]:
        """The centre of the spot near ``req.anchor`` crossing the fewest lines (the nearest of those, then the
        direction nearest ``req.prefer``), clear of the ``placed`` boxes, inside the frame and no nearer one of
        ``req.rivals`` than its anchor (a point's label), tried at ``distances`` beyond the gap; and its count
        (-1 when there is no such spot)."""
        spots, boxes = [], []
        turns = sorted(range(RING), key=lambda k: min(k, RING - k))
        for d in distances:
            for k in turns:
                a = req.prefer + 2 * math.pi * k / RING
                ux, uy = math.cos(a), math.sin(a)
                r = req.gap + d + half_extent(ux, uy, req.width, req.height)
                cx, cy = req.anchor[0] + ux * r, req.anchor[1] + uy * r
                spots.append((cx, cy))
                boxes.append(req.box(cx, cy))
        counts = self.count(boxes)
        x0, y0, x1, y1 = self._frame
        bounds = shapely.bounds(np.array(boxes, dtype=object))
        inside = (bounds[:, 0] >= x0) & (bounds[:, 1] >= y0) & (bounds[:, 2] <= x1) & (bounds[:, 3] <= y1)
        free = inside.copy()
        if len(placed):
            p = np.empty(len(placed), dtype=object)
            p[:] = list(placed)
            k, _ = shapely.STRtree(p).query(np.array(boxes, dtype=object), predicate="intersects")
            free[k] = False
        if req.rivals:
            free &= ~np.array(nearer_rival(req, spots), dtype=bool)
        if not free.any():
            return req.anchor[0], req.anchor[1], -1
        i = int(np.flatnonzero(free)[np.argmin(counts[free])])     # the first of the fewest: nearest first
        return spots[i][0], spots[i][1], int(counts[i])
