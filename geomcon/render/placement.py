"""Placing labels off the lines: greedy, deterministic, in step order.

For each text, candidate boxes are tried (sixteen directions around its anchor at a few distances, or the
explicit candidates of a dimension text) and the one with the largest clearance from the drawn strokes,
markers, texts and the labels placed before wins. Clearances above :data:`ENOUGH` count as equal, so a
label with room to spare takes its preferred direction; small penalties favour near and preferred
positions among equally free ones.

Scoring is bounded (:mod:`.clearance`): the candidates of a text are measured in batches, which gives
bounds of each one's score at once, and only what decides the choice is scored exactly (by shapely, as
:meth:`Placer.clearance` defines the score) — a candidate whose bound cannot beat the best so far is
passed over, and so is every candidate before one whose lower bound beats all their upper bounds. The
choice and its score are those of scoring every candidate in turn.

Examples
--------
>>> p = Placer([(shapely.LineString([(0, 5), (10, 5)]), "line", 0.0)], (0.0, 0.0, 10.0, 10.0))
>>> cx, cy = p.place(Request((5.0, 5.0), 2.0, 2.0, 0.5, math.pi / 2), "pt")
>>> cy > 6.0                                   # below the line on paper, off it
True
"""
from __future__ import annotations

import functools
import itertools
import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
import shapely
from shapely import affinity

from .clearance import ENOUGH, Layer, Measure, Nearby

XY = tuple[float, float]

DISTANCES = (0.0, 2.0, 4.5, 8.0)
"""Extra distances (paper mm) beyond the gap at which a text is tried, nearest first."""

LABEL_DISTANCES = (0.0, 1.0, 2.0, 3.0)
"""The distances tried for a point's label: its box then lies within gap + 3 mm of the point (gap = the
marker's radius + 0.4 mm), so that a reader never takes it for another point's label."""

LABEL_REACH = 6.0
"""The most (paper mm) a point's label box lies from its point, whatever the marker (checked over the
gallery by the tests)."""

AMBIGUOUS = 5.0
"""Score lost by a label's box nearer another point than its own (worse than covering a line, better than
covering a text or leaving the frame)."""

FAR_PENALTY = 0.25
"""Score lost per step of :data:`DISTANCES`."""


@dataclass(frozen=True, slots=True)
class Request:
    """A text box to place (paper mm, y down).

    Parameters
    ----------
    anchor : (float, float)
        The point the text belongs to.
    width, height : float
        The text box.
    gap : float
        Room kept between the anchor and the box.
    prefer : float
        Preferred direction from the anchor (radians, paper orientation).
    spread : float
        Score lost per rank away from the preferred direction (how much the direction matters).
    candidates : tuple of (float, float)
        Explicit box centres to choose from, best first (instead of directions around the anchor).
    rotate : float
        Rotation of the box about its centre, degrees (clockwise as seen).
    distances : tuple of float
        Extra distances (paper mm) beyond the gap at which the box is tried, nearest first (a point's label
        stays near its point: :data:`LABEL_DISTANCES`).
    rivals : tuple of (float, float)
        Other points near the anchor (a point's label): a box nearer one of them than the anchor would be
        read as its label, and loses :data:`AMBIGUOUS`.
    """

    anchor: XY
    width: float
    height: float
    gap: float
    prefer: float
    spread: float = 0.004
    candidates: tuple[XY, ...] = ()
    rotate: float = 0.0
    distances: tuple[float, ...] = DISTANCES
    rivals: tuple[XY, ...] = ()

    def box(self, cx: float, cy: float) -> shapely.Geometry:
        """The box centred at (cx, cy), rotated as the text will be."""
        b = shapely.box(cx - self.width / 2, cy - self.height / 2, cx + self.width / 2, cy + self.height / 2)
        return affinity.rotate(b, self.rotate, origin=(cx, cy)) if self.rotate else b


def directions(prefer: float, n: int = 16) -> list[float]:
    """``n`` directions around the circle (radians, paper orientation), nearest to ``prefer`` first; of two
    equally near, the one counter-clockwise as seen (upwards on paper) first.

    Examples
    --------
    >>> [round(math.degrees(a)) for a in directions(0.0, 4)]
    [0, -90, 90, 180]
    """
    step = 2 * math.pi / n
    base = round(prefer / step)
    ks = [0]
    for k in range(1, n // 2):
        ks += [-k, k]
    ks.append(n // 2)
    return [math.atan2(math.sin((base + k) * step), math.cos((base + k) * step)) for k in ks]


def half_extent(ux: float, uy: float, w: float, h: float) -> float:
    """Distance from the centre of a w × h box to its boundary along the unit direction (ux, uy).

    Examples
    --------
    >>> half_extent(1.0, 0.0, 4.0, 2.0), half_extent(0.0, 1.0, 4.0, 2.0)
    (2.0, 1.0)
    """
    tx = (w / 2) / abs(ux) if abs(ux) > 1e-12 else math.inf
    ty = (h / 2) / abs(uy) if abs(uy) > 1e-12 else math.inf
    return min(tx, ty)


def nearer_rival(req: Request, boxes: np.ndarray) -> list[bool]:
    """Whether each of ``boxes`` lies nearer one of ``req.rivals`` than its anchor (a label read as
    another point's).

    >>> r = Request((0.0, 0.0), 2.0, 2.0, 0.5, 0.0, rivals=((6.0, 0.0),))
    >>> nearer_rival(r, shapely.box([1.0, 4.0], [-1.0, -1.0], [3.0, 5.5], [1.0, 1.0]))
    [False, True]
    """
    if not req.rivals or not len(boxes):
        return [False] * len(boxes)
    own = shapely.distance(boxes, shapely.Point(req.anchor))
    other = np.min(shapely.distance(np.asarray(boxes)[:, None], shapely.points(np.array(req.rivals))[None, :]), axis=1)
    return (other < own).tolist()


class Placer:
    """Greedy text placement against fixed obstacles (shapely geometries in paper mm).

    Parameters
    ----------
    obstacles : sequence of (geometry, owner, allowance)
        Drawn strokes, markers and texts. ``owner`` tags the step that drew it (a label ignores its own
        point's marker); ``allowance`` is added to the distance, so that crossing a thin, light
        construction line (allowance > 0) costs less than touching a link.
    frame : (x0, y0, x1, y1)
        Texts must stay inside this paper box.
    """

    def __init__(self, obstacles: Sequence[tuple[shapely.Geometry, str, float]],
                 frame: tuple[float, float, float, float]):
        self._obstacles = Layer([g for g, _, _ in obstacles], [o for _, o, _ in obstacles],
                                [a for _, _, a in obstacles], split=True)
        self._placed = Layer([])
        self._boxes: list[shapely.Geometry] = []
        self._tree: shapely.STRtree | None = None
        self._frame = frame

    def covers_placed(self, boxes: np.ndarray) -> np.ndarray:
        """Whether each of ``boxes`` meets a text box or leader placed before (such a place is as bad as
        one outside the frame: two texts never print on top of each other while any other place is left)."""
        out = np.zeros(len(boxes), dtype=bool)
        if self._boxes and len(boxes):
            if self._tree is None:
                self._tree = shapely.STRtree(self._boxes)
            hit = self._tree.query(boxes, predicate="intersects")[0]
            out[hit] = True
        return out

    def _near(self, bounds: np.ndarray, owner: str) -> tuple[tuple[Layer, Nearby], ...]:
        """What may come near each of the boxes ``bounds``: obstacles not ``owner``'s, placed geometries."""
        return (self._obstacles, self._obstacles.near(bounds, owner)), (self._placed, self._placed.near(bounds, None))

    def clearance(self, box: shapely.Geometry, owner: str) -> float:
        """Distance (capped at :data:`ENOUGH`) from ``box`` to every obstacle not owned by ``owner`` (plus its
        allowance) and to everything placed so far; negative when the box covers something, the more the
        more it covers (so that among crowded places the least covered wins)."""
        boxes = np.array([box], dtype=object)
        bounds = shapely.bounds(boxes)
        return Measure(boxes, bounds, [(layer, *near.pairs([0])) for layer, near in self._near(bounds, owner)],
                       False).exact(0)

    def best(self, req: Request, owner: str) -> tuple[XY, float]:
        """The centre of the best box for ``req`` and its score: its clearance less the penalties for
        distance and for leaving the preferred direction (very negative outside the frame).

        The candidates are tried in order; one replaces the best so far when its score is higher by more
        than 1e-12. Only what decides that is scored exactly (see :class:`_Scan`).
        """
        return _Scan(self, req, owner).run()

    def commit(self, geom: shapely.Geometry) -> None:
        """Record something placed (a text's box, a leader line): later texts keep clear of it."""
        self._placed.append(geom)
        self._boxes.append(geom)
        self._tree = None

    def place(self, req: Request, owner: str) -> XY:
        """Place ``req`` at its best position and record it; returns the box centre."""
        centre, _ = self.best(req, owner)
        self.commit(req.box(*centre))
        return centre


class _Scan:
    """The candidates of one text, measured a batch at a time (:data:`BATCH`), and the choice among them.

    Each measured candidate has a lower and an upper bound of its score (equal when its box touches
    nothing); one not measured, its static bound (:data:`ENOUGH` less its penalties). A candidate whose
    upper bound does not beat the best so far is passed over, and so is every candidate before one whose
    lower bound beats all their upper bounds (that one replaces the best whatever they score); a touching
    candidate's bounds are tightened before its exact score is computed.
    """

    def __init__(self, placer: Placer, req: Request, owner: str):
        self.anchor = req.anchor
        self.centres, self.cost = _centres(req)
        self.n = len(self.centres)
        self.boxes = _boxes(req, self.centres)
        self.bounds = shapely.bounds(self.boxes)
        f, b = placer._frame, self.bounds
        inside = (f[0] <= b[:, 0]) & (f[1] <= b[:, 1]) & (b[:, 2] <= f[2]) & (b[:, 3] <= f[3])
        inside &= ~placer.covers_placed(self.boxes)
        self.outside = [0.0 if ok else 50.0 for ok in inside.tolist()]
        if req.rivals:
            self.outside = [o + (AMBIGUOUS if bad else 0.0) for o, bad in zip(self.outside, nearer_rival(req, self.boxes))]
        self.static = [ENOUGH - penalty - out for penalty, out in zip(self.cost, self.outside)]
        self.reach = list(itertools.accumulate(reversed(self.static), max))[::-1]   # the best static from i on
        self.near = placer._near(self.bounds, owner)
        self.aligned = not req.rotate
        self.lower: list[float] = []
        self.upper: list[float] = []
        self.where: list[tuple[Measure, int] | None] = []

    def measure(self, best_score: float) -> None:
        """Measure the next batch: those that can still beat ``best_score``."""
        start = len(self.upper)
        stop = min(self.n, start + BATCH)
        todo = [i for i in range(start, stop) if self.static[i] > best_score + 1e-12]
        m = Measure(self.boxes[todo], self.bounds[todo], [(layer, *nb.pairs(todo)) for layer, nb in self.near],
                    self.aligned) if todo else None
        slot = {i: k for k, i in enumerate(todo)}
        for i in range(start, stop):
            k = slot.get(i)
            if m is None or k is None:           # it cannot beat the best so far, nor any later best
                self.lower.append(-math.inf)
                self.upper.append(self.static[i])
                self.where.append(None)
            else:
                lo, hi = m.bounds(k)
                self.lower.append(lo - self.cost[i] - self.outside[i])
                self.upper.append(hi - self.cost[i] - self.outside[i])
                self.where.append((m, k))

    def sure_winner(self, i: int, best_score: float) -> int | None:
        """A later candidate that replaces the best whatever the ones from ``i`` to it score."""
        top = max(best_score, self.upper[i])
        j = i + 1
        while j < self.n and self.reach[j] > top + 1e-12:
            if j == len(self.upper):
                self.measure(best_score)
            if self.lower[j] > top + 1e-12:
                return j
            top = max(top, self.upper[j])
            j += 1
        return None

    def run(self) -> tuple[XY, float]:
        """The centre of the best candidate and its score (the anchor and -inf when there is none)."""
        best, best_score = None, -math.inf
        i = 0
        while i < self.n:
            if i == len(self.upper):
                self.measure(best_score)
            if self.upper[i] <= best_score + 1e-12:
                i += 1                           # it cannot win
                continue
            j = self.sure_winner(i, best_score)
            if j is None and self.lower[i] < self.upper[i]:     # it touches something: bound what it covers
                m, k = self.where[i]                            # type: ignore[misc]
                pen, out = self.cost[i], self.outside[i]
                self.upper[i] = m.refine(k, lambda hi: hi - pen - out <= best_score + 1e-12) - pen - out
                if self.upper[i] <= best_score + 1e-12:
                    i += 1
                    continue
            i = i if j is None else j
            m, k = self.where[i]                                # type: ignore[misc]
            score = m.exact(k) - self.cost[i] - self.outside[i]
            if score > best_score + 1e-12:
                best, best_score = i, score
            elif j is not None:
                raise AssertionError("a sure winner did not win: its bounds were wrong")
            i += 1
        return (self.centres[best] if best is not None else self.anchor), best_score


BATCH = 16
"""Candidates measured at once (one distance of the sixteen directions)."""


def _boxes(req: Request, centres: Sequence[XY]) -> np.ndarray:
    """``req.box`` at each centre (the same coordinates; one vectorised call when not rotated)."""
    if req.rotate:
        out = np.empty(len(centres), dtype=object)
        out[:] = [req.box(cx, cy) for cx, cy in centres]
        return out
    c = np.array(centres, dtype=float).reshape(-1, 2)
    hw, hh = req.width / 2, req.height / 2
    return shapely.box(c[:, 0] - hw, c[:, 1] - hh, c[:, 0] + hw, c[:, 1] + hh)


def _centres(req: Request) -> tuple[list[XY], list[float]]:
    """The candidate box centres of ``req`` in the order they are tried, and their penalties: the explicit
    candidates, or the directions of :func:`directions` at each of :data:`DISTANCES` beyond the gap (the
    box's :func:`half_extent` along the direction added), computed as those functions compute them."""
    if req.candidates:
        return list(req.candidates), [req.spread * i for i in range(len(req.candidates))]
    ux, uy = _units(req.prefer)
    ax, ay = np.abs(ux), np.abs(uy)
    with np.errstate(divide="ignore"):
        tx = np.where(ax > 1e-12, (req.width / 2) / ax, math.inf)
        ty = np.where(ay > 1e-12, (req.height / 2) / ay, math.inf)
    reach = (req.gap + np.array(req.distances)[:, None]) + np.minimum(tx, ty)
    cx, cy = req.anchor[0] + ux * reach, req.anchor[1] + uy * reach
    rank = np.arange(len(ux))
    penalty = FAR_PENALTY * np.arange(len(req.distances))[:, None] + req.spread * rank
    return list(zip(cx.ravel().tolist(), cy.ravel().tolist())), penalty.ravel().tolist()


@functools.lru_cache(maxsize=1024)
def _units(prefer: float) -> tuple[np.ndarray, np.ndarray]:
    """The unit vectors of :func:`directions` around ``prefer``, nearest first."""
    a = directions(prefer)
    return np.array([math.cos(t) for t in a]), np.array([math.sin(t) for t in a])
