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


def _stationary(f, x: float, w: float) -> float:
    """The maximum of a smooth f near ``x``: where f(t + h) = f(t − h), by bisection on the sign within
    x ± r (r = 1e-2·x, else 1e-3·x, 1e-4·x: the widest bracket in which the sign changes once), for
    h = r/10, r/20, r/40, combined by Richardson's rule twice (a chord's midpoint lies O(h²) off the
    maximum): the golden bracket alone holds x only to √ε. At a kink ``x`` stays."""
    for r in (1e-2 * x, 1e-3 * x, 1e-4 * x):
        if r <= 2.0 * w:
            return x
        roots = []
        for h in (r / 10.0, r / 20.0, r / 40.0):
            d = lambda t, h=h: f(t + h) - f(t - h)    # noqa: E731
            lo, hi = x - r, x + r
            if not (d(lo) > 0.0 > d(hi)):
                break
            for _ in range(200):
                m = (lo + hi) / 2.0
                if m in (lo, hi):
                    break
                lo, hi = (m, hi) if d(m) > 0.0 else (lo, m)
            roots.append((lo + hi) / 2.0)
        if len(roots) == 3:
            r1, r2 = (4.0 * roots[1] - roots[0]) / 3.0, (4.0 * roots[2] - roots[1]) / 3.0
            return (16.0 * r2 - r1) / 15.0             # Richardson twice: the h² and h⁴ offsets cancel
    return x


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
    c = _stationary(f, (a + b) / 2.0, b - a)
    best = max(designs_at(K, psi, AD, c), key=lambda d: d["gamma_min"])
    return {**best, "theta": theta_from_k(K), "K": K, "psi": psi}


def _slot_points(c1, c2, th: float, AD: float) -> list:
    """:func:`frame_points` by slot (the side s of the chord, the sign of x): None where a slot is empty, so
    that a root can be followed along the family."""
    L = math.dist(c1, c2)
    ex, ey = (c2[0] - c1[0]) / L, (c2[1] - c1[1]) / L
    nx, ny = -ey, ex
    mx, my = (c1[0] + c2[0]) / 2.0, (c1[1] + c2[1]) / 2.0
    h = -mx * nx - my * ny
    CD = math.hypot(*c1)
    cot = math.cos(th) / math.sin(th)
    out = []
    for s in (1.0, -1.0):
        den = s * L * cot - 2.0 * h
        y = (AD - CD) * (AD + CD) / den if den != 0.0 else 0.0
        x2 = L * L / 4.0 + L * abs(y) * cot - y * y
        for sign in (1.0, -1.0):
            if den == 0.0 or y * s <= 0.0 or x2 < 0.0:
                out.append(None)
            else:
                x = sign * math.sqrt(x2)
                out.append((mx + x * ex + y * nx, my + x * ey + y * ny))
    return out


def _slot_design(K: float, psi: float, AD: float, CD: float, slot: int) -> dict[str, float] | None:
    th = math.radians(theta_from_k(K))
    a1, a2 = math.radians(90.0 + psi / 2.0), math.radians(90.0 - psi / 2.0)
    c1, c2 = (CD * math.cos(a1), CD * math.sin(a1)), (CD * math.cos(a2), CD * math.sin(a2))
    p = _slot_points(c1, c2, th, AD)[slot]
    if p is None:
        return None
    ax, ay = p
    d1, d2 = math.dist(p, c1), math.dist(p, c2)
    a, b = abs(d2 - d1) / 2.0, (d1 + d2) / 2.0
    if not rocker_design_valid(a, b, CD, AD, (ax * c1[1] - ay * c1[0]) / AD, (ax * c2[1] - ay * c2[0]) / AD):
        return None
    g = crank_rocker_gamma_from_positions(p, (0.0, 0.0), *((c1, c2) if d1 < d2 else (c2, c1)))
    side = lambda x, y: (c2[0] - c1[0]) * (y - c1[1]) - (c2[1] - c1[1]) * (x - c1[0])   # noqa: E731
    return {"AB": a, "BC": b, "CD": CD, "AD": AD, "psi": psi, "gamma_min": g, "theta": theta_from_k(K), "K": K,
            "C1_folded": float(d1 < d2), "A_near": float(side(ax, ay) * side(0.0, 0.0) > 0)}


def designs_at_ratio(K: float, psi: float, AD: float, AB: float, *, samples: int = 4000,
                     cd_max: float = 100.0) -> list[dict[str, float]]:
    """Every crank-rocker with K, ψ, the frame AD and the crank AB (C1 folded), the textbook's order: AB(CD)
    followed slot by slot on a logarithmic grid of CD, each change of sign of AB(CD) − AB bisected; where a
    slot stops being a valid design between two samples, its edge is found first and the sign taken there
    (a root close to the Grashof boundary). Rockers beyond ``cd_max`` frames are not sought (the
    construction's limit, :data:`geomcon.recipes.crank_rocker_crank_frame.CD_MAX`)."""
    lo, hi = math.log(1e-3 * AD), math.log(cd_max * AD)
    grid = [math.exp(lo + (hi - lo) * i / samples) for i in range(samples + 1)]
    out = []
    for slot in range(4):
        def f(c: float) -> float | None:
            d = _slot_design(K, psi, AD, c, slot)
            return None if d is None or not d["C1_folded"] else d["AB"] - AB
        vals = [f(c) for c in grid]
        for i in range(samples):
            u, v = vals[i], vals[i + 1]
            a, b = grid[i], grid[i + 1]
            if (u is None) != (v is None):          # the slot ends between the samples: a root may lie before
                inside, outside = (a, b) if u is not None else (b, a)
                for _ in range(200):
                    m = (inside + outside) / 2.0
                    if m in (inside, outside):
                        break
                    inside, outside = (m, outside) if f(m) is not None else (inside, m)
                w = f(inside)
                if u is None:
                    a, u, v = inside, w, v
                else:
                    b, v = inside, w
            if u is None or v is None or u * v > 0.0:
                continue
            for _ in range(200):
                m = (a + b) / 2.0
                if m in (a, b):
                    break
                fm = f(m)
                if fm is None:
                    break
                a, b = (m, b) if (fm > 0.0) == (u > 0.0) else (a, m)
            if f((a + b) / 2.0) is None:
                continue
            d = _slot_design(K, psi, AD, (a + b) / 2.0, slot)
            if d is not None:
                out.append(d)
    return sorted(out, key=lambda s: (-s["C1_folded"], -s["A_near"], s["AD"], s["CD"]))
