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

from .linkages import theta_from_k


def _sides_from_e(L: float, th: float, e: float) -> tuple[float, float]:
    """(u, v) of the triangle with base L seen under θ (rad) from a point at height e above the base."""
    uv = e * L / math.sin(th)
    d = math.sqrt(L * L - 2.0 * uv * (1.0 - math.cos(th)))        # v − u
    s = math.sqrt(L * L + 2.0 * uv * (1.0 + math.cos(th)))        # v + u
    return (s - d) / 2.0, (s + d) / 2.0


def _sides_from_a(L: float, th: float, a: float) -> tuple[float, float]:
    uv = (L * L - 4.0 * a * a) / (2.0 * (1.0 - math.cos(th)))
    s = math.sqrt(4.0 * a * a + 4.0 * uv)
    return (s - 2.0 * a) / 2.0, (s + 2.0 * a) / 2.0


def _sides_from_b(L: float, th: float, b: float) -> tuple[float, float]:
    uv = (4.0 * b * b - L * L) / (2.0 * (1.0 + math.cos(th)))
    d = math.sqrt(max(0.0, 4.0 * b * b - 4.0 * uv))
    return (2.0 * b - d) / 2.0, (2.0 * b + d) / 2.0


def crank_slider_design(K: float, H: float, *, e: float | None = None, AB: float | None = None,
                        BC: float | None = None) -> dict[str, float]:
    """AB, BC, e of the offset crank-slider with time ratio K and stroke H, given exactly one of e, AB, BC.

    The pivot A lies at height e above the guide and to the outside of the stroke (the foot of A is not
    between C1 and C2); the feasible ranges are 0 < e ≤ H·cot θ, (H/2)·tan(θ/2) ≤ AB < H/2 and
    H/2 < BC ≤ (H/2)·cot(θ/2). Raises ValueError outside them.
    """
    th = math.radians(theta_from_k(K))
    if not 0.0 < th < math.pi / 2:
        raise ValueError(f"θ = {math.degrees(th):g}° must lie in (0°, 90°) for a crank-slider designed by K")
    if e is not None:
        if not 0.0 < e <= H / math.tan(th) * (1 + 1e-12):
            raise ValueError(f"e = {e:g} outside (0, H·cot θ = {H / math.tan(th):g}]")
        u, v = _sides_from_e(H, th, e)
    elif AB is not None:
        lo, hi = H / 2 * math.tan(th / 2), H / 2
        if not lo * (1 - 1e-12) <= AB < hi:
            raise ValueError(f"AB = {AB:g} outside [H/2·tan(θ/2) = {lo:g}, H/2 = {hi:g})")
        u, v = _sides_from_a(H, th, AB)
    elif BC is not None:
        lo, hi = H / 2, H / 2 / math.tan(th / 2)
        if not lo < BC <= hi * (1 + 1e-12):
            raise ValueError(f"BC = {BC:g} outside (H/2 = {lo:g}, H/2·cot(θ/2) = {hi:g}]")
        u, v = _sides_from_b(H, th, BC)
    else:
        raise ValueError("give exactly one of e, AB, BC")
    a, b = (v - u) / 2.0, (v + u) / 2.0
    ecc = u * v * math.sin(th) / H
    gamma = math.degrees(math.atan2(math.sqrt(max(0.0, (b - a - ecc) * (b + a + ecc))), a + ecc))
    return {"AB": a, "BC": b, "e": ecc, "theta": math.degrees(th), "K": K, "alpha_max": 90.0 - gamma,
            "gamma_min": gamma, "AC1": u, "AC2": v}
