"""Closed forms of the disc cam with a translating follower: the analytic twin of ``cam.translating``.

Frame: the cam centre O at the origin, the follower's axis vertical, moving up, at x = e (e > 0: right of O)
in the drawing of the starting position; the follower starts (δ = 0) at the bottom of its stroke, on the
base circle r0 of the pitch curve, at height s0 = √(r0² − e²). k = +1 for a cam turning counter-clockwise,
−1 clockwise. With S = s0 + s and E = s′ − k·e (′ = d/dδ, per radian):

- pitch point (inversion, the follower turned by −kδ): ccw (S sin δ + e cos δ, S cos δ − e sin δ),
  cw (−S sin δ + e cos δ, S cos δ + e sin δ);
- pressure angle tan α = |E| / S (so an offset on the side k·e > 0 lowers the rise's α: 逆转右偏, 顺转左偏);
- radius of curvature of the pitch curve ρ = (S² + E²)^{3/2} / (S² + E(E + s′) − S·s″), > 0 where convex;
- flat face (perpendicular to the axis, r0 = base circle of the profile): contact at k·s′ from O's line,
  k·s′ − e from the axis; profile radius of curvature r0 + s + s″ (convex when > 0 everywhere).

This module imports nothing from the geometry, the scene or the profile machinery; maxima are located by
bisection on the sign of their exact derivative, ρmin by successive parabolic interpolation.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
...                       {"kind": "return", "angle": 90, "law": "uniform"}, {"kind": "dwell", "angle": 90}])
>>> cam = TranslatingCam(prog, h=16.0, r0=30.0, e=0.0)
>>> [round(float(v), 9) for v in cam.pitch(0.0)]
[0.0, 30.0]
>>> round(float(cam.alpha(60.0)), 6)                  # tan α = s′/(s0 + s) = 12/38
17.525568
>>> [round(v, 6) for v in cam.alpha_max("rise") + cam.alpha_max("return")]
[17.901969, 51.897868, 18.753919, 270.0]
>>> round(cam.rho_min_pitch(), 9), round(cam.flat_rho_min(), 9), cam.face_extent()
(28.714034069, 28.0, (10.185916357881302, 12.0))
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from ..errors import NotAMechanism
from .program import Program

_DENSE = 4096
TIE = 1e-12
"""Maxima equal to this relative tolerance tie; the smallest cam angle is reported."""


@dataclass(frozen=True)
class TranslatingCam:
    """A disc cam with a translating follower (see the module docstring for the conventions)."""

    program: Program
    h: float
    r0: float
    e: float = 0.0
    rotation: str = "ccw"
    results: dict = field(default_factory=dict, compare=False, repr=False)
    """The searches done so far on this cam object (α_max, ρmin, …), each once."""

    @property
    def k(self) -> float:
        """+1 for a counter-clockwise cam, −1 for a clockwise one."""
        return 1.0 if self.rotation == "ccw" else -1.0

    @property
    def s0(self) -> float:
        """Height of the follower's lowest position above O: √(r0² − e²)."""
        if abs(self.e) >= self.r0:
            raise NotAMechanism(f"offset |e| = {abs(self.e):g} must be smaller than r0 = {self.r0:g}")
        return math.sqrt((self.r0 - self.e) * (self.r0 + self.e))

    def motion(self, delta_deg) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(s, s′, s″) at cam angles in degrees."""
        return self.program.motion(self.h, delta_deg)

    def pitch(self, delta_deg) -> tuple[np.ndarray, np.ndarray]:
        """The pitch point (roller centre, knife tip) in the cam's frame."""
        d = np.radians(delta_deg)
        S = self.s0 + self.motion(delta_deg)[0]
        c, s = np.cos(d), np.sin(d)
        return self.k * S * s + self.e * c, S * c - self.k * self.e * s

    def alpha(self, delta_deg) -> np.ndarray:
        """Pressure angle (degrees) of a knife or roller follower at cam angles ``delta_deg``."""
        s, v, _ = self.motion(delta_deg)
        return np.degrees(np.arctan2(np.abs(v - self.k * self.e), self.s0 + s))

    def _rad(self, d):
        return self.program.motion(self.h, d, radians=True)

    def alpha_max(self, kind: str) -> tuple[float, float]:
        """(α_max, δ where it occurs) in degrees over the rise or the return (knife or roller)."""
        return _memo(self, "alpha_max_" + kind, lambda: self._alpha_max(kind))

    def _alpha_max(self, kind: str) -> tuple[float, float]:
        seg = self.program.rise if kind == "rise" else self.program.ret
        if seg is None:
            return 0.0, 0.0

        def g(d):                     # α itself (deg): ties are judged on α, not on tan α (huge near 90°)
            s, v, _ = self._rad(d)
            return np.degrees(np.arctan2(np.abs(v - self.k * self.e), self.s0 + s))

        def dg(d):                    # sign of d/dδ (|E|/S) = sign(E)(s″S − E s′)/S²
            s, v, a = self._rad(d)
            E = v - self.k * self.e
            return np.sign(E) * (a * (self.s0 + s) - E * v)

        motion1, h, ke, s0 = self.program.motion1, self.h, self.k * self.e, self.s0

        def dg1(d):                   # the same on one float (the same bits)
            s, v, a = motion1(h, d, True)
            E = v - ke
            return _sign(E) * (a * (s0 + s) - E * v)

        best, at = _max_by_root(g, dg, math.radians(seg.start), math.radians(seg.end), dg1)
        return best, math.degrees(at)

    def pitch_curvature(self, d_rad) -> np.ndarray:
        """1/ρ of the pitch curve at cam angles in radians, positive where convex."""
        s, v, a = self._rad(d_rad)
        S, E = self.s0 + s, v - self.k * self.e
        return (S * S + E * (E + v) - S * a) / (S * S + E * E) ** 1.5

    def pitch_curvature1(self, d: float) -> float:
        """:meth:`pitch_curvature` at one cam angle (radians), on floats (the same bits: the power 1.5 as
        numpy computes it)."""
        s, v, a = self.program.motion1(self.h, d, True)
        S, E = self.s0 + s, v - self.k * self.e
        return (S * S + E * (E + v) - S * a) / _pow(S * S + E * E, 1.5)

    def rho_min_pitch(self) -> float:
        """Smallest radius of curvature of the convex parts of the pitch curve."""
        return _memo(self, "rho_min_pitch", self._rho_min_pitch)

    def _rho_min_pitch(self) -> float:
        top = max(_max_by_parabola(self.pitch_curvature, a, b, self.pitch_curvature1) for a, b in self._pieces())
        return 1.0 / top if top > 0 else math.inf

    def flat_rho(self, d_rad) -> np.ndarray:
        """r0 + s + s″: radius of curvature of a flat-faced follower's profile (r0 its base circle)."""
        s, _, a = self._rad(d_rad)
        return self.r0 + s + a

    def flat_rho_min(self) -> float:
        """min (r0 + s + s″) over the turn."""
        return _memo(self, "flat_rho_min", self._flat_rho_min)

    def _flat_rho_min(self) -> float:
        motion1, h, r0 = self.program.motion1, self.h, self.r0

        def low1(d):
            s, _, a = motion1(h, d, True)
            return -(r0 + s + a)

        return -max(_max_by_parabola(lambda d: -self.flat_rho(d), a, b, low1) for a, b in self._pieces())

    def face_extent(self) -> tuple[float, float]:
        """(left, right): how far the flat face's contact goes left and right of the follower's axis (mm),
        max(e − k·s′) and max(k·s′ − e), each at least 0."""
        return _memo(self, "face_extent", self._face_extent)

    def _face_extent(self) -> tuple[float, float]:
        d = np.concatenate([_grid(a, b) for a, b in self._pieces()])
        v = self._rad(d)[1]
        # s′ is extreme where s″ = 0 or at segment ends: refine by bisection on s″
        ext = [float(x) for x in v]
        motion1, h = self.program.motion1, self.h
        for a, b in self._pieces():
            for sign in (1.0, -1.0):
                best, _ = _max_by_root(lambda x: sign * self._rad(x)[1], lambda x: sign * self._rad(x)[2], a, b,
                                       lambda x: sign * motion1(h, x, True)[2])
                ext.append(sign * best)
        rel = [self.k * x - self.e for x in ext]
        return max(0.0, -min(rel)), max(0.0, max(rel))

    def _pieces(self) -> list[tuple[float, float]]:
        """Smooth pieces (radians): the segments, parabolic ones cut in half (s″ jumps there)."""
        out = []
        for seg in self.program.segments:
            cut = seg.law is not None and seg.law.name == "parabolic"
            ends = [seg.start, seg.start + seg.angle / 2, seg.end] if cut else [seg.start, seg.end]
            out += [(math.radians(a), math.radians(b)) for a, b in zip(ends, ends[1:])]
        return out


def _grid(a: float, b: float, n: int = _DENSE // 4) -> np.ndarray:
    d = np.linspace(a, b, n + 1)
    d[-1] = np.nextafter(b, a)
    return d


def _max_by_root(g: Callable, dg: Callable, a: float, b: float, dg1: Callable[[float], float] | None = None
                 ) -> tuple[float, float]:
    """Max of g on [a, b) (right end one-sided): the ends and every place where dg changes sign from + to −,
    found by bisection to the last bit (on floats by ``dg1``, dg of one angle with the same bits, when
    given: the same halvings without an array call each)."""
    d = _grid(a, b)
    w = (b - a) * np.array([1e-10, 1e-8, 1e-6, 1e-4, 1e-3])      # a maximum squeezed against an end
    d = np.unique(np.concatenate([d, a + w, np.nextafter(b, a) - w]))
    slope = dg(d)
    cands = [d[0], d[-1]]
    up = slope[:-1] > 0
    up[0] = slope[0] >= 0           # the slope is often exactly 0 at a segment's start (a law starting at rest)
    for i in np.nonzero(up & (slope[1:] <= 0))[0]:
        lo, hi = float(d[i]), float(d[i + 1])
        while True:
            mid = 0.5 * (lo + hi)
            if mid <= lo or mid >= hi:
                break
            if (dg1(mid) if dg1 is not None else float(dg(np.array([mid]))[0])) > 0:
                lo = mid
            else:
                hi = mid
        cands.append(lo)
    vals = np.asarray(g(np.array(cands, dtype=float)), dtype=float)
    top = float(np.max(vals))
    tied = [c for c, v in zip(cands, vals) if v >= top - TIE * abs(top)]     # equal to roundoff: earliest place
    at = min(tied)
    return float(vals[cands.index(at)]), float(at)


def _max_by_parabola(g: Callable, a: float, b: float, g1: Callable[[float], float] | None = None) -> float:
    """Max of g on [a, b): dense samples, then successive parabolic interpolation about each of the few
    best local maxima of the samples (a peak between samples may overtake the best sample's); ``g1``, g of
    one angle with the same bits, when given, evaluates the interpolation's points without an array call."""
    d = _grid(a, b)
    v = g(d)
    best = float(np.max(v))
    peaks = np.array(_peaks(v), dtype=np.intp)
    # the four highest, ties by place: sorted(peaks, key=lambda j: -v[j])[:4] without a key call per peak (a
    # dwell's flat samples are all peaks: 512 of them)
    for i in peaks[np.argsort(-v[peaks], kind="stable")[:4]].tolist():
        best = max(best, _parabola(g, d, v, i, g1))
    if v[0] > v[1]:                               # a peak between the first two samples
        m = np.array([d[0], 0.5 * (d[0] + d[1]), d[1]])
        best = max(best, _parabola(g, m, _values(g, g1, m), 1, g1))
    if v[-1] > v[-2]:
        m = np.array([d[-2], 0.5 * (d[-2] + d[-1]), d[-1]])
        best = max(best, _parabola(g, m, _values(g, g1, m), 1, g1))
    return best


def _peaks(v: np.ndarray) -> list[int]:
    """The inner samples not below either neighbour, ascending: ``[i for i in range(1, len(v) - 1) if v[i] >=
    v[i - 1] and v[i] >= v[i + 1]]`` in one array pass (the same comparisons: a nan is no peak and stops none
    beside it; ~4 against ~45 µs on a 1 025-sample grid).

    >>> _peaks(np.array([0.0, 1.0, 1.0, 0.0, 2.0, np.nan, 3.0, 1.0]))
    [1, 2]
    >>> _peaks(np.array([1.0, 1.0, 1.0])), _peaks(np.array([1.0, 2.0]))
    ([1], [])
    """
    mid = v[1:-1]
    return (np.flatnonzero((mid >= v[:-2]) & (mid >= v[2:])) + 1).tolist()


def _values(g: Callable, g1: Callable[[float], float] | None, d: np.ndarray) -> np.ndarray:
    """g at a few angles, one by one on the scalar path when there is one."""
    return g(d) if g1 is None else np.array([g1(x) for x in d.tolist()])


def _sign(x: float) -> float:
    """np.sign of one float."""
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else (0.0 if x == 0.0 else math.nan))


def _pow(x: float, y: float) -> float:
    """x ** y as numpy computes it on arrays (its own power routine), for one float."""
    one = np.empty(1)
    one[0] = x
    return float(np.power(one, y)[0])


def _memo(cam: "TranslatingCam", name: str, compute: Callable[[], Any]) -> Any:
    """``compute()`` once per cam object: a twin's searches, kept with the cam, so that the checks and the
    warnings of one solve share them (the recipe hands its twin on from the checks to the warnings)."""
    memo = cam.results
    if name not in memo:
        memo[name] = compute()
    return memo[name]


def _parabola(g: Callable, d: np.ndarray, v: np.ndarray, i: int, g1: Callable[[float], float] | None = None) -> float:
    """Successive parabolic interpolation from the samples i − 1, i, i + 1 (the middle one the highest or not)."""
    best = float(v[i])
    (x0, x1, x2), (y0, y1, y2) = (float(t) for t in d[i - 1:i + 2]), (float(t) for t in v[i - 1:i + 2])
    for _ in range(100):
        den = (x1 - x0) * (y1 - y2) - (x1 - x2) * (y1 - y0)
        if den == 0.0 or x2 - x0 < 1e-14:
            break
        t = x1 - 0.5 * ((x1 - x0) ** 2 * (y1 - y2) - (x1 - x2) ** 2 * (y1 - y0)) / den
        if not x0 < t < x2 or t == x1:
            break
        yt = g1(t) if g1 is not None else float(g(np.array([t]))[0])
        if yt >= y1:        # t becomes the middle point
            (x0, y0, x2, y2) = (x1, y1, x2, y2) if t > x1 else (x0, y0, x1, y1)
            x1, y1 = t, yt
        elif t > x1:
            x2, y2 = t, yt
        else:
            x0, y0 = t, yt
    return max(best, y1)
