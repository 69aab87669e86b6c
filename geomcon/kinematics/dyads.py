"""The elements of a class-II linkage, each solved in closed form over arrays of crank angles.

A :class:`Crank` turns about a fixed pivot; each Assur dyad places one new joint from points and links already
known: :class:`RRR` (two links meeting at a revolute), :class:`RRP` (a link whose end slides on a guide),
:class:`RPR` (a guide link through a pivot, its slider pinned to a known point: the guide bar, 导杆),
:class:`PRP` (a revolute joining two sliders on two guides); :class:`OnLink` carries a point rigidly with a link.
A guide (:class:`Guide`) is fixed, or carried by a link.

Positions are closed form; velocities and accelerations solve the loop equation differentiated once and twice
(two real linear equations per dyad, :func:`~.motion.solve_real_pair`). Each dyad with two assemblies takes
its ``branch`` (+1 or −1, defined on each class) and keeps it at every crank angle; its assembly margin
(≥ 0 where it can be assembled, 0 at a dead or change point) goes to ``State.margins``.

Examples
--------
>>> import numpy as np
>>> st = State.start(np.radians([90.0]), {"A": 0j, "D": 4 + 0j})
>>> Crank("AB", "A", "B", 1.0, omega=1.0).apply(st)
>>> RRR("C", "B", "D", 4.0, 1.0, branch=1, link1="BC", link2="DC").apply(st)
>>> complex(np.round(st.points["C"].p[0], 12))
(4+1j)
>>> [round(float(st.links[k].omega[0]), 12) + 0.0 for k in ("BC", "DC")]
[0.0, 1.0]
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .motion import LinkMotion, PointMotion, SlipMotion, solve_real_pair


@dataclass
class State:
    """The motion found so far over the crank angles ``phi`` (rad): points, links, sliders, and each dyad's
    assembly margin (a squared length ratio; negative where it cannot be assembled)."""

    phi: np.ndarray
    derivatives: bool = True
    points: dict[str, PointMotion] = field(default_factory=dict)
    links: dict[str, LinkMotion] = field(default_factory=dict)
    slips: dict[str, SlipMotion] = field(default_factory=dict)
    margins: dict[str, np.ndarray] = field(default_factory=dict)

    @classmethod
    def start(cls, phi: np.ndarray, fixed: dict[str, complex], derivatives: bool = True) -> "State":
        """A state with the fixed points at rest and the crank angles ``phi`` (rad); with ``derivatives``
        False only positions are computed (velocities and accelerations are None)."""
        phi = np.asarray(phi, dtype=float)
        zero = np.broadcast_to(np.complex128(0), phi.shape)      # no memory: a fixed point is one number
        st = cls(phi, derivatives)
        for name, z in fixed.items():
            st.points[name] = PointMotion(np.broadcast_to(np.complex128(z), phi.shape), zero, zero)
        return st


def cis(theta: np.ndarray) -> np.ndarray:
    """exp(iθ) from one cosine and one sine (numpy's complex exp is several times slower).

    >>> complex(cis(np.array([np.pi / 2]))[0].round(15))
    1j
    """
    theta = np.asarray(theta, dtype=float)
    out = np.empty(theta.shape, dtype=complex)
    np.cos(theta, out=out.real)
    np.sin(theta, out=out.imag)
    return out


def carried(base: PointMotion, r: np.ndarray, w: np.ndarray, eps: np.ndarray) -> PointMotion:
    """The motion of the point ``base + r`` of a link turning at ``w`` with ``eps`` (rigid-body formulas)."""
    return PointMotion(base.p + r, base.v + 1j * w * r, base.a + (1j * eps - w * w) * r)


@dataclass(frozen=True)
class Crank:
    """The driving link ``link``: ``pivot`` (a fixed point) to ``joint``, ``length`` mm, at the crank angle φ
    (counter-clockwise from +x), turning at ``omega`` rad/s with angular acceleration ``epsilon`` rad/s²."""

    link: str
    pivot: str
    joint: str
    length: float
    omega: float
    epsilon: float = 0.0

    def apply(self, st: State) -> None:
        """Place the crank's joint and its link."""
        o = st.points[self.pivot]
        r = self.length * cis(st.phi)
        if not st.derivatives:
            st.points[self.joint] = PointMotion(o.p + r, None, None)
            st.links[self.link] = LinkMotion(st.phi, None, None)
            return
        w = np.full(st.phi.shape, float(self.omega))
        eps = np.full(st.phi.shape, float(self.epsilon))
        st.points[self.joint] = carried(o, r, w, eps)
        st.links[self.link] = LinkMotion(st.phi.copy(), w, eps)


@dataclass(frozen=True)
class Guide:
    """A straight guide through the point ``through`` at ``angle`` (rad): fixed when ``link`` is None (then
    ``through`` is a fixed point), else carried by ``link`` (``through`` a point of that link, the direction
    ``angle`` measured from the link's angle)."""

    through: str
    angle: float
    link: str | None = None

    def motion(self, st: State) -> tuple[PointMotion, np.ndarray, np.ndarray, np.ndarray]:
        """The reference point's motion, the unit direction ``d`` and the guide's ω and ε."""
        g = st.points[self.through]
        if self.link is None:
            zero = np.broadcast_to(np.float64(0), st.phi.shape)
            return g, np.broadcast_to(np.complex128(complex(np.cos(self.angle), np.sin(self.angle))),
                                      st.phi.shape), zero, zero
        lk = st.links[self.link]
        return g, cis(lk.theta + self.angle), lk.omega, lk.epsilon


def _angle(z: np.ndarray) -> np.ndarray:
    return np.angle(z)


@dataclass(frozen=True)
class RRR:
    """Joint ``joint`` at ``l1`` from the known point ``p1`` and ``l2`` from ``p2`` (links ``link1`` = p1→joint,
    ``link2`` = p2→joint). ``branch`` +1: the joint lies left of p1→p2, −1: right. Margin h²/l1², h the
    joint's distance from the line p1p2 (0 when the links are collinear)."""

    name: str
    p1: str
    p2: str
    l1: float
    l2: float
    branch: int
    link1: str
    link2: str
    joint: str = ""

    def apply(self, st: State) -> None:
        """Place the joint and both links."""
        A, B = st.points[self.p1], st.points[self.p2]
        d = B.p - A.p
        dist = np.abs(d)
        u = d / dist
        a = (dist * dist + self.l1 ** 2 - self.l2 ** 2) / (2 * dist)
        h2 = self.l1 ** 2 - a * a
        st.margins[self.name] = h2 / self.l1 ** 2
        h = np.sqrt(np.maximum(h2, 0.0))
        C = A.p + (a + 1j * self.branch * h) * u
        u1, u2 = C - A.p, C - B.p
        if not st.derivatives:
            st.points[self.joint or self.name] = PointMotion(C, None, None)
            st.links[self.link1] = LinkMotion(_angle(u1), None, None)
            st.links[self.link2] = LinkMotion(_angle(u2), None, None)
            return
        w1, w2 = solve_real_pair(1j * u1, -1j * u2, B.v - A.v)
        rhs = B.a - A.a + w1 * w1 * u1 - w2 * w2 * u2
        e1, e2 = solve_real_pair(1j * u1, -1j * u2, rhs)
        st.points[self.joint or self.name] = PointMotion(C, A.v + 1j * w1 * u1, A.a + (1j * e1 - w1 * w1) * u1)
        st.links[self.link1] = LinkMotion(_angle(u1), w1, e1)
        st.links[self.link2] = LinkMotion(_angle(u2), w2, e2)


@dataclass(frozen=True)
class RRP:
    """Link ``link`` of ``length`` from the known point ``p`` to the slider's pin ``joint`` on ``guide``; the
    pin's place along the guide from its reference point is the slip ``slider``. ``branch`` +1: the pin lies
    ahead (along the guide's direction) of the foot of the perpendicular from ``p``, −1: behind. Margin
    h²/length², h the pin's distance from that foot (0 when the link is perpendicular to the guide)."""

    name: str
    p: str
    length: float
    guide: Guide
    branch: int
    link: str
    slider: str = ""
    joint: str = ""

    def apply(self, st: State) -> None:
        """Place the pin, the link and the slip."""
        P = st.points[self.p]
        G, d, wg, eg = self.guide.motion(st)
        w = (P.p - G.p) * np.conj(d)
        h2 = self.length ** 2 - w.imag ** 2
        st.margins[self.name] = h2 / self.length ** 2
        s = w.real + self.branch * np.sqrt(np.maximum(h2, 0.0))
        C = G.p + s * d
        u = C - P.p
        if not st.derivatives:
            st.points[self.joint or self.name] = PointMotion(C, None, None)
            st.links[self.link] = LinkMotion(_angle(u), None, None)
            st.slips[self.slider or self.joint or self.name] = SlipMotion(s, None, None)
            return
        rot = 1j * wg * d
        sv, w1 = solve_real_pair(d, -1j * u, P.v - G.v - s * rot)
        rhs = P.a - w1 * w1 * u - G.a - 2 * sv * rot - s * (1j * eg - wg * wg) * d
        sa, e1 = solve_real_pair(d, -1j * u, rhs)
        st.points[self.joint or self.name] = PointMotion(C, P.v + 1j * w1 * u, P.a + (1j * e1 - w1 * w1) * u)
        st.links[self.link] = LinkMotion(_angle(u), w1, e1)
        st.slips[self.slider or self.joint or self.name] = SlipMotion(s, sv, sa)


@dataclass(frozen=True)
class RPR:
    """Guide link ``link`` turning about the known point ``pivot``, its slider pinned at the known point
    ``slider``; the guide's line passes ``offset`` mm to the left of the pivot (signed). The link's angle is
    the guide's direction; ``branch`` +1: the slider lies ahead of the pivot along it (slip s > 0), −1: behind.
    Margin s²/|slider − pivot|² (0 when the pivot–slider distance falls to |offset|)."""

    name: str
    slider: str
    pivot: str
    link: str
    branch: int = 1
    offset: float = 0.0
    slip: str = ""

    def apply(self, st: State) -> None:
        """Place the guide link and the slip."""
        P1, P2 = st.points[self.slider], st.points[self.pivot]
        r = P1.p - P2.p
        rho2 = (r * np.conj(r)).real
        e = self.offset
        s2 = rho2 - e * e
        st.margins[self.name] = s2 / rho2
        s = self.branch * np.sqrt(np.maximum(s2, 0.0))
        d = r / (s + 1j * e)
        if not st.derivatives:
            st.links[self.link] = LinkMotion(_angle(d), None, None)
            st.slips[self.slip or self.name] = SlipMotion(s, None, None)
            return
        dv = (P1.v - P2.v) * np.conj(d)
        w = dv.imag / s
        sv = dv.real + w * e
        da = (P1.a - P2.a) * np.conj(d)
        eps = (da.imag - 2 * w * sv + w * w * e) / s
        sa = da.real + eps * e + w * w * s
        st.links[self.link] = LinkMotion(_angle(d), w, eps)
        st.slips[self.slip or self.name] = SlipMotion(s, sv, sa)


@dataclass(frozen=True)
class PRP:
    """A revolute ``joint`` joining two sliders, one on each guide: the joint is where the guides cross. Slips
    ``slip1``, ``slip2`` along each guide from its reference point. Margin sin² of the angle between the
    guides (0 when parallel)."""

    name: str
    guide1: Guide
    guide2: Guide
    slip1: str
    slip2: str

    def apply(self, st: State) -> None:
        """Place the joint and both slips."""
        G1, d1, w1, e1 = self.guide1.motion(st)
        G2, d2, w2, e2 = self.guide2.motion(st)
        c = (d1 * np.conj(d2)).imag
        st.margins[self.name] = c * c
        s1, s2 = solve_real_pair(d1, -d2, G2.p - G1.p)
        if not st.derivatives:
            st.points[self.name] = PointMotion(G1.p + s1 * d1, None, None)
            st.slips[self.slip1], st.slips[self.slip2] = SlipMotion(s1, None, None), SlipMotion(s2, None, None)
            return
        r1, r2 = 1j * w1 * d1, 1j * w2 * d2
        v1, v2 = solve_real_pair(d1, -d2, G2.v - G1.v + s2 * r2 - s1 * r1)
        rhs = (G2.a - G1.a + 2 * v2 * r2 + s2 * (1j * e2 - w2 * w2) * d2
               - 2 * v1 * r1 - s1 * (1j * e1 - w1 * w1) * d1)
        a1, a2 = solve_real_pair(d1, -d2, rhs)
        p = G1.p + s1 * d1
        vel = G1.v + v1 * d1 + s1 * r1
        acc = G1.a + a1 * d1 + 2 * v1 * r1 + s1 * (1j * e1 - w1 * w1) * d1
        st.points[self.name] = PointMotion(p, vel, acc)
        st.slips[self.slip1] = SlipMotion(s1, v1, a1)
        st.slips[self.slip2] = SlipMotion(s2, v2, a2)


@dataclass(frozen=True)
class OnLink:
    """The point ``name`` carried by ``link``: ``length`` mm from the link's point ``base`` at ``angle`` (rad)
    from the link's direction."""

    name: str
    link: str
    base: str
    length: float
    angle: float = 0.0

    def apply(self, st: State) -> None:
        """Place the point."""
        b, lk = st.points[self.base], st.links[self.link]
        r = self.length * cis(lk.theta + self.angle)
        if not st.derivatives:
            st.points[self.name] = PointMotion(b.p + r, None, None)
            return
        st.points[self.name] = carried(b, r, lk.omega, lk.epsilon)


Element = Crank | RRR | RRP | RPR | PRP | OnLink
"""One element of a chain."""
