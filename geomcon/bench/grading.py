"""``geomcon bench``'s grading row: a class of 100 000 rows × 6 answers graded with diagnosis (issue 13's
target: ≥ 20 000 answers per second per core).

The key is a worksheet of 40 students (design by K: AB, AD; extremes: θ, K, ψ, γmin); the answers file has
100 000 rows cycling through them (so most ids repeat and are flagged, which is part of the work), each answer
written one of the ten ways of :mod:`geomcon.grading.example` (exact, within and outside tolerance, a
diagnosed mistake, centimetres, decimal comma, blank, garbage). Timed in CPU seconds of this process: reading
the bytes, grading (each variant's alternatives prepared once: the precompute, timed apart too) and writing
grades.csv's text.

Examples
--------
>>> r = measure_grading(rows=200, students=4)
>>> r.answers, r.rows
(1200, 200)
"""
from __future__ import annotations

import time
from dataclasses import dataclass

from .report import format_table

SPEC = """
title = "bench"
seed = 5
[[exercise]]
recipe = "crank_rocker.design_by_K"
ask = ["AB", "AD"]
[exercise.given]
K = [1.25, 1.4, 1.5]
CD = {min = 60, max = 120, step = 5}
psi = 40
BC = {min = 50, max = 150, step = 5}
[[exercise]]
recipe = "crank_rocker.extremes"
ask = ["theta", "K", "psi", "gamma_min"]
[exercise.given]
AB = {min = 20, max = 40, step = 5}
BC = {min = 60, max = 90, step = 5}
CD = {min = 50, max = 80, step = 5}
AD = {min = 70, max = 100, step = 5}
"""
TARGET = 20_000.0


@dataclass(frozen=True)
class GradingRow:
    """What one grading run measured: rows, answers, CPU seconds in all and for the precompute, the
    answers per second, how many answers were diagnosed."""

    rows: int
    answers: int
    variants: int
    seconds: float
    precompute: float
    rate: float
    diagnosed: int


def measure_grading(*, rows: int = 100_000, students: int = 40) -> GradingRow:
    """Grade ``rows`` synthetic rows of a ``students``-student key (see the module)."""
    from ..grading import grade
    from ..grading.answers import read_answers
    from ..grading.diagnosis import prepare
    from ..grading.example import synthetic_answers
    from ..grading.keyfile import key_from_json
    from ..grading.tables import grades_csv
    from ..worksheet import make_key
    from ..worksheet.roster import numbered
    from ..worksheet.spec import parse_spec

    key = key_from_json(make_key(parse_spec(SPEC), numbered(students)))
    data = synthetic_answers(key, rows=rows).encode()
    t0 = time.process_time()
    cache: dict = {}
    for s in key.students.values():
        for ex in s.exercises:
            cache.setdefault((s.variant or s.id, ex.n), prepare(ex))
    t1 = time.process_time()
    book = grade(key, read_answers(data), cache=cache)
    grades_csv(book)
    t2 = time.process_time()
    n = sum(len(r.answers) for r in book.rows)
    diagnosed = sum(1 for r in book.rows for g in r.answers if g.diagnosis)
    return GradingRow(len(book.rows), n, len(cache), t2 - t0, t1 - t0, n / (t2 - t0), diagnosed)


def grading_table(r: GradingRow) -> str:
    """The printed table of the grading row."""
    head = ("grading (issue 13)", "rows × answers", "CPU s", "precompute", "answers/s per core", "target")
    row = ("read + grade with diagnosis + grades.csv", f"{r.rows} × {r.answers // max(r.rows, 1)}",
           f"{r.seconds:.2f}", f"{r.precompute:.2f} s ({r.variants} variant-exercises)", f"{r.rate:,.0f}",
           f"≥ {TARGET:,.0f} ({'met' if r.rate >= TARGET else 'SHORT'})")
    return format_table(head, [row], "lllrrl") + f"\n{r.diagnosed} of {r.answers} answers diagnosed"


__all__ = ["GradingRow", "SPEC", "TARGET", "grading_table", "measure_grading"]
