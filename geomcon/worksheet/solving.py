"""Solving one variant and reading the answers an exercise asks for, for every valid solution.

Examples
--------
>>> sol = solve_given("guide_bar.extremes", {"AB": 145, "AC": 290})
>>> from geomcon.worksheet.spec import AnswerRef
>>> read(sol, (AnswerRef("theta", "theta", None, "deg"),))
[{'theta': 60.00000000000001}]
"""
from __future__ import annotations

import math
from typing import Any, Mapping, Sequence

from ..errors import GeomconError, NotAMechanism
from ..problems import Problem, validate_given
from ..recipes import get_recipe
from ..solve import Solution, solve
from .spec import AnswerRef


def solve_given(recipe: str, given: Mapping[str, Any]) -> Solution:
    """Validate a variant's raw givens as a problem file's and build its solution (lean: nothing computed yet).

    Raises
    ------
    GeomconError
        Bad givens (``ProblemError``) or no mechanism (``NotAMechanism``).
    """
    rec = get_recipe(recipe)
    raw = {k: _raw(v) for k, v in given.items() if v is not None}      # a problem's normalised givens, as a file's
    return solve(Problem(id=recipe, recipe=rec.name, given=validate_given(rec, raw)))


def same_given(sol: Solution, recipe: str, given: Mapping[str, Any]) -> bool:
    """Whether ``sol`` is the solution :func:`solve_given` builds for ``recipe`` and ``given``: the same recipe
    and the same givens once validated (a key's givens come back from JSON as lists and ints; validated, they
    are the judged variant's).

    >>> sol = solve_given("guide_bar.extremes", {"AB": 145.0, "AC": 290})
    >>> same_given(sol, "guide_bar.extremes", {"AB": 145, "AC": 290.0}), same_given(sol, "guide_bar.extremes", {"AB": 140, "AC": 290})
    (True, False)
    """
    rec = get_recipe(recipe)
    if sol.recipe.name != rec.name:
        return False
    try:
        return dict(sol.problem.given) == validate_given(rec, {k: _raw(v) for k, v in given.items() if v is not None})
    except GeomconError:
        return False


def _raw(value: Any) -> Any:
    """A normalised given as a problem file writes it: tuples (lists, a program's rows) back to lists; an
    absent optional given (None) is left out by the caller.

    >>> _raw((1.0, (2.0, 3.0)))
    [1.0, [2.0, 3.0]]
    """
    return [_raw(v) for v in value] if isinstance(value, tuple) else value


def read(sol: Solution, refs: Sequence[AnswerRef]) -> list[dict[str, float | None]]:
    """The referred answers of every valid solution, the textbook's choice first; a value is None where the
    variant has no such answer (an answer of another form, an index beyond a list). A recipe with one
    solution evaluates only the steps those answers need."""
    c = sol.construction
    if not c.solutions:
        keys = {r.name: c.answers[r.name] for r in refs if r.name in c.answers}
        vals = sol.evaluate(keys.values())
        raw = {n: vals[k] for n, k in keys.items()}
        row = {r.text: _number(r, raw) for r in refs}
        return [row]
    return [{r.text: _number(r, s) for r in refs} for s in sol.solution_values]


def _number(ref: AnswerRef, answers: Mapping[str, Any]) -> float | None:
    v = answers.get(ref.name)
    if v is None:
        return None
    if ref.index is not None:
        if ref.index >= len(v):
            return None
        v = v[ref.index]
    x = float(v)
    if not math.isfinite(x):
        raise NotAMechanism(f"answer '{ref.text}' is not a finite number ({x!r})")
    return x


def chosen_map(sol: Solution) -> Mapping[str, str]:
    """Answer name → step key of the textbook's choice of solution (the map :attr:`Solution.answers` reads):
    the construction's answers, or the first valid candidate in the recipe's order of preference (the same
    filter and the same stable sort as :attr:`Solution.solution_values`)."""
    c = sol.construction
    if not c.solutions:
        return c.answers
    maps = [m for m in c.solutions if "_valid" not in m or sol.evaluate([m["_valid"]])[m["_valid"]]]
    if sol.recipe.order is not None and len(maps) > 1:
        def values(m: Mapping[str, str]) -> dict[str, Any]:
            got = sol.evaluate([k for n, k in m.items() if n != "_valid"])
            return {n: (float(got[k]) if isinstance(got[k], (int, float)) else got[k]) for n, k in m.items()
                    if n != "_valid"}
        maps = sorted(maps, key=lambda m: sol.recipe.order(values(m)))
    return maps[0] if maps else c.answers


__all__ = ["chosen_map", "read", "same_given", "solve_given"]
