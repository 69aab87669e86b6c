"""A student's cell read as a number (or a point): decimal comma, units, full-width characters.

A cell is a number with an optional unit — lengths ``mm cm m`` (converted to mm), angles ``° deg rad``
(converted to degrees); a ratio takes no unit — or, for a point answer, two numbers as ``x, y`` or
``(x; y)``. Full-width digits and signs (what a Chinese input method types) are read as ASCII (NFKC), the minus
sign U+2212 (what the sheets print) as "-". A
decimal comma is accepted where it cannot be a separator (``21,07``). An empty cell is a blank; anything
else is unreadable, with the reason.

Examples
--------
>>> read_cell("21,07 mm", "mm"), read_cell(" 2.1cm", "mm").value, read_cell("0.5 rad", "deg").value
(Cell(value=21.07, text='21.07', decimals=2), 21.0, 28.64788975654116)
>>> read_cell("(12,5; 3)", "point").value, read_cell("(−12,5; −3)", "point").value, read_cell("−0.27°", "deg")
((12.5, 3.0), (-12.5, -3.0), Cell(value=-0.27, text='-0.27', decimals=2))
>>> read_cell("", "mm") is None
True
>>> read_cell("=1+1", "mm")
Traceback (most recent call last):
...
geomcon.grading.cells.Unreadable: not a number: '=1+1'
"""
from __future__ import annotations

import math
import re
import unicodedata
from dataclasses import dataclass

MINUS = "\u2212"
"""The minus sign (what the sheets print, and what a student copies from them or a word processor types): read as
"-" (NFKC leaves it alone)."""
MAX_CELL = 200
"""Characters in a cell: a longer cell is unreadable (and is not copied whole into any output)."""

_NUM = r"[+-]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][+-]?\d{1,3})?"
_ONE = re.compile(rf"^\s*({_NUM})\s*(mm|cm|m|°|º|deg|degrees?|rad)?\s*$", re.IGNORECASE)
_POINT = re.compile(rf"^\s*\(?\s*({_NUM})\s*(?:;|,\s|\s)\s*({_NUM})\s*\)?\s*(mm)?\s*$")
_TO_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0}
_TO_DEG = {"°": 1.0, "º": 1.0, "deg": 1.0, "degree": 1.0, "degrees": 1.0, "rad": 180.0 / math.pi}


class Unreadable(ValueError):
    """A cell that is neither empty nor a number of the answer's kind."""


@dataclass(frozen=True)
class Cell:
    """A number a student wrote: its value in the answer's unit, the plain decimal text of the number as
    written (the unit dropped, a decimal point; exact, for deciding tolerance boundaries), and how many
    decimals it has (for the ``rounding`` diagnosis)."""

    value: float | tuple[float, float]
    text: str
    decimals: int


def _number(s: str) -> tuple[float, str, int]:
    s = s.replace(",", ".")
    mant = s.split("e")[0].split("E")[0]
    dec = len(mant.split(".")[1]) if "." in mant else 0
    x = float(s)
    if not math.isfinite(x):
        raise Unreadable(f"not a finite number: {s!r}")
    return x, s, dec


def shown(text: str) -> str:
    """A cell as a message quotes it: at most 40 characters."""
    return repr(text if len(text) <= 40 else text[:37] + "…")


def read_cell(raw: str, unit: str) -> Cell | None:
    """The number in ``raw`` for an answer of ``unit`` (``mm``, ``deg``, ``""`` or ``point``); None when blank.

    Raises
    ------
    Unreadable
        With the reason (too long, not a number, a unit that does not fit the answer).
    """
    if len(raw) > MAX_CELL:
        raise Unreadable(f"longer than {MAX_CELL} characters")
    s = unicodedata.normalize("NFKC", raw).replace(MINUS, "-").strip()
    if not s:
        return None
    if unit == "point":
        m = _POINT.match(s)
        if m is None:
            raise Unreadable(f"not a point 'x, y' or '(x; y)': {shown(raw)}")
        (x, tx, dx), (y, ty, dy) = _number(m.group(1)), _number(m.group(2))
        return Cell((x, y), f"{tx};{ty}", min(dx, dy))
    m = _ONE.match(s)
    if m is None:
        raise Unreadable(f"not a number: {shown(raw)}")
    x, text, dec = _number(m.group(1))
    u = (m.group(2) or "").lower()
    if u:
        if unit == "mm" and u in _TO_MM:
            factor = _TO_MM[u]
        elif unit == "deg" and (u in _TO_DEG or m.group(2) in _TO_DEG):
            factor = _TO_DEG.get(u, 1.0)
        else:
            raise Unreadable(f"unit {m.group(2)!r} does not fit an answer in {unit or 'a ratio'}: {shown(raw)}")
        if factor != 1.0:
            x = x * factor
            text = repr(x)
            dec = max(dec - round(math.log10(factor)), 0) if unit == "mm" else 12
    return Cell(x, text, dec)


__all__ = ["Cell", "MAX_CELL", "Unreadable", "read_cell", "shown"]
