"""Answer checking (issue 13): grade a class's answers against a worksheet key or a problem file, name each
mistake by replaying the construction the wrong way, give partial and follow-through credit, and write the
gradebook, the class report, each student's feedback and a Moodle question bank.

The pieces: :mod:`.answers` reads the untrusted answers file (limits, encodings, separators, malformed rows),
:mod:`.cells` a cell (decimal comma, units, points), :mod:`.keyfile` the key, :mod:`.replay` replays a
variant's scene with a branch flipped or a step substituted, :mod:`.mistakes` holds what each recipe declares,
:mod:`.expr` a teacher's diagnosis expression, :mod:`.diagnosis` precomputes each variant's plausible wrong
values, :mod:`.credit` grades a row, :mod:`.tables` writes grades.csv and grades.json, :mod:`.feedback` the
students' feedback, :mod:`.report` report.html and :mod:`.moodle` the question bank.

Examples
--------
>>> from geomcon.grading.keyfile import key_from_problem
>>> from geomcon.grading.answers import read_answers
>>> key = key_from_problem("problems/001-08_crank_rocker.toml")
>>> book = grade(key, read_answers("id,theta,K\\n1,12.5,1.15\\n2,12.5,0.87\\n3,,x\\n".encode()))
>>> [[(g.verdict, g.diagnosis, g.points) for g in r.answers] for r in book.rows]
[[('correct', '', 1.0), ('correct', '', 1.0)], [('correct', '', 1.0), ('wrong', 'K_inverted', 0.0)], [('blank', '', 0.0), ('unreadable', '', 0.0)]]
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from .answers import Sheet
from .credit import GradedRow, grade_row
from .diagnosis import Prepared, prepare
from .keyfile import Key


@dataclass(frozen=True)
class Gradebook:
    """A graded class: the key, the graded columns (the key's, in key order, that the file has or the key
    asks), the rows in input order, and notes (ignored columns, duplicate ids, malformed rows)."""

    key: Key
    columns: tuple[str, ...]
    rows: tuple[GradedRow, ...]
    notes: tuple[str, ...]


def grade(key: Key, sheet: Sheet, *, cache: dict[tuple[str, int], Prepared] | None = None) -> Gradebook:
    """Grade every row of ``sheet`` against ``key``: each variant's alternatives are computed once (keyed by
    the variant code and exercise; in ``cache`` when one is given), however many rows it has."""
    known = set(key.columns)
    ignored = [c for c in sheet.columns if c not in known]
    columns = key.columns if key.source == "key" else tuple(c for c in key.columns if c in sheet.columns)
    prepared = cache if cache is not None else {}
    notes = [f"column {c[:40]!r} is not an answer of the key: ignored" for c in ignored]
    first: dict[str, int] = {}
    rows = []
    for row in sheet.rows:
        student = key.variant_of(row.id)
        dup = bool(row.id) and row.id in first
        if dup:
            notes.append(f"line {row.line}: id {row.id[:40]!r} repeats line {first[row.id]}")
        elif row.id:
            first[row.id] = row.line
        if row.problem:
            notes.append(row.problem)
        elif student is None:
            notes.append(f"line {row.line}: id {row.id[:40]!r} is not in the key")
        if student is not None and not row.problem:
            if key.source == "problem":
                student = _only(student, columns)
            for ex in student.exercises:
                if (student.variant or student.id, ex.n) not in prepared:
                    prepared[(student.variant or student.id, ex.n)] = prepare(ex)
        g = grade_row(row, sheet.columns, student, prepared, columns)
        rows.append(GradedRow(g.line, g.id, g.name, g.score, g.max_score, g.answers, g.problem, dup))
    return Gradebook(key, columns, tuple(rows), tuple(notes))


_ONLY: dict = {}


def _only(student, columns):
    """A problem key's variant restricted to the columns the file has (so that max_score counts only them)."""
    from dataclasses import replace

    k = (id(student), columns)
    if k not in _ONLY:
        if len(_ONLY) > 64:
            _ONLY.clear()
        exs = tuple(replace(ex, answers=tuple(a for a in ex.answers if a.column in columns)) for ex in student.exercises)
        _ONLY[k] = (student, replace(student, exercises=exs))
    return _ONLY[k][1]


__all__ = ["Gradebook", "grade"]
