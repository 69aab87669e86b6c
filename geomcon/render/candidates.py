"""The candidate boxes of many texts at once: centres, penalties, boxes, and what rules some out before anything
is measured (leaving the frame, lying nearer another point than the text's own).

A text is tried at its explicit centres (a dimension's places, best first) or in the sixteen directions of
:func:`directions` around its anchor at each of its distances beyond the gap (the box's half extent along the
direction added). The texts of one placement pass are laid out together, each text's candidates a slice of
one set of arrays: a few numpy calls for all of them instead of some forty for each. Every number is what
laying out one text at a time gave (the same elementwise operations on the same operands).

Examples
--------
>>> from geomcon.render.placement import Request
>>> c = candidates([Request((0.0, 0.0), 2.0, 1.0, 0.5, 0.0), Request((9.0, 9.0), 2.0, 1.0, 0.5, 0.0,
...                 candidates=((9.0, 7.0), (9.0, 11.0)))], [0, 1], (-50.0, -50.0, 50.0, 50.0))
>>> c.starts.tolist()                            # 16 directions × 4 distances, then the two explicit centres
[0, 64, 66]
>>> c.cx[0].item(), c.cy[0].item(), c.cost[:2].tolist(), c.cx[64:].tolist(), c.cost[64:].tolist()
(1.5, 0.0, [0.0, 0.004], [9.0, 9.0], [0.0, 0.004])
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np

from .boxgeom import box_point
from .clearance import Boxes, turn
from .joined import parts_rivalled

if TYPE_CHECKING:
    from .placement import Request

FAR_PENALTY = 0.25
"""Score lost per step of a text's distances."""

LEADER_MAX = 15.0
"""The longest leader (paper mm): a text joined to its anchor by a leader is never farther from it."""


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


def between(prefer: float, n: int = 16) -> list[float]:
    """The ``n`` directions halfway between those of :func:`directions`, nearest to ``prefer`` first; of two
    equally near, the one counter-clockwise as seen (upwards on paper) first, as there.

    Examples
    --------
    >>> [round(math.degrees(a)) for a in between(0.0, 4)]
    [-45, 45, -135, 135]
    >>> [round(math.degrees(a), 2) for a in between(math.radians(100.0))][:3]
    [101.25, 78.75, 123.75]
    """
    step = 2 * math.pi / n
    out = [math.atan2(math.sin((k + 0.5) * step), math.cos((k + 0.5) * step)) for k in range(n)]

    def off(a: float) -> tuple[float, float]:
        d = math.remainder(a - prefer, 2 * math.pi)
        return round(abs(d), 9), d

    return sorted(out, key=off)


@functools.lru_cache(maxsize=1024)
def _units(prefer: float) -> tuple[np.ndarray, np.ndarray]:
    """The unit vectors of :func:`directions` around ``prefer``, nearest first."""
    a = directions(prefer)
    return np.array([math.cos(t) for t in a]), np.array([math.sin(t) for t in a])


@dataclass(frozen=True)
class Candidates:
    """The candidates of several texts, text after text: text ``i``'s are ``starts[i]:starts[i + 1]``.

    ``cx, cy`` the box centres, ``cost`` the penalties for distance and direction, ``boxes`` the boxes (turned as
    the text is, owned by the text's step), ``framed`` whether a box lies inside the frame, ``rivalled``
    whether it lies nearer another point than the text's anchor; ``led`` the candidates that would be joined to
    their anchor by a leader (a request's ``lead``), ``leader`` its segment from the anchor to the nearest point of
    the box (ax, ay, bx, by, one row per led candidate), ``far`` whether that leader would be longer than
    :data:`LEADER_MAX`."""

    cx: np.ndarray
    cy: np.ndarray
    cost: np.ndarray
    boxes: Boxes
    framed: np.ndarray
    rivalled: np.ndarray
    starts: np.ndarray
    led: np.ndarray
    leader: np.ndarray
    far: np.ndarray


def candidates(reqs: Sequence[Request], owners: Sequence[int], frame: tuple[float, float, float, float]
               ) -> Candidates:
    """The candidates of every request of ``reqs`` (each owned by the step coded in ``owners``), in order."""
    m = len(reqs)
    counts = np.array([len(r.candidates) if r.candidates else 16 * len(r.distances) for r in reqs], dtype=np.intp)
    starts = np.zeros(m + 1, dtype=np.intp)
    np.cumsum(counts, out=starts[1:])
    n = int(starts[-1])
    cx, cy, cost = np.empty(n), np.empty(n), np.empty(n)
    _explicit(reqs, starts, counts, cx, cy, cost)
    _around(reqs, starts, cx, cy, cost)
    per = np.repeat(np.arange(m), counts)
    shape = np.array([_shape(r) for r in reqs]).reshape(-1, 6)[per]     # hw, hh, cos, sin, extents x and y
    ex, ey = shape[:, 4], shape[:, 5]
    boxes = Boxes(cx, cy, shape[:, 0], shape[:, 1], shape[:, 2], shape[:, 3], cx - ex, cy - ey, cx + ex, cy + ey,
                  np.array(owners, dtype=np.intp).reshape(-1)[per])
    f = frame
    framed = (f[0] <= boxes.x0) & (f[1] <= boxes.y0) & (boxes.x1 <= f[2]) & (boxes.y1 <= f[3])
    led, leader, far = leaders(reqs, starts, counts, boxes)
    return Candidates(cx, cy, cost, boxes, framed, rivalled(reqs, starts, counts, boxes), starts, led, leader, far)


def leaders(reqs: Sequence[Request], starts: np.ndarray, counts: np.ndarray, boxes: Boxes
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The candidates of requests with a finite ``lead`` lying farther than it from the nearest of their
    ``starts`` (the anchor when none; they get a leader), each one's leader (from that start to the nearest
    point of the box, as the figure draws it) and whether that is longer than :data:`LEADER_MAX`. A turned box
    is measured by its bounds."""
    far = np.zeros(len(boxes), dtype=bool)
    which = [i for i, r in enumerate(reqs) if r.lead < math.inf]
    if not which:
        return _NO_ROWS, np.zeros((0, 4)), far
    rows = np.concatenate([np.arange(starts[i], starts[i + 1]) for i in which])
    lead = np.repeat([reqs[i].lead for i in which], counts[which])
    ns = max(len(reqs[i].starts) or 1 for i in which)          # each request's starts, its last repeated
    pts = np.array([[(r.starts or (r.anchor,))[min(j, len(r.starts or (r.anchor,)) - 1)] for j in range(ns)]
                    for r in (reqs[i] for i in which)], dtype=float).reshape(len(which), ns, 2)
    sx = np.repeat(pts[:, :, 0], counts[which], axis=0)                     # led candidate × start
    sy = np.repeat(pts[:, :, 1], counts[which], axis=0)
    x0, y0, x1, y1 = (v[rows][:, None] for v in (boxes.x0, boxes.y0, boxes.x1, boxes.y1))
    dist = box_point(x0, y0, x1, y1, sx, sy)
    pick = np.argmin(dist, axis=1)                                          # the start nearest the box
    at = np.arange(len(rows))
    ax, ay, d = sx[at, pick], sy[at, pick], dist[at, pick]
    bx = np.clip(ax, boxes.x0[rows], boxes.x1[rows])
    by = np.clip(ay, boxes.y0[rows], boxes.y1[rows])
    on = d > lead
    far[rows[on & (d > LEADER_MAX)]] = True
    return rows[on], np.stack([ax[on], ay[on], bx[on], by[on]], axis=1), far


_NO_ROWS = np.zeros(0, dtype=np.intp)


def _shape(r: Request) -> tuple[float, float, float, float, float, float]:
    """Half width and height, cosine and sine of the turn, half extents along x and y of a request's box (as
    :meth:`.Boxes.aligned` and :meth:`.Boxes.turned_by` compute them)."""
    hw, hh = r.width / 2, r.height / 2
    if not r.rotate:
        return hw, hh, 1.0, 0.0, hw, hh
    c, s = turn(r.rotate)
    return hw, hh, c, s, abs(c) * hw + abs(s) * hh, abs(s) * hw + abs(c) * hh


def _explicit(reqs: Sequence[Request], starts: np.ndarray, counts: np.ndarray, cx: np.ndarray, cy: np.ndarray,
              cost: np.ndarray) -> None:
    """Fill in the explicit candidates: their centres, ``spread`` per rank (a request's ``costs`` when given)."""
    which = [i for i, r in enumerate(reqs) if r.candidates]
    if not which:
        return
    xy = np.array([c for i in which for c in reqs[i].candidates], dtype=float).reshape(-1, 2)
    lens = counts[which]
    first = np.repeat(np.cumsum(lens) - lens, lens)
    rank = np.arange(len(xy)) - first
    at = np.repeat(starts[which], lens) + rank
    cx[at], cy[at] = xy[:, 0], xy[:, 1]
    cost[at] = np.repeat([reqs[i].spread for i in which], lens) * rank
    given = [i for i in which if reqs[i].costs]
    if given:
        rows = np.concatenate([np.arange(starts[i], starts[i] + counts[i]) for i in given])
        cost[rows] = np.array([c for i in given for c in reqs[i].costs], dtype=float)


def _around(reqs: Sequence[Request], starts: np.ndarray, cx: np.ndarray, cy: np.ndarray, cost: np.ndarray) -> None:
    """Fill in the candidates around the anchors: the directions of :func:`directions` at each distance beyond
    the gap (the box's half extent along the direction added), nearest first, :data:`FAR_PENALTY` per step of
    distance and ``spread`` per rank of direction; requests with as many distances together."""
    groups: dict[int, list[int]] = {}
    for i, r in enumerate(reqs):
        if not r.candidates:
            groups.setdefault(len(r.distances), []).append(i)
    for nd, which in groups.items():
        g = [reqs[i] for i in which]
        units = [_units(r.prefer) for r in g]
        ux, uy = np.array([u[0] for u in units]), np.array([u[1] for u in units])     # text × direction
        ax, ay = np.abs(ux), np.abs(uy)
        with np.errstate(divide="ignore"):
            tx = np.where(ax > 1e-12, np.array([r.width / 2 for r in g])[:, None] / ax, math.inf)
            ty = np.where(ay > 1e-12, np.array([r.height / 2 for r in g])[:, None] / ay, math.inf)
        beyond = np.array([r.gap for r in g])[:, None] + np.array([r.distances for r in g], dtype=float)
        reach = beyond[:, :, None] + np.minimum(tx, ty)[:, None, :]              # text × distance × direction
        x = np.array([r.anchor[0] for r in g])[:, None, None] + ux[:, None, :] * reach
        y = np.array([r.anchor[1] for r in g])[:, None, None] + uy[:, None, :] * reach
        penalty = ((FAR_PENALTY * np.arange(nd))[None, :, None]
                   + np.array([r.spread for r in g])[:, None, None] * np.arange(16)[None, None, :])
        at = (starts[which][:, None] + np.arange(16 * nd)).ravel()
        cx[at], cy[at], cost[at] = x.ravel(), y.ravel(), penalty.ravel()


def rivalled(reqs: Sequence[Request], starts: np.ndarray, counts: np.ndarray, boxes: Boxes) -> np.ndarray:
    """Whether each box lies nearer one of its request's ``rivals`` than its anchor (the distance from a box to
    a point as :meth:`.Boxes.to_point` measures it); a label naming several points, whether one of its parts
    lies nearer a rival than its own point (:func:`.joined.parts_rivalled`)."""
    out = parts_rivalled(reqs, starts, boxes)
    which = [i for i, r in enumerate(reqs) if r.rivals and not r.parts]
    if not which:
        return out
    npts = np.array([1 + len(reqs[i].rivals) for i in which])                # the anchor, then the rivals
    pts = np.array([p for i in which for p in (reqs[i].anchor, *reqs[i].rivals)], dtype=float)
    pairs = counts[which] * npts                                              # (candidate, point), candidate-major
    text = np.repeat(np.arange(len(which)), pairs)
    local = np.arange(int(pairs.sum())) - np.repeat(np.cumsum(pairs) - pairs, pairs)
    k = npts[text]
    box = starts[which][text] + local // k
    pt = (np.cumsum(npts) - npts)[text] + local % k
    px, py = pts[pt, 0], pts[pt, 1]
    d = box_point(boxes.x0[box], boxes.y0[box], boxes.x1[box], boxes.y1[box], px, py)
    turned = np.flatnonzero(boxes.sin[box] != 0.0)
    if len(turned):                                                          # a turned box: in its own frame
        b = box[turned]
        c, s, hw, hh = boxes.cos[b], boxes.sin[b], boxes.hw[b], boxes.hh[b]
        ux, uy = px[turned] - boxes.cx[b], py[turned] - boxes.cy[b]
        d[turned] = box_point(-hw, -hh, hw, hh, ux * c + uy * s, uy * c - ux * s)
    first = np.flatnonzero(local % k == 0)                                  # each box's own anchor
    own = d[first]
    d[first] = math.inf
    rival = np.minimum.reduceat(d, first)
    near = rival < own
    reach = [reqs[i].rival_reach for i in which]
    if any(r < math.inf for r in reach):        # a led box rivalled only by a point this near it
        reach, lead = np.array(reach)[text[first]], np.array([reqs[i].lead for i in which])[text[first]]
        near &= (own <= lead) | (rival <= reach)
    out[box[first]] = near
    return out


__all__ = ["FAR_PENALTY", "LEADER_MAX", "Candidates", "between", "candidates", "directions", "leaders", "rivalled"]
