"""The benchmark measures what it says: the sweep's error shrinks as N grows, the construction agrees with
the twin, answers alone evaluate fewer steps than the drawing, and the command writes a valid plot.
(Correctness only: times are reported, never asserted.)"""
from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.bench import CASES, QUICK, measure_drawing, measure_extremes, render_plot
from geomcon.bench.sweep import sweep_crank_rocker, sweep_crank_slider, sweep_guide_bar

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def rows():
    return measure_extremes(QUICK)


def test_construction_agrees_with_the_twin(rows):
    cons = [r for r in rows if r.method == "construction"]
    assert len(cons) == len(CASES)
    assert all(r.rel_error <= 1e-9 for r in cons)


def test_sweep_error_shrinks_as_N_grows(rows):
    for case in CASES:
        errs = [r.rel_error for r in rows if r.case == case and r.method == "sweep"]
        assert len(errs) >= 3 and errs == sorted(errs, reverse=True) and errs[-1] < errs[0] / 10, (case, errs)


def test_sweep_theta_is_within_one_step(rows):
    for r in rows:
        if r.method == "sweep":
            assert r.errors["theta"] <= 360.0 / r.n, (r.case.label, r.n, r.errors)


def test_sweep_starts_off_the_round_angles():
    # from 0, every 1° sample of N = 360 falls on the guide-bar's extremes (210°, 330°): an accidental exact ψ
    given = {"AB": 145.0, "AC": 290.0}
    assert sweep_guide_bar(given, 360, phase=0.0)["psi"] == pytest.approx(60.0, abs=1e-12)
    assert abs(sweep_guide_bar(given, 360)["psi"] - 60.0) > 1e-4


def test_sweep_follows_the_branch():
    above = sweep_crank_rocker({"AB": 50, "BC": 70, "CD": 80, "AD": 90, "branch": "above"}, 3600)
    below = sweep_crank_rocker({"AB": 50, "BC": 70, "CD": 80, "AD": 90, "branch": "below"}, 3600)
    assert below["psi"] == pytest.approx(above["psi"], rel=1e-6)
    assert abs(below["theta"] - above["theta"]) <= 2 * 360 / 3600


@pytest.mark.parametrize("sweep, given, key, exact", [
    (sweep_crank_rocker, {"AB": 50, "BC": 70, "CD": 80, "AD": 90}, "psi", 77.8862570493),
    (sweep_crank_slider, {"AB": 120, "BC": 250, "e": 60}, "H", 249.777099324),
    (sweep_guide_bar, {"AB": 145, "AC": 290}, "psi", 60.0),
])
def test_a_fine_sweep_converges_to_the_twin(sweep, given, key, exact):
    assert sweep(given, 200_000)[key] == pytest.approx(exact, rel=1e-6)


def test_answers_only_evaluate_fewer_steps_than_the_drawing():
    rows = measure_drawing(QUICK)
    for case in CASES:
        a, d = [r for r in rows if r.case == case]
        assert a.steps_evaluated < d.steps_evaluated == d.steps_total


def test_plot_has_a_series_per_method_and_problem(rows):
    root = ET.fromstring(render_plot(rows, quick=True).encode())
    svg = "{http://www.w3.org/2000/svg}"
    series = [g for g in root.iter(svg + "g") if "series" in g.get("class", "").split()]
    assert sorted((g.get("data-recipe"), g.get("data-method")) for g in series) == sorted(
        (case.recipe, m) for case in CASES for m in ("construction", "sweep"))
    text = " ".join(t.text or "" for t in root.iter(svg + "text"))
    for case in CASES:
        assert f"{case.label} · construction" in text and f"{case.label} · sweep" in text
    assert "N = 36,000" in text and "floor 10⁻¹⁷" in text


def test_plot_is_deterministic_given_the_numbers(rows):
    assert render_plot(rows) == render_plot(rows)


def test_bench_command_writes_the_plot(tmp_path):
    out = tmp_path / "b.svg"
    r = subprocess.run([sys.executable, "-m", "geomcon.cli", "bench", "--quick", "--out", str(out)],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert r.returncode == 0, r.stderr
    assert out.is_file() and ET.parse(out).getroot().tag.endswith("svg")
    assert "construction" in r.stdout and "steps evaluated" in r.stdout
    assert "geomcon gallery --check" in r.stdout and "one figure (sheet 1)" in r.stdout


def test_design_by_K_agrees_with_sympy_geometry():
    pytest.importorskip("sympy")      # in the test extra; the bench reports "not measured" without it
    from geomcon.bench.exact import engine_crank_slider, sympy_crank_slider

    for g in ({"K": 1.5, "H": 50, "e": 20}, {"K": 2, "H": 300, "e": 60}):
        e_ab, e_bc = engine_crank_slider(**g)
        s_ab, s_bc = sympy_crank_slider(**g)
        assert e_ab == pytest.approx(s_ab, rel=1e-12) and e_bc == pytest.approx(s_bc, rel=1e-12)
