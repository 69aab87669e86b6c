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


def crank_rocker_gamma_from_positions(A, D, Cf, Ce) -> float:
    """γmin (deg) of the crank-rocker with pivots A, D, folded extreme position Cf and extended Ce (points).

    With the crank along the frame (BD = AD ∓ AB) the triangle B C D has sides BC, CD, BD, and
    tan²(γ/2) = E_BC·E_CD / (P·E_BD) (E_x: the other two sides minus x, P the perimeter). Each E is an
    excess of the triangle A D Cf or A D Ce (e.g. BC + (AD − AB) − CD = ACf + AD − DCf), taken from the
    positions by :func:`_excess_xy`: near the Grashof boundary an extreme position lies within rounding of the
    frame line and the excess, O(h²), is lost in the lengths but not in the points (γ stays ∝ h).
    Computed on plain floats by :func:`gamma_from_positions_xy`.

    >>> import math
    >>> A, D = (0.0, 0.0), (90.0, 0.0)
    >>> ex = crank_rocker_extremes(50, 70, 80, 90)
    >>> Cf = (20 * math.cos(math.radians(ex["angle_C1AD"])), 20 * math.sin(math.radians(ex["angle_C1AD"])))
    >>> Ce = (120 * math.cos(math.radians(ex["angle_C2AD"])), 120 * math.sin(math.radians(ex["angle_C2AD"])))
    >>> round(crank_rocker_gamma_from_positions(A, D, Cf, Ce), 9) == round(ex["gamma_min"], 9)
    True
    """
    return gamma_from_positions_xy(A[0], A[1], D[0], D[1], Cf[0], Cf[1], Ce[0], Ce[1])


def _excess_xy(vx: float, vy: float, px: float, py: float, qx: float, qy: float, x: float, y: float,
               z: float) -> float:
    """|vp| + |vq| − |pq| of the triangle v p q whose sides x = |vp|, y = |vq|, z = |pq| are known, as
    4·x·y·sin²(δ/2)/(x + y + z) with δ = 180° − ∠pvq taken by atan2 from the coordinates: no cancellation when
    v lies nearly on the segment pq.

    >>> round(_excess_xy(0.0, 0.0, 3.0, 0.0, 0.0, 4.0, 3.0, 4.0, 5.0), 12)    # 3 + 4 − 5
    2.0
    """
    s = x + y + z
    if s == 0.0:
        return 0.0
    px, py, qx, qy = px - vx, py - vy, qx - vx, qy - vy
    return 4.0 * x * y * _sin(_atan2(abs(px * qy - py * qx), -(px * qx + py * qy)) / 2.0) ** 2 / s


def gamma_from_positions_xy(ax: float, ay: float, dx: float, dy: float, fx: float, fy: float, ex: float,
                            ey: float) -> float:
    """:func:`crank_rocker_gamma_from_positions` of A = (ax, ay), D, Cf = (fx, fy) and Ce = (ex, ey) on plain
    floats: the five distances once each (``math.dist(p, q)`` is ``hypot`` of the differences, the same
    float; a − b is −(b − a) exactly) and the six excesses of :func:`_excess_xy`.

    >>> gamma_from_positions_xy(0.0, 0.0, 90.0, 0.0, 20.0, 0.0, 120.0, 0.0) == 0.0     # a dead point: γ = 0
    True
    """
    ace, acf = _hypot(ax - ex, ay - ey), _hypot(ax - fx, ay - fy)
    c, d, dce = _hypot(dx - fx, dy - fy), _hypot(ax - dx, ay - dy), _hypot(dx - ex, dy - ey)
    a = abs(ace - acf) / 2.0
    b = (ace + acf) / 2.0
    # B towards D: E_BC at D of A, Ce; E_CD at A of D, Cf; E_BD at Ce of A, D; perimeter b + c + d − a
    g = _excess_xy(dx, dy, ax, ay, ex, ey, d, dce, ace) * _excess_xy(ax, ay, dx, dy, fx, fy, d, acf, c)
    p = (b + c + d - a) * _excess_xy(ex, ey, ax, ay, dx, dy, ace, dce, d)
    g1 = _degrees(2.0 * _atan2(_sqrt(g if g > 0.0 else 0.0), _sqrt(p if p > 0.0 else 0.0)))   # max(0.0, …)
    # B away from D: at D of A, Cf; at A of D, Ce; at Cf of A, D; perimeter b + c + d + a
    g = _excess_xy(dx, dy, ax, ay, fx, fy, d, c, acf) * _excess_xy(ax, ay, dx, dy, ex, ey, d, ace, dce)
    p = (b + c + d + a) * _excess_xy(fx, fy, ax, ay, dx, dy, acf, c, d)
    g2 = _degrees(2.0 * _atan2(_sqrt(g if g > 0.0 else 0.0), _sqrt(p if p > 0.0 else 0.0)))
    t = 180.0 - g1
    t1 = t if t < g1 else g1                                   # min(g, 180° − g), each
    t = 180.0 - g2
    t2 = t if t < g2 else g2
    return t2 if t2 < t1 else t1


_hypot, _atan2, _sin, _sqrt, _degrees = math.hypot, math.atan2, math.sin, math.sqrt, math.degrees


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
