"""How clear a text box is of what is drawn and placed: exact scores and cheap bounds of them.

The clearance of a box is its distance (capped at :data:`ENOUGH`) from every obstacle not its own (plus
the obstacle's allowance) and from every box and leader placed before; a box touching something scores
minus a measure of how much it covers. :func:`gaps` is that measure, by shapely (GEOS), and decides.

Measuring many candidate boxes at once (:class:`Measure`) takes every distance from GEOS in one call and
bounds what a touching box covers by estimates (:mod:`.boxgeom`) that differ from GEOS's values by far
less than :data:`EPS`; the exact clearance, as :func:`gaps` defines it, is computed on demand. A long
polyline is cut into pieces (:data:`PIECE` segments) so that only the pieces near a box are measured: its
distance is the least of its segments', which the pieces share.

Examples
--------
>>> line = shapely.LineString([(0, 5), (10, 5)])
>>> layer = Layer([line], ["line"], [0.0], split=True)
>>> boxes = shapely.box([4.0, 4.0], [6.0, 4.0], [6.0, 6.0], [7.0, 6.0])     # clear of it, across it
>>> m = Measure(layer, Layer([]), boxes, shapely.bounds(boxes), "pt", aligned=True)
>>> [m.exact(k) for k in range(2)]
[1.0, -0.6]
>>> [m.bounds(k) for k in range(2)]                # the second touches the line: it covers 0 to all
[(1.0, 1.0), (-2.0, 0.0)]
>>> tuple(round(b, 6) for b in m.refine(1))       # it covers 2 mm of it (within 1e-9)
(-0.6, -0.6)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
import shapely

from .boxgeom import Box, box_overlap, inside_length

ENOUGH = 1.6
"""Clearance (paper mm) beyond which a candidate position counts as free."""

EPS = 1e-9
"""Paper mm by which an estimate may differ from GEOS's value (rounding differs by ~1e-13)."""

REACH = ENOUGH + 1e-6
"""Pairs are looked at when their bounds come this near: anything farther cannot lower a clearance."""

PIECE = 8
"""Segments per piece of a long polyline obstacle."""

SEGMENTS, BOX, OTHER = 0, 1, 2
"""Kinds of piece: points and line strings (by their segments), axis-parallel rectangles, anything else
(measured by GEOS)."""


def covering(box: shapely.Geometry, geoms: np.ndarray) -> np.ndarray:
    """Minus the measure of how much ``box`` covers each of ``geoms`` (all touching it): 0.3 × the length
    it covers, or 0.3 × twice the square root of the area, at most 2."""
    inter = shapely.intersection(box, geoms)
    area = shapely.area(inter)
    covered = np.where(area > 0.0, 2.0 * np.sqrt(area), shapely.length(inter))
    return -np.minimum(2.0, 0.3 * covered)


def gaps(box: shapely.Geometry, geoms: np.ndarray) -> np.ndarray:
    """Distances from ``box`` to ``geoms``; for those it touches, minus a measure of how much it covers."""
    d = shapely.distance(box, geoms)
    hit = d == 0.0
    if hit.any():
        d[hit] = covering(box, geoms[hit])
    return d


def _is_box(xy: list[list[float]], bounds: Box) -> bool:
    """Whether a polygon's exterior ``xy`` (no holes) is an axis-parallel rectangle, as ``shapely.box``
    makes them: four distinct corners on its bounds, each side parallel to an axis."""
    x0, y0, x1, y1 = bounds
    if len(xy) != 5 or x0 == x1 or y0 == y1:
        return False
    if any((x != x0 and x != x1) or (y != y0 and y != y1) for x, y in xy):
        return False
    return all((xy[i][0] == xy[i + 1][0]) != (xy[i][1] == xy[i + 1][1]) for i in range(4))


@dataclass(frozen=True, slots=True)
class Piece:
    """A geometry to measure, or a piece of a long line string: the geometry, the index of the whole, its
    kind, bounds and (points and line strings) vertices."""

    geom: shapely.Geometry
    parent: int
    kind: int
    bounds: Box
    xy: np.ndarray | None = None


class Layer:
    """Geometries prepared for measuring: their owners, allowances and bounds, and their pieces (a long
    line string cut when ``split``). Geometries may be appended (what is placed, one text after another).

    Parameters
    ----------
    geoms : sequence of shapely geometries
    owners : sequence of str, optional
        The step that drew each (its own label does not keep clear of it).
    allow : sequence of float, optional
        Added to each one's distance (0 by default).
    split : bool
        Cut long line strings into pieces of :data:`PIECE` segments and index the pieces in a tree.
    """

    def __init__(self, geoms: Sequence[shapely.Geometry], owners: Sequence[str] | None = None,
                 allow: Sequence[float] | None = None, split: bool = False):
        self._split = split
        self.geoms: list[shapely.Geometry] = []
        self.simple: list[bool] = []
        self.pieces: list[Piece] = []
        self._owners: list[str] = []
        self._allow: list[float] = []
        self._bounds: list[Box] = []
        self._arrays: tuple[np.ndarray, ...] | None = None
        self._segments: dict[int, list[tuple[float, float, float, float]]] = {}
        for i, g in enumerate(geoms):
            self.append(g, owners[i] if owners is not None else "", allow[i] if allow is not None else 0.0)
        self.tree = shapely.STRtree(self.arrays()[0]) if split and self.pieces else None

    def append(self, geom: shapely.Geometry, owner: str = "", allow: float = 0.0) -> None:
        """Add a geometry (not to the tree, which indexes those of the constructor only)."""
        i = len(self.geoms)
        self.geoms.append(geom)
        self._owners.append(owner)
        self._allow.append(float(allow))
        self._arrays = None
        t = shapely.get_type_id(geom)
        xy = shapely.get_coordinates(geom)
        simple = True
        if not len(xy):
            self._bounds.append((math.nan,) * 4)
            self.simple.append(simple)
            return
        bounds = (float(xy[:, 0].min()), float(xy[:, 1].min()), float(xy[:, 0].max()), float(xy[:, 1].max()))
        self._bounds.append(bounds)
        if t in (0, 1):
            if t == 1 and len(xy) > 2:
                simple = bool(shapely.is_simple(geom))
            if len(xy) == 1:
                xy = np.vstack([xy, xy])
            if self._split and len(xy) > 2 * PIECE + 1:
                parts = [xy[j:j + PIECE + 1] for j in range(0, len(xy) - 1, PIECE)]
                for part, g in zip(parts, shapely.linestrings(np.vstack(parts), indices=np.repeat(
                        np.arange(len(parts)), [len(p) for p in parts]))):
                    self.pieces.append(Piece(g, i, SEGMENTS, (float(part[:, 0].min()), float(part[:, 1].min()),
                                                               float(part[:, 0].max()), float(part[:, 1].max())), part))
            else:
                self.pieces.append(Piece(geom, i, SEGMENTS, bounds, xy))
        else:
            rect = t == 3 and shapely.get_num_interior_rings(geom) == 0 and _is_box(xy.tolist(), bounds)
            self.pieces.append(Piece(geom, i, BOX if rect else OTHER, bounds))
        self.simple.append(simple)

    def arrays(self) -> tuple[np.ndarray, ...]:
        """The pieces' geometries, their wholes' indices, the wholes' owners, allowances and bounds, and the
        pieces' bounds, as arrays."""
        if self._arrays is None:
            geoms = np.empty(len(self.pieces), dtype=object)
            geoms[:] = [p.geom for p in self.pieces]
            self._arrays = (geoms, np.array([p.parent for p in self.pieces], dtype=np.intp),
                            np.array(self._owners, dtype=object), np.array(self._allow, dtype=float),
                            np.array(self._bounds, dtype=float).reshape(-1, 4),
                            np.array([p.bounds for p in self.pieces], dtype=float).reshape(-1, 4))
        return self._arrays

    def segments(self, piece: int) -> list[tuple[float, float, float, float]]:
        """The segments of a point or line-string piece (a point is one of zero length)."""
        out = self._segments.get(piece)
        if out is None:
            xy = self.pieces[piece].xy
            assert xy is not None
            out = self._segments[piece] = [tuple(s) for s in np.hstack([xy[:-1], xy[1:]]).tolist()]
        return out

    def near(self, bounds: np.ndarray, owner: str | None) -> tuple[np.ndarray, np.ndarray]:
        """(row, piece) pairs that may come within :data:`REACH` of the boxes ``bounds`` (one row per box),
        allowance included; with an ``owner``, only pieces of geometries whose bounds come within
        :data:`ENOUGH` (the envelope test of ``STRtree.query``) not drawn by it."""
        if not self.pieces:
            return np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp)
        geoms, parent, owners, allow, wb, pb = self.arrays()
        x0, y0, x1, y1 = bounds.T
        if self.tree is not None:
            rows, pieces = self.tree.query(shapely.box(x0 - REACH, y0 - REACH, x1 + REACH, y1 + REACH))
        else:
            far = ((pb[None, :, 0] > (x1 + REACH)[:, None]) | (pb[None, :, 2] < (x0 - REACH)[:, None])
                   | (pb[None, :, 1] > (y1 + REACH)[:, None]) | (pb[None, :, 3] < (y0 - REACH)[:, None]))
            rows, pieces = np.nonzero(~far)
        idx = parent[pieces]
        if owner is not None and len(rows):
            ob = wb[idx]
            keep = ~((ob[:, 0] > x1[rows] + ENOUGH) | (ob[:, 2] < x0[rows] - ENOUGH)
                     | (ob[:, 1] > y1[rows] + ENOUGH) | (ob[:, 3] < y0[rows] - ENOUGH))
            keep &= owners[idx] != owner
            rows, pieces, idx = rows[keep], pieces[keep], idx[keep]
        if len(rows):                            # the bounds' distance is at most the distance
            b = pb[pieces]
            gx = np.maximum(np.maximum(b[:, 0] - x1[rows], x0[rows] - b[:, 2]), 0.0)
            gy = np.maximum(np.maximum(b[:, 1] - y1[rows], y0[rows] - b[:, 3]), 0.0)
            keep = np.hypot(gx, gy) + allow[idx] <= REACH
            rows, pieces = rows[keep], pieces[keep]
        return rows, pieces


class Measure:
    """The clearances of a few candidate boxes: bounds of each at once, tighter bounds and the exact one
    on demand.

    Every distance is GEOS's (one vectorised call per layer), so a box that touches nothing has its exact
    clearance at once. What a touching box covers (an intersection, the costly part) is bounded instead,
    by 0 and all at first, then (:meth:`refine`) by the length of a line string inside the box shrunk and
    grown by :data:`EPS` (the longest single segment's for a line string that overlaps itself) or by the
    overlap of two rectangles; it is computed only for a box whose exact clearance is asked for.

    Parameters
    ----------
    obstacles, placed : Layer
        What is drawn (split, with owners and allowances) and what was placed before.
    boxes : array of shapely polygons
    bounds : array (n, 4)
        Their bounds.
    owner : str
        The step the text belongs to.
    aligned : bool
        The boxes are axis-parallel rectangles (their bounds); otherwise :meth:`refine` does not tighten.
    """

    def __init__(self, obstacles: Layer, placed: Layer, boxes: np.ndarray, bounds: np.ndarray, owner: str,
                 aligned: bool):
        n = len(boxes)
        self._boxes, self._bounds, self._aligned = boxes, bounds, aligned
        self._base = np.full(n, ENOUGH)          # the least distance plus allowance (touching ones at 0)
        self._lo = self._base
        self._touching: list[tuple[Layer, np.ndarray, np.ndarray]] = []
        for layer, owner_ in ((obstacles, owner), (placed, None)):
            rows, pieces = layer.near(bounds, owner_)
            if not len(rows):
                continue
            geoms, parent, _, allow, _, _ = layer.arrays()
            d = shapely.distance(boxes[rows], geoms[pieces])
            np.minimum.at(self._base, rows, d + allow[parent[pieces]])
            touch = d == 0.0
            if touch.any():
                self._touching.append((layer, rows[touch], pieces[touch]))
        if self._touching:
            self._lo = self._base.copy()
            for layer, rows, pieces in self._touching:          # what it covers is at most 2
                _, parent, _, allow, _, _ = layer.arrays()
                np.minimum.at(self._lo, rows, allow[parent[pieces]] - 2.0)

    def bounds(self, k: int) -> tuple[float, float]:
        """A lower and an upper bound of the clearance of box ``k`` (equal when it touches nothing)."""
        return float(self._lo[k]), float(self._base[k])

    def refine(self, k: int) -> tuple[float, float]:
        """Tighter bounds of the clearance of box ``k``, from estimates of what it covers."""
        lo = hi = float(self._base[k])
        if not self._aligned:
            return float(self._lo[k]), hi
        box = tuple(self._bounds[k].tolist())
        for layer, rows, pieces in self._touching:
            for parent, (c_lo, c_hi) in _cover_bounds(layer, pieces[rows == k].tolist(), box).items():
                a = layer._allow[parent]
                lo = min(lo, a - min(2.0, 0.3 * c_hi))
                hi = min(hi, a - min(2.0, 0.3 * c_lo))
        return lo, hi

    def exact(self, k: int) -> float:
        """The clearance of box ``k``: at most :data:`ENOUGH`, the least gap of :func:`gaps` (plus the
        obstacle's allowance) over the obstacles in reach not its own and every placed geometry."""
        best = float(self._base[k])
        for layer, rows, pieces in self._touching:
            _, parent, _, allow, _, _ = layer.arrays()
            hit = np.unique(parent[pieces[rows == k]])
            if len(hit):
                geoms = np.empty(len(hit), dtype=object)
                geoms[:] = [layer.geoms[h] for h in hit.tolist()]
                best = min(best, float(np.min(covering(self._boxes[k], geoms) + allow[hit])))
        return best


def _cover_bounds(layer: Layer, pieces: list[int], box: Box) -> dict[int, tuple[float, float]]:
    """Bounds of what the axis-parallel ``box`` covers of each geometry whose ``pieces`` touch it: a length
    inside the box shrunk and grown by :data:`EPS` (for a line string that overlaps itself, at least its
    longest single segment's), twice the root of an area, or 0 to all."""
    x0, y0, x1, y1 = box
    shrunk, grown = (x0 + EPS, y0 + EPS, x1 - EPS, y1 - EPS), (x0 - EPS, y0 - EPS, x1 + EPS, y1 + EPS)
    lengths: dict[int, list[float]] = {}             # total in the shrunk box, longest one, total in the grown
    out: dict[int, tuple[float, float]] = {}
    for i in pieces:
        piece = layer.pieces[i]
        if piece.kind == SEGMENTS:
            acc = lengths.setdefault(piece.parent, [0.0, 0.0, 0.0])
            gx0, gy0, gx1, gy1 = grown
            for s in layer.segments(i):
                ax, ay, bx, by = s
                if (ax < gx0 and bx < gx0) or (ax > gx1 and bx > gx1) or (ay < gy0 and by < gy0) \
                        or (ay > gy1 and by > gy1):
                    continue                         # wholly beside the grown box
                inner = inside_length(s, shrunk)
                acc[0] += inner
                acc[1] = max(acc[1], inner)
                acc[2] += inside_length(s, grown)
        elif piece.kind == BOX:
            ox, oy = box_overlap(box, piece.bounds)
            if ox > EPS and oy > EPS:                # surely an area, not just a shared edge
                out[piece.parent] = (2.0 * math.sqrt((ox - EPS) * (oy - EPS)), 2.0 * math.sqrt((ox + EPS) * (oy + EPS)))
            else:
                out[piece.parent] = (0.0, math.inf)
        else:
            out[piece.parent] = (0.0, math.inf)
    for parent, (total, longest, outer) in lengths.items():
        inner = total if layer.simple[parent] else longest
        out[parent] = (max(inner - EPS, 0.0), outer + EPS)
    return out
