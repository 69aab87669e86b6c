"""Function generation by Freudenstein's equation: the twin of ``four_bar.function_generation``.

Conventions (those of the recipe): A at the origin, D = (d, 0) on +x; the crank AB = a makes the angle φ
with the frame line A→D (counter-clockwise); the rocker carries a marked line DE whose direction makes the
angle ψ with the same direction A→D, i.e. with AD extended beyond D (counter-clockwise; the interior angle
∠ADE is 180° − ψ). The hinge C of the coupler on the rocker lies at CD = c in the direction ψ + β, where β is
the (unknown) angle of DC from the marked line DE. BC = b.

Freudenstein's equation for the direction χ = ψ + β of DC reads

    K1·cos χ − K2·cos φ + K3 = cos(φ − χ),   K1 = d/a,  K2 = d/c,  K3 = (a² − b² + c² + d²)/(2ac)

(expand |C − B|² = b² with B = a(cos φ, sin φ), C = (d + c cos χ, c sin χ) and divide by 2ac). The crank a
is given, so K1 is known; multiplying by c/d and expanding χ = ψ + β leaves an equation that is linear in
U = c·cos β, V = c·sin β and W = c·K3/d:

    U·(cos ψ/a − cos(φ − ψ)/d) − V·(sin ψ/a + sin(φ − ψ)/d) + W = cos φ.

Three pairs (φi, ψi) give a 3×3 linear system, solved here by Cramer's rule. Then c = √(U² + V²),
β = atan2(V, U) and b² = a² + c² + d² − 2adW. When C lies on the marked line (β = 0) this is the textbook
form with U = 1/K2 = c/d·d, V = 0, W = K3/K2.

The code is complex-safe (``cmath``), so the sensitivity of C1 to each given is its complex-step
derivative: exact to rounding, a route separate from the construction's first-order geometry.

Examples
--------
>>> r = function_generation(60.0, 20.0, (30.0, 75.0, 120.0), (80.0, 95.0, 115.0))
>>> [round(v, 6) for v in (*r["C1"], r["BC"], r["CD"], r["beta"])]
[100.884517, 41.329152, 89.24382, 58.134693, 325.309869]
>>> r["crank"], r["branch_ok"], r["order_ok"]
(True, True, True)
"""
from __future__ import annotations

import cmath
import math
from typing import Sequence

from ..errors import NotAMechanism
from ..numeric import deg360
from .fourbar_drive import (REFUSE_CONDITION, WARN_CONDITION, arc_through, bd_extremes, centre_condition,
                            dead_point_free, on_arc, turns_fully)
from .linkages import _tri_angle

STEP = 1e-30
"""Complex-step size: f'(x) = Im f(x + i·STEP) / STEP, free of cancellation."""

SINGULAR_REL = 1e-14
"""The normalised 3×3 system with a relative determinant at or below this is singular to double precision
(a backstop: the recipes refuse nearly collinear inverted points first, by :func:`check_inverted`)."""

REFUSE_FLAT = 1e-6
"""Refuse when two of the three inverted points coincide: shortest side over the longest at or below this."""


def solve3(M: Sequence[Sequence[complex]], r: Sequence[complex]) -> tuple[complex, complex, complex]:
    """Solve the 3×3 system M·x = r by Cramer's rule (complex-safe), normalised first.

    The columns are scaled to unit size (unknowns of different units or sizes — lengths next to a pure
    number, AD = 1e7 next to 1) and then the rows, so that the singularity test is relative and
    scale-free: the relative determinant |det| / (|row1|·|row2|·|row3|) (Hadamard's bound, 1 for
    orthogonal rows) of the normalised matrix at or below :data:`SINGULAR_REL` is refused.

    >>> [round(abs(v), 12) for v in solve3([[2, 0, 0], [0, 4, 0], [1, 0, 1]], [2, 8, 3])]
    [1.0, 2.0, 2.0]
    >>> [float(f"{abs(v):.12g}") for v in solve3([[2e-7, 0, 1], [0, 4e-7, 1], [1e-7, 1e-7, 1]], [3, 3, 2.5])]
    [10000000.0, 5000000.0, 1.0]
    """
    # written out (no comprehensions: the complex-step sensitivities call it a dozen times a twin), each
    # number formed by the same operations in the same order as the loops it replaces, so the same bits
    def det(m00, m01, m02, m10, m11, m12, m20, m21, m22):
        return (m00 * (m11 * m22 - m12 * m21) - m01 * (m10 * m22 - m12 * m20)
                + m02 * (m10 * m21 - m11 * m20))

    def size(v):
        return abs(v.real if isinstance(v, complex) else v)

    (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = M
    k0, k1, k2 = max(size(a0), size(b0), size(c0)), max(size(a1), size(b1), size(c1)), max(size(a2), size(b2), size(c2))
    if not (k0 > 0.0 and k1 > 0.0 and k2 > 0.0):
        raise NotAMechanism("the 3×3 linear system is singular (a column of zeros)")
    a0, a1, a2, b0, b1, b2, c0, c1, c2 = a0 / k0, a1 / k1, a2 / k2, b0 / k0, b1 / k1, b2 / k2, c0 / k0, c1 / k1, c2 / k2
    ra, rb, rc = max(size(a0), size(a1), size(a2)), max(size(b0), size(b1), size(b2)), max(size(c0), size(c1), size(c2))
    a0, a1, a2, b0, b1, b2, c0, c1, c2 = a0 / ra, a1 / ra, a2 / ra, b0 / rb, b1 / rb, b2 / rb, c0 / rc, c1 / rc, c2 / rc
    r0, r1, r2 = r[0] / ra, r[1] / rb, r[2] / rc
    D = det(a0, a1, a2, b0, b1, b2, c0, c1, c2)
    bound = math.prod((math.sqrt(sum((abs(a0) ** 2, abs(a1) ** 2, abs(a2) ** 2))),
                       math.sqrt(sum((abs(b0) ** 2, abs(b1) ** 2, abs(b2) ** 2))),
                       math.sqrt(sum((abs(c0) ** 2, abs(c1) ** 2, abs(c2) ** 2)))))
    if not abs(D) > SINGULAR_REL * bound:
        raise NotAMechanism(f"the 3×3 linear system is singular (relative determinant {abs(D) / bound:.3g} ≤ "
                            f"{SINGULAR_REL:g} after scaling rows and columns)")
    return (det(r0, a1, a2, r1, b1, b2, r2, c1, c2) / D / k0, det(a0, r0, a2, b0, r1, b2, c0, r2, c2) / D / k1,
            det(a0, a1, r0, b0, b1, r1, c0, c1, r2) / D / k2)


def _hinge(d, a, phi, psi):
    """(C1x, C1y, U, V, W) from the linear Freudenstein system; angles in radians; complex-safe.

    Rows 2 and 3 are taken minus row 1, their differences of cosines and sines as products
    (cos x − cos y = −2 sin((x + y)/2) sin((x − y)/2), sin x − sin y = 2 cos((x + y)/2) sin((x − y)/2)):
    with all angles within 0.1° of the frame the U column is the W column (all ones) plus O(angle²), and
    Cramer's rule on the rows as written lost C1's height to 4e-4 of itself."""
    def dcos(x, y):
        return -2.0 * cmath.sin((x + y) / 2) * cmath.sin((x - y) / 2)

    def dsin(x, y):
        return 2.0 * cmath.cos((x + y) / 2) * cmath.sin((x - y) / 2)

    f0, p0 = phi[0], psi[0]
    q0 = f0 - p0
    rows = [[cmath.cos(p0) / a - cmath.cos(q0) / d, -(cmath.sin(p0) / a + cmath.sin(q0) / d), 1.0]]
    rhs = [cmath.cos(f0)]
    for f, p in zip(phi[1:], psi[1:]):
        q = f - p
        rows.append([dcos(p, p0) / a - dcos(q, q0) / d, -(dsin(p, p0) / a + dsin(q, q0) / d), 0.0])
        rhs.append(dcos(f, f0))
    U, V, W = solve3(rows, rhs)
    c1, s1 = cmath.cos(psi[0]), cmath.sin(psi[0])
    return d + U * c1 - V * s1, U * s1 + V * c1, U, V, W


def flatness(P: Sequence[tuple[float, float]]) -> tuple[float, float]:
    """(relative height, relative shortest side) of the triangle P: 2·area/L² and min side/L, L the
    longest side (both 0 for coincident points).

    >>> [round(v, 6) for v in flatness([(0, 0), (2, 0), (1, 1)])]
    [0.5, 0.707107]
    """
    sides = [math.dist(P[i], P[(i + 1) % 3]) for i in range(3)]
    L = max(sides)
    if L == 0.0:
        return 0.0, 0.0
    area2 = abs((P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[1][1] - P[0][1]) * (P[2][0] - P[0][0]))
    return area2 / (L * L), min(sides) / L


def inverted_pins(AD: float, AB: float, phi: Sequence[float], psi: Sequence[float]) -> list[tuple[float, float]]:
    """B1 and the crank pins of positions 2, 3 turned about D by ψ1 − ψi (the points the hinge C1 is the
    centre of), for the flatness test of the givens.

    >>> [tuple(round(v, 9) for v in p) for p in inverted_pins(10.0, 5.0, (0, 0, 0), (0, 90, 180))]
    [(5.0, 0.0), (10.0, 5.0), (15.0, 0.0)]
    """
    out = []
    for f, p in zip(phi, psi):
        bx, by = AB * math.cos(math.radians(f)) - AD, AB * math.sin(math.radians(f))
        t = math.radians(psi[0] - p)
        out.append((AD + bx * math.cos(t) - by * math.sin(t), bx * math.sin(t) + by * math.cos(t)))
    return out


def check_inverted(P: Sequence[tuple[float, float]], what: str, names: str) -> list[str]:
    """Refuse (NotAMechanism) or warn when the three inverted points are coincident or nearly collinear, by
    the policy of every three-position synthesis: the condition R / h_min of the triangle
    (:func:`~geomcon.analytic.fourbar_drive.centre_condition`) warned from
    :data:`~geomcon.analytic.fourbar_drive.WARN_CONDITION` = 100, refused from
    :data:`~geomcon.analytic.fourbar_drive.REFUSE_CONDITION` = 1e7.

    ``what`` names the sought hinge, ``names`` the three points (for the message).

    >>> check_inverted([(0, 0), (1, 0), (2, 1e-9)], "C1", "B1, B2′, B3′")
    Traceback (most recent call last):
    ...
    geomcon.errors.NotAMechanism: the inverted points B1, B2′, B3′ are (nearly) collinear (R/h_min = 2e+18 ≥ 1e+07): C1 would lie at infinity
    """
    h, short = flatness(P)
    k = centre_condition(*P)
    if short <= REFUSE_FLAT:
        raise NotAMechanism(f"two of the inverted points {names} coincide (shortest side {short:.3g} of the longest "
                            f"≤ {REFUSE_FLAT:g}): {what} is not determined")
    if k >= REFUSE_CONDITION:
        raise NotAMechanism(f"the inverted points {names} are (nearly) collinear (R/h_min = {k:.3g} ≥ "
                            f"{REFUSE_CONDITION:g}): {what} would lie at infinity")
    if k >= WARN_CONDITION:
        return [f"the inverted points {names} are nearly collinear (R/h_min = {k:.4g} ≥ {WARN_CONDITION:g}): "
                f"{what} moves up to {k:.4g} mm per mm of error in one of them"]
    return []


def _branch(B, C, D) -> int:
    """+1 when C lies left of B→D (the fourbar_drive convention), −1 right, 0 on it."""
    s = math.sin(math.atan2(C[1] - B[1], C[0] - B[0]) - math.atan2(D[1] - B[1], D[0] - B[0]))
    return (s > 0) - (s < 0)


def transmission_at(a: float, b: float, c: float, d: float, W: float, phi: float) -> float:
    """The acute transmission angle (deg) of the linkage a, b, c, d at crank angle ``phi`` (deg), from the
    triangle B C D with sides b, c and BD(φ) = √((a − d)² + 4ad·sin²(φ/2)) by Kahan's factors
    tan²(∠BCD/2) = (c − δ)(b + BD − c) / ((b + c + BD)(c + δ)), δ = b − BD.

    δ is never the difference of the two floats b and BD when they are the longer sides: with AD = 1e9 and
    CD = 150 both are ~1e9 and hold δ only to their last bit (1e-7 mm, 1e-6° of a 0.4° γ); it is
    (b² − BD²)/(b + BD) with b² − BD² = c² − 2ad(W − cos φ) from Freudenstein's W (b² = a² + c² + d² − 2adW).

    >>> W = (50**2 + 80**2 + 90**2 - 70**2) / (2 * 50 * 90)        # a crank-rocker 50, 70, 80, 90
    >>> round(transmission_at(50.0, 70.0, 80.0, 90.0, W, 0.0), 9), round(_tri_angle(70.0, 80.0, 40.0), 9)
    (29.994725527, 29.994725527)
    """
    t = math.radians(phi)
    s = math.sin(t / 2.0)
    bd = math.sqrt((a - d) ** 2 + 4.0 * a * d * s * s)
    if c >= max(b, bd):
        delta = b - bd                                     # c is the longest: b − BD does not cancel against it
    else:
        delta = (c * c - 2.0 * a * d * (W - math.cos(t))) / (b + bd)
    big = (b - c) + bd if b >= bd else (bd - c) + b        # b + BD − c, exact where c ≈ b + BD (Sterbenz)
    g = math.degrees(2.0 * math.atan2(math.sqrt(max(0.0, (c - delta) * big)),
                                      math.sqrt(max(0.0, (b + c + bd) * (c + delta)))))
    return min(g, 180.0 - g)


def _solution(d: float, a: float, phi: Sequence[float], psi: Sequence[float]) -> tuple[list[float], tuple[float, ...]]:
    """(the angles in radians, (x, y, U, V, W) of the real system): the part of the twin the answers need."""
    rad = [math.radians(v) for v in (*phi, *psi)]
    return rad, tuple(z.real for z in _hinge(d, a, rad[:3], rad[3:]))


def hinge_distance(AD: float, AB: float, phi: Sequence[float], psi: Sequence[float]) -> float:
    """CD = |DC1| of :func:`function_generation` (the same numbers), without its sensitivities: the
    recipe's validation refuses a hinge on D with it.

    >>> hinge_distance(60.0, 20.0, (30.0, 75.0, 120.0), (80.0, 95.0, 115.0)) == function_generation(
    ...     60.0, 20.0, (30.0, 75.0, 120.0), (80.0, 95.0, 115.0))["CD"]
    True
    """
    _, (_, _, U, V, _) = _solution(AD, AB, phi, psi)
    return math.hypot(U, V)


def function_generation(AD: float, AB: float, phi: Sequence[float], psi: Sequence[float]) -> dict:
    """Every answer of ``four_bar.function_generation`` by the linear Freudenstein system.

    Angles in degrees as documented in the module; returns C1 (tuple), BC, CD, beta, gamma_min, grashof,
    crank, branch_ok, order_ok, sens_C1 (mm per 0.1° of any one given angle) and sens_C1_mm (mm per 0.1 mm
    of AD or AB).
    """
    d, a = AD, AB
    rad, (x, y, U, V, W) = _solution(d, a, phi, psi)
    c = math.hypot(U, V)
    b = math.sqrt(max(0.0, a * a + c * c + d * d - 2.0 * a * d * W))
    beta = deg360(math.degrees(math.atan2(V, U)))
    ls = sorted((a, b, c, d))
    branches = []
    for f, p in zip(phi, psi):
        B = (a * math.cos(math.radians(f)), a * math.sin(math.radians(f)))
        C = (d + c * math.cos(math.radians(p + beta)), c * math.sin(math.radians(p + beta)))
        branches.append(_branch(B, C, (d, 0.0)))
    crank = turns_fully(a, b, c, d)
    start, swept = (0.0, 360.0) if crank else arc_through(*phi)
    lo, hi = bd_extremes((0.0, 0.0), (d, 0.0), a, start, swept)
    free = dead_point_free(lo, hi, b, c)
    # γ is extreme where BD is: with the crank along the frame (on the arc) or at the ends of the arc
    at = [f for f in (0.0, 180.0) if crank or on_arc(f, start, swept)] + ([] if crank else [phi[0], phi[2]])
    gammas = [transmission_at(a, b, c, d, W, f) for f in at]
    sens = []
    for k in range(8):          # φ1..3, ψ1..3 (rad), AD, AB (mm)
        gk = [complex(v) for v in (*rad, d, a)]
        gk[k] += 1j * STEP
        xk, yk = _hinge(gk[6], gk[7], gk[:3], gk[3:6])[:2]
        sens.append(math.hypot(xk.imag, yk.imag) / STEP)
    return {"C1": (x, y), "BC": b, "CD": c, "beta": beta, "gamma_min": min(gammas) if crank or free else 0.0,
            "grashof": ls[0] + ls[3] <= ls[1] + ls[2], "crank": crank,
            "branch_ok": len(set(branches)) == 1 and 0 not in branches, "order_ok": crank or free,
            "sens_C1": max(sens[:6]) * math.radians(0.1), "sens_C1_mm": max(sens[6:]) * 0.1}
