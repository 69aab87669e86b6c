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

The search over a (:func:`arc_root`) keeps a bisection's bracket but steps by Newton on the crossing of two
parts' bounds when different parts bind at its ends (the kink, located in a few steps), or by the secant of
the slope when one position binds at both. The twin (:class:`~geomcon.cam.arm_twin.ArmTwin`, its own module)
uses neither wedges nor circles: rays from A0 and the excess α − α_allow, its peaks refined by Brent's method.

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
from .arm_twin import ArmTwin, arm_rho_min  # noqa: F401  (the twin, re-exported: its own module)
from .arm_twin import _falsi   # the same Illinois search the twin's binding positions use
from .oscillating import ArmMotion, Motion, levels, piece_grid, pieces, segment_motion, segment_motion1
from .profile import sign1
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


ROOT_TOL = 1e-13
"""Width (as a fraction of a segment) to which a stationary position is located: the value there is then
exact to rounding (its error is quadratic), the slopes taken there to about 1e-13."""


def stationary_max(seg: Segment, level: float, h: float, g: Callable[[Motion], np.ndarray],
                   slope: Callable[[Motion], np.ndarray], n: int = GRID_ARM,
                   grid: tuple[np.ndarray, Motion] | None = None, *,
                   g1: Callable[[tuple[float, float, float, float]], float] | None = None,
                   slope1: Callable[[tuple[float, float, float, float]], float] | None = None,
                   values: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[float, float]:
    """(max of ``g`` over the segment, the fraction where): the grid, the ends of every smooth piece
    (one-sided) and the roots of ``slope`` = dg/dδ (per radian) where it turns from + to − between grid
    points, refined only where the grid values and slopes leave room for a value above the best so far.
    ``grid`` = (fractions, their motion) may be given precomputed (:func:`arm_grid`), and ``values`` = (g, slope)
    on it. ``g1`` and ``slope1``, the same functions of one motion (δ, ψ, ψ′, ψ″) of
    :func:`~geomcon.cam.oscillating.segment_motion1` on floats, refine without array calls.

    >>> from geomcon.cam.laws import law
    >>> seg = Segment("rise", 0.0, 120.0, law("cosine"))
    >>> v, x = stationary_max(seg, 0.0, 20.0, lambda m: m.d1, lambda m: m.d2, g1=lambda m: m[2], slope1=lambda m: m[3])
    >>> round(x, 12), round(v, 12) == round(math.radians(20.0) * math.pi / 2 / math.radians(120.0), 12)
    (0.5, True)
    """
    xs, m = grid if grid is not None else arm_grid(seg, level, h, n)
    v, sl = values if values is not None else (g(m), slope(m))
    j = int(np.argmax(v))
    best, where = float(v[j]), float(xs[j])
    step = math.radians(seg.angle) * (xs[1:] - xs[:-1])
    room = np.maximum(v[:-1], v[1:]) + step * np.maximum(sl[:-1], -sl[1:])
    live = np.nonzero((sl[:-1] > 0) & (sl[1:] < 0) & (step > 0) & ~(room < best))[0].tolist()
    if not live:
        return best, where
    if slope1 is not None and g1 is not None:
        f = lambda x: slope1(segment_motion1(seg, level, h, x))
        value = lambda x: g1(segment_motion1(seg, level, h, x))
    else:
        f = lambda x: float(slope(segment_motion(seg, level, h, [x]))[0])
        value = lambda x: float(g(segment_motion(seg, level, h, [x]))[0])
    for i in live:
        x = _falsi(f, float(xs[i]), float(xs[i + 1]), float(sl[i]), float(sl[i + 1]), ROOT_TOL)
        val = value(x)
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
    each: tuple[tuple[str, float, float], ...] = ()
    """(part, its own lower bound, ∂ of it /∂a) for every constrained part: where two parts bind at once,
    the kink is where their bounds cross."""

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
    derivative in δ changes sign (the exact ψ″). β is computed once per grid position for both ends; the
    roots are refined on floats."""
    eps, h = arm.eps, arm.h
    two_pi = 2.0 * math.pi
    lo, hi, part, at, slope_a = -math.inf, math.inf, "", 0.0, 0.0
    each = []
    for p in parts:
        al, ca = p.alpha, math.cos(p.alpha)
        m = p.grid[1]
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            b, db = _beta(L * (1.0 - eps * m.d1) * ca / a, -eps * L * m.d2 * ca / a)
            v_lo = np.abs(b - al) - m.psi
            s_lo = np.sign(b - al) * db - m.d1
            v_hi = m.psi - np.minimum(b + al, two_pi - b - al)
            s_hi = m.d1 - np.where(b + al < math.pi, db, -db)

        def beta1(d1: float, d2: float, al=al, ca=ca) -> tuple[float, float]:
            mu = L * (1.0 - eps * d1) * ca / a
            dmu = -eps * L * d2 * ca / a
            return math.acos(min(max(mu, -1.0), 1.0)), -dmu / math.sqrt(max(1.0 - mu * mu, 1e-300))

        def g_lo1(mo, al=al, beta1=beta1):
            return abs(beta1(mo[2], mo[3])[0] - al) - mo[1]

        def s_lo1(mo, al=al, beta1=beta1):
            b1, db1 = beta1(mo[2], mo[3])
            return sign1(b1 - al) * db1 - mo[2]

        def g_hi1(mo, al=al, beta1=beta1):
            b1 = beta1(mo[2], mo[3])[0]
            return mo[1] - min(b1 + al, two_pi - b1 - al)

        def s_hi1(mo, al=al, beta1=beta1):
            b1, db1 = beta1(mo[2], mo[3])
            return mo[2] - (db1 if b1 + al < math.pi else -db1)

        v, x = stationary_max(p.seg, p.level, h, None, None, grid=p.grid, values=(v_lo, s_lo), g1=g_lo1,
                              slope1=s_lo1)
        w, _ = stationary_max(p.seg, p.level, h, None, None, grid=p.grid, values=(v_hi, s_hi), g1=g_hi1,
                              slope1=s_hi1)
        hi = min(hi, -w)
        d1 = segment_motion1(p.seg, p.level, h, x)[2]
        mu = L * (1.0 - eps * d1) * ca / a
        b1 = math.acos(min(max(mu, -1.0), 1.0))
        sb = math.sqrt(max(1.0 - mu * mu, 0.0))
        d = math.copysign(1.0, b1 - al) * mu / (a * sb) if sb > 0 else math.copysign(math.inf, mu)
        each.append((p.part, v, d))
        if v > lo:
            lo, part, at, slope_a = v, p.part, p.seg.start + p.seg.angle * x, d
    return ArcBounds(a, lo, hi, part, at, slope_a, tuple(each))


def arm_a_min(arm: ArmProgram, L: float, lims: list[Limit]) -> float:
    """The smallest centre distance for which every wedge reaches the circle of radius a about A0:
    max over the constrained parts of |K A0|·cos α_allow = L·|1 − εψ′|·cos α_allow."""
    out = 0.0
    for p in arm_parts(arm, lims):
        ca = math.cos(p.alpha)
        eps = arm.eps
        out = max(out, stationary_max(p.seg, p.level, arm.h, lambda m: L * np.abs(1.0 - eps * m.d1) * ca,
                                      lambda m: -np.sign(1.0 - eps * m.d1) * eps * m.d2 * L * ca, grid=p.grid,
                                      g1=lambda mo: L * abs(1.0 - eps * mo[2]) * ca,
                                      slope1=lambda mo: -sign1(1.0 - eps * mo[2]) * eps * mo[3] * L * ca)[0])
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
    """The centre distance of the smallest base circle: the sign change of d(r0²)/da along the lower end of
    the admissible arc (:func:`arc_root`). The distances whose circle meets the (convex) admissible region
    form an interval, and r0 is unimodal on it (its sublevel sets are convex); a distance whose circle misses
    the region counts as negative below an admissible one (:func:`admissible_distance`) and positive above
    it, so the search ends at the smooth minimum, at a kink (two positions binding) or at the region's
    nearest or farthest distance from A0."""
    a_f = admissible_distance(arm, L, parts, a_min)
    seen: dict[float, ArcBounds] = {}

    def evaluate(x: float) -> tuple[float, ArcBounds]:
        b = seen[x] = arc_bounds(arm, L, x, parts)
        if not b.feasible:
            return (-1.0 if x < a_f else 1.0), b
        return grad_r0(L, b), b

    lo, hi = a_min * (1.0 + 1e-12), a_f
    at_lo = evaluate(lo)
    if at_lo[0] >= 0:
        return lo
    for _ in range(2000):
        at_hi = evaluate(hi)
        if at_hi[0] > 0:
            break
        lo, hi, at_lo = hi, 2.0 * hi, at_hi
    lo, hi = arc_root(evaluate, lo, hi, at_lo, at_hi)
    ends = [b for b in (seen[x] if x in seen else arc_bounds(arm, L, x, parts) for x in (lo, hi)) if b.feasible]
    if not ends:
        return hi
    return min(ends, key=lambda b: (b.a - L) ** 2 + 4.0 * b.a * L * math.sin(b.lo / 2) ** 2).a


SAME_PLACE = 1e-2
"""Cam angles (degrees) within which two binding positions of one part count as the same position (a
binding position moves with a; two peaks of one part lie a grid cell apart or more)."""


def arc_root(evaluate: Callable[[float], tuple[float, ArcBounds]], lo: float, hi: float,
             at_lo: tuple[float, ArcBounds], at_hi: tuple[float, ArcBounds]) -> tuple[float, float]:
    """The last representable bracket [lo, hi] of the place where d(r0²)/da turns positive, given its values
    and arcs at both ends (``evaluate(x)`` = (the sign's value, :func:`arc_bounds` at x)).

    Each step tries the point the two ends predict: when one position binds at both ends the slope is smooth
    between them and its secant is taken; when two different positions bind, the optimum is usually the kink
    where their bounds cross, and the tangents of ψ0 = lo(a) at both ends (the binding position held,
    ∂lo/∂a exact) meet near it. A trial point is kept a few units of the last place inside the bracket (so a
    step onto the root is followed by one just past it), and the bracket is halved instead when an end is
    not admissible or two steps in a row failed to halve it: a bisection's bracket, in a dozen steps rather
    than sixty.

    Examples
    --------
    >>> def ev(x):            # a kink at x = 2: ψ0 = max(1 − x/4, x/2 − 1/2), r0² grows with ψ0 only
    ...     first = 1 - x / 4 >= x / 2 - 0.5
    ...     b = ArcBounds(x, 1 - x / 4 if first else x / 2 - 0.5, 9.0, "rise", 10.0 if first else 50.0,
    ...                   -0.25 if first else 0.5)
    ...     return b.dlo_da, b
    >>> lo, hi = arc_root(ev, 0.0, 8.0, ev(0.0), ev(8.0))
    >>> lo <= 2.0 <= hi and hi - lo <= 4.5e-16
    True
    """
    slow, last, scale_lo, scale_hi = 0, 0, 1.0, 1.0
    for _ in range(400):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if 0.0 < 4.0 * lo < hi:
            mid = math.sqrt(lo * hi)                        # a wide bracket of distances: halved in ratio
        (f1, b1), (f2, b2) = at_lo, at_hi
        x = mid
        if slow < 3 and b1.feasible and b2.feasible:
            x = _trial(lo, hi, f1 * scale_lo, b1, f2 * scale_hi, b2)
            tol = 4.0 * _EPS * max(abs(lo), abs(hi))
            x = min(max(x, lo + tol), hi - tol) if lo <= x <= hi else mid
            if not lo < x < hi:
                x = mid
        width = hi - lo
        at = evaluate(x)
        if at[0] > 0:
            hi, at_hi = x, at
            side = 1
        else:
            lo, at_lo = x, at
            side = -1
        if side < 0:                                # Illinois: the end kept twice in a row has its value halved
            scale_lo, scale_hi = 1.0, scale_hi * 0.5 if last < 0 else scale_hi
        else:
            scale_hi, scale_lo = 1.0, scale_lo * 0.5 if last > 0 else scale_lo
        last = side
        slow = 0 if x == mid or hi - lo <= 0.5 * width else slow + 1
    return lo, hi


def _trial(lo: float, hi: float, f1: float, b1: ArcBounds, f2: float, b2: ArcBounds) -> float:
    """The next point :func:`arc_root` tries in [lo, hi] (``nan`` for none): Newton's step on the difference
    of two parts' bounds where different parts bind at the ends (from the end nearer their crossing), the
    secant of the slope where one position binds at both (else none: the bracket is halved)."""
    if b1.part != b2.part:
        steps = []
        for b in (b1, b2):
            own = {p: (v, d) for p, v, d in b.each}
            if b1.part in own and b2.part in own:
                (v1, d1), (v2, d2) = own[b1.part], own[b2.part]
                if d1 != d2 and math.isfinite(d1) and math.isfinite(d2):
                    steps.append((abs(v1 - v2), b.a - (v1 - v2) / (d1 - d2)))
        if steps:
            return min(steps)[1]
    if b1.part == b2.part and abs(b1.delta - b2.delta) <= SAME_PLACE and f2 != f1:
        return hi - f2 * (hi - lo) / (f2 - f1)
    return math.nan


_EPS = 2.220446049250313e-16


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
