"""Construction against analytic twin, and the audit of published (printed) answers.

Examples
--------
>>> check_row("theta", 12.5055860934, 12.5055860934, "deg", 90.0)["ok"]
True
>>> audit_row("theta", 12.5, 12.5055860934)["deviation"]
-0.0055860934
"""
from __future__ import annotations

from .tolerance import CHECK_REL, agree

PUBLISHED_WARN_REL = 0.03
"""Published answers are drawn by hand: a deviation beyond 3 % is reported as a warning."""


def scale_for(unit: str, length_scale: float) -> float:
    """The value below which relative comparison is replaced by an absolute one: 1° for angles, the
    problem's length scale for lengths, 1 for ratios."""
    return length_scale if unit == "mm" else 1.0


def check_row(quantity: str, construction: float, analytic: float, unit: str, length_scale: float) -> dict:
    """One row of ``checks``: construction vs analytic to ``CHECK_REL`` relative."""
    err = abs(construction - analytic)
    return {
        "quantity": quantity,
        "construction": construction,
        "analytic": analytic,
        "abs_error": err,
        "ok": agree(construction, analytic, scale=scale_for(unit, length_scale), rel=CHECK_REL),
    }


def audit_row(quantity: str, published: float, exact: float) -> dict:
    """One row of ``published``: the printed value, the exact one and the deviation."""
    dev = round(published - exact, 12)
    return {
        "quantity": quantity,
        "published": published,
        "exact": exact,
        "deviation": dev,
        "rel_deviation": (dev / abs(exact)) if exact != 0 else None,
    }
