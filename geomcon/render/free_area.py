"""Room on sheet 1 for the Results and Warnings blocks inside the drawing's own area: a free box that meets no
drawn element, found after the figure is drawn, so that the answer the title asks for is read on sheet 1
without shrinking the drawing to a smaller standard scale (issue 11, review item A1).

The drawing is centred in its area, so its free room is in the corners: a box is tried at every position of a
2 mm grid over the frame (less the title block, the scale bar and the step captions' box), each width of
:data:`WIDTHS` (the lines wrap to it, so the height follows), and the free one nearest a corner of the frame is
taken (the first width of :data:`WIDTHS` on a tie). A box is free when, grown by :data:`CLEAR`, it meets no
stroke, mark, symbol or text of the figure (:func:`geomcon.render.shapes.obstacle`): the figure is rasterised
once into 1 mm cells (strokes sampled every 0.5 mm, areas by their bounding boxes) and a box is tested by the
cells it covers with one cell of slack, so the test is conservative and every grid position costs four look-ups
(the cell indices found once per column and per row of the grid: :func:`_grid_counts`).

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

import functools
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


CELL = 1.0
"""Cell of the occupancy raster (paper mm): a box is tested against the cells it covers."""
DENSE = 0.5
"""Strokes are sampled every this many paper mm when rasterised (a sample within 0.25 mm of every point)."""


def raster(geoms: Sequence[shapely.Geometry], region: Box) -> np.ndarray:
    """A raster of ``region`` in :data:`CELL` cells, a cell 1 when a stroke sample, a point, or the bounding box
    of an area (a filled symbol, a text) falls in it. Conservative: areas count by their bounding boxes."""
    x0, y0, x1, y1 = region
    nx, ny = int(np.ceil((x1 - x0) / CELL)) + 1, int(np.ceil((y1 - y0) / CELL)) + 1
    grid = np.zeros((ny, nx), dtype=np.int32)
    geoms = np.asarray(geoms, dtype=object)
    if len(geoms):
        kinds = shapely.get_type_id(geoms)
        areas = (kinds == 3) | (kinds == 6)                               # polygons: their bounding boxes
        for bx0, by0, bx1, by1 in shapely.bounds(geoms[areas]):
            _paint(grid, region, (bx0, by0, bx1, by1))
        if (~areas).any():
            pts = _samples(geoms[~areas])
            j = np.clip(((pts[:, 0] - x0) // CELL).astype(np.int64), 0, nx - 1)
            i = np.clip(((pts[:, 1] - y0) // CELL).astype(np.int64), 0, ny - 1)
            grid[i, j] = 1
    return grid


def _samples(geoms: np.ndarray) -> np.ndarray:
    """The vertices of ``geoms`` (strokes, points) and points along every segment, :data:`DENSE` apart at most;
    non-finite coordinates dropped (a degenerate stroke, e.g. one repeated point, is its vertex).

    >>> _samples(np.array([shapely.LineString([(0, 0), (1, 0)])], dtype=object)).tolist()
    [[0.0, 0.0], [1.0, 0.0], [0.0, 0.0], [0.5, 0.0]]
    """
    coords, owner = shapely.get_coordinates(geoms, return_index=True)
    same = owner[1:] == owner[:-1]
    a, b = coords[:-1][same], coords[1:][same]
    length = np.hypot(b[:, 0] - a[:, 0], b[:, 1] - a[:, 1])
    length = np.where(np.isfinite(length), length, 0.0)
    n = np.clip(np.ceil(length / DENSE), 1, 100000).astype(np.int64)
    rep = np.repeat(np.arange(len(a)), n)
    k = np.arange(len(rep)) - np.repeat(np.cumsum(n) - n, n)
    t = (k / np.repeat(n, n))[:, None]
    pts = np.concatenate([coords, a[rep] + (b[rep] - a[rep]) * t]) if len(rep) else coords
    return pts[np.isfinite(pts).all(axis=1)]


def _paint(grid: np.ndarray, region: Box, box: Box) -> None:
    """Mark the cells of ``grid`` (a raster of ``region``) that ``box`` covers."""
    ny, nx = grid.shape
    i0, i1 = _cell(box[1], region[1], ny), _cell(box[3], region[1], ny)
    j0, j1 = _cell(box[0], region[0], nx), _cell(box[2], region[0], nx)
    grid[i0:i1 + 1, j0:j1 + 1] = 1


def occupancy(geoms: Sequence[shapely.Geometry], region: Box) -> np.ndarray:
    """The summed-area table of :func:`raster`: a box's count of occupied cells is four look-ups
    (:func:`_counts`)."""
    return _table(raster(geoms, region))


def _table(grid: np.ndarray) -> np.ndarray:
    """The summed-area table of ``grid`` (0 and 1), a row and a column of zeros first: summed in place in 32-bit
    integers (a count never exceeds the grid's cells), ~4× faster on a sheet's grid than ``cumsum`` to 64 bits
    and a copy.

    >>> _table(np.array([[1, 0, 1], [1, 1, 0]], dtype=np.int32)).tolist()
    [[0, 0, 0, 0], [0, 1, 1, 2], [0, 2, 3, 4]]
    """
    table = np.zeros((grid.shape[0] + 1, grid.shape[1] + 1), dtype=np.int32)
    inner = table[1:, 1:]
    np.cumsum(grid, axis=0, dtype=np.int32, out=inner)
    np.cumsum(inner, axis=1, dtype=np.int32, out=inner)
    return table


def _cell(v: float, lo: float, n: int) -> int:
    return int(min(max((v - lo) // CELL, 0), n - 1))


def _counts(table: np.ndarray, region: Box, bx0: np.ndarray, by0: np.ndarray, bx1: np.ndarray, by1: np.ndarray
            ) -> np.ndarray:
    """How many occupied cells each box (x0, y0, x1, y1 arrays, paper mm) covers, one cell of slack around."""
    ny, nx = table.shape[0] - 1, table.shape[1] - 1
    j0 = np.clip(((bx0 - region[0]) // CELL).astype(np.int64) - 1, 0, nx)
    i0 = np.clip(((by0 - region[1]) // CELL).astype(np.int64) - 1, 0, ny)
    j1 = np.clip(((bx1 - region[0]) // CELL).astype(np.int64) + 2, 0, nx)
    i1 = np.clip(((by1 - region[1]) // CELL).astype(np.int64) + 2, 0, ny)
    return table[i1, j1] - table[i0, j1] - table[i1, j0] + table[i0, j0]


def _cells(b0: np.ndarray, b1: np.ndarray, lo: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The first and past-the-last cell (of ``n`` from ``lo``) along one axis of boxes from ``b0`` to ``b1``, one
    cell of slack around (:func:`_counts`'s arithmetic)."""
    c0 = ((b0 - lo) // CELL).astype(np.int64) - 1
    c1 = ((b1 - lo) // CELL).astype(np.int64) + 2
    np.maximum(c0, 0, out=c0)                   # np.clip's numbers, without its overhead
    np.minimum(c0, n, out=c0)
    np.maximum(c1, 0, out=c1)
    np.minimum(c1, n, out=c1)
    return c0, c1


def _grid_counts(table: np.ndarray, region: Box, bx0: np.ndarray, by0: np.ndarray, bx1: np.ndarray, by1: np.ndarray
                 ) -> np.ndarray:
    """:func:`_counts` of every box of a grid: the boxes ``(bx0[j], by0[i], bx1[j], by1[i])`` (paper mm), their
    counts as one array of ``len(by0) × len(bx0)`` raveled row by row. The cell indices are found per column and
    per row (the same arithmetic as :func:`_counts`, so the same cells) and the table read by outer indexing.

    >>> t = occupancy([], (0.0, 0.0, 10.0, 10.0))
    >>> _grid_counts(t, (0.0, 0.0, 10.0, 10.0), np.array([0.0, 2.0]), np.array([0.0]), np.array([4.0, 6.0]),
    ...              np.array([4.0])).tolist()
    [0, 0]
    """
    ny, nx = table.shape[0] - 1, table.shape[1] - 1
    j0, j1 = _cells(bx0, bx1, region[0], nx)
    i0, i1 = _cells(by0, by1, region[1], ny)
    return _read(table, i0, i1, j0, j1)


def _read(table: np.ndarray, i0: np.ndarray, i1: np.ndarray, j0: np.ndarray, j1: np.ndarray) -> np.ndarray:
    """The counts of the cells ``i0:i1`` × ``j0:j1`` for every row range and column range, raveled row by row."""
    a, b = table[i1], table[i0]
    return (a[:, j1] - b[:, j1] - a[:, j0] + b[:, j0]).ravel()


@functools.lru_cache(maxsize=1024)
def _axis(lo: float, hi: float, size: float, origin: float, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The grid positions of a box ``size`` long from ``lo`` to ``hi`` (:func:`_positions`) and the cells each
    covers grown by :data:`CLEAR` (:func:`_cells` of a raster of ``n`` cells from ``origin``): a function of its
    arguments alone, remembered (a sheet's rooms share their region and are asked the same sizes). Not to be
    changed."""
    pos = _positions(lo, hi - size)
    return (pos, *_cells(pos - CLEAR, pos + size + CLEAR, origin, n))


_DRAWN: dict[tuple[Box, tuple[int, ...]], tuple[tuple[Shape, ...], np.ndarray]] = {}
_DRAWN_MAX = 8


def _drawn(shapes: tuple[Shape, ...], region: Box) -> np.ndarray:
    """:func:`raster` of the shapes' obstacles, remembered for the last few sets of shapes (the same objects: shapes
    are frozen, and kept here while remembered so that no other takes their ids): a sheet's layout search makes the
    free room of one figure again and again, with other boxes kept out (results_in_free_room for each block of
    lines, each detail window). A raster marks each geometry's cells, so that of shapes holding a remembered set is
    that set's with the others' added (a figure whose strokes were asked before its texts were placed,
    :func:`geomcon.render.svg.may_hold_results`). Not to be changed: a room copies it."""
    key = (region, tuple(map(id, shapes)))
    hit = _DRAWN.get(key)
    if hit is None:
        grid = None
        ids = set(key[1])
        for (at, some), (_, part) in _DRAWN.items():      # a figure rasterised before its texts were placed
            if at == region and len(some) < len(ids) and ids.issuperset(some):     # (a sketch): the rest added
                had = set(some)
                grid = np.maximum(part, raster([obstacle(s) for s in shapes if id(s) not in had], region))
                break
        if grid is None:
            grid = raster([obstacle(s) for s in shapes], region)
        if len(_DRAWN) >= _DRAWN_MAX:
            _DRAWN.clear()
        hit = _DRAWN[key] = (shapes, grid)
    return hit[1]


class FreeRoom:
    """The free room of ``region`` (paper mm) around ``shapes`` and ``keepouts``, rasterised once
    (:func:`raster`): :meth:`find` places boxes in it, :meth:`without` takes a placed box out of it.

    >>> room = FreeRoom([], (0.0, 0.0, 50.0, 50.0), [(0.0, 0.0, 25.0, 30.0)])
    >>> room.find([(20.0, 10.0)])
    (30.0, 0.0, 20.0, 10.0)
    >>> room.without((30.0, 0.0, 50.0, 10.0)).find([(20.0, 10.0)])
    (0.0, 40.0, 20.0, 10.0)
    """

    def __init__(self, shapes: Iterable[Shape], region: Box, keepouts: Sequence[Box], _grid: np.ndarray | None = None):
        self.region = region
        x0, y0, x1, y1 = region
        self.grown = (x0 - 2 * CLEAR, y0 - 2 * CLEAR, x1 + 2 * CLEAR, y1 + 2 * CLEAR)
        if _grid is None:
            _grid = _drawn(tuple(shapes), self.grown).copy()
            if len(keepouts):                   # a raster marks each geometry's cells: of all, the union of each's
                np.maximum(_grid, raster([shapely.box(*k) for k in keepouts], self.grown), out=_grid)
        self.grid = _grid
        self.table = _table(_grid)
        self._nearest: dict[tuple[float, float], tuple[float, float, float] | None] = {}     # :meth:`find`'s, by size

    def without(self, box: Box) -> FreeRoom:
        """This room with ``box`` (paper mm) taken."""
        grid = self.grid.copy()
        _paint(grid, self.grown, box)
        return FreeRoom((), self.region, (), grid)

    def fits(self, x: float, y: float, w: float, h: float) -> bool:
        """Whether the box ``(x, y, w, h)`` lies in the region, clear of every shape by :data:`CLEAR` (the test
        :meth:`find` makes at each position).

        >>> room = FreeRoom([], (0.0, 0.0, 50.0, 50.0), [(0.0, 0.0, 25.0, 30.0)])
        >>> room.fits(30.0, 0.0, 20.0, 10.0), room.fits(20.0, 0.0, 20.0, 10.0), room.fits(30.0, 45.0, 20.0, 10.0)
        (True, False, False)
        """
        x0, y0, x1, y1 = self.region
        if x < x0 or y < y0 or x + w > x1 or y + h > y1:
            return False
        a = np.array
        return int(_counts(self.table, self.grown, a([x - CLEAR]), a([y - CLEAR]), a([x + w + CLEAR]),
                           a([y + h + CLEAR]))[0]) == 0

    def _free(self, w: float, h: float) -> tuple[np.ndarray, np.ndarray] | None:
        """The corners (x, y) of every free box ``w`` × ``h`` at the grid's positions, row by row (top-left
        first); None when there is none."""
        x0, y0, x1, y1 = self.region
        ny, nx = self.table.shape[0] - 1, self.table.shape[1] - 1
        xs, j0, j1 = _axis(x0, x1, w, self.grown[0], nx)
        ys, i0, i1 = _axis(y0, y1, h, self.grown[1], ny)
        if not (len(xs) and len(ys)):
            return None
        n = _read(self.table, i0, i1, j0, j1)          # :func:`_grid_counts` of the boxes at those positions
        free = np.flatnonzero(n == 0)
        if not len(free):
            return None
        return xs[free % len(xs)], ys[free // len(xs)]

    def span(self, w: float, h: float) -> tuple[float, float, float, float] | None:
        """The least and greatest x, then y, of the corners of the free boxes ``w`` × ``h`` (:meth:`find`'s
        positions); None when there is none.

        >>> FreeRoom([], (0.0, 0.0, 50.0, 50.0), [(0.0, 0.0, 25.0, 30.0)]).span(20.0, 10.0)
        (0.0, 30.0, 0.0, 40.0)
        """
        free = self._free(w, h)
        if free is None:
            return None
        gx, gy = free
        return float(gx.min()), float(gx.max()), float(gy.min()), float(gy.max())

    def find(self, sizes: Sequence[tuple[float, float]]) -> tuple[float, float, float, float] | None:
        """The free box ``(x, y, w, h)`` nearest a corner of the region among ``sizes`` (tried in order: the
        first size wins a tie), clear of every shape by :data:`CLEAR`; None when no size fits anywhere."""
        best: tuple[float, int, tuple[float, float, float, float]] | None = None
        for rank, (w, h) in enumerate(sizes):
            near = self._nearest.get((w, h), False)
            if near is False:
                near = self._nearest[w, h] = self._near(w, h)
            if near is None:
                continue
            cand = (near[0], rank, (near[1], near[2], w, h))
            if best is None or cand[:2] < best[:2]:
                best = cand
        return None if best is None else best[2]

    def _near(self, w: float, h: float) -> tuple[float, float, float] | None:
        """The free box ``w`` × ``h`` nearest a corner of the region: its distance to that corner and its corner
        (x, y); None when there is none. Remembered by :meth:`find` (a room is never changed: :meth:`without`
        makes another), which a layout search asks the same sizes again and again."""
        free = self._free(w, h)
        if free is None:
            return None
        x0, y0, x1, y1 = self.region
        gx, gy = free                                           # row by row: top-left first
        # distance of the box to the nearest corner of the region: the larger of its x and y gaps to it
        d = np.maximum(np.minimum(gx - x0, x1 - (gx + w)), np.minimum(gy - y0, y1 - (gy + h)))
        k = int(np.argmin(d))                      # the first (row-major: top-left first) on a tie
        return float(d[k]), float(gx[k]), float(gy[k])


def free_box(shapes: Iterable[Shape], region: Box, keepouts: Sequence[Box], sizes: Sequence[tuple[float, float]]
             ) -> tuple[float, float, float, float] | None:
    """The free box ``(x, y, w, h)`` nearest a corner of ``region`` (paper mm) among ``sizes`` (tried in order:
    the first size wins a tie), clear of every shape by :data:`CLEAR` and meeting no ``keepouts`` box; None
    when no size fits anywhere (:class:`FreeRoom`: the shapes are rasterised once, so each size is tested at
    every grid position by array look-ups).

    >>> free_box([], (0.0, 0.0, 50.0, 50.0), [(0.0, 0.0, 25.0, 30.0)], [(20.0, 10.0)])
    (30.0, 0.0, 20.0, 10.0)
    """
    return FreeRoom(shapes, region, keepouts).find(sizes)


__all__ = ["CELL", "CLEAR", "STEP", "WIDTHS", "FreeRoom", "free_box", "occupancy", "raster"]
