"""Crank-rocker designs by K with the frame given: the closed form of A (the twin of the θ-circle met by the
circle of radius AD about D), and the one-parameter family of designs along the rocker's length that
``best_by_K`` searches.

With the rocker's extremes c1, c2 (D at the origin, |c1| = |c2| = CD, chord L = |c1c2|) take coordinates x
along c1→c2 from the chord's midpoint and y to its left; D is at (0, h). A sees the chord under θ when
x² + y² − L²/4 = L·|y|·cot θ (the dot and cross products of A→c1, A→c2), and lies at AD from D when
x² + (y − h)² = AD²; subtracting, y·(s·L·cot θ − 2h) = AD² − CD² with s = sign(y): y is linear, then x².

Examples
--------
>>> pts = frame_points((-30.0, 40.0), (30.0, 40.0), math.radians(20.0), 100.0)
>>> all(abs(math.hypot(x, y) - 100.0) < 1e-9 for x, y in pts), len(pts)
(True, 4)
"""
from __future__ import annotations

import math


def frame_points(c1: tuple[float, float], c2: tuple[float, float], th: float, AD: float) -> list[tuple[float, float]]:
    """Every A (D at the origin) at distance ``AD`` from D that sees c1c2 under ``th`` (radians, 0 < th < π)."""
    L = math.dist(c1, c2)
    ex, ey = (c2[0] - c1[0]) / L, (c2[1] - c1[1]) / L
    nx, ny = -ey, ex
    mx, my = (c1[0] + c2[0]) / 2.0, (c1[1] + c2[1]) / 2.0
    h = (0.0 - mx) * nx + (0.0 - my) * ny
    CD2 = c1[0] * c1[0] + c1[1] * c1[1]
    cot = math.cos(th) / math.sin(th)
    out = []
    for s in (1.0, -1.0):
        den = s * L * cot - 2.0 * h
        if den == 0.0:
            continue
        y = (AD - math.sqrt(CD2)) * (AD + math.sqrt(CD2)) / den
        if y * s <= 0.0:
            continue
        x2 = L * L / 4.0 + L * abs(y) * cot - y * y
        if x2 < 0.0:
            continue
        for x in ((math.sqrt(x2), -math.sqrt(x2)) if x2 > 0.0 else (0.0,)):
            out.append((mx + x * ex + y * nx, my + x * ey + y * ny))
    return out
