"""Random valid synthesis problems (geomcon.fuzz.valid_synthesis, fixed seeds): every case solves with all
checks passing and gives back the linkage it was stated from, or — only where the case says it may — is
refused with one line; no numpy warning on the way."""
from __future__ import annotations

import random
import warnings

import pytest

from geomcon.errors import GeomconError
from geomcon.fuzz.valid_synthesis import GENERATORS, in_range
from geomcon.problems import problem_from_dict
from geomcon.solve import solve


def _matches(value, want, tol) -> bool:
    if isinstance(want, tuple):
        return len(value) == len(want) and all(abs(a - b) <= tol for a, b in zip(value, want))
    return abs(value - want) <= tol


@pytest.mark.parametrize("recipe", sorted(GENERATORS))
def test_random_valid_problems_solve_and_give_the_linkage_back(recipe):
    gen = GENERATORS[recipe]
    for i in range(60):
        case = gen(random.Random(f"{recipe}-{i}"))
        assert case.problem["recipe"] == recipe and in_range(case.problem)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                sol = solve(problem_from_dict(case.problem, name="fuzz"))
                ok, solutions = sol.ok, sol.solution_values
            except GeomconError as exc:
                assert case.may_refuse, (i, case.kind, str(exc), case.problem)
                assert "\n" not in str(exc)
                continue
        assert ok, (i, case.kind, [r for r in sol.checks if not r["ok"]], case.problem)
        assert any(all(_matches(s[k], v, t) for k, (v, t) in case.expect.items()) for s in solutions), (
            i, case.kind, case.expect, solutions[0], case.problem)


def test_generators_make_every_kind_of_case():
    kinds = {GENERATORS[r](random.Random(f"k{i}")).kind for r in GENERATORS for i in range(80)}
    text = " ".join(kinds)
    for word in ("2° apart", "nearly collinear", "drafted", "tiny scale 1e-3", "huge scale 1e6"):
        assert word in text, word
    assert "random" in kinds
