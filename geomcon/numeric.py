"""Numeric routines that act only on the function they are given, shared by constructions and analytic twins:
sharing one shares no geometry (each caller keeps its own function and its own bracket rules).

Examples
--------
>>> x = stationary(lambda t: -(t - 0.3) ** 2 * (2.0 + t), 0.305, (1e-2, 1e-3))
>>> abs(x - 0.3) < 1e-12
True
"""
from __future__ import annotations

from typing import Callable, Iterable


def stationary(f: Callable[[float], float], x: float, radii: Iterable[float]) -> float:
    """The maximum of a smooth ``f`` near ``x``, to the last digits.

    For each bracket half-width r of ``radii`` in turn (the caller's, widest first: the first in which the
    sign changes once wins): the place where f(t + h) = f(t − h) within x ± r, by bisection on the sign, for
    h = r/10, r/20, r/40, combined by Richardson's rule twice (a chord's midpoint lies O(h²) off the maximum,
    so the h² and h⁴ offsets cancel). A golden-section bracket alone holds the maximum only to √ε. Where no
    r gives three such places (a kink, or an end of the domain too near), ``x`` stays.

    Parameters
    ----------
    f : callable
        The function, smooth near its maximum.
    x : float
        A first estimate of the maximum (e.g. the middle of a golden-section bracket).
    radii : iterable of float
        The bracket half-widths to try, each wholly inside ``f``'s domain.

    Returns
    -------
    float
        The refined place of the maximum, or ``x``.

    Examples
    --------
    >>> stationary(abs, 0.0, (1e-2,))     # a minimum: no sign change f(t + h) > f(t − h) → <, x stays
    0.0
    """
    for r in radii:
        roots = []
        for h in (r / 10.0, r / 20.0, r / 40.0):
            d = lambda t, h=h: f(t + h) - f(t - h)    # noqa: E731
            lo, hi = x - r, x + r
            if not (d(lo) > 0.0 > d(hi)):
                break
            for _ in range(200):
                m = (lo + hi) / 2.0
                if m in (lo, hi):
                    break
                lo, hi = (m, hi) if d(m) > 0.0 else (lo, m)
            roots.append((lo + hi) / 2.0)
        if len(roots) == 3:
            r1, r2 = (4.0 * roots[1] - roots[0]) / 3.0, (4.0 * roots[2] - roots[1]) / 3.0
            return (16.0 * r2 - r1) / 15.0             # Richardson twice: the h² and h⁴ offsets cancel
    return x


def derivative(f: Callable[[float], float], x: float, h: float) -> float:
    """f′(x) by central differences at the steps h, h/2, h/4 combined by Richardson's rule twice (the h² and
    h⁴ terms cancel: the error is O(h⁶) plus the rounding of f over h).

    >>> import math
    >>> abs(derivative(math.sin, 0.7, 1e-2) - math.cos(0.7)) < 1e-13
    True
    """
    d = [(f(x + s) - f(x - s)) / (2.0 * s) for s in (h, h / 2.0, h / 4.0)]
    r1, r2 = (4.0 * d[1] - d[0]) / 3.0, (4.0 * d[2] - d[1]) / 3.0
    return (16.0 * r2 - r1) / 15.0


def bisect_up(f: Callable[[float], float], lo: float, hi: float) -> float:
    """The crossing of f from f(lo) < 0 to f(hi) ≥ 0 by bisection to the last bit: the end on the f ≥ 0 side.

    >>> bisect_up(lambda x: x * x - 2.0, 1.0, 2.0) ** 2 >= 2.0, abs(bisect_up(lambda x: x * x - 2.0, 1.0, 2.0) - 2 ** 0.5) < 1e-15
    (True, True)
    """
    while True:
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            return hi
        if f(mid) < 0.0:
            lo = mid
        else:
            hi = mid


def illinois(f: Callable[[float], float], lo: float, flo: float, hi: float, fhi: float, *,
             iterations: int = 200) -> float:
    """The crossing of f from flo = f(lo) < 0 to fhi = f(hi) ≥ 0 by regula falsi, Illinois variant (the value
    kept at an end that stays twice is halved): an exact root when one is hit, else the end on the f ≥ 0 side
    once the bracket is within 4e-16 of it or a trial point leaves it.

    >>> abs(illinois(lambda x: x ** 3 - 2.0, 1.0, -1.0, 2.0, 6.0) - 2 ** (1 / 3)) < 1e-15
    True
    """
    side = 0
    for _ in range(iterations):
        x = (lo * fhi - hi * flo) / (fhi - flo)
        if not lo < x < hi or hi - lo <= 4e-16 * hi:
            break
        fx = f(x)
        if fx == 0.0:
            return x
        if fx < 0.0:
            lo, flo = x, fx
            if side == -1:
                fhi /= 2.0
            side = -1
        else:
            hi, fhi = x, fx
            if side == 1:
                flo /= 2.0
            side = 1
    return hi
