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
>>> bounds = shapely.bounds(boxes)
>>> m = Measure(boxes, bounds, [(layer, *layer.near(bounds, "pt").pairs([0, 1]))], aligned=True)
>>> [m.exact(k) for k in range(2)]
[1.0, -0.6]
>>> [m.bounds(k) for k in range(2)]                # the second touches the line: it covers 0 to all
[(1.0, 1.0), (-2.0, 0.0)]
>>> round(m.refine(1), 6)                          # it covers at least 2 mm of it (less 1e-9)
-0.6
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Iterator, Sequence

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
        self._segments: dict[int, list[list[float]]] = {}
        self.extend(geoms, owners, allow)
        self.tree = shapely.STRtree(self.arrays()[0]) if split and self.pieces else None

    def append(self, geom: shapely.Geometry, owner: str = "", allow: float = 0.0) -> None:
        """Add a geometry (not to the tree, which indexes those of the constructor only)."""
        self.extend([geom], [owner], [allow])

    def extend(self, geoms: Sequence[shapely.Geometry], owners: Sequence[str] | None = None,
               allow: Sequence[float] | None = None) -> None:
        """Add geometries (not to the tree, which indexes those of the constructor only)."""
        n0, n = len(self.geoms), len(geoms)
        g = np.empty(n, dtype=object)
        g[:] = list(geoms)
        self.geoms += g.tolist()
        self._owners += list(owners) if owners is not None else [""] * n
        self._allow += [float(a) for a in allow] if allow is not None else [0.0] * n
        self._arrays = None
        types = shapely.get_type_id(g).tolist()
        bounds = shapely.bounds(g).reshape(-1, 4)
        self._bounds += [tuple(b) for b in bounds.tolist()]
        xy, which = shapely.get_coordinates(g, return_index=True)
        count = np.bincount(which, minlength=n)
        start = (np.cumsum(count) - count).tolist()
        count = count.tolist()
        simple = np.ones(n, dtype=bool)
        knotty = np.nonzero((np.array(types) == 1) & (np.array(count) > 2))[0]
        simple[knotty] = shapely.is_simple(g[knotty])
        self.simple += simple.tolist()
        holes = shapely.get_num_interior_rings(g).tolist()
        cut: list[np.ndarray] = []               # the parts of long line strings, made in one call
        for i in range(n):
            c, t = count[i], types[i]
            if not c:
                continue                         # empty: nothing to keep clear of
            coords = xy[start[i]:start[i] + c]
            b = tuple(bounds[i].tolist())
            if t not in (0, 1):
                rect = t == 3 and holes[i] == 0 and _is_box(coords.tolist(), b)
                self.pieces.append(Piece(g[i], n0 + i, BOX if rect else OTHER, b))
            elif c == 1:
                self.pieces.append(Piece(g[i], n0 + i, SEGMENTS, b, np.vstack([coords, coords])))
            elif self._split and c > 2 * PIECE + 1:
                for j in range(0, c - 1, PIECE):
                    part = coords[j:j + PIECE + 1]
                    cut.append(part)
                    self.pieces.append(Piece(None, n0 + i, SEGMENTS, b, part))
            else:
                self.pieces.append(Piece(g[i], n0 + i, SEGMENTS, b, coords))
        if cut:
            made = shapely.linestrings(np.vstack(cut), indices=np.repeat(np.arange(len(cut)), [len(p) for p in cut]))
            made_bounds = shapely.bounds(made).tolist()
            k = 0
            for j, p in enumerate(self.pieces):
                if p.geom is None:
                    self.pieces[j] = Piece(made[k], p.parent, SEGMENTS, tuple(made_bounds[k]), p.xy)
                    k += 1

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

    def segments(self, piece: int) -> list[list[float]]:
        """The segments [ax, ay, bx, by] of a point or line-string piece (a point is one of zero length)."""
        out = self._segments.get(piece)
        if out is None:
            xy = self.pieces[piece].xy
            assert xy is not None
            out = self._segments[piece] = np.hstack([xy[:-1], xy[1:]]).tolist()
        return out

    def near(self, bounds: np.ndarray, owner: str | None) -> Nearby:
        """The pieces that may come within :data:`REACH` of each of the boxes ``bounds`` (their bounds'
        distance, plus the allowance, does); with an ``owner``, only pieces of geometries whose bounds come
        within :data:`ENOUGH` (the envelope test of ``STRtree.query``) and not drawn by it."""
        if not self.pieces or not len(bounds):
            return Nearby(np.zeros(0, dtype=np.intp), np.zeros((len(bounds), 0), dtype=bool))
        _, parent, owners, allow, wb, pb = self.arrays()
        x0, y0, x1, y1 = (v[:, None] for v in bounds.T)
        if self.tree is not None:
            local = np.sort(self.tree.query(shapely.box(x0.min() - REACH, y0.min() - REACH,
                                                        x1.max() + REACH, y1.max() + REACH)))
        else:
            local = np.arange(len(self.pieces))
        idx = parent[local]
        b = pb[local]
        gx = np.maximum(np.maximum(b[:, 0] - x1, x0 - b[:, 2]), 0.0)
        gy = np.maximum(np.maximum(b[:, 1] - y1, y0 - b[:, 3]), 0.0)
        mask = np.hypot(gx, gy) + allow[idx] <= REACH    # the bounds' distance is at most the distance
        if owner is not None:
            ob = wb[idx]
            mask &= (owners[idx] != owner) & ~((ob[:, 0] > x1 + ENOUGH) | (ob[:, 2] < x0 - ENOUGH)
                                               | (ob[:, 1] > y1 + ENOUGH) | (ob[:, 3] < y0 - ENOUGH))
        return Nearby(local, mask)


@dataclass(frozen=True)
class Nearby:
    """The pieces (of a layer) that may come near each of some boxes: ``mask[i, j]`` for box ``i`` and
    piece ``local[j]``."""

    local: np.ndarray
    mask: np.ndarray

    def pairs(self, rows: Sequence[int]) -> tuple[np.ndarray, np.ndarray]:
        """(row in ``rows``, piece) pairs of the boxes ``rows``, rows numbered from 0 in that order."""
        r, j = np.nonzero(self.mask[rows])
        return r, self.local[j]


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
    boxes : array of shapely polygons
    bounds : array (n, 4)
        Their bounds.
    near : sequence of (Layer, rows, pieces)
        For each layer (what is drawn, what was placed), the (box, piece) pairs that may come near
        (:meth:`Layer.near`).
    aligned : bool
        The boxes are axis-parallel rectangles (their bounds); otherwise :meth:`refine` does not tighten.
    """

    def __init__(self, boxes: np.ndarray, bounds: np.ndarray,
                 near: Sequence[tuple[Layer, np.ndarray, np.ndarray]], aligned: bool):
        n = len(boxes)
        self._boxes, self._bounds, self._aligned = boxes, bounds, aligned
        self._base = np.full(n, ENOUGH)          # the least distance plus allowance (touching ones at 0)
        self._lo = self._base
        self._touching: list[tuple[Layer, np.ndarray, np.ndarray]] = []
        for layer, rows, pieces in near:
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

    def refine(self, k: int, enough: Callable[[float], bool] = lambda hi: False) -> float:
        """A tighter upper bound of the clearance of box ``k``, from lower bounds of what it covers of each
        geometry it touches; measured until ``enough(bound)`` holds."""
        hi = float(self._base[k])
        if not self._aligned or enough(hi):
            return hi
        box = tuple(self._bounds[k].tolist())
        for layer, rows, pieces in self._touching:
            for parent, covered in _covered(layer, pieces[rows == k].tolist(), box):
                hi = min(hi, layer._allow[parent] - min(2.0, 0.3 * covered))
                if enough(hi):
                    return hi
        return hi

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


def _covered(layer: Layer, pieces: list[int], box: Box) -> Iterator[tuple[int, float]]:
    """At least what the axis-parallel ``box`` covers of each geometry whose ``pieces`` touch it, growing:
    the length of a line string inside the box shrunk by :data:`EPS` (for one that overlaps itself, its
    longest single segment's), summed a segment at a time; twice the root of the overlap of a rectangle;
    0 for anything else. A geometry may be yielded several times, each time with more."""
    x0, y0, x1, y1 = box
    inner = (x0 + EPS, y0 + EPS, x1 - EPS, y1 - EPS)
    sums: dict[int, float] = {}
    for i in pieces:
        piece = layer.pieces[i]
        if piece.kind == BOX:
            ox, oy = box_overlap(box, piece.bounds)
            yield piece.parent, (2.0 * math.sqrt((ox - EPS) * (oy - EPS)) if ox > EPS and oy > EPS else 0.0)
        elif piece.kind == OTHER:
            yield piece.parent, 0.0
        else:
            simple = layer.simple[piece.parent]
            total = sums.get(piece.parent, 0.0)
            for seg in layer.segments(i):
                ax, ay, bx, by = seg
                if (ax < x0 and bx < x0) or (ax > x1 and bx > x1) or (ay < y0 and by < y0) or (ay > y1 and by > y1):
                    continue                        # wholly beside the box
                length = inside_length(seg, inner)
                if length > 0.0:
                    total = total + length if simple else max(total, length)
                    yield piece.parent, max(total - EPS, 0.0)
            sums[piece.parent] = total
