"""The drawn strokes a ground symbol and a rotation arrow keep off besides links and dimensions: the circles and
arcs drawn at a link's or a given circle's weight (a crank's circle, a θ-circle, a cam's base circle) and the
wide translucent bands (the pressure-angle limit lines, the admissible arcs).

A hatch across a crank's circle reads as a frame the crank cannot pass (001-19's A); one across a limit band
hides which side of the band is admissible (200-09's and 200-19's O).

Examples
--------
>>> from geomcon.render.shapes import ArcP, Pen
>>> ring = (ArcP((0.0, 0.0), 5.0, 0.0, math.pi, Pen("#000", 0.35)), 0.175)
>>> got = near_strokes((6.0, 1.0), (ring,), 2.0)
>>> len(got.lines), round(float(got.gaps[0]), 3), got.ways, got.zone
(1, 0.475, [], None)
>>> near_strokes((50.0, 50.0), (ring,), 2.0) is None
True
"""
from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
import shapely

from .shapes import ArcP, Disc, Poly
from .style import Style

XY = tuple[float, float]

STROKE_GAP = 0.3
"""Least paper mm between a ground symbol's (or rotation arrow's) strokes and the edge of such a stroke."""

RING_WIDTH = 0.25
"""The least pen width (paper mm) of a circle or an arc a ground keeps off: a θ-circle, a given circle (a cam's
base circle), a link's circle; the thin grey compass arcs of a construction (0.18) may run under a ground."""

BAND_WIDTH = 1.0
"""The least pen width (paper mm) of a straight line a ground keeps off: the admissible bands (1.6)."""

ARC_STEP = 0.4
"""Paper mm between the points an arc is sampled at near a hinge."""


def kept_off(style: Style, shape: Any) -> bool:
    """Whether a ground keeps off ``shape`` drawn in ``style``: a band (a stroke :data:`BAND_WIDTH` wide or more)
    or a circle or arc of :data:`RING_WIDTH` or more that is not a compass's short arc.

    >>> from geomcon.render.style import STYLES
    >>> from geomcon.render.shapes import Pen
    >>> kept_off(STYLES["theta-circle"], Disc((0, 0), 5, Pen("#000", 0.25))), kept_off(STYLES["construction"], Disc((0, 0), 5, None))
    (True, False)
    >>> kept_off(STYLES["admissible"], Poly(((0, 0), (1, 1)), Pen("#000", 1.6))), kept_off(STYLES["link"], Poly(((0, 0), (1, 1)), Pen("#000", 0.7)))
    (True, False)
    """
    if style.opacity <= 0.0:
        return False
    if isinstance(shape, (ArcP, Disc)):
        return style.width >= RING_WIDTH - 1e-9 and not style.compass
    return isinstance(shape, Poly) and style.width >= BAND_WIDTH - 1e-9


def _arc_near(c: XY, r: float, start: float, sweep: float, at: XY, reach: float) -> list[tuple[XY, ...]]:
    """The pieces of the paper arc (centre ``c``, radius ``r``, ``start``, signed ``sweep``) within about
    ``reach`` of ``at``, as point chains."""
    d = math.hypot(at[0] - c[0], at[1] - c[1])
    if abs(d - r) > reach or r <= 0.0:
        return []
    if d <= 1e-9 or d + r <= reach:
        lo, hi = 0.0, 2.0 * math.pi
    else:
        cos_w = max(-1.0, min(1.0, (d * d + r * r - reach * reach) / (2.0 * d * r)))
        mid, w = math.atan2(at[1] - c[1], at[0] - c[0]), math.acos(cos_w)
        lo, hi = mid - w, mid + w
    a0, a1 = (start, start + sweep) if sweep >= 0 else (start + sweep, start)
    out = []
    for k in (-1, 0, 1):                                  # the window shifted by whole turns
        s, e = max(a0, lo + 2.0 * math.pi * k), min(a1, hi + 2.0 * math.pi * k)
        if e > s:
            n = max(2, int(math.ceil((e - s) * r / ARC_STEP)) + 1)
            out.append(tuple((c[0] + r * math.cos(s + (e - s) * i / (n - 1)), c[1] + r * math.sin(s + (e - s) * i / (n - 1)))
                             for i in range(n)))
    return out


THROUGH = 0.5
"""Paper mm within which a stroke passes through a hinge: it then leaves the hinge like a link."""

HINGE_CLEAR = 3.0
"""Paper mm about a hinge where a stroke through it may meet the symbol's legs (the room kept from its directions,
as from a link's, keeps the rest apart)."""


def _ways(piece: tuple[XY, ...], at: XY) -> list[XY]:
    """The unit paper directions in which the chain ``piece`` passing through ``at`` leaves it."""
    best = min(range(len(piece) - 1), key=lambda i: shapely.LineString(piece[i:i + 2]).distance(shapely.Point(at)))
    (x0, y0), (x1, y1) = piece[best], piece[best + 1]
    n = math.hypot(x1 - x0, y1 - y0)
    if n <= 0.0:
        return []
    u = ((x1 - x0) / n, (y1 - y0) / n)
    out = []
    if math.hypot(piece[-1][0] - at[0], piece[-1][1] - at[1]) > 1.0:
        out.append(u)
    if math.hypot(piece[0][0] - at[0], piece[0][1] - at[1]) > 1.0:
        out.append((-u[0], -u[1]))
    return out


class Strokes(NamedTuple):
    """The kept-off strokes near a hinge (:func:`near_strokes`)."""

    lines: Any
    """The pieces there of those not through the hinge, as shapely lines."""
    gaps: Any
    """The least distance a symbol's stroke keeps from each (its half width and :data:`STROKE_GAP`)."""
    through: Any
    """Which of all the strokes near pass through the hinge (within :data:`THROUGH`): met only beyond
    :data:`HINGE_CLEAR` (:attr:`zone`)."""
    ways: list[XY]
    """The unit paper directions in which those through the hinge leave it."""
    zone: Any = None
    """What a symbol's stroke may not meet of those through the hinge: each one's band (its gap about it)
    beyond :data:`HINGE_CLEAR` of the hinge, as prepared shapes (None without)."""


def near_strokes(at: XY, strokes: tuple[tuple[Any, float], ...], reach: float) -> Strokes | None:
    """The kept-off ``strokes`` (paper shape, half its pen width) coming within ``reach`` of paper point ``at``
    (:class:`Strokes`); None when none comes near."""
    pieces: list[tuple[XY, ...]] = []
    gaps: list[float] = []
    spot = shapely.Point(at)
    for sh, half in strokes:
        if isinstance(sh, Disc):
            got = _arc_near(sh.c, sh.r, 0.0, 2.0 * math.pi, at, reach + half)
        elif isinstance(sh, ArcP):
            got = _arc_near(sh.c, sh.r, sh.start, sh.sweep, at, reach + half)
        else:
            line = shapely.LineString(sh.pts)
            got = [sh.pts] if shapely.dwithin(line, spot, reach + half) else []
        pieces += got
        gaps += [half + STROKE_GAP] * len(got)
    if not pieces:
        return None
    lines = np.array([shapely.LineString(p) for p in pieces], dtype=object)
    through = shapely.dwithin(lines, spot, THROUGH)
    ways = [w for p, t in zip(pieces, through) if t for w in _ways(p, at)]
    gaps_a = np.array(gaps)
    zone = None
    if through.any():
        zone = shapely.difference(shapely.buffer(lines[through], gaps_a[through], quad_segs=4),
                                  spot.buffer(HINGE_CLEAR, 8))
        shapely.prepare(zone)
    return Strokes(lines[~through], gaps_a[~through], through, ways, zone)


def strokes_hit(geo: Any, near: Strokes) -> Any:
    """How many of the strokes ``near`` each of the symbols' strokes ``geo`` (a column of shapely shapes, their
    hinge left out) comes too close to: a stroke through the hinge counted only beyond :data:`HINGE_CLEAR` of it."""
    hit = shapely.dwithin(geo, near.lines[None, :], near.gaps[None, :]).sum(axis=1) if len(near.lines) else 0
    if near.zone is not None:
        hit = hit + shapely.intersects(geo, near.zone[None, :]).sum(axis=1)
    return hit
