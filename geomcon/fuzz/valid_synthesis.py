"""Random valid problems of the three-position syntheses, stated from a linkage made first.

Every generator builds a linkage (a four-bar, or a rocker driving a slider), drives it to three (two)
positions, states the problem from those positions and expects the linkage back: its pivots and lengths are
the ground truth, known without the twin. Then the whole problem is scaled (log-uniform 1e-3 … 1e6 mm,
sometimes exactly 1e-3 or 1e6), turned and moved.

Cases (``kind``): ``"random"``; ``"near-degenerate: …"`` for positions only 2° apart, nearly collinear
positions (a far pivot), drafted data (coordinates or angles rounded to 4 decimals, as a textbook prints
them) and huge or tiny scales.

Tolerances of ``expect`` are propagated, not guessed: the given data carry a known error — rounding of
double precision, ``ε·M`` for coordinates of magnitude M, or half a unit of the 4th decimal for drafted
data — and the sought point moves by at most ``κ`` times that, where ``κ`` is the conditioning of the
three points it is the centre of (circumradius over the smallest altitude, computed here from the
generating linkage), or the conditioning of the bisector's meeting with the guide for two positions.
Cases near or beyond a documented refusal limit carry ``may_refuse``: a condition R/h_min — or, for two
positions, (1/2 + far)/cos — of :data:`ANSWER_CONDITION_BAND` or more (the recipes refuse at 1e7, the
solver refuses an answer whose own relative condition passes 1e7, which happens from about 1e5 on), or a
rigid-coupler spread over 1 %. Drafted data whose rounding, propagated, moves the answers by more than 5 %
of the linkage's size do not determine the linkage: such a case expects no values (it must still solve
without exit 1 or be refused with a number).

Examples
--------
>>> import random
>>> c = GENERATORS["four_bar.three_positions"](random.Random(1))
>>> c.problem["recipe"], sorted(c.problem["given"])
('four_bar.three_positions', ['B1', 'B2', 'B3', 'C1', 'C2', 'C3'])
>>> sorted(c.expect)
['A', 'AB', 'AD', 'BC', 'CD', 'D']
>>> all(GENERATORS[k](random.Random(7)).problem["recipe"] == k for k in GENERATORS)
True
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass

from ..numeric import deg360
from .case import Generator, ValidCase

XY = tuple[float, float]
EPS = 2.220446049250313e-16
DRAFT_DECIMALS = 4
"""Drafted data are rounded to 4 decimals (mm or degrees), as coordinates copied from a textbook are."""
DRAFT_HALF = 0.5 * 10.0 ** -DRAFT_DECIMALS
"""The largest rounding error of one drafted number."""
REFUSE_CONDITION = 1e7
"""The recipes refuse three positions with R/h_min at or beyond this (documented in synthesis_common)."""
ANSWER_CONDITION_BAND = 3e4
"""From R/h_min ≈ 1e5 on, some answer's own relative condition (the sensitivities are derivatives, and angle
givens count with their magnitude, up to 1260° here) can pass the solver's limit KAPPA_REFUSE = 1e7
(:mod:`geomcon.condition`), which refuses the problem with the number: such cases may be refused."""
REFUSE_FLAT = 1e-6
"""The recipes refuse two coincident points: a chord at or below this relative size."""


# ----------------------------------------------------------------------------------------- small geometry
def _rot(p: XY, t: float) -> XY:
    c, s = math.cos(t), math.sin(t)
    return (p[0] * c - p[1] * s, p[0] * s + p[1] * c)


def _polar(c: XY, r: float, deg: float) -> XY:
    t = math.radians(deg)
    return (c[0] + r * math.cos(t), c[1] + r * math.sin(t))


def _deg(p: XY, q: XY) -> float:
    return math.degrees(math.atan2(q[1] - p[1], q[0] - p[0]))


def _meet(P: XY, r: float, Q: XY, s: float, side: int) -> XY | None:
    """Circle(P, r) ∩ circle(Q, s) on ``side`` of P→Q (+1 left); None when they miss or nearly touch."""
    d = math.dist(P, Q)
    if d == 0.0 or d >= (r + s) * (1 - 1e-6) or d <= abs(r - s) * (1 + 1e-6):
        return None
    x = (d * d + r * r - s * s) / (2 * d)
    h = math.sqrt((r + x) * (r - x))
    ux, uy = (Q[0] - P[0]) / d, (Q[1] - P[1]) / d
    return (P[0] + x * ux - side * h * uy, P[1] + x * uy + side * h * ux)


def condition(P1: XY, P2: XY, P3: XY) -> float:
    """R / h_min of the triangle P1P2P3: how far its circumcentre moves per unit of error of one point.

    >>> round(condition((0, 0), (1, 1), (2, 0)), 12)
    1.0
    """
    a, b, c = math.dist(P2, P3), math.dist(P3, P1), math.dist(P1, P2)
    area2 = abs((P2[0] - P1[0]) * (P3[1] - P1[1]) - (P2[1] - P1[1]) * (P3[0] - P1[0]))
    if area2 == 0.0:
        return math.inf
    return (a * b * c / (2 * area2)) / (area2 / max(a, b, c))


@dataclass(frozen=True)
class Frame:
    """A similarity applied to a whole problem: x ↦ k·R(t)·x + T."""

    k: float
    t: float
    T: XY

    def __call__(self, p: XY) -> XY:
        q = _rot(p, self.t)
        return (self.k * q[0] + self.T[0], self.k * q[1] + self.T[1])

    @property
    def deg(self) -> float:
        return math.degrees(self.t)


def _scale(rng: random.Random) -> tuple[float, str]:
    """The problem's scale factor, and the kind it makes."""
    u = rng.random()
    if u < 0.1:
        return 1e-3, "near-degenerate: tiny scale 1e-3"
    if u < 0.2:
        return 1e6, "near-degenerate: huge scale 1e6"
    return 10.0 ** rng.uniform(-3.0, 6.0), ""


def _frame(rng: random.Random, k: float, *, turn: bool = True) -> Frame:
    t = rng.uniform(-math.pi, math.pi) if turn else 0.0
    T = (rng.uniform(-3, 3) * k, rng.uniform(-3, 3) * k) if rng.random() < 0.8 else (0.0, 0.0)
    return Frame(k, t, T)


def _kind(*parts: str) -> str:
    parts = [p.removeprefix("near-degenerate: ") for p in parts if p]
    return "near-degenerate: " + ", ".join(parts) if parts else "random"


def _draft(v: float) -> float:
    return round(v, DRAFT_DECIMALS)


def _pt(p: XY, drafted: bool) -> list[float]:
    return [_draft(p[0]), _draft(p[1])] if drafted else [p[0], p[1]]


# ----------------------------------------------------------------------------------------- four-bars
def _fourbar(rng: random.Random) -> tuple[float, float, float]:
    """AB, BC, CD of a four-bar on the frame A = (0, 0), D = (1, 0)."""
    return rng.uniform(0.1, 1.5), rng.uniform(0.3, 2.0), rng.uniform(0.2, 1.5)


def _spacing(rng: random.Random) -> tuple[tuple[float, float], str]:
    u = rng.random()
    if u < 0.12:
        return (2.0, 2.0), "positions 2° apart"
    if u < 0.2:
        return (0.2, 1.0), "nearly collinear positions (far pivot)"
    return (8.0, 70.0), ""


def _drive(rng: random.Random, spread: tuple[float, float]):
    """A four-bar and three positions (B_i, C_i) on one branch at increasing crank angles (unit frame)."""
    while True:
        AB, BC, CD = _fourbar(rng)
        A, D = (0.0, 0.0), (1.0, 0.0)
        phi = rng.uniform(-180, 180)
        side, sense = rng.choice((1, -1)), rng.choice((1, -1))
        out = []
        for _ in range(3):
            B = _polar(A, AB, phi)
            C = _meet(D, CD, B, BC, -side)
            if C is None:
                break
            # keep away from dead points: the transmission angle at least 3°
            cg = ((B[0] - C[0]) * (D[0] - C[0]) + (B[1] - C[1]) * (D[1] - C[1])) / (BC * CD)
            if abs(cg) > math.cos(math.radians(3.0)):
                break
            out.append((B, C))
            phi += sense * rng.uniform(*spread)
        if len(out) == 3:
            return A, D, AB, BC, CD, out


def _tol(kappa: float, err: float, length: float) -> float:
    """Expect tolerance: 1e-9 of the linkage's size plus the data error ``err`` amplified by ``kappa``."""
    return 1e-9 * length + 8.0 * kappa * err


def _determined(expect: dict, tol: float, length: float) -> dict:
    """``expect``, or nothing when the propagated error passes 5 % of the linkage's size (first-order
    propagation no longer holds: the data do not determine the linkage)."""
    return expect if tol <= 0.05 * length else {}


def gen_three_positions(rng: random.Random) -> ValidCase:
    """``four_bar.three_positions``: a four-bar driven to three positions; expect its pivots and lengths."""
    k, kscale = _scale(rng)
    spread, kspread = _spacing(rng)
    A, D, AB, BC, CD, pos = _drive(rng, spread)
    f = _frame(rng, k)
    drafted = 10.0 <= k <= 1000.0 and rng.random() < 0.25
    Bs = [f(B) for B, _ in pos]
    Cs = [f(C) for _, C in pos]
    given = {f"B{i}": _pt(B, drafted) for i, B in enumerate(Bs, 1)} | {f"C{i}": _pt(C, drafted) for i, C in enumerate(Cs, 1)}
    kA, kD = condition(*Bs), condition(*Cs)
    M = max(abs(c) for p in Bs + Cs for c in p)
    L = k * max(AB, BC, CD, 1.0)
    if drafted:
        # drafted points move by ≤ √2·h; the coupler fit moves C_i by ≤ the spread of |B_iC_i| (≤ 4·√2·h)
        err, gb = math.sqrt(2) * DRAFT_HALF, [[_draft(c) for c in p] for p in Bs]
        gc = [[_draft(c) for c in p] for p in Cs]
        kA, kD = max(kA, condition(*gb)), max(kD, condition(*gc))
        errA, errD = 3 * err, 3 * 5 * err
        lens = [math.dist(b, c) for b, c in zip(gb, gc)]
        refuse = max(lens) - min(lens) > 0.01 * max(lens)
    else:
        errA = errD = 8 * EPS * M
        refuse = False
    refuse = refuse or max(kA, kD) >= ANSWER_CONDITION_BAND
    tA, tD = _tol(kA, errA, L), _tol(kD, errD, L)
    Aw, Dw = f(A), f(D)
    expect = {"A": (Aw, tA), "D": (Dw, tD), "AB": (k * AB, tA + errA), "CD": (k * CD, tD + errD),
              "AD": (k, tA + tD), "BC": (k * BC, 1e-9 * L + 4 * errD)}
    return ValidCase({"recipe": "four_bar.three_positions", "given": given}, _determined(expect, max(tA, tD), L),
                     _kind(kscale, kspread, "drafted data rounded to 4 decimals" if drafted else ""), may_refuse=refuse)


def gen_fixed_pivots(rng: random.Random) -> ValidCase:
    """``four_bar.three_positions_fixed_pivots``: the fixed pivots and three crank positions of a four-bar, the
    coupler given by a point K rigid with it or by the coupler line's angles; expect the hinge C1 and lengths."""
    k, kscale = _scale(rng)
    spread, kspread = _spacing(rng)
    A, D, AB, BC, CD, pos = _drive(rng, spread)
    f = _frame(rng, k)
    drafted = 10.0 <= k <= 1000.0 and rng.random() < 0.25
    Bs = [f(B) for B, _ in pos]
    Cs = [f(C) for _, C in pos]
    Aw, Dw = f(A), f(D)
    with_k = rng.random() < 0.5
    off = rng.uniform(-180, 180)                         # the coupler line BK at a fixed angle to BC
    dirs = [_deg(B, C) + off for B, C in zip(Bs, Cs)]
    given = {"A": _pt(Aw, drafted), "D": _pt(Dw, drafted)} | {f"B{i}": _pt(B, drafted) for i, B in enumerate(Bs, 1)}
    if with_k:
        r = k * rng.uniform(0.2, 1.5)
        Ks = [_polar(B, r, a) for B, a in zip(Bs, dirs)]
        given |= {f"K{i}": _pt(K, drafted) for i, K in enumerate(Ks, 1)}
    else:
        turns = [360.0 * rng.randint(-2, 2) if rng.random() < 0.2 else 0.0 for _ in dirs]
        given["coupler_angles"] = [(_draft(a + t) if drafted else a + t) for a, t in zip(dirs, turns)]
    # the hinge C1 is the centre of D, D2′, D3′ (D carried with the coupler onto position 1)
    Dp = [Dw] + [_add(Bs[0], _rot(_sub(Dw, Bs[i]), math.radians(dirs[0] - dirs[i]))) for i in (1, 2)]
    kappa = condition(*Dp)
    M = max(abs(c) for p in Bs + Cs + [Aw, Dw] for c in p)
    L = k * max(AB, BC, CD, 1.0)
    refuse = kappa >= ANSWER_CONDITION_BAND
    if drafted:
        h = math.sqrt(2) * DRAFT_HALF
        # D′ moves with D, B1, B_i (h each) and the turn of B_iK_i (h / |BK| rad, or the angle's rounding)
        turn_err = 2 * (h / r if with_k else math.radians(DRAFT_HALF))
        err = 4 * h + turn_err * max(math.dist(Dw, B) for B in Bs)
        lens = [math.dist(Aw, B) for B in Bs]
        refuse = refuse or max(lens) - min(lens) > 0.01 * max(lens)
        if with_k:
            bk = [math.dist(_pt(B, True), _pt(K, True)) for B, K in zip(Bs, Ks)]
            refuse = refuse or max(bk) - min(bk) > 0.01 * max(bk)
    else:
        err = 16 * EPS * M
    t = _tol(kappa, err, L)
    expect = {"C1": (Cs[0], t), "BC": (k * BC, t + err), "CD": (k * CD, t + err),
              "AB": (k * AB, 1e-9 * L + 4 * err), "AD": (k, 1e-9 * L + 4 * err)}
    return ValidCase({"recipe": "four_bar.three_positions_fixed_pivots", "given": given}, _determined(expect, t, L),
                     _kind(kscale, kspread, "drafted data rounded to 4 decimals" if drafted else "",
                           "" if with_k else "coupler_angles"), may_refuse=refuse)


def _add(p: XY, q: XY) -> XY:
    return (p[0] + q[0], p[1] + q[1])


def _sub(p: XY, q: XY) -> XY:
    return (p[0] - q[0], p[1] - q[1])


def gen_function_generation(rng: random.Random) -> ValidCase:
    """``four_bar.function_generation``: a four-bar on A = (0, 0), D = (AD, 0) driven to three crank angles; the
    rocker's marked line at a random angle β from DC; expect C1, BC, CD, β."""
    k, kscale = _scale(rng)
    spread, kspread = _spacing(rng)
    _, _, AB, BC, CD, pos = _drive(rng, spread)
    beta = rng.uniform(-180, 180)
    drafted = rng.random() < 0.2
    turns = [360.0 * rng.randint(-3, 3) if rng.random() < 0.15 else 0.0 for _ in range(6)]
    phi = [_deg((0.0, 0.0), B) + t for (B, _), t in zip(pos, turns)]
    psi = [_deg((1.0, 0.0), C) - beta + t for (_, C), t in zip(pos, turns[3:])]
    if drafted:
        phi, psi = [_draft(v) for v in phi], [_draft(v) for v in psi]
    # C1 is the centre of B1 and the pins of positions 2, 3 turned about D by ψ1 − ψi
    Bs = [_polar((0.0, 0.0), AB, p) for p in phi]
    P = [Bs[0]] + [_add((1.0, 0.0), _rot(_sub(Bs[i], (1.0, 0.0)), math.radians(psi[0] - psi[i]))) for i in (1, 2)]
    kappa = condition(*P)
    refuse = kappa >= ANSWER_CONDITION_BAND
    L = k * max(AB, BC, CD, 1.0)
    ang = max(abs(v) for v in phi + psi) + 360.0
    # an angle error δ (rad) moves a point by ≤ δ·(|AD| + |AB| + |CD|)
    dang = math.radians(DRAFT_HALF) if drafted else 4 * EPS * math.radians(ang)
    err = 2 * dang * k * (1.0 + AB + CD) + 4 * EPS * L
    t = _tol(kappa, err, L)
    given = {"AD": k, "AB": k * AB, "phi": phi, "psi": psi}
    C1 = (k * pos[0][1][0], k * pos[0][1][1])
    bt = t / (k * CD)                                     # rad
    expect = {"C1": (C1, t), "BC": (k * BC, 2 * t), "CD": (k * CD, t),
              "beta": (deg360(beta), math.degrees(bt) + 1e-9 * 180 + (math.degrees(dang) if drafted else 0.0))}
    return ValidCase({"recipe": "four_bar.function_generation", "given": given}, _determined(expect, t, L),
                     _kind(kscale, kspread, "angles rounded to 4 decimals" if drafted else ""), may_refuse=refuse)


# ----------------------------------------------------------------------------------------- rocker–sliders
def _slider(rng: random.Random, n: int, spread: tuple[float, float]):
    """A rocker D, DF, β driving a rod EF to a guide at height e' below/above D (unit frame, horizontal guide
    through the origin): rocker angles ψ_i, hinges F_i, pins E_i = (x_i, 0)."""
    while True:
        DF, EF = rng.uniform(0.3, 1.0), rng.uniform(0.8, 2.5)
        D = (0.0, rng.uniform(-0.9, 0.9) * (EF - DF) + rng.uniform(-0.2, 0.2))
        beta = rng.uniform(-180, 180)
        p = rng.uniform(-180, 180)
        side = rng.choice((1, -1))
        sense = rng.choice((1, -1))
        psis, Fs, xs = [], [], []
        for _ in range(n):
            F = _polar(D, DF, p + beta)
            if abs(F[1]) >= EF * 0.99:                   # keep the rod ≥ 8° from perpendicular to the guide
                break
            x = F[0] + side * math.sqrt((EF - F[1]) * (EF + F[1]))
            psis.append(p)
            Fs.append(F)
            xs.append(x)
            p += sense * rng.uniform(*spread)
        if len(psis) == n:
            return D, DF, EF, beta, psis, Fs, xs


def _guide_frame(rng: random.Random, f: Frame) -> tuple[float, float, float] | None:
    """The transformed guide (the x-axis of the unit frame) as (e, guide_angle, t0): the line through (0, e) at
    guide_angle, and t0 the coordinate along it of the image of the unit frame's origin."""
    alpha = f.deg
    ca = math.cos(f.t)
    if abs(ca) < 0.2:
        return None
    G = f((0.0, 0.0))
    t = -G[0] / ca                                      # G + t·u meets x = 0
    e = G[1] + t * math.sin(f.t)
    return e, alpha, -t


def _slider_case(rng: random.Random, n: int):
    k, kscale = _scale(rng)
    spread, kspread = _spacing(rng)
    spread = (spread[0], min(spread[1], 40.0))
    while True:
        D, DF, EF, beta, psis, Fs, xs = _slider(rng, n, spread)
        f = _frame(rng, k)
        g = _guide_frame(rng, f)
        if g is not None:
            break
    e, alpha, t0 = g
    return k, kscale, kspread, f, D, DF, EF, beta, psis, Fs, xs, e, alpha, t0


def gen_rocker_slider_three(rng: random.Random) -> ValidCase:
    """``rocker_slider.three_positions``: a rocker driving a slider, three positions; expect F1, DF, EF, β."""
    k, kscale, kspread, f, D, DF, EF, beta, psis, Fs, xs, e, alpha, t0 = _slider_case(rng, 3)
    drafted = 10.0 <= k <= 1000.0 and rng.random() < 0.2
    Dw = f(D)
    psi_w = [p + f.deg for p in psis]
    s = [t0 + k * x for x in xs]
    if drafted:
        Dw, psi_w, s, e = (_draft(Dw[0]), _draft(Dw[1])), [_draft(v) for v in psi_w], [_draft(v) for v in s], _draft(e)
    # F1 is the centre of E1 and the pins of positions 2, 3 turned about D by ψ1 − ψi
    Es = [(x, 0.0) for x in xs]
    P = [Es[0]] + [_add(D, _rot(_sub(Es[i], D), math.radians(psis[0] - psis[i]))) for i in (1, 2)]
    kappa = condition(*P)
    refuse = kappa >= ANSWER_CONDITION_BAND
    L = k * max(DF, EF, math.hypot(*D), 1.0)
    M = max(abs(v) for v in (*Dw, e, *s)) + L
    if drafted:
        err = 4 * DRAFT_HALF + 2 * math.radians(DRAFT_HALF) * 3 * L
    else:
        err = 16 * EPS * M + 4 * EPS * math.radians(max(abs(v) for v in psi_w) + 360) * L
    t = _tol(kappa, err, L)
    given = {"D": list(Dw), "psi": psi_w, "e": e, "guide_angle": alpha, "s": s}
    expect = {"F1": (f(Fs[0]), t), "DF": (k * DF, t + err), "EF": (k * EF, 2 * t + err),
              "beta": (deg360(beta), math.degrees(2 * t / (k * DF)) + 1e-7)}
    return ValidCase({"recipe": "rocker_slider.three_positions", "given": given}, _determined(expect, t, L),
                     _kind(kscale, kspread, "drafted data rounded to 4 decimals" if drafted else ""), may_refuse=refuse)


def gen_rocker_slider_two(rng: random.Random) -> ValidCase:
    """``rocker_slider.two_positions``: a rocker driving a slider in two positions, the hinge F1 given and the
    slider's positions of some mark (not the pin); expect the pin E1, s_E1, EF, DF."""
    k, kscale, kspread, f, D, DF, EF, beta, psis, Fs, xs, e, alpha, t0 = _slider_case(rng, 2)
    drafted = 10.0 <= k <= 1000.0 and rng.random() < 0.2
    mark = rng.uniform(-1, 1) * k
    Dw, F1w = f(D), f(Fs[0])
    psi_w = [p + f.deg for p in psis]
    s = [t0 + k * x + mark for x in xs]
    if drafted:
        Dw, F1w = (_draft(Dw[0]), _draft(Dw[1])), (_draft(F1w[0]), _draft(F1w[1]))
        psi_w, s, e = [_draft(v) for v in psi_w], [_draft(v) for v in s], _draft(e)
    # E1: the bisector of F1F2′ (F2′ = F2 moved back by s2 − s1) meets the guide
    F2p = (Fs[1][0] - (xs[1] - xs[0]), Fs[1][1])
    chord = math.dist(Fs[0], F2p)
    cosg = abs(F2p[0] - Fs[0][0]) / chord
    mid = ((Fs[0][0] + F2p[0]) / 2, (Fs[0][1] + F2p[1]) / 2)
    kappa = (0.5 + math.dist(mid, (xs[0], 0.0)) / chord) / max(cosg, 1e-300)
    refuse = kappa >= ANSWER_CONDITION_BAND or chord <= 30 * REFUSE_FLAT * max(DF, abs(xs[1] - xs[0]))
    L = k * max(DF, EF, math.hypot(*D), 1.0)
    M = max(abs(v) for v in (*Dw, *F1w, e, *s)) + L
    if drafted:
        err = 6 * DRAFT_HALF + 2 * math.radians(DRAFT_HALF) * 3 * L
    else:
        err = 16 * EPS * M + 4 * EPS * math.radians(max(abs(v) for v in psi_w) + 360) * L
    t = _tol(kappa, err, L)
    given = {"D": list(Dw), "psi": psi_w, "F1": list(F1w), "e": e, "guide_angle": alpha, "s": s}
    expect = {"E1": (f((xs[0], 0.0)), t), "s_E1": (t0 + k * xs[0], t), "EF": (k * EF, t + err),
              "DF": (k * DF, 1e-9 * L + 4 * err)}
    return ValidCase({"recipe": "rocker_slider.two_positions", "given": given}, _determined(expect, t, L),
                     _kind(kscale, kspread, "drafted data rounded to 4 decimals" if drafted else ""), may_refuse=refuse)


LENGTH_KEYS = frozenset({"B1", "B2", "B3", "C1", "C2", "C3", "A", "D", "K1", "K2", "K3", "F1", "AD", "AB", "e", "s"})
"""Givens that are lengths or coordinates (mm): the global range applies to them."""


def in_range(problem: dict) -> bool:
    """True when every nonzero length or coordinate lies in the global range 1e-6 … 1e9 mm and spans at most
    1e10 (:mod:`geomcon.problems`): a translated problem can put a coordinate at 1e-7 mm by chance, and
    such a draw is made again rather than counted as a refusal.

    >>> in_range({"given": {"A": [0.0, 5.0], "D": [1e-7, 3.0]}}), in_range({"given": {"A": [0.0, 5.0]}})
    (False, True)
    """
    xs = []
    for k, v in problem["given"].items():
        if k in LENGTH_KEYS:
            xs += [abs(x) for x in (v if isinstance(v, (list, tuple)) else [v]) if x != 0.0]
    return all(1e-6 <= x <= 1e9 for x in xs) and (not xs or max(xs) <= 1e10 * min(xs))


def _ranged(gen: Generator) -> Generator:
    """``gen``, drawn again (from the same stream) until its problem lies in the global range."""
    def draw(rng: random.Random) -> ValidCase:
        while True:
            case = gen(rng)
            if in_range(case.problem):
                return case
    draw.__doc__, draw.__name__ = gen.__doc__, gen.__name__
    return draw


GENERATORS: dict[str, Generator] = {
    "four_bar.three_positions": _ranged(gen_three_positions),
    "four_bar.three_positions_fixed_pivots": _ranged(gen_fixed_pivots),
    "four_bar.function_generation": _ranged(gen_function_generation),
    "rocker_slider.three_positions": _ranged(gen_rocker_slider_three),
    "rocker_slider.two_positions": _ranged(gen_rocker_slider_two),
}
"""The synthesis family's generators, by recipe name."""
