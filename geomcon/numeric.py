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


TURN_EPS = 1e-9
"""Degrees within which an angle of a cycle short of 360° is the cycle's start, 0° (:func:`deg360`)."""


def deg360(x: float) -> float:
    """An angle of a cycle (degrees) as a textbook states it, in [0°, 360°): a cam angle, or an angle measured
    counter-clockwise from a line; within :data:`TURN_EPS` of 360° it is 0° (the end of a return is the start
    of the next rise: 001-29 printed δ(α′max) = 360° where the textbook says 0°).

    >>> deg360(-171.561), deg360(360.0), deg360(-1e-17), deg360(359.9999999999), deg360(725.0)
    (188.439, 0.0, 0.0, 0.0, 5.0)
    """
    r = x % 360.0
    return 0.0 if 360.0 - r < TURN_EPS else r


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


EPS = 2.220446049250313e-16
"""The spacing of floats at 1 (float64's machine epsilon)."""


def brent_root(f: Callable[[float], float], a: float, b: float, fa: float | None = None, fb: float | None = None,
               *, xtol: float = 0.0, rtol: float = 4.0 * EPS, maxiter: int = 200) -> float:
    """A root of ``f`` in [a, b], where f(a) and f(b) differ in sign (or one is 0), by Brent's method.

    The algorithm is scipy.optimize.brentq's (R. P. Brent, *Algorithms for Minimization without
    Derivatives*, 1973, ch. 4, "zeroin"; scipy's ``brentq.c``): inverse quadratic interpolation through the
    last three points, or a secant, when it steps well inside the bracket and shrinks it fast enough, else a
    bisection; the bracket always holds a sign change. One safeguard more than brentq: when three steps in a
    row have not halved the bracket (a flat, multiple root, where interpolation creeps), the next step
    bisects, so the count never exceeds about three times bisection's. It is written here instead of
    depending on scipy, whose import alone costs more than a whole cam solve. The search stops when the
    bracket's half-width is below (``xtol`` + ``rtol``·|x|)/2 or f(x) = 0; with the defaults (xtol 0,
    rtol 4ε) that is within a few units of the last place of the root, in 8–12 calls of ``f`` for a smooth
    simple root.

    Parameters
    ----------
    f : callable
        The function, on floats.
    a, b : float
        The bracket's ends (either order).
    fa, fb : float, optional
        f(a) and f(b) when known (not computed again).
    xtol, rtol : float
        The absolute and relative tolerance of the root's place.
    maxiter : int
        Most calls of ``f`` after the ends.

    Returns
    -------
    float
        The root's place: the end of the last bracket with the smaller |f|.

    Raises
    ------
    ValueError
        When f(a) and f(b) have the same sign (no bracket).

    Examples
    --------
    >>> import math
    >>> abs(brent_root(math.cos, 1.0, 2.0) - math.pi / 2) < 1e-15
    True
    >>> calls = []
    >>> x = brent_root(lambda t: calls.append(t) or t ** 3 - 2.0, 0.0, 2.0)
    >>> abs(x - 2 ** (1 / 3)) < 1e-15, len(calls) <= 14
    (True, True)
    >>> brent_root(lambda t: t - 0.25, 0.25, 1.0)          # a root at an end is that end
    0.25
    """
    xpre, xcur = float(a), float(b)
    fpre = f(xpre) if fa is None else float(fa)
    fcur = f(xcur) if fb is None else float(fb)
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    if (fpre > 0.0) == (fcur > 0.0):
        raise ValueError(f"no sign change on [{a!r}, {b!r}]: f = {fpre!r}, {fcur!r}")
    xblk = fblk = spre = scur = 0.0
    width, slow = abs(xcur - xpre), 0               # the bracket's width when it last halved, steps since
    for _ in range(maxiter):
        if fpre != 0.0 and fcur != 0.0 and (fpre > 0.0) != (fcur > 0.0):
            xblk, fblk = xpre, fpre                 # the bracket is [xcur, xblk]
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):                   # xcur: the best point so far
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = 0.5 * (xtol + rtol * abs(xcur))
        sbis = 0.5 * (xblk - xcur)
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if 4.0 * abs(sbis) <= width:
            width, slow = 2.0 * abs(sbis), 0
        else:
            slow += 1
        if slow < 3 and abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:                        # secant
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:                                   # inverse quadratic interpolation
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre, scur = scur, stry             # accept the interpolation
            else:
                spre = scur = sbis                  # bisect
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0.0 else -delta)
        fcur = f(xcur)
    return xcur
