"""The batch API: many variants of one recipe in one call give exactly the answers of one-by-one solves,
errors in their places, rows and columns alike."""
from __future__ import annotations

import numpy as np
import pytest

from geomcon.batch import Batch, solve_batch
from geomcon.errors import ProblemError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

ROWS = [
    {"AB": 50, "BC": 70, "CD": 80, "AD": 90},
    {"AB": 25.5, "BC": 61, "CD": 70, "AD": 80, "branch": "below"},
    {"AB": 95, "BC": 70, "CD": 80, "AD": 90},          # AB is not the shortest: no crank-rocker
    {"AB": 50, "BC": 70, "CD": 80},                     # AD missing: bad input
    {"AB": 40, "BC": 75, "CD": 66, "AD": 86},
]


def _one(given: dict) -> dict | None:
    try:
        return solve(problem_from_dict({"recipe": "crank_rocker.extremes", "given": given}, name="one")).answers
    except ProblemError:
        return None
    except ValueError:
        return None


def test_rows_give_the_answers_of_single_solves_and_errors_in_place():
    b = solve_batch("crank_rocker.extremes", ROWS)
    assert isinstance(b, Batch) and len(b) == len(ROWS) and b.recipe == "crank_rocker.extremes"
    for row, got, err, ok in zip(ROWS, b.answers, b.errors, b.ok):
        want = _one(row)
        assert got == want                       # the same code path: identical floats, not just close
        assert (err is None) == (want is not None) and ok == (want is not None)
    assert "AD" in b.errors[3] and "not the strictly shortest" in b.errors[2]


def test_columns_and_numpy_arrays_equal_rows():
    rows = [r for r in ROWS if "AD" in r and "branch" not in r]
    cols = {k: np.array([r[k] for r in rows], dtype=float) for k in ("AB", "BC", "CD", "AD")}
    assert solve_batch("crank_rocker.extremes", cols).answers == solve_batch("crank_rocker.extremes", rows).answers


def test_checks_off_still_answers_and_keeps_construction_warnings():
    rows = [{"AB": 15, "BC": 50, "CD": 35, "AD": 30}]        # Grashof equality: a change-point warning
    on, off = solve_batch("crank_rocker.extremes", rows), solve_batch("crank_rocker.extremes", rows, checks=False)
    assert on.answers == off.answers and off.ok == [True]
    assert any("Grashof equality" in w for w in off.warnings[0])


def test_design_recipe_batch_back_substitutes():
    rows = [{"K": k, "H": 50.0, "e": 20.0} for k in (1.2, 1.4, 1.6)]
    b = solve_batch("crank_slider.design_by_K", rows)
    assert b.ok == [True, True, True]
    for row, got in zip(rows, b.answers):
        assert got == solve(problem_from_dict({"recipe": "crank_slider.design_by_K", "given": row}, name="x")).answers


def test_bad_calls_raise():
    with pytest.raises(ProblemError, match="unknown recipe"):
        solve_batch("no.such", [])
    with pytest.raises(ValueError, match="different lengths"):
        solve_batch("guide_bar.extremes", {"AB": [1.0, 2.0], "AC": [3.0]})
    assert len(solve_batch("guide_bar.extremes", [])) == 0


@pytest.mark.parametrize("recipe", ["crank_rocker.extremes", "crank_slider.extremes", "guide_bar.extremes",
                                    "crank_slider.design_by_K", "crank_rocker.design_by_K"])
def test_the_replayed_lane_gives_what_single_solves_give(recipe):
    # many variants: the first teach the plan and the tape, the rest take the batch's replayed lane; the
    # answers (bit for bit), the verdicts, the warnings and the refusals are those of one-by-one solves
    from tests.test_bench_lean import _variants
    rows = list(_variants(recipe, 60))
    for checks in (True, False):
        b = solve_batch(recipe, rows, checks=checks)
        for row, got, err, ok, words in zip(rows, b.answers, b.errors, b.ok, b.warnings):
            try:
                sol = solve(problem_from_dict({"recipe": recipe, "given": row}, name="x"))
                want = sol.answers
                want_ok, want_words = (sol.ok, sol.warnings) if checks else (True, sol.construction_warnings)
            except ValueError as exc:
                assert got is None and err == str(exc) and not ok and words == []
                continue
            assert (got, err, ok, words) == (want, None, want_ok, want_words)


@pytest.mark.parametrize("checks", [True, False])
def test_a_batch_solved_in_chunks_gives_what_one_chunk_gives(monkeypatch, checks):
    """The variants are solved :data:`~geomcon.batch.CHUNK` at a time (a whole large batch at once cost more per
    variant the larger it was); across chunk boundaries every answer, error, verdict and warning stays in place."""
    import geomcon.batch as batch
    rows = [ROWS[i % len(ROWS)] | {"AB": ROWS[i % len(ROWS)].get("AB", 50) + (i % 7) * 0.5} for i in range(37)]
    monkeypatch.setattr(batch, "CHUNK", 8)
    chunked = solve_batch("crank_rocker.extremes", rows, checks=checks)
    monkeypatch.setattr(batch, "CHUNK", 1000)
    whole = solve_batch("crank_rocker.extremes", rows, checks=checks)
    assert chunked == whole
    assert sum(e is not None for e in whole.errors) >= 7 and sum(whole.ok) >= 14
