"""The one tolerance policy: decisions are taken relative to the scale of the objects involved.

Every predicate that must decide "zero or not" (tangent or secant, parallel or crossing, coincident or
distinct) compares a length with ``tol(scale...)``, where the scale is the largest length that takes part.
There is no absolute floor, so a linkage drawn at 1e-3 mm and the same linkage at 1e6 mm take the same
decisions.

Examples
--------
>>> tol(100.0) == REL_TOL * 100.0
True
>>> is_zero(1e-12, 100.0), is_zero(1e-9, 100.0)
(True, False)
"""
from __future__ import annotations

import math
import sys

EPS: float = sys.float_info.epsilon
"""Machine epsilon of IEEE double, 2.22e-16."""

REL_TOL: float = 1e-13
"""Relative tolerance of every geometric decision (about 450 ulp): a gap smaller than ``REL_TOL`` times
the scene's scale counts as zero (tangency, parallelism, coincidence). Near-tangent cases with a relative
gap of 1e-12 or more are therefore still resolved as two points."""

CHECK_REL: float = 1e-9
"""Relative agreement required between a construction and its analytic twin."""


def tol(*scales: float) -> float:
    """Return the absolute tolerance for lengths of the given scales.

    Parameters
    ----------
    *scales : float
        Lengths taking part in the decision (distances, radii); their largest magnitude sets the scale.

    Returns
    -------
    float
        ``REL_TOL * max(|scale|)``.

    Examples
    --------
    >>> tol(3.0, -4.0) == 4.0 * REL_TOL
    True
    """
    return REL_TOL * max(map(abs, scales))


def is_zero(length: float, *scales: float) -> bool:
    """Tell whether ``length`` is zero at the scale of ``scales``.

    Examples
    --------
    >>> is_zero(0.0, 1.0)
    True
    """
    return abs(length) <= tol(*scales)


def agree(a: float, b: float, *, scale: float = 0.0, rel: float = CHECK_REL) -> bool:
    """Tell whether two results agree to ``rel`` relative to ``max(|a|, |b|, scale)``.

    ``scale`` keeps a comparison meaningful when the exact value is zero (an angle of 0°).

    Examples
    --------
    >>> agree(1.0, 1.0 + 1e-12), agree(0.0, 1e-12, scale=1.0), agree(1.0, 1.001)
    (True, True, False)
    """
    if not (math.isfinite(a) and math.isfinite(b)):
        return False
    return abs(a - b) <= rel * max(abs(a), abs(b), scale)
