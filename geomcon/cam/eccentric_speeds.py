"""The eccentric-circle cam's follower speeds in closed form (the twin of ``cam.eccentric``'s v, a, ω2, ε2 and
their maxima): the exact motion of :mod:`geomcon.cam.eccentric` differentiated by hand.

Translating knife or roller, u = e − OA·cos φ, u′ = OA·sin φ, w = √(Rp² − u²), g = u·u′:

    y = OA·sin φ + w,  y′ = OA·cos φ − g/w,  y″ = −OA·sin φ − g′/w − g²/w³,
    y‴ = −OA·cos φ − g″/w − 3g·g′/w³ − 3g³/w⁵,   g′ = u′² + u·u″, g″ = 3u′·u″ + u·u‴;

a flat face: y = OA·sin φ + R. With δ the cam angle (dδ/dt = ω, dφ/dδ = ±1 by the sense of rotation),
v = ±ω·y′ and a = ω²·y″. The maxima over the turn: |y′| at a root of y″, |y″| at a root of y‴ (bracketed on a
grid of :data:`GRID` cells, refined by Brent's method,
:func:`geomcon.numeric.brent_root`).

Oscillating roller: B = Q + L·(cos t, sin t) with |B − A| = Rp; differentiating the constraint twice
(A′ = J·A, A″ = −A, J the quarter turn, n = (B − A)·J(B − Q)):

    t′ = (B − A)·J·A / n,   t″ = (t′²·(B − A)·(B − Q) − |t′·J(B − Q) − J·A|² − (B − A)·A) / n;

ψ = ∠OQB grows with t when B lies right of Q→O's line (sign of B's x): ω2 = ±ω·sgn·t′, ε2 = ω²·sgn·t″.
|t′| is largest at a root of t″; |t″|'s largest value is searched (grid, then Brent), its value exact to
rounding because the maximum is flat.

Examples
--------
>>> from geomcon.cam.eccentric import Translating
>>> cam = Translating(R=40, OA=10, follower="flat")
>>> [round(x, 12) for x in translating_maxima(cam, 2.0)]
[20.0, 40.0]
"""
from __future__ import annotations

import math

import numpy as np

from ..numeric import brent_root
from .eccentric import Oscillating, Translating
from .profile import maximise

GRID = 720
"""Cells of the turn on which a sign change of the next derivative is looked for."""


def translating_derivatives(cam: Translating, phi: float) -> tuple[float, float, float]:
    """(y′, y″, y‴) of the follower's height with respect to φ (mm per rad, rad², rad³)."""
    E = cam.OA
    s, c = math.sin(phi), math.cos(phi)
    if cam.follower == "flat":
        return E * c, -E * s, -E * c
    u, u1, u2, u3 = cam.e - E * c, E * s, E * c, -E * s
    w = math.sqrt((cam.Rp - u) * (cam.Rp + u))
    g, g1, g2 = u * u1, u1 * u1 + u * u2, 3.0 * u1 * u2 + u * u3
    return (E * c - g / w, -E * s - g1 / w - g * g / w ** 3,
            -E * c - g2 / w - 3.0 * g * g1 / w ** 3 - 3.0 * g ** 3 / w ** 5)


def translating_speeds(cam: Translating, phi: float, omega: float) -> tuple[float, float]:
    """(v, a) at the position φ: v = ±ω·y′ (> 0 rising), a = ω²·y″ (mm/s, mm/s²)."""
    y1, y2, _ = translating_derivatives(cam, phi)
    return cam.sense * omega * y1, omega * omega * y2


def _largest_at_roots(value, slope, lo: float) -> float:
    """max |value| over the roots of ``slope`` on [lo, lo + 2π] (grid of :data:`GRID` cells, Brent)."""
    xs = [lo + 2.0 * math.pi * i / GRID for i in range(GRID + 1)]
    gs = [slope(x) for x in xs]
    best = 0.0
    for x0, x1, g0, g1 in zip(xs, xs[1:], gs, gs[1:]):
        if g0 == 0.0:
            best = max(best, abs(value(x0)))
        elif g1 != 0.0 and (g0 > 0.0) != (g1 > 0.0):
            best = max(best, abs(value(brent_root(slope, x0, x1, g0, g1))))
    return best


def translating_maxima(cam: Translating, omega: float) -> tuple[float, float]:
    """(v_max, a_max) over the turn (mm/s, mm/s²)."""
    d = lambda p: translating_derivatives(cam, p)            # noqa: E731
    vm = _largest_at_roots(lambda p: d(p)[0], lambda p: d(p)[1], cam.phi_low)
    am = _largest_at_roots(lambda p: d(p)[1], lambda p: d(p)[2], cam.phi_low)
    return omega * vm, omega * omega * am


def arm_derivatives(cam: Oscillating, phi: float) -> tuple[float, float]:
    """(ψ′, ψ″) of the arm's angle with respect to φ (rad per rad, rad²)."""
    ax, ay = cam.OA * math.cos(phi), cam.OA * math.sin(phi)
    bx, by = cam.B(phi)
    qx, qy = bx, by - cam.a                                   # B − Q
    rx, ry = bx - ax, by - ay                                 # B − A
    n = rx * -qy + ry * qx                                    # (B − A)·J(B − Q)
    t1 = (rx * -ay + ry * ax) / n                             # (B − A)·J·A / n
    vx, vy = t1 * -qy + ay, t1 * qx - ax                      # B′ − A′ = t′·J(B − Q) − J·A
    t2 = (t1 * t1 * (rx * qx + ry * qy) - (vx * vx + vy * vy) - (rx * ax + ry * ay)) / n
    sgn = 1.0 if bx > 0 else -1.0
    return sgn * t1, sgn * t2


def arm_speeds(cam: Oscillating, phi: float, omega: float) -> tuple[float, float]:
    """(ω2, ε2) at the position φ: ω2 = ±ω·ψ′ (> 0 swinging out), ε2 = ω²·ψ″ (rad/s, rad/s²)."""
    p1, p2 = arm_derivatives(cam, phi)
    return cam.sense * omega * p1, omega * omega * p2


def arm_maxima(cam: Oscillating, omega: float) -> tuple[float, float]:
    """(ω2_max, ε2_max) over the turn (rad/s, rad/s²)."""
    d = lambda p: arm_derivatives(cam, p)                     # noqa: E731
    wm = _largest_at_roots(lambda p: d(p)[0], lambda p: d(p)[1], cam.phi_low)
    f1 = lambda p: abs(d(p)[1])                               # noqa: E731
    lo = cam.phi_low
    em = maximise(np.vectorize(f1, otypes=[float]), [(lo, lo + 2.0 * math.pi)], dense=GRID, g1=f1).value
    return omega * wm, omega * omega * em
