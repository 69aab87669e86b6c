"""Twins of the three-position syntheses: circumcentres and the coupler-frame solve by linear algebra.

Nothing here draws a bisector. The fixed pivot of a link whose moving end passes P1, P2, P3 is the centre
O of the circle through them, found from the 2×2 linear system ``2(P_k − P1)·(O − P1) = |P_k − P1|²``
(k = 2, 3) by Cramer's rule. The moving hinge C of a coupler whose positions are given as (B_i, u_i) — the
point B and the unit direction u of the coupler line BK — is found in the coupler's own frame: with
C_i = B_i + c₁·u_i + c₂·u_i⊥ and w_i = B_i − D, equal distances |C_i − D| = |C_1 − D| are two linear
equations in (c₁, c₂):

    2c₁·(w_i·u_i − w_1·u_1) + 2c₂·(w_i·u_i⊥ − w_1·u_1⊥) = |w_1|² − |w_i|²,   i = 2, 3.

Every function is written with + − × ÷ and ``** 0.5`` only, so it also runs on complex numbers: the
**sensitivities** are complex-step derivatives (f(x + ih) = f(x) + ih·f′(x) + O(h²), the imaginary part
carries the derivative to machine precision, no cancellation), and the worst case over the direction of a
0.1 mm drafting error of one given point is 0.1 times the spectral norm of the 2×2 Jacobian (numpy's SVD).

Examples
--------
>>> circumcentre((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0))
(0.0, 0.0)
>>> r = three_positions((0, 0), (-10, 30), (-10, 0), (0, 50), (4, 78), (40, 0))
>>> [round(r[k], 6) for k in ("AB", "BC", "CD", "AD")]
[15.811388, 50.0, 58.933356, 75.651441]
>>> r["crank"], r["branch_ok"], r["order_ok"]          # C2 lies on the other side of B→D: a branch defect
(True, False, True)
"""
from __future__ import annotations

import math
from typing import Any, Callable, Sequence


from .fourbar_drive import (angle_of, arc_through, bd_extremes, branch_of, dead_point_free, turns_fully)
from .linkages import _tri_angle

XY = tuple[float, float]
DRAFT = 0.1
"""The drafting error the sensitivities are quoted for, mm."""


# ------------------------------------------------------------------------------------------ linear algebra
def circumcentre(P1: Sequence, P2: Sequence, P3: Sequence) -> tuple:
    """Centre of the circle through three points by Cramer's rule (relative to P1, for accuracy).

    Raises
    ------
    ZeroDivisionError
        When the points are collinear (the system is singular).
    """
    ax, ay = P2[0] - P1[0], P2[1] - P1[1]
    bx, by = P3[0] - P1[0], P3[1] - P1[1]
    a2, b2 = ax * ax + ay * ay, bx * bx + by * by
    det = 2.0 * (ax * by - ay * bx)
    return (P1[0] + (a2 * by - b2 * ay) / det, P1[1] + (ax * b2 - bx * a2) / det)


def _unit(v: Sequence) -> tuple:
    n = (v[0] * v[0] + v[1] * v[1]) ** 0.5
    return (v[0] / n, v[1] / n)


def coupler_hinge(D: Sequence, Bs: Sequence[Sequence], us: Sequence[Sequence]) -> tuple:
    """C1: the coupler point equidistant from D in the three coupler positions (B_i, u_i).

    ``us`` are the directions of the coupler line at the three positions (need not be unit vectors).
    """
    us = [_unit(u) for u in us]
    rows = []
    for B, u in zip(Bs, us):
        w = (B[0] - D[0], B[1] - D[1])
        rows.append((w[0] * u[0] + w[1] * u[1], -w[0] * u[1] + w[1] * u[0], w[0] * w[0] + w[1] * w[1]))
    (p1, q1, n1), (p2, q2, n2), (p3, q3, n3) = rows
    a11, a12, r1 = 2.0 * (p2 - p1), 2.0 * (q2 - q1), n1 - n2
    a21, a22, r2 = 2.0 * (p3 - p1), 2.0 * (q3 - q1), n1 - n3
    det = a11 * a22 - a12 * a21
    c1, c2 = (r1 * a22 - r2 * a12) / det, (a11 * r2 - a21 * r1) / det
    B1, u1 = Bs[0], us[0]
    return (B1[0] + c1 * u1[0] - c2 * u1[1], B1[1] + c1 * u1[1] + c2 * u1[0])


def worst_shift(f: Callable[[list], Sequence], points: Sequence[XY], which: Sequence[int] | None = None) -> float:
    """Largest displacement of the point ``f(points)`` when one of ``points`` (those listed in ``which``,
    default all) moves by :data:`DRAFT` mm in any direction: 0.1·max‖∂f/∂P‖₂ by complex-step derivatives."""
    pts = [tuple(complex(c) for c in p) for p in points]
    scale = max(max(abs(c) for c in p) for p in points) or 1.0
    h = 1e-30 * scale
    worst = 0.0
    for k in (range(len(points)) if which is None else which):
        cols = []
        for axis in (0, 1):
            moved = [list(p) for p in pts]
            moved[k][axis] += 1j * h
            out = f(moved)
            cols.append([out[0].imag / h, out[1].imag / h])
        worst = max(worst, _spectral_norm_2x2(cols[0][0], cols[1][0], cols[0][1], cols[1][1]))
    return DRAFT * worst


def _spectral_norm_2x2(a: float, b: float, c: float, d: float) -> float:
    """‖[[a, b], [c, d]]‖₂, the largest singular value, in closed form: σ² = (S + √((a² + b² − c² − d²)² +
    4(ac + bd)²))/2 with S the sum of squares (no numpy: a linkage problem never loads it).

    >>> _spectral_norm_2x2(3.0, 0.0, 0.0, -4.0), round(_spectral_norm_2x2(1.0, 1.0, 0.0, 1.0), 15)
    (4.0, 1.618033988749895)
    """
    s = a * a + b * b + c * c + d * d
    root = math.hypot(a * a + b * b - c * c - d * d, 2.0 * (a * c + b * d))
    return math.sqrt((s + root) / 2.0)


# ------------------------------------------------------------------------------------------ the designed linkage
def _acute(x: float) -> float:
    return min(x, 180.0 - x)


def linkage_report(A: XY, D: XY, Bs: Sequence[XY], Cs: Sequence[XY]) -> dict[str, Any]:
    """Lengths, Grashof class, transmission angles and the branch and order defects of the four-bar A B C D
    designed to pass the positions (B_i, C_i).

    ``gamma_min`` is taken over the full turn when AB is a crank, else over the working arc (the input
    turning from B1 through B2 to B3); ``gamma_min_work`` always over the working arc. A dead point on the
    working arc gives 0.
    """
    dist = lambda P, Q: math.hypot(Q[0] - P[0], Q[1] - P[1])   # noqa: E731
    AB, BC, CD, AD = dist(A, Bs[0]), dist(Bs[0], Cs[0]), dist(D, Cs[0]), dist(A, D)
    s, p, q, l = sorted((AB, BC, CD, AD))
    margin = (p + q) - (s + l)
    tol = 1e-13 * l
    crank = turns_fully(AB, BC, CD, AD)
    phis = [angle_of(A, B) for B in Bs]
    start, sweep = arc_through(*phis)
    lo, hi = bd_extremes(A, D, AB, start, sweep)
    order_ok = crank or dead_point_free(lo, hi, BC, CD)

    def gamma(bd_lo: float, bd_hi: float) -> float:
        return min(_acute(_tri_angle(BC, CD, bd_lo)), _acute(_tri_angle(BC, CD, bd_hi)))

    work = gamma(lo, hi) if order_ok else 0.0
    sides = [branch_of(B, C, D) for B, C in zip(Bs, Cs)]
    return {
        "AB": AB, "BC": BC, "CD": CD, "AD": AD,
        "grashof": margin >= -tol, "grashof_margin": margin,
        "crank": crank, "output_crank": turns_fully(CD, BC, AB, AD),
        "gamma_min": gamma(abs(AD - AB), AD + AB) if crank else work,
        "gamma_min_work": work,
        "branch_ok": len(set(sides)) == 1 and sides[0] != 0,
        "order_ok": order_ok,
        "phi": tuple(phis),
    }


# ------------------------------------------------------------------------------------------ drafted data
def rigid_fit(anchors: Sequence[XY], pts: Sequence[XY]) -> list[XY]:
    """Drafted positions of one rigid link (anchor_i → point_i) made rigid: the link's length is the mean
    of the three drawn lengths and each point is moved along its own line from its anchor to it — the rule
    the recipes document (their code is separate).

    >>> rigid_fit([(0.0, 0.0)] * 3, [(3.0, 4.0), (0.0, 5.003), (-5.003, 0.0)])[1]
    (0.0, 5.002)
    """
    lens = [math.hypot(p[0] - a[0], p[1] - a[1]) for a, p in zip(anchors, pts)]
    r = math.fsum(lens) / 3.0
    out = []
    for a, p, d in zip(anchors, pts, lens):
        k = r / d if d > 0.0 else 1.0
        out.append((a[0] + (p[0] - a[0]) * k, a[1] + (p[1] - a[1]) * k) if k != 1.0 else tuple(p))
    return out


# ------------------------------------------------------------------------------------------ the two twins
def three_positions(B1: XY, B2: XY, B3: XY, C1: XY, C2: XY, C3: XY) -> dict[str, Any]:
    """``four_bar.three_positions``: A and D as circumcentres, the linkage report and the sensitivities.
    Drafted data (|B_iC_i| not quite equal) are made rigid by :func:`rigid_fit` (C_i moved along B_iC_i)."""
    Bs = [B1, B2, B3]
    Cs = rigid_fit(Bs, [C1, C2, C3])
    A = tuple(float(v) for v in circumcentre(*Bs))
    D = tuple(float(v) for v in circumcentre(*Cs))
    out = linkage_report(A, D, Bs, Cs)
    out.update(A=A, D=D, sens_A=worst_shift(lambda p: circumcentre(*p), Bs),
               sens_D=worst_shift(lambda p: circumcentre(*p), Cs))
    return out


def coupler_directions(Bs: Sequence[XY], Ks: Sequence[XY] | None, angles: Sequence[float] | None) -> list[XY]:
    """Directions of the coupler line: B_i→K_i, or at the given angles (deg)."""
    if Ks is not None:
        return [(K[0] - B[0], K[1] - B[1]) for B, K in zip(Bs, Ks)]
    return [(math.cos(math.radians(a)), math.sin(math.radians(a))) for a in angles]


def three_positions_fixed_pivots(A: XY, D: XY, Bs: Sequence[XY], Ks: Sequence[XY] | None = None,
                                 angles: Sequence[float] | None = None) -> dict[str, Any]:
    """``four_bar.three_positions_fixed_pivots``: C1 by the coupler-frame solve, C2 and C3 by carrying it with
    the coupler, the linkage report and the sensitivity of C1 (to D, the B_i and the K_i; A does not enter).
    Drafted B_i (|AB_i| not quite equal) are made rigid by :func:`rigid_fit` (moved along AB_i); the coupler's
    directions B_iK_i are those drawn (K_i moves with B_i)."""
    us = coupler_directions(Bs, Ks, angles)
    fitted = rigid_fit([A] * 3, Bs)
    if Ks is not None:
        Ks = [(K[0] + F[0] - B[0], K[1] + F[1] - B[1]) for B, F, K in zip(Bs, fitted, Ks)]
    Bs = fitted
    C1 = tuple(float(v) for v in coupler_hinge(D, Bs, us))
    u1 = _unit(us[0])
    # C1 in the coupler frame of position 1, then carried to positions 2 and 3
    dx, dy = C1[0] - Bs[0][0], C1[1] - Bs[0][1]
    c1, c2 = dx * u1[0] + dy * u1[1], -dx * u1[1] + dy * u1[0]
    Cs = [C1]
    for B, u in zip(Bs[1:], us[1:]):
        u = _unit(u)
        Cs.append((B[0] + c1 * u[0] - c2 * u[1], B[1] + c1 * u[1] + c2 * u[0]))
    out = linkage_report(A, D, Bs, Cs)
    if Ks is not None:
        pts = [D, *Bs, *Ks]
        f = lambda p: coupler_hinge(p[0], p[1:4], [(k[0] - b[0], k[1] - b[1]) for b, k in zip(p[1:4], p[4:7])])  # noqa: E731
    else:
        pts = [D, *Bs]
        f = lambda p: coupler_hinge(p[0], p[1:4], us)  # noqa: E731
    out.update(C1=C1, C2=Cs[1], C3=Cs[2], sens_C=worst_shift(f, pts))
    return out
