"""Grading a row: each answer's verdict, diagnosis and points, with follow-through credit.

Verdicts: ``correct`` (within tolerance), ``wrong``, ``blank`` (an empty cell), ``unreadable`` (a cell that
is not a number of the answer's kind, or a malformed row, or an id the key does not know).

Points. A correct answer earns its points. A wrong one earns a fraction of them when the diagnosis says
the construction was right and only the reading went wrong (:data:`PARTIAL`: ``rounding``, ``scale``,
``degrees_radians``, ``turn``, ``sign`` and ``swapped`` earn half), else nothing. **Follow-through**: a wrong answer
that is right given the student's own earlier answer of the same exercise (the later answer's step replayed
with the earlier step holding the student's value: K from their θ) earns its full points, diagnosis
``follow_through`` — but only when that earlier answer is itself a diagnosed mistake or lies within 3
tolerances, so that nonsense written early does not pay, and only once: an answer credited by
follow-through is never the base of another.

A boundary is decided on the decimals as written: |student − expected| ≤ tol is evaluated in decimal
arithmetic on the student's digits and the key's, so a value exactly one tolerance away is correct on every
machine.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation
from typing import Any

from .answers import Row
from .cells import Cell, Unreadable, read_cell
from .diagnosis import WORDS, Prepared, distance, match, rounding
from .keyfile import Answer, StudentKey

PARTIAL = {"rounding": 0.5, "scale": 0.5, "degrees_radians": 0.5, "turn": 0.5, "sign": 0.5, "swapped": 0.5}
"""Fraction of an answer's points a diagnosed reading slip earns (a wrong construction earns 0)."""
FOLLOW_WITHIN = 3.0
"""An undiagnosed earlier answer supports follow-through within this many of its tolerances."""
VERDICTS = ("correct", "wrong", "blank", "unreadable")


@dataclass(frozen=True)
class Graded:
    """One answer of one row, as grades.csv shows it (``value`` the student's number as read, ``text`` the
    cell as written, ``why`` the reason for an unreadable cell, ``en``/``zh`` the diagnosis in words)."""

    column: str
    value: Any
    text: str
    expected: Any
    deviation: float | None
    tol: float
    verdict: str
    diagnosis: str
    points: float
    max_points: float
    en: str = ""
    zh: str = ""
    why: str = ""


@dataclass(frozen=True)
class GradedRow:
    """A row's grades: line, id, name, score, max score, each answer, and what is wrong with the row."""

    line: int
    id: str
    name: str
    score: float
    max_score: float
    answers: tuple[Graded, ...]
    problem: str
    duplicate: bool = False


def within(cell: Cell, a: Answer) -> tuple[bool, float]:
    """(|student − expected| ≤ tol, the deviation), decided in decimals for numbers (see the module).

    >>> from geomcon.grading.keyfile import Answer
    >>> from geomcon.worksheet.spec import AnswerRef
    >>> a = Answer("AB", 1, AnswerRef("AB", "AB", None, "mm"), 0.3, Decimal("0.3"), 0.1, Decimal("0.1"), 1.0)
    >>> within(Cell(0.4, "0.4", 1), a), within(Cell(0.2, "0.2", 1), a)    # in floats 0.4 − 0.3 > 0.1
    ((True, 0.1), (True, -0.1))
    """
    if isinstance(a.expected, tuple):
        d = distance(cell.value, a.expected)
        return d <= a.tol, d
    dev = float(cell.value) - a.expected
    t = a.tol
    if abs(dev) < t * (1 - 1e-9):
        return True, dev
    if abs(dev) > t * (1 + 1e-9) + 1e-300 or a.exact is None:
        return False, dev
    try:
        exact = Decimal(cell.text) - a.exact
    except InvalidOperation:
        return abs(dev) <= t, dev
    return abs(exact) <= a.tol_exact, float(exact)


def _unreadable(a: Answer, text: str, why: str) -> Graded:
    return Graded(a.column, None, text, a.expected, None, a.tol, "unreadable", "", 0.0, a.points, why=why)


def grade_row(row: Row, columns: tuple[str, ...], student: StudentKey | None, prepared: dict[tuple[str, int], Prepared],
              all_columns: tuple[str, ...]) -> GradedRow:
    """Grade one row against its variant (``prepared``: (variant id, exercise n) → :class:`Prepared`)."""
    problem = row.problem
    if not problem and student is None:
        problem = f"line {row.line}: id {row.id[:40]!r} is not in the key"
    cells = dict(zip(columns, row.cells))
    out: list[Graded] = []
    if problem:
        for col in all_columns:
            a = student.answer(col) if student is not None else None
            out.append(_unreadable(a, cells.get(col, ""), problem) if a is not None else
                       Graded(col, None, cells.get(col, ""), None, None, 0.0, "unreadable", "", 0.0, 0.0, why=problem))
        return GradedRow(row.line, row.id, row.name, 0.0, sum(g.max_points for g in out), tuple(out), problem)
    for ex in student.exercises:
        prep = prepared[(student.variant or student.id, ex.n)]
        done: dict[str, tuple[Graded, Cell | None, Any]] = {}
        for a in ex.answers:
            raw = cells.get(a.column, "")
            try:
                cell = read_cell(raw, a.unit)
            except Unreadable as exc:
                done[a.column] = (_unreadable(a, raw, str(exc)), None, None)
                continue
            if cell is None:
                done[a.column] = (Graded(a.column, None, raw, a.expected, None, a.tol, "blank", "", 0.0, a.points),
                                  None, None)
                continue
            ok, dev = within(cell, a)
            if ok:
                g = Graded(a.column, cell.value, raw, a.expected, dev, a.tol, "correct", "", a.points, a.points)
                done[a.column] = (g, cell, None)
                continue
            alt = match(prep.alts.get(a.column, ()), cell.value)
            if alt is not None:
                pts = a.points * PARTIAL.get(alt.code, 0.0)
                g = Graded(a.column, cell.value, raw, a.expected, dev, a.tol, "wrong", alt.code, pts, a.points,
                           alt.en, alt.zh)
            elif a.unit != "point" and rounding(cell.text, cell.value, a.expected):
                en, zh = WORDS["rounding"]
                g = Graded(a.column, cell.value, raw, a.expected, dev, a.tol, "wrong", "rounding",
                           a.points * PARTIAL["rounding"], a.points, en, zh)
            else:
                g = Graded(a.column, cell.value, raw, a.expected, dev, a.tol, "wrong", "", 0.0, a.points)
            done[a.column] = (g, cell, alt)
        if prep.variant is not None:
            _follow_through(ex.answers, done, prep)
        out += [done[a.column][0] for a in ex.answers]
    score = sum(g.points for g in out)
    return GradedRow(row.line, row.id, row.name, score, sum(g.max_points for g in out), tuple(out), "")


def _follow_through(answers: tuple[Answer, ...], done: dict, prep: Prepared) -> None:
    by_col = {a.column: a for a in answers}
    for b in answers:
        g, cell, _ = done[b.column]
        if g.verdict != "wrong" or cell is None:
            continue
        for col in prep.uses.get(b.column, ()):
            base, bcell, _ = done[col]
            if base.verdict != "wrong" or bcell is None or base.diagnosis == "follow_through":
                continue
            a = by_col[col]
            if not (base.diagnosis or abs(base.deviation) <= FOLLOW_WITHIN * a.tol):
                continue
            v = prep.follow(a, float(bcell.value), b)
            if v is None or not math.isfinite(v) or distance(cell.value, v) > b.tol:
                continue
            en, zh = WORDS["follow_through"]
            done[b.column] = (Graded(b.column, g.value, g.text, g.expected, g.deviation, g.tol, "wrong", "follow_through",
                                     b.points, b.points, f"{en} {a.ref.text} = {bcell.text}",
                                     f"{zh}({a.ref.text} = {bcell.text})"), cell, None)
            break


__all__ = ["FOLLOW_WITHIN", "Graded", "GradedRow", "PARTIAL", "VERDICTS", "grade_row", "within"]
