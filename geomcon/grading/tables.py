"""``grades.csv`` and ``grades.json``: one row per input row, in input order (issue 13's column contract).

grades.csv: ``id, name, score, max_score``, then per answer column ``<col>.value, <col>.expected,
<col>.deviation, <col>.tol, <col>.verdict, <col>.diagnosis, <col>.points``. ``value`` is the number as read
(lengths in mm, angles in degrees; a point ``x;y``), or for an unreadable cell the cell as written. Any text
cell that starts with ``= + - @`` (or a tab or carriage return) is written with a leading apostrophe, so a
spreadsheet never runs it as a formula; numbers are written as numbers. grades.json holds the same, typed, with
each row's line, problems, duplicate flag and the diagnosis in words, and the notes.

Examples
--------
>>> safe("=HYPERLINK(\\"x\\")"), safe("-3.5"), safe("Li")
('\\'=HYPERLINK("x")', '-3.5', 'Li')
"""
from __future__ import annotations

import csv
import io
import json
import re
from functools import lru_cache
from typing import Any

from ..check import rounded
from . import Gradebook
from .credit import Graded

FIELDS = ("value", "expected", "deviation", "tol", "verdict", "diagnosis", "points")
_PLAIN_NUMBER = re.compile(r"^-?\d+(\.\d+)?(e-?\d+)?$")


def safe(text: str) -> str:
    """A text cell neutralised against CSV injection (see the module); a plain number is left as it is."""
    if text[:1] in ("=", "+", "-", "@", "\t", "\r") and not _PLAIN_NUMBER.match(text):
        return "'" + text
    return text


@lru_cache(maxsize=1 << 16)
def num(x: Any, scale: float = 1.0) -> str:
    """A number as the tables write it: 12 significant digits at ``scale``, integers without a point
    (memoised: a class repeats each variant's expected values, tolerances and points row after row)."""
    if x is None:
        return ""
    if isinstance(x, tuple):
        return f"{num(x[0], scale)};{num(x[1], scale)}"
    r = rounded(float(x), scale)
    return str(int(r)) if r.is_integer() and abs(r) < 1e15 else repr(r)


def _scale(g: Graded) -> float:
    e = g.expected
    if isinstance(e, tuple):
        return max(abs(e[0]), abs(e[1]), 1.0)
    return max(abs(e), 1.0) if e is not None else 1.0


def cells(g: Graded) -> list[str]:
    """The seven cells of one answer."""
    s = _scale(g)
    value = safe(g.text.strip()) if g.verdict == "unreadable" else num(g.value, s)
    return [value, num(g.expected, s), num(g.deviation, s), num(g.tol, s) if g.expected is not None else "",
            g.verdict, g.diagnosis, num(g.points)]


def grades_csv(book: Gradebook) -> str:
    """grades.csv's text (UTF-8, ``\\n`` line ends; see the module)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["id", "name", "score", "max_score"] + [f"{c}.{f}" for c in book.columns for f in FIELDS])
    for r in book.rows:
        by = {g.column: g for g in r.answers}
        row = [safe(r.id), safe(r.name), num(r.score), num(r.max_score)]
        for c in book.columns:
            row += cells(by[c]) if c in by else [""] * len(FIELDS)
        w.writerow(row)
    return buf.getvalue()


def _typed(x: Any, scale: float) -> Any:
    if x is None:
        return None
    if isinstance(x, tuple):
        return [rounded(x[0], scale), rounded(x[1], scale)]
    return rounded(float(x), scale)


def grades_data(book: Gradebook) -> dict[str, Any]:
    """grades.json as a dictionary."""
    rows = []
    for r in book.rows:
        answers = {}
        for g in r.answers:
            s = _scale(g)
            answers[g.column] = {"value": _typed(g.value, s), "text": g.text, "expected": _typed(g.expected, s),
                                 "deviation": _typed(g.deviation, s), "tol": _typed(g.tol, s), "verdict": g.verdict,
                                 "diagnosis": g.diagnosis, "points": rounded(g.points, 1.0),
                                 "max_points": rounded(g.max_points, 1.0),
                                 **({"diagnosis_en": g.en, "diagnosis_zh": g.zh} if g.en else {}),
                                 **({"unreadable": g.why} if g.why else {})}
        rows.append({"line": r.line, "id": r.id, "name": r.name, "score": rounded(r.score, 1.0),
                     "max_score": rounded(r.max_score, 1.0), "duplicate_id": r.duplicate,
                     "problem": r.problem, "answers": answers})
    return {"title": book.key.title, **({"title_zh": book.key.title_zh} if book.key.title_zh else {}),
            "source": book.key.source, "columns": list(book.columns), "rows": rows,
            "notes": list(book.notes)}


def grades_json(book: Gradebook) -> str:
    """grades.json's text."""
    return json.dumps(grades_data(book), ensure_ascii=False, indent=1, allow_nan=False) + "\n"


__all__ = ["FIELDS", "cells", "grades_csv", "grades_data", "grades_json", "num", "safe"]
