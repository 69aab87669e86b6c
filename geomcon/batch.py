"""Solving many variants of one recipe in one call: answers and twin checks only, no drawing.

Worksheets solve a class set of variants, grading solves every student's givens; both need the answers (and
that each construction agreed with its twin) thousands of times. :func:`solve_batch` validates each variant's
givens exactly as a problem file's, solves it with lean, planned scenes (the recipe's evaluation plan is
learned on the first variant and reused), and collects the answers. A variant that is bad input or no
mechanism does not stop the batch: its error is reported in its place.

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

from dataclasses import dataclass
from typing import Any, Mapping, Sequence

from .errors import GeomconError
from .problems import Problem, validate_given
from .recipes import get_recipe
from .solve import solve

BATCH_MAX = 100_000
"""Most variants one call takes (the caller splits larger sets)."""


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
    return [({k: (v.item() if hasattr(v, "item") else v) for k, v in g.items()} if isinstance(g, Mapping) else g)
            for g in givens]


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
    answers: list[dict[str, Any] | None] = []
    errors: list[str | None] = []
    ok: list[bool] = []
    warns: list[list[str]] = []
    for i, row in enumerate(rows):
        try:
            given = validate_given(rec, row)
            problem = Problem(id=f"{recipe}[{i}]", recipe=rec.name, given=given)
            sol = solve(problem)
            answers.append(sol.answers)
            good = sol.ok if checks else True
            warns.append(sol.warnings if checks else sol.construction_warnings)
        except GeomconError as exc:
            answers.append(None)
            errors.append(str(exc))
            ok.append(False)
            warns.append([])
            continue
        errors.append(None)
        ok.append(good)
    return Batch(rec.name, answers, errors, ok, warns)


__all__ = ["BATCH_MAX", "Batch", "solve_batch"]
