"""Placing labels off the lines: greedy, deterministic, in step order.

For each text, candidate boxes are tried (sixteen directions around its anchor at a few distances, or the
explicit candidates of a dimension text) and the one with the largest clearance from the drawn strokes,
markers, texts and the labels placed before wins. Clearances above :data:`ENOUGH` count as equal, so a
label with room to spare takes its preferred direction; small penalties favour near and preferred
positions among equally free ones.

Scoring is vectorised (:mod:`.clearance`): :meth:`Placer.prepare` lays out the candidates of every text of a
figure at once (:mod:`.candidates`) and measures them against the fixed drawing in one pass, and each text
then measures its candidates against the few texts and leaders placed before it; only what a candidate covers of an area is left to shapely, computed for
the candidates whose choice it decides. The candidates are tried in order, one replacing the best so far
when its score is higher by more than 1e-12: the choice of scoring every candidate in turn by shapely (the
closed forms agree with GEOS to rounding).

Examples
--------
>>> p = Placer([(shapely.LineString([(0, 5), (10, 5)]), "line", 0.0)], (0.0, 0.0, 10.0, 10.0))
>>> cx, cy = p.place(Request((5.0, 5.0), 2.0, 2.0, 0.5, math.pi / 2), "pt")
>>> cy > 6.0                                   # below the line on paper, off it
True
"""
from __future__ import annotations

import copy
import math
from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np
import shapely
from shapely import affinity

from .candidates import FAR_PENALTY, Candidates, candidates, directions, rivalled
from .clearance import ENOUGH, NEAR_WEIGHT, Boxes, Layer, Measured, Placed, _starts, gaps

XY = tuple[float, float]

DISTANCES = (0.0, 2.0, 4.5, 8.0)
"""Extra distances (paper mm) beyond the gap at which a text is tried, nearest first."""

LABEL_DISTANCES = (0.0, 1.0, 2.0, 3.0)
"""The distances tried for a point's label: its box then lies within gap + 3 mm of the point (gap = the
marker's radius + 0.4 mm), so that a reader never takes it for another point's label."""

LABEL_REACH = 3.0
"""The most (paper mm) a point's label box lies from its point (its centre), whatever the marker (checked over
the gallery by the tests): a label farther off gets a leader."""


def label_distances(gap: float) -> tuple[float, ...]:
    """The distances beyond ``gap`` at which a point's label is tried: those of :data:`LABEL_DISTANCES` that keep
    its box within :data:`LABEL_REACH` of the point, the farthest at that reach (none beyond the gap when the
    marker leaves no room).

    Examples
    --------
    >>> label_distances(0.95), label_distances(1.9), label_distances(3.2)
    ((0.0, 1.0, 2.05), (0.0, 1.1), (0.0,))
    """
    room = round(LABEL_REACH - gap, 9)
    if room <= 0.0:
        return (0.0,)
    return tuple(d for d in LABEL_DISTANCES if d < room - 0.25) + (room,)

LEADER_CROSSING = 3.0
"""Score lost by a box whose leader would cross a link or a pivot symbol: another place is taken where there is
one (worse than an ambiguous label, better than a box outside the frame)."""

VALUE_LEADER_CROSSING = 1.5
"""What a mark's value (a request with leader ``starts``: an angle's value) loses instead of
:data:`LEADER_CROSSING` when its leader would cross a link or a pivot symbol: less than a value crossed by a thin
line loses (its crossing weight, and what it covers), for a value is not to be crossed by any line (ISO 129-1),
while a leader may cross an outline (001-28's α printed across the normal through B, 001-07's αmax on the
construction arc through C3): a link's line, a cam's profile, a roller (the placer's ``outlines``), not a pin,
a ground or a block, which a leader across reads as naming (004-03's θ led through D's ground). A point's label keeps :data:`LEADER_CROSSING`: it stays by its point, across a
ray, rather than go off with a leader (001-24's O among the division rays)."""

TOO_LONG = 12.0
"""Score lost by a box whose leader would be longer than :data:`.candidates.LEADER_MAX`: worse than a leader
across a link, better than a box outside the frame or on a text placed before (which cannot be read)."""

HARD = 2.0
"""The crossing weight of a link or a pivot symbol (a point's marker, a ground): what a leader must not cross."""

ROUND_JOINT = 0.05
"""A closed curve of weight :data:`HARD` centred this near (paper mm) a leader's start is a part drawn round that
joint (a roller): the leader leaves it, as it must, without counting as crossing (not a cam's profile round a
mark's arc)."""

AMBIGUOUS = 15.0
"""Score lost by a label's box nearer another point than its own (worse than covering a line, better than
covering a text or leaving the frame)."""

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
    lead : float
        Distance (paper mm) from the anchor beyond which the text is joined to it by a leader (inf: never). A
        box whose leader would be longer than :data:`.candidates.LEADER_MAX` loses :data:`TOO_LONG`; one whose leader would cross a link or a pivot symbol (an obstacle of crossing weight 2, not of
        the text's own step) loses :data:`LEADER_CROSSING`, and one whose leader would cross a text placed
        before is as bad as one outside the frame.
    starts : tuple of (float, float)
        Where a leader may start (points along a mark's arc; the anchor when empty): the one nearest the box;
        ``lead`` is the distance from it.
    parts : tuple of (float, (float, float))
        A label naming several points (:mod:`.joined`): each printed part's width and its own point, in the
        order of its names. The box is then rivalled when a part lies nearer one of ``rivals`` than its own
        point (not the whole box nearer a rival than the anchor).
    costs : tuple of float
        The penalty of each explicit candidate, when given (instead of ``spread`` per rank): places laid out as
        those around the anchor are, some left out (:func:`.figure._between`).
    rival_reach : float
        A box beyond ``lead`` (joined to its point by a leader) is rivalled only by a point of ``rivals`` within
        this (paper mm) of it (inf: by any nearer than the anchor); nearer its anchor, by any.
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
    lead: float = math.inf
    starts: tuple[XY, ...] = ()
    parts: tuple[tuple[float, XY], ...] = ()
    costs: tuple[float, ...] = ()
    rival_reach: float = math.inf

    def box(self, cx: float, cy: float) -> shapely.Geometry:
        """The box centred at (cx, cy), rotated as the text will be."""
        b = shapely.box(cx - self.width / 2, cy - self.height / 2, cx + self.width / 2, cy + self.height / 2)
        return affinity.rotate(b, self.rotate, origin=(cx, cy)) if self.rotate else b


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


def nearer_rival(req: Request, centres: Sequence[XY]) -> list[bool]:
    """Whether the box of ``req`` centred at each of ``centres`` lies nearer one of ``req.rivals`` than its
    anchor (a label read as another point's).

    >>> r = Request((0.0, 0.0), 2.0, 2.0, 0.5, 0.0, rivals=((6.0, 0.0),))
    >>> nearer_rival(r, [(2.0, 0.0), (4.75, 0.0)])
    [False, True]
    """
    if not req.rivals or not len(centres):
        return [False] * len(centres)
    c = np.array(centres, dtype=float).reshape(-1, 2)
    n = len(c)
    return rivalled([req], np.array([0, n]), np.array([n]), _boxes(req, c[:, 0], c[:, 1], -1)).tolist()


def nudged(leaders: np.ndarray, by: float = 0.3) -> np.ndarray:
    """Leaders (rows of ax, ay, bx, by) without their first ``by`` mm: a leader starting at an end of its arc,
    on a ray of the angle, does not cross that line.

    >>> nudged(np.array([[0.0, 0.0, 2.0, 0.0]])).tolist()
    [[0.3, 0.0, 2.0, 0.0]]
    """
    d = leaders[:, 2:] - leaders[:, :2]
    n = np.hypot(d[:, 0], d[:, 1])[:, None]
    k = np.minimum(by / np.where(n > 0.0, n, 1.0), 1.0)
    return np.concatenate([leaders[:, :2] + d * k, leaders[:, 2:]], axis=1)


class _Batch:
    """The candidates of the texts prepared together (:class:`.Candidates`) and what is known of them: the
    static loss (outside the frame, nearer a rival point), their best possible scores, and the clearances from
    the drawing of those measured so far (NaN for the others; ``pending``: what GEOS is left to compute, by
    candidate). A text's are a slice of these arrays."""

    def __init__(self, c: Candidates, barred: np.ndarray, values: np.ndarray | None = None):
        self.c, self.boxes = c, c.boxes
        self.leading = np.where(c.far, TOO_LONG, 0.0)
        crossing = np.full(len(c.cost), LEADER_CROSSING)
        if values is not None:          # a mark's value (per candidate): :data:`VALUE_LEADER_CROSSING`
            crossing[values] = VALUE_LEADER_CROSSING
        self.leading[c.led[barred]] += crossing[c.led[barred]]
        self.outside = np.where(c.framed, 0.0, 50.0) + np.where(c.rivalled, AMBIGUOUS, 0.0) + self.leading
        self.static = (ENOUGH - c.cost) - self.outside
        self.static_list: list[float] = self.static.tolist()
        self.known, self.hi = np.full(len(c.cost), np.nan), np.full(len(c.cost), np.nan)
        self.cross = np.zeros(len(c.cost))
        self.pending: dict[int, np.ndarray] = {}
        self.starts: list[int] = c.starts.tolist()                          # each text's candidates and led ones
        self.led_starts: list[int] = np.searchsorted(c.led, c.starts).tolist()

    def record(self, rows: np.ndarray, m: Measured) -> None:
        """Keep the clearances ``m`` of the candidates ``rows`` (of the batch)."""
        self.known[rows], self.hi[rows] = m.known, m.hi
        if m.cross is not None:
            self.cross[rows] = m.cross
        pk, pp = m.pending
        if len(pk):
            cut = np.flatnonzero(np.concatenate((_starts(pk[1:] != pk[:-1]), [True])))
            for i, j in zip(cut[:-1].tolist(), cut[1:].tolist()):
                self.pending[int(rows[pk[i]])] = pp[i:j]

    def upper(self) -> list[float]:
        """The best score each candidate may still get: by its clearance from the drawing when measured (NaN
        when not)."""
        return (((self.hi - self.cross) - self.c.cost) - self.outside).tolist()


class _Text:
    """The candidates of one text, a slice of a :class:`_Batch`: penalties, boxes, static loss, best possible
    scores and clearances from the drawing (views of the batch's arrays, numbered from 0).

    The drawing alone already rules candidates out: :meth:`advance` scans them in order with the clearance from
    the drawing as the score (at least the final one: what is placed only lowers it) and stops at the first not
    yet measured that could still win; the candidates it passes over need not be measured at all.
    """

    def __init__(self, batch: _Batch, i: int):
        a, b = batch.starts[i], batch.starts[i + 1]
        self.batch, self.offset, self.n = batch, a, b - a
        c = batch.c
        self.cost, self.framed, self.rivalled = c.cost[a:b], c.framed[a:b], c.rivalled[a:b]
        self.leading = batch.leading[a:b]
        lo, hi = batch.led_starts[i], batch.led_starts[i + 1]
        self.led, self.leader = c.led[lo:hi] - a, c.leader[lo:hi]
        self.boxes = batch.boxes.slice(a, b)
        self.outside, self.static = batch.outside[a:b], batch.static[a:b]
        self.known, self.hi, self.cross = batch.known[a:b], batch.hi[a:b], batch.cross[a:b]
        self._at, self._best, self._waves = 0, -math.inf, 0

    def centre(self, i: int) -> XY:
        """The centre of candidate ``i``."""
        k = self.offset + i
        return self.batch.c.cx[k].item(), self.batch.c.cy[k].item()

    def pending(self, i: int) -> np.ndarray | None:
        """What GEOS is left to compute of candidate ``i`` against the drawing (None: nothing)."""
        return self.batch.pending.get(self.offset + i)

    def unmeasured(self, start: int, best: float, count: int) -> np.ndarray:
        """Up to ``count`` candidates from ``start`` on, not measured yet, that could beat ``best``."""
        rest = np.flatnonzero(np.isnan(self.known[start:]) & (self.static[start:] > best + 1e-12)) + start
        return rest[:count]

    def advance(self, upper: list[float]) -> np.ndarray:
        """Scan on with the drawing's clearances (``upper``: :meth:`_Batch.upper`); the candidates to measure
        next (none when the scan is done)."""
        i, best, o = self._at, self._best, self.offset
        static = self.batch.static_list
        while i < self.n:
            h = upper[o + i]
            if h != h:                                      # not measured
                if static[o + i] > best + 1e-12:
                    break
            elif h > best + 1e-12:
                best = h
            i += 1
        self._at, self._best = i, best
        if i == self.n:
            return _NONE
        self._waves += 1
        return self.unmeasured(i, best, WAVE << (self._waves - 1))


WAVE = 16
"""Candidates of a text measured in the first wave (one distance of the sixteen directions); each later wave
takes twice as many as the one before (fewer waves for a text that needs many)."""

_NONE = np.zeros(0, dtype=np.intp)


class Placer:
    """Greedy text placement against fixed obstacles (shapely geometries in paper mm).

    Parameters
    ----------
    obstacles : sequence of (geometry, owner, allowance[, weight[, own weight[, halo]]])
        Drawn strokes, markers and texts. ``owner`` tags the step that drew it (a text keeps no distance from its
        own step's strokes); ``allowance`` is added to the distance, so that crossing a thin, light
        construction line (allowance > 0) costs less than touching a link; ``weight`` (0 when left out) is its
        crossing weight: a box touching it loses :data:`.clearance.CROSS` × the weight, its own step's too (a
        mark's value across its own arc), so that the box crossing fewest lines wins; ``own weight`` (``weight``
        when left out) is the weight for a text of its own step (0 for a point's marker, never met by its label);
        ``halo`` (weight ≥ :data:`.clearance.NEAR_WEIGHT` when left out) whether a box of another step within
        :data:`.clearance.NEAR` of it crosses it (not an empty area kept out of).
    frame : (x0, y0, x1, y1)
        Texts must stay inside this paper box.
    """

    def __init__(self, obstacles: Sequence[tuple[shapely.Geometry, str, float]],
                 frame: tuple[float, float, float, float], outlines: Sequence[bool] = ()):
        self._fixed = Layer([o[0] for o in obstacles], [o[1] for o in obstacles], [o[2] for o in obstacles],
                            index=True, weight=[o[3] if len(o) > 3 else 0.0 for o in obstacles],
                            own=[o[4] if len(o) > 4 else (o[3] if len(o) > 3 else 0.0) for o in obstacles],
                            halo=[o[5] if len(o) > 5 else (o[3] if len(o) > 3 else 0.0) >= NEAR_WEIGHT
                                  for o in obstacles])
        self._placed = Placed()
        self._frame = frame
        self._ready: dict[tuple[Request, str], _Text] = {}
        self._bars: tuple[shapely.STRtree, np.ndarray, np.ndarray, np.ndarray] | None = None
        self._outlines = np.array([bool(o) for o in outlines] + [False] * (len(obstacles) - len(outlines)), dtype=bool)

    def widened(self, frame: tuple[float, float, float, float]) -> Placer:
        """A placer whose texts may take ``frame``, sharing this one's obstacles and what is placed (what either
        commits, both keep clear of)."""
        other = copy.copy(self)
        other._frame, other._ready = frame, {}
        return other

    def prepare(self, jobs: Sequence[tuple[Request, str]]) -> None:
        """Measure the candidates of every (request, owner) of ``jobs`` against the fixed drawing, in a few
        waves each taking, for every text at once, the next candidates the drawing alone cannot rule out."""
        todo = [j for j in dict.fromkeys(jobs) if j not in self._ready]
        if not todo:
            return
        c = candidates([r for r, _ in todo], [self._fixed.code(o) for _, o in todo], self._frame)
        values = np.repeat([bool(r.starts) for r, _ in todo], np.diff(c.starts))
        barred, hard = self._barred(c)
        batch = _Batch(c, barred, values & ~np.isin(np.arange(len(c.cost)), c.led[hard]))
        texts = [_Text(batch, i) for i in range(len(todo))]
        self._ready.update(zip(todo, texts))
        while texts:
            upper = batch.upper()
            wave = [(t, t.advance(upper)) for t in texts]
            wave = [(t, rows) for t, rows in wave if len(rows)]
            self._measure(batch, wave)
            texts = [t for t, _ in wave]

    def bound(self, req: Request, owner: str) -> float:
        """The highest score :meth:`best` can give ``req`` (prepared if need be): its best candidate's against the
        fixed drawing alone (what is placed later only lowers a score; within 1e-12). A text whose bound is
        already below a threshold surely takes its fallback, which can then be prepared with the others."""
        self.prepare([(req, owner)])
        t = self._ready[req, owner]
        return t._best + 1e-12 if t.n else -math.inf

    def _barred(self, c: Candidates) -> tuple[np.ndarray, np.ndarray]:
        """Whether the leader of each led candidate of ``c`` crosses a link or a pivot symbol (an obstacle of
        weight :data:`HARD`) not of its text's own step, nor a part drawn round its start (an area holding it: a
        slider block on its joint; a closed curve centred within :data:`ROUND_JOINT` of it: a roller round its
        centre): one query of a tree of them for all. Also whether it crosses one that is not an outline (a pin, a
        ground, a block: not one of ``outlines``), which a mark's value's leader may not cross more cheaply
        (:data:`VALUE_LEADER_CROSSING`)."""
        out = np.zeros(len(c.led), dtype=bool)
        if not len(c.led):
            return out, out
        if self._bars is None:
            weight, codes = self._fixed.arrays()[10], self._fixed.arrays()[5]
            idx = np.flatnonzero(weight >= HARD)
            geoms = np.empty(len(idx), dtype=object)
            geoms[:] = [self._fixed.geoms[i] for i in idx.tolist()]
            rings = (shapely.get_type_id(geoms) == 1) & shapely.is_closed(geoms)      # a roller's circle
            centres = np.full((len(geoms), 2), np.nan)
            if rings.any():
                centres[rings] = [shapely.Polygon(g.coords).centroid.coords[0] for g in geoms[rings]]
            shapely.prepare(geoms)          # a cam's profile indexed once, not walked for each leader
            self._bars = (shapely.STRtree(geoms), codes[idx], centres, self._outlines[idx])
        tree, codes, centres, outline = self._bars
        lines = shapely.linestrings(nudged(c.leader).reshape(-1, 2, 2))
        k, j = tree.query(lines)                            # bounds that meet; then the prepared bar meets it
        met = shapely.intersects(tree.geometries[j], lines[k])
        k, j = k[met], j[met]
        mine = codes[j] == c.boxes.owner[c.led[k]]
        if len(j):          # an area round the leader's start (a slider block on its joint), a closed curve
            # centred there (a roller round its centre) is left, not crossed
            ax, ay = c.leader[k, 0], c.leader[k, 1]
            mine |= shapely.contains_xy(tree.geometries[j], ax, ay)
            mine |= np.hypot(centres[j, 0] - ax, centres[j, 1] - ay) <= ROUND_JOINT
        out[k[~mine]] = True
        hard = np.zeros(len(c.led), dtype=bool)
        hard[k[~mine & ~outline[j]]] = True
        return out, hard

    def _measure(self, batch: _Batch, wave: list[tuple[_Text, np.ndarray]]) -> None:
        """Measure the candidates ``rows`` of each text of ``wave`` (all of ``batch``) against the drawing, in one
        pass."""
        if not wave:
            return
        rows = np.concatenate([t.offset + r for t, r in wave])
        batch.record(rows, self._fixed.measure(batch.boxes.take(rows)))

    def clearance(self, box: shapely.Geometry, owner: str) -> float:
        """Distance (capped at :data:`ENOUGH`) from ``box`` to every obstacle not owned by ``owner`` (plus its
        allowance) and to everything placed so far; negative when the box covers something, the more the
        more it covers (so that among crowded places the least covered wins); less :data:`.clearance.CROSS` ×
        the crossing weight of every obstacle it touches, its own step's included. By shapely: the definition
        the placer's closed forms follow."""
        best = ENOUGH
        codes, allow = self._fixed.arrays()[5:7]
        keep = np.flatnonzero(codes != self._fixed.code(owner))
        if len(keep):                                   # a marker's disc as the circle it stands for
            best = min(best, float(np.min(self._fixed.gaps(box, keep) + allow[keep])))
        if self._placed.geoms:
            g = np.empty(len(self._placed.geoms), dtype=object)
            g[:] = self._placed.geoms
            best = min(best, float(np.min(gaps(box, g))))
        return best - self._fixed.crossing(box, owner)

    def best(self, req: Request, owner: str) -> tuple[XY, float]:
        """The centre of the best box for ``req`` and its score: its clearance less the penalties for
        distance and for leaving the preferred direction (very negative outside the frame or on a text placed
        before); the anchor and -inf when there is no candidate.

        The candidates are tried in order; one replaces the best so far when its score is higher by more
        than 1e-12. What a candidate covers of an area is computed (by shapely) only when it decides that.
        """
        self.prepare([(req, owner)])
        t = self._ready[req, owner]
        placed = self._placed.measure(t.boxes) if len(self._placed) else None
        outside = t.outside
        blocked = None if placed is None else placed.touching
        if len(t.led) and len(self._placed):                   # a leader across a text placed before
            across = self._placed.across(nudged(t.leader))
            if across.any():
                blocked = blocked.copy()
                blocked[t.led[across]] = True
        if blocked is not None and blocked.any():               # on a text placed before: as bad as outside
            outside = (np.where(t.framed & ~blocked, 0.0, 50.0) + np.where(t.rivalled, AMBIGUOUS, 0.0)
                       + t.leading)
        crossed = set() if placed is None else set(placed.pending[0].tolist())     # boxes covering a placed one
        best, best_score = None, -math.inf
        i = 0
        while i < t.n:
            hi = t.hi if placed is None else np.minimum(t.hi, placed.hi)
            upper = (((hi - t.cross) - t.cost) - outside).tolist()
            static = ((ENOUGH - t.cost) - outside).tolist()
            for i in range(i, t.n):
                u = upper[i]
                if u != u:                                      # not measured: measure what may still win
                    if static[i] > best_score + 1e-12:
                        self._measure(t.batch, [(t, t.unmeasured(i, best_score, t.n))])
                        break
                    continue
                if u <= best_score + 1e-12:
                    continue                                    # it cannot win
                score = u
                drawn = t.pending(i)
                if drawn is not None or i in crossed:
                    box = req.box(*t.centre(i))
                    c = min(float(t.known[i]), self._fixed.exact(box, _NONE if drawn is None else drawn),
                            math.inf if placed is None else float(placed.known[i]),
                            math.inf if placed is None else self._placed.exact(box, placed.pending_of(i)))
                    score = ((c - float(t.cross[i])) - float(t.cost[i])) - float(outside[i])
                if score > best_score + 1e-12:
                    best, best_score = i, score
            else:
                break
        return (t.centre(best) if best is not None else req.anchor), best_score

    def past_rivals(self, req: Request, owner: str, reach: float, floor: float = -math.inf) -> Request | None:
        """``req`` (a point's label with a leader, prepared if need be) with only its candidates that lie nearer
        another point than its own but farther than ``reach`` from it, and may still score more than ``floor``,
        as explicit candidates with their penalties and ``rival_reach`` ``reach`` (:attr:`Request.rival_reach`);
        None when there are none. Its other candidates score as they do for ``req``: only these can do better,
        and only these are measured."""
        self.prepare([(req, owner)])
        t = self._ready[req, owner]
        k = np.flatnonzero(t.rivalled & (t.static + AMBIGUOUS > floor + 1e-12))
        if not len(k):
            return None
        c = t.batch.c
        spots = np.stack([c.cx[t.offset + k], c.cy[t.offset + k]], axis=1)
        wide = replace(req, rival_reach=reach)
        keep = ~np.array(nearer_rival(wide, [tuple(p) for p in spots.tolist()]), dtype=bool)
        if not keep.any():
            return None
        return replace(wide, candidates=tuple(map(tuple, spots[keep].tolist())),
                       costs=tuple(t.cost[k[keep]].tolist()))

    def rivalled(self, req: Request, owner: str, centre: XY) -> bool:
        """:func:`nearer_rival` of the box of ``req`` at ``centre``, read from the candidates already laid out
        when ``centre`` is one of them (as :meth:`best` returns it)."""
        t = self._ready.get((req, owner))
        if t is not None:
            c, a, b = t.batch.c, t.offset, t.offset + t.n
            k = np.flatnonzero((c.cx[a:b] == centre[0]) & (c.cy[a:b] == centre[1]))
            if len(k):
                return bool(t.rivalled[k[0]])
        return nearer_rival(req, [centre])[0]

    def commit(self, geom: shapely.Geometry) -> None:
        """Record something placed (a text's box, a leader line): later texts keep clear of it."""
        self._placed.append(geom)

    def place(self, req: Request, owner: str) -> XY:
        """Place ``req`` at its best position and record it; returns the box centre."""
        centre, _ = self.best(req, owner)
        self.commit(req.box(*centre))
        return centre


def _boxes(req: Request, cx: np.ndarray, cy: np.ndarray, owner: int) -> Boxes:
    """The boxes of ``req`` centred at (cx, cy), turned as the text will be; all of the step ``owner``."""
    return Boxes.turned_by(cx, cy, req.width, req.height, req.rotate, np.full(len(cx), owner, dtype=np.intp))
