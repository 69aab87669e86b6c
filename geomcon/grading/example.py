"""A synthetic class's answers made from a key, for the gallery's graded example and the benchmark: each
student answers each question one of ten ways in turn (exactly, rounded, within and just outside tolerance,
with the first diagnosed mistake of the variant, in centimetres, with a decimal comma, blank, garbage), so
every verdict and several diagnoses occur. Deterministic: the same key gives the same bytes.

Examples
--------
>>> from geomcon.grading.keyfile import key_from_problem
>>> text = synthetic_answers(key_from_problem("problems/001-08_crank_rocker.toml"), rows=3)
>>> text.splitlines()[0][:30]
'id,name,theta,psi,K,gamma_min,'
"""
from __future__ import annotations

import csv
import io
from typing import Any

from .diagnosis import Prepared, prepare
from .keyfile import Answer, Key

CLASS_SPEC = '''# A worksheet spec for the grading tests and the gallery's graded example: design by K, extremes, a cam.
title = "Grading example — linkages and a cam"
title_zh = "评分示例——连杆机构与凸轮"
seed = 13

[[exercise]]
recipe = "crank_rocker.design_by_K"
ask = ["AB", "AD"]
points = [3, 3]
[exercise.given]
K = [1.25, 1.4, 1.5]
CD = {min = 60, max = 120, step = 5}
psi = 40
BC = {min = 50, max = 150, step = 5}
[exercise.diagnose]
AD = {code = "AC2_for_AD", expr = "AB + BC", en = "AC2 (= AB + BC) measured instead of AD", zh = "把 AC2(= AB + BC)当作了 AD"}

[[exercise]]
recipe = "crank_rocker.extremes"
ask = ["theta", "K", "psi", "gamma_min"]
points = [2, 1, 2, 2]
[exercise.given]
AB = {min = 20, max = 40, step = 5}
BC = {min = 60, max = 90, step = 5}
CD = {min = 50, max = 80, step = 5}
AD = {min = 70, max = 100, step = 5}
[exercise.require]
gamma_min = {min = 30}
[exercise.tol]
K = {abs = 0.02}

[[exercise]]
recipe = "cam.translating"
ask = ["rho_min_actual", "alpha_max_rise"]
max_tol_rel = 0.1
[exercise.given]
follower = "roller"
r0 = {min = 40, max = 60, step = 5}
e = [8, 10, 12]
rr = 10
h = {min = 15, max = 25, step = 5}
program = [{kind = "rise", angle = 120, law = ["cosine", "cycloidal"]}, {kind = "dwell", angle = 60},
           {kind = "return", angle = 90, law = "cycloidal"}, {kind = "dwell", angle = 90}]
'''
"""The worksheet spec of the gallery's graded example and of the grading tests: a design by K with a
teacher's diagnosis, extremes with a tolerance rule for K, a roller cam."""
WAYS = ("exact", "two_decimals", "inside", "mistake", "exact", "outside", "centimetres", "comma", "blank", "garbage")


def _cell(a: Answer, way: str, alt_value: float | None) -> str:
    e = a.expected
    if isinstance(e, tuple):
        return f"{e[0]:.3f}, {e[1]:.3f}" if way != "blank" else ""
    if way == "exact":
        return repr(e)
    if way == "two_decimals":
        return f"{e:.2f}" if abs(round(e, 2) - e) <= a.tol else repr(e)
    if way == "inside":
        return repr(e + 0.5 * a.tol)
    if way == "outside":
        return repr(e + 1.5 * a.tol + 1e-6 * max(abs(e), 1.0))
    if way == "mistake":
        return repr(alt_value) if alt_value is not None else repr(e)
    if way == "centimetres":
        return f"{e / 10:.5f} cm" if a.unit == "mm" else f"{e:.4f}"
    if way == "comma":
        return f"{e:.4f}".replace(".", ",")
    if way == "blank":
        return ""
    return "n/a"


def synthetic_answers(key: Key, *, rows: int | None = None, ids: list[str] | None = None,
                      cache: dict[tuple[str, int], Prepared] | None = None) -> str:
    """The answers file's text (UTF-8, comma separated): one row per student of the key (or ``rows`` rows
    cycling through them, or the given ``ids``), every answer column. A variant's mistakes are those of
    :func:`.diagnosis.prepare`, computed once per variant and exercise (in ``cache`` when one is given, keyed
    as :func:`geomcon.grading.grade` keys them: grading a worksheet key's answers needs the very same; a
    problem key's grading prepares only the columns a file has, so share no cache there)."""
    prepared = cache if cache is not None else {}
    students = list(key.students.values())
    if ids is None:
        n = rows if rows is not None else len(students)
        ids = [students[i % len(students)].id if key.source == "key" else str(i + 1) for i in range(n)]
    first: dict[tuple[str, int], dict[str, float | None]] = {}
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["id", "name"] + list(key.columns))
    for i, sid in enumerate(ids):
        s = key.variant_of(sid)
        row = [sid, f"student {sid}"]
        for j, col in enumerate(key.columns):
            a = s.answer(col) if s is not None else None
            if a is None:
                row.append("")
                continue
            k = (s.variant or s.id, a.n)
            if k not in first:
                if k not in prepared:
                    prepared[k] = prepare(next(e for e in s.exercises if e.n == a.n))
                p = prepared[k]
                first[k] = {c: next((x.value for x in alts if x.code not in ("scale", "sign", "swapped")), None)
                            for c, alts in p.alts.items()}
            row.append(_cell(a, WAYS[(i + 3 * j) % len(WAYS)], first[k].get(col)))
        w.writerow(row)
    return buf.getvalue()


def judged(key: Key, assignment: Any) -> dict[tuple[str, int], Prepared]:
    """Every variant of ``key`` prepared for grading (:func:`.diagnosis.prepare`) from the solution that judging
    it for the worksheet built (``assignment``: the :class:`~geomcon.worksheet.assign.Assignment` the key was
    written from), keyed as :func:`geomcon.grading.grade` keys them: each variant is solved once, for the key,
    the answers, the grades and the Moodle bank's givens figures."""
    out: dict[tuple[str, int], Prepared] = {}
    for student, row in zip(assignment.students, assignment.variants):
        s = key.students[student.id]
        for ex, acc in zip(s.exercises, row):
            k = (s.variant or s.id, ex.n)
            if k not in out:
                out[k] = prepare(ex, acc.solved.sol if acc.solved is not None else None)
    return out


def gallery_files(students: int = 8) -> dict[str, str]:
    """The gallery's graded example: the key of :data:`CLASS_SPEC` for ``students`` students, a synthetic
    class's answers, the grades (CSV and JSON), the class report, one student's feedback and the Moodle bank."""
    from . import grade
    from .answers import read_answers
    from .feedback import feedback_text
    from .keyfile import key_from_json
    from .moodle import moodle_xml
    from .report import report_html
    from .tables import grades_csv, grades_json
    from ..worksheet import key_and_assignment
    from ..worksheet.roster import numbered
    from ..worksheet.spec import parse_spec

    key_text, assignment = key_and_assignment(parse_spec(CLASS_SPEC), numbered(students))   # its pages not shown
    key = key_from_json(key_text)
    # each variant's mistakes, computed once for answers, grades and bank, from the solution judging it built
    prepared = judged(key, assignment)
    answers = synthetic_answers(key, cache=prepared)
    book = grade(key, read_answers(answers.encode()), cache=prepared)
    return {"grading_key.json": key_text, "grading_answers.csv": answers, "grading_grades.csv": grades_csv(book),
            "grading_grades.json": grades_json(book), "grading_report.html": report_html(book),
            "grading_feedback_2.txt": feedback_text(book.rows[1], key.title, key.lang, key.title_zh),
            "grading_bank.xml": moodle_xml(key, cache=prepared)}


__all__ = ["CLASS_SPEC", "WAYS", "gallery_files", "judged", "synthetic_answers"]
