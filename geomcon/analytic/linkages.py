"""Closed forms for the extreme positions of the basic linkages (law of cosines, right triangles).

All lengths in mm, all angles in degrees. Each function returns a dict keyed by the recipe's answer names.

Examples
--------
>>> r = crank_rocker_extremes(AB=50, BC=70, CD=80, AD=90)
>>> round(r["theta"], 4), round(r["gamma_min"], 4)
(12.5056, 29.9947)
>>> round(crank_slider_extremes(AB=120, BC=250, e=60)["H"], 3)
249.777
>>> guide_bar_extremes(AB=145, AC=290)["theta"]
60.00000000000001
"""
from __future__ import annotations

import math


def _tri_angle(x: float, y: float, z: float) -> float:
    """The angle (deg) between sides x and y of a triangle whose third side is z (opposite the angle).

    Kahan's formula for needle-like triangles: accurate to a few ulps for any valid float sides, also when
    the triangle is nearly flat (angles near 0° or 180°), where the law of cosines loses half the digits.
    Sides that violate the triangle inequality by rounding only are taken as flat.

    >>> round(_tri_angle(3.0, 4.0, 5.0), 12), _tri_angle(1.0, 2.0, 3.0), _tri_angle(1.0, 2.0, 1.0)
    (90.0, 180.0, 0.0)
    """
    a, b, c = max(x, y), min(x, y), z
    mu = c - (a - b) if b >= c else b - (a - c)
    num = max(0.0, ((a - b) + c) * mu)
    den = max(0.0, (a + (b + c)) * ((a - c) + b))
    return math.degrees(2.0 * math.atan2(math.sqrt(num), math.sqrt(den)))


def _leg(hyp: float, leg: float) -> float:
    """The other leg of a right triangle, √((hyp − leg)(hyp + leg)) (no cancellation in hyp² − leg²)."""
    return math.sqrt(max(0.0, (hyp - leg) * (hyp + leg)))


def k_from_theta(theta: float) -> float:
    """Time-ratio coefficient K = (180° + θ)/(180° − θ)."""
    return (180.0 + theta) / (180.0 - theta)


def theta_from_k(K: float) -> float:
    """Crank angle between the extreme positions θ = 180°(K − 1)/(K + 1)."""
    return 180.0 * (K - 1.0) / (K + 1.0)


def crank_rocker_extremes(AB: float, BC: float, CD: float, AD: float) -> dict[str, float]:
    """Extreme positions of a crank-rocker by the law of cosines.

    In the folded position (C1) A sees C at distance BC − AB, in the extended one (C2) at BC + AB; both C lie
    on the rocker circle about D. θ = ∠C1AD − ∠C2AD, ψ = ∠ADC2 − ∠ADC1 (both C on one side of AD). The
    transmission angle γ = ∠BCD (or its supplement) is extreme when the crank lies along the frame:
    BD = AD − AB (γ1) or AD + AB (γ2).
    """
    f, x = BC - AB, BC + AB
    c1ad, c2ad = _tri_angle(f, AD, CD), _tri_angle(x, AD, CD)
    adc1, adc2 = _tri_angle(AD, CD, f), _tri_angle(AD, CD, x)
    theta = abs(c1ad - c2ad)
    g1 = _tri_angle(BC, CD, AD - AB)
    g2 = _tri_angle(BC, CD, AD + AB)
    t1, t2 = min(g1, 180.0 - g1), min(g2, 180.0 - g2)
    return {
        "theta": theta,
        "psi": adc2 - adc1,
        "K": k_from_theta(theta),
        "gamma_min": min(t1, t2),
        "gamma_1": t1,
        "gamma_2": t2,
        "angle_C1AD": c1ad,
        "angle_C2AD": c2ad,
        "AC1": f,
        "AC2": x,
    }


def _excess(v: tuple[float, float], p: tuple[float, float], q: tuple[float, float]) -> float:
    """|vp| + |vq| − |pq| of the triangle v p q, as 4·|vp|·|vq|·sin²(δ/2)/perimeter with δ = 180° − ∠pvq
    taken by atan2 from the coordinates: no cancellation when v lies nearly on the segment pq."""
    return _excess_of(v, p, q, math.dist(v, p), math.dist(v, q), math.dist(p, q))


def _excess_of(v: tuple[float, float], p: tuple[float, float], q: tuple[float, float], x: float, y: float,
               z: float) -> float:
    """:func:`_excess` with its sides x = |vp|, y = |vq|, z = |pq| known (a distance is the same float either
    way round: a − b is −(b − a) exactly)."""
    if x + y + z == 0.0:
        return 0.0
    px, py, qx, qy = p[0] - v[0], p[1] - v[1], q[0] - v[0], q[1] - v[1]
    delta = math.atan2(abs(px * qy - py * qx), -(px * qx + py * qy))
    return 4.0 * x * y * math.sin(delta / 2.0) ** 2 / (x + y + z)


def crank_rocker_gamma_from_positions(A, D, Cf, Ce) -> float:
    """γmin (deg) of the crank-rocker with pivots A, D, folded extreme position Cf and extended Ce (points).

    With the crank along the frame (BD = AD ∓ AB) the triangle B C D has sides BC, CD, BD, and
    tan²(γ/2) = E_BC·E_CD / (P·E_BD) (E_x: the other two sides minus x, P the perimeter). Each E is an
    excess of the triangle A D Cf or A D Ce (e.g. BC + (AD − AB) − CD = ACf + AD − DCf), taken from the
    positions by :func:`_excess`: near the Grashof boundary an extreme position lies within rounding of the
    frame line and the excess, O(h²), is lost in the lengths but not in the points (γ stays ∝ h).

    >>> import math
    >>> A, D = (0.0, 0.0), (90.0, 0.0)
    >>> ex = crank_rocker_extremes(50, 70, 80, 90)
    >>> Cf = (20 * math.cos(math.radians(ex["angle_C1AD"])), 20 * math.sin(math.radians(ex["angle_C1AD"])))
    >>> Ce = (120 * math.cos(math.radians(ex["angle_C2AD"])), 120 * math.sin(math.radians(ex["angle_C2AD"])))
    >>> round(crank_rocker_gamma_from_positions(A, D, Cf, Ce), 9) == round(ex["gamma_min"], 9)
    True
    """
    ace, acf = math.dist(A, Ce), math.dist(A, Cf)           # the five distances once each (the six excesses
    c, d, dce = math.dist(D, Cf), math.dist(A, D), math.dist(D, Ce)      # share them)
    a = abs(ace - acf) / 2.0
    b = (ace + acf) / 2.0
    out = []
    for e_b, e_c, e_bd, per in (
            (_excess_of(D, A, Ce, d, dce, ace), _excess_of(A, D, Cf, d, acf, c), _excess_of(Ce, A, D, ace, dce, d),
             b + c + d - a),                                                             # B towards D
            (_excess_of(D, A, Cf, d, c, acf), _excess_of(A, D, Ce, d, ace, dce), _excess_of(Cf, A, D, acf, c, d),
             b + c + d + a)):                                                            # B away from D
        g = math.degrees(2.0 * math.atan2(math.sqrt(max(0.0, e_b * e_c)), math.sqrt(max(0.0, per * e_bd))))
        out.append(min(g, 180.0 - g))
    return min(out)


def crank_slider_extremes(AB: float, BC: float, e: float) -> dict[str, float]:
    """Extreme positions of an offset crank-slider from right triangles.

    With the guide at distance e from A, C1 (folded, AC1 = BC − AB) and C2 (extended, AC2 = BC + AB) lie at
    horizontal distances √(AC² − e²) from the foot of A. The pressure angle at the slider is
    α = asin(distance of B from the guide / BC): largest with B farthest from the guide (fast stroke); over
    the slow stroke it is largest at the folded position or with B nearest the guide.
    """
    a, b = AB, BC
    x1, x2 = _leg(b - a, e), _leg(b + a, e)          # C1, C2 measured along the guide from the foot of A
    theta = math.degrees(math.atan2(e, x1) - math.atan2(e, x2))
    # pressure angle with B at height y above the guide: tan α = y / √(b² − y²)
    gamma_fast = math.degrees(math.atan2(_leg(b, a + e), a + e))
    alpha_max = 90.0 - gamma_fast
    gamma_slow = min(math.degrees(math.atan2(x1, e)), math.degrees(math.atan2(_leg(b, abs(a - e)), abs(a - e))))
    return {
        "H": x2 - x1,
        "theta": theta,
        "K": k_from_theta(theta),
        "alpha_max": alpha_max,
        "gamma_min": gamma_fast,
        "gamma_min_fast": gamma_fast,
        "gamma_min_slow": gamma_slow,
        "AC1": b - a,
        "AC2": b + a,
    }


def guide_bar_extremes(AB: float, AC: float) -> dict[str, float]:
    """Extreme positions of the oscillating guide-bar: the guide bar is tangent to the crank circle.

    sin(ψ/2) = AB/AC and θ = ψ; the transmission angle of a centric guide-bar is always 90°.
    """
    psi = 2.0 * math.degrees(math.atan2(AB, _leg(AC, AB)))
    return {"theta": psi, "psi": psi, "K": k_from_theta(psi)}
