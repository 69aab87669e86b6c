"""A problem with several valid solutions (issue 11): the text output says how many and lists them, and
``geomcon solve FILE --solution N`` reports and draws solution N."""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from geomcon.cli import main
from geomcon.errors import ProblemError
from geomcon.problems import load_problem
from geomcon.solve import solve

JAW = Path(__file__).parent.parent / "problems" / "001-16_jaw_crusher_AC1.toml"


def test_the_text_says_how_many_solutions_and_lists_them(capsys):
    assert main(["solve", str(JAW)]) == 0
    out = capsys.readouterr().out
    assert "4 valid solutions; the one above is the textbook's choice (solution 1)" in out
    assert [line.split(":")[0].strip() for line in out.splitlines() if line.strip().startswith("solution ")] == [
        "solution 2", "solution 3", "solution 4"]


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_solution_n_is_drawn_and_reported(n, tmp_path, capsys):
    sol = solve(load_problem(JAW))
    want = sol.solution_values[n - 1]
    svg = tmp_path / "s.svg"
    assert main(["solve", str(JAW), "--solution", str(n), "--svg", str(svg)]) == 0
    out = capsys.readouterr().out
    assert f"AB = {want['AB']:.3f} mm" in out.splitlines()[1]            # the answers shown are solution n's
    text = svg.read_text()
    assert (f"solution {n} of 4" in text) == (n > 1)
    lines = sol.as_solution(n).figure_lines("en")                      # the sheet's results: solution n's
    assert any(f"{want['AD']:.3f}" in line for line in lines if line.startswith("AD"))
    drawn = sol.as_solution(n)
    A, D = drawn.drawing_scene.evaluate(["A", "D"]).values()
    assert math.isclose(abs(A - D), want["AD"], rel_tol=1e-12)     # the figure's linkage is solution n's
    assert drawn.answers == want and drawn.ok
    assert sorted(map(json.dumps, drawn.solution_values)) == sorted(map(json.dumps, sol.solution_values))


@pytest.mark.parametrize("n", ["0", "5", "x", "-1", "2.5"])
def test_a_solution_that_does_not_exist_is_refused_in_one_line(n, tmp_path, capsys):
    svg = tmp_path / "s.svg"
    assert main(["solve", str(JAW), "--solution", n, "--svg", str(svg)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"error: {JAW}: --solution")
    assert not svg.exists()


def test_a_problem_with_one_solution_has_no_solution_2():
    sol = solve(load_problem(Path(__file__).parent.parent / "problems" / "001-08_crank_rocker.toml"))
    assert sol.as_solution(1) is sol
    with pytest.raises(ProblemError, match="1 valid solution"):
        sol.as_solution(2)


@pytest.mark.parametrize("n", [1, 3])
def test_the_figure_draws_the_other_valid_designs_light(n):
    """Each valid design but the drawn one appears in its folded position (crank, coupler, frame), light."""
    drawn = solve(load_problem(JAW)).as_solution(n)
    others = drawn.drawing_scene.value("other_designs")
    assert len(others) == 3 * (len(drawn.solution_values) - 1) == 9
    frames = sorted(round(abs(s.b - s.a), 9) for s in others[2::3])            # A–D of each other design
    assert frames == sorted(round(s["AD"], 9) for s in drawn.solution_values[1:])
    cranks = sorted(round(abs(s.b - s.a), 9) for s in others[0::3])
    assert cranks == sorted(round(s["AB"], 9) for s in drawn.solution_values[1:])
    assert drawn.drawing_scene["other_designs"].style == "ghost"
