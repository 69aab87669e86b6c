"""Motion laws beyond the five standard ones: the design handbooks' double-harmonic, modified-trapezoid and
modified-sine laws, a polynomial in the normalised angle (coefficients given) and a law given as a table
(a clamped cubic spline). Each is normalised like :mod:`geomcon.cam.laws`: f(x) for x = δ/Φ in [0, 1],
f(0) = 0, f(1) = 1, with exact f′, f″ and f‴.

Definitions (acceleration shapes as in R. L. Norton, *Cam Design and Manufacturing Handbook*, 2nd ed.,
Industrial Press 2009, ch. 3, and H. A. Rothbart, *Cam Design Handbook*, McGraw-Hill 2004, ch. 3):

==================  =================================================================================
double_harmonic     f = ½[(1 − cos πx) − ¼(1 − cos 2πx)]: f″(0) = 0, f″(1) = −π² (meant for a rise
                    followed by a return without a dwell; before a dwell the acceleration jumps: soft)
modified_trapezoid  f″ = C·sin 4πx on [0, ⅛], C on [⅛, ⅜], C·cos 4π(x − ⅜) on [⅜, ⅝], −C on [⅝, ⅞],
                    −C·sin 4π(1 − x) on [⅞, 1]; C = 8π/(π + 2) ≈ 4.8881, peak f′ = 2
modified_sine       f″ = C·sin 4πx on [0, ⅛], C·cos(4π(x − ⅛)/3) on [⅛, ⅞], −C·sin 4π(1 − x) on [⅞, 1];
                    C ≈ 5.5280, peak f′ = C/π ≈ 1.7596
poly                f = Σ c_k x^k (``coefficients = [c0, c1, …]``, at most :data:`MAX_COEFFICIENTS`), with
                    c0 = 0 and Σ c_k = 1 (checked to 1e-9)
table               the clamped cubic spline through the points (x_i, f_i) (``points = [[0, 0], …, [1, 1]]``,
                    2 to :data:`MAX_POINTS` points, x strictly increasing from 0 to 1, f from 0 to 1) with
                    f′(0) = f′(1) = 0: C2 (f, f′, f″ continuous; f‴ jumps at the points), the second
                    derivatives from the tridiagonal system solved here (numpy, no scipy)
==================  =================================================================================

The handbook laws' piecewise closed forms are integrated here once, piece by piece, from their
accelerations (the constants chained for continuity of f′ and f); C then makes f(1) = 1. The impact class
(rigid, soft or none at the ends of a rise between dwells) is read off the end values of f′ and f″.

Examples
--------
>>> mt, ms = law("modified_trapezoid"), law("modified_sine")
>>> round(mt.fn1(0.25)[2], 10), round(mt.fn1(0.5)[1], 12), round(ms.fn1(0.5)[1] * math.pi, 4)
(4.8881237628, 2.0, 5.528)
>>> p = custom_law("poly", {"coefficients": [0, 0, 0, 10, -15, 6]})
>>> p.fn1(0.5) == law("poly345").fn1(0.5), p.impact
(True, 'none')
>>> t = custom_law("table", {"points": [[0, 0], [0.5, 0.5], [1, 1]]})
>>> [round(v, 12) for v in t.fn1(0.5)], t.impact
([0.5, 1.5, 0.0], 'soft')
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import replace
from functools import lru_cache
from typing import Any, Callable, Mapping

import numpy as np

from ..errors import NotAMechanism
from .laws import Law, law

MAX_COEFFICIENTS = 16
"""Most coefficients of a ``poly`` law (degree ≤ 15)."""
MAX_POINTS = 64
"""Most points of a ``table`` law."""
END_TOL = 1e-9
"""f(0) = 0 and f(1) = 1 must hold to this (a polynomial's Σc, a table's end values)."""
NUMBER_MAX = 1e6
"""Largest |coefficient| or |table value|."""
PARAMETRISED = ("poly", "table")
"""The laws made from numbers, with the key that holds them."""
PARAM_KEY = {"poly": "coefficients", "table": "points"}


def _vectorised(fn1: Callable[[float], tuple[float, float, float]]) -> Callable:
    """The array form of a scalar law: the scalar form element by element (so both give the same bits)."""

    def fn(x):
        xa = np.asarray(x, dtype=float)
        out = np.array([fn1(v) for v in xa.reshape(-1).tolist()], dtype=float).reshape(-1, 3)
        return tuple(out[:, i].reshape(xa.shape) for i in range(3))

    return fn


def _impact(fn1: Callable[[float], tuple[float, float, float]]) -> str:
    """rigid when f′ ≠ 0 at an end, soft when f″ ≠ 0 there, else none (to 1e-12)."""
    (_, v0, a0), (_, v1, a1) = fn1(0.0), fn1(1.0)
    if max(abs(v0), abs(v1)) > 1e-12:
        return "rigid"
    return "soft" if max(abs(a0), abs(a1)) > 1e-12 else "none"


def _finish(name: str, zh: str, fn1, fn3, cuts: tuple[float, ...] = (), params: tuple = (), fn=None) -> Law:
    """The Law with its impact class and its exact peak |f′| (:func:`geomcon.cam.kinematics.law_peaks`);
    ``fn``, the array form, written with the scalar form's operations in the same order (else the scalar form
    element by element)."""
    from .kinematics import law_peaks
    lw = Law(name, zh, _impact(fn1), fn or _vectorised(fn1), fn1, math.inf, fn3, cuts, params)
    return replace(lw, peak1=law_peaks(lw).v)


# ------------------------------------------------------------------------------------ piecewise accelerations
def _accel_law(pieces: list[tuple[float, float, float, float]]) -> tuple[Callable, Callable, tuple[float, ...]]:
    """A law from its acceleration's pieces ``(x0, x1, w, p)``: f″ = C·sin(w(x − x0) + p) (w ≠ 0) or C·p
    (w = 0, a constant), integrated in closed form with f(0) = f′(0) = 0; C is chosen so that f(1) = 1."""
    rows, v0, s0 = [], 0.0, 0.0
    for x0, x1, w, p in pieces:                      # unit amplitude first
        rows.append((x0, w, p, v0, s0))
        v0, s0 = _vs(x1 - x0, w, p, v0, s0)
    scale = 1.0 / s0
    rows = [(x0, w, p, v * scale, s * scale) for x0, w, p, v, s in rows]
    starts = [r[0] for r in rows]

    def fn1(x: float) -> tuple[float, float, float]:
        x0, w, p, v, s = rows[max(bisect_right(starts, x) - 1, 0)]
        t = x - x0
        if w == 0.0:
            a = scale * p
            return s + v * t + a * t * t / 2.0, v + a * t, a
        c = scale / w
        return (s + v * t + c * (t * math.cos(p) - (math.sin(w * t + p) - math.sin(p)) / w),
                v + c * (math.cos(p) - math.cos(w * t + p)), scale * math.sin(w * t + p))

    def fn3(x: float) -> float:
        x0, w, p, _, _ = rows[max(bisect_right(starts, x) - 1, 0)]
        return 0.0 if w == 0.0 else scale * w * math.cos(w * (x - x0) + p)

    cols = [np.array(c, dtype=float) for c in zip(*rows)]        # x0, w, p, v, s of each piece
    sn = np.array([math.sin(r[2]) for r in rows])                # the constants as the scalar form's math makes them
    cs = np.array([math.cos(r[2]) for r in rows])
    wsafe = np.where(cols[1] == 0.0, 1.0, cols[1])
    arr = np.array(starts)

    def fn(x):                                 # the array form: fn1's operations, piece by piece gathered
        xa = np.asarray(x, dtype=float)
        i = np.maximum(np.searchsorted(arr, xa, side="right") - 1, 0)
        x0, w, p, v, s0 = (c[i] for c in cols)
        t = xa - x0
        ws = wsafe[i]
        c = scale / ws
        arg = ws * t + p
        sin_arg = np.sin(arg)
        const = w == 0.0
        a = scale * p
        f = np.where(const, s0 + v * t + a * t * t / 2.0, s0 + v * t + c * (t * cs[i] - (sin_arg - sn[i]) / ws))
        f1 = np.where(const, v + a * t, v + c * (cs[i] - np.cos(arg)))
        f2 = np.where(const, a, scale * sin_arg)
        return f, f1, f2

    return fn1, fn3, tuple(starts[1:]), fn


def _vs(t: float, w: float, p: float, v: float, s: float) -> tuple[float, float]:
    """f′ and f at the end of a unit-amplitude piece of length t that starts with f′ = v, f = s."""
    if w == 0.0:
        return v + p * t, s + v * t + p * t * t / 2.0
    return v + (math.cos(p) - math.cos(w * t + p)) / w, s + v * t + (t * math.cos(p) - (math.sin(w * t + p) - math.sin(p)) / w) / w


_Q, _H = 4.0 * math.pi, math.pi / 2.0
_TRAPEZOID = [(0.0, 0.125, _Q, 0.0), (0.125, 0.375, 0.0, 1.0), (0.375, 0.625, _Q, _H), (0.625, 0.875, 0.0, -1.0),
              (0.875, 1.0, _Q, -_H)]
_MSINE = [(0.0, 0.125, _Q, 0.0), (0.125, 0.875, _Q / 3.0, _H), (0.875, 1.0, _Q, -_H)]


def _double_harmonic1(x: float) -> tuple[float, float, float]:
    a, b = math.pi * x, 2.0 * math.pi * x
    return (0.5 * ((1.0 - math.cos(a)) - 0.25 * (1.0 - math.cos(b))), math.pi / 2.0 * (math.sin(a) - 0.5 * math.sin(b)),
            math.pi ** 2 / 2.0 * (math.cos(a) - math.cos(b)))


def _double_harmonic(x):
    """:func:`_double_harmonic1` on an array (the same operations)."""
    xa = np.asarray(x, dtype=float)
    a, b = math.pi * xa, 2.0 * math.pi * xa
    return (0.5 * ((1.0 - np.cos(a)) - 0.25 * (1.0 - np.cos(b))), math.pi / 2.0 * (np.sin(a) - 0.5 * np.sin(b)),
            math.pi ** 2 / 2.0 * (np.cos(a) - np.cos(b)))


def _double_harmonic3(x: float) -> float:
    return math.pi ** 3 / 2.0 * (2.0 * math.sin(2.0 * math.pi * x) - math.sin(math.pi * x))


def _handbook() -> dict[str, Law]:
    mt1, mt3, mt_cuts, mt = _accel_law(_TRAPEZOID)
    ms1, ms3, ms_cuts, ms = _accel_law(_MSINE)
    return {l.name: l for l in (
        _finish("double_harmonic", "双谐波运动规律", _double_harmonic1, _double_harmonic3, fn=_double_harmonic),
        _finish("modified_trapezoid", "改进梯形加速度运动规律", mt1, mt3, mt_cuts, fn=mt),
        _finish("modified_sine", "改进正弦加速度运动规律", ms1, ms3, ms_cuts, fn=ms),
    )}


HANDBOOK_LAWS: dict[str, Law] = _handbook()
HANDBOOK_ALIASES = {"双谐波": "double_harmonic", "改进梯形": "modified_trapezoid", "修正梯形": "modified_trapezoid",
                    "改进正弦": "modified_sine", "修正正弦": "modified_sine", "modified_sinusoid": "modified_sine"}


# ---------------------------------------------------------------------------------------------- polynomial
def _horner(c: tuple[float, ...], x: float) -> float:
    out = 0.0
    for k in reversed(c):
        out = out * x + k
    return out


def _derivative(c: tuple[float, ...]) -> tuple[float, ...]:
    return tuple(k * ci for k, ci in enumerate(c))[1:] or (0.0,)


def poly_law(coefficients: tuple[float, ...]) -> Law:
    """f = Σ c_k x^k (c0 = 0, Σc = 1 to :data:`END_TOL`)."""
    c = tuple(float(v) for v in coefficients)
    if abs(c[0]) > END_TOL:
        raise NotAMechanism(f"coefficients: c0 = {c[0]:g} must be 0 (f(0) = 0)")
    if abs(math.fsum(c) - 1.0) > END_TOL:
        raise NotAMechanism(f"coefficients add up to {math.fsum(c):.12g}, not 1 (f(1) = 1)")
    d1 = _derivative(c)
    d2 = _derivative(d1)
    d3 = _derivative(d2)

    def fn1(x: float) -> tuple[float, float, float]:
        return _horner(c, x), _horner(d1, x), _horner(d2, x)

    def fn(x):                                 # Horner on an array: the same operations, element by element
        xa = np.asarray(x, dtype=float)
        return _horner(c, xa) + 0.0 * xa, _horner(d1, xa) + 0.0 * xa, _horner(d2, xa) + 0.0 * xa

    return _finish("poly", "多项式运动规律", fn1, lambda x: _horner(d3, x), (), c, fn=fn)


# ---------------------------------------------------------------------------------------------- table
def spline_moments(x: tuple[float, ...], f: tuple[float, ...]) -> np.ndarray:
    """Second derivatives M_i of the clamped cubic spline (f′ = 0 at both ends) through (x_i, f_i): the
    tridiagonal system h_{i−1}M_{i−1} + 2(h_{i−1} + h_i)M_i + h_iM_{i+1} = 6(d_i − d_{i−1}) (d the chords'
    slopes; the end rows 2h_0M_0 + h_0M_1 = 6d_0, h_{n−1}M_{n−2} + 2h_{n−1}M_{n−1} = −6d_{n−1}), solved by the
    Thomas algorithm (diagonally dominant: no pivoting needed).

    >>> [round(float(v), 12) for v in spline_moments((0.0, 1.0), (0.0, 1.0))]
    [6.0, -6.0]
    """
    n = len(x)
    hs = np.diff(np.asarray(x, dtype=float))
    d = np.diff(np.asarray(f, dtype=float)) / hs
    lo, di, up, rhs = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
    di[0], up[0], rhs[0] = 2.0 * hs[0], hs[0], 6.0 * d[0]
    di[-1], lo[-1], rhs[-1] = 2.0 * hs[-1], hs[-1], -6.0 * d[-1]
    for i in range(1, n - 1):
        lo[i], di[i], up[i], rhs[i] = hs[i - 1], 2.0 * (hs[i - 1] + hs[i]), hs[i], 6.0 * (d[i] - d[i - 1])
    for i in range(1, n):                      # forward elimination
        m = lo[i] / di[i - 1]
        di[i] -= m * up[i - 1]
        rhs[i] -= m * rhs[i - 1]
    out = np.zeros(n)
    out[-1] = rhs[-1] / di[-1]
    for i in range(n - 2, -1, -1):
        out[i] = (rhs[i] - up[i] * out[i + 1]) / di[i]
    return out


def table_law(points: tuple[tuple[float, float], ...]) -> Law:
    """The clamped cubic spline through ``points`` (see the module docstring)."""
    xs = tuple(float(p[0]) for p in points)
    fs = tuple(float(p[1]) for p in points)
    if xs[0] != 0.0 or xs[-1] != 1.0:
        raise NotAMechanism(f"points: x must run from 0 to 1 (the normalised cam angle), got {xs[0]:g} … {xs[-1]:g}")
    for i in range(1, len(xs)):
        if not xs[i] > xs[i - 1]:
            raise NotAMechanism(f"points[{i}]: x = {xs[i]:g} must be greater than x = {xs[i - 1]:g} before it")
    if abs(fs[0]) > END_TOL or abs(fs[-1] - 1.0) > END_TOL:
        raise NotAMechanism(f"points: f must run from 0 to 1 (normalised displacement), got {fs[0]:g} … {fs[-1]:g}")
    M = tuple(spline_moments(xs, fs).tolist())
    rows = [(xs[i], xs[i + 1] - xs[i], fs[i], fs[i + 1], M[i], M[i + 1]) for i in range(len(xs) - 1)]
    starts = list(xs[:-1])

    def row(x: float):
        return rows[min(max(bisect_right(starts, x) - 1, 0), len(rows) - 1)]

    def fn1(x: float) -> tuple[float, float, float]:
        x0, h, f0, f1, m0, m1 = row(x)
        a, b = (x0 + h - x) / h, (x - x0) / h
        s = a * f0 + b * f1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0
        v = (f1 - f0) / h + ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1) * h / 6.0
        return s, v, a * m0 + b * m1

    def fn3(x: float) -> float:
        _, h, _, _, m0, m1 = row(x)
        return (m1 - m0) / h

    cols = [np.array(c, dtype=float) for c in zip(*rows)]
    arr = np.array(starts)

    def fn(x):                                 # fn1's operations on an array, each point's interval gathered
        xa = np.asarray(x, dtype=float)
        i = np.clip(np.searchsorted(arr, xa, side="right") - 1, 0, len(rows) - 1)
        x0, h, f0, f1, m0, m1 = (c[i] for c in cols)
        a, b = (x0 + h - xa) / h, (xa - x0) / h
        s = a * f0 + b * f1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0
        v = (f1 - f0) / h + ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1) * h / 6.0
        return s, v, a * m0 + b * m1

    return _finish("table", "列表(三次样条)运动规律", fn1, fn3, tuple(xs[1:-1]), tuple(zip(xs, fs)), fn=fn)


def _numbers(value: Any, where: str, count: int) -> tuple[float, ...]:
    """A list of at most ``count`` finite numbers, each |x| ≤ :data:`NUMBER_MAX` (booleans and strings
    refused)."""
    if not isinstance(value, (list, tuple)) or not value:
        raise NotAMechanism(f"{where} must be a non-empty list of numbers")
    if len(value) > count:
        raise NotAMechanism(f"{where} has {len(value)} entries; at most {count}")
    out = []
    for i, v in enumerate(value):
        if type(v) not in (int, float) or not math.isfinite(v) or abs(v) > NUMBER_MAX:
            raise NotAMechanism(f"{where}[{i}] must be a finite number of size ≤ {NUMBER_MAX:g}, got {v!r}"[:200])
        out.append(float(v))
    return tuple(out)


@lru_cache(maxsize=256)
def _cached(name: str, params: tuple) -> Law:
    return poly_law(params) if name == "poly" else table_law(params)


def custom_law(name: str, table: Mapping[str, Any], where: str = "law") -> Law:
    """A parametrised law (``poly`` with ``coefficients``, ``table`` with ``points``) from a program
    segment's table, its numbers validated (sizes limited: :data:`MAX_COEFFICIENTS`, :data:`MAX_POINTS`);
    the same numbers give the same (cached) law."""
    key = PARAM_KEY[name]
    if key not in table:
        raise NotAMechanism(f"{where}: law = \"{name}\" needs {key}")
    if name == "poly":
        params = _numbers(table[key], f"{where}.{key}", MAX_COEFFICIENTS)
    else:
        raw = table[key]
        if not isinstance(raw, (list, tuple)) or not 2 <= len(raw) <= MAX_POINTS:
            raise NotAMechanism(f"{where}.{key} must be a list of 2 to {MAX_POINTS} points [x, f]")
        params = tuple(_numbers(p, f"{where}.{key}[{i}]", 2) for i, p in enumerate(raw))
        if any(len(p) != 2 for p in params):
            raise NotAMechanism(f"{where}.{key}: every point is [x, f]")
    try:
        return _cached(name, params)
    except NotAMechanism as exc:
        raise NotAMechanism(f"{where}: {exc}") from None


__all__ = ["HANDBOOK_LAWS", "custom_law", "poly_law", "table_law", "spline_moments", "law"]
