"""The twin of the follower's motion: s, s′, s″ of a cam program written again from the laws' definitions,
independently of :mod:`geomcon.cam.laws`, :mod:`geomcon.cam.custom_laws` and :mod:`geomcon.cam.program`,
and the maxima of |s′| and |s″| at the ends of each smooth piece and the roots of the next derivative, s″ and
s‴ (written here too: the closed forms', the handbook shapes' and the polynomial's differentiated, the
spline's constant f‴ on each interval), bracketed on :data:`CELLS` cells and refined by Brent's method.

- The five standard laws and the double-harmonic law: their closed forms in x = (δ − start)/Φ.
- The modified trapezoid and modified sine: only their accelerations are written here (the handbook's
  shapes); f′ and f are Gauss–Legendre quadratures of it (f(x) = ∫₀ˣ (x − t)·f″(t) dt, 24 nodes per smooth
  piece: exact to rounding for these shapes) and the amplitude is 1/∫₀¹ (1 − t)·A(t) dt.
- A polynomial: sums of terms (math.fsum), not Horner.
- A table: the clamped cubic spline in Hermite form, its slopes from the C2 conditions solved as one dense
  linear system (the construction solves for second derivatives by the Thomas algorithm).

Examples
--------
>>> prog = [{"kind": "rise", "angle": 180, "law": "modified_sine"}, {"kind": "return", "angle": 180, "law": "cosine"}]
>>> s, v, a = motion(prog, 10.0, 90.0)
>>> round(s, 12), round(v * math.pi / 10.0, 4)
(5.0, 1.7596)
>>> [round(x, 6) for x in maxima(prog, 10.0)]
[5.600992, 5.600992]
"""
from __future__ import annotations

import math
from functools import lru_cache
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from ..cam.custom_laws import HANDBOOK_ALIASES
from ..cam.laws import ALIASES
from ..numeric import brent_root

Triple = tuple[float, float, float]
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(24)


def _name(law: str) -> str:
    return ALIASES.get(law, HANDBOOK_ALIASES.get(law, law))


# ---------------------------------------------------------------------------------------- closed forms
def _closed(name: str, x: float) -> Triple:
    pi = math.pi
    if name == "uniform":
        return x, 1.0, 0.0
    if name == "parabolic":
        if x < 0.5:
            return 2.0 * x ** 2, 4.0 * x, 4.0
        return 1.0 - 2.0 * (1.0 - x) ** 2, 4.0 * (1.0 - x), -4.0
    if name == "cosine":
        return 0.5 - 0.5 * math.cos(pi * x), 0.5 * pi * math.sin(pi * x), 0.5 * pi ** 2 * math.cos(pi * x)
    if name == "cycloidal":
        w = 2.0 * pi
        return x - math.sin(w * x) / w, 1.0 - math.cos(w * x), w * math.sin(w * x)
    if name == "poly345":
        return 10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5, 30 * x ** 2 - 60 * x ** 3 + 30 * x ** 4, 60 * x - 180 * x ** 2 + 120 * x ** 3
    if name == "double_harmonic":
        return (0.5 * (1.0 - math.cos(pi * x)) - 0.125 * (1.0 - math.cos(2 * pi * x)),
                0.5 * pi * math.sin(pi * x) - 0.25 * pi * math.sin(2 * pi * x),
                0.5 * pi ** 2 * math.cos(pi * x) - 0.5 * pi ** 2 * math.cos(2 * pi * x))
    raise KeyError(name)


# ------------------------------------------------------------------------ accelerations, integrated
def _trapezoid_shape(t: float) -> float:
    q = 4.0 * math.pi
    if t < 0.125:
        return math.sin(q * t)
    if t < 0.375:
        return 1.0
    if t < 0.625:
        return math.cos(q * (t - 0.375))
    if t < 0.875:
        return -1.0
    return -math.sin(q * (1.0 - t))


def _msine_shape(t: float) -> float:
    q = 4.0 * math.pi
    if t < 0.125:
        return math.sin(q * t)
    if t < 0.875:
        return math.cos(q * (t - 0.125) / 3.0)
    return -math.sin(q * (1.0 - t))


SHAPES: dict[str, tuple[Callable[[float], float], tuple[float, ...]]] = {
    "modified_trapezoid": (_trapezoid_shape, (0.0, 0.125, 0.375, 0.625, 0.875, 1.0)),
    "modified_sine": (_msine_shape, (0.0, 0.125, 0.875, 1.0)),
}


def _integrals(shape: Callable[[float], float], edges: tuple[float, ...], x: float) -> tuple[float, float]:
    """(∫₀ˣ A, ∫₀ˣ (x − t)·A(t) dt) by Gauss–Legendre on each smooth piece below x."""
    i1, i2 = [], []
    for a, b in zip(edges, edges[1:]):
        if a >= x:
            break
        b = min(b, x)
        half, mid = 0.5 * (b - a), 0.5 * (a + b)
        for n, w in zip(_NODES.tolist(), _WEIGHTS.tolist()):
            t = mid + half * n
            at = shape(t)
            i1.append(w * half * at)
            i2.append(w * half * (x - t) * at)
    return math.fsum(i1), math.fsum(i2)


@lru_cache(maxsize=None)
def _amplitude(name: str) -> float:
    shape, edges = SHAPES[name]
    return 1.0 / _integrals(shape, edges, 1.0)[1]


def _integrated(name: str, x: float) -> Triple:
    shape, edges = SHAPES[name]
    c = _amplitude(name)
    v, s = _integrals(shape, edges, x)
    return c * s, c * v, c * shape(x) if x < 1.0 else -c * math.sin(4.0 * math.pi * (1.0 - x))


# ---------------------------------------------------------------------------------------------- poly, table
def _poly(c: Sequence[float], x: float) -> Triple:
    return (math.fsum(ck * x ** k for k, ck in enumerate(c)),
            math.fsum(k * ck * x ** (k - 1) for k, ck in enumerate(c) if k >= 1),
            math.fsum(k * (k - 1) * ck * x ** (k - 2) for k, ck in enumerate(c) if k >= 2))


@lru_cache(maxsize=64)
def _slopes(points: tuple[tuple[float, float], ...]) -> tuple[float, ...]:
    """The clamped spline's slopes m_i (m_0 = m_n = 0) from the C2 conditions at the inner points, one dense
    solve."""
    x = [p[0] for p in points]
    f = [p[1] for p in points]
    n = len(x)
    if n == 2:
        return (0.0, 0.0)
    hs = [x[i + 1] - x[i] for i in range(n - 1)]
    d = [(f[i + 1] - f[i]) / hs[i] for i in range(n - 1)]
    A = np.zeros((n - 2, n - 2))
    r = np.zeros(n - 2)
    for k, i in enumerate(range(1, n - 1)):
        A[k, k] = 2.0 * (hs[i - 1] + hs[i])
        if k > 0:
            A[k, k - 1] = hs[i]
        if k < n - 3:
            A[k, k + 1] = hs[i - 1]
        r[k] = 3.0 * (hs[i] * d[i - 1] + hs[i - 1] * d[i])
    return (0.0, *np.linalg.solve(A, r).tolist(), 0.0)


def _interval(points: tuple[tuple[float, float], ...], x: float) -> tuple[int, tuple[float, ...]]:
    """The table's interval holding ``x`` (its index) and the spline's slopes at the points."""
    m = _slopes(points)
    i = 0
    while i < len(points) - 2 and x >= points[i + 1][0]:
        i += 1
    return i, m


def _table(points: tuple[tuple[float, float], ...], x: float) -> Triple:
    i, m = _interval(points, x)
    (x0, f0), (x1, f1) = points[i], points[i + 1]
    h = x1 - x0
    t = (x - x0) / h
    h00, h10, h01, h11 = 2 * t ** 3 - 3 * t ** 2 + 1, t ** 3 - 2 * t ** 2 + t, -2 * t ** 3 + 3 * t ** 2, t ** 3 - t ** 2
    d00, d10, d01, d11 = 6 * t ** 2 - 6 * t, 3 * t ** 2 - 4 * t + 1, -6 * t ** 2 + 6 * t, 3 * t ** 2 - 2 * t
    e00, e10, e01, e11 = 12 * t - 6, 6 * t - 4, -12 * t + 6, 6 * t - 2
    s = h00 * f0 + h10 * h * m[i] + h01 * f1 + h11 * h * m[i + 1]
    v = (d00 * f0 + d10 * h * m[i] + d01 * f1 + d11 * h * m[i + 1]) / h
    a = (e00 * f0 + e10 * h * m[i] + e01 * f1 + e11 * h * m[i + 1]) / (h * h)
    return s, v, a


def normalised(row: Mapping[str, Any], x: float) -> Triple:
    """(f, f′, f″) of a program row's law at x in [0, 1]."""
    name = _name(row["law"])
    if name == "poly":
        return _poly([float(c) for c in row["coefficients"]], x)
    if name == "table":
        return _table(tuple((float(p[0]), float(p[1])) for p in row["points"]), x)
    if name in SHAPES:
        return _integrated(name, x)
    return _closed(name, x)


# ---------------------------------------------------------------------------------------------- the program
def _rows(program: Sequence[Mapping[str, Any]]) -> list[tuple[Mapping[str, Any], float, float, float]]:
    """(row, start deg, angle deg, level before it in units of h)."""
    out, start, level = [], 0.0, 0.0
    for row in program:
        angle = float(row["angle"])
        out.append((row, start, angle, level))
        start += angle
        level += {"rise": 1.0, "return": -1.0}.get(row["kind"], 0.0)
    return out


def motion(program: Sequence[Mapping[str, Any]], h: float, delta_deg: float) -> Triple:
    """(s, ds/dδ, d²s/dδ²) at the cam angle δ (deg; derivatives per radian) of a full-turn program."""
    d = delta_deg % 360.0
    if d == 0.0 and delta_deg > 0.0:            # the full turn belongs to the last segment
        d = 360.0
    rows = _rows(program)
    row, start, angle, level = rows[0]
    for r in rows:
        if r[1] <= d:
            row, start, angle, level = r
    if row["kind"] == "dwell":
        return level * h, 0.0, 0.0
    x = min(max((d - start) / angle, 0.0), 1.0)
    f, f1, f2 = normalised(row, x)
    sign = 1.0 if row["kind"] == "rise" else -1.0
    phi = math.radians(angle)
    return level * h + sign * h * f, sign * h * f1 / phi, sign * h * f2 / phi ** 2


def _golden_max(g: Callable[[float], float], lo: float, hi: float) -> float:
    """max of g on [lo, hi] (unimodal there) by golden sections to 1e-13."""
    r = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo, hi
    c, d = b - r * (b - a), a + r * (b - a)
    gc, gd = g(c), g(d)
    while b - a > 1e-13:
        if gc >= gd:
            b, d, gd = d, c, gc
            c = b - r * (b - a)
            gc = g(c)
        else:
            a, c, gc = c, d, gd
            d = a + r * (b - a)
            gd = g(d)
    return max(gc, gd, g(lo), g(hi))


# ---------------------------------------------------------------------------------------- the third derivative
def _closed3(name: str, x: float) -> float:
    pi = math.pi
    if name in ("uniform", "parabolic"):
        return 0.0
    if name == "cosine":
        return -0.5 * pi ** 3 * math.sin(pi * x)
    if name == "cycloidal":
        w = 2.0 * pi
        return w * w * math.cos(w * x)
    if name == "poly345":
        return 60.0 - 360.0 * x + 360.0 * x * x
    if name == "double_harmonic":
        return -0.5 * pi ** 3 * math.sin(pi * x) + pi ** 3 * math.sin(2.0 * pi * x)
    raise KeyError(name)


def _shape_slope(name: str, t: float) -> float:
    """d/dt of the handbook shapes above (their pieces differentiated one by one)."""
    q = 4.0 * math.pi
    if name == "modified_trapezoid":
        if t < 0.125:
            return q * math.cos(q * t)
        if t < 0.375 or 0.625 <= t < 0.875:
            return 0.0
        if t < 0.625:
            return -q * math.sin(q * (t - 0.375))
        return q * math.cos(q * (1.0 - t))
    if t < 0.125:
        return q * math.cos(q * t)
    if t < 0.875:
        return -q / 3.0 * math.sin(q * (t - 0.125) / 3.0)
    return q * math.cos(q * (1.0 - t))


def _table3(points: tuple[tuple[float, float], ...], x: float) -> float:
    """The spline's f‴ (constant on each interval): the Hermite basis differentiated three times."""
    i, m = _interval(points, x)
    (x0, f0), (x1, f1) = points[i], points[i + 1]
    h = x1 - x0
    return (12.0 * f0 + 6.0 * h * m[i] - 12.0 * f1 + 6.0 * h * m[i + 1]) / h ** 3


def third(row: Mapping[str, Any], x: float) -> float:
    """f‴ of a program row's law at x in [0, 1] (a piece's own value at its left end)."""
    name = _name(row["law"])
    if name == "poly":
        c = [float(v) for v in row["coefficients"]]
        return math.fsum(k * (k - 1) * (k - 2) * ck * x ** (k - 3) for k, ck in enumerate(c) if k >= 3)
    if name == "table":
        return _table3(tuple((float(p[0]), float(p[1])) for p in row["points"]), x)
    if name in SHAPES:
        return _amplitude(name) * _shape_slope(name, x)
    return _closed3(name, x)


def _smooth_pieces(row: Mapping[str, Any]) -> tuple[float, ...]:
    """The edges of the law's smooth pieces on [0, 1]."""
    name = _name(row["law"])
    if name in SHAPES:
        return SHAPES[name][1]
    if name == "table":
        return tuple(float(p[0]) for p in row["points"])
    if name == "parabolic":
        return (0.0, 0.5, 1.0)
    return (0.0, 1.0)


CELLS = 32
"""Cells per smooth piece in which a sign change of the next derivative is looked for."""


def _segment_max(row: Mapping[str, Any], k: int) -> float:
    """max |f^(k)| (k = 1, 2) on [0, 1]: at the ends of the smooth pieces (a piece's right end one-sided) and at
    the roots of f^(k+1) inside each (a sign change on :data:`CELLS` cells, refined by Brent's method,
    :func:`geomcon.numeric.brent_root`)."""
    def value(x: float) -> float:
        return abs(normalised(row, x)[k])

    name = _name(row["law"])
    if k == 2:
        slope: Callable[[float], float] = lambda x: third(row, x)              # noqa: E731
    elif name in SHAPES:                          # f″ is the shape itself: no quadrature for a slope's sign
        slope = SHAPES[name][0]
    else:
        slope = lambda x: normalised(row, x)[2]                                # noqa: E731

    edges = _smooth_pieces(row)
    best = max(value(0.0), value(1.0))
    for a, b in zip(edges, edges[1:]):
        right = math.nextafter(b, a)
        best = max(best, value(a), value(right))
        xs = [a + (right - a) * i / CELLS for i in range(CELLS)] + [right]
        gs = [slope(x) for x in xs]
        for x0, x1, g0, g1 in zip(xs, xs[1:], gs, gs[1:]):
            if g0 == 0.0:
                best = max(best, value(x0))
            elif g1 != 0.0 and (g0 > 0.0) != (g1 > 0.0):
                best = max(best, value(brent_root(slope, x0, x1, g0, g1)))
    return best


def maxima(program: Sequence[Mapping[str, Any]], h: float) -> tuple[float, float]:
    """(max |s′| per rad, max |s″| per rad²) over the turn."""
    vm = am = 0.0
    for row, _, angle, _ in _rows(program):
        if row["kind"] == "dwell":
            continue
        phi = math.radians(angle)
        vm = max(vm, abs(h) * _segment_max(row, 1) / phi)
        am = max(am, abs(h) * _segment_max(row, 2) / phi ** 2)
    return vm, am


def follower_speeds(g: Mapping[str, Any], *, angular: bool) -> dict[str, Any]:
    """The twin's answers for a given ``omega``: translating ``v a v_max a_max`` (mm/s, mm/s²), an arm's
    ``omega2 epsilon2 omega2_max epsilon2_max`` (rad/s, rad/s²; h in degrees); ``{}`` without ω."""
    omega = g.get("omega")
    if omega is None:
        return {}
    omega = float(omega)
    k = math.pi / 180.0 if angular else 1.0
    names = ("omega2", "epsilon2", "omega2_max", "epsilon2_max") if angular else ("v", "a", "v_max", "a_max")
    h, prog = float(g["h"]), g["program"]
    vm, am = maxima(prog, h)
    out: dict[str, Any] = {names[2]: omega * vm * k, names[3]: omega * omega * am * k}
    at = tuple(g.get("at") or ())
    if at:
        ms = [motion(prog, h, float(d)) for d in at]
        out[names[0]] = tuple(omega * m[1] * k for m in ms)
        out[names[1]] = tuple(omega * omega * m[2] * k for m in ms)
    return out
