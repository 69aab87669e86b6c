"""Placing labels off the lines: greedy, deterministic, in step order.

For each text, candidate boxes are tried (sixteen directions around its anchor at a few distances, or the
explicit candidates of a dimension text) and the one with the largest clearance from the drawn strokes,
markers, texts and the labels placed before wins. Clearances above :data:`ENOUGH` count as equal, so a
label with room to spare takes its preferred direction; small penalties favour near and preferred
positions among equally free ones.

Examples
--------
>>> p = Placer([(shapely.LineString([(0, 5), (10, 5)]), "line", 0.0)], (0.0, 0.0, 10.0, 10.0))
>>> cx, cy = p.place(Request((5.0, 5.0), 2.0, 2.0, 0.5, math.pi / 2), "pt")
>>> cy > 6.0                                   # below the line on paper, off it
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
import shapely
from shapely import affinity

XY = tuple[float, float]

ENOUGH = 1.6
"""Clearance (paper mm) beyond which a candidate position counts as free."""

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


def _gaps(box: shapely.Geometry, geoms: np.ndarray) -> np.ndarray:
    """Distances from ``box`` to ``geoms``; for those it touches, minus a measure of how much it covers."""
    d = shapely.distance(box, geoms)
    hit = d == 0.0
    if hit.any():
        inter = shapely.intersection(box, geoms[hit])
        area = shapely.area(inter)
        covered = np.where(area > 0.0, 2.0 * np.sqrt(area), shapely.length(inter))
        d[hit] = -np.minimum(2.0, 0.3 * covered)
    return d


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
        self._geoms = np.array([g for g, _, _ in obstacles], dtype=object)
        self._owners = np.array([o for _, o, _ in obstacles], dtype=object)
        self._allow = np.array([a for _, _, a in obstacles], dtype=float)
        self._tree = shapely.STRtree(self._geoms) if len(self._geoms) else None
        self._placed: list[shapely.Geometry] = []
        self._frame = frame

    def clearance(self, box: shapely.Geometry, owner: str) -> float:
        """Distance (capped at :data:`ENOUGH`) from ``box`` to every obstacle not owned by ``owner`` (plus its
        allowance) and to everything placed so far; negative when the box covers something, the more the
        more it covers (so that among crowded places the least covered wins)."""
        best = ENOUGH
        x0, y0, x1, y1 = box.bounds
        near = shapely.box(x0 - ENOUGH, y0 - ENOUGH, x1 + ENOUGH, y1 + ENOUGH)
        if self._tree is not None:
            idx = self._tree.query(near)
            idx = np.sort(idx[self._owners[idx] != owner])
            if len(idx):
                best = min(best, float(np.min(_gaps(box, self._geoms[idx]) + self._allow[idx])))
        if self._placed:
            best = min(best, float(np.min(_gaps(box, np.array(self._placed, dtype=object)))))
        return best

    def _score(self, req: Request, owner: str, centre: XY, penalty: float) -> float:
        box = req.box(*centre)
        x0, y0, x1, y1 = box.bounds
        f = self._frame
        outside = 0.0 if f[0] <= x0 and f[1] <= y0 and x1 <= f[2] and y1 <= f[3] else 50.0
        return self.clearance(box, owner) - penalty - outside

    def _centres(self, req: Request) -> list[tuple[XY, float]]:
        if req.candidates:
            return [(c, req.spread * i) for i, c in enumerate(req.candidates)]
        out = []
        for j, extra in enumerate(DISTANCES):
            for rank, a in enumerate(directions(req.prefer)):
                ux, uy = math.cos(a), math.sin(a)
                reach = req.gap + extra + half_extent(ux, uy, req.width, req.height)
                out.append(((req.anchor[0] + ux * reach, req.anchor[1] + uy * reach),
                            FAR_PENALTY * j + req.spread * rank))
        return out

    def best(self, req: Request, owner: str) -> tuple[XY, float]:
        """The centre of the best box for ``req`` and its score: its clearance less the penalties for
        distance and for leaving the preferred direction (very negative outside the frame)."""
        best, best_score = req.anchor, -math.inf
        for centre, penalty in self._centres(req):
            score = self._score(req, owner, centre, penalty)
            if score > best_score + 1e-12:
                best, best_score = centre, score
        return best, best_score

    def commit(self, geom: shapely.Geometry) -> None:
        """Record something placed (a text's box, a leader line): later texts keep clear of it."""
        self._placed.append(geom)

    def place(self, req: Request, owner: str) -> XY:
        """Place ``req`` at its best position and record it; returns the box centre."""
        centre, _ = self.best(req, owner)
        self.commit(req.box(*centre))
        return centre
