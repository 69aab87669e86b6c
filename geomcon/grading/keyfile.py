"""What grading reads: a worksheet's ``key.json`` (every student's variant) or one problem file (the same
variant for every row), as answer columns with expected values, tolerances and points.

A key is a file given on the command line, so it is checked like any input: at most :data:`MAX_KEY_BYTES`,
standard JSON of the shape ``geomcon worksheet`` writes, each answer's ``value`` a number (or ``[x, y]``),
``tol`` ≥ 0, ``points`` ≥ 0. Expected values and tolerances are kept as the decimals written in the file
(:class:`decimal.Decimal`), so a boundary is decided on the numbers the teacher sees.

For a problem file the columns are the recipe's numeric answers; the tolerance is the drafting tolerance
(:mod:`geomcon.worksheet.drafting`) at the largest standard scale at which the construction fits an A4
sheet, as a worksheet would draw it; each answer is worth 1 point.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass
from decimal import Decimal
from pathlib import Path
from typing import Any, Mapping

from ..errors import GeomconError, ProblemError
from ..problems import one_line_title, title_in
from ..recipes import get_recipe
from ..worksheet.spec import AnswerRef, _answer_ref

MAX_KEY_BYTES = 64 * 2 ** 20


@dataclass(frozen=True)
class Answer:
    """One graded answer of one variant: its column (``1.AB`` or ``AB``), exercise number, reference, expected
    value (a float or an (x, y) point) and its decimal text, tolerance, points."""

    column: str
    n: int
    ref: AnswerRef
    expected: float | tuple[float, float]
    exact: Decimal | None
    tol: float
    tol_exact: Decimal
    points: float

    @property
    def unit(self) -> str:
        """``mm``, ``deg``, ``""`` (a ratio) or ``point``."""
        return "point" if isinstance(self.expected, tuple) else self.ref.unit


@dataclass(frozen=True)
class ExerciseKey:
    """One exercise of one variant: recipe, raw givens, answers in ask order, the teacher's diagnoses."""

    n: int
    recipe: str
    given: Mapping[str, Any]
    answers: tuple[Answer, ...]
    diagnose: Mapping[str, tuple[Mapping[str, str], ...]]
    statement: str = ""


@dataclass(frozen=True)
class StudentKey:
    """A student's variant: id, name, variant code, exercises."""

    id: str
    name: str
    variant: str
    exercises: tuple[ExerciseKey, ...]

    def answer(self, column: str) -> Answer | None:
        """The answer of ``column`` (None when this variant has no such column)."""
        for ex in self.exercises:
            for a in ex.answers:
                if a.column == column:
                    return a
        return None


@dataclass(frozen=True)
class Key:
    """A loaded key: title, language of the sheet, the columns in key order, the students by id (a problem
    file's one variant under the id ``*``, used for every row), where it came from and the Chinese title (the
    spec's or problem's ``title_zh``; "" when it has none)."""

    title: str
    lang: str
    columns: tuple[str, ...]
    students: Mapping[str, StudentKey]
    source: str
    title_zh: str = ""

    def heading(self, lang: str | None = None) -> str:
        """The title in ``lang`` (the key's own language by default) on one line, as the pages made from the key
        print it (:func:`~geomcon.problems.title_in`: ``both`` is English, two spaces, Chinese; ``zh`` falls
        back to the English title when there is no Chinese one).

        >>> k = Key("Guide bar", "both", (), {}, "key", "导杆机构")
        >>> k.heading(), k.heading("zh"), k.heading("en")
        ('Guide bar  导杆机构', '导杆机构', 'Guide bar')
        """
        return one_line_title(title_in(self.title, self.title_zh, self.lang if lang is None else lang))

    def variant_of(self, ident: str) -> StudentKey | None:
        """The variant a row with id ``ident`` is graded against."""
        if "*" in self.students:
            return self.students["*"]
        return self.students.get(ident)


def _bad(what: str) -> ProblemError:
    return ProblemError(f"not a geomcon key: {what}")


def _dec(x: Any, where: str, *, minimum: float | None = None) -> Decimal:
    if isinstance(x, bool) or not isinstance(x, (int, Decimal)) or not Decimal(x).is_finite():
        raise _bad(f"{where} must be a number, got {str(x)[:40]!r}")
    d = Decimal(x)
    if minimum is not None and d < minimum:
        raise _bad(f"{where} must be ≥ {minimum:g}, got {d}")
    return d


def _floats(v: Any) -> Any:
    """Givens as :func:`json.loads` gives them without ``parse_float=Decimal``."""
    if isinstance(v, Decimal):
        return float(v)
    if isinstance(v, dict):
        return {k: _floats(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_floats(x) for x in v]
    return v


def key_from_json(text: str) -> Key:
    """A key from ``key.json``'s text.

    Raises
    ------
    ProblemError
        Not JSON, or not of the shape ``geomcon worksheet`` writes (naming what is wrong).
    """
    try:
        data = json.loads(text, parse_float=Decimal)
    except (ValueError, RecursionError) as exc:
        raise ProblemError(f"not JSON: {str(exc)[:120]}") from None
    if not isinstance(data, dict) or not isinstance(data.get("students"), list):
        raise _bad("no 'students' list")
    diag: dict[int, Mapping[str, Any]] = {}
    for ex in data.get("exercises", []) or []:
        if isinstance(ex, dict) and isinstance(ex.get("diagnose"), dict):
            diag[ex.get("n")] = ex["diagnose"]
    lang = data.get("lang", "en") if data.get("lang") in ("en", "zh", "both") else "en"
    students: dict[str, StudentKey] = {}
    columns: list[str] = []
    for i, s in enumerate(data["students"]):
        where = f"students[{i}]"
        if not isinstance(s, dict) or not isinstance(s.get("id"), str) or not isinstance(s.get("exercises"), list):
            raise _bad(f"{where} needs an 'id' text and an 'exercises' list")
        exs = []
        for j, e in enumerate(s["exercises"]):
            at = f"{where}.exercises[{j}]"
            if not isinstance(e, dict) or not isinstance(e.get("answers"), dict) or not isinstance(e.get("n"), int) \
                    or not isinstance(e.get("recipe"), str):
                raise _bad(f"{at} needs 'n', 'recipe' and 'answers'")
            try:
                recipe = get_recipe(e["recipe"])
            except GeomconError as exc:
                raise _bad(f"{at}: {exc}") from None
            answers = []
            for name, a in e["answers"].items():
                aw = f"{at}.answers.{name}"
                if not isinstance(a, dict):
                    raise _bad(f"{aw} must be an object")
                v = a.get("value")
                try:
                    if isinstance(v, list) and name in {q.name for q in recipe.answers}:
                        ref = AnswerRef(name, name, None, "point")        # a point, graded by distance
                    else:
                        ref = _answer_ref(recipe, name, aw)
                except ProblemError as exc:
                    raise _bad(str(exc)) from None
                if isinstance(v, list) and len(v) == 2:
                    pt = (float(_dec(v[0], aw + ".value[0]")), float(_dec(v[1], aw + ".value[1]")))
                    expected, exact = pt, None
                else:
                    exact = _dec(v, aw + ".value")
                    expected = float(exact)
                tol = _dec(a.get("tol"), aw + ".tol", minimum=0)
                pts = _dec(a.get("points", 1), aw + ".points", minimum=0)
                col = f"{e['n']}.{name}"
                answers.append(Answer(col, e["n"], ref, expected, exact, float(tol), tol, float(pts)))
                if col not in columns:
                    columns.append(col)
            st = e.get("statement")
            text = st.get("zh" if lang == "zh" else "en", "") if isinstance(st, dict) else ""
            exs.append(ExerciseKey(e["n"], recipe.name, _floats(e.get("given")) if isinstance(e.get("given"), dict) else {},
                                   tuple(answers), diag.get(e["n"], {}), text if isinstance(text, str) else ""))
        if s["id"] in students:
            raise _bad(f"{where}: the id {s['id'][:40]!r} appears twice")
        students[s["id"]] = StudentKey(s["id"], str(s.get("name", ""))[:200], str(s.get("variant", ""))[:64], tuple(exs))
    title = data.get("title") if isinstance(data.get("title"), str) else ""
    zh = data.get("title_zh") if isinstance(data.get("title_zh"), str) else ""
    return Key(title, lang, tuple(columns), students, "key", zh)


def key_from_problem(path: str | Path) -> Key:
    """A key from one problem file: every numeric answer of its recipe, drafting tolerance at the largest
    standard scale fitting A4 (see the module), 1 point each.

    Raises
    ------
    GeomconError
        The problem's own refusal.
    """
    from ..check import rounded
    from ..paper import PAPERS, best_fit
    from ..problems import load_problem
    from ..solve import solve
    from ..worksheet.accept import FIGURE_MARGIN, TEXT_BAND
    from ..worksheet.drafting import tolerances
    from ..worksheet.readability import extent
    from ..worksheet.spec import _SCALAR

    problem = load_problem(path)
    sol = solve(problem)
    recipe = get_recipe(problem.recipe)
    refs, nominal = [], {}
    answers = sol.answers
    for q in recipe.answers:
        v = answers.get(q.name)
        if q.unit in _SCALAR and isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v):
            ref = AnswerRef(q.name, q.name, None, q.unit)
            refs.append(ref)
            nominal[q.name] = float(v)
    box = extent(sol, [r.name for r in refs])
    try:
        scale, _ = best_fit((box[2] - box[0], box[3] - box[1]), PAPERS["A4"], TEXT_BAND, margin=FIGURE_MARGIN)
        factor = scale.factor
    except ValueError:
        factor = 1.0
    # the problem's givens as written: a default filled in by validation (a cam's at = ()) is not a given, and an
    # empty list would be refused when the drafting tolerance solves the problem again
    given = {k: v for k, v in problem.given.items() if v != ()}
    tols = tolerances(recipe.name, given, refs, nominal, factor)
    out = []
    for r in refs:
        exact = Decimal(repr(rounded(nominal[r.name], sol.unit_scale(r.unit))))
        t = Decimal(f"{tols[r.name]:.2g}")
        out.append(Answer(r.name, 1, r, float(exact), exact, float(t), t, 1.0))
    ex = ExerciseKey(1, recipe.name, given, tuple(out), {}, problem.statement if isinstance(problem.statement, str) else "")
    return Key(problem.title or problem.id, "en", tuple(a.column for a in out),
               {"*": StudentKey("*", "", "", (ex,))}, "problem", problem.title_zh)


def load_key(path: str | Path) -> Key:
    """``key.json`` or a problem file (``.toml``).

    Raises
    ------
    GeomconError
        An unusable key (naming what is wrong).
    """
    p = Path(path)
    if p.suffix.lower() == ".toml":
        return key_from_problem(p)
    try:
        if not p.is_file():
            raise ProblemError("not a regular file")
        if p.stat().st_size > MAX_KEY_BYTES:
            raise ProblemError(f"larger than {MAX_KEY_BYTES // 2 ** 20} MiB")
        text = p.read_bytes().decode("utf-8-sig")
    except OSError as exc:
        raise ProblemError(f"cannot read: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise ProblemError("not UTF-8") from None
    return key_from_json(text)


__all__ = ["Answer", "ExerciseKey", "Key", "MAX_KEY_BYTES", "StudentKey", "key_from_json", "key_from_problem",
           "load_key"]
