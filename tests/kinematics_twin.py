"""An independent route to a chain's motion, for the tests only: every loop equation solved by Newton's method
in 60-digit arithmetic (mpmath), not in closed form, and velocities and accelerations taken as central
differences of those positions in time (the crank turning at ω with ε), so that nothing is shared with
:mod:`geomcon.kinematics.dyads` but the description of the chain."""
from __future__ import annotations

import mpmath as mp

from geomcon.kinematics.chain import Mechanism
from geomcon.kinematics.dyads import PRP, RPR, RRP, RRR, OnLink

mp.mp.dps = 60
H = mp.mpf("1e-15")


def _newton(f, x0: list, iters: int = 80) -> list:
    """A root of the vector function ``f`` near ``x0`` (Jacobian by mp finite differences)."""
    x = [mp.mpf(v) for v in x0]
    for _ in range(iters):
        fx = f(x)
        if max(abs(v) for v in fx) < mp.mpf("1e-50"):
            break
        n = len(x)
        J = mp.matrix(n, n)
        for j in range(n):
            xp = list(x)
            xp[j] += mp.mpf("1e-30")
            fp = f(xp)
            for i in range(n):
                J[i, j] = (fp[i] - fx[i]) / mp.mpf("1e-30")
        dx = mp.lu_solve(J, mp.matrix(fx))
        x = [x[i] - dx[i] for i in range(n)]
    return x


def positions(m: Mechanism, phi, guess: dict) -> tuple[dict, dict, dict]:
    """Points (mpc), link angles (mpf, rad) and slips at the crank angle ``phi`` (mpf), each loop solved near
    ``guess`` (points, angles and slips from anywhere close: another solution, or a float answer)."""
    gp, gl, gs = guess
    pts = {k: mp.mpc(v) for k, v in m.fixed.items()}
    links, slips = {}, {}
    c = m.crank
    pts[c.joint] = pts[c.pivot] + c.length * mp.expj(phi)
    links[c.link] = phi

    def guide(g):
        ang = g.angle + (links[g.link] if g.link else 0)
        return pts[g.through], mp.expj(ang)

    for el in m.chain:
        if isinstance(el, RRR):
            P1, P2 = pts[el.p1], pts[el.p2]
            z0 = gp[el.joint or el.name]

            def f(x, P1=P1, P2=P2, el=el):
                C = mp.mpc(x[0], x[1])
                return [abs(C - P1) ** 2 - el.l1 ** 2, abs(C - P2) ** 2 - el.l2 ** 2]
            x = _newton(f, [z0.real, z0.imag])
            C = mp.mpc(x[0], x[1])
            pts[el.joint or el.name] = C
            links[el.link1] = mp.arg(C - P1)
            links[el.link2] = mp.arg(C - P2)
        elif isinstance(el, RRP):
            P = pts[el.p]
            G, d = guide(el.guide)
            key = el.slider or el.joint or el.name

            def f(x, P=P, G=G, d=d, el=el):
                return [abs(G + x[0] * d - P) ** 2 - el.length ** 2]
            s = _newton(f, [gs[key]])[0]
            C = G + s * d
            pts[el.joint or el.name] = C
            slips[key] = s
            links[el.link] = mp.arg(C - P)
        elif isinstance(el, RPR):
            P1, P2 = pts[el.slider], pts[el.pivot]
            key = el.slip or el.name

            def f(x, P1=P1, P2=P2, el=el):
                z = P2 + (x[1] + 1j * el.offset) * mp.expj(x[0]) - P1
                return [z.real, z.imag]
            th, s = _newton(f, [gl[el.link], gs[key]])
            links[el.link] = th
            slips[key] = s
        elif isinstance(el, PRP):
            G1, d1 = guide(el.guide1)
            G2, d2 = guide(el.guide2)

            def f(x, G1=G1, G2=G2, d1=d1, d2=d2):
                z = G1 + x[0] * d1 - G2 - x[1] * d2
                return [z.real, z.imag]
            s1, s2 = _newton(f, [gs[el.slip1], gs[el.slip2]])
            slips[el.slip1], slips[el.slip2] = s1, s2
            pts[el.name] = G1 + s1 * d1
        elif isinstance(el, OnLink):
            pts[el.name] = pts[el.base] + el.length * mp.expj(links[el.link] + el.angle)
    return pts, links, slips


def _near(a, ref):
    """The angle ``a`` moved by whole turns next to ``ref``."""
    return a + 2 * mp.pi * mp.nint((ref - a) / (2 * mp.pi))


def guess_of(st) -> tuple[dict, dict, dict]:
    """The starting guess for :func:`motion` from a double-precision state at one crank angle: the points,
    link angles and slips it found."""
    return ({k: complex(v.p[0]) for k, v in st.points.items()},
            {k: float(v.theta[0]) for k, v in st.links.items()},
            {k: float(v.s[0]) for k, v in st.slips.items()})


def motion(m: Mechanism, phi0: float, guess: dict) -> dict:
    """({point: triple}, {link: triple}, {slip: triple}) at the crank angle ``phi0`` (deg), each triple the value
    and its first and second time derivatives: complex for points, the angle (rad) for links, real for slips.
    Always in 60 digits, whatever precision another test left mpmath at (a test that sets ``mp.dps`` lower
    made the differences in time lose their digits: 5e-11 where 1e-15 is asked)."""
    with mp.workdps(60):
        return _motion(m, phi0, guess)


def _motion(m: Mechanism, phi0: float, guess: dict) -> dict:
    w, e = mp.mpf(m.crank.omega), mp.mpf(m.crank.epsilon)
    p0 = mp.radians(mp.mpf(phi0))
    sols = {}
    cur = guess
    for k in (0, 1, -1, 2, -2):
        t = k * H
        sols[k] = positions(m, p0 + w * t + e * t * t / 2, cur)
        if k == 0:
            cur = (sols[0][0], sols[0][1], sols[0][2])
    out: tuple[dict, dict, dict] = ({}, {}, {})
    for kind in range(3):
        for name in sols[0][kind]:
            f = {k: sols[k][kind][name] for k in sols}
            if kind == 1:
                f = {k: _near(v, f[0]) for k, v in f.items()}
            d1 = (-f[2] + 8 * f[1] - 8 * f[-1] + f[-2]) / (12 * H)
            d2 = (-f[2] + 16 * f[1] - 30 * f[0] + 16 * f[-1] - f[-2]) / (12 * H * H)
            out[kind][name] = (f[0], d1, d2)
    return out
