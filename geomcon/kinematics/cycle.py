"""A linkage solved over a crank turn: dead and change points, and exact extremes of any output.

:func:`run_cycle` solves the chain on the requested crank angles, after checking on a fine grid that every
dyad can be assembled over the whole range: where a dyad's margin turns negative the solve stops, naming the
dyad and the crank angles of its dead points (found by bisection to the last bit of the margin's sign), so a
branch is never crossed silently. A margin that touches zero without changing sign is a change point
(parallelogram, 变化点): reported with its angle, the named branch kept.

:func:`stationary_points` finds the extremes of a position-level output as the roots of its exact derivative
(bracketed on the grid, then safeguarded Newton steps on the exact second derivative), not by sampling.

Examples
--------
>>> from .dyads import Crank, Guide, RRP
>>> m = Mechanism({"A": 0j, "G": 0j}, Crank("AB", "A", "B", 30.0, omega=10.0),
...               (RRP("C", "B", 90.0, Guide("G", 0.0), 1, "BC"),))
>>> [(round(p.phi_deg, 9), round(p.value, 9), p.kind) for p in stationary_points(m, "C.x")]
[(0.0, 120.0, 'max'), (180.0, 60.0, 'min')]
>>> s = stroke(m, "C.x")
>>> round(s.stroke, 9), round(s.K, 9)
(60.0, 1.0)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from ..errors import ProblemError
from .chain import Mechanism, solve_chain  # noqa: F401  (Mechanism: doctests)
from .dyads import State
from .quantities import derivatives, fold_gamma, parse_name, principal_deg

GRID = 2880
"""Crank positions per turn of the grid on which margins and derivatives are bracketed (0.125°)."""

CHANGE_TOL = 1e-12
"""A margin (squared length ratio) whose minimum is below this is a change point."""


class DeadPoint(ProblemError):
    """A dyad cannot be assembled over part of the crank's range."""


@dataclass(frozen=True)
class ChangePoint:
    """A crank angle where a dyad's links fall collinear and rise again: the named branch is kept."""

    dyad: str
    phi_deg: float


@dataclass(frozen=True)
class Stationary:
    """An extreme of an output: crank angle (deg), value, and ``kind`` ("max", "min" or "flat")."""

    quantity: str
    phi_deg: float
    value: float
    kind: str


@dataclass(frozen=True)
class Stroke:
    """An output's range over the turn: ``stroke`` = max − min; with exactly one maximum and one minimum the
    crank angles of the increasing and decreasing motions (deg, in the crank's sense of rotation),
    K = larger/smaller and θ = 180°(K − 1)/(K + 1); otherwise ``K`` is None."""

    quantity: str
    stroke: float
    at_max: float
    at_min: float
    increasing: float | None
    decreasing: float | None
    K: float | None
    theta: float | None


def _at(m: Mechanism, phi: float) -> State:
    return solve_chain(m, np.array([phi]))


def _grid(start: float, stop: float, n: int = GRID) -> np.ndarray:
    k = max(8, int(math.ceil(n * abs(stop - start) / (2 * math.pi))))
    return np.linspace(start, stop, k + 1)


def _bisect(f, lo: float, hi: float) -> float:
    """A sign change of ``f`` in [lo, hi] to the last bit."""
    flo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        fm = f(mid)
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _golden_min(f, lo: float, hi: float, iters: int = 90) -> float:
    g = (math.sqrt(5) - 1) / 2
    a, b = lo, hi
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(iters):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    return 0.5 * (a + b)


def assembly(m: Mechanism, start: float, stop: float) -> list[ChangePoint]:
    """Check that every dyad can be assembled for crank angles in [start, stop] (rad); return the change
    points. A dead point raises :class:`DeadPoint` naming the dyad and the crank angles where it cannot be
    assembled."""
    phi = _grid(start, stop)
    full = abs(abs(stop - start) - 2 * math.pi) < 1e-12
    st = solve_chain(m, phi)
    changes: list[ChangePoint] = []
    for name, margin in st.margins.items():
        def f(x: float, name: str = name) -> float:
            return float(_at(m, x).margins[name][0])
        bad = margin < 0
        if bad.any():
            edges = []
            idx = np.flatnonzero(np.diff(bad.astype(np.int8)))
            for i in idx:
                edges.append(math.degrees(_bisect(f, float(phi[i]), float(phi[i + 1]))))
            at = ", ".join(f"{x:.6f}°" for x in edges) or "over the whole range"
            raise DeadPoint(f"dyad '{name}' cannot be assembled over part of the crank's range "
                            f"{math.degrees(start):g}°…{math.degrees(stop):g}°: dead points at {at} "
                            f"(smallest margin {float(margin.min()):.3g}); the crank cannot turn through them")
        step = float(phi[1] - phi[0])
        if full:       # periodic: the first and last samples are one position
            prev, nxt = np.roll(margin[:-1], 1), np.roll(margin[:-1], -1)
            mid = margin[:-1]
        else:
            prev = np.concatenate(([np.inf], margin[:-1]))
            nxt = np.concatenate((margin[1:], [np.inf]))
            mid = margin
        for i in np.flatnonzero((mid <= prev) & (mid <= nxt) & (mid < 1e-4)):
            lo, hi = float(phi[i]) - step, float(phi[i]) + step
            if not full:
                lo, hi = max(lo, start), min(hi, stop)
            x = _golden_min(f, lo, hi)
            if f(x) < CHANGE_TOL:
                deg = math.degrees(x) % 360.0 if full else math.degrees(x)
                changes.append(ChangePoint(name, deg))
    return changes


def _newton_root(g, lo: float, hi: float) -> float:
    """A root of ``g`` (returning value and derivative) bracketed in [lo, hi]: Newton steps kept inside the
    bracket, bisection otherwise, to the last bit."""
    glo = g(lo)[0]
    x = 0.5 * (lo + hi)
    for _ in range(200):
        gx, dg = g(x)
        if gx == 0:
            return x
        if (gx < 0) == (glo < 0):
            lo, glo = x, gx
        else:
            hi = x
        step = x - gx / dg if dg != 0 and math.isfinite(dg) else None
        nxt = step if step is not None and lo < step < hi else 0.5 * (lo + hi)
        if nxt == x or hi - lo <= 4 * math.ulp(max(abs(lo), abs(hi), 1.0)):
            return nxt
        x = nxt
    return x


def stationary_points(m: Mechanism, name: str, start: float = 0.0, stop: float = 2 * math.pi) -> list[Stationary]:
    """Every extreme of the position-level output ``name`` for crank angles in [start, stop) (rad): the roots
    of dq/dφ, exact to rounding. Values as :func:`~.quantities.value` gives them."""
    mu = m.unit_speed()
    phi = _grid(start, stop)
    full = abs(abs(stop - start) - 2 * math.pi) < 1e-12
    _, d1, _ = derivatives(solve_chain(mu, phi), name)
    scale = float(np.max(np.abs(d1))) or 1.0
    sign = np.where(np.abs(d1) <= 1e-14 * scale, 0.0, np.sign(d1))

    def g(x: float) -> tuple[float, float]:
        _, a, b = derivatives(_at(mu, x), name)
        return float(a[0]), float(b[0])

    roots: list[tuple[float, str]] = []
    n = len(phi) - 1
    for i in range(n):
        s0, s1 = sign[i], sign[i + 1]
        if s0 == 0 and (i > 0 or not full):
            kind = "flat"
            prev, nxt = sign[i - 1] if i > 0 else sign[-2], s1
            if prev > 0 > nxt:
                kind = "max"
            elif prev < 0 < nxt:
                kind = "min"
            roots.append((float(phi[i]), kind))
        elif s0 == 0 and i == 0:
            prev = sign[-2]
            kind = "max" if prev > 0 > s1 else "min" if prev < 0 < s1 else "flat"
            roots.append((float(phi[0]), kind))
        elif s0 * s1 < 0:
            roots.append((_newton_root(g, float(phi[i]), float(phi[i + 1])), "max" if s0 > 0 else "min"))
    if not full and sign[n] == 0:
        roots.append((float(phi[n]), "flat"))
    out = []
    obj, _ = parse_name(name)
    for x, kind in roots:
        q = derivatives(_at(m, x), name)[0][0]
        val = float(fold_gamma(np.array([q]))[0]) if obj == "gamma" else float(q)
        if obj != "gamma" and name.endswith(".angle"):
            val = float(principal_deg(np.array([val]))[0])
        if obj == "gamma" and kind != "flat" and math.degrees(q) % 180.0 > 90.0:
            kind = "min" if kind == "max" else "max"     # γ = 180° − μ there: an extreme of μ, reversed
        out.append(Stationary(name, math.degrees(x) % 360.0, val, kind))
    return sorted(out, key=lambda p: p.phi_deg)


def _unwrapped_values(m: Mechanism, name: str, pts: list[Stationary]) -> list[float]:
    """Values at the stationary points, angles as continuous radians→degrees (so a rocker through 0° keeps its
    swing)."""
    if not name.endswith(".angle"):
        return [p.value for p in pts]
    th = [math.degrees(float(derivatives(_at(m, math.radians(p.phi_deg)), name)[0][0])) for p in pts]
    ref = th[0]
    return [ref + ((t - ref + 180.0) % 360.0 - 180.0) for t in th]


def stroke(m: Mechanism, name: str, found: Sequence[Stationary] | None = None) -> Stroke:
    """The output's stroke over a full crank turn and, with one maximum and one minimum, the time ratio.
    ``found``: ``stationary_points(m, name)`` when the caller has it already (the same turn: the same points)."""
    if found is None:
        found = stationary_points(m, name)
    pts = [p for p in found if p.kind in ("max", "min")]
    if not pts:
        raise ProblemError(f"'{name}' has no extreme over the crank turn (it does not move back and forth)")
    vals = _unwrapped_values(m, name, pts)
    imax = max(range(len(pts)), key=lambda i: vals[i])
    imin = min(range(len(pts)), key=lambda i: vals[i])
    inc = dec = K = theta = None
    if len(pts) == 2:
        a, b = pts[imin].phi_deg, pts[imax].phi_deg
        up = (b - a) % 360.0 if m.crank.omega > 0 else (a - b) % 360.0
        inc, dec = up, 360.0 - up
        K = max(inc, dec) / min(inc, dec)
        theta = 180.0 * (K - 1.0) / (K + 1.0)
    return Stroke(name, vals[imax] - vals[imin], pts[imax].phi_deg, pts[imin].phi_deg, inc, dec, K, theta)


@dataclass(frozen=True)
class Cycle:
    """A linkage solved at the crank angles ``phi_deg``, with the change points found on the way."""

    mechanism: Mechanism
    phi_deg: np.ndarray
    state: State
    changes: tuple[ChangePoint, ...]


def run_cycle(m: Mechanism, phi_deg: np.ndarray) -> Cycle:
    """Solve ``m`` at the crank angles ``phi_deg`` (ascending), after checking assembly over their range."""
    phi_deg = np.asarray(phi_deg, dtype=float)
    lo, hi = math.radians(float(phi_deg[0])), math.radians(float(phi_deg[-1]))
    changes = assembly(m, lo, hi if hi > lo else lo + 2 * math.pi)
    return Cycle(m, phi_deg, solve_chain(m, np.radians(phi_deg)), tuple(changes))
