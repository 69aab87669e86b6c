"""Crank-rocker designs by K with the crank, the frame and the swing given (``K AB AD psi`` → BC, CD): every
design in closed form, the twin of the construction that searches the θ-circles' arcs.

With a = AB, b = BC, c = CD, d = AD, the folded and extended positions AC1 = b − a, AC2 = b + a, the rocker's
extremes at φ1 = ∠ADC1 and φ2 = φ1 + ψ (both on one side of AD, so φ2 > φ1 because AC2 > AC1), and
β = φ1 + ψ/2 the direction of their bisector from DA, the law of cosines in A D C1 and A D C2 gives (half their
difference and half their sum, s = sin(ψ/2), k = cos(ψ/2))

    a·b = c·d·s·sin β,        a² + b² = c² + d² − 2·c·d·k·cos β,

and in A C1 C2, whose base C1C2 = 2·c·s is seen from A under θ (S = sin(θ/2), C = cos(θ/2)),

    c²·s² = b²·S² + a²·C².

The last makes c² linear in B = b²; eliminating β by sin² + cos² = 1 leaves a quadratic in B:

    (S² − s²)²·B² + [2(S² − s²)·q + 4s²k²(a² − d²S²)]·B + (q − 2skdaC)(q + 2skdaC) = 0,   q = a²C² + s²(d² − a²).

Each positive root gives b, c and β = atan2(2k·a·b, s·(c² + d² − a² − b²)); it is a design when both extremes
lie strictly on one side of AD (0 < φ1, φ2 < 180°) and AB is a crank by Grashof
(:func:`geomcon.analytic.design_by_k.rocker_design_valid`). So there are at most two designs, and none is
missed however narrow the range of CD in which it exists. Each root is polished by Newton's method on the
quadratic, then by Newton's method in (b, c) on the design's own θ and ψ (Kahan's triangle angles,
:func:`_residual`): near the Grashof boundary the elimination loses digits (a design with γmin = 1.4° came
back with K off by 1.4e-7 before, 2.5e-12 after).

Examples
--------
>>> sols = crank_frame_designs(10 / 9, 46.6717, 120.0, 80.0)
>>> sorted((round(s["BC"], 2), round(s["CD"], 2)) for s in sols)
[(98.95, 73.47), (116.16, 73.88)]
"""
from __future__ import annotations

import math

from .design_by_k import rocker_design_valid
from .linkages import _tri_angle, crank_rocker_gamma_from_positions, theta_from_k


def _quadratic(a: float, d: float, th: float, psi: float) -> tuple[float, float, float]:
    """The coefficients (B², B, 1) of the elimination above (``th``, ``psi`` in radians)."""
    S, C = math.sin(th / 2.0), math.cos(th / 2.0)
    s, k = math.sin(psi / 2.0), math.cos(psi / 2.0)
    p = (S - s) * (S + s)
    q = a * a * C * C + s * s * (d - a) * (d + a)
    m = 2.0 * s * k * d * a * C
    return p * p, 2.0 * p * q + 4.0 * s * s * k * k * (a - d * S) * (a + d * S), (q - m) * (q + m)


def _roots(c2: float, c1: float, c0: float) -> list[float]:
    """The real roots of c2·x² + c1·x + c0 (c2 may be 0), by the stable pair of formulas; a double root once."""
    if c2 == 0.0:
        return [] if c1 == 0.0 else [-c0 / c1]
    disc = c1 * c1 - 4.0 * c2 * c0
    if disc < 0.0:
        # a double root lost to rounding: keep it when the discriminant is within rounding of 0
        if -disc > 1e-12 * c1 * c1:
            return []
        disc = 0.0
    t = -0.5 * (c1 + math.copysign(math.sqrt(disc), c1))
    if t == 0.0:
        return [0.0]
    return sorted({t / c2, c0 / t})


def _polish(coef: tuple[float, float, float], x: float) -> float:
    """Newton's method on the quadratic from ``x``, while a step makes the residual smaller (steps of 1e-7 of the folded length AC1 = b − a, small near the Grashof
    boundary, where the angles change on that scale)."""
    c2, c1, c0 = coef
    for _ in range(12):
        f, df = (c2 * x + c1) * x + c0, 2.0 * c2 * x + c1
        if df == 0.0:
            break
        y = x - f / df
        if abs((c2 * y + c1) * y + c0) >= abs(f):
            break
        x = y
    return x


def _residual(a: float, b: float, c: float, d: float, theta: float, psi: float) -> tuple[float, float]:
    """(θ − theta, ψ − psi) in degrees of the linkage a, b, c, d: θ = |∠C1AD − ∠C2AD| and ψ = ∠ADC2 − ∠ADC1
    from AC1 = b − a, AC2 = b + a by Kahan's formula (accurate for needle-like triangles)."""
    f, x = b - a, b + a
    th = abs(_tri_angle(f, d, c) - _tri_angle(x, d, c))
    return th - theta, _tri_angle(d, c, x) - _tri_angle(d, c, f) - psi


def _newton(a: float, b: float, c: float, d: float, theta: float, psi: float) -> tuple[float, float]:
    """(b, c) polished by Newton's method on :func:`_residual` (a forward-difference Jacobian), while a step
    makes the residual smaller (steps of 1e-7 of the folded length AC1 = b − a, small near the Grashof
    boundary, where the angles change on that scale)."""
    r = _residual(a, b, c, d, theta, psi)
    for _ in range(12):
        n = abs(r[0]) + abs(r[1])
        if n == 0.0:
            break
        hb = hc = 1e-7 * min(b - a, c)          # the folded length b − a sets the scale near the boundary
        rb, rc = _residual(a, b + hb, c, d, theta, psi), _residual(a, b, c + hc, d, theta, psi)
        j11, j21 = (rb[0] - r[0]) / hb, (rb[1] - r[1]) / hb
        j12, j22 = (rc[0] - r[0]) / hc, (rc[1] - r[1]) / hc
        det = j11 * j22 - j12 * j21
        if det == 0.0 or not math.isfinite(det):
            break
        nb, nc = b - (j22 * r[0] - j12 * r[1]) / det, c - (j11 * r[1] - j21 * r[0]) / det
        if not (nb > a and nc > 0.0):
            break
        q = _residual(a, nb, nc, d, theta, psi)
        if not abs(q[0]) + abs(q[1]) < n:
            break
        b, c, r = nb, nc, q
    return b, c


def crank_frame_designs(K: float, AB: float, AD: float, psi: float, *, cd_max: float = math.inf) -> list[dict[str, float]]:
    """Every crank-rocker with time ratio K, crank AB, frame AD and rocker swing ψ (deg), C1 the folded
    position: ``AB BC CD AD psi gamma_min theta K C1_folded A_near`` each, A_near first, then by CD. Rockers
    longer than ``cd_max`` frames are left out (the construction's limit)."""
    th, ps = math.radians(theta_from_k(K)), math.radians(psi)
    a, d = AB, AD
    S, C = math.sin(th / 2.0), math.cos(th / 2.0)
    s, k = math.sin(ps / 2.0), math.cos(ps / 2.0)
    coef = _quadratic(a, d, th, ps)
    out = []
    for B in _roots(*coef):
        B = _polish(coef, B)
        if B <= 0.0:
            continue
        b = math.sqrt(B)
        c = math.sqrt(B * S * S + a * a * C * C) / s
        if c > cd_max * d:
            continue
        beta = math.atan2(2.0 * k * a * b, s * ((c - a) * (c + a) + (d - b) * (d + b)))
        phi1, phi2 = beta - ps / 2.0, beta + ps / 2.0
        if not rocker_design_valid(a, b, c, d, c * math.sin(phi1), c * math.sin(phi2)) or phi1 <= 0.0 or phi2 >= math.pi:
            continue
        b, c = _newton(a, b, c, d, math.degrees(th), psi)
        phi1 = math.radians(_tri_angle(d, c, b - a))          # both extremes on one side of AD: as checked
        phi2 = math.radians(_tri_angle(d, c, b + a))
        beta = (phi1 + phi2) / 2.0
        if c > cd_max * d or not rocker_design_valid(a, b, c, d, c * math.sin(phi1), c * math.sin(phi2)):
            continue
        c1, c2 = (c * math.cos(phi1), c * math.sin(phi1)), (c * math.cos(phi2), c * math.sin(phi2))
        out.append({"AB": a, "BC": b, "CD": c, "AD": d, "psi": psi,
                    "gamma_min": crank_rocker_gamma_from_positions((d, 0.0), (0.0, 0.0), c1, c2),
                    "theta": math.degrees(th), "K": K, "C1_folded": True,
                    "A_near": d * math.cos(beta) < c * k})
    return sorted(out, key=lambda r: (-r["A_near"], r["CD"]))
