"""Closed forms of an oscillating-follower disc cam (摆动从动件盘形凸轮) by the inversion method (反转法).

Conventions (the textbook's analytic frame)
-------------------------------------------
The cam centre O is the origin; the arm's fixed pivot A0 lies on +y at distance ``a`` (centre distance); the
arm A0B has length ``L``; B is the roller centre (the knife tip). Coordinates are those of the cam at δ = 0
(the cam frame), the frame in which the profile is cut.

- ``rotation``: the cam's sense, ``"ccw"`` (σ = +1) or ``"cw"`` (σ = −1). The inversion holds the cam still
  and turns the frame by −σδ about O, so the pivot's inverted position is A0′(δ) = R(−σδ)·A0.
- ``arm``: the side of the line A0→O on which the roller lies, as drawn with A0 above O: ``"left"`` or
  ``"right"``. The arm makes the angle φ = ψ0 + ψ(δ) with the line A0′O and swings away from O during the
  rise: clockwise (τ = −1) for a left arm, counter-clockwise (τ = +1) for a right arm.
- ε = σ·τ = +1 when the arm swings, during the rise, in the same sense as the cam turns ("same"), −1 when
  opposite. A ccw cam with a left arm (ε = −1) is the textbook's formula
  x = a sin δ − L sin(δ + ψ0 + ψ), y = a cos δ − L cos(δ + ψ0 + ψ).

With θA = 90° − σδ (polar angle of A0′) and e(θ) = (cos θ, sin θ), the pitch curve is

    B(δ) = a·e(θA) − L·e(θA + τφ),     cos ψ0 = (a² + L² − r0²)/(2aL).

Pressure angle: the roller's velocity is perpendicular to the arm; the contact normal is perpendicular to
the pitch curve's tangent, so α is the acute angle between B′(δ) and the arm. Resolving B′ along and across
the arm,

    tan α = |L(1 − εψ′) − a cos φ| / (a sin φ),        ψ′ = dψ/dδ (rad/rad),

the same as the relative instant centre P of cam and arm on the line OA0′ at A0′P = a/(1 − εψ′) gives.
Since L − a cos φ = r·cos β (r = OB, β = ∠OBA0′), the textbook's rule follows: when ∠OBA0′ is acute, a rise
that swings the arm in the same sense as the cam turns (ε = +1) lowers the rise pressure angle, and the
opposite sense raises it; when ∠OBA0′ is obtuse it is the other way round. So the sense matters.

Radius of curvature ρ of the pitch curve: positive where the curve is convex (outward), negative on concave
parts; the roller undercuts where 0 < ρ ≤ rr.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
...                       {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
>>> cam = OscillatingCam(a=150.0, L=132.0, r0=50.0, h=20.0, program=prog)
>>> round(math.degrees(cam.psi0), 4), cam.eps
(19.0822, -1)
>>> x, y = cam.pitch(0.0)
>>> round(float(math.hypot(x, y)), 12)                # B0 lies on the base circle
50.0
>>> round(float(cam.pressure_angle(60.0)), 4)
25.942
"""
from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..numeric import brent_root
from .profile import PitchCurve, brent_max1, pow1, sign1
from .program import Program, Segment

GRID = 240
"""Grid points per smooth piece of a segment for bracketing the extrema of α and of the curvature."""
ROOT_XTOL = 1e-15
"""The scalar root search's tolerance in fractions of the segment (1e-15·Φ rad): a flat maximum's value is
then exact to ~1e-30 of its curvature, its place far beyond the printed digits."""


@dataclass(frozen=True)
class Motion:
    """ψ, ψ′, ψ″ in radians (per radian of cam angle) at the cam angles ``delta`` (radians)."""

    delta: np.ndarray
    psi: np.ndarray
    d1: np.ndarray
    d2: np.ndarray


def segment_motion(seg: Segment, level: float, h: float, x) -> Motion:
    """The motion on one segment at fractions ``x`` (0 … 1, both ends included, one-sided values there).

    ``level`` is ψ (deg) at the segment's start, ``h`` the stroke (deg).

    Examples
    --------
    >>> from geomcon.cam.program import Segment
    >>> from geomcon.cam.laws import law
    >>> m = segment_motion(Segment("rise", 0.0, 10.0, law("parabolic")), 0.0, 20.0, [0.5, 1.0])
    >>> [round(math.degrees(v), 9) for v in m.psi], round(float(m.d1[0]), 12)
    ([10.0, 20.0], 4.0)
    """
    xa = np.asarray(x, dtype=float)
    delta = math.radians(seg.start) + math.radians(seg.angle) * xa
    if seg.kind == "dwell":
        zero = np.zeros_like(xa)
        return Motion(delta, np.full_like(xa, math.radians(level)), zero, zero)
    f, f1, f2 = seg.law.derivatives(xa)
    sign = 1.0 if seg.kind == "rise" else -1.0
    span, hr = math.radians(seg.angle), math.radians(h)
    return Motion(delta, math.radians(level) + sign * hr * f, sign * hr * f1 / span, sign * hr * f2 / span ** 2)


def segment_motion1(seg: Segment, level: float, h: float, x: float) -> tuple[float, float, float, float]:
    """:func:`segment_motion` at one fraction ``x``, on floats: (δ, ψ, ψ′, ψ″), the same operations in the
    same order, so the same bits (the searches' scalar path).

    >>> from geomcon.cam.laws import law
    >>> seg = Segment("return", 30.0, 120.0, law("cosine"))
    >>> m = segment_motion(seg, 20.0, 20.0, [0.3])
    >>> segment_motion1(seg, 20.0, 20.0, 0.3) == (float(m.delta[0]), float(m.psi[0]), float(m.d1[0]), float(m.d2[0]))
    True
    """
    delta = math.radians(seg.start) + math.radians(seg.angle) * x
    if seg.kind == "dwell":
        return delta, math.radians(level), 0.0, 0.0
    f, f1, f2 = seg.law.fn1(x)
    sign = 1.0 if seg.kind == "rise" else -1.0
    span, hr = math.radians(seg.angle), math.radians(h)
    return delta, math.radians(level) + sign * hr * f, sign * hr * f1 / span, sign * hr * f2 / span ** 2


def levels(program: Program, h: float) -> list[float]:
    """ψ (deg) at the start of each segment of ``program``."""
    out, level = [], 0.0
    for seg in program.segments:
        out.append(level)
        level += {"rise": h, "return": -h}.get(seg.kind, 0.0)
    return out


def pieces(seg: Segment) -> tuple[tuple[float, float], ...]:
    """The smooth pieces (fractions) of a segment: the parabolic law's acceleration jumps at ½."""
    if seg.law is not None and seg.law.name == "parabolic":
        return ((0.0, 0.5), (0.5, 1.0))
    return ((0.0, 1.0),)


def piece_grid(x0: float, x1: float, n: int = GRID) -> np.ndarray:
    """``n`` fractions from x0 to just below x1 (so the law's left piece owns the right end)."""
    x = np.linspace(x0, x1, n)
    x[-1] = np.nextafter(x1, x0)
    return x


def psi0_rad(a: float, L: float, r0: float) -> float:
    """The arm's initial angle ψ0 (rad) with the line A0O, from cos ψ0 = (a² + L² − r0²)/(2aL), in the
    half-angle form (accurate for slim triangles); ``nan`` when the triangle a, L, r0 does not close.

    Examples
    --------
    >>> round(math.degrees(psi0_rad(150.0, 132.0, 50.0)), 4), round(math.degrees(psi0_rad(150.0, 123.0, 50.0)), 4)
    (19.0822, 17.8232)
    """
    p, q = (r0 - a + L) * (r0 + a - L), (a + L + r0) * (a + L - r0)
    if p < 0 or q <= 0:
        return math.nan
    return 2.0 * math.atan2(math.sqrt(p), math.sqrt(q))


class ArmMotion:
    """The motion and the senses of an arm follower, shared by the roller/knife arm (:class:`OscillatingCam`)
    and the flat-faced arm (:class:`geomcon.cam.oscillating_flat.FlatArmCam`): a subclass has the fields
    ``h`` (deg), ``program``, ``rotation`` and ``arm``."""

    h: float
    program: Program
    rotation: str
    arm: str

    @property
    def sigma(self) -> int:
        """+1 for a ccw cam, −1 for cw."""
        return 1 if self.rotation == "ccw" else -1

    @property
    def tau(self) -> int:
        """The arm's rise sense: −1 (cw) for a left arm, +1 (ccw) for a right arm."""
        return -1 if self.arm == "left" else 1

    @property
    def eps(self) -> int:
        """+1 when the arm swings in the cam's sense during the rise, −1 when opposite."""
        return self.sigma * self.tau

    def motion(self, delta) -> Motion:
        """ψ, ψ′, ψ″ (rad) at cam angles ``delta`` (deg), from the program (half-open segments)."""
        d = np.asarray(delta, dtype=float)
        s, v, acc = self.program.motion(self.h, d)
        return Motion(np.radians(d), np.radians(s), np.radians(v), np.radians(acc))

    def breaks(self) -> tuple[float, ...]:
        """Cam angles (rad) where ψ′ or ψ″ may jump: segment ends and the parabolic law's midpoints."""
        out = []
        for seg in self.program.segments:
            out += [math.radians(seg.start + seg.angle * x0) for x0, _ in pieces(seg)]
        return tuple(sorted(set(out) - {0.0}))

    def rests(self) -> tuple[tuple[float, float], ...]:
        """The dwells' cam angles [start, end] (rad): the arm at rest, the pitch curve an arc about O."""
        return tuple((math.radians(seg.start), math.radians(seg.end)) for seg in self.program.segments
                     if seg.kind == "dwell")

    def motion_rad(self, delta) -> Motion:
        """The motion at cam angles ``delta`` in radians, segment ends compared in radians (so that
        ``nextafter`` of a break, :meth:`breaks`, falls in the piece before it)."""
        d = np.asarray(delta, dtype=float)
        s, v, acc = self.program.motion(self.h, d, radians=True)
        return Motion(d, np.radians(s), np.radians(v), np.radians(acc))

    def segment_max(self, kind: str, g: Callable[[Motion], np.ndarray],
                    slope: Callable[[Motion], np.ndarray],
                    slope1: Callable[[tuple[float, float, float, float]], float] | None = None) -> tuple[float, float]:
        """(max of ``g``, δ in degrees where it is reached) over the ``kind`` ("rise" or "return") segment.

        Candidates are the ends of each smooth piece (one-sided values) and the interior roots of ``slope``
        (a function with the sign of dg/dδ), located by bisection on its sign. Ties go to the smaller cam
        angle. ``slope1``, the slope of one motion (δ, ψ, ψ′, ψ″) of :func:`segment_motion1`, refines each
        bracket on floats by Brent's method instead (:func:`_roots`). (The construction's pressure angle has
        its own search, :func:`geomcon.cam.arm_alpha.segment_max_one_pass`; this one is the twin's.)
        """
        k = next(i for i, s in enumerate(self.program.segments) if s.kind == kind)
        seg, level = self.program.segments[k], levels(self.program, self.h)[k]
        best = (-math.inf, 0.0)
        h = self.h
        fn1 = None if slope1 is None else lambda x: slope1(segment_motion1(seg, level, h, x))
        for x0, x1 in pieces(seg):
            roots = _roots(lambda x: slope(segment_motion(seg, level, self.h, x)), x0, x1, fn1=fn1)
            m = segment_motion(seg, level, self.h, roots + [x0, x1])
            for a, delta in zip(g(m), np.degrees(m.delta)):
                if a > best[0] + 1e-13 or (abs(a - best[0]) <= 1e-13 and delta < best[1]):
                    best = (float(a), float(delta))
        return best

    def turn_max(self, f: Callable[[Motion], np.ndarray],
                 f1: Callable[[tuple[float, float, float, float]], float] | None = None) -> tuple[float, float]:
        """(max of ``f``, δ in degrees) over the turn: the ends of every smooth piece and every grid maximum
        inside refined by golden-section search (dwells: their ends). With ``f1`` (``f`` of one motion (δ, ψ,
        ψ′, ψ″) of :func:`segment_motion1`, on floats) the grid maxima are refined by Brent's method on
        floats (:func:`~geomcon.cam.profile.brent_max1`, to the same tolerance) and every candidate is valued
        by ``f1``: no array call but one grid per piece."""
        best = (-math.inf, 0.0)
        h = self.h
        for seg, level in zip(self.program.segments, levels(self.program, h)):
            for x0, x1 in pieces(seg):
                def fx(x, seg=seg, level=level):
                    return f(segment_motion(seg, level, h, x))
                if f1 is not None:
                    def fx1(x, seg=seg, level=level):
                        return f1(segment_motion1(seg, level, h, x))
                    found = [(x0, fx1(x0)), (x1, fx1(x1))]
                    if seg.kind != "dwell":
                        found += _brent_maxima(fx, fx1, x0, x1)
                    for x, val in found:
                        if val > best[0]:
                            best = (val, seg.start + seg.angle * float(x))
                    continue
                xs = (x0, x1) if seg.kind == "dwell" else _golden_maxima(fx, x0, x1)
                for x in xs:
                    val = float(fx(np.asarray([x]))[0])
                    if val > best[0]:
                        best = (val, seg.start + seg.angle * float(x))
        return best


@dataclass(frozen=True)
class OscillatingCam(ArmMotion):
    """An oscillating-follower disc cam: geometry plus motion program (see the module docstring).

    Parameters
    ----------
    a, L, r0 : float
        Centre distance OA0, arm length A0B and base-circle radius of the pitch curve (mm).
    h : float
        Angular stroke ψmax (deg).
    program : Program
        The motion program (a full turn).
    rotation : str
        ``"ccw"`` or ``"cw"``.
    arm : str
        ``"left"`` or ``"right"`` of the line A0→O.
    """

    a: float
    L: float
    r0: float
    h: float
    program: Program
    rotation: str = "ccw"
    arm: str = "left"

    @property
    def psi0(self) -> float:
        """Initial arm angle ψ0 (rad)."""
        return psi0_rad(self.a, self.L, self.r0)

    # ------------------------------------------------------------------ pitch curve
    def pitch_of(self, m: Motion) -> tuple[np.ndarray, ...]:
        """(x, y, x′, y′, x″, y″) of the pitch curve for a motion ``m`` (derivatives per radian of δ)."""
        sg, tu = self.sigma, self.tau
        ta = math.pi / 2 - sg * m.delta
        t2 = ta + tu * (self.psi0 + m.psi)
        w2 = -sg + tu * m.d1                                  # dθ2/dδ
        ca, sa, c2, s2 = np.cos(ta), np.sin(ta), np.cos(t2), np.sin(t2)
        x, y = self.a * ca - self.L * c2, self.a * sa - self.L * s2
        dx = -sg * self.a * -sa - self.L * w2 * -s2
        dy = -sg * self.a * ca - self.L * w2 * c2
        ddx = -self.a * ca - self.L * tu * m.d2 * -s2 + self.L * w2 ** 2 * c2
        ddy = -self.a * sa - self.L * tu * m.d2 * c2 + self.L * w2 ** 2 * s2
        return x, y, dx, dy, ddx, ddy

    def pitch(self, delta) -> tuple[np.ndarray, np.ndarray]:
        """The pitch point B(δ) (cam frame) at cam angles ``delta`` (deg)."""
        return self.pitch_of(self.motion(delta))[:2]

    def pivot(self, delta) -> tuple[np.ndarray, np.ndarray]:
        """The pivot's inverted position A0′(δ) = R(−σδ)·A0."""
        ta = math.pi / 2 - self.sigma * np.radians(np.asarray(delta, dtype=float))
        return self.a * np.cos(ta), self.a * np.sin(ta)

    # ------------------------------------------------------------------ pressure angle
    def tan_pressure_parts(self, m: Motion) -> tuple[np.ndarray, ...]:
        """(N, D, N′, D′) with tan α = |N|/D: N = L(1 − εψ′) − a cos φ, D = a sin φ (derivatives per rad)."""
        phi = self.psi0 + m.psi
        c, s = np.cos(phi), np.sin(phi)
        n = self.L * (1.0 - self.eps * m.d1) - self.a * c
        return n, self.a * s, -self.eps * self.L * m.d2 + self.a * s * m.d1, self.a * c * m.d1

    def pressure_of(self, m: Motion) -> np.ndarray:
        """Pressure angle α (deg, 0 … 90) for a motion ``m``."""
        n, d, _, _ = self.tan_pressure_parts(m)
        return np.degrees(np.arctan2(np.abs(n), d))

    def pressure_angle(self, delta) -> np.ndarray:
        """Pressure angle α (deg) at cam angles ``delta`` (deg)."""
        return self.pressure_of(self.motion(delta))

    def pressure_arg(self, m: Motion) -> np.ndarray:
        """α (deg) by a separate route (the twin's): the acute angle between the pitch curve's tangent
        B′ = w·u (u = c′ − iσc, see :meth:`convex_curvature_complex`) and the arm B − A0′ = −L·w·e^(iτφ)."""
        e = np.exp(1j * self.tau * (self.psi0 + m.psi))
        u = -1j * self.tau * self.L * m.d1 * e - 1j * self.sigma * (self.a - self.L * e)
        t = np.abs(np.angle(-u / e))                        # angle between tangent and arm, 0 … π
        return np.degrees(np.minimum(t, np.pi - t))

    def pressure_arg_slope(self, m: Motion) -> np.ndarray:
        """d/dδ of the angle between tangent and arm by the same route: Im(B″/B′) − Im(q′/q), q the arm
        vector (q′/q = i(τψ′ − σ)); α is stationary where it vanishes."""
        e = np.exp(1j * self.tau * (self.psi0 + m.psi))
        c = self.a - self.L * e
        c1 = -1j * self.tau * self.L * m.d1 * e
        c2 = -1j * self.tau * self.L * m.d2 * e + self.L * m.d1 ** 2 * e
        u, v = c1 - 1j * self.sigma * c, c2 - 2j * self.sigma * c1 - c
        return np.imag(v / u) - (self.tau * m.d1 - self.sigma)

    def worst_pressure(self, kind: str, *, route: str = "tan") -> tuple[float, float]:
        """(α_max, δ where it occurs) over the ``kind`` ("rise" or "return") segment, both in degrees.

        Candidates are the ends of each smooth piece (one-sided values) and the interior stationary points,
        the roots of dα/dδ located on its exact sign: sign(N)(N′D − ND′) with tan α = |N|/D (``route = "tan"``,
        :meth:`tan_slope`; only its changes from + to −, the maxima, searched by
        :func:`~geomcon.cam.arm_alpha.segment_max_one_pass` — a − → + change is a minimum, such as the kink
        α = 0 where N changes sign), or :meth:`pressure_arg_slope` with α from :meth:`pressure_arg`
        (``route = "arg"``, the analytic twin's, by :meth:`ArmMotion.segment_max`). Ties go to the smaller
        cam angle.
        """
        k = next(i for i, s in enumerate(self.program.segments) if s.kind == kind)
        if route == "tan":
            from .arm_alpha import segment_max_one_pass
            return segment_max_one_pass(self.program.segments[k], levels(self.program, self.h)[k], self.h,
                                        self.pressure_of, self.tan_slope, self._tan_slope1())
        return self.segment_max(kind, self.pressure_arg, self.pressure_arg_slope, self.pressure_arg_slope1())

    def tan_slope(self, m: Motion) -> np.ndarray:
        """sign(N)(N′D − ND′) (:meth:`tan_pressure_parts`): the sign of dα/dδ, exactly."""
        n, d, n1, d1 = self.tan_pressure_parts(m)
        return np.sign(n) * (n1 * d - n * d1)

    def _tan_slope1(self) -> Callable[[tuple[float, float, float, float]], float]:
        """The "tan" route's slope sign(N)(N′D − ND′) of one motion (δ, ψ, ψ′, ψ″), on floats: the operations
        of :meth:`tan_pressure_parts` in their order (the same bits)."""
        psi0, eps, L, a = self.psi0, self.eps, self.L, self.a

        def slope1(m):
            _, psi, d1, d2 = m
            phi = psi0 + psi
            c, s = math.cos(phi), math.sin(phi)
            n = L * (1.0 - eps * d1) - a * c
            d = a * s
            return sign1(n) * ((-eps * L * d2 + a * s * d1) * d - n * (a * c * d1))

        return slope1

    # ------------------------------------------------------------------ curvature
    def convex_curvature_of(self, m: Motion) -> np.ndarray:
        """1/ρ of the pitch curve (1/mm): positive where it is convex outward."""
        _, _, dx, dy, ddx, ddy = self.pitch_of(m)
        return -self.sigma * (dx * ddy - dy * ddx) / np.hypot(dx, dy) ** 3

    def convex_curvature_complex(self, m: Motion) -> np.ndarray:
        """The same 1/ρ by a separate route (the analytic twin's): B = w·c with w = e^(iθA) and
        c = a − L·e^(iτφ) in the frame that turns with A0′, so B′ = w(c′ − iσc), B″ = w(c″ − 2iσc′ − c) and
        κ = Im(conj(B′)·B″)/|B′|³ (the rotation w drops out)."""
        e = np.exp(1j * self.tau * (self.psi0 + m.psi))
        c = self.a - self.L * e
        c1 = -1j * self.tau * self.L * m.d1 * e
        c2 = -1j * self.tau * self.L * m.d2 * e + self.L * m.d1 ** 2 * e
        u, v = c1 - 1j * self.sigma * c, c2 - 2j * self.sigma * c1 - c
        return -self.sigma * np.imag(np.conj(u) * v) / np.abs(u) ** 3

    def pitch_curve(self, *, scalar: bool = False) -> PitchCurve:
        """The pitch curve as a :class:`~geomcon.cam.profile.PitchCurve` (parameter δ in radians); with
        ``scalar``, also on one float (:meth:`pitch1`: the searches' scalar path, the same bits)."""
        return PitchCurve(lambda d: self.pitch_of(self.motion_rad(d)), self.breaks(),
                          fn1=self.pitch1_fn() if scalar else None, still=self.rests())

    def pitch1_fn(self) -> Callable[[float], tuple[float, float, float, float, float, float]]:
        """:meth:`pitch_of` ∘ :meth:`motion_rad` at one cam angle (radians), on floats: the same operations
        in the same order (squares as products, as numpy's), so the same bits.

        >>> from geomcon.cam.program import parse_program
        >>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
        ...                       {"kind": "return", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60}])
        >>> cam = OscillatingCam(a=150.0, L=132.0, r0=50.0, h=20.0, program=prog)
        >>> d = np.array([0.3, 2.5, 4.0])
        >>> vec = cam.pitch_of(cam.motion_rad(d))
        >>> all(cam.pitch1_fn()(x) == tuple(float(v[i]) for v in vec) for i, x in enumerate(d.tolist()))
        True
        """
        motion1, h, rad, of = self.program.motion1, self.h, math.radians, self.pitch_of1()

        def fn1(delta):
            s, v, acc = motion1(h, delta, True)
            return of((delta, rad(s), rad(v), rad(acc)))

        return fn1

    def pitch_of1(self) -> Callable[[tuple[float, float, float, float]], tuple[float, ...]]:
        """:meth:`pitch_of` of one motion (δ, ψ, ψ′, ψ″), on floats (the same bits)."""
        sg, tu, a, L, psi0 = self.sigma, self.tau, self.a, self.L, self.psi0
        cos, sin = math.cos, math.sin
        half_pi = math.pi / 2

        def fn1(m):
            delta, psi, d1, d2 = m
            ta = half_pi - sg * delta
            t2 = ta + tu * (psi0 + psi)
            w2 = -sg + tu * d1
            ca, sa, c2, s2 = cos(ta), sin(ta), cos(t2), sin(t2)
            ww = w2 * w2
            return (a * ca - L * c2, a * sa - L * s2,
                    -sg * a * -sa - L * w2 * -s2, -sg * a * ca - L * w2 * c2,
                    -a * ca - L * tu * d2 * -s2 + L * ww * c2, -a * sa - L * tu * d2 * c2 + L * ww * s2)

        return fn1

    def rho(self, delta) -> np.ndarray:
        """Signed radius of curvature ρ of the pitch curve (mm) at ``delta`` (deg); ±inf where straight."""
        with np.errstate(divide="ignore"):
            return 1.0 / self.convex_curvature_of(self.motion(delta))

    def rho_min(self, curvature: Callable[[Motion], np.ndarray] | None = None,
                curvature1: Callable[[tuple[float, float, float, float]], float] | None = None) -> tuple[float, float]:
        """(ρmin, δ) of the pitch curve over its convex parts: the largest positive curvature, found on a grid
        of each smooth piece and refined (:meth:`ArmMotion.turn_max`); ``inf`` when nowhere convex.

        ``curvature`` (default :meth:`convex_curvature_of`) lets an independent formula use the same search;
        ``curvature1``, the same formula on one motion (floats), refines on the scalar path (the default's
        is :meth:`convex_curvature1`).
        """
        if curvature is None:
            curvature, curvature1 = self.convex_curvature_of, self.convex_curvature1()
        best = self.turn_max(curvature, curvature1)
        return (1.0 / best[0], best[1]) if best[0] > 0 else (math.inf, best[1])

    def convex_curvature1(self) -> Callable[[tuple[float, float, float, float]], float]:
        """:meth:`convex_curvature_of` of one motion (δ, ψ, ψ′, ψ″), on floats."""
        of, sg = self.pitch_of1(), self.sigma

        def k1(m):
            _, _, dx, dy, ddx, ddy = of(m)
            return -sg * (dx * ddy - dy * ddx) / pow1(math.hypot(dx, dy), 3.0)

        return k1

    def _uv1(self) -> Callable[[tuple[float, float, float, float]], tuple[complex, complex, float]]:
        """u = c′ − iσc and v = c″ − 2iσc′ − c of one motion (the complex form's relative velocity and
        acceleration), with ψ′, shared by the scalar curvature and pressure-angle slope."""
        tau, sg, L, a, psi0 = self.tau, self.sigma, self.L, self.a, self.psi0
        exp = cmath.exp

        def uv1(m):
            _, psi, d1, d2 = m
            e = exp(1j * tau * (psi0 + psi))
            c = a - L * e
            c1 = -1j * tau * L * d1 * e
            c2 = -1j * tau * L * d2 * e + L * (d1 * d1) * e
            return c1 - 1j * sg * c, c2 - 2j * sg * c1 - c, d1

        return uv1

    def convex_curvature_complex1(self) -> Callable[[tuple[float, float, float, float]], float]:
        """:meth:`convex_curvature_complex` of one motion (δ, ψ, ψ′, ψ″), with Python's complex numbers (the
        twin's route on the scalar path)."""
        sg, uv1 = self.sigma, self._uv1()

        def k1(m):
            u, v, _ = uv1(m)
            return -sg * (u.conjugate() * v).imag / pow1(abs(u), 3.0)

        return k1

    def pressure_arg_slope1(self) -> Callable[[tuple[float, float, float, float]], float]:
        """:meth:`pressure_arg_slope` of one motion (δ, ψ, ψ′, ψ″), with Python's complex numbers."""
        tau, sg, uv1 = self.tau, self.sigma, self._uv1()

        def slope1(m):
            u, v, d1 = uv1(m)
            return (v / u).imag - (tau * d1 - sg) if u != 0 else math.nan

        return slope1

    # ------------------------------------------------------------------ roller
    def roller_contact(self, delta, rr: float) -> tuple[np.ndarray, np.ndarray]:
        """The actual (working) profile point of a roller of radius ``rr`` at ``delta`` (deg): the pitch point
        moved by rr along the inward normal (the inner envelope of the roller circles)."""
        x, y, dx, dy, _, _ = self.pitch_of(self.motion(delta))
        n = np.hypot(dx, dy)
        ox, oy = -self.sigma * dy / n, self.sigma * dx / n      # outward unit normal
        return x - rr * ox, y - rr * oy


def _roots(fn: Callable, x0: float, x1: float, n: int = GRID, fn1: Callable[[float], float] | None = None
           ) -> list[float]:
    """Interior points of [x0, x1) where ``fn`` changes sign, refined by bisection to the last bit (all
    brackets at once: one call of ``fn`` per halving, whatever their number); or, with ``fn1`` (``fn`` on one
    float), each bracket by Brent's method on floats (:func:`geomcon.numeric.brent_root`, to
    :data:`ROOT_XTOL` of the segment: about ten calls where bisection takes fifty). The grid is denser towards the
    ends (1e-3 … 1e-9 of the piece), where a law starting or ending at rest makes the slope 0 and a maximum
    may hide within the first or last cell.

    >>> [round(r, 12) for r in _roots(np.cos, 0.0, 10.0)]
    [1.570796326795, 4.712388980385, 7.853981633974]
    """
    near = (x1 - x0) * np.logspace(-9.0, -3.0, 7)
    xs = np.unique(np.concatenate([piece_grid(x0, x1, n), x0 + near, np.nextafter(x1, x0) - near]))
    g = fn(xs)
    i = np.nonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0)[0]
    lo, hi, s_lo = xs[i].astype(float), xs[i + 1].astype(float), np.sign(g[i])
    if fn1 is not None:
        return [brent_root(fn1, a, b, ga, gb, xtol=ROOT_XTOL)
                for a, b, ga, gb in zip(lo.tolist(), hi.tolist(), g[i].tolist(), g[i + 1].tolist())]
    while lo.size:
        mid = 0.5 * (lo + hi)
        live = (mid > lo) & (mid < hi)
        if not live.any():
            break
        same = np.sign(fn(mid)) == s_lo
        lo, hi = np.where(live & same, mid, lo), np.where(live & ~same, mid, hi)
    return lo.tolist()


def _brent_maxima(f: Callable, f1: Callable[[float], float], x0: float, x1: float, n: int = GRID
                  ) -> list[tuple[float, float]]:
    """(place, value) of every grid maximum of ``f`` in [x0, x1) (as :func:`_golden_maxima` finds them: the
    grid in one array call) refined by Brent's method on ``f1`` (``f`` on one float) to the same tolerance,
    1e-12 of the place.

    >>> [(round(x, 6), round(v, 12)) for x, v in _brent_maxima(np.sin, math.sin, 0.0, 10.0)]
    [(1.570796, 1.0), (7.853982, 1.0)]
    """
    xs = piece_grid(x0, x1, n)
    v = f(xs)
    left = np.concatenate([[-np.inf], v[:-1]])
    right = np.concatenate([v[1:], [-np.inf]])
    out = []
    for i in np.nonzero((v > left) & (v >= right))[0].tolist():
        lo, hi = float(xs[max(i - 1, 0)]), float(xs[min(i + 1, n - 1)])
        out.append(brent_max1(f1, lo, float(xs[i]), hi, float(v[i]), 1e-12 * max(1.0, abs(hi))))
    return out


def _golden_maxima(f: Callable, x0: float, x1: float, n: int = GRID) -> list[float]:
    """The ends of [x0, x1) and every grid maximum of ``f`` (an end included when it beats its neighbour)
    refined by golden-section search (all peaks at once: one call of ``f`` per step, each peak stopping
    at its own tolerance, 1e-12 of its place).

    >>> [round(x, 6) for x in _golden_maxima(np.sin, 0.0, 10.0)]     # a place from values: to about √ε
    [0.0, 10.0, 1.570796, 7.853982]
    """
    xs = piece_grid(x0, x1, n)
    v = f(xs)
    out = [float(xs[0]), float(xs[-1])]
    inv = (math.sqrt(5.0) - 1.0) / 2.0
    left = np.concatenate([[-np.inf], v[:-1]])
    right = np.concatenate([v[1:], [-np.inf]])
    peaks = np.nonzero((v > left) & (v >= right))[0]    # an end beating its neighbour: a peak may hide inside
    if not peaks.size:
        return out
    lo, hi = xs[np.maximum(peaks - 1, 0)].astype(float), xs[np.minimum(peaks + 1, n - 1)].astype(float)
    c, d = hi - inv * (hi - lo), lo + inv * (hi - lo)
    fc, fd = f(c), f(d)
    live = hi - lo > 1e-12 * np.maximum(1.0, np.abs(hi))
    while live.any():
        go = live & (fc >= fd)                            # the maximum is in [lo, d]
        other = live & ~(fc >= fd)
        hi, d, fd = np.where(go, d, hi), np.where(go, c, d), np.where(go, fc, fd)
        lo, c, fc = np.where(other, c, lo), np.where(other, d, c), np.where(other, fd, fc)
        c = np.where(go, hi - inv * (hi - lo), c)
        d = np.where(other, lo + inv * (hi - lo), d)
        new = np.where(go, c, d)
        f_new = f(new)
        fc, fd = np.where(go, f_new, fc), np.where(other, f_new, fd)
        live = live & (hi - lo > 1e-12 * np.maximum(1.0, np.abs(hi)))
    return out + (0.5 * (lo + hi)).tolist()
