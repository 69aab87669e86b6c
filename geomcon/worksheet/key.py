"""The answer key, ``key.json``, and a plain ``variants.csv``: deterministic bytes.

``key.json`` follows issue 12's contract (title, seed, geomcon's version, spec_sha256, students → exercises →
given, scale, answers {value, unit, tol, points}) and adds what grading and the sheets need: each
exercise's statement (the numbers filled, in the languages asked for), the sheet its figure is drawn on, the
variant code, the tolerance model, and per exercise the acceptance statistics. Answer values carry 12
significant digits at the scale of their quantity (:func:`geomcon.check.rounded`: lengths at the variant's
length scale, angles and ratios at 1); a tolerance carries 2 significant digits; givens are written as the spec
gives them (90, not 90.0). Students are listed in class order, exercises in spec order, answers in ``ask``
order, givens in the spec's order: no dictionary order or hash reaches the file.

``variants.csv`` has one row per student: id, name, variant code, then each exercise's scale and numeric givens
(``1.K``, ``1.CD`` …); a cell that starts with ``= + - @`` is written with a leading apostrophe, so a
spreadsheet never runs it as a formula.

Examples
--------
>>> variant_code([0, 35, 36])
'0-z-10'
>>> plain({"K": 1.25, "CD": 90.0, "program": [{"angle": 120.0, "law": "cosine"}]})
{'K': 1.25, 'CD': 90, 'program': [{'angle': 120, 'law': 'cosine'}]}
"""
from __future__ import annotations

import csv
import io
import json
from importlib import metadata
from typing import Any, Mapping, Sequence

from ..check import rounded
from ..recipes import get_recipe
from .accept import Accepted
from .assign import Assignment
from .drafting import DEGREES, PAPER_MM
from .spec import Exercise, Spec
from ..render.page import zh_punct
from .statements import CHOICE, answer_words, default_template, fill, find_sentence, shown_givens

_DIGITS36 = "0123456789abcdefghijklmnopqrstuvwxyz"
TOLERANCE_MODEL = (f"drafting: each given laid off with ±{PAPER_MM:g} mm on paper (a length, at the exercise's scale) "
                   f"or ±{DEGREES:g}° (an angle; K through θ), a rigid body's given points (a coupler's positions) "
                   "moved and turned as a body, each answer read with the same; the answer's shifts "
                   "(central differences of the solve over each drafting interval) combined root-sum-square")


def version() -> str:
    """geomcon's version as installed."""
    try:
        return metadata.version("geomcon")
    except metadata.PackageNotFoundError:        # pragma: no cover - a source tree never installed
        return "unknown"


def base36(n: int) -> str:
    """``n`` ≥ 0 in base 36 (digits 0-9, a-z)."""
    out = ""
    while True:
        n, d = divmod(n, 36)
        out = _DIGITS36[d] + out
        if n == 0:
            return out


def variant_code(indices: Sequence[int]) -> str:
    """A student's variant code: each exercise's pool index in base 36, joined by ``-`` (with the spec, enough
    to regenerate the variant: :meth:`~.spec.Exercise.given_of`)."""
    return "-".join(base36(i) for i in indices)


def plain(v: Any) -> Any:
    """A given as a teacher writes it: integral floats as integers, tuples as lists, recursively."""
    if isinstance(v, bool) or v is None or isinstance(v, (str, int)):
        return v
    if isinstance(v, float):
        return int(v) if v.is_integer() and abs(v) < 2 ** 53 else v
    if isinstance(v, Mapping):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    return v


def statement(ex: Exercise, v: Accepted, lang: str) -> str:
    """The exercise's statement for variant ``v`` in ``lang`` ("en" or "zh"): the spec's own (``{choice}``
    filled), else the recipe form's template, the sentence asking for the answers and, for a variant with
    several solutions, the sentence naming the textbook's choice."""
    given = {k: x for k, x in v.given.items() if x is not None}
    defaults = {q.name: q.default for q in get_recipe(ex.recipe).givens
                if q.name not in given and q.default is not None and q.default is not False and q.default != ()}
    k = 1 if lang == "zh" else 0
    choice = CHOICE[ex.recipe][k] if v.several and ex.recipe in CHOICE else ""
    values = {**shown_givens(ex.recipe, {**defaults, **given}, lang), "choice": choice}
    own = ex.statement.get(lang) if ex.statement is not None else None
    if own is not None:
        return zh_punct(fill(own, values)) if lang == "zh" else fill(own, values)
    template = default_template(ex.recipe, given, get_recipe(ex.recipe).title)[k]
    words = [answer_words(r.name, r.index, given, lang, ex.recipe) for r in ex.ask]
    parts = [fill(template, values), find_sentence(words, lang)] + ([choice] if choice else [])
    return zh_punct("".join(parts)) if lang == "zh" else " ".join(parts)


def _langs(lang: str) -> tuple[str, ...]:
    return ("en", "zh") if lang == "both" else (lang,)


def _answers(ex: Exercise, v: Accepted) -> dict[str, Any]:
    out = {}
    for a, pts in zip(v.answers, ex.points):
        row = {"value": rounded(a.value, a.scale), "unit": a.ref.unit, "tol": float(f"{a.tol:.2g}"),
               "points": plain(pts)}
        if ex.tol.get(a.ref.text) is not None:
            row["drafting_tol"] = float(f"{a.drafting_tol:.2g}")
            row["tol_rule"] = {ex.tol[a.ref.text].kind: plain(ex.tol[a.ref.text].value)}
        out[a.ref.text] = row
    return out


def key_data(spec: Spec, a: Assignment, *, paper: str, lang: str, seed: int | str | None) -> dict[str, Any]:
    """The key as a JSON-ready dictionary (see the module)."""
    used = spec.seed if seed is None else seed
    students = []
    held: list[dict[int, list[str]]] = [{} for _ in spec.exercises]      # per exercise: variant → ids holding it
    for s, variants in zip(a.students, a.variants):
        exercises = []
        for j, (ex, v) in enumerate(zip(spec.exercises, variants)):
            before = held[j].setdefault(v.index, [])
            exercises.append({
                "n": ex.n, "recipe": ex.recipe,
                "given": plain({k: x for k, x in v.given.items() if x is not None}),
                "scale": str(v.scale), "sheet": str(v.sheet),
                "statement": {lg: statement(ex, v, lg) for lg in _langs(lang)},
                "answers": _answers(ex, v),
                **({"shared_with": list(before)} if before else {}),
            })
            before.append(s.id)
        students.append({"id": s.id, "name": s.name, "variant": variant_code([v.index for v in variants]),
                         "exercises": exercises})
    return {
        "title": spec.title, **({"title_zh": spec.title_zh} if spec.title_zh else {}), "seed": used, "geomcon": version(), "spec_sha256": spec.sha256,
        "paper": paper, "lang": lang, "tolerance": TOLERANCE_MODEL,
        "exercises": [{"n": ex.n, "recipe": ex.recipe, "ask": [r.text for r in ex.ask], "points": plain(list(ex.points)),
                       "pool": st.pool, "judged": st.tried, "accepted": st.accepted,
                       "acceptance": float(f"{st.rate:.3g}"), "rejected": dict(st.rejected), "shared": st.shared,
                       "pool_exhausted": st.exhausted, "acceptable": st.accepted if st.exhausted else None,
                       **({"sharing": st.short()} if st.shared else {}),
                       **({"diagnose": {k: list(v) for k, v in ex.diagnose.items()}} if ex.diagnose else {})}
                      for ex, st in zip(spec.exercises, a.stats)],
        "students": students,
    }


def key_json(spec: Spec, a: Assignment, *, paper: str, lang: str, seed: int | str | None) -> str:
    """``key.json``'s text (UTF-8, two-space indents, a final newline)."""
    return json.dumps(key_data(spec, a, paper=paper, lang=lang, seed=seed), ensure_ascii=False, indent=2,
                      allow_nan=False) + "\n"


def _cell(x: Any) -> str:
    text = x if isinstance(x, str) else json.dumps(plain(x), ensure_ascii=False)
    return "'" + text if text[:1] in ("=", "+", "-", "@") else text


def variants_csv(spec: Spec, a: Assignment) -> str:
    """``variants.csv``'s text (see the module)."""
    cols: list[tuple[int, str]] = []
    for j, ex in enumerate(spec.exercises):
        names = [k for k, x in (a.variants[0][j].given.items() if a.variants else ())
                 if x is not None and not isinstance(x, (list, dict))]
        cols += [(j, "scale")] + [(j, k) for k in names]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["id", "name", "variant"] + [f"{spec.exercises[j].n}.{k}" for j, k in cols])
    for s, variants in zip(a.students, a.variants):
        row = [_cell(s.id), _cell(s.name), variant_code([v.index for v in variants])]
        for j, k in cols:
            row.append(str(variants[j].scale) if k == "scale" else _cell(variants[j].given.get(k)))
        w.writerow(row)
    return buf.getvalue()


__all__ = ["TOLERANCE_MODEL", "base36", "key_data", "key_json", "plain", "statement", "variant_code", "variants_csv",
           "version"]
