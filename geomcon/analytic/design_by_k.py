"""Closed forms for design by the time-ratio coefficient K (independent of the θ-circle construction).

In the triangle A C1 C2 of any K-design, C1 C2 = L is seen from A under θ; with u = AC1 = b − a and
v = AC2 = b + a the law of cosines and the area give

    L² = (v − u)² + 2uv(1 − cos θ) = (v + u)² − 2uv(1 + cos θ),

so one more condition (the offset e = uv·sin θ / L, the crank a or the coupler b) fixes u and v.

Examples
--------
>>> r = crank_slider_design(K=1.5, H=50, e=20)
>>> round(r["AB"], 4), round(r["BC"], 4), round(r["alpha_max"], 4)
(21.5067, 46.5171, 63.1624)
>>> r = crank_slider_design(K=1.5, H=50, AB=r["AB"])
>>> round(r["e"], 9)
20.0
"""
from __future__ import annotations

import math

from ..errors import NotAMechanism
from ..tolerance import REL_TOL
from .linkages import _tri_angle, gamma_from_positions_xy, theta_from_k


def _sides_from_e(L: float, th: float, e: float) -> tuple[float, float]:
    """(u, v) of the triangle with base L seen under θ (rad) from a point at height e above the base.

    (v − u)² = L² − 4uv·sin²(θ/2) = L(L − 2e·tan(θ/2)) and (v + u)² = L(L + 2e·cot(θ/2)) (uv = eL/sin θ);
    u = uv/v, not (s − d)/2, which cancels when A is near C1."""
    uv = e * L / math.sin(th)
    d = math.sqrt(max(0.0, L * (L - 2.0 * e * math.tan(th / 2.0))))   # v − u
    s = math.sqrt(L * (L + 2.0 * e / math.tan(th / 2.0)))             # v + u
    return 2.0 * uv / (s + d), (s + d) / 2.0


def _sides_from_a(L: float, th: float, a: float) -> tuple[float, float]:
    uv = (L - 2.0 * a) * (L + 2.0 * a) / (4.0 * math.sin(th / 2.0) ** 2)
    s = math.sqrt(4.0 * a * a + 4.0 * uv)
    return 2.0 * uv / (s + 2.0 * a), (s + 2.0 * a) / 2.0


def _sides_from_b(L: float, th: float, b: float) -> tuple[float, float]:
    """(v − u)² = 4b² − 4uv = (L − 2b·sin(θ/2))(L + 2b·sin(θ/2)) / cos²(θ/2): no cancellation as θ → 0."""
    uv = (2.0 * b - L) * (2.0 * b + L) / (4.0 * math.cos(th / 2.0) ** 2)
    sh = math.sin(th / 2.0)
    d = math.sqrt(max(0.0, (L - 2.0 * b * sh) * (L + 2.0 * b * sh))) / math.cos(th / 2.0)
    return 2.0 * uv / (2.0 * b + d), (2.0 * b + d) / 2.0


def _foot_from_e(L: float, th: float, e: float) -> float:
    """X = FC1, the distance of C1 from the foot F of A on the guide, given the offset e.

    The vertical through F meets the θ-circle at heights e and H·cot θ − e, so the power of F gives
    X(X + L) = e(L·cot θ − e); the root is taken as 2c/(L + √(L² + 4c)), without cancellation.

    >>> round(_foot_from_e(1.0, math.pi / 4, 0.5), 12), round((math.sqrt(2.0) - 1.0) / 2.0, 12)
    (0.207106781187, 0.207106781187)
    """
    c = e * (L / math.tan(th) - e)
    return 2.0 * max(0.0, c) / (L + math.sqrt(L * L + 4.0 * max(0.0, c)))


def _foot_from_a(L: float, th: float, a: float, s: float) -> float:
    """X = FC1 given the crank a (s = AC1 + AC2): X = ((2a·s)² − L⁴)/(2L(2a·s + L²)) with the numerator
    factored exactly, (L² − 4a²)·cot²(θ/2)·(2a − L·tan(θ/2))(2a + L·tan(θ/2)): zero at Q (a = (L/2)·tan(θ/2))
    without the cancellation of 2a·s − L²."""
    t2 = math.tan(th / 2.0)
    num = (L - 2.0 * a) * (L + 2.0 * a) * (2.0 * a - L * t2) * (2.0 * a + L * t2) / (t2 * t2)
    return max(0.0, num) / (2.0 * L * (2.0 * a * s + L * L))


def _foot_from_b(L: float, th: float, b: float, d: float) -> float:
    """X = FC1 given the coupler b (d = AC2 − AC1): X = ((2b·d)² − L⁴)/(2L(2b·d + L²)) with the numerator
    (4b² − L²)·tan²(θ/2)·(L·cot(θ/2) − 2b)(L·cot(θ/2) + 2b): zero at Q (b = (L/2)·cot(θ/2))."""
    t2 = math.tan(th / 2.0)
    num = (2.0 * b - L) * (2.0 * b + L) * t2 * t2 * (L / t2 - 2.0 * b) * (L / t2 + 2.0 * b)
    return max(0.0, num) / (2.0 * L * (2.0 * b * d + L * L))


def _gamma_min(u: float, v: float, e: float, X: float) -> float:
    """γmin (deg) of the crank-slider with AC1 = u, AC2 = v, offset e and FC1 = X: the crank perpendicular
    to the guide away from it, cos γ = (a + e)/b, with b − a − e = u − e = X²/(u + e) (never u − e itself,
    which cancels near the end Q of the arc) and b + a + e = v + e."""
    a = (v - u) / 2.0
    gap = X * X / (u + e) if u + e > 0 else 0.0
    return math.degrees(math.atan2(math.sqrt(gap * (v + e)), a + e))


def crank_slider_design(K: float, H: float, *, e: float | None = None, AB: float | None = None,
                        BC: float | None = None) -> dict[str, float]:
    """AB, BC, e of the offset crank-slider with time ratio K and stroke H, given exactly one of e, AB, BC.

    The pivot A lies at height e above the guide and to the outside of the stroke (the foot of A is not
    between C1 and C2); the feasible ranges are 0 < e ≤ H·cot θ, (H/2)·tan(θ/2) ≤ AB < H/2 and
    H/2 < BC ≤ (H/2)·cot(θ/2). Raises NotAMechanism outside them. γmin comes from the distance FC1 of C1
    from the foot of A, in a closed form of the given condition that vanishes at Q without cancellation.
    """
    th = math.radians(theta_from_k(K))
    if not 0.0 < th < math.pi / 2:
        raise NotAMechanism(f"θ = {math.degrees(th):g}° must lie in (0°, 90°) for a crank-slider designed by K")
    if e is not None:
        if not 0.0 < e <= H / math.tan(th) * (1 + 1e-12):
            raise NotAMechanism(f"e = {e:g} outside (0, H·cot θ = {H / math.tan(th):g}]")
        u, v = _sides_from_e(H, th, e)
        X = _foot_from_e(H, th, e)
    elif AB is not None:
        lo, hi = H / 2 * math.tan(th / 2), H / 2
        if not lo * (1 - 1e-12) <= AB < hi:
            raise NotAMechanism(f"AB = {AB:g} outside [H/2·tan(θ/2) = {lo:g}, H/2 = {hi:g})")
        u, v = _sides_from_a(H, th, AB)
        X = _foot_from_a(H, th, AB, u + v)
    elif BC is not None:
        lo, hi = H / 2, H / 2 / math.tan(th / 2)
        if not lo < BC <= hi * (1 + 1e-12):
            raise NotAMechanism(f"BC = {BC:g} outside (H/2 = {lo:g}, H/2·cot(θ/2) = {hi:g}]")
        u, v = _sides_from_b(H, th, BC)
        X = _foot_from_b(H, th, BC, v - u)
    else:
        raise NotAMechanism("give exactly one of e, AB, BC")
    a, b = (v - u) / 2.0, (v + u) / 2.0
    ecc = u * v * math.sin(th) / H
    gamma = _gamma_min(u, v, ecc, X)
    return {"AB": a, "BC": b, "e": ecc, "theta": math.degrees(th), "K": K, "alpha_max": 90.0 - gamma,
            "gamma_min": gamma, "AC1": u, "AC2": v}


# ---------------------------------------------------------------------------------------------- crank-rocker
def _trilaterate(p: tuple[float, float], q: tuple[float, float], rp: float, rq: float) -> list[tuple[float, float]]:
    """The points at distance rp from p and rq from q (0, 1 or 2): the angle at p of the triangle p q A by
    Kahan's formula (accurate when the triangle is nearly flat), sides short of a triangle by REL_TOL only
    taken as flat."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    sides = sorted([rp, rq, d])
    if sides[2] - (sides[0] + sides[1]) > REL_TOL * sides[2]:
        return []
    base = math.atan2(dy, dx)
    turn = math.radians(_tri_angle(rp, d, rq))
    return [(p[0] + rp * math.cos(base + s * turn), p[1] + rp * math.sin(base + s * turn)) for s in (1, -1)]


def rocker_design_candidates(K: float, CD: float, c1: tuple[float, float], c2: tuple[float, float], *,
                             BC: float | None = None, AB: float | None = None, AC1: float | None = None,
                             frame_line: bool = False, AD: float | None = None) -> list[tuple[float, float]]:
    """Every position of A (D at the origin, rocker extremes at c1, c2) meeting the closing condition.

    No validity filter here: see :func:`rocker_design`.
    """
    th = math.radians(theta_from_k(K))
    L = math.dist(c1, c2)
    out: list[tuple[float, float]] = []
    if th == 0.0:                           # K = 1: A on the line C1C2, beyond one end
        ux, uy = (c2[0] - c1[0]) / L, (c2[1] - c1[1]) / L
        if frame_line:                      # meets the horizontal through D
            if abs(uy) < 1e-15:
                return []
            t = -c1[1] / uy
            return [(c1[0] + t * ux, 0.0)]
        if AD is not None:                  # at distance AD from D: t² + 2t(c1·u) + |c1|² − AD² = 0
            bq = c1[0] * ux + c1[1] * uy
            disc = bq * bq - (c1[0] ** 2 + c1[1] ** 2 - AD * AD)
            if disc < 0:
                return []
            return [(c1[0] + t * ux, c1[1] + t * uy) for t in (-bq - math.sqrt(disc), -bq + math.sqrt(disc))]
        raise NotAMechanism("K = 1 needs AD or frame_line")
    pairs: list[tuple[float, float]] = []   # (distance to c1, distance to c2)
    if BC is not None or AB is not None:
        if BC is not None:
            uv = (2 * BC - L) * (2 * BC + L) / (4 * math.cos(th / 2) ** 2)
            s, d = 2 * BC, math.sqrt(max(0.0, 4 * BC * BC - 4 * uv))
        else:
            uv = (L - 2 * AB) * (L + 2 * AB) / (4 * math.sin(th / 2) ** 2)
            d = 2 * AB
            s = math.sqrt(d * d + 4 * uv)
        u, v = (s - d) / 2, (s + d) / 2
        pairs = [(u, v), (v, u)]
    elif AC1 is not None:                   # triangle A c1 c2 with side AC1 and angle θ at A
        disc = L * L - (AC1 * math.sin(th)) ** 2
        if disc >= 0:
            for w in (AC1 * math.cos(th) - math.sqrt(disc), AC1 * math.cos(th) + math.sqrt(disc)):
                if w > 0:
                    pairs.append((AC1, w))
    elif frame_line:                        # A = (x, 0) with ∠c1 A c2 = θ: bracket and bisect the angle
        return _frame_line_points(c1, c2, th)
    elif AD is not None:                    # the frame given: a closed form (geomcon.analytic.design_by_k_frame)
        from .design_by_k_frame import frame_points
        return frame_points(c1, c2, th, AD)
    else:
        raise NotAMechanism("give one of BC, AB, AC1, frame_line")
    for rp, rq in pairs:
        if rp > 0 and rq > 0:
            out += _trilaterate(c1, c2, rp, rq)
    return out


def _frame_line_points(c1, c2, th: float) -> list[tuple[float, float]]:
    """The points A = (x, 0) that see c1c2 under θ, in closed form.

    With p = c1 − A, q = c2 − A, ∠c1Ac2 = θ exactly when σ·(p × q) > 0 and p·q = σ·(p × q)·cot θ for
    σ = ±1; p·q is quadratic and p × q linear in x, so each σ gives sin θ·x² + βx + γ = 0 (roots by the
    stable form); roots with σ·(p × q) ≤ 0 see the chord under 180° − θ and are dropped.
    """
    (x1, y1), (x2, y2) = c1, c2
    s, c = math.sin(th), math.cos(th)
    out = []
    for sigma in (1.0, -1.0):
        # p·q = x² − (x1 + x2)x + x1x2 + y1y2 ;  p × q = (x1y2 − y1x2) + x(y1 − y2)
        qa = s
        qb = -s * (x1 + x2) - sigma * c * (y1 - y2)
        qc = s * (x1 * x2 + y1 * y2) - sigma * c * (x1 * y2 - y1 * x2)
        disc = qb * qb - 4 * qa * qc
        if disc < 0:
            continue
        t = -0.5 * (qb + math.copysign(math.sqrt(disc), qb))
        for x in {t / qa, qc / t} if t != 0 else {0.0}:
            if sigma * ((x1 * y2 - y1 * x2) + x * (y1 - y2)) > 0:
                out.append((x, 0.0))
    return sorted(out)


def angle_deg_at(v: tuple[float, float], p: tuple[float, float], q: tuple[float, float]) -> float:
    """The unsigned angle pvq (deg) by atan2 of the cross and dot products.

    >>> angle_deg_at((0.0, 0.0), (1.0, 0.0), (0.0, 2.0))
    90.0
    """
    px, py, qx, qy = p[0] - v[0], p[1] - v[1], q[0] - v[0], q[1] - v[1]
    return math.degrees(math.atan2(abs(px * qy - py * qx), px * qx + py * qy))


def rocker_design_valid(a: float, b: float, CD: float, AD: float, h1: float, h2: float) -> bool:
    """The one validity rule of a crank-rocker designed from its extreme positions (construction and twin).

    ``a``, ``b``: crank and coupler; ``h1``, ``h2``: signed distances of the two extreme positions from the
    frame line A→D. Valid when AB is a crank — 0 < a strictly shortest, and Grashof a + l ≤ p + q within
    REL_TOL·l (the change-point boundary counts as a crank, as in ``crank_rocker.extremes``) — and both
    extreme positions lie strictly on one side of AD, each farther than REL_TOL·max(b, CD, AD) from it
    (otherwise they are not the extreme positions of one assembly of the linkage).

    >>> rocker_design_valid(50, 70, 80, 90, 40.0, 60.0), rocker_design_valid(50, 70, 80, 90, 40.0, -1.0)
    (True, False)
    """
    scale = max(b, CD, AD)
    if not 0.0 < a or AD <= REL_TOL * scale:
        return False
    if h1 * h2 <= 0 or min(abs(h1), abs(h2)) <= REL_TOL * scale:
        return False
    ls = sorted([b, CD, AD])
    return a < ls[0] and a + ls[2] <= ls[0] + ls[1] + REL_TOL * ls[2]


def rocker_design(K: float, CD: float, c1: tuple[float, float], c2: tuple[float, float], *,
                  c1_folded_only: bool = False, **closing: float | bool | None) -> list[dict[str, float]]:
    """Every valid crank-rocker for the rocker extremes c1, c2 (D at the origin) and one closing condition.

    Valid by :func:`rocker_design_valid`: AB is a crank by Grashof and the two extremes lie on one side of
    the frame line AD (otherwise the linkage's real extreme positions are not c1 and c2). Each solution gives
    A, which extreme is folded, AB, BC, AD and the extreme-position figures of the designed linkage: θ as the
    answer defines it, 180°(K − 1)/(K + 1) (as the frame and links forms; the designed linkage's own θ is the
    back-substitution's K), ψ = ∠c1Dc2 and γmin (:func:`geomcon.analytic.linkages.crank_rocker_gamma_from_positions`) from the points,
    not read back from the designed lengths, which lose an extreme position lying within rounding of the frame
    line (the Grashof boundary). ``c1_folded_only`` keeps only the designs in which c1 is the folded extreme
    (with ψ given the two extremes are symmetric, and the others are their mirror images).
    """
    theta = theta_from_k(K)
    return [{"AB": a, "BC": b, "CD": CD, "AD": ad, "Ax": ax, "Ay": ay, "c1_folded": folded, "theta": theta, "K": K,
             "psi": psi, "gamma_min": gamma}
            for a, b, ad, ax, ay, folded, psi, gamma in rocker_design_rows(K, CD, c1, c2, c1_folded_only, closing)]


def rocker_design_rows(K: float, CD: float, c1: tuple[float, float], c2: tuple[float, float], c1_folded_only: bool,
                       closing: dict) -> list[tuple[float, float, float, float, float, float, float, float]]:
    """:func:`rocker_design`'s solutions as plain floats, ``(AB, BC, AD, Ax, Ay, c1_folded, psi, gamma_min)``
    each: what the twin of ``crank_rocker.design_by_K`` reads, with no dictionary per candidate.

    >>> c1, c2 = (-79.93483318692972, 278.7658918221125), (79.93483318692975, 278.7658918221125)   # 001-10
    >>> [[round(x, 3) for x in row] for row in rocker_design_rows(1.25, 290.0, c1, c2, True, {"BC": 260.0})]
    [[66.981, 260.0, 467.64, -217.866, 413.789, 1.0, 32.0, 27.204], [66.981, 260.0, 261.013, -217.866, 143.743, 1.0, 32.0, 40.86]]
    """
    c1x, c1y = c1
    c2x, c2y = c2
    psi = None
    out = []
    for ax, ay in rocker_design_candidates(K, CD, c1, c2, **closing):
        d1, d2 = _hypot(ax - c1x, ay - c1y), _hypot(ax - c2x, ay - c2y)      # math.dist((ax, ay), c1): the same
        if c1_folded_only and not d1 < d2:
            continue
        a, b = abs(d2 - d1) / 2, (d1 + d2) / 2
        ad = _hypot(ax, ay)
        if ad == 0:
            continue
        h1 = (ax * c1y - ay * c1x) / ad  # signed distances from the line A→D (D at the origin)
        h2 = (ax * c2y - ay * c2x) / ad
        if not rocker_design_valid(a, b, CD, ad, h1, h2):
            continue
        if psi is None:                  # ∠c1Dc2: one value for every candidate
            psi = angle_deg_at((0.0, 0.0), c1, c2)
        if d1 < d2:
            out.append((a, b, ad, ax, ay, 1.0, psi, gamma_from_positions_xy(ax, ay, 0.0, 0.0, c1x, c1y, c2x, c2y)))
        else:
            out.append((a, b, ad, ax, ay, 0.0, psi, gamma_from_positions_xy(ax, ay, 0.0, 0.0, c2x, c2y, c1x, c1y)))
    return out


_hypot = math.hypot


# ---------------------------------------------------------------------------------------------- guide bars
def guide_bar_design(K: float, *, AC: float | None = None, AB: float | None = None) -> dict[str, float]:
    """Oscillating guide-bar with time ratio K: ψ = θ and AB = AC·sin(θ/2) (the guide bar tangent to the
    crank circle at the extremes).

    >>> r = guide_bar_design(1.8, AB=70)
    >>> round(r["AC"], 2), round(r["psi"], 2)
    (161.33, 51.43)
    """
    th = theta_from_k(K)
    s = math.sin(math.radians(th / 2))
    if AC is not None:
        AB = AC * s
    elif AB is not None:
        AC = AB / s
    else:
        raise NotAMechanism("give AC or AB")
    return {"AB": AB, "AC": AC, "psi": th, "theta": th, "K": K}


def shaper_design(K: float, H: float, *, AC: float | None = None, AB: float | None = None,
                  alpha_allow: float | None = None) -> dict[str, float]:
    """The guide-bar six-bar of a shaper: the ram's stroke H is the chord of D's arc, H = 2·CD·sin(θ/2); the
    ram's guide at the middle of the arc's sagitta, h = CD(1 + cos(θ/2))/2 from C, keeps the largest
    deviation of D from it, CD(1 − cos(θ/2))/2, as small as it can be; with a pressure-angle limit the
    shortest coupler is DE = that deviation / sin(α_allow).

    >>> r = shaper_design(2, 300, AB=75)
    >>> round(r["AC"], 6), round(r["CD"], 6), round(r["h"], 3)
    (150.0, 300.0, 279.904)
    """
    out = guide_bar_design(K, AC=AC, AB=AB)
    half = math.radians(out["theta"] / 2)
    CD = H / (2 * math.sin(half))
    out.update(H=H, CD=CD, h=CD * (1 + math.cos(half)) / 2, deviation=CD * (1 - math.cos(half)) / 2)
    if alpha_allow is not None:
        out["DE_min"] = out["deviation"] / math.sin(math.radians(alpha_allow))
    return out


# ---------------------------------------------------------------------------------------------- optimum
def _working_parts(H: float, th: float, a: float) -> tuple[float, float, float, float, float, float]:
    """(γ_fold, γ_near in radians, u, v, e, X) of the crank-slider with crank ``a`` on the θ-circle.

    γ_fold = atan2(X, e) at the folded position (√(u² − e²) is X itself); γ_near with the crank
    perpendicular to the guide towards it, cos γ = |a − e|/b, where b − |a − e| is u + e or v − e exactly."""
    u, v = _sides_from_a(H, th, a)
    e = u * v * math.sin(th) / H
    X = _foot_from_a(H, th, a, u + v)
    b = (u + v) / 2.0
    d = abs(a - e)
    near_gap = u + e if a >= e else v - e              # b − |a − e|
    g_fold = math.atan2(X, e)
    g_near = math.atan2(math.sqrt(max(0.0, near_gap * (b + d))), d)
    return g_fold, g_near, u, v, e, X


def working_stroke_gamma(K: float, H: float, a: float) -> tuple[float, float, float, float]:
    """(γ_w,min, BC, e, γmin) of the crank-slider with crank ``a`` on the θ-circle: the working (slow) stroke's
    smallest transmission angle is the smaller of the one at the folded position, atan2(FC1, e), and
    the one with the crank perpendicular to the guide towards it, acos(|a − e| / b); γmin of the cycle by
    :func:`_gamma_min` (no cancellation in b − a − e).

    >>> [round(x, 6) for x in working_stroke_gamma(1.5, 100, 48.593)]
    [49.562104, 61.757413, 8.538747, 22.316648]
    """
    th = math.radians(theta_from_k(K))
    g_fold, g_near, u, v, e, X = _working_parts(H, th, a)
    return math.degrees(min(g_fold, g_near)), (u + v) / 2.0, e, _gamma_min(u, v, e, X)


def crank_slider_best(K: float, H: float, *, e_min: float = 0.0, e_max: float = math.inf) -> dict[str, float]:
    """The crank on the admissible range [(H/2)·tan(θ/2), H/2) that maximises γ_w,min (seed 004).

    The folded position's angle rises from 0° (A at Q) and the other falls to 0° (A at C1), so the optimum is
    where they are equal: found by bisection on their difference, then limited to the offsets allowed.

    >>> r = crank_slider_best(1.5, 100)
    >>> round(r["AB"], 3), round(r["gamma_w_min"], 3)
    (48.593, 49.563)
    """
    th = math.radians(theta_from_k(K))
    lo, hi = H / 2 * math.tan(th / 2), H / 2

    # each bisection stops when a step leaves its bracket as it was (the midpoint rounds onto an end): every
    # further step of the 300 would repeat that one, so the result is the same
    x0, x1 = lo * (1 + 1e-15), hi * (1 - 1e-15)
    for _ in range(300):
        m = (x0 + x1) / 2
        f, n = _working_parts(H, th, m)[:2]
        if f < n:
            if x0 == m:
                break
            x0 = m
        else:
            if x1 == m:
                break
            x1 = m
    a = (x0 + x1) / 2
    # offsets decrease from e(lo) to 0 as a grows: clamp to the allowed band
    e_of = lambda x: _working_parts(H, th, x)[4]  # noqa: E731
    if e_of(a) > e_max or e_of(a) < e_min:
        target = e_max if e_of(a) > e_max else e_min
        y0, y1 = lo * (1 + 1e-15), hi * (1 - 1e-15)
        for _ in range(300):
            m = (y0 + y1) / 2
            if e_of(m) > target:
                if y0 == m:
                    break
                y0 = m
            else:
                if y1 == m:
                    break
                y1 = m
        a = (y0 + y1) / 2
    gw, b, e, gg = working_stroke_gamma(K, H, a)
    return {"AB": a, "BC": b, "e": e, "gamma_w_min": gw, "gamma_min": gg, "alpha_max": 90.0 - gg,
            "theta": math.degrees(th), "K": K}


def best_table(H: float = 100.0, Ks: tuple[float, ...] = tuple(round(1.05 + 0.05 * i, 2) for i in range(14))):
    """The optimum for each K (seed 004's Table 1, recomputed in full)."""
    return [crank_slider_best(K, H) for K in Ks]
