"""Closed forms of the eccentric-circle cam (偏心圆凸轮): the analytic twin of ``cam.eccentric``.

The cam is a disc of radius ``R`` whose centre A lies at the eccentricity ``OA`` from the rotation centre O.
Ground frame: O at the origin, the translating follower moving up (+y) along the line x = e (e > 0: its axis
right of O); an oscillating follower's pivot Q sits at (0, a), as in ``cam.oscillating``. The cam's position is the polar angle φ of
O→A (radians, counter-clockwise from +x). The roller centre (or the knife edge) lies on the pitch circle of
radius Rp = R + rr about A (rr = 0 for a knife), so everything follows from one triangle:

- translating knife / roller: y(φ) = OA·sin φ + √(Rp² − (e − OA·cos φ)²) (the upper meeting point),
  sin α = |e − OA·cos φ| / Rp (the normal passes through A);
- translating flat face (face ⊥ guide): y(φ) = OA·sin φ + R, α ≡ 0;
- oscillating roller: B on the arm circle (Q, L) and the pitch circle, on the arm's side of the directed
  line Q→A, by the law of cosines; sin α = |(A − B)·(B − Q)| / (Rp·L).

The lowest position is φ_low (the pitch point nearest O on the follower), the cam angle δ counts from it in
the sense of rotation, s(δ) = y − y_low. Extremes of α over the rise and return are found by root-finding
on the exact derivative of (e − OA·cos φ)² (translating) or by a bracketed golden-section search
(oscillating), a different route from the construction's "OA ⊥ guide" positions.

This module imports nothing from :mod:`geomcon.geometry` or :mod:`geomcon.scene`.

Examples
--------
>>> cam = Translating(R=30, OA=10, e=-10, rotation="ccw")          # seed 001-26
>>> round(cam.r0, 9), round(cam.h, 4), round(cam.rise_angle, 4)
(20.0, 21.4093, 164.4775)
>>> st = cam.state(cam.phi_from(A_angle=0.0))
>>> round(st["delta"], 6), round(st["s"], 4), round(st["alpha"], 4)
(60.0, 5.0402, 41.8103)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

from ..errors import NotAMechanism
from ..numeric import deg360
import numpy as np

from .base_radius import bisect_root
from .profile import maximise, numpy_is_libm

FOLLOWERS = ("knife", "roller", "flat")
ROTATIONS = ("ccw", "cw")
SAMPLES = 720
"""Grid of cam angles that brackets the critical points of α before they are refined."""


def check_disc(R: float, OA: float) -> None:
    """Refuse a disc whose rotation centre is not strictly inside it, or that is not eccentric.

    >>> check_disc(30, 30)
    Traceback (most recent call last):
    ...
    geomcon.errors.NotAMechanism: OA = 30 ≥ R = 30: the rotation centre O must lie inside the disc
    """
    if OA <= 0:
        raise NotAMechanism(f"OA = {OA:g}: the disc is not eccentric (no motion)")
    if OA >= R:
        raise NotAMechanism(f"OA = {OA:g} ≥ R = {R:g}: the rotation centre O must lie inside the disc")


class _Turning:
    """Cam angles of a cam that turns ``rotation`` and has its lowest and highest positions at the polar
    angles ``phi_low``, ``phi_high`` of O→A (radians)."""

    rotation: str
    phi_low: float
    phi_high: float

    @property
    def sense(self) -> float:
        """+1 for a counter-clockwise cam, −1 for a clockwise one."""
        return 1.0 if self.rotation == "ccw" else -1.0

    def delta_of(self, phi: float) -> float:
        """Cam angle (deg, [0, 360)) turned from the lowest position to the position φ."""
        return deg360(self.sense * math.degrees(phi - self.phi_low))

    def phi_of(self, delta: float) -> float:
        """φ after turning the cam by δ (deg) from the lowest position."""
        return self.phi_low + self.sense * math.radians(delta)

    @property
    def rise_angle(self) -> float:
        """Cam angle of the rise (deg)."""
        return self.delta_of(self.phi_high)


@dataclass(frozen=True)
class Translating(_Turning):
    """An eccentric-circle cam with a translating follower (see the module docstring for the frame)."""

    R: float
    OA: float
    e: float = 0.0
    rr: float = 0.0
    follower: str = "knife"
    rotation: str = "ccw"

    def __post_init__(self) -> None:
        check_disc(self.R, self.OA)
        if self.follower not in FOLLOWERS or self.rotation not in ROTATIONS:
            raise NotAMechanism(f"follower {self.follower!r} / rotation {self.rotation!r} unknown")
        if self.follower != "flat" and abs(self.e) >= self.Rp - self.OA:
            raise NotAMechanism(
                f"offset |e| = {abs(self.e):g} ≥ r0 = Rp − OA = {self.Rp - self.OA:g}: the follower's line misses "
                f"(or only touches) the pitch circle in some positions")

    @property
    def Rp(self) -> float:
        """Radius of the pitch circle (the path of the roller centre relative to the cam)."""
        return self.R + (self.rr if self.follower == "roller" else 0.0)

    @property
    def r0(self) -> float:
        """Base circle: of the pitch curve (knife, roller) or of the profile (flat)."""
        return self.Rp - self.OA if self.follower != "flat" else self.R - self.OA

    @property
    def r0_actual(self) -> float:
        """Base circle of the actual profile, R − OA."""
        return self.R - self.OA

    # -------------------------------------------------------------- the motion
    def y(self, phi: float) -> float:
        """Height of the pitch point (or of the flat face) above O."""
        E = self.OA
        if self.follower == "flat":
            return E * math.sin(phi) + self.R
        u = self.e - E * math.cos(phi)
        return E * math.sin(phi) + math.sqrt((self.Rp - u) * (self.Rp + u))

    def dy(self, phi: float) -> float:
        """dy/dφ."""
        E = self.OA
        if self.follower == "flat":
            return E * math.cos(phi)
        u = self.e - E * math.cos(phi)
        return E * math.cos(phi) - u * E * math.sin(phi) / math.sqrt((self.Rp - u) * (self.Rp + u))

    @property
    def y_low(self) -> float:
        """Lowest height: √(r0² − e²), or r0 for a flat face."""
        r0 = self.r0
        return r0 if self.follower == "flat" else math.sqrt((r0 - self.e) * (r0 + self.e))

    @property
    def y_high(self) -> float:
        """Highest height: √((Rp + OA)² − e²), or R + OA for a flat face."""
        top = self.Rp + self.OA
        return top if self.follower == "flat" else math.sqrt((top - self.e) * (top + self.e))

    @property
    def h(self) -> float:
        """The stroke."""
        return self.y_high - self.y_low

    @property
    def phi_low(self) -> float:
        """φ at the lowest position: A opposite the pitch point nearest O."""
        return -math.pi / 2 if self.follower == "flat" else math.atan2(-self.y_low, -self.e)

    @property
    def phi_high(self) -> float:
        """φ at the highest position: A between O and the farthest pitch point."""
        return math.pi / 2 if self.follower == "flat" else math.atan2(self.y_high, self.e)

    def alpha(self, phi: float) -> float:
        """Pressure angle (deg) at the position φ."""
        if self.follower == "flat":
            return 0.0
        return math.degrees(math.asin(min(1.0, abs(self.e - self.OA * math.cos(phi)) / self.Rp)))

    # -------------------------------------------------------------- states
    def phi_from(self, *, delta: float | None = None, A_angle: float | None = None,
                 contact_angle: float | None = None, turn: float = 0.0) -> float:
        """φ of a state: cam angle δ from the lowest position, or the polar angle of O→A in the figure, or
        the contact point (the roller centre) on the ray from A at ``contact_angle`` from the ray O→A; then
        turned further by ``turn`` degrees in the sense of rotation."""
        if delta is not None:
            phi = self.phi_of(delta)
        elif A_angle is not None:
            phi = math.radians(A_angle)
        elif contact_angle is not None:
            phi = self._phi_of_contact(math.radians(contact_angle))
        else:
            phi = self.phi_low
        return phi + self.sense * math.radians(turn)

    def _phi_of_contact(self, c: float) -> float:
        if self.follower == "flat":
            return math.pi / 2 - c              # the face touches where the disc's radius points up
        bx, by = self.OA + self.Rp * math.cos(c), self.Rp * math.sin(c)   # cam frame with A on +x
        t = math.sqrt(bx * bx + by * by - self.e ** 2)     # |OB| ≥ r0 > |e|
        # the foot (e, 0) lies inside the pitch circle (|e| < r0), so the point with t > 0 is always the upper
        # meeting point: every point of the pitch circle is touched once per turn
        return math.atan2(t, self.e) - math.atan2(by, bx)

    def state(self, phi: float, omega: float | None = None) -> dict[str, float]:
        """δ, s, α (and v = ω·ds/dδ, mm/s with ω in rad/s) at the position φ."""
        out = {"delta": self.delta_of(phi), "s": self.y(phi) - self.y_low, "alpha": self.alpha(phi)}
        if omega is not None:                               # ds/dt = dy/dφ · dφ/dt, dφ/dt = ±ω; at rest at the
            rest = out["delta"] in (0.0, self.rise_angle)   # ends of the stroke (dy/dφ there is roundoff)
            out["v"] = 0.0 if rest else self.sense * omega * self.dy(phi)
        return out

    # -------------------------------------------------------------- extremes of α
    def _critical(self, lo: float, hi: float) -> list[float]:
        """φ in [lo, hi] where d/dφ (e − OA cos φ)² = 0 (bracketed on a grid, then bisected), plus the ends."""
        g: Callable[[float], float] = lambda p: (self.e - self.OA * math.cos(p)) * math.sin(p)
        out = [lo, hi]
        n = max(8, int(SAMPLES * (hi - lo) / (2 * math.pi)))
        grid = [lo + (hi - lo) * i / n for i in range(n + 1)]
        for a, b in zip(grid, grid[1:]):
            ga, gb = g(a), g(b)
            if ga == 0.0:
                out.append(a)
            elif ga * gb < 0:
                out.append(bisect_root(g, a, b))
        return out

    def _span(self, part: str) -> tuple[float, float]:
        """(φ start, φ end) of the rise or the return, in increasing order of δ mapped to φ increasing."""
        d0, d1 = (0.0, self.rise_angle) if part == "rise" else (self.rise_angle, 360.0)
        return d0, d1

    def alpha_extremes(self, part: str) -> dict[str, float]:
        """``alpha_max_<part>``, the cam angle where it occurs, and for the rise ``alpha_min_rise``."""
        if self.follower == "flat":
            out = {f"alpha_max_{part}": 0.0}
            if part == "rise":
                out["alpha_min_rise"] = 0.0
            return out
        d0, d1 = self._span(part)
        p0, p1 = sorted((self.phi_of(d0), self.phi_of(d1)))
        cands = self._critical(p0, p1)
        best = max(cands, key=self.alpha)
        out = {f"alpha_max_{part}": self.alpha(best), f"delta_alpha_max_{part}": self.delta_of(best)}
        if part == "rise":
            out["alpha_min_rise"] = min(self.alpha(p) for p in cands)
        return out

    def offset_correct(self) -> bool:
        """True when this offset gives a smaller largest rise pressure angle than the mirrored one."""
        other = Translating(self.R, self.OA, -self.e, self.rr, self.follower, self.rotation)
        return self.alpha_extremes("rise")["alpha_max_rise"] < other.alpha_extremes("rise")["alpha_max_rise"]

    def cycle(self) -> dict[str, float]:
        """The answers that do not depend on a state."""
        out = {"r0": self.r0, "r0_actual": self.r0_actual, "h": self.h, "rise_angle": self.rise_angle,
               "return_angle": 360.0 - self.rise_angle}
        out.update(self.alpha_extremes("rise"))
        out.update(self.alpha_extremes("return"))
        out["alpha_max"] = max(out["alpha_max_rise"], out["alpha_max_return"])
        if self.follower != "flat" and self.e != 0.0:
            out["offset_correct"] = self.offset_correct()
        return out


@dataclass(frozen=True)
class Oscillating(_Turning):
    """An eccentric-circle cam with an oscillating roller (or knife) follower.

    The arm's pivot Q lies at (0, a) above O (as in ``cam.oscillating``), the arm QB has length L, and the
    roller centre B lies on the ``arm`` side ("left": x < 0 at the extreme positions, i.e. right of the
    directed line Q→A throughout the turn; "right": the mirror image).
    """

    R: float
    OA: float
    a: float
    L: float
    rr: float = 0.0
    rotation: str = "ccw"
    arm: str = "left"

    def __post_init__(self) -> None:
        check_disc(self.R, self.OA)
        r0, top = self.Rp - self.OA, self.Rp + self.OA
        if self.a <= top:
            raise NotAMechanism(f"the pivot (a = {self.a:g}) lies within the cam's reach Rp + OA = {top:g}")
        if not (abs(self.a - self.L) < r0 and top < self.a + self.L):
            raise NotAMechanism(
                f"the arm circle (a = {self.a:g}, L = {self.L:g}) must cross both the base circle r0 = {r0:g} and the "
                f"circle Rp + OA = {top:g}: need |a − L| < {r0:g} and a + L > {top:g}")

    @property
    def side(self) -> float:
        """−1 for a left arm (B turned clockwise from Q→A), +1 for a right arm."""
        return -1.0 if self.arm == "left" else 1.0

    @property
    def Rp(self) -> float:
        """Pitch circle radius R + rr."""
        return self.R + self.rr

    @property
    def r0(self) -> float:
        """Base circle of the pitch curve."""
        return self.Rp - self.OA

    def arm_angle_at(self, dist: float) -> float:
        """∠OQB (rad) when B is at distance ``dist`` from O (law of cosines)."""
        return math.acos((self.a ** 2 + self.L ** 2 - dist ** 2) / (2 * self.a * self.L))

    def B(self, phi: float) -> tuple[float, float]:
        """Roller centre at the position φ: the law of cosines in triangle Q A B."""
        ax, ay = self.OA * math.cos(phi), self.OA * math.sin(phi) - self.a
        d = math.hypot(ax, ay)
        beta = math.acos((self.L ** 2 + d * d - self.Rp ** 2) / (2 * self.L * d))
        t = math.atan2(ay, ax) + self.side * beta
        return self.L * math.cos(t), self.a + self.L * math.sin(t)

    def psi(self, phi: float) -> float:
        """∠OQB (deg)."""
        bx, by = self.B(phi)
        return math.degrees(math.atan2(abs(bx), self.a - by))

    def alpha(self, phi: float) -> float:
        """Pressure angle (deg): sin α = |(A − B)·(B − Q)| / (Rp·L)."""
        bx, by = self.B(phi)
        ax, ay = self.OA * math.cos(phi), self.OA * math.sin(phi)
        c = ((ax - bx) * bx + (ay - by) * (by - self.a)) / (self.Rp * self.L)
        return math.degrees(math.asin(min(1.0, abs(c))))

    def _extreme_phi(self, dist: float, toward: float) -> float:
        g = self.arm_angle_at(dist)
        bx, by = self.side * self.L * math.sin(g), self.a - self.L * math.cos(g)
        return math.atan2(toward * by, toward * bx)

    @property
    def phi_low(self) -> float:
        """A opposite the lowest roller centre (|OB| = r0)."""
        return self._extreme_phi(self.r0, -1.0)

    @property
    def phi_high(self) -> float:
        """A towards the highest roller centre (|OB| = Rp + OA)."""
        return self._extreme_phi(self.Rp + self.OA, 1.0)

    def alpha_max(self, part: str) -> float:
        """Largest α over the rise or the return: grid, then the peaks refined by Brent's method on floats."""
        d0, d1 = (0.0, self.rise_angle) if part == "rise" else (self.rise_angle, 360.0)
        f1 = lambda d: self.alpha(self.phi_of(math.degrees(d)))           # noqa: E731
        return maximise(lambda d: self._alphas(d, f1), [(math.radians(d0), math.radians(d1))], dense=SAMPLES,
                        g1=f1).value

    def _alphas(self, d: np.ndarray, f1: Callable[[float], float]) -> np.ndarray:
        """``f1`` (α at the cam angle δ in radians, from the lowest position) at every angle of ``d``: on arrays
        by the operations of :meth:`phi_of`, :meth:`B` and :meth:`alpha` in their order (math.hypot one element
        at a time; arccos, arctan2 and arcsin numpy's where they are the C library's), the same bits; where
        math would raise or min(1, |c|) meets a nan, the angles one by one by ``f1`` (np.vectorize, as before).

        >>> cam = Oscillating(R=40.0, OA=20.0, a=90.0, L=70.0, rr=10.0)
        >>> d = np.linspace(0.0, 6.0, 7)
        >>> f1 = lambda x: cam.alpha(cam.phi_of(math.degrees(x)))
        >>> cam._alphas(d, f1).tolist() == [f1(x) for x in d.tolist()]
        True
        """
        d = np.asarray(d, dtype=float)
        if not all(numpy_is_libm(n) for n in ("arccos", "arctan2", "arcsin")):
            return np.vectorize(f1, otypes=[float])(d) if d.size else np.zeros(d.shape)
        OA, a, L, Rp, side = self.OA, self.a, self.L, self.Rp, self.side
        L2, Rp2 = L ** 2, Rp ** 2                                       # (Python's float powers, as B's)
        phi = self.phi_low + self.sense * np.radians(np.degrees(d))     # phi_of(degrees(d))
        with np.errstate(all="ignore"):
            c, s = np.cos(phi), np.sin(phi)
            ax, ay = OA * c, OA * s - a
            dd = np.array([math.hypot(x, y) for x, y in zip(ax.reshape(-1).tolist(), ay.reshape(-1).tolist())],
                          dtype=float).reshape(d.shape)
            arg = (L2 + dd * dd - Rp2) / (2 * L * dd)
            t = np.arctan2(ay, ax) + side * np.arccos(arg)
            bx, by = L * np.cos(t), a + L * np.sin(t)
            ax2, ay2 = OA * c, OA * s
            k = ((ax2 - bx) * bx + (ay2 - by) * (by - a)) / (Rp * L)
            out = np.degrees(np.arcsin(np.minimum(1.0, np.abs(k))))
        if not (bool(np.all(np.abs(arg) <= 1.0)) and bool(np.all(dd != 0.0)) and not bool(np.isnan(k).any())
                and bool(np.all(np.isfinite(out)))):
            return np.vectorize(f1, otypes=[float])(d) if d.size else np.zeros(d.shape)
        return out

    def cycle(self) -> dict[str, float]:
        """The answers that do not depend on a state."""
        psi0 = math.degrees(self.arm_angle_at(self.r0))
        out = {"r0": self.r0, "r0_actual": self.R - self.OA, "psi0": psi0,
               "psi_max": math.degrees(self.arm_angle_at(self.Rp + self.OA)) - psi0,
               "rise_angle": self.rise_angle, "return_angle": 360.0 - self.rise_angle,
               "alpha_max_rise": self.alpha_max("rise"), "alpha_max_return": self.alpha_max("return")}
        out["alpha_max"] = max(out["alpha_max_rise"], out["alpha_max_return"])
        return out

    def phi_from(self, *, delta: float | None = None, A_angle: float | None = None, turn: float = 0.0) -> float:
        """φ of a state (δ from the lowest position or the polar angle of O→A), turned further by ``turn``."""
        phi = self.phi_of(delta) if delta is not None else (math.radians(A_angle) if A_angle is not None
                                                            else self.phi_low)
        return phi + self.sense * math.radians(turn)

    def state(self, phi: float) -> dict[str, float]:
        """δ, ψ (the arm's swing from its lowest position) and α at the position φ."""
        return {"delta": self.delta_of(phi), "psi": self.psi(phi) - math.degrees(self.arm_angle_at(self.r0)),
                "alpha": self.alpha(phi)}
