"""The analytic twin of the oscillating follower's smallest base circle (``cam.base_radius``, ``motion =
"oscillating"``): written from the pressure-angle formula alone, with no wedges and no circles about A0.

With the centre O at distance a from the arm's pivot A0 and the arm's angle φ = ψ0 + ψ from A0O,

    tan α = |c − a cos φ| / (a sin φ),        c = L(1 − εψ′)

(conventions of :mod:`geomcon.cam.oscillating`). On the ray from A0 at arm angle ψ0 = θ the condition
α ≤ α_allow is linear in the distance a: a·p ≥ c and a·q ≤ c with p = cos φ + t sin φ, q = cos φ − t sin φ,
t = tan α_allow. So each position admits an interval of a, and the ray meets the admissible region in
[a_in(θ), a_out(θ)], the largest lower and the smallest upper bound over the positions (:meth:`ArmTwin.ray`).
Those extremes are taken on a grid of each smooth piece of the motion and every grid peak that could beat the
grid's best is refined by Brent's method on the bound's value, one float at a time
(:func:`~geomcon.cam.profile.brent_max1`, the motion by :func:`~geomcon.cam.oscillating.segment_motion1`).

With a free, the nearest point of the ray to B0 is a = clip(L cos θ, a_in, a_out), and r0² along it is
minimised over θ by bisection on the sign of d(r0²)/dθ: the binding position held (the envelope theorem),
located to the last digits by regula falsi on the bound's exact slope in δ, ∂a/∂θ = −c·p′/p². Rays that miss
the region count as negative before an admissible ray (found by one scan of θ, all rays and positions in one
array) and positive after it. With a given, the largest excess α − α_allow over the positions is minimised
over θ by golden section (it is unimodal: its sublevel sets are arcs of one circle in a convex region) and
the smallest admissible θ is found by bisection on its sign.

The construction (:func:`geomcon.cam.base_radius.arm_best`) takes the other route: the admissible arc of the
circle about A0 at each distance a, its ends from the exact slopes, and bisection on a.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
>>> out = ArmTwin(prog, 20.0, 100.0, alpha_allow=35.0).best()
>>> round(out["r0"], 6), round(out["a"], 6), round(out["psi0"], 6)
(15.801126, 109.828531, 6.768158)
>>> round(ArmTwin(prog, 20.0, 100.0, alpha_allow=35.0).best(130.0)["r0"], 6)
43.587387
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..errors import NotAMechanism
from .oscillating import levels, piece_grid, pieces, segment_motion, segment_motion1
from .profile import brent_max1
from .program import Program, Segment

TWIN_GRID = 128
"""The twin's grid of positions per smooth piece; its peaks are refined by Brent's method."""
TWIN_SCAN = 128
"""Arm angles ψ0 scanned by the twin (rays from A0) for one whose ray meets the admissible region."""
PEAK_TOL = 1e-10
"""Width (as a fraction of the segment) to which Brent's method narrows a peak: the value there is exact to
rounding (its error is quadratic in the place's)."""
ROOT_TOL = 1e-13
"""Width (as a fraction of the segment) to which the binding position is located on the bound's exact slope
before ∂a/∂θ is taken there."""
_INV = (math.sqrt(5.0) - 1.0) / 2.0
_INF = math.inf


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


def bounds_of(phi: np.ndarray, t: float, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(lowest, highest) admissible distance a along a ray for positions at arm angles ``phi`` from A0O with
    c = L(1 − εψ′): from a·p ≥ c and a·q ≤ c, p = cos φ + t sin φ, q = cos φ − t sin φ (±inf where no
    distance or every distance passes). Arrays of any shape.

    >>> low, high = bounds_of(np.array([0.5]), 0.7, np.array([80.0]))
    >>> bool(abs(low[0] - 80.0 / (math.cos(0.5) + 0.7 * math.sin(0.5))) < 1e-12), bool(high[0] == 80.0 / (math.cos(0.5) - 0.7 * math.sin(0.5)))
    (True, True)
    """
    cs, sn = np.cos(phi), np.sin(phi)
    p, q = cs + t * sn, cs - t * sn
    with np.errstate(divide="ignore", invalid="ignore"):
        rp, rq = c / p, c / q
    inf = np.inf
    low = np.maximum(np.where(p > 0, rp, np.where(c > 0, inf, -inf)),
                     np.where(q < 0, rq, np.where(c < 0, np.where(q > 0, -inf, inf), -inf)))
    high = np.minimum(np.where(p < 0, rp, inf), np.where(q > 0, rq, inf))
    return low, high


def bounds1(phi: float, t: float, c: float) -> tuple[float, float]:
    """:func:`bounds_of` for one position, on floats.

    >>> bounds1(0.5, 0.7, 80.0) == tuple(float(v[0]) for v in bounds_of(np.array([0.5]), 0.7, np.array([80.0])))
    True
    """
    cs, sn = math.cos(phi), math.sin(phi)
    p, q = cs + t * sn, cs - t * sn
    low = c / p if p > 0 else (_INF if c > 0 else -_INF)
    if q < 0:
        low = max(low, c / q)
    elif c < 0 and not q > 0:
        low = _INF
    high = _INF
    if p < 0:
        high = c / p
    if q > 0:
        high = min(high, c / q)
    return low, high


@dataclass(frozen=True)
class _Piece:
    """One smooth piece of a constrained part: its grid of fractions with ψ and c = L(1 − εψ′) there."""

    part: int
    seg: Segment
    level: float
    t: float
    xs: np.ndarray
    psi: np.ndarray
    c: np.ndarray


def _tops(values: np.ndarray, best: float) -> list[int]:
    """Grid indices of the peaks of ``values`` (interior local maxima and ends beating their neighbour) whose
    neighbourhood could hold a value above ``best``: a smooth peak exceeds its grid value by at most a third
    of its drop to the lower neighbour (a parabola through three grid points)."""
    v = values
    n = v.size
    if n < 2:
        return []
    left = np.concatenate([[-np.inf], v[:-1]])
    right = np.concatenate([v[1:], [-np.inf]])
    near = np.minimum(np.where(np.isfinite(left), left, right), np.where(np.isfinite(right), right, left))
    with np.errstate(invalid="ignore"):
        room = v + 2.0 * (v - near)
    return np.nonzero((v >= left) & (v >= right) & np.isfinite(v) & ~(room < best))[0].tolist()


class ArmTwin:
    """The twin of :func:`~geomcon.cam.base_radius.arm_best` (see the module docstring): rays from A0 with a
    free, the excess α − α_allow over the arm angle with a given."""

    def __init__(self, program: Program, h: float, L: float, *, alpha_allow: float, rotation: str = "ccw",
                 arm: str = "left", alpha_allow_return: float | None = None) -> None:
        self.h, self.L = h, L
        sigma = 1 if rotation == "ccw" else -1
        tau = -1 if arm == "left" else 1
        self.eps = sigma * tau
        allow = {"rise": alpha_allow}
        if alpha_allow_return is not None and program.ret is not None:
            allow["return"] = alpha_allow_return
        self.pieces: list[_Piece] = []
        self.allow: list[float] = []
        for k, (part, value) in enumerate(allow.items()):
            j = next(i for i, s in enumerate(program.segments) if s.kind == part)
            seg, level = program.segments[j], levels(program, h)[j]
            t = math.tan(math.radians(value))
            self.allow.append(math.radians(value))
            for x0, x1 in pieces(seg):
                xs = piece_grid(x0, x1, TWIN_GRID)
                m = segment_motion(seg, level, h, xs)
                self.pieces.append(_Piece(k, seg, level, t, xs, m.psi, L * (1.0 - self.eps * m.d1)))

    # ------------------------------------------------------------------ one position, on floats
    def _pos(self, pc: _Piece, x: float) -> tuple[float, float, float, float]:
        """(ψ, ψ′, ψ″, c) at fraction x of a piece's segment."""
        _, psi, d1, d2 = segment_motion1(pc.seg, pc.level, self.h, x)
        return psi, d1, d2, self.L * (1.0 - self.eps * d1)

    def _refine(self, fn: Callable[[float], float], xs: np.ndarray, i: int, v: float) -> tuple[float, float]:
        """(place, value) of the peak of ``fn`` at grid index i (value v), by Brent's method between the grid
        neighbours (the piece's own: its ends are one-sided)."""
        lo, hi = float(xs[max(i - 1, 0)]), float(xs[min(i + 1, xs.size - 1)])
        x = start = float(xs[i])
        fx = v
        if not lo < x < hi:                                  # an end: start inside, the end stays a candidate
            x = 0.5 * (lo + hi)
            fx = fn(x)
        place, val = brent_max1(fn, lo, x, hi, fx, PEAK_TOL)
        return (place, val) if val > v else (start, v)

    # ------------------------------------------------------------------ rays (a free)
    def ray(self, theta: float) -> tuple[float, float, tuple | None, tuple | None]:
        """(a_in, a_out, (piece index, fraction) of the positions binding a_in and a_out) on the ray at
        ψ0 = θ."""
        a_in, a_out, bind_in, bind_out = 0.0, _INF, None, None
        grids = []
        for k, pc in enumerate(self.pieces):
            low, high = bounds_of(theta + pc.psi, pc.t, pc.c)
            grids.append((low, -high))
            i, j = int(np.argmax(low)), int(np.argmax(-high))
            if low[i] > a_in:
                a_in, bind_in = float(low[i]), (k, float(pc.xs[i]))
            if high[j] < a_out:
                a_out, bind_out = float(high[j]), (k, float(pc.xs[j]))
        if a_in == _INF:
            return a_in, a_out, bind_in, bind_out
        for k, (pc, (low, neg_high)) in enumerate(zip(self.pieces, grids)):
            def lo1(x, pc=pc):
                psi, _, _, c = self._pos(pc, x)
                return bounds1(theta + psi, pc.t, c)[0]

            def hi1(x, pc=pc):
                psi, _, _, c = self._pos(pc, x)
                return -bounds1(theta + psi, pc.t, c)[1]

            for i in _tops(low, a_in):
                x, v = self._refine(lo1, pc.xs, i, float(low[i]))
                if v > a_in:
                    a_in, bind_in = v, (k, x)
            for i in _tops(neg_high, -a_out):
                x, v = self._refine(hi1, pc.xs, i, float(neg_high[i]))
                if -v < a_out:
                    a_out, bind_out = -v, (k, x)
        return a_in, a_out, bind_in, bind_out

    def _bound_slope(self, theta: float, k: int, x: float, upper: bool) -> float:
        """d/dδ of the binding bound c/p (or c/q) at fraction x of piece k: (c′p − c·p′)/p², c′ = −εLψ″,
        p′ = (−sin φ ± t cos φ)·ψ′ — the lower bound's largest, the upper's smallest of the two."""
        pc = self.pieces[k]
        psi, w, d2, c = self._pos(pc, x)
        dc, t = -self.eps * self.L * d2, pc.t
        phi = theta + psi
        cs, sn = math.cos(phi), math.sin(phi)
        opts = []
        for p, dp, sgn in ((cs + t * sn, (-sn + t * cs) * w, 1.0), (cs - t * sn, (-sn - t * cs) * w, -1.0)):
            if (sgn * p < 0) if upper else (sgn * p > 0):
                opts.append((c / p, (dc * p - c * dp) / (p * p)))
        return (min if upper else max)(opts)[1] if opts else 0.0

    def _polish(self, theta: float, bind: tuple | None, upper: bool) -> tuple | None:
        """The binding position located to :data:`ROOT_TOL` by regula falsi on the bound's exact slope
        (values alone leave a flat peak's place uncertain by about √ε, and ∂a/∂θ with it)."""
        if bind is None:
            return None
        k, x = bind
        sign = -1.0 if upper else 1.0
        f = lambda z: sign * self._bound_slope(theta, k, z, upper)
        w = 2.0 / TWIN_GRID
        pc = self.pieces[k]
        lo, hi = max(x - w, float(pc.xs[0])), min(x + w, float(pc.xs[-1]))
        flo, fhi = f(lo), f(hi)
        if not (flo > 0 > fhi):
            return bind
        return k, _falsi(f, lo, hi, flo, fhi, ROOT_TOL)

    def _d_bound(self, theta: float, bind: tuple, upper: bool) -> float:
        """∂a/∂θ of the bound a = c/p or c/q binding at ``bind`` (the position held): −c·p′/p²."""
        pc = self.pieces[bind[0]]
        psi, _, _, c = self._pos(pc, bind[1])
        phi, t = theta + psi, pc.t
        cs, sn = math.cos(phi), math.sin(phi)
        p, dp, q, dq = cs + t * sn, -sn + t * cs, cs - t * sn, -sn - t * cs
        opts = []
        if (p < 0) if upper else (p > 0):
            opts.append((c / p, -c * dp / (p * p)))
        if (q > 0) if upper else (q < 0):
            opts.append((c / q, -c * dq / (q * q)))
        return (min if upper else max)(opts)[1] if opts else 0.0

    def _seed(self, top: float) -> float:
        """An arm angle whose ray meets the admissible region: the widest of a scan of :data:`TWIN_SCAN` rays
        on the grid of positions (all rays and positions in one array each), checked by :meth:`ray`."""
        thetas = np.linspace(0.0, top, TWIN_SCAN + 2)[1:-1]
        a_in, a_out = np.zeros(thetas.size), np.full(thetas.size, np.inf)
        for pc in self.pieces:
            low, high = bounds_of(thetas[:, None] + pc.psi[None, :], pc.t, pc.c[None, :])
            a_in, a_out = np.maximum(a_in, np.max(low, axis=1)), np.minimum(a_out, np.min(high, axis=1))
        with np.errstate(divide="ignore", invalid="ignore"):
            score = np.where(a_in == np.inf, -np.inf, np.where(a_out == np.inf, np.inf,
                                                               (a_out - a_in) / np.maximum(a_in, 1e-300)))
        for k in np.argsort(-score, kind="stable")[:8]:
            a_in1, a_out1, _, _ = self.ray(float(thetas[k]))
            if a_in1 <= a_out1:
                return float(thetas[k])
        raise NotAMechanism("no cam centre keeps the pressure angle within the limit (no ray from the arm's "
                            "pivot meets every position's admissible region)")

    def _best_free(self) -> tuple[float, float]:
        top = math.pi - math.radians(self.h)
        seed = self._seed(top)
        L = self.L

        def sign(th: float) -> float:
            if th <= 0.0:
                return -1.0
            if th >= top:
                return 1.0
            a_in, a_out, b_in, b_out = self.ray(th)
            if a_in > a_out:
                return -1.0 if th < seed else 1.0
            a = min(max(L * math.cos(th), a_in), a_out)
            if a == a_in and b_in is not None:
                slope = self._d_bound(th, self._polish(th, b_in, False), upper=False)
            elif a == a_out and b_out is not None:
                slope = self._d_bound(th, self._polish(th, b_out, True), upper=True)
            else:
                slope = 0.0                                     # the foot of B0 on the ray: r0 = L sin ψ0
            return (a - L * math.cos(th)) * slope + a * L * math.sin(th)

        lo, hi = 0.0, top
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if not lo < mid < hi:
                break
            if sign(mid) > 0:
                hi = mid
            else:
                lo = mid
        best = None                                     # the end of the last bracket whose ray meets the region
        for th in (lo, hi):
            a_in, a_out, _, _ = self.ray(th)
            if 0.0 < th < top and a_in <= a_out * (1.0 + 1e-13):
                a = min(max(L * math.cos(th), a_in), a_out)
                r2 = (a - L) ** 2 + 4.0 * a * L * math.sin(th / 2) ** 2
                if best is None or r2 < best[0]:
                    best = (r2, a, th)
        if best is None:
            raise NotAMechanism(f"no ray from the arm's pivot near ψ0 = {math.degrees(hi):.6g}° meets the admissible "
                                "region")
        return best[1], best[2]

    # ------------------------------------------------------------------ a given
    def excess(self, a: float, theta: float) -> float:
        """The largest α − α_allow (rad) over the constrained positions for the centre (a, ψ0 = θ)."""
        worst = -_INF
        grids = []
        for pc in self.pieces:
            phi = theta + pc.psi
            v = np.arctan2(np.abs(pc.c - a * np.cos(phi)), a * np.sin(phi)) - self.allow[pc.part]
            grids.append(v)
            worst = max(worst, float(np.max(v)))
        for pc, v in zip(self.pieces, grids):
            allow = self.allow[pc.part]

            def alpha1(x, pc=pc, allow=allow):
                psi, _, _, c = self._pos(pc, x)
                phi = theta + psi
                return math.atan2(abs(c - a * math.cos(phi)), a * math.sin(phi)) - allow

            for i in _tops(v, worst):
                worst = max(worst, self._refine(alpha1, pc.xs, i, float(v[i]))[1])
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
        lo, hi = 0.0, c if fc <= 0 else d                   # excess > 0 at lo (θ ≤ 0 never passes), ≤ 0 at hi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if not lo < mid < hi:
                break
            if f(mid) <= 0:
                hi = mid
            else:
                lo = mid
        return 0.5 * (lo + hi)

    def best(self, a: float | None = None) -> dict[str, float]:
        """``r0``, ``a``, ``psi0`` (deg) of the smallest base circle (at the given a, or the best a)."""
        if a is None:
            a, psi0 = self._best_free()
        else:
            psi0 = self._psi0_at(a)
        r0 = math.sqrt((a - self.L) ** 2 + 4.0 * a * self.L * math.sin(psi0 / 2) ** 2)
        return {"r0": r0, "a": a, "psi0": math.degrees(psi0)}


def arm_rho_min(cam) -> float:
    """ρmin of an oscillating cam's pitch curve over its convex parts by the twin's route: the complex-form
    curvature (:meth:`~geomcon.cam.oscillating.OscillatingCam.convex_curvature_complex`, and its form on one
    motion for Brent's refinement of the grid peaks); ``inf`` when nowhere convex."""
    return cam.rho_min(cam.convex_curvature_complex, cam.convex_curvature_complex1())[0]
