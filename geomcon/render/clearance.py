"""How clear text boxes are of what is drawn and placed: many candidate boxes measured in one vectorised pass.

The clearance of a box is its distance (capped at :data:`ENOUGH`) from every obstacle not its own (plus the
obstacle's allowance) and from every box and leader placed before; a box touching something scores minus a
measure of how much it covers (:func:`covering`: 0.3 × the length of a line inside it, or 0.3 × twice the root
of the area it shares with an area, at most 2).

Obstacles are flattened into segments (a point is one of zero length, an area its rings'), and the boxes are
measured against the segments near them in closed form (:mod:`.boxgeom`: distances, and the length of a
segment inside a box, so what a box covers of a line string that does not overlap itself is known at once).
What a box covers of an area, or of a line string that overlaps itself, is left to shapely (GEOS): it is
bounded (between the allowance less 2 and the allowance) until a choice needs it (:meth:`Measured.exact`).
The closed forms agree with GEOS's distances to rounding (a few units in the last place).

Examples
--------
>>> line = shapely.LineString([(0, 5), (10, 5)])
>>> layer = Layer([line], ["line"], [0.0], index=True)
>>> boxes = Boxes.aligned(np.array([5.0, 5.0]), np.array([3.5, 5.0]), 2.0, 1.0, np.full(2, layer.code("pt")))
>>> m = layer.measure(boxes)                      # 1 mm clear of it; across it, covering 2 mm
>>> m.known.tolist(), m.hi.tolist()
([1.0, -0.6], [1.0, -0.6])
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
import shapely

from .boxdisc import box_disc, disc_gap, discs
from .boxgeom import box_point, box_segment, inside_length

ENOUGH = 1.6
"""Clearance (paper mm) beyond which a candidate position counts as free."""

REACH = ENOUGH + 1e-6
"""Pairs are measured when their bounds come this near: anything farther cannot lower a clearance."""

CROSS = 1.0
"""Score lost per unit of crossing weight of each drawn geometry a box touches (a link or a point's marker weighs
2, a thin line 1, a text 0): a box across six thin lines scores worse than one across a single line, where the
clearance alone (the worst thing covered) would tie them. A text's own step's strokes count too (a mark's own arc
and the normal drawn with it), though their distance does not."""

NEAR = 0.2
"""Paper (mm) within which a box meets a geometry of crossing weight :data:`NEAR_WEIGHT` or more (a link, a pin,
a ground, a slider block) of another step though it does not touch it: the text's white halo cuts into the line
(200-05's value printed a hair under O's ground), so it loses the greatest crossing weight of those it comes so
near, as if it crossed one of them (once, not once a stroke: a ground's hatch is many)."""

NEAR_WEIGHT = 2.0
"""The least crossing weight of a geometry a box must keep :data:`NEAR` from (that of a link)."""


def covering(box: shapely.Geometry, geoms: np.ndarray) -> np.ndarray:
    """Minus the measure of how much ``box`` covers each of ``geoms`` (all touching it): 0.3 × the length
    it covers, or 0.3 × twice the square root of the area, at most 2."""
    inter = shapely.intersection(box, geoms)
    area = shapely.area(inter)
    covered = np.where(area > 0.0, 2.0 * np.sqrt(area), shapely.length(inter))
    return -np.minimum(2.0, 0.3 * covered)


def rect_covering(a: Sequence[float], b: Sequence[float]) -> float:
    """:func:`covering` of two axis-parallel rectangles that touch (bounds x0, y0, x1, y1), in closed form: GEOS
    clips one by the other to the rectangle of their common bounds, whose area is the product of its sides (an
    edge or a corner in common: a line of that length, a point).

    >>> box = shapely.box(0.0, 0.0, 4.0, 2.0)
    >>> for b in [(3.0, 1.0, 6.0, 5.0), (4.0, 0.5, 6.0, 1.0), (0.0, 0.0, 0.5, 0.25), (4.0, 2.0, 5.0, 3.0), (5.0, 0.0, 6.0, 1.0)]:
    ...     assert rect_covering(box.bounds, b) == covering(box, np.array([shapely.box(*b)]))[0]
    >>> rect_covering((0.0, 0.0, 4.0, 2.0), (3.0, 1.0, 6.0, 5.0))
    -0.6
    """
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    if w < 0.0 or h < 0.0:                              # apart after all: GEOS's empty intersection
        return -0.0
    covered = 2.0 * math.sqrt(w * h) if w > 0.0 and h > 0.0 else max(w, h)
    return -min(2.0, 0.3 * covered)


def gaps(box: shapely.Geometry, geoms: np.ndarray) -> np.ndarray:
    """Distances from ``box`` to ``geoms``; for those it touches, minus a measure of how much it covers (the
    definition the closed forms follow)."""
    d = shapely.distance(box, geoms)
    hit = d == 0.0
    if hit.any():
        d[hit] = covering(box, geoms[hit])
    return d


@dataclass(frozen=True)
class Boxes:
    """Candidate text boxes (paper mm): centres, half sizes, rotation (as ``shapely.affinity.rotate`` turns
    them), bounds (of the turned box) and each one's owner code; one array each, of one length.

    Examples
    --------
    >>> b = Boxes.aligned(np.array([1.0]), np.array([2.0]), 4.0, 2.0, np.array([0]))
    >>> b.geom(0).bounds
    (-1.0, 1.0, 3.0, 3.0)
    """

    cx: np.ndarray
    cy: np.ndarray
    hw: np.ndarray
    hh: np.ndarray
    cos: np.ndarray
    sin: np.ndarray
    x0: np.ndarray
    y0: np.ndarray
    x1: np.ndarray
    y1: np.ndarray
    owner: np.ndarray

    @staticmethod
    def aligned(cx: np.ndarray, cy: np.ndarray, width: float, height: float, owner: np.ndarray) -> Boxes:
        """Axis-parallel boxes: ``shapely.box(cx - w/2, cy - h/2, cx + w/2, cy + h/2)``'s coordinates."""
        hw, hh = np.full(len(cx), width / 2), np.full(len(cx), height / 2)
        return Boxes(cx, cy, hw, hh, np.ones(len(cx)), np.zeros(len(cx)), cx - hw, cy - hh, cx + hw, cy + hh, owner)

    @staticmethod
    def turned_by(cx: np.ndarray, cy: np.ndarray, width: float, height: float, angle: float,
                  owner: np.ndarray) -> Boxes:
        """Boxes turned by ``angle`` degrees about their centres (:func:`turn`)."""
        if not angle:
            return Boxes.aligned(cx, cy, width, height, owner)
        c, s = turn(angle)
        hw, hh = width / 2, height / 2
        ex, ey = abs(c) * hw + abs(s) * hh, abs(s) * hw + abs(c) * hh
        n = len(cx)
        return Boxes(cx, cy, np.full(n, hw), np.full(n, hh), np.full(n, c), np.full(n, s),
                     cx - ex, cy - ey, cx + ex, cy + ey, owner)

    @staticmethod
    def concat(parts: Sequence[Boxes]) -> Boxes:
        """One set of all ``parts``' boxes, in order."""
        return Boxes(*(np.concatenate([getattr(p, f) for p in parts]) for f in Boxes.__dataclass_fields__))

    def __len__(self) -> int:
        return len(self.cx)

    def take(self, rows: np.ndarray) -> Boxes:
        """The boxes ``rows``."""
        return Boxes(*(getattr(self, f)[rows] for f in Boxes.__dataclass_fields__))

    def slice(self, start: int, stop: int) -> Boxes:
        """The boxes ``start`` to ``stop`` (views, not copies)."""
        return Boxes(*(getattr(self, f)[start:stop] for f in Boxes.__dataclass_fields__))

    @property
    def turned(self) -> np.ndarray:
        """Which boxes are rotated."""
        return self.sin != 0.0

    def geom(self, k: int) -> shapely.Geometry:
        """Box ``k`` as a shapely polygon (for what GEOS measures)."""
        if not self.sin[k]:
            return shapely.box(float(self.x0[k]), float(self.y0[k]), float(self.x1[k]), float(self.y1[k]))
        c, s, w, h = float(self.cos[k]), float(self.sin[k]), float(self.hw[k]), float(self.hh[k])
        x, y = float(self.cx[k]), float(self.cy[k])
        return shapely.Polygon([(x + c * u - s * v, y + s * u + c * v) for u, v in ((w, -h), (w, h), (-w, h), (-w, -h))])

    def to_point(self, px: float | np.ndarray, py: float | np.ndarray) -> np.ndarray:
        """Distance from each box to the point (a turned box measured in its own frame); points given as a
        column (shape (m, 1)) give one row per point."""
        if not self.turned.any():
            return box_point(self.x0, self.y0, self.x1, self.y1, px, py)
        ux, uy = px - self.cx, py - self.cy
        return box_point(-self.hw, -self.hh, self.hw, self.hh, ux * self.cos + uy * self.sin, uy * self.cos - ux * self.sin)


def turn(angle: float) -> tuple[float, float]:
    """Cosine and sine of a rotation by ``angle`` degrees, as ``shapely.affinity.rotate`` computes them."""
    a = angle * math.pi / 180.0
    c, s = math.cos(a), math.sin(a)
    return (0.0 if abs(c) < 2.5e-16 else c), (0.0 if abs(s) < 2.5e-16 else s)


def pair_distance(boxes: Boxes, k: np.ndarray, ax: np.ndarray, ay: np.ndarray, bx: np.ndarray, by: np.ndarray,
                  wanted: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distance between box ``k[i]`` and segment i (ends a, b), whether they meet, and the length of the
    segment inside the box (0 where they miss, and where ``wanted`` is False when given). A turned box is
    measured in its own frame (the segment turned back about its centre)."""
    x0, y0, x1, y1 = boxes.x0[k], boxes.y0[k], boxes.x1[k], boxes.y1[k]
    turned = boxes.sin[k] != 0.0
    if turned.any():
        t = np.flatnonzero(turned)
        kt = k[t]
        c, s, cx, cy = boxes.cos[kt], boxes.sin[kt], boxes.cx[kt], boxes.cy[kt]
        ax, ay, bx, by = ax.copy(), ay.copy(), bx.copy(), by.copy()
        x0[t], y0[t], x1[t], y1[t] = -boxes.hw[kt], -boxes.hh[kt], boxes.hw[kt], boxes.hh[kt]
        for px, py in ((ax, ay), (bx, by)):
            ux, uy = px[t] - cx, py[t] - cy
            px[t], py[t] = ux * c + uy * s, uy * c - ux * s
    d, hit = box_segment(x0, y0, x1, y1, ax, ay, bx, by)
    inside = np.zeros(len(d))
    h = np.flatnonzero(hit if wanted is None else hit & wanted)
    if len(h):
        inside[h] = inside_length(x0[h], y0[h], x1[h], y1[h], ax[h], ay[h], bx[h], by[h])
    return d, hit, inside


@dataclass(frozen=True)
class Measured:
    """The clearances of some boxes from one layer: ``known`` what the closed forms give (the least of the
    distances plus allowances, of what a box covers of simple line strings, and :data:`ENOUGH`); ``hi`` and
    ``lo`` bounds that also hold what it covers of the geometries left to GEOS (``pending``: box, geometry
    pairs, by box); ``touching`` whether a box meets anything of the layer; ``cross`` :data:`CROSS` × the
    crossing weights of the geometries each box touches, its own step's included (the score loses it on top of
    the clearance)."""

    known: np.ndarray
    hi: np.ndarray
    lo: np.ndarray
    touching: np.ndarray
    pending: tuple[np.ndarray, np.ndarray]
    cross: np.ndarray | None = None

    def pending_of(self, k: int) -> np.ndarray:
        """The geometries (indices) box ``k`` touches whose covering GEOS computes."""
        rows, parents = self.pending
        lo, hi = np.searchsorted(rows, [k, k + 1])
        return parents[lo:hi]

    def part(self, start: int, stop: int) -> Measured:
        """The clearances of boxes ``start`` to ``stop``, numbered from 0."""
        rows, parents = self.pending
        lo, hi = np.searchsorted(rows, [start, stop])
        return Measured(self.known[start:stop], self.hi[start:stop], self.lo[start:stop], self.touching[start:stop],
                        (rows[lo:hi] - start, parents[lo:hi]), None if self.cross is None else self.cross[start:stop])


def _diagonals(x0: np.ndarray, y0: np.ndarray, x1: np.ndarray, y1: np.ndarray) -> np.ndarray:
    """Line strings from (x0, y0) to (x1, y1): their envelopes are what ``shapely.STRtree`` indexes and
    queries, and they are made faster than boxes."""
    return shapely.linestrings(np.stack([x0, y0, x1, y1], axis=1).reshape(-1, 2, 2))


def _starts(changed: np.ndarray) -> np.ndarray:
    """Where runs begin, from where each element differs from the one before: ``[True, *changed]``."""
    out = np.empty(len(changed) + 1, dtype=bool)
    out[0] = True
    out[1:] = changed
    return out


def least(out: np.ndarray, rows: np.ndarray, values: np.ndarray) -> None:
    """``out[r] = min(out[r], values where rows == r)`` for rows sorted ascending (``np.minimum.at``, faster)."""
    if not len(rows):
        return
    start = np.flatnonzero(_starts(rows[1:] != rows[:-1]))
    r = rows[start]
    out[r] = np.minimum(out[r], np.minimum.reduceat(values, start))


_NONE = np.zeros(0, dtype=np.intp)
_NO = np.zeros(0, dtype=bool)


def _count(cross: np.ndarray, k: np.ndarray, p: np.ndarray, weight: np.ndarray, ng: int) -> None:
    """Add :data:`CROSS` × the weight of each distinct (box ``k``, geometry ``p``) pair to ``cross[k]``."""
    if not len(k):
        return
    pair = np.unique(k * ng + p)
    cross += CROSS * np.bincount(pair // ng, weights=weight[pair % ng], minlength=len(cross))


def _near(cross: np.ndarray, k: np.ndarray, p: np.ndarray, weight: np.ndarray, met: np.ndarray,
          ng: int = 1) -> None:
    """Add :data:`CROSS` × the greatest weight of the geometries ``p`` each box ``k`` comes within :data:`NEAR`
    of without meeting them (``met``: the box, geometry pairs it meets, as box × ``ng`` + geometry) to
    ``cross``: once a box, not once a geometry (a ground's hatch is many strokes); ``met`` sorted ascending."""
    if len(k) and len(met):
        pair = k * ng + p
        at = np.searchsorted(met, pair)                 # ``np.isin``, on the sorted ``met``: faster
        keep = met[np.minimum(at, len(met) - 1)] != pair
        k, p = k[keep], p[keep]
    if len(k):
        np.maximum.at(near := np.zeros(len(cross)), k, weight[p])
        cross += CROSS * near


class Layer:
    """Geometries flattened into segments for measuring: their owners (a box does not keep clear of its own
    step's), allowances (added to their distances), bounds and whether each is an area. Geometries may be
    appended (what is placed, one text after another): a layer built with ``index`` measures many boxes through
    a tree of its segments, one without measures a few boxes against all it holds near
    them.

    Parameters
    ----------
    geoms : sequence of shapely geometries
    owners : sequence of str, optional
        The step that drew each.
    allow : sequence of float, optional
        Added to each one's distance (0 by default).
    weight : sequence of float, optional
        Each one's crossing weight (:data:`CROSS`; 0 by default: not counted).
    own : sequence of float, optional
        Each one's crossing weight for a text of its own step (``weight`` by default; 0 for a point's marker,
        which its label's box never meets: its pairs are then not measured at all).
    halo : sequence of bool, optional
        Whether a box of another step coming within :data:`NEAR` of it counts as crossing it (by default those
        weighing :data:`NEAR_WEIGHT` or more; not an empty area kept out of, as the inside of ω's arc).
    index : bool
        Index the segments in a tree (geometries appended later are not).
    """

    def __init__(self, geoms: Sequence[shapely.Geometry], owners: Sequence[str] | None = None,
                 allow: Sequence[float] | None = None, index: bool = False, weight: Sequence[float] | None = None,
                 own: Sequence[float] | None = None, halo: Sequence[bool] | None = None):
        self.geoms: list[shapely.Geometry] = []
        self.codes: dict[str, int] = {}
        self._parts: list[tuple[np.ndarray, ...]] = []
        self._arrays: tuple[np.ndarray, ...] | None = None
        self._disc_parts: list[tuple[np.ndarray, ...]] = []
        self._discs: tuple[np.ndarray, ...] | None = None
        self._round: dict[int, tuple[float, float, float]] = {}     # a disc's centre and radius, by geometry
        self._simple: dict[int, bool] = {}
        self._rects: dict[int, tuple[float, ...] | None] = {}      # :meth:`_rect`
        self.extend(geoms, owners, allow, weight, own, halo)
        self.tree = None
        self._indexed = 0                                       # segments in the tree (the discs follow)
        if index and len(self.arrays()[0]) + len(self.discs()[0]):
            ax, ay, bx, by = self.arrays()[:4]
            cx, cy, r, _ = self.discs()
            self._indexed = len(ax)
            self.tree = shapely.STRtree(_diagonals(np.concatenate([ax, cx - r]), np.concatenate([ay, cy - r]),
                                                   np.concatenate([bx, cx + r]), np.concatenate([by, cy + r])))

    def code(self, owner: str | None) -> int:
        """The code of an owner's name (-1 for none or one that drew nothing here)."""
        return -1 if owner is None else self.codes.get(owner, -1)

    def append(self, geom: shapely.Geometry) -> None:
        """Add a geometry (not to the tree)."""
        self.extend([geom])

    def extend(self, geoms: Sequence[shapely.Geometry], owners: Sequence[str] | None = None,
               allow: Sequence[float] | None = None, weight: Sequence[float] | None = None,
               own: Sequence[float] | None = None, halo: Sequence[bool] | None = None) -> None:
        """Add geometries (not to the tree)."""
        n0, n = len(self.geoms), len(geoms)
        if not n:
            return
        g = np.empty(n, dtype=object)
        g[:] = list(geoms)
        self.geoms += g.tolist()
        codes = [self.codes.setdefault(o, len(self.codes)) for o in owners] if owners is not None else [-1] * n
        allowed = np.array(allow, dtype=float) if allow is not None else np.zeros(n)
        weighed = np.array(weight, dtype=float) if weight is not None else np.zeros(n)
        mine = np.array(own, dtype=float) if own is not None else weighed
        haloed = np.array(halo, dtype=bool) if halo is not None else weighed >= NEAR_WEIGHT
        round_, cx, cy, r = discs(g)                            # a marker: measured whole, as a circle
        if len(round_):
            self._disc_parts.append((cx, cy, r, round_ + n0))
            self._discs = None
            self._round.update(zip((round_ + n0).tolist(), zip(cx.tolist(), cy.tolist(), r.tolist())))
            g_parts = np.delete(g, round_)
            whole_of = np.delete(np.arange(n), round_)
        else:
            g_parts, whole_of = g, None
        parts, whole = shapely.get_parts(g_parts, return_index=True)
        if whole_of is not None:
            whole = whole_of[whole]
        areal = shapely.get_dimensions(parts) == 2
        lines, owner = parts, whole
        if areal.any():                                         # an area by its rings
            rings, of = shapely.get_rings(parts[areal], return_index=True)
            lines = np.concatenate([parts[~areal], rings])
            owner = np.concatenate([whole[~areal], whole[areal][of]])
        xy, which = shapely.get_coordinates(lines, return_index=True)
        single = (np.bincount(which, minlength=len(lines)) == 1)[which]     # a point: a segment of zero length
        same = which[1:] == which[:-1]
        a = np.concatenate([xy[:-1][same], xy[single]])
        b = np.concatenate([xy[1:][same], xy[single]])
        parent = np.concatenate([owner[which[1:][same]], owner[which[single]]]) + n0
        types = shapely.get_type_id(g)
        simple = np.where((types == 0) | ((types == 1) & (shapely.get_num_coordinates(g) <= 2)), 1, -1)
        simple[shapely.get_dimensions(g) == 2] = 0              # an area: what a box covers of it by GEOS
        simple[(types > 1) & (types != 3)] = 0
        simple[round_] = 1                                      # a disc: what a box covers of it in closed form
        ringed = shapely.get_dimensions(g) == 2
        ringed[round_] = False
        self._parts.append((a[:, 0].copy(), a[:, 1].copy(), b[:, 0].copy(), b[:, 1].copy(), parent,
                            np.array(codes, dtype=np.intp), allowed, shapely.bounds(g).reshape(-1, 4),
                            ringed, simple.astype(np.int8), weighed, mine, haloed))
        self._arrays = None

    def arrays(self) -> tuple[np.ndarray, ...]:
        """The segments' ends (ax, ay, bx, by) and geometry, and the geometries' owner codes, allowances, bounds,
        whether each is an area, and whether each is a simple line string or point (1), not (0) or not yet
        known (-1), their crossing weights (for other steps' texts, and for their own step's), and whether a box
        within :data:`NEAR` of each crosses it."""
        if self._arrays is None:
            if not self._parts:
                z = np.zeros(0)
                self._arrays = (z, z, z, z, _NONE, _NONE, z, np.zeros((0, 4)), np.zeros(0, dtype=bool),
                                np.zeros(0, dtype=np.int8), z, z, np.zeros(0, dtype=bool))
            else:
                self._arrays = tuple(np.concatenate(c) for c in zip(*self._parts))
                self._parts = [self._arrays]
        return self._arrays

    def discs(self) -> tuple[np.ndarray, ...]:
        """The discs' (:func:`.boxdisc.discs`) centres (cx, cy), radii and geometry."""
        if self._discs is None:
            if not self._disc_parts:
                z = np.zeros(0)
                self._discs = (z, z, z, _NONE)
            else:
                self._discs = tuple(np.concatenate(c) for c in zip(*self._disc_parts))
                self._disc_parts = [self._discs]
        return self._discs

    def _simple_of(self, parents: np.ndarray) -> np.ndarray:
        """Whether each geometry of ``parents`` is simple (what a box covers of it is the sum of what it covers of
        its segments): points and line strings that do not overlap themselves."""
        simple = self.arrays()[9]
        of = simple[parents]
        if (of < 0).any():                                  # not yet known: GEOS says, once
            unknown = np.unique(parents[of < 0])
            geoms = np.empty(len(unknown), dtype=object)
            geoms[:] = [self.geoms[i] for i in unknown.tolist()]
            simple[unknown] = shapely.is_simple(geoms)
            of = simple[parents]
        return of == 1

    def pairs(self, boxes: Boxes) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(box, segment or disc) pairs, sorted by box, whose bounds come within :data:`REACH` of each other (by
        the tree, or each box's bounds against those of the segments and discs of the geometries near all the
        boxes: a pair farther apart cannot lower a clearance below :data:`ENOUGH`, nor meet), not of a box's own
        step unless counted (a crossing weight): box ``k``, segment ``s`` (a disc's number where ``disc``:
        :meth:`discs`), the geometry of each and whether it is of the box's own step."""
        ax, ay, bx, by, parent, owner, _, bounds, _, _, _, own, _ = self.arrays()
        cx, cy, r, cparent = self.discs()
        if not len(ax) + len(cx) or not len(boxes):
            return _NONE, _NONE, _NONE, _NO, _NO
        if self.tree is not None:
            k, s = self.tree.query(_diagonals(boxes.x0 - REACH, boxes.y0 - REACH, boxes.x1 + REACH, boxes.y1 + REACH))
            disc = s >= self._indexed
            s = np.where(disc, s - self._indexed, s)
        else:
            x0, y0 = boxes.x0.min() - REACH, boxes.y0.min() - REACH
            x1, y1 = boxes.x1.max() + REACH, boxes.y1.max() + REACH
            near = (bounds[:, 0] <= x1) & (x0 <= bounds[:, 2]) & (bounds[:, 1] <= y1) & (y0 <= bounds[:, 3])
            found = []
            for sx0, sy0, sx1, sy1, of in ((np.minimum(ax, bx), np.minimum(ay, by), np.maximum(ax, bx),
                                            np.maximum(ay, by), parent), (cx - r, cy - r, cx + r, cy + r, cparent)):
                s1 = np.flatnonzero(near[of])               # each box, the segments (discs) near it
                if not len(s1):
                    found.append((_NONE, _NONE))
                    continue
                close = ((sx0[s1] <= (boxes.x1 + REACH)[:, None]) & ((boxes.x0 - REACH)[:, None] <= sx1[s1])
                         & (sy0[s1] <= (boxes.y1 + REACH)[:, None]) & ((boxes.y0 - REACH)[:, None] <= sy1[s1]))
                k, j = np.nonzero(close)
                found.append((k, s1[j]))
            (k, s), (kd, sd) = found
            disc = np.zeros(len(k) + len(kd), dtype=bool)
            if len(kd):
                disc[len(k):] = True
                order = np.argsort(np.concatenate([k, kd]), kind="stable")
                k, s, disc = np.concatenate([k, kd])[order], np.concatenate([s, sd])[order], disc[order]
            if not len(k):
                return _NONE, _NONE, _NONE, _NO, _NO
        if disc.any():
            p = np.empty(len(s), dtype=np.intp)
            p[disc], p[~disc] = cparent[s[disc]], parent[s[~disc]]
        else:
            p = parent[s]
        o = owner[p]
        mine = (o == boxes.owner[k]) & (o >= 0)
        keep = ~mine | (own[p] > 0.0)
        return k[keep], s[keep], p[keep], mine[keep], disc[keep]

    def _distances(self, boxes: Boxes, k: np.ndarray, s: np.ndarray, disc: np.ndarray, wanted: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """For each pair (:meth:`pairs`): the distance between its box and its segment or disc, whether they
        meet, and what the box covers of it where ``wanted`` (the length of a segment inside it; of a disc, twice
        the root of the area they share: :func:`covering`'s measure of an area)."""
        ax, ay, bx, by = self.arrays()[:4]
        if not disc.any():
            return pair_distance(boxes, k, ax[s], ay[s], bx[s], by[s], wanted)
        cx, cy, r, _ = self.discs()
        n = len(k)
        d, hit, inside = np.empty(n), np.empty(n, dtype=bool), np.empty(n)
        seg = np.flatnonzero(~disc)
        if len(seg):
            ss = s[seg]
            d[seg], hit[seg], inside[seg] = pair_distance(boxes, k[seg], ax[ss], ay[ss], bx[ss], by[ss],
                                                          wanted[seg])
        round_ = np.flatnonzero(disc)
        kd, sd = k[round_], s[round_]
        px, py = cx[sd], cy[sd]
        x0, y0, x1, y1 = boxes.x0[kd], boxes.y0[kd], boxes.x1[kd], boxes.y1[kd]
        turned = boxes.sin[kd] != 0.0
        if turned.any():                                # a turned box in its own frame: the centre turned back
            t = np.flatnonzero(turned)
            kt = kd[t]
            c, sn = boxes.cos[kt], boxes.sin[kt]
            ux, uy = px[t] - boxes.cx[kt], py[t] - boxes.cy[kt]
            px, py = px.copy(), py.copy()
            px[t], py[t] = ux * c + uy * sn, uy * c - ux * sn
            x0, y0, x1, y1 = x0.copy(), y0.copy(), x1.copy(), y1.copy()
            x0[t], y0[t], x1[t], y1[t] = -boxes.hw[kt], -boxes.hh[kt], boxes.hw[kt], boxes.hh[kt]
        dd, area = box_disc(x0, y0, x1, y1, px, py, r[sd])
        d[round_], hit[round_] = dd, dd == 0.0
        inside[round_] = np.where(wanted[round_], 2.0 * np.sqrt(area), 0.0)
        return d, hit, inside

    def measure(self, boxes: Boxes) -> Measured:
        """The clearances of ``boxes`` from this layer's geometries (not those of a box's own step)."""
        _, _, _, _, _, _, allow, _, _, simple, weight, own, halo = self.arrays()
        n = len(boxes)
        k, s, p, mine, disc = self.pairs(boxes)     # what a box covers: of other steps' geometries not known complex
        d, hit, inside = self._distances(boxes, k, s, disc, ~mine & (simple[p] != 0))
        known = np.full(n, ENOUGH)
        cross = np.zeros(n)
        if mine.any():                                          # its own step's: crossings only
            met = np.flatnonzero(hit & mine)
            _count(cross, k[met], p[met], own, len(self.geoms))
            other = np.flatnonzero(~mine)
            k, p, d, hit, inside = k[other], p[other], d[other], hit[other], inside[other]
        least(known, k, d + allow[p])
        near = np.flatnonzero((d <= NEAR) & halo[p])      # a halo into a link: as crossing it
        nk, np_ = k[near], p[near]
        touching = np.zeros(n, dtype=bool)
        h = np.flatnonzero(hit)
        touching[k[h]] = True
        hk, hp, hin = k[h], p[h], inside[h]
        ck, cp = self._contained(boxes)                        # boxes inside an area, clear of its rings
        if len(ck):
            touching[ck] = True
            hk, hp, hin = np.concatenate([hk, ck]), np.concatenate([hp, cp]), np.concatenate([hin, np.zeros(len(ck))])
        if not len(hk):
            _near(cross, nk, np_, weight, _NONE)
            return Measured(known, known, known, touching, (_NONE, _NONE), cross)
        order = np.argsort(hk * len(self.geoms) + hp, kind="stable")
        hk, hp, hin = hk[order], hp[order], hin[order]
        first = np.flatnonzero(_starts((hk[1:] != hk[:-1]) | (hp[1:] != hp[:-1])))
        gk, gp = hk[first], hp[first]
        cross += CROSS * np.bincount(gk, weights=weight[gp], minlength=n)
        _near(cross, nk, np_, weight, gk * len(self.geoms) + gp, len(self.geoms))
        covered = np.add.reduceat(hin, first)
        simple = self._simple_of(gp)
        least(known, gk[simple], allow[gp[simple]] - np.minimum(2.0, 0.3 * covered[simple]))
        pend_k, pend_p = gk[~simple], gp[~simple]
        if not len(pend_k):
            return Measured(known, known, known, touching, (_NONE, _NONE), cross)
        hi, lo = known.copy(), known.copy()
        least(hi, pend_k, allow[pend_p])
        least(lo, pend_k, allow[pend_p] - 2.0)
        return Measured(known, hi, lo, touching, (pend_k, pend_p), cross)

    def crossing(self, box: shapely.Geometry, owner: str | None) -> float:
        """:data:`CROSS` × the crossing weights of the geometries ``box`` touches, its own step's included (by
        GEOS: the definition :meth:`measure`'s ``cross`` follows)."""
        weight, own, codes, halo = self.arrays()[10], self.arrays()[11], self.arrays()[5], self.arrays()[12]
        mine = (codes == self.code(owner)) & (codes >= 0)
        w = np.where(mine, own, weight)
        idx = np.flatnonzero(w > 0.0)
        if not len(idx):
            return 0.0
        geoms = np.empty(len(idx), dtype=object)
        geoms[:] = [self.geoms[i] for i in idx.tolist()]
        met = shapely.intersects(box, geoms)
        within = shapely.dwithin(box, geoms, NEAR)
        for j, i in enumerate(idx.tolist()):                # a disc: as the circle it stands for
            if i in self._round:
                apart = disc_gap(box, *self._round[i])[0]
                met[j], within[j] = apart <= 0.0, apart <= NEAR
        near = ~met & ~mine[idx] & halo[idx] & within
        return CROSS * (float(w[idx][met].sum()) + float(w[idx][near].max(initial=0.0)))

    def gaps(self, box: shapely.Geometry, idx: np.ndarray) -> np.ndarray:
        """:func:`gaps` of ``box`` and the geometries ``idx``, a disc as the circle it stands for
        (:func:`.boxdisc.disc_gap`): the definition :meth:`measure` follows."""
        out = np.empty(len(idx))
        rest = [j for j, i in enumerate(idx.tolist()) if i not in self._round]
        if rest:
            geoms = np.empty(len(rest), dtype=object)
            geoms[:] = [self.geoms[i] for i in idx[rest].tolist()]
            out[rest] = gaps(box, geoms)
        for j, i in enumerate(idx.tolist()):
            if i in self._round:
                apart, area = disc_gap(box, *self._round[i])
                out[j] = apart if apart > 0.0 else -min(2.0, 0.3 * (2.0 * math.sqrt(area)))
        return out

    def _contained(self, boxes: Boxes) -> tuple[np.ndarray, np.ndarray]:
        """(box, area) pairs, sorted by box, where the box lies within the area's bounds and meets the area (by
        GEOS): a box wholly inside an area meets none of its rings."""
        _, _, _, _, _, owner, _, bounds, areal, _, _, _, _ = self.arrays()
        if not areal.any() or not len(boxes):
            return _NONE, _NONE
        w, h = (boxes.x1 - boxes.x0).min(), (boxes.y1 - boxes.y0).min()
        a = np.flatnonzero(areal & (bounds[:, 2] - bounds[:, 0] >= w) & (bounds[:, 3] - bounds[:, 1] >= h))
        if not len(a):
            return _NONE, _NONE
        ab = bounds[a]
        within = ((ab[None, :, 0] <= boxes.x0[:, None]) & (ab[None, :, 1] <= boxes.y0[:, None])
                  & (boxes.x1[:, None] <= ab[None, :, 2]) & (boxes.y1[:, None] <= ab[None, :, 3]))
        k, j = np.nonzero(within)
        p = a[j]
        keep = (owner[p] != boxes.owner[k]) | (owner[p] < 0)
        k, p = k[keep], p[keep]
        if not len(k):
            return _NONE, _NONE
        geoms = np.empty(len(k), dtype=object)
        geoms[:] = [self.geoms[i] for i in p.tolist()]
        meets = shapely.intersects(np.array([boxes.geom(i) for i in k.tolist()], dtype=object), geoms)
        return k[meets], p[meets]

    def exact(self, box: shapely.Geometry, parents: np.ndarray) -> float:
        """The least of :func:`covering` plus allowance over the geometries ``parents`` (all touching ``box``): an
        axis-parallel box and an axis-parallel rectangle (a text drawn, a slider block) by :func:`rect_covering`,
        anything else by GEOS."""
        if not len(parents):
            return math.inf
        allow = self.arrays()[6]
        rect = _rect_of(box)
        least_ = math.inf
        rest = []
        for i in parents.tolist():
            other = None if rect is None else self._rect(i)
            if other is None:
                rest.append(i)
            else:
                least_ = min(least_, rect_covering(rect, other) + float(allow[i]))
        if rest:
            geoms = np.empty(len(rest), dtype=object)
            geoms[:] = [self.geoms[i] for i in rest]
            least_ = min(least_, float(np.min(covering(box, geoms) + allow[rest])))
        return least_

    def _rect(self, i: int) -> tuple[float, ...] | None:
        """:func:`_rect_of` geometry ``i`` (remembered)."""
        if i not in self._rects:
            self._rects[i] = _rect_of(self.geoms[i])
        return self._rects[i]


class Placed:
    """What was placed, one text after another: axis-parallel text boxes, leaders (two-point line strings) and
    turned text boxes (convex polygons), measured against axis-parallel candidates densely (rectangle to
    rectangle, box to segment: a leader or a side of a turned box, and whether a box's centre lies in a turned
    box), and anything else (then everything, as segments of a :class:`Layer`; so too for turned candidates).
    What a box covers of a placed geometry is left to GEOS (such a box is as bad as one outside the frame)."""

    def __init__(self) -> None:
        self.geoms: list[shapely.Geometry] = []
        self._rects: list[tuple[float, ...]] = []
        self._rect_ids: list[int] = []
        self._rect_at: dict[int, tuple[float, ...]] = {}     # index into :attr:`geoms` → a rectangle's bounds
        self._leaders: list[tuple[float, ...]] = []
        self._leader_bounds: list[tuple[float, ...]] = []
        self._leader_ids: list[int] = []
        self._hulls: list[tuple[np.ndarray, int]] = []     # turned boxes: their corners and index
        self._general = False
        self._others: list[shapely.Geometry] = []            # neither a rectangle nor a leader
        self._others_tree: shapely.STRtree | None = None
        self._arrays: tuple[np.ndarray, ...] | None = None
        self._rect_rows = np.empty((5, 16))                 # the rectangles' bounds and index, grown in place
        self._leader_rows = np.empty((9, 16))               # the segments' bounds, ends and index
        self._hull_edges: list[tuple[np.ndarray, ...]] = []  # each turned box's corners and sides (:func:`_inside`)
        self._hull_bounds: list[tuple[float, ...]] = []       # and its bounds
        self._layer = Layer([])                 # all of it as segments, grown as it is needed (:meth:`_segments`)

    def __len__(self) -> int:
        return len(self.geoms)

    def append(self, geom: shapely.Geometry) -> None:
        """Record a placed geometry."""
        rect = _rect_of(geom)
        if rect is not None:
            self._rects.append(rect)
            self._rect_ids.append(len(self.geoms))
            self._rect_at[len(self.geoms)] = rect
            self._rect_rows = _row(self._rect_rows, len(self._rects) - 1, (*rect, len(self.geoms)))
        elif shapely.get_type_id(geom) == 1 and shapely.get_num_coordinates(geom) == 2:
            ax, ay, bx, by = shapely.get_coordinates(geom).ravel().tolist()
            self._leader(ax, ay, bx, by)
        else:
            corners = _convex_of(geom)
            if corners is None:
                self._general = True
            else:                                           # a turned box: its sides as segments
                self._hulls.append((corners, len(self.geoms)))
                self._hull_bounds.append((*corners.min(axis=0).tolist(), *corners.max(axis=0).tolist()))
                b = np.roll(corners, -1, axis=0)
                self._hull_edges.append((corners[:, 0][:, None], corners[:, 1][:, None],
                                         (b[:, 0] - corners[:, 0])[:, None], (b[:, 1] - corners[:, 1])[:, None]))
                for (ax, ay), (bx, by) in zip(corners.tolist(), b.tolist()):
                    self._leader(ax, ay, bx, by)
            self._others.append(geom)
            self._others_tree = None
        self.geoms.append(geom)
        self._arrays = None

    def _leader(self, ax: float, ay: float, bx: float, by: float) -> None:
        """Record a segment (a leader, a side of a turned box) of the geometry being appended."""
        self._leaders.append((ax, ay, bx, by))
        self._leader_bounds.append((min(ax, bx), min(ay, by), max(ax, bx), max(ay, by)))
        self._leader_ids.append(len(self.geoms))
        self._leader_rows = _row(self._leader_rows, len(self._leaders) - 1,
                                 (*self._leader_bounds[-1], ax, ay, bx, by, len(self.geoms)))

    def _dense(self) -> tuple[np.ndarray, ...]:
        """The rectangles' and the segments' (leaders, sides of turned boxes) bounds side by side (x0, y0, x1,
        y1; the rectangles first), the segments' ends (ax, ay, bx, by) and the index into :attr:`geoms` of each
        of them (from the rows kept as they were appended)."""
        if self._arrays is None:
            r, s = self._rect_rows[:, :len(self._rects)], self._leader_rows[:, :len(self._leaders)]
            bounds = np.concatenate((r[:4], s[:4]), axis=1)
            ids = np.concatenate((r[4], s[8])).astype(np.intp)
            self._arrays = (*bounds, *s[4:8].copy(), ids)
        return self._arrays

    def _segments(self) -> Layer:
        """Everything placed as the segments of a :class:`Layer` (the geometries placed since the last call
        added in one batch: the same layer as one built of them all at once, measuring the same numbers)."""
        done = len(self._layer.geoms)
        if done < len(self.geoms):
            self._layer.extend(self.geoms[done:])
        return self._layer

    def measure(self, boxes: Boxes) -> Measured:
        """The clearances of ``boxes`` from everything placed (pending: box, index into :attr:`geoms`).

        Rectangle to rectangle by their bounds; a box and a leader or a side of a turned box by the closed
        forms, for the pairs whose bounds come within :data:`REACH` (a segment lies within its bounds, so the
        others cannot lower a clearance, nor meet); a box meeting no side of a turned box touches it when its
        centre lies inside (the box then lies wholly inside: the distance to the sides is kept, as a
        :class:`Layer` keeps it for a box inside an area)."""
        if self._general or boxes.sin.any():                   # rare: all of it as segments (a turned candidate)
            return self._segments().measure(boxes)
        n = len(boxes)
        known = np.full(n, ENOUGH)
        px0, py0, px1, py1, ax, ay, bx, by, ids = self._dense()
        nr = len(self._rects)
        if n * len(ids) > 256:      # only what comes near the candidates at all: the rest meets none, nor comes
            reach = 2.0 * REACH     # within REACH of one (the same numbers, from fewer columns)
            near = ((px0 <= boxes.x1.max() + reach) & (boxes.x0.min() - reach <= px1)
                    & (py0 <= boxes.y1.max() + reach) & (boxes.y0.min() - reach <= py1))
            if not near.all():
                cols, lines = np.flatnonzero(near), near[nr:]
                px0, py0, px1, py1, ids = px0[cols], py0[cols], px1[cols], py1[cols], ids[cols]
                ax, ay, bx, by = ax[lines], ay[lines], bx[lines], by[lines]
                nr = int(np.count_nonzero(near[:nr]))
        gx = np.maximum(px0 - boxes.x1[:, None], boxes.x0[:, None] - px1)
        gy = np.maximum(py0 - boxes.y1[:, None], boxes.y0[:, None] - py1)
        touch = (gx <= 0.0) & (gy <= 0.0)
        np.maximum(gx, 0.0, out=gx)
        np.maximum(gy, 0.0, out=gy)
        gx *= gx
        gy *= gy
        gx += gy
        if nr:
            np.minimum(known, np.sqrt(gx[:, :nr].min(axis=1)), out=known)
        if len(ax):
            k, j = np.nonzero(gx[:, nr:] <= REACH * REACH)
            if len(k):
                d, hit = box_segment(boxes.x0[k], boxes.y0[k], boxes.x1[k], boxes.y1[k], ax[j], ay[j], bx[j], by[j])
                least(known, k, d)
                touch[k[~hit], nr + j[~hit]] = False            # their bounds meet, they do not
        k, j = np.nonzero(touch)
        if self._hulls:                                     # boxes inside a turned box; a pair once, in order
            pairs = np.zeros((n, len(self.geoms)), dtype=bool)
            pairs[k, ids[j]] = True
            cx0, cx1, cy0, cy1 = boxes.cx.min(), boxes.cx.max(), boxes.cy.min(), boxes.cy.max()
            for (_, i), edges, (hx0, hy0, hx1, hy1) in zip(self._hulls, self._hull_edges, self._hull_bounds):
                if hx0 <= cx1 and cx0 <= hx1 and hy0 <= cy1 and cy0 <= hy1:     # a centre may lie inside
                    pairs[:, i] |= _inside(*edges, boxes.cx, boxes.cy)
            k, p = np.nonzero(pairs)
            touching = pairs.any(axis=1)
        else:
            p = ids[j]
            touching = touch.any(axis=1)
        if not len(k):
            return Measured(known, known, known, touching, (_NONE, _NONE))
        hi, lo = known.copy(), known.copy()
        np.minimum(hi, 0.0, out=hi, where=touching)
        np.minimum(lo, -2.0, out=lo, where=touching)
        return Measured(known, hi, lo, touching, (k, p))

    def across(self, segments: np.ndarray) -> np.ndarray:
        """Whether each segment (rows of ax, ay, bx, by) meets a placed text box (an axis-parallel rectangle, as
        :func:`.boxgeom.box_segment` decides; a placed geometry of any other kind by GEOS)."""
        out = np.zeros(len(segments), dtype=bool)
        if not len(segments):
            return out
        if self._rects:
            px0, py0, px1, py1 = self._dense()[:4]
            nr = len(self._rects)
            ax, ay, bx, by = (segments[:, i][:, None] for i in range(4))
            near = ((np.minimum(ax, bx) <= px1[None, :nr]) & (px0[None, :nr] <= np.maximum(ax, bx))
                    & (np.minimum(ay, by) <= py1[None, :nr]) & (py0[None, :nr] <= np.maximum(ay, by)))
            k, j = np.nonzero(near)
            if len(k):
                _, hit = box_segment(px0[j], py0[j], px1[j], py1[j], segments[k, 0], segments[k, 1],
                                     segments[k, 2], segments[k, 3])
                out[k[hit]] = True
        if self._others:
            if self._others_tree is None:
                self._others_tree = shapely.STRtree(self._others)
            k, _ = self._others_tree.query(shapely.linestrings(segments.reshape(-1, 2, 2)), predicate="intersects")
            out[k] = True
        return out

    def exact(self, box: shapely.Geometry, parents: np.ndarray) -> float:
        """The least of :func:`covering` over the placed geometries ``parents`` (all touching ``box``): an
        axis-parallel box and a placed text box by :func:`rect_covering`, anything else by GEOS."""
        if not len(parents):
            return math.inf
        rect = _rect_of(box) if self._rect_at else None
        least_ = math.inf
        rest = []
        for i in parents.tolist():
            other = None if rect is None else self._rect_at.get(i)
            if other is None:
                rest.append(self.geoms[i])
            else:
                least_ = min(least_, rect_covering(rect, other))
        if rest:
            geoms = np.empty(len(rest), dtype=object)
            geoms[:] = rest
            least_ = min(least_, float(np.min(covering(box, geoms))))
        return least_


def _convex_of(geom: shapely.Geometry) -> np.ndarray | None:
    """The corners (rows of x, y, in ring order, the closing one left out) of a convex polygon without holes, all
    its turns one way (a turned text box); None for anything else.

    >>> _convex_of(shapely.Polygon([(0, 0), (2, 1), (1, 3), (-1, 2)])).tolist()
    [[0.0, 0.0], [2.0, 1.0], [1.0, 3.0], [-1.0, 2.0]]
    >>> _convex_of(shapely.Polygon([(0, 0), (2, 0), (1, 1), (2, 2), (0, 2)])) is None
    True
    """
    if shapely.get_type_id(geom) != 3 or shapely.get_num_interior_rings(geom):
        return None
    xy = shapely.get_coordinates(geom)[:-1]
    if len(xy) < 3:
        return None
    e = np.roll(xy, -1, axis=0) - xy
    turns = e[:, 0] * np.roll(e[:, 1], -1) - e[:, 1] * np.roll(e[:, 0], -1)
    return xy if (turns > 0.0).all() or (turns < 0.0).all() else None


def _within(corners: np.ndarray, px: np.ndarray, py: np.ndarray) -> np.ndarray:
    """Whether each point lies in the convex polygon of ``corners`` (:func:`_convex_of`), its boundary included.

    >>> _within(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]), np.array([1.0, 3.0]), np.array([0.5, 0.5])).tolist()
    [True, False]
    """
    a, b = corners, np.roll(corners, -1, axis=0)
    side = ((b[:, 0] - a[:, 0])[:, None] * (py[None, :] - a[:, 1][:, None])
            - (b[:, 1] - a[:, 1])[:, None] * (px[None, :] - a[:, 0][:, None]))
    return (side >= 0.0).all(axis=0) | (side <= 0.0).all(axis=0)


def _inside(ax: np.ndarray, ay: np.ndarray, ex: np.ndarray, ey: np.ndarray, px: np.ndarray, py: np.ndarray
            ) -> np.ndarray:
    """:func:`_within` from a polygon's corners (``ax``, ``ay``) and sides (``ex``, ``ey``: to the next corner),
    as columns: the same numbers.

    >>> sq = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]])
    >>> e = np.roll(sq, -1, axis=0) - sq
    >>> _inside(sq[:, :1], sq[:, 1:], e[:, :1], e[:, 1:], np.array([1.0, 3.0]), np.array([0.5, 0.5])).tolist()
    [True, False]
    """
    side = ex * (py - ay) - ey * (px - ax)
    return (side >= 0.0).all(axis=0) | (side <= 0.0).all(axis=0)


def _row(rows: np.ndarray, i: int, values: tuple[float, ...]) -> np.ndarray:
    """``rows`` with column ``i`` set to ``values`` (twice as many columns when full)."""
    if i == rows.shape[1]:
        rows = np.concatenate((rows, np.empty_like(rows)), axis=1)
    rows[:, i] = values
    return rows


def _rect_of(geom: shapely.Geometry) -> tuple[float, float, float, float] | None:
    """The bounds of an axis-parallel rectangle as ``shapely.box`` makes them (one ring of four distinct corners
    on its bounds, each side parallel to an axis); None for anything else."""
    if type(geom) is not shapely.Polygon:
        return None
    xy = shapely.get_coordinates(geom).tolist()
    if len(xy) != 5:                                    # a hole would add coordinates
        return None
    xs, ys = [p[0] for p in xy], [p[1] for p in xy]
    x0, y0, x1, y1 = min(xs), min(ys), max(xs), max(ys)     # its bounds
    if x0 == x1 or y0 == y1:
        return None
    if any((x != x0 and x != x1) or (y != y0 and y != y1) for x, y in xy):
        return None
    if not all((xy[i][0] == xy[i + 1][0]) != (xy[i][1] == xy[i + 1][1]) for i in range(4)):
        return None
    return x0, y0, x1, y1
