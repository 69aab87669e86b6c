"""The follower's velocity and acceleration when the cam turns at a constant ω, and their exact maxima.

With δ the cam angle turned (in the cam's own sense of rotation, whichever it is) and s(δ) the program's
displacement, the follower moves at v = ds/dt = ω·s′(δ) and accelerates at a = ω²·s″(δ) (ω constant):
positive v is away from the cam centre (rising), for either sense of rotation, since δ grows with the turn.
An oscillating follower's arm (h and s in degrees) turns at ω2 = ω·ψ′ (rad/s, ψ′ in rad/rad) with angular
acceleration ε2 = ω²·ψ″; positive is swinging out (ψ growing, away from the base circle).

The maxima over the cycle are exact: on each smooth piece of each law, |f′| is largest at an end or at a root
of f″, |f″| at an end or at a root of f‴; the roots are bracketed on a grid of the piece and bisected to the
last bit (:func:`largest_abs`). One-sided values at the ends of pieces count (a uniform law's a_max is 0:
its rigid impacts are infinite accelerations at the ends, which the impacts list names).

Examples
--------
>>> from geomcon.cam.laws import law
>>> p = law_peaks(law("poly345"))
>>> round(p.v, 15), round(p.x_v, 15), round(p.a, 12), round(p.x_a, 12)
(1.875, 0.5, 5.773502691896, 0.211324865405)
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 180, "law": "cycloidal"}, {"kind": "return", "angle": 180, "law": "cosine"}])
>>> [round(x, 9) for x in program_extrema(prog, 20.0)]
[12.732395447, 90.0, 12.732395447, 45.0]
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import TYPE_CHECKING, Callable

from .laws import Law

if TYPE_CHECKING:                          # (the program module imports the laws, which use law_peaks)
    from .program import Program

GRID = 64
"""Cells per smooth piece in which a sign change of the next derivative is looked for."""


@dataclass(frozen=True)
class Peaks:
    """The largest |f′| (at x_v) and |f″| (at x_a) of a normalised law on [0, 1]."""

    v: float
    x_v: float
    a: float
    x_a: float


def _root(g: Callable[[float], float], lo: float, hi: float, glo: float) -> float:
    """A root of g in [lo, hi] where g(lo) and g(hi) differ in sign: bisection until the interval stops
    shrinking (the last bit)."""
    while True:
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            return lo if abs(glo) <= abs(g(hi)) else hi
        gm = g(mid)
        if gm == 0.0:
            return mid
        if (gm > 0.0) == (glo > 0.0):
            lo, glo = mid, gm
        else:
            hi = mid


def candidates(slope: Callable[[float], float], cuts: tuple[float, ...]) -> list[float]:
    """Where a function whose derivative is ``slope`` may be extreme on [0, 1]: the ends of every piece
    (one-sided: a piece's right end just below the cut) and the roots of ``slope`` inside each piece (sign
    changes on a grid of :data:`GRID` cells, bisected)."""
    edges = (0.0, *cuts, 1.0)
    cands = []
    for p0, p1 in zip(edges, edges[1:]):
        right = p1 if p1 == 1.0 else math.nextafter(p1, p0)
        cands += [p0, right]
        xs = [p0 + (right - p0) * i / GRID for i in range(GRID + 1)]
        gs = [slope(x) for x in xs]
        for x0, x1, g0, g1 in zip(xs, xs[1:], gs, gs[1:]):
            if g0 == 0.0:
                cands.append(x0)
            elif g1 != 0.0 and (g0 > 0.0) != (g1 > 0.0):
                cands.append(_root(slope, x0, x1, g0))
    return cands


def largest_abs(value: Callable[[float], float], slope: Callable[[float], float],
                cuts: tuple[float, ...]) -> tuple[float, float]:
    """(max |value|, where) on [0, 1] over the :func:`candidates` (the first one reaching it)."""
    best, where = -1.0, 0.0
    for x in candidates(slope, cuts):
        v = abs(value(x))
        if v > best:
            best, where = v, x
    return best, where


@lru_cache(maxsize=512)
def law_peaks(lw: Law) -> Peaks:
    """The exact peaks of |f′| and |f″| of a law (roots of f″ and of f‴)."""
    fn1, fn3 = lw.fn1, lw.fn3
    v, xv = largest_abs(lambda x: fn1(x)[1], lambda x: fn1(x)[2], lw.cuts)
    if fn3 is None:
        raise ValueError(f"law {lw.name} has no third derivative")
    a, xa = largest_abs(lambda x: fn1(x)[2], fn3, lw.cuts)
    return Peaks(v, xv, a, xa)


def program_extrema(program: Program, h: float) -> tuple[float, float, float, float]:
    """(max |s′| per rad, δ where (deg), max |s″| per rad², δ where) over the program; the first segment
    reaching a maximum names its place."""
    vm, dv, am, da = 0.0, 0.0, 0.0, 0.0
    for seg in program.segments:
        if seg.kind == "dwell":
            continue
        p, span = law_peaks(seg.law), math.radians(seg.angle)
        v, a = abs(h) * p.v / span, abs(h) * p.a / (span * span)
        if v > vm:
            vm, dv = v, seg.start + p.x_v * seg.angle
        if a > am:
            am, da = a, seg.start + p.x_a * seg.angle
    return vm, dv, am, da


def speeds_at(program: Program, h: float, omega: float, at: tuple[float, ...], scale: float = 1.0
              ) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(ω·s′·scale, ω²·s″·scale) at the cam angles ``at`` (deg): v, a of a translating follower (scale 1,
    mm/s, mm/s²) or ω2, ε2 of an arm (scale π/180: rad/s, rad/s²)."""
    out_v, out_a = [], []
    for d in at:
        _, v, a = program.motion1(h, float(d))
        out_v.append(omega * v * scale)
        out_a.append(omega * omega * a * scale)
    return tuple(out_v), tuple(out_a)


def speed_maxima(program: Program, h: float, omega: float, scale: float = 1.0) -> tuple[float, float, float, float]:
    """(v_max, δ of v_max, a_max, δ of a_max): :func:`program_extrema` times ω and ω² (and ``scale``)."""
    vm, dv, am, da = program_extrema(program, h)
    return omega * vm * scale, dv, omega * omega * am * scale, da


def smallest(value: Callable[[float], float], slope: Callable[[float], float], cuts: tuple[float, ...]
             ) -> tuple[float, float]:
    """(min of value, where) on [0, 1] over the :func:`candidates` (the first one reaching it)."""
    best, where = math.inf, 0.0
    for x in candidates(slope, cuts):
        v = value(x)
        if v < best:
            best, where = v, x
    return best, where


def flat_curvature_floor(program: Program, h: float) -> tuple[float, float]:
    """(min of s + s″ over the turn, δ where (deg)): a translating flat face's profile has ρ = r0 + s + s″
    (s″ per rad²), so r0 ≥ ρallow − min(s + s″) keeps ρ ≥ ρallow everywhere. Exact: on each smooth piece of each
    law the ends and the roots of s′ + s‴ (f′/Φ + f‴/Φ³); a dwell is its level.

    >>> from geomcon.cam.program import parse_program
    >>> prog = parse_program([{"kind": "rise", "angle": 180, "law": "poly", "coefficients": [0, 2, -1]},
    ...                       {"kind": "return", "angle": 180, "law": "poly", "coefficients": [0, 0, 1]}])
    >>> [round(v, 12) for v in flat_curvature_floor(prog, 4 * math.pi ** 2)]      # GATE 2020: y + y″ ≥ −8
    [-8.0, 0.0]
    """
    best, where, level = math.inf, 0.0, 0.0
    for seg in program.segments:
        if seg.kind == "dwell":
            if level * h < best:
                best, where = level * h, seg.start
            continue
        sign = 1.0 if seg.kind == "rise" else -1.0
        span = math.radians(seg.angle)
        k = 1.0 / (span * span)
        fn1, fn3, base = seg.law.fn1, seg.law.fn3, level * h

        def value(x, fn1=fn1, sign=sign, k=k, base=base):
            f, _, f2 = fn1(x)
            return base + sign * h * (f + f2 * k)

        def slope(x, fn1=fn1, fn3=fn3, sign=sign, k=k):
            return sign * (fn1(x)[1] + fn3(x) * k)

        v, x = smallest(value, slope, seg.law.cuts)
        if v < best:
            best, where = v, seg.start + x * seg.angle
        level += sign
    return best, where
