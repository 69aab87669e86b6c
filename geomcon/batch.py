"""Solving many variants of one recipe in one call: answers and twin checks only, no drawing.

Worksheets solve a class set of variants, grading solves every student's givens; both need the answers (and
that each construction agreed with its twin) thousands of times. :func:`solve_batch` validates each variant's
givens exactly as a problem file's, solves it with lean, planned scenes (the recipe's evaluation plan is
learned on the first variant and reused), and collects the answers. A variant that is bad input or no
mechanism does not stop the batch: its error is reported in its place.

Once the recipe is taped (:mod:`geomcon.taped`), a variant whose givens follow a recorded path is solved
without a scene or a :class:`~geomcon.solve.Solution`: the tape's arithmetic on its givens, the compiled plan
of the answer steps (the one single solves run, shared), and the answers read as a solution reads them; the
twin checks then run on a solution holding those answers. Whatever that lane does not cover (a path not
recorded yet, a failing step, no valid candidate, a value that is not finite) is solved as one problem, which
gives its answers or words its refusal exactly as :func:`~geomcon.solve.solve` does.

Examples
--------
>>> b = solve_batch("guide_bar.extremes", [{"AB": 145, "AC": 290}, {"AB": 300, "AC": 290}])
>>> round(b.answers[0]["theta"], 9), b.ok
(60.0, [True, False])
>>> b.errors[1]
'AB = 300 ≥ AC = 290: the guide bar turns fully (rotating guide-bar), it has no extreme positions'
>>> b = solve_batch("guide_bar.extremes", {"AB": [100.0, 145.0], "AC": [200.0, 290.0]}, checks=False)
>>> [round(a["K"], 12) for a in b.answers]
[2.0, 2.0]
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

from .errors import GeomconError
from .plan import planned
from .problems import Problem, plain_validator, validate_given
from .recipes import Recipe, get_recipe
from .scene.scene import Scene
from .tolerance import CHECK_REL
from .solve import Solution, _answer_pairs, read_candidates, solve, taped_table
from .taped import replayed_construction, taped_values

BATCH_MAX = 100_000
"""Most variants one call takes (the caller splits larger sets)."""

CHUNK = 128
"""Variants solved together, phase by phase (validation, replay, answers, twins, verdicts): enough for each
phase's code to stay hot, few enough that their solutions stay in the processor's cache. All variants at once
made a variant with checks cost more the larger the batch (crank_rocker.extremes: 40 µs each at 300 variants,
45 at 1 000, 47 at 3 000, while single solves stayed at 40 µs)."""


@dataclass(frozen=True)
class Batch:
    """The results of :func:`solve_batch`, one entry per variant in the order given.

    Attributes
    ----------
    recipe : str
        The recipe's public name.
    answers : list of dict or None
        The textbook's choice of solution, ``{answer name: value}``; None where the variant failed.
    errors : list of str or None
        The one-line reason a variant was refused (bad givens, no such mechanism); None where it solved.
    ok : list of bool
        Solved and, when checks were asked for, every twin check passed.
    warnings : list of list of str
        Each solved variant's warnings (borderline geometry, failed checks); empty for failed variants.
    """

    recipe: str
    answers: list[dict[str, Any] | None]
    errors: list[str | None]
    ok: list[bool]
    warnings: list[list[str]]

    def __len__(self) -> int:
        return len(self.answers)


def _rows(givens: Sequence[Mapping[str, Any]] | Mapping[str, Sequence[Any]]) -> list[Mapping[str, Any]]:
    """Variants as a list of mappings; columns (a mapping of equal-length sequences, numpy arrays included)
    are turned into rows, numpy scalars into Python numbers.

    >>> _rows({"a": [1, 2], "b": (3.0, 4.0)})
    [{'a': 1, 'b': 3.0}, {'a': 2, 'b': 4.0}]
    """
    if isinstance(givens, Mapping):
        cols = {k: (v.tolist() if hasattr(v, "tolist") else list(v)) for k, v in givens.items()}
        sizes = {len(v) for v in cols.values()}
        if len(sizes) > 1:
            raise ValueError(f"columns of different lengths: {', '.join(f'{k}: {len(v)}' for k, v in cols.items())}")
        n = sizes.pop() if sizes else 0
        return [{k: v[i] for k, v in cols.items()} for i in range(n)]
    return [({k: (v if type(v) in _PLAIN else v.item() if hasattr(v, "item") else v) for k, v in g.items()}
             if isinstance(g, Mapping) else g) for g in givens]


_PLAIN = frozenset((float, int, str, bool, list, tuple))
"""Types a given arrives as from TOML or Python (no numpy scalar to unwrap: a failed ``hasattr`` costs more than
the rest of a row's copy)."""


def solve_batch(recipe: str, givens: Sequence[Mapping[str, Any]] | Mapping[str, Sequence[Any]], *,
                checks: bool = True) -> Batch:
    """Solve every variant of ``recipe``: answers, and the twin checks unless ``checks`` is False.

    Parameters
    ----------
    recipe : str
        A recipe's public name (``geomcon recipes`` lists them).
    givens : sequence of mappings, or mapping of sequences
        The variants' givens, as rows (``[{"AB": 50, ...}, ...]``) or columns (``{"AB": [50, 55, ...], ...}``,
        lists or numpy arrays). Each row is validated as a problem file's ``[given]`` table.
    checks : bool
        Compare each variant's answers with the analytic twin (``ok`` then means they agreed).

    Returns
    -------
    Batch

    Raises
    ------
    ProblemError
        When ``recipe`` is unknown.
    ValueError
        When columns differ in length or there are more than :data:`BATCH_MAX` variants.
    """
    rec = get_recipe(recipe)
    rows = _rows(givens)
    if len(rows) > BATCH_MAX:
        raise ValueError(f"{len(rows)} variants; at most {BATCH_MAX} per call")
    n = len(rows)
    answers: list[dict[str, Any] | None] = [None] * n
    errors: list[str | None] = [None] * n
    ok: list[bool] = [False] * n
    warns: list[list[str]] = [[] for _ in range(n)]
    plain = plain_validator(rec)            # the recipe's quantities read once for every row
    for start in range(0, n, CHUNK):
        _solve_chunk(rec, recipe, rows, range(start, min(n, start + CHUNK)), plain, checks, answers, errors, ok,
                     warns)
    return Batch(rec.name, answers, errors, ok, warns)


def _solve_chunk(rec: Recipe, recipe: str, rows: list[Mapping[str, Any]], chunk: range, plain: Any, checks: bool,
                 answers: list, errors: list, ok: list, warns: list) -> None:
    """:func:`solve_batch` of the variants ``chunk`` of ``rows``, written into the four lists in their places."""
    # in phases, each over every variant of the chunk, so that each phase's code stays hot (interleaved,
    # validation and replay cost a sixth more per variant on the development machine)
    valid: list[tuple[int, dict[str, Any], list[str]]] = []
    validate = rec.validate
    for i in chunk:
        row = rows[i]
        try:
            given = plain(row)
            if given is None:               # not all plain numbers, or one to refuse: validated in full
                given = validate_given(rec, row)
            valid.append((i, given, planned(rec.name, validate, given) if validate is not None else []))
        except GeomconError as exc:
            errors[i] = str(exc)
    fast = [_replayed(rec, given) for _, given, _ in valid]
    sols: list[tuple[int, Solution]] = []
    for (i, given, warnings), replayed in zip(valid, fast):
        if replayed is not None and not checks:
            answers[i], ok[i], warns[i] = replayed[0][0][1], True, list(warnings)
            continue
        try:
            problem = _problem(f"{recipe}[{i}]", rec.name, given)
            sols.append((i, solve(problem) if replayed is None else _solution(rec, problem, warnings, *replayed)))
        except GeomconError as exc:
            errors[i] = str(exc)
    # the checks in phases too: the answers, the twins, the verdicts (each kept as it is made)
    verdicts: dict[int, Any] = {}
    for out, step in ((answers, _ANSWERS), (None, _TWIN), (verdicts, _VERDICT)) if checks else \
            ((answers, _ANSWERS), (warns, _BUILT)):
        alive = []
        for i, sol in sols:
            try:
                got = step(sol)
            except GeomconError as exc:
                answers[i], ok[i], warns[i], errors[i] = None, False, [], str(exc)
                continue
            if out is not None:
                out[i] = got
            alive.append((i, sol))
        sols = alive
    if not checks:
        for i, _ in sols:
            ok[i] = True
    else:
        for i, _ in sols:
            ok[i], warns[i] = verdicts[i]


def _problem(ident: str, recipe: str, given: dict[str, Any]) -> Problem:
    """``Problem(id=ident, recipe=recipe, given=given)``, its fields set in place (the frozen dataclass's
    ``__init__`` sets each of its ten through ``object.__setattr__``: ~3 µs of a variant's ~100 on the
    development machine).

    >>> _problem("r[0]", "guide_bar.extremes", {"AB": 1.0}) == Problem(id="r[0]", recipe="guide_bar.extremes",
    ...                                                                given={"AB": 1.0})
    True
    """
    p = _new(Problem)
    p.__dict__.update(id=ident, recipe=recipe, given=given, published={}, title="", source="", seed="", statement="",
                      notes="", path=None, title_zh="")
    return p


_new = object.__new__


def _ANSWERS(s: Solution) -> Any:
    return s.answers


def _TWIN(s: Solution) -> Any:
    return s.analytic


def _VERDICT(s: Solution) -> tuple[bool, list[str]]:
    """``(s.ok, s.warnings)``; when every check passes (:func:`_all_pass`) without the table of check rows,
    which the batch does not return: passing rows add no warning."""
    if _all_pass(s):
        return True, s.warnings_with(())
    return s.ok, s.warnings


def _float_passes(b: Any, e: Any, scale: float) -> bool:
    """True when ``b`` and ``e`` are both floats and agree as a check row has them agree:
    ``|b − e| < inf`` and ``|b − e| ≤ CHECK_REL·max(|b|, |e|, scale)`` (the max written as comparisons).

    >>> _float_passes(1.0, 1.0 + 1e-12, 1.0), _float_passes(1.0, 1.1, 1.0), _float_passes(1, 1.0, 1.0)
    (True, False, False)
    """
    if type(b) is not float or type(e) is not float:
        return False
    err = abs(b - e)
    m = abs(b)
    t = abs(e)
    if t > m:
        m = t
    if scale > m:
        m = scale
    return err < math.inf and err <= CHECK_REL * m


def _all_pass(s: Solution) -> bool:
    """True when every check of :attr:`Solution.checks` passes at ``CHECK_REL`` as a plain comparison of
    floats: each answer of each matched pair of solutions and each back-substitution, their errors and
    tolerances computed as the rows compute them (``err < inf and err <= CHECK_REL·max(|b|, |e|, scale)``), as
    many solutions as the twin has. False when one does not pass, or is not a pair of floats, or the counts
    differ: the caller then makes the rows (a failing row is judged again at the problem's condition, and
    words its warning)."""
    built_all, exact_all = s.solution_values, s.analytic
    if len(built_all) != len(exact_all):
        return False
    scales = s._unit_scales
    pairs = _answer_pairs(s.recipe)
    for i, j in s.matching:
        built, exact = built_all[i], exact_all[j]
        for name, unit in pairs:
            b = built.get(name)
            if b is None:
                continue
            e = exact.get(name)
            if e is None:
                continue
            if type(b) is bool and type(e) is bool:  # a yes/no answer (C1_folded, A_near) passes when equal
                if b is not e:
                    return False
                continue
            if not _float_passes(b, e, scales[unit]):
                return False
    back_check = s.recipe.back_check
    if back_check is not None:
        given = s.problem.given
        for built in built_all:
            for _, b, e, unit in planned(s.recipe.name, back_check, given, built):
                t = scales.get(unit)
                if not _float_passes(b, e, s.unit_scale(unit) if t is None else t):
                    return False
    return True


def _BUILT(s: Solution) -> list[str]:
    return s.construction_warnings


def _replayed(rec: Recipe, given: dict[str, Any]) -> tuple[list, Any, dict, Any] | None:
    """The valid candidates ``[(index, answers), …]`` of ``given`` (as :class:`~geomcon.solve.Solution` reads
    them), the tape, its memo and what the compiled plan left pending (:meth:`~geomcon.scene.Scene.settle`), by the recipe's current tape and the compiled plan of its answer steps; None
    when the tape does not cover these givens or a value needs the full solve to be judged or refused."""
    try:
        found = taped_values(rec, given)
    except Exception:              # the tape's arithmetic leaves its domain: the single solve says how
        return None
    if found is None:
        return None
    tape, memo = found
    keys, table = taped_table(rec, tape.solutions, tape.answers)
    run = tape.program(keys)
    if run is None:
        return None
    try:
        pending = run(memo)        # the other steps' objects are made only if the scene is read further
    except Exception:              # the single solve evaluates step by step and words the failure
        return None
    out = read_candidates(rec, table, memo)
    if not out:
        return None
    for _, sol in out:
        for v in sol.values():
            if not (type(v) is float and v - v == 0.0 or type(v) is str):   # finite (the common case) or a word
                return None
    return out, tape, memo, pending


def _solution(rec: Recipe, problem: Problem, warnings: list[str], out: list, tape: Any, memo: dict,
              pending: Any) -> Solution:
    """The :class:`~geomcon.solve.Solution` of a replayed variant holding the answers already read, for its
    twin checks (its scene is the replay's, and completes itself when anything else is asked of it)."""
    sc = Scene.replayed(tape, memo, pending)
    given = problem.given
    sc.rebuild_with(lambda: rec.construct(given).scene)
    sol = Solution(problem, rec, replayed_construction(sc, tape), warnings)
    sol.__dict__["_valid_candidates"] = out
    return sol


__all__ = ["BATCH_MAX", "Batch", "solve_batch"]
