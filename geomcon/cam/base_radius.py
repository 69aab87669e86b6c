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
smallest admissible ψ0 = max_δ(|β − α_allow| − ψ) (:func:`arm_best`, the construction's route), and with a
free the a where d(r0²)/da changes sign. The admissible region (an intersection of wedges) is convex, so r0(a)
is unimodal and the optimum unique; it is often a vertex where two positions bind at once (a kink of r0(a)).
The twin (:class:`ArmTwin`) never uses the wedges: it measures the largest α of a candidate cam with
cam.oscillating's complex-tangent route and solves α_max(ψ0) = α_allow by regula falsi.

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
from .oscillating import ArmMotion, Motion, OscillatingCam, levels, segment_motion
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


# ---------------------------------------------------------------------------- oscillating (arm) follower
@dataclass(frozen=True)
class ArmProgram(ArmMotion):
    """The motion of an arm follower without a cam yet: angular stroke ``h`` (deg), ``program``, senses."""

    h: float
    program: Program
    rotation: str = "ccw"
    arm: str = "left"


def _arm_ratio(arm: ArmProgram, L: float, a: float, alpha: float, m: Motion) -> tuple[np.ndarray, np.ndarray]:
    """(μ, dμ/dδ) with μ = L(1 − εψ′)·cos α / a = cos β."""
    ca = math.cos(alpha)
    return L * (1.0 - arm.eps * m.d1) * ca / a, -arm.eps * L * m.d2 * ca / a


def arm_a_min(arm: ArmProgram, L: float, lims: list[Limit]) -> float:
    """The smallest centre distance for which every wedge reaches the circle of radius a about A0:
    max over the constrained parts of |K A0|·cos α_allow = L·|1 − εψ′|·cos α_allow."""
    out = 0.0
    for lim in lims:
        ca = math.cos(math.atan(lim.t))
        out = max(out, arm.segment_max(lim.part, lambda m: L * np.abs(1.0 - arm.eps * m.d1) * ca,
                                       lambda m: -np.sign(1.0 - arm.eps * m.d1) * arm.eps * m.d2)[0])
    return out


def arm_reach(arm: ArmProgram, L: float, lims: list[Limit], a: float | None) -> float:
    """:func:`arm_a_min`, after refusing a given centre distance ``a`` that does not exceed it."""
    a_min = arm_a_min(arm, L, lims)
    if a is not None and a <= a_min:
        raise NotAMechanism(f"a = {a:g} mm ≤ {a_min:.6g} mm = max L·|1 − εψ′|·cos α_allow: no centre at that "
                            "distance from A0 keeps the pressure angle within the limit")
    return a_min


def arm_lower(arm: ArmProgram, L: float, a: float, lim: Limit) -> tuple[float, float, float]:
    """(the smallest admissible ψ0 (rad) for the part, δ (deg) of the binding position, ∂ψ0/∂a there).

    At a position with arm angle φ = ψ0 + ψ from A0O, α ≤ α_allow ⟺ |β − α_allow| ≤ φ ≤ β + α_allow with
    cos β = L(1 − εψ′)·cos α_allow / a; so ψ0 ≥ |β − α| − ψ, largest at a part end or where its
    derivative sign(β − α)·β′ − ψ′ changes sign (bisection on the exact ψ″)."""
    alpha = math.atan(lim.t)

    def parts(m):
        mu, dmu = _arm_ratio(arm, L, a, alpha, m)
        beta = np.arccos(np.clip(mu, -1.0, 1.0))
        root = np.sqrt(np.maximum(1.0 - mu * mu, 1e-300))
        return mu, beta, -dmu / root, root

    def g(m):
        return np.abs(parts(m)[1] - alpha) - m.psi

    def slope(m):
        _, beta, dbeta, _ = parts(m)
        return np.sign(beta - alpha) * dbeta - m.d1

    val, at = arm.segment_max(lim.part, g, slope)
    m = part_motion(arm, lim.part, at)
    mu, beta, _, root = parts(m)
    return val, at, float(np.sign(beta[0] - alpha) * mu[0] / (a * root[0]))


def arm_upper_excess(arm: ArmProgram, L: float, a: float, lim: Limit, psi0: float) -> float:
    """max over the part of ψ0 + ψ − min(β + α, 2π − β − α) (rad): > 0 when some position's upper bound on
    φ is crossed (the admissible arc at this a is empty)."""
    alpha = math.atan(lim.t)

    def beta(m):
        mu, dmu = _arm_ratio(arm, L, a, alpha, m)
        return np.arccos(np.clip(mu, -1.0, 1.0)), -dmu / np.sqrt(np.maximum(1.0 - mu * mu, 1e-300))

    def g(m):
        b = beta(m)[0]
        return psi0 + m.psi - np.minimum(b + alpha, 2 * math.pi - b - alpha)

    def slope(m):
        b, db = beta(m)
        return m.d1 - np.where(b + alpha < 2 * math.pi - b - alpha, db, -db)

    return arm.segment_max(lim.part, g, slope)[0]


def part_motion(arm: ArmMotion, part: str, delta_deg: float) -> Motion:
    """The motion at ``delta_deg`` inside the ``part`` segment (one-sided at its ends)."""
    k = next(i for i, s in enumerate(arm.program.segments) if s.kind == part)
    seg = arm.program.segments[k]
    x = min(max((delta_deg - seg.start) / seg.angle, 0.0), 1.0)
    return segment_motion(seg, levels(arm.program, arm.h)[k], arm.h, [x])


def arm_psi0(arm: ArmProgram, L: float, a: float, lims: list[Limit]) -> tuple[float, str, float, float]:
    """(ψ0 (rad), part, δ (deg), ∂ψ0/∂a) of the smallest admissible arm angle at centre distance ``a``."""
    best = (-math.inf, "", 0.0, 0.0)
    for lim in lims:
        val, at, slope = arm_lower(arm, L, a, lim)
        if val > best[0]:
            best = (val, lim.part, at, slope)
    return best


def arm_best(program: Program, h: float, L: float, *, alpha_allow: float, rotation: str = "ccw", arm: str = "left",
             alpha_allow_return: float | None = None, a: float | None = None) -> dict[str, float]:
    """The smallest base circle r0 = OB0 of an oscillating roller/knife follower with arm length ``L`` (the
    wedge route, used by the construction): ``r0``, ``a``, ``psi0`` (deg) and the binding position.

    With ``a`` given, the smallest r0 at that centre distance: r0² = a² + L² − 2aL·cos ψ0 grows with ψ0, so
    ψ0 is the largest lower bound (:func:`arm_lower`). With ``a`` free, r0(a) is minimised by bisection on
    the sign of d(r0²/2)/da = a − L cos ψ0 + aL sin ψ0·∂ψ0/∂a (one-sided at a kink).

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
    a_min = arm_reach(motion, L, lims, a)
    if a is None:
        def grad(x: float) -> float:
            psi0, _, _, slope = arm_psi0(motion, L, x, lims)
            return x - L * math.cos(psi0) + x * L * math.sin(psi0) * slope
        lo = a_min * (1.0 + 1e-12) + 1e-300
        hi = max(2.0 * a_min, L)
        while grad(hi) < 0:
            hi *= 2.0
        a = lo if grad(lo) >= 0 else bisect_root(grad, lo, hi)
    psi0, part, at, _ = arm_psi0(motion, L, a, lims)
    if not psi0 > 1e-9:
        raise NotAMechanism(f"the best centre puts O on the arm's line A0B0 (ψ0 = {math.degrees(psi0):.6g}°, "
                            f"a = {a:.6g} mm): no proper cam")
    if math.degrees(psi0) + h >= 180.0:
        raise NotAMechanism(f"ψ0 + h = {math.degrees(psi0):.6g}° + {h:g}° ≥ 180° at a = {a:.6g} mm: the arm would "
                            "swing through the line A0O")
    for lim in lims:
        over = arm_upper_excess(motion, L, a, lim, psi0)
        if over > 1e-12:
            raise NotAMechanism(f"at a = {a:.6g} mm no arm angle ψ0 satisfies every position of the {lim.part}: "
                                f"its upper bound is crossed by {math.degrees(over):.4g}°")
    r0 = math.sqrt(max((a - L) ** 2 + 4.0 * a * L * math.sin(psi0 / 2) ** 2, 0.0))
    return {"r0": r0, "a": a, "psi0": math.degrees(psi0), "part": part, "delta": at}


# ---------------------------------------------------------------------------- the oscillating twin
def _illinois(f: Callable[[float], float], lo: float, flo: float, hi: float, fhi: float) -> float:
    """The point where ``f`` turns from > 0 (at lo) to ≤ 0 (at hi), by regula falsi with the Illinois
    modification to the last bits; returns the ≤ 0 side."""
    side = 0
    for _ in range(300):
        c = (lo * fhi - hi * flo) / (fhi - flo)
        if not min(lo, hi) < c < max(lo, hi):
            c = 0.5 * (lo + hi)
            if not min(lo, hi) < c < max(lo, hi):
                break
        fc = f(c)
        if fc > 0:
            lo, flo = c, fc
            if side < 0:
                fhi *= 0.5
            side = -1
        else:
            hi, fhi = c, fc
            if side > 0:
                flo *= 0.5
            side = 1
        if abs(hi - lo) <= 4e-16 * abs(hi):
            break
    return hi


STEP = 0.02
"""The twin's largest step (rad) in ψ0 while it looks for an admissible arm angle: the admissible interval of
ψ0 at a centre distance is assumed wider than this (about 1.1°)."""


class ArmTwin:
    """The twin of :func:`arm_best`: for a candidate centre (a, ψ0) the largest pressure angles of the rise
    (and the return) by :meth:`OscillatingCam.worst_pressure` (its complex-tangent route, roots of dα/dδ);
    ψ0(a) is where the largest excess over the allowance turns ≤ 0 (regula falsi), and with a free the
    optimum is where d(r0²)/da changes sign (bisection), dψ0/da = c·sin φ / (a(a − c cos φ)) at the binding
    position (c = L(1 − εψ′), by implicit differentiation of tan α = (c − a cos φ)/(a sin φ))."""

    def __init__(self, program: Program, h: float, L: float, *, alpha_allow: float, rotation: str = "ccw",
                 arm: str = "left", alpha_allow_return: float | None = None) -> None:
        self.program, self.h, self.L, self.rotation, self.arm = program, h, L, rotation, arm
        self.allow = {"rise": alpha_allow}
        if alpha_allow_return is not None and program.ret is not None:
            self.allow["return"] = alpha_allow_return
        self.hint: float | None = None          # the last ψ0 found, where the next search starts
        self.moved = STEP                        # how far it moved from the one before
        self.too_near = 0.0                      # the largest centre distance found inadmissible

    def cam(self, a: float, psi0: float) -> OscillatingCam:
        """The cam with centre distance a and initial arm angle ψ0 (rad)."""
        r0 = math.sqrt((a - self.L) ** 2 + 4.0 * a * self.L * math.sin(psi0 / 2) ** 2)
        return OscillatingCam(a, self.L, r0, self.h, self.program, self.rotation, self.arm)

    def excess(self, a: float, psi0: float) -> tuple[float, str, float]:
        """(largest α_max − α_allow (deg) over the constrained parts, its part, its δ (deg))."""
        cam = self.cam(a, psi0)
        worst = {p: cam.worst_pressure(p, route="arg") for p in self.allow}
        return max((worst[p][0] - v, p, worst[p][1]) for p, v in self.allow.items())

    def psi0_at(self, a: float) -> float | None:
        """The smallest admissible ψ0 (rad) at centre distance a; None when no ψ0 < π − h is admissible."""
        f = lambda p: self.excess(a, p)[0]
        top = math.pi - math.radians(self.h)
        w = STEP if self.hint is None else min(max(2.0 * self.moved, 1e-14 * self.hint, 1e-300), STEP)
        lo = 1e-9 if self.hint is None else self.hint - w
        flo = f(lo)
        while flo <= 0 and lo > 1e-9:
            w = min(4.0 * w, STEP)
            lo = max(lo - w, 1e-9)
            flo = f(lo)
        if flo <= 0:
            return None
        hi = lo
        while True:
            hi = min(hi + w, top)
            fhi = f(hi)
            if fhi <= 0:
                break
            if hi >= top:
                return None
            lo, flo, w = hi, fhi, min(4.0 * w, STEP)
        psi0 = _illinois(f, lo, flo, hi, fhi)
        self.moved = abs(psi0 - self.hint) if self.hint is not None else STEP
        self.hint = psi0
        return psi0

    def grad(self, a: float) -> float:
        """The sign-carrying d(r0²/2)/da; −1 where no centre at distance a is admissible (a too small: the
        admissible distances from A0 are those of a convex region beyond ``too_near``)."""
        if a <= self.too_near:
            return -1.0
        psi0 = self.psi0_at(a)
        if psi0 is None:
            self.too_near = a
            return -1.0
        _, part, at = self.excess(a, psi0)
        m = part_motion(self.cam(a, psi0), part, at)
        c, phi = self.L * (1.0 - self.cam(a, psi0).eps * float(m.d1[0])), psi0 + float(m.psi[0])
        dpsi = c * math.sin(phi) / (a * (a - c * math.cos(phi)))
        return a - self.L * math.cos(psi0) + a * self.L * math.sin(psi0) * dpsi

    def best(self, a: float | None = None) -> dict[str, float]:
        """``r0``, ``a``, ``psi0`` (deg) of the smallest base circle (at the given a, or the best a)."""
        if a is None:
            lo = hi = self.L
            if self.grad(hi) < 0:
                while self.grad(hi) < 0:
                    lo, hi = hi, 1.5 * hi
            else:
                while self.grad(lo) >= 0:
                    lo, hi = 0.75 * lo, lo
            a = bisect_root(self.grad, lo, hi)
        psi0 = self.psi0_at(a)
        if psi0 is None:
            raise NotAMechanism(f"a = {a:g} mm: no arm angle keeps the pressure angle within the limit")
        r0 = math.sqrt((a - self.L) ** 2 + 4.0 * a * self.L * math.sin(psi0 / 2) ** 2)
        return {"r0": r0, "a": a, "psi0": math.degrees(psi0)}
