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
    owners : sequence of str, optional
        The step that drew each (a text's own step is weighed by :meth:`fewest`'s ``own``).
    """

    def __init__(self, geoms: Sequence[Any], hard: Sequence[bool], frame: tuple[float, float, float, float],
                 owners: Sequence[str] | None = None):
        g = np.empty(len(geoms), dtype=object)
        g[:] = list(geoms)
        self._geoms = g
        self._weight = np.where(np.asarray(hard, dtype=bool), 2, 1) if len(hard) else np.zeros(0, dtype=int)
        self._owners = np.array(list(owners) if owners is not None else [""] * len(g), dtype=object)
        self._tree = shapely.STRtree(g)
        self._frame = frame

    def count(self, boxes: Sequence[Any], own: tuple[str, np.ndarray] | None = None) -> np.ndarray:
        """The weighted number of lines each box crosses; ``own`` = (step, weight of each of the geometries when
        it is that step's: 0 leaves it out) weighs a text's own step."""
        out = np.zeros(len(boxes), dtype=int)
        if not len(boxes) or not len(self._geoms):
            return out
        b = np.empty(len(boxes), dtype=object)
        b[:] = list(boxes)
        k, j = self._tree.query(b, predicate="intersects")
        w = self._weight[j]
        if own is not None:
            mine = self._owners[j] == own[0]
            w = np.where(mine, own[1][j], w)
        np.add.at(out, k, w)
        return out

    def fewest(self, req: Request, placed: Sequence[Any], distances: Sequence[float] = NEAR,
               own: tuple[str, np.ndarray] | None = None) -> tuple[float, float, int]:
        """The centre of the spot near ``req.anchor`` crossing the fewest lines (the nearest of those, then the
        direction nearest ``req.prefer``), clear of the ``placed`` boxes, inside the frame and no nearer one of
        ``req.rivals`` than its anchor (a point's label), tried at ``distances`` beyond the gap; and its count
        (-1 when there is no such spot); ``own`` as :meth:`count` takes it."""
        k = np.array(sorted(range(RING), key=lambda k: min(k, RING - k)), dtype=float)
        a = req.prefer + 2 * math.pi * k / RING
        ux, uy = np.cos(a), np.sin(a)
        with np.errstate(divide="ignore"):
            reach = np.minimum(np.where(np.abs(ux) > 1e-12, (req.width / 2) / np.abs(ux), np.inf),
                               np.where(np.abs(uy) > 1e-12, (req.height / 2) / np.abs(uy), np.inf))
        p = np.empty(len(placed), dtype=object)
        p[:] = list(placed)
        near = shapely.STRtree(p) if len(p) else None
        x0, y0, x1, y1 = self._frame
        best: tuple[float, float, int] = (req.anchor[0], req.anchor[1], -1)
        for d in distances:                         # ring by ring, nearest first: a ring with a free spot ends it
            cx = req.anchor[0] + ux * (req.gap + d + reach)
            cy = req.anchor[1] + uy * (req.gap + d + reach)
            if req.rotate:
                boxes = np.array([req.box(x, y) for x, y in zip(cx.tolist(), cy.tolist())], dtype=object)
            else:
                boxes = shapely.box(cx - req.width / 2, cy - req.height / 2, cx + req.width / 2, cy + req.height / 2)
            bounds = shapely.bounds(boxes)
            free = (bounds[:, 0] >= x0) & (bounds[:, 1] >= y0) & (bounds[:, 2] <= x1) & (bounds[:, 3] <= y1)
            if near is not None:
                hit, _ = near.query(boxes, predicate="intersects")
                free[hit] = False
            if req.rivals:
                free &= ~np.array(nearer_rival(req, list(zip(cx.tolist(), cy.tolist()))), dtype=bool)
            if not free.any():
                continue
            rows = np.flatnonzero(free)
            counts = self.count(boxes[rows], own)
            i = int(np.argmin(counts))                              # the first of the fewest: nearest direction
            if best[2] < 0 or counts[i] < best[2]:
                best = (float(cx[rows[i]]), float(cy[rows[i]]), int(counts[i]))
            if best[2] == 0:
                break
        return best
