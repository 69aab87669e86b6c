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

from .clearance import ENOUGH, Layer, Measure

XY = tuple[float, float]

DISTANCES = (0.0, 2.0, 4.5, 8.0)
"""Extra distances (paper mm) beyond the gap at which a text is tried, nearest first."""

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
    """

    anchor: XY
    width: float
    height: float
    gap: float
    prefer: float
    spread: float = 0.004
    candidates: tuple[XY, ...] = ()
    rotate: float = 0.0

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
        self._frame = frame

    def _measure(self, boxes: np.ndarray, bounds: np.ndarray, owner: str, aligned: bool) -> Measure:
        return Measure(self._obstacles, self._placed, boxes, bounds, owner, aligned)

    def clearance(self, box: shapely.Geometry, owner: str) -> float:
        """Distance (capped at :data:`ENOUGH`) from ``box`` to every obstacle not owned by ``owner`` (plus its
        allowance) and to everything placed so far; negative when the box covers something, the more the
        more it covers (so that among crowded places the least covered wins)."""
        boxes = np.array([box], dtype=object)
        return self._measure(boxes, shapely.bounds(boxes), owner, False).exact(0)

    def _centres(self, req: Request) -> list[tuple[XY, float]]:
        if req.candidates:
            return [(c, req.spread * i) for i, c in enumerate(req.candidates)]
        out = []
        for j, extra in enumerate(DISTANCES):
            for rank, (ux, uy) in enumerate(_units(req.prefer)):
                reach = req.gap + extra + half_extent(ux, uy, req.width, req.height)
                out.append(((req.anchor[0] + ux * reach, req.anchor[1] + uy * reach),
                            FAR_PENALTY * j + req.spread * rank))
        return out

    def best(self, req: Request, owner: str) -> tuple[XY, float]:
        """The centre of the best box for ``req`` and its score: its clearance less the penalties for
        distance and for leaving the preferred direction (very negative outside the frame).

        The candidates are tried in order; one replaces the best so far when its score is higher by more
        than 1e-12. Only what decides that is scored exactly: a candidate whose upper bound does not beat
        the best so far is passed over, and so is every candidate before one whose lower bound beats all
        their upper bounds (that one replaces the best whatever they score).
        """
        cands = self._centres(req)
        n = len(cands)
        boxes = _boxes(req, [c for c, _ in cands])
        bounds = shapely.bounds(boxes)
        f = self._frame
        inside = (f[0] <= bounds[:, 0]) & (f[1] <= bounds[:, 1]) & (bounds[:, 2] <= f[2]) & (bounds[:, 3] <= f[3])
        cost = [penalty for _, penalty in cands]
        outside = [0.0 if ok else 50.0 for ok in inside.tolist()]
        static = [ENOUGH - penalty - out for penalty, out in zip(cost, outside)]
        reach = list(itertools.accumulate(reversed(static), max))[::-1]      # the best static bound from i on
        lower: list[float] = []
        upper: list[float] = []
        where: list[tuple[Measure, int] | None] = []

        def measure(best_score: float) -> None:
            start = len(upper)
            stop = min(n, start + (1 if start == 0 else BATCH))
            todo = [i for i in range(start, stop) if static[i] > best_score + 1e-12]
            m = self._measure(boxes[todo], bounds[todo], owner, not req.rotate) if todo else None
            slot = {i: k for k, i in enumerate(todo)}
            for i in range(start, stop):
                k = slot.get(i)
                if m is None or k is None:       # it cannot beat the best so far, nor any later best
                    lower.append(-math.inf)
                    upper.append(static[i])
                    where.append(None)
                else:
                    lo, hi = m.bounds(k)
                    lower.append(lo - cost[i] - outside[i])
                    upper.append(hi - cost[i] - outside[i])
                    where.append((m, k))

        def sure_winner(i: int, best_score: float) -> int | None:
            """A later candidate that replaces the best whatever the ones from ``i`` to it score."""
            top = max(best_score, upper[i])
            j = i + 1
            while j < n and reach[j] > top + 1e-12:
                if j == len(upper):
                    measure(best_score)
                if lower[j] > top + 1e-12:
                    return j
                top = max(top, upper[j])
                j += 1
            return None

        best, best_score = req.anchor, -math.inf
        i = 0
        while i < n:
            if i == len(upper):
                measure(best_score)
            if upper[i] <= best_score + 1e-12:
                i += 1                           # it cannot win
                continue
            j = sure_winner(i, best_score)
            if j is None and lower[i] < upper[i]:    # it touches something: bound what it covers first
                m, k = where[i]                      # type: ignore[misc]
                lo, hi = m.refine(k)
                lower[i], upper[i] = lo - cost[i] - outside[i], hi - cost[i] - outside[i]
                if upper[i] <= best_score + 1e-12:
                    i += 1
                    continue
            i = i if j is None else j
            m, k = where[i]                      # type: ignore[misc]
            score = m.exact(k) - cost[i] - outside[i]
            if score > best_score + 1e-12:
                best, best_score = cands[i][0], score
            elif j is not None:
                raise AssertionError("a sure winner did not win: its bounds were wrong")
            i += 1
        return best, best_score

    def commit(self, geom: shapely.Geometry) -> None:
        """Record something placed (a text's box, a leader line): later texts keep clear of it."""
        self._placed.append(geom)

    def place(self, req: Request, owner: str) -> XY:
        """Place ``req`` at its best position and record it; returns the box centre."""
        centre, _ = self.best(req, owner)
        self.commit(req.box(*centre))
        return centre


BATCH = 16
"""Candidates measured per batch after the first (the preferred position alone)."""


def _boxes(req: Request, centres: Sequence[XY]) -> np.ndarray:
    """``req.box`` at each centre (the same coordinates; one vectorised call when not rotated)."""
    if req.rotate:
        out = np.empty(len(centres), dtype=object)
        out[:] = [req.box(cx, cy) for cx, cy in centres]
        return out
    c = np.array(centres, dtype=float).reshape(-1, 2)
    hw, hh = req.width / 2, req.height / 2
    return shapely.box(c[:, 0] - hw, c[:, 1] - hh, c[:, 0] + hw, c[:, 1] + hh)


@functools.lru_cache(maxsize=1024)
def _units(prefer: float) -> tuple[XY, ...]:
    """The unit vectors of :func:`directions` around ``prefer``, nearest first."""
    return tuple((math.cos(a), math.sin(a)) for a in directions(prefer))
