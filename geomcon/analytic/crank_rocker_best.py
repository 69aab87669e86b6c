"""The crank-rocker with time ratio K, swing ψ and frame AD whose smallest transmission angle is largest
(the twin of ``crank_rocker.best_by_K``).

The designs with the frame AD form a one-parameter family in the rocker's length CD
(:func:`geomcon.analytic.design_by_k_frame.frame_points` gives A for each CD); γmin is a function of CD,
sampled on a logarithmic grid, its best sample refined by golden-section search between its neighbours and
the maximum then placed where the central difference of γmin changes sign (a smooth maximum: the golden
bracket alone would hold CD only to √ε).

Examples
--------
>>> r = crank_rocker_best(10 / 9, 80.0, 120.0)
>>> round(r["AB"], 2), round(r["BC"], 2), round(r["CD"], 2), round(r["gamma_min"], 2)
(46.67, 116.16, 73.88, 37.73)
"""
from __future__ import annotations

import math

from ..numeric import stationary
from .design_by_k import rocker_design_valid
from .design_by_k_frame import frame_points
from .linkages import crank_rocker_gamma_from_positions, theta_from_k

_GOLD = (math.sqrt(5.0) - 1.0) / 2.0


def designs_at(K: float, psi: float, AD: float, CD: float) -> list[dict[str, float]]:
    """Every valid crank-rocker with K, ψ, the frame AD and the rocker CD (D at the origin)."""
    th = math.radians(theta_from_k(K))
    a1, a2 = math.radians(90.0 + psi / 2.0), math.radians(90.0 - psi / 2.0)
    c1, c2 = (CD * math.cos(a1), CD * math.sin(a1)), (CD * math.cos(a2), CD * math.sin(a2))
    out = []
    for ax, ay in frame_points(c1, c2, th, AD):
        d1, d2 = math.dist((ax, ay), c1), math.dist((ax, ay), c2)
        a, b = abs(d2 - d1) / 2.0, (d1 + d2) / 2.0
        h1, h2 = (ax * c1[1] - ay * c1[0]) / AD, (ax * c2[1] - ay * c2[0]) / AD
        if not rocker_design_valid(a, b, CD, AD, h1, h2):
            continue
        g = crank_rocker_gamma_from_positions((ax, ay), (0.0, 0.0), *((c1, c2) if d1 < d2 else (c2, c1)))
        out.append({"AB": a, "BC": b, "CD": CD, "AD": AD, "gamma_min": g})
    return out


def _best_gamma(K: float, psi: float, AD: float, CD: float) -> float:
    ds = designs_at(K, psi, AD, CD)
    return max((d["gamma_min"] for d in ds), default=-1.0)


def crank_rocker_best(K: float, psi: float, AD: float, *, samples: int = 4000) -> dict[str, float]:
    """The design of largest γmin (``AB BC CD gamma_min`` plus θ, K, ψ, AD)."""
    lo, hi = math.log(1e-3 * AD), math.log(1e3 * AD)
    grid = [math.exp(lo + (hi - lo) * i / samples) for i in range(samples + 1)]
    vals = [_best_gamma(K, psi, AD, c) for c in grid]
    i = max(range(len(vals)), key=lambda k: vals[k])
    if vals[i] < 0:
        from ..errors import NotAMechanism
        raise NotAMechanism(f"no crank-rocker has K = {K:g}, ψ = {psi:g}° and a frame AD = {AD:g}")
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, samples)]
    f = lambda c: _best_gamma(K, psi, AD, c)          # noqa: E731
    x1, x2 = b - _GOLD * (b - a), a + _GOLD * (b - a)
    f1, f2 = f(x1), f(x2)
    for _ in range(200):
        if f1 < f2:
            a, x1, f1 = x1, x2, f2
            x2 = a + _GOLD * (b - a)
            f2 = f(x2)
        else:
            b, x2, f2 = x2, x1, f1
            x1 = b - _GOLD * (b - a)
            f1 = f(x1)
        if b - a <= 1e-15 * b:
            break
    x = (a + b) / 2.0                                 # the sign change of a central difference, refined
    c = stationary(f, x, [r for r in (1e-2 * x, 1e-3 * x, 1e-4 * x) if r > 2.0 * (b - a)])
    best = max(designs_at(K, psi, AD, c), key=lambda d: d["gamma_min"])
    return {**best, "theta": theta_from_k(K), "K": K, "psi": psi}
