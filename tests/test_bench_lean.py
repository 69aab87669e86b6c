"""The lean-core table is honest arithmetic: the plain-DAG reference really is the same construction (same
answers), ratios and verdicts follow from the timings, the sweep's N for 1e-9 follows from its measured order.
(Correctness only: times are reported, never asserted.)"""
from __future__ import annotations

import math
import random

import pytest

from geomcon.bench.lean import LeanRow, batch_rows, lean_table, sweep_n_for, sympy_rows
from geomcon.bench.plain import PLAIN
from geomcon.problems import load_problem, problem_from_dict
from geomcon.solve import solve


def _variants(recipe: str, n: int):
    rng = random.Random(7)
    for _ in range(n):
        if recipe == "crank_rocker.extremes":
            yield {"AB": rng.uniform(15, 40), "BC": rng.uniform(55, 85), "CD": rng.uniform(55, 85),
                   "AD": rng.uniform(65, 95), "branch": rng.choice(["above", "below"])}
        elif recipe == "crank_slider.extremes":
            yield {"AB": rng.uniform(10, 120), "BC": rng.uniform(130, 300), "e": rng.uniform(0, 60)}
        elif recipe == "guide_bar.extremes":
            yield {"AB": rng.uniform(10, 280), "AC": rng.uniform(100, 300)}
        elif recipe == "crank_rocker.design_by_K":
            yield {"K": rng.uniform(1.05, 2.0), "CD": rng.uniform(100, 400), "psi": rng.uniform(10, 80),
                   "BC": rng.uniform(100, 500)}
        else:
            yield {"K": rng.uniform(1.05, 2.0), "H": rng.uniform(20, 300), "e": rng.uniform(0, 60)}


BENCHED = ("crank_rocker.extremes", "crank_slider.extremes", "guide_bar.extremes", "crank_slider.design_by_K",
           "crank_rocker.design_by_K")


def test_every_benched_linkage_has_a_plain_replica():
    from geomcon.bench.lean import LINKAGES
    assert set(BENCHED) == set(PLAIN) == {recipe for _, recipe, _ in LINKAGES}
    for _, recipe, given in LINKAGES:                       # the bench's own problems are in the replicas' forms
        p = problem_from_dict({"recipe": recipe, "given": given}, name="x")
        assert PLAIN[recipe](p.given).keys() == solve(p).answers.keys()


@pytest.mark.parametrize("recipe", BENCHED)
def test_the_plain_dag_is_the_same_construction(recipe):
    checked = 0
    for given in _variants(recipe, 80):
        try:
            sol = solve(problem_from_dict({"recipe": recipe, "given": given}, name="x"))
            want = sol.answers
        except ValueError:
            continue
        got = PLAIN[recipe](sol.problem.given)
        assert set(got) == set(want)
        for k, v in got.items():
            assert abs(v - want[k]) <= 1e-12 * max(1.0, abs(want[k]), sol.length_scale), (given, k, v, want[k])
        checked += 1
    assert checked >= 20


def test_a_replica_refuses_a_form_it_does_not_cover():
    with pytest.raises(ValueError, match="covers"):
        PLAIN["crank_rocker.design_by_K"]({"K": 1.25, "CD": 290.0, "psi": 32.0, "AB": 60.0})
    with pytest.raises(ValueError, match="covers"):
        PLAIN["crank_slider.design_by_K"]({"K": 1.5, "H": 50.0, "AB": 20.0})


def test_ratios_and_verdicts_follow_from_the_times():
    fast = LeanRow("answers only", "c", 40e-6, "plain DAG", 30e-6, "≤ 50 µs, ≤ 1.5×", 50e-6, 1.5)
    slow_ratio = LeanRow("answers only", "c", 49e-6, "plain DAG", 30e-6, "≤ 50 µs, ≤ 1.5×", 50e-6, 1.5)
    slow_time = LeanRow("answers + twin checks", "c", 101e-6, "answers only", 90e-6, "≤ 100 µs", 100e-6, None)
    sym = LeanRow("vs sympy.geometry", "c", 100e-6, "sympy.geometry", 2.0, "≥ 10⁴×", None, None, speedup=1e4)
    sym_short = LeanRow("vs sympy.geometry", "c", 100e-6, "sympy.geometry", 0.5, "≥ 10⁴×", None, None, speedup=1e4)
    assert [r.met for r in (fast, slow_ratio, slow_time, sym, sym_short)] == [True, False, False, True, False]
    text = lean_table([fast, slow_ratio, sym])
    assert "2 of 3 targets met" in text and "SHORT" in text and "2e+04× faster" in text


class _Sweep:
    def __init__(self, n, seconds, value, error):
        self.n, self.seconds, self.values, self.errors = n, seconds, {"H": value}, {"H": error}


def test_sweep_n_for_fits_the_order_it_sees():
    rows = [_Sweep(360, 1e-5, 100.0, 1e-2), _Sweep(3600, 1e-4, 100.0, 1e-4), _Sweep(36000, 1e-3, 100.0, 1e-6)]
    n, t, order = sweep_n_for(rows, "H")                          # 1e-8 relative at 36,000: extrapolated
    assert order == pytest.approx(2.0) and n == pytest.approx(36000 * 10 ** 0.5) and t == pytest.approx(1e-3 * n / 36000)
    floor = rows + [_Sweep(360000, 1e-2, 100.0, 5e-11), _Sweep(1000000, 3e-2, 100.0, 4.9e-11)]   # a rounding floor
    n, t, order = sweep_n_for(floor, "H")                         # reached at 360,000: interpolated, not the floor's fit
    assert 36000 < n < 360000 and order == pytest.approx(math.log(1e-8 / 5e-13) / math.log(10))
    assert sweep_n_for([_Sweep(360, 1e-5, 100.0, 0.0)], "H")[0] == 360      # exact at once


def test_sympy_rows_pair_the_two_routes():
    class R:
        def __init__(self, method, seconds):
            self.given, self.method, self.seconds = {"K": 1.5, "H": 50, "e": 20}, method, seconds
    rows = sympy_rows([R("geomcon", 1e-4), R("sympy.geometry", 2.0)])
    assert len(rows) == 1 and rows[0].met and rows[0].ratio == pytest.approx(5e-5)
    assert sympy_rows(None) == []


def test_batch_rows_report_a_cost_per_variant_of_the_valid_variants():
    rows = batch_rows(quick=True)              # 200 random draws: some are no crank-rocker, and are left out
    assert len(rows) == 4 and all(r.seconds > 0 and r.ref_seconds > 0 and r.max_ratio == 1.0 for r in rows)
    assert all(100 <= int(r.case.split(" × ")[0]) <= 200 for r in rows)
    assert [r.reference for r in rows] == ["one solve at a time (answers)",
                                            "one solve at a time (answers, ok, warnings)"] * 2


def test_the_baseline_line_quotes_python_c_pass():
    from geomcon.bench.lean import baseline_line
    whole = LeanRow("whole process", "geomcon solve 001-08", 0.1, "python -c pass", 0.025, "≤ 120 ms", 0.120, None)
    assert baseline_line([whole]).startswith("python -c pass: 25 ms")
    assert baseline_line([]) == "python -c pass: not measured"
    assert lean_table([whole]).splitlines()[1] == baseline_line([whole])


def test_cam_rows_cover_every_bundled_cam_with_a_fitting_reference():
    from geomcon.bench.cam_plain import covered
    from geomcon.bench.lean import _cam_problems, cam_rows
    rows = [r for r in cam_rows(quick=True) if r.what == "cam answers only"]
    assert len(rows) == len(_cam_problems()) >= 10 and len({r.case for r in rows}) == len(rows)
    plain = {p.stem.split("_")[0] for p in _cam_problems() if covered(load_problem(p).recipe, load_problem(p).given)}
    assert len(plain) >= 10
    for r in rows:
        twin = r.case.split()[0] not in plain                # flat faces, eccentric cams, new laws, ω given
        assert r.reference == ("its analytic twin" if twin else "scalar reference") and r.ref_seconds > 0
        assert r.met == (r.seconds <= 2e-3)
