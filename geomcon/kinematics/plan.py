"""The fast path: a chain compiled once into a plan of real-arithmetic kernels, run over crank angles in
cache-sized chunks.

:func:`~.chain.solve_chain` is the reference: each element solved with complex numpy arrays over every crank
angle at once. A :class:`Plan` solves the same description (every element of :mod:`.dyads`: crank, RRR,
RRP, RPR, PRP, carried points, fixed or link-carried guides) by the same closed forms, rewritten in real x, y
arithmetic only where the rewrite is algebraically exact:

- a link is carried as its vector (C − A for an RRR link, length l) rather than its angle: no arctan2 unless
  the angles are asked for, no cos/sin of an angle sum for a carried point or guide (the vector turned by
  the fixed angle instead);
- the RRR joint is C = A + k_a·d + β·k_h·(i·d) with d = B − A, k_a = ½ + (l₁² − l₂²)/(2|d|²) and
  k_h = √(l₁²/|d|² − k_a²) (the reference's a/|d| and h/|d|: no square root of |d|², one division);
- each 2 × 2 linear solve is Cramer's rule written out on the components;
- fixed points, a fixed guide's direction and a crank's ω, ε are scalars, not arrays.

Each chunk of :data:`CHUNK` crank angles is solved with arrays that stay in cache, and the results are
written once into the output arrays; the positions agree with the reference to a few units in the last place
(tests/test_kinematics_plan.py: 1e-15 of the linkage's size on random chains in both branches). The plan
holds no state between calls but the element list: compiling it costs microseconds, so
:func:`solve_fast` compiles on each call.

Examples
--------
>>> import numpy as np
>>> from .chain import Mechanism
>>> from .dyads import RRR, Crank
>>> m = Mechanism({"A": 0j, "D": 4 + 0j}, Crank("AB", "A", "B", 1.0, omega=1.0),
...               (RRR("C", "B", "D", 4.0, 1.0, 1, "BC", "DC"),))
>>> st = compile_chain(m).solve(np.radians([90.0]))
>>> complex(np.round(st.points["C"].p[0], 12))
(4+1j)
>>> [round(float(st.links[k].omega[0]), 12) + 0.0 for k in ("BC", "DC")]
[0.0, 1.0]
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from .chain import Mechanism, check_chain
from .dyads import PRP, RPR, RRP, RRR, Crank, Guide, OnLink, State
from .motion import LinkMotion, PointMotion, SlipMotion

CHUNK = 16384
"""Crank angles per chunk: each working array is 128 KiB, the dozen a four-bar needs stay in the 512 KiB L2
cache of the development machine's cores (measured best among 2 048 … 1 000 000, ``geomcon bench``)."""

Kernel = Callable[["_Chunk"], None]


class _Chunk:
    """The working values of one chunk: points as (x, y, vx, vy, ax, ay), links as (rx, ry, length, ω, ε),
    each an array over the chunk or a float (a fixed point, a constant rate)."""

    __slots__ = ("phi", "sl", "der", "pts", "lks")

    def __init__(self, phi: np.ndarray, sl: slice, der: bool, fixed: dict[str, tuple]):
        self.phi, self.sl, self.der = phi, sl, der
        self.pts: dict[str, tuple] = dict(fixed)
        self.lks: dict[str, tuple] = {}


class _Out:
    """The output arrays of one solve, filled chunk by chunk."""

    def __init__(self, n: int, der: bool, angles: bool):
        self.n, self.der, self.angles = n, der, angles
        self.points: dict[str, tuple[np.ndarray, ...]] = {}
        self.links: dict[str, tuple[np.ndarray | None, ...]] = {}
        self.slips: dict[str, tuple[np.ndarray | None, ...]] = {}
        self.margins: dict[str, np.ndarray] = {}

    def point(self, name: str) -> tuple[np.ndarray, ...]:
        arrs = [np.empty(self.n, dtype=complex) for _ in range(3 if self.der else 1)]
        self.points[name] = tuple(arrs)
        return tuple(x for a in arrs for x in (a.real, a.imag))

    def link(self, name: str, theta: bool = True) -> tuple[np.ndarray | None, ...]:
        th = np.empty(self.n) if self.angles and theta else None
        rates = (np.empty(self.n), np.empty(self.n)) if self.der else (None, None)
        self.links[name] = (th, *rates)
        return self.links[name]

    def slip(self, name: str) -> tuple[np.ndarray | None, ...]:
        self.slips[name] = tuple(np.empty(self.n) if k == 0 or self.der else None for k in range(3))
        return self.slips[name]

    def margin(self, name: str) -> np.ndarray:
        self.margins[name] = np.empty(self.n)
        return self.margins[name]


def _put(dst: tuple, sl: slice, values: tuple) -> None:
    for d, v in zip(dst, values):
        if d is not None:
            d[sl] = v


def _link_angle(th: np.ndarray | None, sl: slice, rx: np.ndarray, ry: np.ndarray) -> None:
    if th is not None:
        np.arctan2(ry, rx, out=th[sl])


def _scratch(n: int, k: int) -> list[np.ndarray]:
    """``k`` working arrays of one chunk, allocated once per solve and reused by every chunk."""
    return [np.empty(n) for _ in range(k)]


def _views(bufs: list[np.ndarray], m: int) -> list[np.ndarray]:
    return bufs if bufs[0].shape[0] == m else [b[:m] for b in bufs]


def _crank(el: Crank, out: _Out, chunk: int) -> Kernel:
    L, w, e = float(el.length), float(el.omega), float(el.epsilon)
    P = out.point(el.joint)
    _, W, E = out.link(el.link, theta=False)
    out.links[el.link] = (None, W, E)
    ac = -w * w
    bufs = _scratch(chunk, 5)

    def run(c: _Chunk) -> None:
        ox, oy = c.pts[el.pivot][:2]             # a fixed point: at rest
        rx, ry, x, y, t = _views(bufs, c.phi.shape[0])
        np.cos(c.phi, out=rx)
        rx *= L
        np.sin(c.phi, out=ry)
        ry *= L
        np.add(rx, ox, out=x)
        np.add(ry, oy, out=y)
        c.lks[el.link] = (rx, ry, L, w, e)
        _put(P, c.sl, (x, y))
        if not c.der:
            c.pts[el.joint] = (x, y, 0.0, 0.0, 0.0, 0.0)
            return
        sl = c.sl
        vx, vy, ax, ay = (np.multiply(ry, -w, out=P[2][sl]), np.multiply(rx, w, out=P[3][sl]),
                          np.multiply(rx, ac, out=P[4][sl]), np.multiply(ry, ac, out=P[5][sl]))
        if e:
            ax -= np.multiply(ry, e, out=t)
            ay += np.multiply(rx, e, out=t)
        c.pts[el.joint] = (x, y, vx, vy, ax, ay)
        W[sl], E[sl] = w, e
    return run


def _dot_times(ax, ay, bx, by, q, out: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(a · b)·q into ``out`` (``t`` a working array)."""
    np.multiply(ax, bx, out=out)
    out += np.multiply(ay, by, out=t)
    out *= q
    return out


def _rrr(el: RRR, out: _Out, chunk: int) -> Kernel:
    l1s, l2s, b = el.l1 ** 2, el.l2 ** 2, el.branch
    half = 0.5 * (l1s - l2s)
    joint = el.joint or el.name
    P, M = out.point(joint), out.margin(el.name)
    K1, K2 = out.link(el.link1), out.link(el.link2)
    hsub = np.subtract if b > 0 else np.add          # the joint on the named side: ± k_h·(i·d)
    hadd = np.add if b > 0 else np.subtract
    bufs = _scratch(chunk, 14)

    def run(c: _Chunk) -> None:
        Ax, Ay, Avx, Avy, Aax, Aay = c.pts[el.p1]
        Bx, By, Bvx, Bvy, Bax, Bay = c.pts[el.p2]
        sl = c.sl
        dx, dy, d2, t, ka, kh, x, y, q, cx, cy, rx, ry, s1 = _views(bufs, c.phi.shape[0])
        np.subtract(Bx, Ax, out=dx)              # (broadcast when both are fixed points)
        np.subtract(By, Ay, out=dy)
        np.multiply(dx, dx, out=d2)
        d2 += np.multiply(dy, dy, out=t)
        inv = np.divide(1.0, d2, out=kh)
        np.multiply(inv, half, out=ka)
        ka += 0.5
        inv *= l1s
        inv -= np.multiply(ka, ka, out=t)        # k_h² (in kh)
        np.multiply(kh, d2, out=t)
        np.multiply(t, 1.0 / l1s, out=M[sl])
        np.maximum(kh, 0.0, out=kh)
        np.sqrt(kh, out=kh)
        np.multiply(ka, dx, out=x)
        hsub(x, np.multiply(kh, dy, out=t), out=x)
        x += Ax
        np.multiply(ka, dy, out=y)
        hadd(y, np.multiply(kh, dx, out=t), out=y)
        y += Ay
        u1x, u1y = np.subtract(x, Ax, out=dx), np.subtract(y, Ay, out=dy)
        u2x, u2y = np.subtract(x, Bx, out=d2), np.subtract(y, By, out=kh)
        _link_angle(K1[0], sl, u1x, u1y)
        _link_angle(K2[0], sl, u2x, u2y)
        _put(P, sl, (x, y))
        if not c.der:
            c.lks[el.link1] = (u1x, u1y, el.l1, None, None)
            c.lks[el.link2] = (u2x, u2y, el.l2, None, None)
            c.pts[joint] = (x, y, 0.0, 0.0, 0.0, 0.0)
            return
        np.multiply(u1y, u2x, out=q)
        q -= np.multiply(u1x, u2y, out=t)
        np.divide(-1.0, q, out=q)                # −1 / det[i·u1, −i·u2]
        np.subtract(Bvx, Avx, out=cx)
        np.subtract(Bvy, Avy, out=cy)
        w1 = _dot_times(cx, cy, u2x, u2y, q, K1[1][sl], t)
        w2 = _dot_times(cx, cy, u1x, u1y, q, K2[1][sl], t)
        np.multiply(w1, w1, out=s1)
        s2 = np.multiply(w2, w2, out=ka)
        np.subtract(Bax, Aax, out=rx)            # B.a − A.a + ω1²·u1 − ω2²·u2
        rx += np.multiply(s1, u1x, out=t)
        rx -= np.multiply(s2, u2x, out=t)
        np.subtract(Bay, Aay, out=ry)
        ry += np.multiply(s1, u1y, out=t)
        ry -= np.multiply(s2, u2y, out=t)
        e1 = _dot_times(rx, ry, u2x, u2y, q, K1[2][sl], t)
        e2 = _dot_times(rx, ry, u1x, u1y, q, K2[2][sl], t)
        vx = np.multiply(w1, u1y, out=cx)
        np.subtract(Avx, vx, out=vx)
        vy = np.multiply(w1, u1x, out=cy)
        vy += Avy
        ax = np.multiply(e1, u1y, out=rx)
        np.subtract(Aax, ax, out=ax)
        ax -= np.multiply(s1, u1x, out=t)
        ay = np.multiply(e1, u1x, out=ry)
        ay += Aay
        ay -= np.multiply(s1, u1y, out=t)
        c.pts[joint] = (x, y, vx, vy, ax, ay)
        c.lks[el.link1] = (u1x, u1y, el.l1, w1, e1)
        c.lks[el.link2] = (u2x, u2y, el.l2, w2, e2)
        _put(P[2:], sl, (vx, vy, ax, ay))
    return run


def _guide(g: Guide, c: _Chunk) -> tuple[tuple, object, object, object, object]:
    """The guide's reference point, unit direction (dx, dy) and ω, ε (None for a fixed guide)."""
    G = c.pts[g.through]
    if g.link is None:
        return G, math.cos(g.angle), math.sin(g.angle), None, None
    rx, ry, L, w, e = c.lks[g.link]
    kc, ks = math.cos(g.angle) / L, math.sin(g.angle) / L
    return G, kc * rx - ks * ry, ks * rx + kc * ry, w, e


def _rrp(el: RRP, out: _Out, chunk: int) -> Kernel:
    ls, b = el.length ** 2, el.branch
    joint = el.joint or el.name
    P, M = out.point(joint), out.margin(el.name)
    K, S = out.link(el.link), out.slip(el.slider or joint)

    def run(c: _Chunk) -> None:
        Px, Py, Pvx, Pvy, Pax, Pay = c.pts[el.p]
        (Gx, Gy, Gvx, Gvy, Gax, Gay), dx, dy, wg, eg = _guide(el.guide, c)
        qx, qy = Px - Gx, Py - Gy
        wr, wi = qx * dx + qy * dy, qy * dx - qx * dy
        h2 = ls - wi * wi
        M[c.sl] = h2 / ls
        s = wr + b * np.sqrt(np.maximum(h2, 0.0))
        x, y = Gx + s * dx, Gy + s * dy
        ux, uy = x - Px, y - Py
        c.lks[el.link] = (ux, uy, el.length, None, None)
        _link_angle(K[0], c.sl, ux, uy)
        if not c.der:
            c.pts[joint] = (x, y, 0.0, 0.0, 0.0, 0.0)
            _put(P, c.sl, (x, y))
            S[0][c.sl] = s
            return
        q = 1.0 / (dx * ux + dy * uy)      # −1 / det[d, −i·u]
        cx, cy = Pvx - Gvx, Pvy - Gvy
        ax_, ay_ = Pax - Gax, Pay - Gay
        if wg is not None:               # a turning guide: the slip's frame moves
            rotx, roty = -wg * dy, wg * dx
            cx, cy = cx - s * rotx, cy - s * roty
        sv = (cx * ux + cy * uy) * q
        w1 = -(dx * cy - dy * cx) * q
        w1s = w1 * w1
        rx, ry = ax_ - w1s * ux, ay_ - w1s * uy
        if wg is not None:
            wgs = wg * wg
            rx = rx - 2 * sv * rotx - s * (-eg * dy - wgs * dx)
            ry = ry - 2 * sv * roty - s * (eg * dx - wgs * dy)
        sa = (rx * ux + ry * uy) * q
        e1 = -(dx * ry - dy * rx) * q
        vx, vy = Pvx - w1 * uy, Pvy + w1 * ux
        ax, ay = Pax - e1 * uy - w1s * ux, Pay + e1 * ux - w1s * uy
        c.pts[joint] = (x, y, vx, vy, ax, ay)
        c.lks[el.link] = (ux, uy, el.length, w1, e1)
        _put(P, c.sl, (x, y, vx, vy, ax, ay))
        _put(K[1:], c.sl, (w1, e1))
        _put(S, c.sl, (s, sv, sa))
    return run


def _rpr(el: RPR, out: _Out, chunk: int) -> Kernel:
    e, b = float(el.offset), el.branch
    M, K, S = out.margin(el.name), out.link(el.link), out.slip(el.slip or el.name)

    def run(c: _Chunk) -> None:
        P1x, P1y, P1vx, P1vy, P1ax, P1ay = c.pts[el.slider]
        P2x, P2y, P2vx, P2vy, P2ax, P2ay = c.pts[el.pivot]
        rx, ry = P1x - P2x, P1y - P2y
        rho2 = rx * rx + ry * ry
        s2 = rho2 - e * e
        M[c.sl] = s2 / rho2
        s = b * np.sqrt(np.maximum(s2, 0.0))
        if e == 0.0:
            dx, dy = rx / s, ry / s
        else:                            # r / (s + i e) = r (s − i e) / (s² + e²)
            den = s * s + e * e
            dx, dy = (rx * s + ry * e) / den, (ry * s - rx * e) / den
        c.lks[el.link] = (dx, dy, 1.0, None, None)
        _link_angle(K[0], c.sl, dx, dy)
        if not c.der:
            S[0][c.sl] = s
            return
        vx, vy = P1vx - P2vx, P1vy - P2vy
        dvr, dvi = vx * dx + vy * dy, vy * dx - vx * dy
        w = dvi / s
        sv = dvr + w * e
        ax, ay = P1ax - P2ax, P1ay - P2ay
        dar, dai = ax * dx + ay * dy, ay * dx - ax * dy
        ws = w * w
        eps = (dai - 2 * w * sv + ws * e) / s
        sa = dar + eps * e + ws * s
        c.lks[el.link] = (dx, dy, 1.0, w, eps)
        _put(K[1:], c.sl, (w, eps))
        _put(S, c.sl, (s, sv, sa))
    return run


def _prp(el: PRP, out: _Out, chunk: int) -> Kernel:
    P, M = out.point(el.name), out.margin(el.name)
    S1, S2 = out.slip(el.slip1), out.slip(el.slip2)

    def frame(w, e, dx, dy):
        """i·ω·d and (iε − ω²)·d of a guide (zeros for a fixed one)."""
        if w is None:
            return 0.0, 0.0, 0.0, 0.0
        ws = w * w
        return -w * dy, w * dx, -e * dy - ws * dx, e * dx - ws * dy

    def run(c: _Chunk) -> None:
        (G1x, G1y, G1vx, G1vy, G1ax, G1ay), d1x, d1y, w1, e1 = _guide(el.guide1, c)
        (G2x, G2y, G2vx, G2vy, G2ax, G2ay), d2x, d2y, w2, e2 = _guide(el.guide2, c)
        cr = d1x * d2y - d1y * d2x
        M[c.sl] = cr * cr
        q = -1.0 / cr                    # 1 / det[d1, −d2]

        def pair(cx, cy):
            return (d2x * cy - d2y * cx) * q, (d1x * cy - d1y * cx) * q

        s1, s2 = pair(G2x - G1x, G2y - G1y)
        x, y = G1x + s1 * d1x, G1y + s1 * d1y
        if not c.der:
            c.pts[el.name] = (x, y, 0.0, 0.0, 0.0, 0.0)
            _put(P, c.sl, (x, y))
            S1[0][c.sl], S2[0][c.sl] = s1, s2
            return
        r1x, r1y, k1x, k1y = frame(w1, e1, d1x, d1y)
        r2x, r2y, k2x, k2y = frame(w2, e2, d2x, d2y)
        v1, v2 = pair(G2vx - G1vx + s2 * r2x - s1 * r1x, G2vy - G1vy + s2 * r2y - s1 * r1y)
        a1, a2 = pair(G2ax - G1ax + 2 * v2 * r2x + s2 * k2x - 2 * v1 * r1x - s1 * k1x,
                      G2ay - G1ay + 2 * v2 * r2y + s2 * k2y - 2 * v1 * r1y - s1 * k1y)
        vx, vy = G1vx + v1 * d1x + s1 * r1x, G1vy + v1 * d1y + s1 * r1y
        ax = G1ax + a1 * d1x + 2 * v1 * r1x + s1 * k1x
        ay = G1ay + a1 * d1y + 2 * v1 * r1y + s1 * k1y
        c.pts[el.name] = (x, y, vx, vy, ax, ay)
        _put(P, c.sl, (x, y, vx, vy, ax, ay))
        _put(S1, c.sl, (s1, v1, a1))
        _put(S2, c.sl, (s2, v2, a2))
    return run


def _on_link(el: OnLink, out: _Out, chunk: int) -> Kernel:
    P = out.point(el.name)

    def run(c: _Chunk) -> None:
        bx, by, bvx, bvy, bax, bay = c.pts[el.base]
        lx, ly, L, w, e = c.lks[el.link]
        kc, ks = el.length * math.cos(el.angle) / L, el.length * math.sin(el.angle) / L
        rx, ry = kc * lx - ks * ly, ks * lx + kc * ly
        x, y = bx + rx, by + ry
        if not c.der:
            c.pts[el.name] = (x, y, 0.0, 0.0, 0.0, 0.0)
            _put(P, c.sl, (x, y))
            return
        ws = w * w
        vx, vy = bvx - w * ry, bvy + w * rx
        ax, ay = bax - e * ry - ws * rx, bay + e * rx - ws * ry
        c.pts[el.name] = (x, y, vx, vy, ax, ay)
        _put(P, c.sl, (x, y, vx, vy, ax, ay))
    return run


_KERNELS: dict[type, Callable[..., Kernel]] = {Crank: _crank, RRR: _rrr, RRP: _rrp, RPR: _rpr, PRP: _prp,
                                              OnLink: _on_link}


@dataclass(frozen=True)
class Plan:
    """A checked chain, ready to be solved by :meth:`solve` over any array of crank angles."""

    mechanism: Mechanism
    chunk: int = CHUNK

    def solve(self, phi: np.ndarray, derivatives: bool = True, angles: bool = True) -> State:
        """Every point, link and slip at the crank angles ``phi`` (rad), as :func:`~.chain.solve_chain` gives
        them; with ``angles`` False the links' angles are not computed (their ``theta`` is None: joints'
        positions, rates and slips only).

        >>> from .dyads import Crank, Guide, RRP
        >>> m = Mechanism({"A": 0j, "G": 0j}, Crank("AB", "A", "B", 30.0, omega=10.0),
        ...               (RRP("C", "B", 90.0, Guide("G", 0.0), 1, "BC"),))
        >>> st = compile_chain(m, chunk=1).solve(np.radians([0.0, 90.0]))
        >>> [round(float(x), 9) for x in st.points["C"].p.real], round(float(st.slips["C"].v[1]), 9)
        ([120.0, 84.852813742], -300.0)
        """
        m = self.mechanism
        phi = np.asarray(phi, dtype=float)
        flat = np.ascontiguousarray(phi.reshape(-1))
        n = flat.shape[0]
        out = _Out(n, derivatives, angles)
        kernels = [_KERNELS[type(el)](el, out, min(self.chunk, max(n, 1))) for el in (m.crank, *m.chain)]
        fixed = {k: (z.real, z.imag, 0.0, 0.0, 0.0, 0.0) for k, z in m.fixed.items()}
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            for k0 in range(0, n, self.chunk):
                sl = slice(k0, min(n, k0 + self.chunk))
                c = _Chunk(flat[sl], sl, derivatives, fixed)
                for run in kernels:
                    run(c)
        return _state(m, phi, out)


def _state(m: Mechanism, phi: np.ndarray, out: _Out) -> State:
    st = State.start(phi, m.fixed, out.der)
    shape = phi.shape
    for name, arrs in out.points.items():
        p, v, a = (*(x.reshape(shape) for x in arrs), None, None)[:3]
        st.points[name] = PointMotion(p, v, a)
    for name, (th, w, e) in out.links.items():
        if name == m.crank.link and out.angles:
            th = phi.copy()
        st.links[name] = LinkMotion(*(None if x is None else x.reshape(shape) for x in (th, w, e)))
    for name, arrs in out.slips.items():
        st.slips[name] = SlipMotion(*(None if x is None else x.reshape(shape) for x in arrs))
    st.margins = {k: v.reshape(shape) for k, v in out.margins.items()}
    return st


def compile_chain(m: Mechanism, chunk: int = CHUNK) -> Plan:
    """Check ``m`` (:func:`~.chain.check_chain`) and return its plan."""
    check_chain(m)
    if chunk < 1:
        raise ValueError(f"chunk must be at least 1, got {chunk}")
    return Plan(m, int(chunk))


def solve_fast(m: Mechanism, phi: np.ndarray, derivatives: bool = True, angles: bool = True) -> State:
    """:func:`compile_chain` then :meth:`Plan.solve`."""
    return compile_chain(m).solve(phi, derivatives, angles)


__all__ = ["CHUNK", "Plan", "compile_chain", "solve_fast"]
