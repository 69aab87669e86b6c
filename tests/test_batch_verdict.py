"""Issue 10: a checked batch judges a variant whose checks all pass without making the table of check rows
(batch._all_pass): it must say so exactly when the rows would all pass, and then give the same warnings. The
twin is disturbed at random (relative 1e-7 … 1e-11 on one answer: some rows fail, some pass within CHECK_REL) so
that failing, passing and conditioned rows all occur; the batch's answers, verdicts and warnings are those of
one-by-one solves."""
from __future__ import annotations

import random

import pytest

from geomcon import solve as solve_module
from geomcon.batch import _all_pass, solve_batch
from geomcon.cached import cached_property
from geomcon.problems import problem_from_dict
from geomcon.solve import Solution, solve

from tests.test_bench_lean import _variants


def _disturbed(monkeypatch) -> None:
    """Solution.analytic with one float answer of some solutions moved by a random relative amount (the same
    for a given set of givens, so that a batch and a single solve see the same twin)."""
    plain = Solution.__dict__["analytic"].func

    def analytic(self):
        sols = plain(self)
        rnd = random.Random(repr(sorted(self.problem.given.items())))
        if rnd.random() < 0.5:
            return sols
        out = []
        for sol in sols:
            sol = dict(sol)
            names = [k for k, v in sol.items() if type(v) is float and v != 0.0]
            if names:
                k = rnd.choice(names)
                sol[k] = sol[k] * (1 + rnd.choice([1e-7, 3e-9, 1e-9, 5e-10, 1e-11]) * rnd.choice([-1, 1]))
            out.append(sol)
        return out
    prop = cached_property(analytic)
    prop.__set_name__(Solution, "analytic")
    monkeypatch.setattr(Solution, "analytic", prop)


@pytest.mark.parametrize("recipe", ["crank_rocker.extremes", "crank_slider.extremes", "guide_bar.extremes",
                                    "crank_slider.design_by_K", "crank_rocker.design_by_K"])
def test_all_pass_is_every_row_passing(recipe, monkeypatch) -> None:
    _disturbed(monkeypatch)
    rows = list(_variants(recipe, 120))
    seen = {True: 0, False: 0}
    for row in rows:
        try:
            sol = solve(problem_from_dict({"recipe": recipe, "given": row}, name="x"))
            sol.answers
            quick = _all_pass(sol)
        except ValueError:
            continue
        seen[quick] += 1
        assert quick == (sol.ok and all("condition" not in r for r in sol.checks)), row
        if quick:
            assert sol.warnings_with(()) == sol.warnings
    assert seen[True] > 10 and seen[False] > 10, seen
    b = solve_batch(recipe, rows, checks=True)
    for row, got, err, ok, words in zip(rows, b.answers, b.errors, b.ok, b.warnings):
        try:
            sol = solve(problem_from_dict({"recipe": recipe, "given": row}, name="x"))
            want = (sol.answers, None, sol.ok, sol.warnings)
        except ValueError as exc:
            assert got is None and err == str(exc) and not ok and words == []
            continue
        assert (got, err, ok, words) == want
