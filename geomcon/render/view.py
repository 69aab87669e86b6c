"""Paper geometry: the model → paper transform, the nice drawing scale μl, clipping to the view box.

Model coordinates are mm with y up; paper coordinates are mm with y down (one SVG user unit = 1 mm of
paper). Clipping is done in model coordinates and exactly (lines by their parameter interval, circles by
the angles where they cross the box), so no clip path is needed.

Examples
--------
>>> v = View((0.0, 0.0, 100.0, 50.0), 2.0, (10.0, 20.0))
>>> v.xy(0.0, 50.0), v.xy(100.0, 0.0)
((10.0, 20.0), (60.0, 45.0))
>>> clip_interval((0.0, 0.0), (1.0, 0.0), (-5.0, -1.0, 5.0, 1.0))
(-5.0, 5.0)
>>> choose_scale(180.0, 60.0)
1.0
>>> fmt(-0.0001), fmt(2.5), fmt(1 / 3)
('0', '2.5', '0.333')
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Iterator

from ..geometry.primitives import Point

Box = tuple[float, float, float, float]
"""(xmin, ymin, xmax, ymax)."""

TAU = 2.0 * math.pi
NICE = (1.0, 2.0, 2.5, 5.0)
FIG_MARGIN = 10.0       # paper mm around the drawn content (labels, ground symbols)
FIG_TARGET = 150.0      # paper width aimed at, margins included
FIG_MAX_W = 250.0
FIG_MAX_H = 185.0


def fmt(x: float) -> str:
    """A coordinate as printed in the SVG: three decimals, no trailing zeros, never ``-0``.

    Remembered by value (:data:`_FMT`): two of three numbers a gallery prints were printed before (font sizes,
    a subscript's shift, a column's x). Equal numbers print alike (0.0 and -0.0 both as ``0``), so a number
    found under an equal key of another type (1 and 1.0, a numpy float) prints as it would itself."""
    try:
        s = _FMT.get(x)
    except TypeError:                     # unhashable (a 0-d array): not remembered
        return _fmt(x)
    if s is None:
        s = _fmt(x)
        if len(_FMT) >= _FMT_MAX:
            _FMT.clear()
        _FMT[x] = s
    return s


def _fmt(x: float) -> str:
    """:func:`fmt`, computed."""
    s = f"{x:.3f}"
    if s[-1] != "0":
        return s
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


_FMT: dict[float, str] = {}
""":func:`fmt` of the numbers met (cleared when it holds :data:`_FMT_MAX`; a gallery job meets some 10 000)."""
_FMT_MAX = 1 << 16


def nice_values(lo: float, hi: float) -> Iterator[float]:
    """The values 1, 2, 2.5, 5 × 10^k between ``lo`` and ``hi`` (inclusive), ascending.

    Examples
    --------
    >>> list(nice_values(0.4, 3))
    [0.5, 1.0, 2.0, 2.5]
    """
    k = math.floor(math.log10(lo)) - 1
    while True:
        for m in NICE:
            v = float(f"{m * 10.0 ** k:.12g}")
            if v > hi * (1 + 1e-12):
                return
            if v >= lo * (1 - 1e-12):
                yield v
        k += 1


def figure_target(steps: int) -> float:
    """The paper width aimed at for a figure whose protocol has ``steps`` numbered steps: :data:`FIG_TARGET`
    up to 20 steps, growing 4 mm a step to 230 mm, so that a long construction (two protocol columns) is not
    drawn as a small figure beside a large text.

    >>> figure_target(12), figure_target(30), figure_target(60)
    (150.0, 190.0, 230.0)
    """
    return min(230.0, FIG_TARGET + 4.0 * max(0, steps - 20))


def choose_scale(width: float, height: float, margin: float = 0.0, target: float = FIG_TARGET) -> float:
    """The drawing scale μl (model mm per paper mm) from the nice series 1, 2, 2.5, 5 × 10^k.

    The figure ``width`` × ``height`` (model mm), drawn at μl with ``margin`` paper mm added on each side,
    should be about :data:`FIG_TARGET` wide on paper and fit in :data:`FIG_MAX_W` × :data:`FIG_MAX_H`.

    Parameters
    ----------
    width, height : float
        Model size of the content.
    margin : float
        Paper margin added on every side.
    target : float
        Paper width aimed at (see :func:`figure_target`).
    """
    size = max(width, height)
    if not size > 0 or not math.isfinite(size):
        return 1.0
    max_w, max_h = max(FIG_MAX_W, 1.15 * target), max(FIG_MAX_H, 1.05 * target)
    best, best_cost = 1.0, math.inf
    for mu in nice_values(size / 2000.0, size / 5.0):
        pw, ph = width / mu + 2 * margin, height / mu + 2 * margin
        over = max(pw / max_w, ph / max_h)
        cost = abs(math.log(pw / target)) + (100.0 + over if over > 1.0 else 0.0)
        if cost < best_cost - 1e-12:
            best, best_cost = mu, cost
    return best


@dataclass(frozen=True, slots=True)
class View:
    """The model box drawn at scale ``mu`` (model mm per paper mm), its top-left corner at paper ``origin``."""

    box: Box
    mu: float
    origin: tuple[float, float]

    def xy(self, x: float, y: float) -> tuple[float, float]:
        """Paper coordinates of the model point (x, y)."""
        return (self.origin[0] + (x - self.box[0]) / self.mu, self.origin[1] + (self.box[3] - y) / self.mu)

    def p(self, pt: Point) -> tuple[float, float]:
        """Paper coordinates of a model :class:`Point`."""
        return self.xy(pt.x, pt.y)

    def ps(self, pts: Iterable[Point]) -> list[tuple[float, float]]:
        """Paper coordinates of many model points: :meth:`p`'s operations in its order (the same bits), without
        two calls a point (a cam's curves have ~700 points; every label looks at every point of its figure).

        >>> v = View((0.0, 0.0, 10.0, 10.0), 2.0, (5.0, 5.0))
        >>> v.ps([Point(1.0, 3.0), Point(0.1, 0.7)]) == [v.p(Point(1.0, 3.0)), v.p(Point(0.1, 0.7))]
        True
        """
        (ox, oy), x0, y1, mu = self.origin, self.box[0], self.box[3], self.mu
        return [(ox + (q.x - x0) / mu, oy + (y1 - q.y) / mu) for q in pts]

    def length(self, d: float) -> float:
        """Paper length of a model length."""
        return d / self.mu

    @property
    def size(self) -> tuple[float, float]:
        """Paper width and height of the box."""
        return ((self.box[2] - self.box[0]) / self.mu, (self.box[3] - self.box[1]) / self.mu)

    @property
    def paper_box(self) -> Box:
        """The box on paper, (x0, y0, x1, y1) with y down."""
        w, h = self.size
        return (self.origin[0], self.origin[1], self.origin[0] + w, self.origin[1] + h)


def clip_interval(p: tuple[float, float], d: tuple[float, float], box: Box,
                  lo: float = -math.inf, hi: float = math.inf) -> tuple[float, float] | None:
    """The parameter interval [t0, t1] ⊂ [lo, hi] of p + t·d inside ``box``, or None (Liang–Barsky)."""
    for k, (a, b) in enumerate(((box[0], box[2]), (box[1], box[3]))):
        if d[k] == 0.0:
            if not a <= p[k] <= b:
                return None
            continue
        t1, t2 = (a - p[k]) / d[k], (b - p[k]) / d[k]
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    if not lo < hi:
        return None
    return (lo, hi)


def _inside(x: float, y: float, box: Box) -> bool:
    return box[0] <= x <= box[2] and box[1] <= y <= box[3]


def clip_arc(center: Point, r: float, box: Box, start: float = 0.0, sweep: float = TAU) -> list[tuple[float, float]]:
    """The parts of the counter-clockwise arc (``start``, ``sweep``) of a circle inside ``box``.

    Returns
    -------
    list of (start, sweep)
        Model angles in radians; ``[(start, sweep)]`` when the arc lies inside entirely.

    Examples
    --------
    >>> [(round(a, 6), round(s, 6)) for a, s in clip_arc(Point(0, 0), 1.0, (0.0, -2.0, 2.0, 2.0))]
    [(-1.570796, 3.141593)]
    """
    cuts = [0.0, sweep]
    for k, (a, b) in enumerate(((box[0], box[2]), (box[1], box[3]))):
        c = (center.x, center.y)[k]
        for edge in (a, b):
            q = (edge - c) / r
            if abs(q) < 1.0:
                base = math.acos(q) if k == 0 else math.asin(q)
                for ang in ((base, -base) if k == 0 else (base, math.pi - base)):
                    t = (ang - start) % TAU
                    if 0.0 < t < sweep:
                        cuts.append(t)
    cuts.sort()
    out: list[tuple[float, float]] = []
    for t0, t1 in zip(cuts, cuts[1:]):
        if t1 - t0 <= 1e-12:
            continue
        mid = start + (t0 + t1) / 2
        if _inside(center.x + r * math.cos(mid), center.y + r * math.sin(mid), box):
            if out and abs(out[-1][0] + out[-1][1] - (start + t0)) < 1e-12:
                out[-1] = (out[-1][0], out[-1][1] + t1 - t0)
            else:
                out.append((start + t0, t1 - t0))
    if len(out) > 1 and sweep >= TAU and abs(out[0][0] - start) < 1e-12 \
            and abs(out[-1][0] + out[-1][1] - (start + TAU)) < 1e-12:
        last = out.pop()
        out[0] = (last[0] - TAU, last[1] + out[0][1])
    return out


def grow(box: Box, d: float) -> Box:
    """``box`` enlarged by ``d`` on every side."""
    return (box[0] - d, box[1] - d, box[2] + d, box[3] + d)
