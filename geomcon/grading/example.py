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

from .diagnosis import prepare
from .keyfile import Answer, Key

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


def synthetic_answers(key: Key, *, rows: int | None = None, ids: list[str] | None = None) -> str:
    """The answers file's text (UTF-8, comma separated): one row per student of the key (or ``rows`` rows
    cycling through them, or the given ``ids``), every answer column."""
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
                ex = next(e for e in s.exercises if e.n == a.n)
                p = prepare(ex)
                first[k] = {c: next((x.value for x in alts if x.code not in ("scale", "sign", "swapped")), None)
                            for c, alts in p.alts.items()}
            row.append(_cell(a, WAYS[(i + 3 * j) % len(WAYS)], first[k].get(col)))
        w.writerow(row)
    return buf.getvalue()


__all__ = ["WAYS", "synthetic_answers"]
