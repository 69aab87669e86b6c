"""``geomcon solve FILE --solution N`` says truly how many steps its answers took (issue 11: 001-16's solution 2
ended "steps evaluated 1 of 91" — the count of the scene rebuilt to draw it, which had computed only its
choice; its answers came from the solve that evaluated every candidate, 52 steps)."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from geomcon.cli import main
from geomcon.errors import ProblemError
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
SEVERAL = sorted(p.stem for p in (ROOT / "problems").glob("*.toml")
                 if (ROOT / "gallery" / f"{p.stem}.json").exists()
                 and len(json.loads((ROOT / "gallery" / f"{p.stem}.json").read_text(encoding="utf-8"))
                         .get("solutions") or []) > 1)


def test_the_gallery_has_problems_with_several_solutions():
    assert len(SEVERAL) >= 5 and "001-16_jaw_crusher_AC1" in SEVERAL


@pytest.mark.parametrize("stem", SEVERAL)
def test_every_solution_reports_the_steps_its_answers_took(stem):
    """Solution n's count is that of the solve that found its answers (every candidate evaluated), and more
    steps than its answers name."""
    sol = solve(load_problem(ROOT / "problems" / f"{stem}.toml"))
    assert len(sol.solution_values) > 1                           # every candidate evaluated (the count is "so far")
    first = dict(sol.stats)
    assert first["steps_evaluated"] >= len(sol.construction.answers)
    for n in range(2, len(sol.solution_values) + 1):
        try:
            other = sol.as_solution(n)
        except ProblemError as exc:                               # lists its solutions, draws its choice only
            assert "draws one solution only" in str(exc)
            continue
        assert other.solution_values[0] == sol.solution_values[n - 1]
        assert other.stats == first == other.to_json()["stats"], n


def test_the_text_of_solution_2_of_001_16(tmp_path, capsys):
    path = ROOT / "problems" / "001-16_jaw_crusher_AC1.toml"
    assert main(["solve", str(path)]) == 0
    one = re.search(r"steps evaluated (\d+) of (\d+)", capsys.readouterr().out).groups()
    assert main(["solve", str(path), "--solution", "2"]) == 0
    two = re.search(r"steps evaluated (\d+) of (\d+)", capsys.readouterr().out).groups()
    assert two == one and int(two[0]) > 1, (one, two)
