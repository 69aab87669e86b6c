"""Rocker–slider coordination in closed form: the twin of ``rocker_slider.three_positions`` and
``rocker_slider.two_positions``, plus the slider's assembly used by their back-substitution.

Conventions (those of the recipes): the rocker turns about D; its marked line makes the angle ψ with +x
(counter-clockwise). The guide is the line through G = (0, e) with direction u = (cos α, sin α) (α the
given ``guide_angle``, 0 for a horizontal guide); the slider's pin E is at E = G + s·u. The connecting rod
EF is hinged to the rocker at F, which lies at DF = r in the direction ψ + β (β fixed in the rocker).

**Three positions.** With P = E − D = (X, Y) and F − D = R(ψ)·(U, V), U = r·cos β, V = r·sin β, the rod's
length gives |P|² − 2P·R(ψ)(U, V) + r² = EF², which is linear in U, V and W = r² − EF²:

    2U·(X cos ψ + Y sin ψ) + 2V·(Y cos ψ − X sin ψ) − W = X² + Y².

Three positions give a 3×3 system (Cramer's rule, :func:`~geomcon.analytic.function_generation.solve3`).

**Two positions, the rocker's hinge F1 chosen.** The pin E1 = G + t·u lies on the guide and is as far from
F1 as E2 = E1 + (s2 − s1)·u is from F2 (F1 turned about D by ψ2 − ψ1): with p = G − F1,
q = G + (s2 − s1)u − F2 the quadratic terms cancel, t = (|q|² − |p|²) / (2(p − q)·u).

Both are complex-safe, so the sensitivities are complex-step derivatives.

Examples
--------
>>> r = three_positions((0.0, 0.0), (50.0, 90.0, 115.0), -30.0, 0.0, (70.0, 31.0, 26.0))
>>> [round(v, 6) for v in (*r["F1"], r["DF"], r["EF"], r["beta"])]
[21.272791, 44.574855, 49.390782, 89.082826, 14.487775]
>>> round(slider_position(r["F1"], r["EF"], -30.0, 0.0, +1)[0], 9)       # back to s1
70.0
"""
from __future__ import annotations

import cmath
import math
from typing import Sequence

from ..numeric import deg360
from .fourbar_drive import arc_through, on_arc
from .function_generation import STEP, solve3

XY = tuple[float, float]


def _rot(x, y, t):
    c, s = cmath.cos(t), cmath.sin(t)
    return x * c - y * s, x * s + y * c


def _pins(e, alpha, s):
    """The slider pins G + s·u (complex-safe)."""
    ux, uy = cmath.cos(alpha), cmath.sin(alpha)
    return [(si * ux, e + si * uy) for si in s]


def _three(Dx, Dy, psi, e, alpha, s):
    """(F1x, F1y, U, V, W): angles in radians; complex-safe.

    Rows 2 and 3 are taken minus row 1 with |DE_i|² − |DE_1|² = (E_i − E_1)·(E_i + E_1 − 2D) and
    E_i − E_1 = (s_i − s_1)·u: with the guide 1e9 mm from D the squares are 1e18 and their difference, which
    carries F1 (16 mm from D), kept only 1e2 of it (β 1.6e-6° off)."""
    rows, rhs, XY = [], [], []
    ux, uy = cmath.cos(alpha), cmath.sin(alpha)
    for (ex, ey), p in zip(_pins(e, alpha, s), psi):
        X, Y = ex - Dx, ey - Dy
        c, sn = cmath.cos(p), cmath.sin(p)
        rows.append([2 * (X * c + Y * sn), 2 * (Y * c - X * sn), -1.0])
        rhs.append(X * X + Y * Y)
        XY.append((X, Y))
    for i in (1, 2):
        dx, dy = (s[i] - s[0]) * ux, (s[i] - s[0]) * uy
        rows[i] = [rows[i][0] - rows[0][0], rows[i][1] - rows[0][1], 0.0]
        rhs[i] = dx * (XY[i][0] + XY[0][0]) + dy * (XY[i][1] + XY[0][1])
    U, V, W = solve3(rows, rhs)
    fx, fy = _rot(U, V, psi[0])
    return Dx + fx, Dy + fy, U, V, W


def _two(Dx, Dy, psi, F1x, F1y, e, alpha, s):
    """(E1x, E1y, t): angles in radians; complex-safe."""
    ux, uy = cmath.cos(alpha), cmath.sin(alpha)
    vx, vy = _rot(F1x - Dx, F1y - Dy, psi[1] - psi[0])
    F2x, F2y = Dx + vx, Dy + vy
    px, py = -F1x, e - F1y
    qx, qy = (s[1] - s[0]) * ux - F2x, e + (s[1] - s[0]) * uy - F2y
    dx, dy = (s[1] - s[0]) * ux - (F2x - F1x), (s[1] - s[0]) * uy - (F2y - F1y)     # q − p, not of two 1e9s
    t = (dx * (qx + px) + dy * (qy + py)) / (-2 * (dx * ux + dy * uy))               # |q|² − |p|² = (q − p)·(q + p)
    return t * ux, e + t * uy, t


def slider_position(F: XY, EF: float, e: float, alpha_deg: float, branch: int) -> tuple[float, bool]:
    """The slider's pin on the guide at EF from the rocker's hinge F, on ``branch`` (+1: the pin ahead of
    F's foot along u, −1 behind): ``(s, assembled)``; when the rod cannot reach the guide the foot's s is
    returned with False.

    >>> slider_position((0.0, 30.0), 50.0, 0.0, 0.0, -1)
    (-40.0, True)
    """
    ux, uy = math.cos(math.radians(alpha_deg)), math.sin(math.radians(alpha_deg))
    t0 = F[0] * ux + (F[1] - e) * uy                     # foot of F on the guide
    h = -F[0] * uy + (F[1] - e) * ux                     # F's height over the guide
    if abs(h) > EF:
        return t0, False
    return t0 + branch * math.sqrt((EF - h) * (EF + h)), True


def branch_of_pin(F: XY, E: XY, alpha_deg: float) -> int:
    """+1 when the pin E lies ahead of F's foot along the guide's direction, −1 behind, 0 at the foot."""
    v = (E[0] - F[0]) * math.cos(math.radians(alpha_deg)) + (E[1] - F[1]) * math.sin(math.radians(alpha_deg))
    return (v > 0) - (v < 0)


def _pressure(F: XY, E: XY, alpha_deg: float) -> float:
    """Pressure angle at the slider: the acute angle between the rod EF and the guide, degrees."""
    t = math.degrees(math.atan2(F[1] - E[1], F[0] - E[0])) - alpha_deg
    t = abs((t + 90.0) % 180.0 - 90.0)
    return t


def _dead_rocker_angles(D: XY, r: float, l: float, e: float, alpha_deg: float, beta: float) -> list[float]:
    """Rocker angles ψ (deg) where the rod stands perpendicular to the guide (the hinge F at height ±EF over
    it): the swing's dead points."""
    al = math.radians(alpha_deg)
    h0 = -D[0] * math.sin(al) + (D[1] - e) * math.cos(al)        # D's height over the guide
    out = []
    for target in (l, -l):
        sv = (target - h0) / r                                    # sin(ψ + β − α)
        if -1.0 < sv < 1.0:
            w = math.degrees(math.asin(sv))
            out += [w + alpha_deg - beta, 180.0 - w + alpha_deg - beta]
    return out


def _flags(D, r, beta, l, e, alpha, psi, s, *, closed: bool) -> dict:
    """branch_ok, order_ok, alpha_max of the designed rocker–slider."""
    Fs = [(D[0] + r * math.cos(math.radians(p + beta)), D[1] + r * math.sin(math.radians(p + beta))) for p in psi]
    Es = [(si * math.cos(math.radians(alpha)), e + si * math.sin(math.radians(alpha))) for si in s]
    branches = [branch_of_pin(F, E, alpha) for F, E in zip(Fs, Es)]
    start, swept = arc_through(*psi) if closed else (psi[0], (psi[1] - psi[0] + 180.0) % 360.0 - 180.0)
    dead = [t for t in _dead_rocker_angles(D, r, l, e, alpha, beta) if on_arc(t, start, swept)]
    return {"branch_ok": len(set(branches)) == 1 and 0 not in branches, "order_ok": not dead,
            "alpha_max": max(_pressure(F, E, alpha) for F, E in zip(Fs, Es))}


def _sens(f, args: list, angle_idx: Sequence[int], length_idx: Sequence[int]) -> tuple[float, float]:
    """Largest movement of the point f(...)[:2] per 0.1° (angles, radians in ``args``) and per 0.1 mm."""
    out = []
    for k in range(len(args)):
        ak = [complex(v) for v in args]
        ak[k] += 1j * STEP
        x, y = f(*ak[:len(args)])[:2]
        out.append(math.hypot(x.imag, y.imag) / STEP)
    return (max(out[i] for i in angle_idx) * math.radians(0.1), max(out[i] for i in length_idx) * 0.1)


def three_hinge(D: XY, psi: Sequence[float], e: float, alpha: float, s: Sequence[float]) -> tuple[float, ...]:
    """(F1x, F1y, U, V, W) of :func:`three_positions`, real, without its sensitivities and flags (the
    recipe's validation reads DF = √(U² + V²) from it: the same numbers)."""
    rad = [math.radians(p) for p in psi]
    return tuple(z.real for z in _three(D[0], D[1], rad, e, math.radians(alpha), s))


def two_pin(D: XY, psi: Sequence[float], F1: XY, e: float, alpha: float, s: Sequence[float]) -> XY:
    """E1 of :func:`two_positions` (the same numbers), without its sensitivities and flags."""
    rad = [math.radians(p) for p in psi]
    x, y, _ = (z.real for z in _two(D[0], D[1], rad, F1[0], F1[1], e, math.radians(alpha), s))
    return x, y


def three_positions(D: XY, psi: Sequence[float], e: float, alpha: float, s: Sequence[float]) -> dict:
    """Every answer of ``rocker_slider.three_positions``: F1, DF, EF, beta, branch_ok, order_ok, alpha_max,
    sens_F1 (mm per 0.1° of any ψ or α) and sens_F1_mm (mm per 0.1 mm of D, e or any s)."""
    rad = [math.radians(p) for p in psi]
    x, y, U, V, W = three_hinge(D, psi, e, alpha, s)
    r = math.hypot(U, V)
    l = math.sqrt(max(0.0, r * r - W))
    beta = deg360(math.degrees(math.atan2(V, U)))

    def f(Dx, Dy, p1, p2, p3, e_, a_, s1, s2, s3):
        return _three(Dx, Dy, (p1, p2, p3), e_, a_, (s1, s2, s3))

    sa, sl = _sens(f, [D[0], D[1], *rad, e, math.radians(alpha), *s], (2, 3, 4, 6), (0, 1, 5, 7, 8, 9))
    return {"F1": (x, y), "DF": r, "EF": l, "beta": beta,
            **_flags(D, r, beta, l, e, alpha, psi, s, closed=True), "sens_F1": sa, "sens_F1_mm": sl}


def two_positions(D: XY, psi: Sequence[float], F1: XY, e: float, alpha: float, s: Sequence[float]) -> dict:
    """Every answer of ``rocker_slider.two_positions``: E1, s_E1, EF, DF, branch_ok, order_ok, alpha_max,
    sens_E1 (mm per 0.1° of ψ1, ψ2 or α) and sens_E1_mm (mm per 0.1 mm of D, F1, e or s)."""
    rad = [math.radians(p) for p in psi]
    x, y, t = (z.real for z in _two(D[0], D[1], rad, F1[0], F1[1], e, math.radians(alpha), s))
    r = math.dist(F1, D)
    l = math.dist(F1, (x, y))
    beta = math.degrees(math.atan2(F1[1] - D[1], F1[0] - D[0])) - psi[0]

    def f(Dx, Dy, p1, p2, fx, fy, e_, a_, s1, s2):
        return _two(Dx, Dy, (p1, p2), fx, fy, e_, a_, (s1, s2))

    sa, sl = _sens(f, [D[0], D[1], *rad, F1[0], F1[1], e, math.radians(alpha), *s], (2, 3, 7), (0, 1, 4, 5, 6, 8, 9))
    s_pins = (t, t + s[1] - s[0])
    return {"E1": (x, y), "s_E1": t, "EF": l, "DF": r,
            **_flags(D, r, beta, l, e, alpha, psi, s_pins, closed=False), "sens_E1": sa, "sens_E1_mm": sl}
