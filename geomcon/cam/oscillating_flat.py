"""Closed forms of the disc cam with a flat-faced oscillating follower (平底摆动从动件): the analytic twin of
``cam.oscillating`` with ``follower = "flat"``.

Conventions are those of :mod:`geomcon.cam.oscillating` (O at the origin, the arm's pivot A0 on +y at OA0 = a,
σ the cam's sense, τ the arm's rise sense, ε = στ, φ = ψ0 + ψ(δ) the arm's angle from the line A0′O). The face
is a straight line parallel to the arm's direction u (u makes the angle φ with A0′→O, on the ``arm`` side)
at the distance ``f = face_offset`` from the pivot, on the cam's side (f = 0: the face passes through A0).

- Distance of the face from O: p = a·sin φ − f. The lowest position touches the base circle r0 of the
  profile, so **sin ψ0 = (r0 + f)/a** (the acute root: the face's foot lies on the arm's side of A0).
- Contact point K: the common normal at K is perpendicular to the face and passes through the relative instant
  centre P of cam and arm, on the line A0′O at A0′P = a/(1 − εψ′). K is the foot of P on the face, so its
  distance along the face from F (the foot of A0′ on the face, F = A0′ when f = 0), positive towards u, is

      l = a·cos φ / (1 − εψ′).

- Pressure angle: the normal at K (⊥ face) against the velocity of K as a point of the arm (⊥ A0′K). With
  K − A0′ = l·u − f·n, **tan α = |f| / |l|**: α ≡ 0 for a face through the pivot (f = 0), otherwise largest
  where the contact comes nearest to F.
- Radius of curvature of the profile at K (the contact slides along the face at dl/dδ while the face turns at
  −σ(1 − εψ′)): **ρ = (a·sin φ + ε·l′)/(1 − εψ′) − f**, > 0 where convex. At a break where ψ′ jumps, l jumps;
  a jump with ε·Δl < 0 sends the contact backwards (a loop of the envelope): the face cannot follow.

The module imports nothing from the geometry, the scene or the profile machinery (it is the twin of the
envelope computed by :func:`geomcon.cam.profile.envelope`).

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
...                       {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}])
>>> cam = FlatArmCam(a=120.0, r0=40.0, h=15.0, program=prog)
>>> round(math.degrees(cam.psi0), 9)                   # asin(40/120)
19.471220634
>>> round(float(cam.contact(0.0)), 9)                  # a·cos ψ0 on the base circle
113.13708499
>>> cam.convex(), round(cam.rho_min()[0], 6)              # ρ < 0 somewhere: not convex
(False, -2.524869)
>>> cam = FlatArmCam(a=120.0, r0=50.0, h=15.0, program=prog)
>>> cam.convex(), [round(v, 6) for v in cam.rho_min()]
(True, [9.54893, 220.801301])
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from .oscillating import ArmMotion, Motion, levels, pieces, segment_motion
from .program import Program

DROP_REL = 1e-9
"""A drop of ψ′ at a break counts when larger than this fraction of the largest |ψ′| of the turn."""
END_TIE = 1e-12
"""A segment's nearest contact within this many a of a segment end is placed at that end (a law ending with
ψ′ = ψ″ = 0 leaves l flat to roundoff over ~1e-5°, where the place is otherwise arbitrary)."""


def flat_psi0_rad(a: float, r0: float, offset: float = 0.0) -> float:
    """ψ0 (rad) of a flat-faced arm: sin ψ0 = (r0 + f)/a, the acute root, as atan2 (accurate near 90°);
    ``nan`` when 0 < r0 + f < a fails.

    Examples
    --------
    >>> round(math.degrees(flat_psi0_rad(100.0, 50.0)), 12), round(math.degrees(flat_psi0_rad(100.0, 40.0, 10.0)), 12)
    (30.0, 30.0)
    """
    q = r0 + offset
    if not 0.0 < q < a:
        return math.nan
    return math.atan2(q, math.sqrt((a - q) * (a + q)))


@dataclass(frozen=True)
class FlatArmCam(ArmMotion):
    """A disc cam driving a flat-faced arm (see the module docstring).

    Parameters
    ----------
    a, r0 : float
        Centre distance OA0 and base-circle radius of the profile (mm).
    h : float
        Angular stroke ψmax (deg).
    program : Program
        The motion program (a full turn).
    rotation, arm : str
        As for :class:`~geomcon.cam.oscillating.OscillatingCam`.
    offset : float
        f: the face's distance from the pivot, towards the cam (mm; 0: the face passes through A0).
    """

    a: float
    r0: float
    h: float
    program: Program
    rotation: str = "ccw"
    arm: str = "left"
    offset: float = 0.0
    results: dict = field(default_factory=dict, compare=False, repr=False)
    """The searches done so far on this cam object, each once (the checks and the warnings share them)."""

    @property
    def psi0(self) -> float:
        """Initial arm angle ψ0 (rad)."""
        return flat_psi0_rad(self.a, self.r0, self.offset)

    def _m(self, delta) -> Motion:
        return delta if isinstance(delta, Motion) else self.motion(delta)

    def speed(self, m: Motion) -> np.ndarray:
        """1 − εψ′: the face's angular velocity in the cam's frame over the cam's (> 0 for a working cam)."""
        return 1.0 - self.eps * m.d1

    def contact_of(self, m: Motion) -> np.ndarray:
        """l = a cos φ/(1 − εψ′): the contact's place along the face from F (mm)."""
        return self.a * np.cos(self.psi0 + m.psi) / self.speed(m)

    def contact_slope_of(self, m: Motion) -> np.ndarray:
        """dl/dδ (mm per rad) of :meth:`contact_of`."""
        phi, w = self.psi0 + m.psi, self.speed(m)
        return self.a * (-np.sin(phi) * m.d1 * w + self.eps * m.d2 * np.cos(phi)) / w ** 2

    def scalar_forms(self) -> tuple[Callable[[tuple], float], Callable[[tuple], float], Callable[[tuple], float]]:
        """(l, l′, ρ) of one motion (δ, ψ, ψ′, ψ″), on floats: :meth:`contact_of`, :meth:`contact_slope_of` and
        :meth:`rho_of` with the same operations in the same order (the same bits; (1 − εψ′)² as a product).

        >>> from geomcon.cam.program import parse_program
        >>> from geomcon.cam.oscillating import segment_motion, segment_motion1
        >>> prog = parse_program([{"kind": "rise", "angle": 150, "law": "cycloidal"}, {"kind": "dwell", "angle": 30},
        ...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
        >>> cam = FlatArmCam(100.0, 40.0, 15.0, prog, offset=5.0)
        >>> seg = prog.segments[0]
        >>> m = segment_motion(seg, 0.0, 15.0, [0.3])
        >>> m1 = segment_motion1(seg, 0.0, 15.0, 0.3)
        >>> [f(m1) for f in cam.scalar_forms()] == [float(cam.contact_of(m)[0]), float(cam.contact_slope_of(m)[0]), float(cam.rho_of(m)[0])]
        True
        """
        a, eps, psi0, f = self.a, self.eps, self.psi0, self.offset
        cos, sin = math.cos, math.sin

        def contact1(m):
            _, psi, d1, _ = m
            return a * cos(psi0 + psi) / (1.0 - eps * d1)

        def slope1(m):
            _, psi, d1, d2 = m
            phi, w = psi0 + psi, 1.0 - eps * d1
            return a * (-sin(phi) * d1 * w + eps * d2 * cos(phi)) / (w * w)

        def rho1(m):
            phi = psi0 + m[1]
            return (a * sin(phi) + eps * slope1(m)) / (1.0 - eps * m[2]) - f

        return contact1, slope1, rho1

    def _nearest(self, kind: str) -> tuple[float, float]:
        """segment_max of −l over the ``kind`` segment (the nearest contact), once per cam object."""
        key = ("nearest", kind)
        if key not in self.results:
            contact1, slope1, _ = self.scalar_forms()
            self.results[key] = self.segment_max(kind, lambda m: -self.contact_of(m), lambda m: -self.contact_slope_of(m),
                                                 lambda m: -slope1(m))
        return self.results[key]

    def contact(self, delta) -> np.ndarray:
        """l at cam angles ``delta`` (deg)."""
        return self.contact_of(self._m(delta))

    def rho_of(self, m: Motion) -> np.ndarray:
        """Radius of curvature of the profile at the contact: (a sin φ + ε l′)/(1 − εψ′) − f."""
        phi = self.psi0 + m.psi
        return (self.a * np.sin(phi) + self.eps * self.contact_slope_of(m)) / self.speed(m) - self.offset

    def rho(self, delta) -> np.ndarray:
        """ρ at cam angles ``delta`` (deg)."""
        return self.rho_of(self._m(delta))

    def pressure_of(self, m: Motion) -> np.ndarray:
        """α (deg) = atan(|f|/|l|)."""
        return np.degrees(np.arctan2(abs(self.offset) + 0.0 * m.psi, np.abs(self.contact_of(m))))

    def contact_point(self, delta) -> tuple[np.ndarray, np.ndarray]:
        """The contact K in the cam's frame: A0′ + l·u − f·n (n the face normal away from O)."""
        m = self._m(delta)
        ta = math.pi / 2 - self.sigma * m.delta
        tu = ta + self.tau * (self.psi0 + m.psi)
        ux, uy = -np.cos(tu), -np.sin(tu)                        # u = −e(θA + τφ)
        nx, ny = np.cos(tu - self.tau * math.pi / 2), np.sin(tu - self.tau * math.pi / 2)   # n, away from O
        lv = self.contact_of(m)
        return (self.a * np.cos(ta) + lv * ux - self.offset * nx, self.a * np.sin(ta) + lv * uy - self.offset * ny)

    # ------------------------------------------------------------------ extremes
    def contact_extremes(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """((l_min, δ), (l_max, δ)) over the turn (mm, deg): ends of the smooth pieces and the roots of l′."""
        lo, hi = (math.inf, 0.0), (-math.inf, 0.0)
        for seg in self.program.segments:
            if seg.kind == "dwell":
                m = self.motion([seg.start])
                v = float(self.contact_of(m)[0])
                lo, hi = min(lo, (v, seg.start)), max(hi, (v, seg.start), key=lambda t: (t[0], -t[1]))
                continue
            a = self._nearest(seg.kind)
            b = self.segment_max(seg.kind, self.contact_of, self.contact_slope_of, self.scalar_forms()[1])
            lo = min(lo, (-a[0], a[1]))
            hi = max(hi, b, key=lambda t: (t[0], -t[1]))
        return lo, hi

    def worst_pressure(self, kind: str) -> tuple[float, float]:
        """(α_max, δ) in degrees over the rise or return: where |l| is smallest (l > 0 on a working cam)."""
        v, at = self._nearest(kind)
        k = next(i for i, s in enumerate(self.program.segments) if s.kind == kind)
        seg = self.program.segments[k]
        ends = self.contact_of(segment_motion(seg, levels(self.program, self.h)[k], self.h, [0.0, 1.0]))
        for lv, d in zip(ends, (seg.start, seg.end)):     # a minimum as flat as roundoff at an end: the end
            if lv <= -v + END_TIE * self.a:
                at = d
                break
        return math.degrees(math.atan2(abs(self.offset), -v)), at

    def rho_min(self) -> tuple[float, float]:
        """(ρmin, δ in degrees) of the profile over the turn (once per cam object)."""
        if "rho_min" not in self.results:
            rho1 = self.scalar_forms()[2]
            v, at = self.turn_max(lambda m: -self.rho_of(m), lambda m: -rho1(m))
            self.results["rho_min"] = (-v, at)
        return self.results["rho_min"]

    def backward_jumps(self) -> tuple[tuple[float, float], ...]:
        """(ε·Δl, δ in degrees) at every break where the contact jumps backwards along the face.

        With 1 − εψ′ > 0 on both sides and cos φ > 0, ε·Δl = ε·a cos φ·(1/(1 − εψ′₊) − 1/(1 − εψ′₋)) has the
        sign of ψ′₊ − ψ′₋: the contact jumps back exactly where ψ′ drops. A drop counts when it exceeds
        :data:`DROP_REL` of the largest |ψ′| of the turn (a law's end value f′(1) ≈ 2e-16 is roundoff).
        """
        segs, lev = self.program.segments, levels(self.program, self.h)
        ends = []                                                  # (δ, m just before, m just after)
        for k, seg in enumerate(segs):
            for x0, x1 in pieces(seg):
                m = segment_motion(seg, lev[k], self.h, [x0, x1])
                ends.append((seg.start + seg.angle * x0, m))
        peak = max(float(np.max(np.abs(segment_motion(seg, lev[k], self.h, np.linspace(0.0, 1.0, 65)).d1)))
                   for k, seg in enumerate(segs))
        out = []
        for (_, prev), (d1, nxt) in zip(ends[-1:] + ends[:-1], ends):
            w0, w1 = float(prev.d1[1]), float(nxt.d1[0])
            if w1 - w0 < -DROP_REL * peak:
                phi = self.psi0 + float(nxt.psi[0])
                jump = self.eps * self.a * math.cos(phi) * (1.0 / (1.0 - self.eps * w1) - 1.0 / (1.0 - self.eps * w0))
                out.append((jump, d1))
        return tuple(out)

    def convex(self) -> bool:
        """ρ > 0 everywhere and no backward jump of the contact."""
        return self.rho_min()[0] > 0.0 and not self.backward_jumps()

    def speed_floor(self) -> float:
        """A lower bound of 1 − εψ′ over the turn from the laws' largest |f′| (|ψ′| ≤ h·max|f′|/Φ on a segment of
        Φ degrees), a little lower than the bound for roundoff: above the refusal's threshold, the search of
        :meth:`speed_min` cannot find the speed below it (it only evaluates 1 − εψ′ at some angles).

        >>> from geomcon.cam.program import parse_program
        >>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
        ...                       {"kind": "return", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60}])
        >>> cam = FlatArmCam(a=120.0, r0=40.0, h=15.0, program=prog)
        >>> round(cam.speed_floor(), 9), cam.speed_floor() <= cam.speed_min()[0]
        (0.75, True)
        """
        peak = max((abs(self.h) / seg.angle * seg.law.peak1 for seg in self.program.segments if seg.kind != "dwell"),
                   default=0.0)
        return 1.0 - peak * (1.0 + 1e-9) - 1e-12

    def speed_min(self) -> tuple[float, float]:
        """(min of 1 − εψ′, δ in degrees) over the turn: ≤ 0 means the face stops turning relative to the
        cam and the contact runs off to infinity."""
        eps = self.eps
        v, at = self.turn_max(lambda m: -self.speed(m), lambda m: -(1.0 - eps * m[2]))
        return -v, at
