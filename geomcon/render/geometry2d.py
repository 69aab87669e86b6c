"""Paper geometry for the renderer: the model → paper transform, nice scales, clipping, extents.

Model coordinates are mm with y up; paper coordinates are mm with y down (one SVG user unit = 1 mm).

Examples
--------
>>> nice_scale(3.1), nice_scale(0.0042)
(4.0, 0.005)
>>> v = View((0.0, 0.0, 100.0, 50.0), 2.0, (10.0, 20.0))
>>> v.p(0.0, 50.0), v.p(100.0, 0.0)
((10.0, 20.0), (60.0, 45.0))
>>> clip_line((0.0, 0.0), (1.0, 0.0), (-5.0, -1.0, 5.0, 1.0))
((-5.0, 0.0), (5.0, 0.0))
"""
from __future__ import annotations

import math
from dataclasses import dataclass

Box = tuple[float, float, float, float]


def nice_scale(x: float) -> float:
    """The smallest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k that is ≥ x (the scale μl, model mm per paper mm)."""
    if x <= 0 or not math.isfinite(x):
        return 1.0
    k = math.floor(math.log10(x))
    for m in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0):
        v = m * 10.0 ** k
        if v >= x * (1 - 1e-12):
            return float(f"{v:.12g}")
    return 10.0 ** (k + 1)


@dataclass(frozen=True)
class View:
    """Model box → paper: ``mu`` model mm per paper mm, the box's top-left corner at ``origin`` on paper."""

    box: Box
    mu: float
    origin: tuple[float, float]

    def p(self, x: float, y: float) -> tuple[float, float]:
        """Paper coordinates of model point (x, y), rounded to 1 µm of paper."""
        return (round(self.origin[0] + (x - self.box[0]) / self.mu, 3),
                round(self.origin[1] + (self.box[3] - y) / self.mu, 3))

    def length(self, d: float) -> float:
        """Paper length of a model length."""
        return d / self.mu

    @property
    def size(self) -> tuple[float, float]:
        """Paper width and height of the box."""
        return ((self.box[2] - self.box[0]) / self.mu, (self.box[3] - self.box[1]) / self.mu)


def clip_line(p: tuple[float, float], d: tuple[float, float], box: Box, *, ray: bool = False):
    """The part of the line (or ray) p + t·d inside ``box``, as two points, or None."""
    lo, hi = (0.0 if ray else -math.inf), math.inf
    for k, (a, b) in enumerate(((box[0], box[2]), (box[1], box[3]))):
        if abs(d[k]) < 1e-300:
            if not a <= p[k] <= b:
                return None
            continue
        t1, t2 = (a - p[k]) / d[k], (b - p[k]) / d[k]
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    if lo >= hi:
        return None
    return ((p[0] + lo * d[0], p[1] + lo * d[1]), (p[0] + hi * d[0], p[1] + hi * d[1]))


def grow(box: Box, frac: float, minimum: float) -> Box:
    """``box`` enlarged by ``frac`` of its size on every side (at least ``minimum``)."""
    w, h = box[2] - box[0], box[3] - box[1]
    m = max(frac * max(w, h), minimum)
    return (box[0] - m, box[1] - m, box[2] + m, box[3] + m)
