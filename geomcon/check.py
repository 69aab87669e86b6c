"""Construction against analytic twin, and the audit of published (printed) answers.

Examples
--------
>>> check_row("theta", 12.5055860934, 12.5055860934, 1.0)["ok"]
True
>>> audit_row("theta", 12.5, 12.5055860934)["deviation"]
-0.0055860934
>>> rounded(12.50558609341234, 1.0), rounded(3.1e-15, 1.0), rounded(1234567.891234567891, 100.0)
(12.5055860934, 0.0, 1234567.89123)
"""
from __future__ import annotations

import math
from typing import Callable

from .tolerance import CHECK_REL

DIGITS = 12
"""Significant digits of every number geomcon writes, counted at the scale of the quantity (see
:func:`rounded`): last-bit differences between CPUs and library versions never reach a file."""

NOISE_REL = 1e-12
"""Differences below this fraction of the compared magnitude are floating-point noise (they differ between
CPUs): a check's ``abs_error`` under it is written as 0."""

PUBLISHED_WARN_REL = 0.03
"""Published answers are drawn by hand: a deviation beyond 3 % is reported as a warning."""


def scale_for(unit: str, length_scale: float, omega: float = 1.0) -> float:
    """The value below which relative comparison is replaced by an absolute one: the problem's length scale
    for lengths, length scale × |ω| for speeds (mm/s) and × ω² for accelerations (mm/s²), |ω| and ω² for
    angular velocities and accelerations (rad/s, rad/s²), 1 for angles (degrees) and ratios.

    Examples
    --------
    >>> scale_for("mm", 90.0), scale_for("deg", 90.0), scale_for("mm/s", 90.0, 2.0)
    (90.0, 1.0, 180.0)
    """
    if unit in ("mm", "interval"):
        return length_scale
    if unit == "mm/s":
        return length_scale * abs(omega)
    if unit == "mm/s²":
        return length_scale * omega * omega
    if unit == "rad/s":
        return abs(omega)
    if unit == "rad/s²":
        return omega * omega
    return 1.0


def rounded(x: float, scale: float) -> float:
    """``x`` to :data:`DIGITS` significant digits of ``max(|x|, scale)``: a length of 1e-15 mm in a linkage of
    100 mm is 0, a length of 1234.5 keeps 12 digits.

    Examples
    --------
    >>> rounded(-1e-17, 1.0), rounded(2.0 / 3.0, 1e-6)
    (0.0, 0.666666666667)
    """
    if x == 0 or not math.isfinite(x):
        return 0.0 if x == 0 else x
    m = max(abs(x), abs(scale))
    decimals = DIGITS - 1 - math.floor(math.log10(m))
    if 0 <= decimals <= 300:
        # round() takes the digits of f"{x:.{decimals}f}" (the same correctly rounded conversion, read back
        # the same way) without the text: the same float at half the cost (up to 323 decimals; beyond 300
        # the text below)
        return round(x, decimals) + 0.0                 # never -0.0
    out = float(f"{x:.{decimals}f}") if decimals >= 0 else float(f"{x:.{DIGITS}g}")
    return out + 0.0                                    # never -0.0


def rounder(scale: float) -> Callable[[float], float]:
    """``x ↦ rounded(x, scale)`` for many x at one scale: the digits kept are fixed by ``scale`` alone for
    every |x| ≤ |scale| (a table column, a plot's curve), worked out once here; a larger x goes through
    :func:`rounded`. The same floats as :func:`rounded`.

    >>> r = rounder(100.0)
    >>> [r(x) for x in (1.0 / 3.0, -0.0, 123456.789012345678)] == [rounded(x, 100.0) for x in (1.0 / 3.0, -0.0, 123456.789012345678)]
    True
    """
    s = abs(scale)
    if not (0.0 < s < math.inf):
        return lambda x: rounded(x, scale)
    decimals = DIGITS - 1 - math.floor(math.log10(s))
    if not 0 <= decimals <= 300:
        return lambda x: rounded(x, scale)

    def one(x: float) -> float:
        if -s <= x <= s:                    # max(|x|, |scale|) is |scale|: its decimals (0 and -0.0 give 0.0)
            return round(x, decimals) + 0.0
        return rounded(x, scale)

    return one


def error_text(err: float, magnitude: float) -> float:
    """An ``abs_error`` as written: 0 below the noise floor (:data:`NOISE_REL` of ``magnitude``), else two
    significant digits.

    Examples
    --------
    >>> error_text(3.55e-15, 12.5), error_text(2.4e-9, 12.5)
    (0.0, 2.4e-09)
    """
    if not math.isfinite(err) or err > NOISE_REL * magnitude:
        return float(f"{err:.2g}")
    return 0.0


def check_row(quantity: str, construction: float, analytic: float, scale: float, unit: str | None = None) -> dict:
    """One row of ``checks``: construction vs analytic to ``CHECK_REL`` of ``max(|a|, |b|, scale)`` (``tol``,
    the absolute error allowed; the solver may widen it by the problem's condition); with ``unit``, the row
    ends with it (a solution's rows say the unit of each quantity).

    >>> check_row("K", 1.5, 1.5, 1.0, "")["unit"], list(check_row("K", 1.5, 1.5, 1.0))[-1]
    ('', 'ok')
    """
    err = abs(construction - analytic)
    tol = CHECK_REL * max(abs(construction), abs(analytic), scale)
    if unit is None:
        return {"quantity": quantity, "construction": construction, "analytic": analytic, "abs_error": err,
                "tol": tol, "ok": math.isfinite(err) and err <= tol}
    return {"quantity": quantity, "construction": construction, "analytic": analytic, "abs_error": err,
            "tol": tol, "ok": math.isfinite(err) and err <= tol, "unit": unit}


def audit_row(quantity: str, published: float, exact: float, scale: float = 1.0) -> dict:
    """One row of ``published``: the printed value, the exact one and the deviation (both at the quantity's
    scale, :func:`rounded`); ``rel_deviation`` is None where the exact value is 0 or the ratio not finite;
    ``doubtful`` when the printed value is off by more than drafting accuracy (:data:`PUBLISHED_WARN_REL`, or
    at all where the exact value is 0).

    >>> audit_row("theta", 25.0, 12.5055860934)["doubtful"], audit_row("theta", 12.6, 12.5055860934)["doubtful"]
    (True, False)
    """
    exact = rounded(exact, scale)
    dev = rounded(published - exact, scale)
    rel = dev / abs(exact) if exact != 0 else None
    rel = rel if rel is not None and math.isfinite(rel) else None
    return {
        "quantity": quantity,
        "published": published,
        "exact": exact,
        "deviation": dev,
        "rel_deviation": rel,
        "doubtful": abs(rel) > PUBLISHED_WARN_REL if rel is not None else dev != 0,
    }
