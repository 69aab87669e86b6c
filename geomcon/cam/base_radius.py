"""The smallest base circle of a disc cam with a translating or an oscillating follower for an allowed pressure
angle: the analytic side of ``cam.base_radius``.

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

Oscillating (arm) follower
--------------------------
Conventions of :mod:`geomcon.cam.oscillating` (centre distance a = OA0, arm L = A0B, φ = ψ0 + ψ the arm's angle
from A0O, ε = +1 when the arm rises in the cam's sense). The contact normal at B passes through the relative
instant centre P of cam and arm on A0O, A0P = a/(1 − εψ′); the line through O parallel to it meets the arm at
K, A0K = (1 − εψ′)·L (similar triangles A0KO, A0BP): the textbook's velocity-image point, BK = L·ψ′ laid off
from B towards A0 when ε = +1, away from A0 when ε = −1 (no 1/(1 ∓ ψ′) factor: that is A0P). So α is the angle
of KO with the arm's normal, and α ≤ α_allow puts O in the wedge at K between the two lines at ±α_allow to the
normal (on O's side of the arm). On the circle of radius a about A0 that wedge is the arc

    |β − α_allow| ≤ φ ≤ min(β + α_allow, 2π − β − α_allow),      cos β = L(1 − εψ′)·cos α_allow / a,

(with a > L·|1 − εψ′|·cos α_allow, else the circle misses the wedge). What is minimised is r0 = OB0, the
base circle of the pitch curve; r0² = a² + L² − 2aL·cos ψ0 grows with ψ0, so at a given a the answer is the
smallest admissible ψ0 = max_δ(|β − α_allow| − ψ) (:func:`arc_bounds`, the construction's route), provided it
does not exceed the arc's upper end min_δ(min(β + α, 2π − β − α) − ψ). With a free: the admissible region (an
intersection of wedges) is convex, so the distances from A0 at which the circle meets it form an interval
and r0 is unimodal on it (it is often a vertex where two positions bind at once, a kink of r0(a)). The
interval is found from one admissible distance (a log-spaced scan, :func:`admissible_distance`); the optimum
by bisection on the sign of d(r0²)/da, distances that miss the region counting as negative below it and
positive above it (:func:`best_distance`): the result is the smooth minimum, the kink, or the distance at
which the circle touches the region.

The twin (:class:`ArmTwin`) uses neither wedges nor circles: from tan α = |c − a cos φ|/(a sin φ) alone, each
position's condition is linear in a along a ray from A0, so it walks rays (bisection on dr0²/dψ0 with the
nearest admissible point of each ray, its near or its far end), and at a given a it minimises the excess
α − α_allow over ψ0 and bisects on its sign. Extremes over the positions: a grid refined by golden section
(the construction: roots of the exact slopes by regula falsi).

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
from .oscillating import ArmMotion, Motion, levels, piece_grid, pieces, segment_motion
from .program import Program, Segment

GRID = 2048
"""Grid (per constrained part) that brackets the roots of s″ ∓ tan α·s′ before bisection."""
GRID_ARM = 240
"""Grid of positions per smooth piece on which an arm's bounds are bracketed before root refinement."""
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


S0_MIN = 1e-9
"""Smallest height s0 of B0 above O, in units of h: below it the base circle all but touches the offset
circle (α_allow within about 0.001° of 90° makes the limit no constraint)."""


def s0_needed(cands: list[tuple[np.ndarray, np.ndarray, float]], ke: float) -> tuple[float, float]:
    """(s0(e), ds0/de·k) for ``ke`` = k·e: the largest |s′ − ke|/t − s and its slope in ke at the maximiser."""
    best, slope = -math.inf, 0.0
    for s, v, t in cands:
        q = np.abs(v - ke) / t - s
        i = int(np.argmax(q))
        if q[i] > best:
            best, slope = float(q[i]), -math.copysign(1.0, float(v[i] - ke)) / t
    return best, slope


def s0_at_optimum(cands: list[tuple[np.ndarray, np.ndarray, float]], ke: float) -> float:
    """s0 at the best offset ``ke`` (found to its last bit), read off the best-conditioned of the constraints
    that bind there.

    Each |s′ − ke|/t − s carries the rounding of ke magnified by 1/t; at a kink of s0 (two constraints binding
    at once, the usual optimum) a steep one (small α_allow) and a shallow one meet, and the steep one's value is
    ε·|ke|/t uncertain (5e-9 relative at α_allow = 1e-6°). Among the constraints within their rounding of the
    largest, the one with the largest t gives the value.

    >>> cands = [(np.array([0.0]), np.array([1.0]), 1e-8), (np.array([0.0]), np.array([-1.0]), 1.0)]
    >>> ke = 1.0 - 2e-8 / (1.0 + 1e-8)                   # where |1 − ke|/1e-8 = |−1 − ke|/1: the kink
    >>> abs(s0_at_optimum(cands, ke) - 2.0 / (1.0 + 1e-8)) < 1e-15
    True
    """
    eps = np.finfo(float).eps
    rows = []
    for s, v, t in cands:
        q = np.abs(v - ke) / t - s
        err = 4.0 * eps * ((np.abs(v) + abs(ke)) / t + np.abs(s) + np.abs(q))
        rows += list(zip(q.tolist(), err.tolist(), [t] * len(q)))
    top = max(rows)
    near = [r for r in rows if r[0] + r[1] >= top[0] - top[1]]
    return max(near, key=lambda r: (r[2], r[0]))[0]


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
    s0 = s0_needed(cands, ke)[0] if e is not None else s0_at_optimum(cands, ke)
    if not s0 > S0_MIN * h:
        raise NotAMechanism(f"the {'best ' if e is None else ''}centre puts B0 at s0 = {s0:.6g} mm ≤ {S0_MIN:g}·h "
                            f"from the offset circle's tangent point (e = {k * ke:.6g} mm): no proper cam — the limit "
                            f"α_allow = {alpha_allow:g}° hardly constrains it" + ("; give the offset e" if e is None else ""))
    return {"r0": math.hypot(ke, s0), "e": k * ke, "s0": s0}


# ---------------------------------------------------------------------------- oscillating (arm) follower
@dataclass(frozen=True)
class ArmProgram(ArmMotion):
    """The motion of an arm follower without a cam yet: angular stroke ``h`` (deg), ``program``, senses."""

    h: float
    program: Program
    rotation: str = "ccw"
    arm: str = "left"


@dataclass(frozen=True)
class ArmPart:
    """One constrained part (rise or return) of an arm follower's turn: its segment, ψ (deg) at its start and
    the allowed pressure angle ``alpha`` (rad)."""

    part: str
    seg: Segment
    level: float
    alpha: float
    grid: tuple[np.ndarray, Motion]


def arm_parts(arm: ArmProgram, lims: list[Limit]) -> list[ArmPart]:
    """The constrained parts of ``arm``'s program (the first rise, the first return when it has a limit)."""
    out = []
    for lim in lims:
        k = next(i for i, s in enumerate(arm.program.segments) if s.kind == lim.part)
        seg, level = arm.program.segments[k], levels(arm.program, arm.h)[k]
        out.append(ArmPart(lim.part, seg, level, math.atan(lim.t), arm_grid(seg, level, arm.h)))
    return out


def part_motion(arm: ArmMotion, part: str, delta_deg: float) -> Motion:
    """The motion at ``delta_deg`` inside the ``part`` segment (one-sided at its ends)."""
    k = next(i for i, s in enumerate(arm.program.segments) if s.kind == part)
    seg = arm.program.segments[k]
    x = min(max((delta_deg - seg.start) / seg.angle, 0.0), 1.0)
    return segment_motion(seg, levels(arm.program, arm.h)[k], arm.h, [x])


def _fractions(seg: Segment, n: int) -> np.ndarray:
    """A grid of fractions over every smooth piece of ``seg`` (each piece's right end just inside it)."""
    return np.concatenate([piece_grid(x0, x1, n) for x0, x1 in pieces(seg)])


def _falsi(fn: Callable[[float], float], lo: float, hi: float, flo: float, fhi: float, tol: float) -> float:
    """A root of ``fn`` in [lo, hi] (fn(lo)·fn(hi) < 0) by regula falsi with the Illinois modification,
    bisecting when a step leaves the bracket, until the bracket is narrower than ``tol``.

    >>> round(_falsi(lambda x: x * x - 2.0, 0.0, 2.0, -2.0, 2.0, 1e-15), 15)
    1.414213562373095
    """
    side = 0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if hi - lo <= tol or not lo < mid < hi:
            break
        c = (lo * fhi - hi * flo) / (fhi - flo)
        if not lo < c < hi:
            c = mid
        fc = fn(c)
        if fc == 0.0:
            return c
        if (fc > 0) == (flo > 0):
            lo, flo = c, fc
            if side < 0:
                fhi *= 0.5
            side = -1
        else:
            hi, fhi = c, fc
            if side > 0:
                flo *= 0.5
            side = 1
    return 0.5 * (lo + hi)


ROOT_TOL = 1e-13
"""Width (as a fraction of a segment) to which a stationary position is located: the value there is then
exact to rounding (its error is quadratic), the slopes taken there to about 1e-13."""


def stationary_max(seg: Segment, level: float, h: float, g: Callable[[Motion], np.ndarray],
                   slope: Callable[[Motion], np.ndarray], n: int = GRID_ARM,
                   grid: tuple[np.ndarray, Motion] | None = None) -> tuple[float, float]:
    """(max of ``g`` over the segment, the fraction where): the grid, the ends of every smooth piece
    (one-sided) and the roots of ``slope`` = dg/dδ (per radian) where it turns from + to − between grid
    points, refined only where the grid values and slopes leave room for a value above the best so far.
    ``grid`` = (fractions, their motion) may be given precomputed (:func:`arm_grid`)."""
    xs, m = grid if grid is not None else arm_grid(seg, level, h, n)
    v, sl = g(m), slope(m)
    j = int(np.argmax(v))
    best, where = float(v[j]), float(xs[j])
    step = math.radians(seg.angle) * (xs[1:] - xs[:-1])
    room = np.maximum(v[:-1], v[1:]) + step * np.maximum(sl[:-1], -sl[1:])
    for i in np.nonzero((sl[:-1] > 0) & (sl[1:] < 0) & (step > 0) & ~(room < best))[0]:
        f = lambda x: float(slope(segment_motion(seg, level, h, [x]))[0])
        x = _falsi(f, float(xs[i]), float(xs[i + 1]), float(sl[i]), float(sl[i + 1]), ROOT_TOL)
        val = float(g(segment_motion(seg, level, h, [x]))[0])
        if val > best:
            best, where = val, x
    return best, where


def arm_grid(seg: Segment, level: float, h: float, n: int = GRID_ARM) -> tuple[np.ndarray, Motion]:
    """The fractions of :func:`_fractions` and the motion there (cached by the searches over a)."""
    xs = _fractions(seg, n)
    return xs, segment_motion(seg, level, h, xs)


def _beta(mu: np.ndarray, dmu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """β = arccos μ and dβ/dδ (a large finite slope where |μ| = 1)."""
    beta = np.arccos(np.clip(mu, -1.0, 1.0))
    return beta, -dmu / np.sqrt(np.maximum(1.0 - mu * mu, 1e-300))


ARC_TOL = 1e-13
"""Radians by which the ends of an admissible arc may cross (rounding at a tangency) and still count as one
point: the arm's angle is then determined to this, far below any drawing or check."""


@dataclass(frozen=True)
class ArcBounds:
    """What the wedges leave of the circle of radius ``a`` about A0: arm angles ψ0 (rad, from A0B0 towards
    O) in [lo, hi]; the position binding ``lo`` (part, δ in degrees) and ∂lo/∂a there."""

    a: float
    lo: float
    hi: float
    part: str
    delta: float
    dlo_da: float

    @property
    def feasible(self) -> bool:
        """True when the arc is not empty; an arc shorter than :data:`ARC_TOL` the wrong way round counts as
        the single point where the circle touches the region (the arcs' ends are exact to rounding)."""
        return self.lo <= self.hi + ARC_TOL


def arc_bounds(arm: ArmProgram, L: float, a: float, parts: list[ArmPart]) -> ArcBounds:
    """The admissible arc at centre distance ``a`` (a ≥ :func:`arm_a_min`): at a position with arm angle
    φ = ψ0 + ψ from A0O, the wedge meets the circle in |β − α| ≤ φ ≤ min(β + α, 2π − β − α), cos β =
    L(1 − εψ′)·cos α/a; ψ0 is bounded below by the largest |β − α| − ψ and above by the smallest
    min(β + α, 2π − β − α) − ψ over the constrained positions, each found at a part end or where its
    derivative in δ changes sign (the exact ψ″)."""
    eps = arm.eps
    lo, hi, part, at, slope_a = -math.inf, math.inf, "", 0.0, 0.0
    for p in parts:
        al, ca = p.alpha, math.cos(p.alpha)

        def beta(m, al=al, ca=ca):
            return _beta(L * (1.0 - eps * m.d1) * ca / a, -eps * L * m.d2 * ca / a)

        def g_lo(m, al=al):
            return np.abs(beta(m)[0] - al) - m.psi

        def s_lo(m, al=al):
            b, db = beta(m)
            return np.sign(b - al) * db - m.d1

        def g_hi(m, al=al):
            b = beta(m)[0]
            return m.psi - np.minimum(b + al, 2.0 * math.pi - b - al)

        def s_hi(m, al=al):
            b, db = beta(m)
            return m.d1 - np.where(b + al < math.pi, db, -db)

        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            v, x = stationary_max(p.seg, p.level, arm.h, g_lo, s_lo, grid=p.grid)
            w, _ = stationary_max(p.seg, p.level, arm.h, g_hi, s_hi, grid=p.grid)
        hi = min(hi, -w)
        if v > lo:
            m = segment_motion(p.seg, p.level, arm.h, [x])
            mu = float(L * (1.0 - eps * m.d1[0]) * ca / a)
            b = math.acos(min(max(mu, -1.0), 1.0))
            sb = math.sqrt(max(1.0 - mu * mu, 0.0))
            d = math.copysign(1.0, b - al) * mu / (a * sb) if sb > 0 else math.copysign(math.inf, mu)
            lo, part, at, slope_a = v, p.part, p.seg.start + p.seg.angle * x, d
    return ArcBounds(a, lo, hi, part, at, slope_a)


def arm_a_min(arm: ArmProgram, L: float, lims: list[Limit]) -> float:
    """The smallest centre distance for which every wedge reaches the circle of radius a about A0:
    max over the constrained parts of |K A0|·cos α_allow = L·|1 − εψ′|·cos α_allow."""
    out = 0.0
    for p in arm_parts(arm, lims):
        ca = math.cos(p.alpha)
        out = max(out, stationary_max(p.seg, p.level, arm.h, lambda m: L * np.abs(1.0 - arm.eps * m.d1) * ca,
                                      lambda m: -np.sign(1.0 - arm.eps * m.d1) * arm.eps * m.d2 * L * ca,
                                      grid=p.grid)[0])
    return out


def arm_reach(arm: ArmProgram, L: float, lims: list[Limit], a: float | None) -> float:
    """:func:`arm_a_min`, after refusing a given centre distance ``a`` that does not exceed it."""
    a_min = arm_a_min(arm, L, lims)
    if a is not None and a <= a_min:
        raise NotAMechanism(f"a = {a:g} mm ≤ {a_min:.6g} mm = max L·|1 − εψ′|·cos α_allow: no centre at that "
                            "distance from A0 keeps the pressure angle within the limit")
    return a_min


def grad_r0(L: float, b: ArcBounds) -> float:
    """d(r0²/2)/da along the arc's lower end ψ0 = lo(a): a − L cos ψ0 + aL sin ψ0·∂lo/∂a (the binding
    position held, the envelope theorem; one-sided at a kink of lo(a))."""
    return b.a - L * math.cos(b.lo) + b.a * L * math.sin(b.lo) * b.dlo_da


SCAN = 121
"""Centre distances a_min·10^(6k/120), k = 0 … 120, scanned (on the grid of positions) for an admissible one."""
REACH = 1e6
"""The farthest centre distance searched, in units of a_min: a region of admissible centres that begins
farther out (an arm stroke h all but equal to 2α_allow) is refused with these numbers."""


def _grid_widths(arm: ArmProgram, L: float, avals: np.ndarray, parts: list[ArmPart]) -> np.ndarray:
    """hi(a) − lo(a) on the grid of positions only (no refinement), for many centre distances at once."""
    lo, hi = np.full(avals.shape, -np.inf), np.full(avals.shape, np.inf)
    for p in parts:
        m = p.grid[1]
        mu = np.clip(L * (1.0 - arm.eps * m.d1)[None, :] * math.cos(p.alpha) / avals[:, None], -1.0, 1.0)
        b = np.arccos(mu)
        lo = np.maximum(lo, np.max(np.abs(b - p.alpha) - m.psi, axis=1))
        hi = np.minimum(hi, np.min(np.minimum(b + p.alpha, 2 * math.pi - b - p.alpha) - m.psi, axis=1))
    return hi - lo


def admissible_distance(arm: ArmProgram, L: float, parts: list[ArmPart], a_min: float) -> float:
    """A centre distance whose circle meets the admissible region (the intersection of the wedges): the
    widest arc of a log-spaced scan from a_min to REACH·a_min, refined by golden section between its
    neighbours when the scan's grid of positions flattered it.

    Raises
    ------
    NotAMechanism
        When no circle up to REACH·a_min meets every wedge: the wedges have no common point there.
    """
    avals = a_min * np.logspace(0.0, math.log10(REACH), SCAN)
    avals[0] = a_min * (1.0 + 1e-9)
    widths = _grid_widths(arm, L, avals, parts)
    k = int(np.argmax(widths))
    width = lambda x: (lambda b: b.hi - b.lo)(arc_bounds(arm, L, x, parts))
    if width(avals[k]) >= 0:
        return float(avals[k])
    lo, hi = avals[max(k - 1, 0)], avals[min(k + 1, SCAN - 1)]
    inv = (math.sqrt(5.0) - 1.0) / 2.0
    c, d = hi - inv * (hi - lo), lo + inv * (hi - lo)
    fc, fd = width(c), width(d)
    for _ in range(100):
        if max(fc, fd) >= 0:
            return c if fc >= fd else d
        if fc > fd:
            hi, d, fd = d, c, fc
            c = hi - inv * (hi - lo)
            fc = width(c)
        else:
            lo, c, fc = c, d, fd
            d = lo + inv * (hi - lo)
            fd = width(d)
        if hi - lo <= 1e-15 * hi:
            break
    raise NotAMechanism(
        f"no centre keeps the pressure angle within the limit: at every centre distance from a_min = {a_min:.6g} mm "
        f"to {REACH:g}·a_min the wedges of the positions leave no common point (closest at a = {avals[k]:.6g} mm, "
        f"a gap of {math.degrees(-max(fc, fd, widths[k])):.4g}°; an arm stroke h = {arm.h:g}° needs "
        f"α_allow ≥ about h/2 for far centres)")


def best_distance(arm: ArmProgram, L: float, parts: list[ArmPart], a_min: float) -> float:
    """The centre distance of the smallest base circle: bisection on the sign of d(r0²)/da along the lower
    end of the admissible arc. The distances whose circle meets the (convex) admissible region form an
    interval, and r0 is unimodal on it (its sublevel sets are convex); a distance whose circle misses the
    region counts as negative below an admissible one (:func:`admissible_distance`) and positive above it,
    so the bisection ends at the smooth minimum, at a kink (two positions binding) or at the region's
    nearest or farthest distance from A0."""
    a_f = admissible_distance(arm, L, parts, a_min)

    def sign(x: float) -> float:
        b = arc_bounds(arm, L, x, parts)
        if not b.feasible:
            return -1.0 if x < a_f else 1.0
        return grad_r0(L, b)

    lo, hi = a_min * (1.0 + 1e-12), a_f
    if sign(lo) >= 0:
        return lo
    for _ in range(2000):
        if sign(hi) > 0:
            break
        lo, hi = hi, 2.0 * hi
    lo, hi = sign_change(sign, lo, hi)
    ends = [b for b in (arc_bounds(arm, L, x, parts) for x in (lo, hi)) if b.feasible]
    if not ends:
        return hi
    return min(ends, key=lambda b: (b.a - L) ** 2 + 4.0 * b.a * L * math.sin(b.lo / 2) ** 2).a



def sign_change(sign, lo: float, hi: float) -> tuple[float, float]:
    """The last representable bracket ``[lo, hi]`` of the place where ``sign`` turns positive (``sign(lo) ≤ 0 <
    sign(hi)``), by bisection until the midpoint is no longer between them.

    Examples
    --------
    >>> lo, hi = sign_change(lambda x: x - 2.0, 0.0, 8.0)
    >>> lo <= 2.0 <= hi and hi - lo <= 4.5e-16
    True
    """
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if sign(mid) > 0:
            hi = mid
        else:
            lo = mid
    return lo, hi

PSI0_MIN = 1e-9
"""Smallest initial arm angle (rad) of a designed cam: below it O lies on the arm's line A0B0 (the pressure
angle is then no constraint: α_allow → 90°, or an all but vanishing stroke)."""


def arm_psi0(arm: ArmProgram, L: float, a: float, lims: list[Limit]) -> tuple[float, str, float, float]:
    """(ψ0 (rad), part, δ (deg), ∂ψ0/∂a) of the smallest admissible arm angle at centre distance ``a``."""
    b = arc_bounds(arm, L, a, arm_parts(arm, lims))
    return b.lo, b.part, b.delta, b.dlo_da


def arm_best(program: Program, h: float, L: float, *, alpha_allow: float, rotation: str = "ccw", arm: str = "left",
             alpha_allow_return: float | None = None, a: float | None = None) -> dict[str, float]:
    """The smallest base circle r0 = OB0 of an oscillating roller/knife follower with arm length ``L`` (the
    wedge route, used by the construction): ``r0``, ``a``, ``psi0`` (deg) and the binding position.

    With ``a`` given, the smallest r0 at that centre distance: r0² = a² + L² − 2aL cos ψ0 grows with ψ0, so
    ψ0 is the lower end of the admissible arc (:func:`arc_bounds`). With ``a`` free, :func:`best_distance`.

    Examples
    --------
    >>> from geomcon.cam.program import parse_program
    >>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
    ...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
    >>> out = arm_best(prog, 20.0, 100.0, alpha_allow=35.0)
    >>> round(out["r0"], 6), round(out["a"], 6), round(out["psi0"], 6), out["part"]
    (15.801126, 109.828531, 6.768158, 'rise')
    >>> round(arm_best(prog, 20.0, 100.0, alpha_allow=35.0, a=130.0)["r0"], 6)
    43.587387
    >>> round(ArmTwin(prog, 20.0, 100.0, alpha_allow=35.0).best(130.0)["r0"], 6)      # the twin's route
    43.587387
    """
    motion = ArmProgram(h, program, rotation, arm)
    lims = limits(program, alpha_allow, alpha_allow_return)
    parts = arm_parts(motion, lims)
    a_min = arm_reach(motion, L, lims, a)
    if a is None:
        a = best_distance(motion, L, parts, a_min)
    b = arc_bounds(motion, L, a, parts)
    if not b.feasible:
        raise NotAMechanism(f"at a = {a:.6g} mm no arm angle ψ0 keeps α within the limit at every position: the "
                            f"wedges leave ψ0 ≥ {math.degrees(b.lo):.6g}° and ψ0 ≤ {math.degrees(b.hi):.6g}°")
    psi0 = b.lo
    if not psi0 > PSI0_MIN:
        raise NotAMechanism(f"the best centre puts O on the arm's line A0B0 (ψ0 = {math.degrees(psi0):.6g}° ≤ "
                            f"{math.degrees(PSI0_MIN):.3g}°, a = {a:.6g} mm): no proper cam — the limit α_allow = "
                            f"{alpha_allow:g}° hardly constrains it; give a")
    r0 = math.sqrt((a - L) ** 2 + 4.0 * a * L * math.sin(psi0 / 2) ** 2)
    return {"r0": r0, "a": a, "psi0": math.degrees(psi0), "part": b.part, "delta": b.delta}


# ---------------------------------------------------------------------------- the oscillating twin
TWIN_GRID = 128
"""The twin's grid of positions per smooth piece; its local extrema are refined by golden section."""
GOLDEN_STEPS = 44
"""Golden-section steps refining a peak between two grid neighbours: 0.618^44 ≈ 6e-10 of the bracket, so the
peak's value is exact to rounding (its error is quadratic) and its place to about 1e-11 of the part."""
TWIN_SCAN = 128
"""Arm angles ψ0 scanned by the twin (rays from A0) for one whose ray meets the admissible region."""
_INV = (math.sqrt(5.0) - 1.0) / 2.0


def _golden_tops(fn: Callable[[np.ndarray], np.ndarray], xs: np.ndarray, grid: np.ndarray) -> list[tuple[float, float]]:
    """For each row k of ``grid`` (the values of function k at ``xs``), (its largest value, where): the grid
    maximum, with every interior local maximum that could exceed it refined by golden-section search
    between its neighbours (all rows and peaks at once, :data:`GOLDEN_STEPS` steps). ``fn(z)`` returns
    every row's values at the points z.

    >>> xs = np.linspace(0.0, 3.0, 7)
    >>> [(round(v, 12), round(x, 6)) for v, x in _golden_tops(lambda z: np.array([np.sin(z), -np.cos(z)]), xs,
    ...                                                      np.array([np.sin(xs), -np.cos(xs)]))]
    [(1.0, 1.570796), (0.9899924966, 3.0)]
    """
    out, rows, lo, hi = [], [], [], []
    gap = np.diff(xs)
    # the pieces' seams (a right end just below the next piece's start): a peak beside a seam is searched on
    # its own side only, between the end and its neighbour inside the piece
    seam = np.concatenate([[True], gap <= 1e-9 * (xs[-1] - xs[0]), [True]])
    left_x = np.where(seam[:-1], xs, np.concatenate([[xs[0]], xs[:-1]]))
    right_x = np.where(seam[1:], xs, np.concatenate([xs[1:], [xs[-1]]]))
    for k, v in enumerate(grid):
        best = int(np.argmax(v))
        out.append((float(v[best]), float(xs[best])))
        left = np.where(seam[:-1], -np.inf, np.concatenate([[-np.inf], v[:-1]]))
        right = np.where(seam[1:], -np.inf, np.concatenate([v[1:], [-np.inf]]))
        near = np.minimum(np.where(np.isfinite(left), left, right), np.where(np.isfinite(right), right, left))
        with np.errstate(invalid="ignore"):
            room = v + 2.0 * (v - near)                     # a smooth peak exceeds its grid value by ≤ ⅓ of it
        i = np.nonzero((v >= left) & (v >= right) & (right_x > left_x) & ~(room < out[k][0]))[0]
        rows += [k] * i.size
        lo.append(left_x[i])
        hi.append(right_x[i])
    if not rows:
        return out
    rows = np.array(rows)
    pick = lambda z: fn(z)[rows, np.arange(rows.size)]
    lo, hi = np.concatenate(lo), np.concatenate(hi)
    c, d = hi - _INV * (hi - lo), lo + _INV * (hi - lo)
    fc, fd = pick(c), pick(d)
    for _ in range(GOLDEN_STEPS):
        left = fc > fd                                          # the maximum lies in [lo, d]
        hi, lo = np.where(left, d, hi), np.where(left, lo, c)
        c, d = np.where(left, hi - _INV * (hi - lo), d), np.where(left, c, lo + _INV * (hi - lo))
        f_new = pick(np.where(left, c, d))
        fc, fd = np.where(left, f_new, fd), np.where(left, fc, f_new)
    for x, f in ((c, fc), (d, fd)):
        for j in range(rows.size):
            if f[j] > out[rows[j]][0]:
                out[rows[j]] = (float(f[j]), float(x[j]))
    return out


def arm_rho_min(cam, n: int = 4 * TWIN_GRID) -> float:
    """ρmin of an oscillating cam's pitch curve over its convex parts by the twin's route: the complex-form
    curvature (:meth:`OscillatingCam.convex_curvature_complex`) on a grid of every smooth piece, peaks refined
    by golden section, a peak beside a piece's end searched on its own side; ``inf`` when nowhere convex."""
    top = -math.inf
    for seg, level in zip(cam.program.segments, levels(cam.program, cam.h)):
        if seg.kind == "dwell":
            xs = np.array([0.0, 0.5, np.nextafter(1.0, 0.0)])
        else:
            xs = np.concatenate([piece_grid(x0, x1, n) for x0, x1 in pieces(seg)])
        kappa = lambda z, seg=seg, level=level: cam.convex_curvature_complex(segment_motion(seg, level, cam.h, z))[None, :]
        top = max(top, _golden_tops(kappa, xs, kappa(xs))[0][0])
    return 1.0 / top if top > 0 else math.inf


class ArmTwin:
    """The twin of :func:`arm_best`, written from the pressure-angle formula alone (no wedges, no circles
    about A0): tan α = |c − a cos φ|/(a sin φ) with c = L(1 − εψ′) and φ = ψ0 + ψ.

    With ``a`` free it walks rays from A0: on the ray at arm angle ψ0 the condition α ≤ α_allow is linear in
    the distance a, a·(cos φ + tan α_allow·sin φ) ≥ c and a·(cos φ − tan α_allow·sin φ) ≤ c, so each
    position admits an interval of a and the ray meets the admissible region in [a_in(ψ0), a_out(ψ0)]
    (extremes over the positions on a grid refined by golden section). The nearest point of the ray to B0
    is a = clip(L cos ψ0, a_in, a_out), and ψ0 is found by bisection on the sign of d(r0²)/dψ0 (the
    binding position held), rays that miss the region counting as negative before an admissible ray
    (found by a scan of ψ0) and positive after it.

    With ``a`` given it minimises the largest excess α − α_allow over ψ0 by golden section (the excess is
    unimodal in ψ0: its sublevel sets are arcs of one circle in a convex region) and then finds the smallest
    admissible ψ0 by bisection on the sign of the excess."""

    def __init__(self, program: Program, h: float, L: float, *, alpha_allow: float, rotation: str = "ccw",
                 arm: str = "left", alpha_allow_return: float | None = None) -> None:
        self.h, self.L = h, L
        self.motion = ArmProgram(h, program, rotation, arm)
        allow = {"rise": alpha_allow}
        if alpha_allow_return is not None and program.ret is not None:
            allow["return"] = alpha_allow_return
        self.parts = []
        for part, value in allow.items():
            k = next(i for i, s in enumerate(program.segments) if s.kind == part)
            seg = program.segments[k]
            xs = np.concatenate([piece_grid(x0, x1, TWIN_GRID) for x0, x1 in pieces(seg)])
            level = levels(program, h)[k]
            self.parts.append((part, seg, level, math.tan(math.radians(value)), xs, self._mot(seg, level, xs)))

    def _mot(self, seg: Segment, level: float, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(ψ, c = L(1 − εψ′)) at fractions x of a segment."""
        m = segment_motion(seg, level, self.h, x)
        return m.psi, self.L * (1.0 - self.motion.eps * m.d1)

    @staticmethod
    def _ray(theta: float, t: float, psi: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(lowest, highest) admissible distance along the ray at ψ0 = θ for positions (ψ, c): from
        a·p ≥ c and a·q ≤ c with p = cos φ + t sin φ, q = cos φ − t sin φ (±inf where no distance or every
        distance passes)."""
        phi = theta + psi
        cs, sn = np.cos(phi), np.sin(phi)
        p, q = cs + t * sn, cs - t * sn
        with np.errstate(divide="ignore", invalid="ignore"):
            rp, rq = c / p, c / q
        inf = np.inf
        low = np.maximum(np.where(p > 0, rp, np.where(c > 0, inf, -inf)),
                         np.where(q < 0, rq, np.where(c < 0, np.where(q > 0, -inf, inf), -inf)))
        high = np.minimum(np.where(p < 0, rp, inf), np.where(q > 0, rq, inf))
        return low, high

    def ray(self, theta: float) -> tuple[float, float, tuple, tuple]:
        """(a_in, a_out, (part index, fraction) of the positions binding a_in and a_out) on the ray at
        ψ0 = θ."""
        a_in, a_out, bind_in, bind_out = 0.0, math.inf, None, None
        for k, (_, seg, level, t, xs, grid) in enumerate(self.parts):
            def both(z, seg=seg, level=level, t=t):
                low, high = self._ray(theta, t, *self._mot(seg, level, z))
                return np.array([low, -high])
            (v, x), (w, y) = _golden_tops(both, xs, np.array(self._ray(theta, t, *grid)) * [[1.0], [-1.0]])
            if v > a_in:
                a_in, bind_in = v, (k, x)
            if -w < a_out:
                a_out, bind_out = -w, (k, y)
        return a_in, a_out, bind_in, bind_out

    def _bound_slope(self, theta: float, k: int, x: float, upper: bool) -> float:
        """d/dδ of the binding bound c/p (or c/q) at fraction x of part k: (c′p − c·p′)/p², c′ = −εLψ″,
        p′ = (−sin φ ± t cos φ)·ψ′ — the lower bound's largest, the upper's smallest of the two."""
        _, seg, level, t, _, _ = self.parts[k]
        m = segment_motion(seg, level, self.h, [x])
        phi = theta + float(m.psi[0])
        c, dc = self.L * (1.0 - self.motion.eps * float(m.d1[0])), -self.motion.eps * self.L * float(m.d2[0])
        cs, sn, w = math.cos(phi), math.sin(phi), float(m.d1[0])
        opts = []
        for p, dp, ok in ((cs + t * sn, (-sn + t * cs) * w, lambda v: v < 0 if upper else v > 0),
                          (cs - t * sn, (-sn - t * cs) * w, lambda v: v > 0 if upper else v < 0)):
            if ok(p):
                opts.append((c / p, (dc * p - c * dp) / (p * p)))
        return (min if upper else max)(opts)[1] if opts else 0.0

    def _polish(self, theta: float, bind: tuple | None, upper: bool) -> tuple | None:
        """The binding position located to :data:`ROOT_TOL` by regula falsi on the bound's exact slope
        (golden section alone leaves a flat peak's place uncertain by about √ε, and d a/dψ0 with it)."""
        if bind is None:
            return None
        k, x = bind
        sign = -1.0 if upper else 1.0
        f = lambda z: sign * self._bound_slope(theta, k, z, upper)
        w = 2.0 / TWIN_GRID
        lo, hi = max(x - w, 0.0), min(x + w, 1.0)
        flo, fhi = f(lo), f(hi)
        if not (flo > 0 > fhi):
            return bind
        return k, _falsi(f, lo, hi, flo, fhi, ROOT_TOL)

    def _d_bound(self, theta: float, bind: tuple, upper: bool) -> float:
        """∂a/∂ψ0 of the bound a = c/p or c/q binding at ``bind`` (the position held): −c·p′/p²."""
        _, seg, level, t, _, _ = self.parts[bind[0]]
        psi, c = self._mot(seg, level, np.array([bind[1]]))
        phi, c = theta + float(psi[0]), float(c[0])
        cs, sn = math.cos(phi), math.sin(phi)
        p, dp, q, dq = cs + t * sn, -sn + t * cs, cs - t * sn, -sn - t * cs
        opts = []
        if (p < 0) if upper else (p > 0):
            opts.append((c / p, -c * dp / (p * p)))
        if (q > 0) if upper else (q < 0):
            opts.append((c / q, -c * dq / (q * q)))
        return (min if upper else max)(opts)[1] if opts else 0.0

    def _best_free(self) -> tuple[float, float]:
        top = math.pi - math.radians(self.h)
        thetas = np.linspace(0.0, top, TWIN_SCAN + 2)[1:-1]
        score = []
        for th in thetas:
            a_in, a_out = 0.0, math.inf
            for _, seg, level, t, xs, grid in self.parts:
                low, high = self._ray(th, t, *grid)
                a_in, a_out = max(a_in, float(np.max(low))), min(a_out, float(np.min(high)))
            score.append(-math.inf if a_in == math.inf else math.inf if a_out == math.inf else
                         (a_out - a_in) / max(a_in, 1e-300))
        order = np.argsort(-np.array(score), kind="stable")
        seed = None
        for k in order[:8]:
            a_in, a_out, _, _ = self.ray(float(thetas[k]))
            if a_in <= a_out:
                seed = float(thetas[k])
                break
        if seed is None:
            raise NotAMechanism("no cam centre keeps the pressure angle within the limit (no ray from the arm's "
                                "pivot meets every position's admissible region)")

        def sign(th: float) -> float:
            if th <= 0.0:
                return -1.0
            if th >= top:
                return 1.0
            a_in, a_out, b_in, b_out = self.ray(th)
            if a_in > a_out:
                return -1.0 if th < seed else 1.0
            a = min(max(self.L * math.cos(th), a_in), a_out)
            if a == a_in and b_in is not None:
                slope = self._d_bound(th, self._polish(th, b_in, False), upper=False)
            elif a == a_out and b_out is not None:
                slope = self._d_bound(th, self._polish(th, b_out, True), upper=True)
            else:
                slope = 0.0                                     # the foot of B0 on the ray: r0 = L sin ψ0
            return (a - self.L * math.cos(th)) * slope + a * self.L * math.sin(th)

        lo, hi = sign_change(sign, 0.0, top)
        best = None                                     # the end of the last bracket whose ray meets the region
        for th in (lo, hi):
            a_in, a_out, _, _ = self.ray(th)
            if 0.0 < th < top and a_in <= a_out * (1.0 + 1e-13):
                a = min(max(self.L * math.cos(th), a_in), a_out)
                r2 = (a - self.L) ** 2 + 4.0 * a * self.L * math.sin(th / 2) ** 2
                if best is None or r2 < best[0]:
                    best = (r2, a, th)
        if best is None:
            raise NotAMechanism(f"no ray from the arm's pivot near ψ0 = {math.degrees(hi):.6g}° meets the admissible "
                                "region")
        return best[1], best[2]

    def excess(self, a: float, theta: float) -> float:
        """The largest α − α_allow (rad) over the constrained positions for the centre (a, ψ0 = θ)."""
        worst = -math.inf
        for _, seg, level, t, xs, grid in self.parts:
            allow = math.atan(t)

            def alpha(z, psi_c=None, seg=seg, level=level):
                psi, c = psi_c if psi_c is not None else self._mot(seg, level, z)
                phi = theta + psi
                return np.arctan2(np.abs(c - a * np.cos(phi)), a * np.sin(phi))[None, :] - allow
            worst = max(worst, _golden_tops(alpha, xs, alpha(xs, grid))[0][0])
        return worst

    def _psi0_at(self, a: float) -> float:
        top = math.pi - math.radians(self.h)
        f = lambda th: self.excess(a, th)
        lo, hi = 0.0, top
        c, d = hi - _INV * (hi - lo), lo + _INV * (hi - lo)
        fc, fd = f(c), f(d)
        for _ in range(120):
            if min(fc, fd) <= 0:
                break
            if fc < fd:
                hi, d, fd = d, c, fc
                c = hi - _INV * (hi - lo)
                fc = f(c)
            else:
                lo, c, fc = c, d, fd
                d = lo + _INV * (hi - lo)
                fd = f(d)
        if min(fc, fd) > 0:
            raise NotAMechanism(f"a = {a:g} mm: no arm angle keeps the pressure angle within the limit")
        seed = c if fc <= 0 else d
        return bisect_root(lambda th: -1.0 if th <= 0 else (1.0 if f(th) <= 0 else -1.0), 0.0, seed)

    def best(self, a: float | None = None) -> dict[str, float]:
        """``r0``, ``a``, ``psi0`` (deg) of the smallest base circle (at the given a, or the best a)."""
        if a is None:
            a, psi0 = self._best_free()
        else:
            psi0 = self._psi0_at(a)
        r0 = math.sqrt((a - self.L) ** 2 + 4.0 * a * self.L * math.sin(psi0 / 2) ** 2)
        return {"r0": r0, "a": a, "psi0": math.degrees(psi0)}
