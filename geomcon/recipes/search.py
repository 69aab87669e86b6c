"""One-dimensional searches along a construction's parameter (e.g. the angle along an arc): the maximum of
a unimodal function and the place where a condition changes. Used by annotation and optimum steps; the
analytic twins keep their own, independent routes.

Examples
--------
>>> round(maximise(lambda t: -(t - 0.3) ** 2, 0.0, 1.0), 9)
0.3
>>> round(crossing(lambda t: t < 0.25, 0.0, 1.0), 12)
0.25
"""
from __future__ import annotations

import math
from typing import Callable

_GOLD = (math.sqrt(5.0) - 1.0) / 2.0


def maximise(f: Callable[[float], float], lo: float, hi: float, *, width: float = 4e-16,
             iterations: int = 200) -> float:
    """The argument of the maximum of a unimodal ``f`` on [lo, hi] by golden-section search (also exact at a
    kink, where the maximum is the crossing of two branches)."""
    x1, x2 = hi - _GOLD * (hi - lo), lo + _GOLD * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(iterations):
        if f1 < f2:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + _GOLD * (hi - lo)
            f2 = f(x2)
        else:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - _GOLD * (hi - lo)
            f1 = f(x1)
        if hi - lo <= width:
            break
    return (lo + hi) / 2


def crossing(keep: Callable[[float], bool], a: float, b: float, *, iterations: int = 200) -> float:
    """The point between ``a`` and ``b`` where ``keep`` stops holding, by bisection (``keep(a)`` is the side
    that holds; a and b may be in either order)."""
    side = keep(a)
    for _ in range(iterations):
        m = (a + b) / 2
        if keep(m) == side:
            a = m
        else:
            b = m
    return (a + b) / 2
