"""The smallest base circle of a disc cam with a translating follower for an allowed pressure angle: the
analytic twin of ``cam.base_radius``.

With the follower's lowest pitch point B0 at height s0 = √(r0² − e²) above O, the pressure angle is
tan α = |s′ − k·e| / (s0 + s) (k = +1 for a counter-clockwise cam, −1 clockwise; s′ = ds/dδ per radian), so
α ≤ α_allow at δ needs s0 ≥ |s′ − k·e| / tan α_allow − s. The smallest admissible s0 for an offset e is the
largest of these over the constrained part of the turn (the rise, and the return when it has its own limit):

    s0(e) = max_δ ( |s′(δ) − k·e| / tan α_allow(δ) − s(δ) ),   r0(e)² = e² + s0(e)².

For a fixed e, the maximum over δ is reached at a segment end or where d/dδ of the bracket vanishes,
s″ = ±tan α_allow·s′: those cam angles do not depend on e, so they are found once, by bisection on the exact
derivatives (no grid answer). r0(e)² is convex in e (s0 is a maximum of convex functions of e); its
minimum is found by bisection on the sign of its one-sided derivative e + s0·ds0/de (envelope theorem),
which also locates a kink exactly. The construction (``cam.base_radius``) takes the textbook's other route:
the two support lines at α_allow to the curve (ds/dδ, s) and the point of their admissible region nearest B0.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 240}])
>>> out = best_base(prog, 20.0, alpha_allow=30.0, rotation="ccw")
>>> round(out["r0"], 6), round(out["e"], 6)
(14.023902, 7.011951)
>>> round(best_base(prog, 20.0, alpha_allow=30.0, rotation="ccw", e=0.0)["r0"], 6)     # centred follower
24.290111
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..errors import NotAMechanism
from .program import Program

GRID = 2048
"""Grid (per constrained part) that brackets the roots of s″ ∓ tan α·s′ before bisection."""
RR_FACTOR = 0.8
"""The textbook's roller rule: rr ≤ 0.8·ρmin of the pitch curve (rr < ρmin avoids undercut; the margin keeps
the actual profile's smallest radius of curvature ρmin − rr ≥ 0.2·ρmin)."""


def bisect_root(f: Callable[[float], float], a: float, b: float) -> float:
    """A root of ``f`` in [a, b] (f(a)·f(b) ≤ 0) by bisection to the last representable digit; at a jump
    of sign (a discontinuity) it converges to the jump.

    >>> round(bisect_root(lambda x: x * x - 2.0, 0.0, 2.0), 15)
    1.414213562373095
    """
    fa = f(a)
    if fa == 0.0:
        return a
    for _ in range(200):
        m = 0.5 * (a + b)
        if m <= min(a, b) or m >= max(a, b):
            break
        fm = f(m)
        if fm == 0.0:
            return m
        if (fm < 0) == (fa < 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


@dataclass(frozen=True)
class Limit:
    """One constrained part of the turn: cam angles [lo, hi] (radians) with tan α_allow = ``t``."""

    part: str
    lo: float
    hi: float
    t: float


def limits(program: Program, alpha_allow: float, alpha_allow_return: float | None = None) -> list[Limit]:
    """The rise with ``alpha_allow`` (deg), plus the return when ``alpha_allow_return`` is given."""
    out = []
    for part, seg, allow in (("rise", program.rise, alpha_allow), ("return", program.ret, alpha_allow_return)):
        if seg is None or allow is None:
            continue
        if not 0.0 < allow < 90.0:
            raise NotAMechanism(f"allowed pressure angle of the {part} = {allow:g}° must lie in (0°, 90°)")
        out.append(Limit(part, math.radians(seg.start), math.radians(seg.end), math.tan(math.radians(allow))))
    return out


def candidates(program: Program, h: float, lim: Limit) -> tuple[np.ndarray, np.ndarray]:
    """(s, s′) at the cam angles where |s′ − k·e|/t − s can be largest, whatever e: the part's ends
    (one-sided) and the roots of s″ − t·s′ and s″ + t·s′."""
    motion = lambda d: program.motion(h, d, radians=True)
    grid = np.linspace(lim.lo, lim.hi, GRID + 1)
    grid[-1] = np.nextafter(lim.hi, lim.lo)
    _, v, acc = motion(grid)
    deltas = [float(grid[0]), float(grid[-1])]
    for sign in (1.0, -1.0):
        g = acc - sign * lim.t * v
        f = lambda d, sign=sign: float(motion(d)[2] - sign * lim.t * motion(d)[1])
        for i in np.nonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0)[0]:
            deltas.append(bisect_root(f, float(grid[i]), float(grid[i + 1])))
    s, v, _ = motion(np.array(deltas))
    return s, v


def s0_needed(cands: list[tuple[np.ndarray, np.ndarray, float]], ke: float) -> tuple[float, float]:
    """(s0(e), ds0/de·k) for ``ke`` = k·e: the largest |s′ − ke|/t − s and its slope in ke at the maximiser."""
    best, slope = -math.inf, 0.0
    for s, v, t in cands:
        q = np.abs(v - ke) / t - s
        i = int(np.argmax(q))
        if q[i] > best:
            best, slope = float(q[i]), -math.copysign(1.0, float(v[i] - ke)) / t
    return best, slope


def best_base(program: Program, h: float, *, alpha_allow: float, rotation: str = "ccw",
              alpha_allow_return: float | None = None, e: float | None = None) -> dict[str, float]:
    """``r0``, ``e`` and ``s0`` of the smallest base circle (of the pitch curve) that keeps α within the
    limits; with ``e`` given, the smallest r0 for that offset.

    Raises
    ------
    NotAMechanism
        When the optimum would put B0 on the offset circle (s0 ≤ 0): no proper cam.
    """
    k = 1.0 if rotation == "ccw" else -1.0
    cands = [(*candidates(program, h, lim), lim.t) for lim in limits(program, alpha_allow, alpha_allow_return)]
    if e is None:
        grad = lambda ke: ke + s0_needed(cands, ke)[0] * s0_needed(cands, ke)[1]   # d/d(ke) of r0²/2
        span = h + max(float(np.max(np.abs(v))) for _, v, _ in cands)
        lo, hi = -span, span
        while grad(lo) > 0:
            lo *= 2.0
        while grad(hi) < 0:
            hi *= 2.0
        ke = bisect_root(grad, lo, hi)
    else:
        ke = k * e
    s0 = s0_needed(cands, ke)[0]
    if not s0 > 1e-9 * h:
        raise NotAMechanism(f"the best centre puts B0 at s0 = {s0:.6g} mm from the offset circle's tangent point "
                            f"(e = {k * ke:.6g} mm): no proper cam; give the offset e")
    return {"r0": math.hypot(ke, s0), "e": k * ke, "s0": s0}
