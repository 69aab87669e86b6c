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
    kink, where the maximum is the crossing of two branches).

    ``f`` is a function (the same value for the same argument), so a search whose state (bracket, inner
    points, their values) comes back to the one of two steps before repeats those two steps to the end;
    the bracket only ever shrinks, so it no longer moves, and the search stops there with the result of
    running every step (a search to ``width = 0`` ends in such a cycle between adjacent floats after some
    80 of its steps).

    >>> maximise(lambda t: -abs(t - 0.3), 0.0, 1.0, width=0.0, iterations=400) == maximise(
    ...     lambda t: -abs(t - 0.3), 0.0, 1.0, width=0.0, iterations=401)
    True
    """
    x1, x2 = hi - _GOLD * (hi - lo), lo + _GOLD * (hi - lo)
    f1, f2 = f(x1), f(x2)
    before = last = None
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
        state = (lo, hi, x1, x2, f1, f2)
        if state == before:                  # a cycle of two steps (lo, hi fixed): every further step repeats it
            break
        before, last = last, state
    return (lo + hi) / 2


def crossing(keep: Callable[[float], bool], a: float, b: float, *, iterations: int = 200) -> float:
    """The point between ``a`` and ``b`` where ``keep`` stops holding, by bisection (``keep(a)`` is the side
    that holds; a and b may be in either order). A step that leaves the ends as they were (the midpoint rounds
    onto one) ends the search: every further step would repeat it.

    >>> crossing(lambda t: t < 0.1, 0.0, 1.0) == crossing(lambda t: t < 0.1, 0.0, 1.0, iterations=1000)
    True
    """
    side = keep(a)
    for _ in range(iterations):
        m = (a + b) / 2
        if keep(m) == side:
            if a == m:
                break
            a = m
        else:
            if b == m:
                break
            b = m
    return (a + b) / 2
