"""A negative number's minus sign on sheets (U+2212): a module of its own, without svgwrite, so that a text
solve that words a warning (:mod:`geomcon.render.warning_words` → :mod:`geomcon.render.labels`) loads no drawing
library (``tests/test_startup.py``)."""
from __future__ import annotations

import re

MINUS = "\u2212"
"""A negative number's sign as a sheet prints it: U+2212 (the minus sign, as wide as "+"), not the ASCII hyphen
(a short dash: "-3.545 mm"). The JSON, the CSV, the terminal and answer files keep the hyphen."""

_MINUS = re.compile(r"(?<!\w)-(?=\.?\d)")
"""A hyphen that is a minus: right before a number (a digit, or a point and a digit) and not right after a
letter, digit or underscore (a word character, CJK included). So "= -3.5", "(-5.000, 15)", "-0.21 %" and a
text (or a subscript's following run) that begins "-229.2" get the minus; "3-4-5", "4-5-6-7", "K-2",
"000-02_slotter", "2026-11-26" and "5.1e-16" keep their hyphen."""


def minus_signs(text: str) -> str:
    """``text`` with every hyphen that is a negative number's sign (:data:`_MINUS`) printed as :data:`MINUS`.

    >>> minus_signs("min -0.2698° (textbook -1.505, -.5); 3-4-5 rise, K-2, 5.1e-16")
    'min −0.2698° (textbook −1.505, −.5); 3-4-5 rise, K-2, 5.1e-16'
    """
    return _MINUS.sub(MINUS, text) if "-" in text else text


__all__ = ["MINUS", "minus_signs"]
