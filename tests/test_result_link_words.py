"""A result names a link by what it is in its mechanism (issue 11, review item 5): in a guide-bar mechanism
(slotter, shaper, Whitworth) CD is the guide bar or its arm, never a rocker, and DE the coupler to the ram or
slide, never an output arm (001-19 printed "CD = 77 … 摇杆" for the arm of a fully rotating guide bar and
"DE = 443.425 mm … 输出摆杆" for the coupler to the slide)."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.gallery import problem_files
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GUIDE_BAR = ("slotter.", "shaper.", "guide_bar.", "rotating_guide_bar.")
WRONG = {"CD": ("rocker", "摇杆"), "DE": ("output arm", "输出摆杆", "摆杆")}


def _guide_bar_problems() -> list[Path]:
    out = []
    for p in problem_files(ROOT / "problems"):
        head = p.read_text(encoding="utf-8").split("\n", 3)
        if any(line.startswith("recipe = ") and line.split('"')[1].startswith(GUIDE_BAR) for line in head):
            out.append(p)
    return out


def test_there_are_guide_bar_problems_answering_cd_or_de():
    names = {p.stem for p in _guide_bar_problems()}
    assert {"001-19_slotter_rotating_guide_bar", "001-19b_slotter_whitworth_crank_given"} <= names


@pytest.mark.parametrize("path", _guide_bar_problems(), ids=lambda p: p.stem)
def test_a_guide_bar_mechanism_names_no_rocker_and_no_output_arm(path):
    sol = solve(load_problem(path))
    for lang in ("en", "zh", "both"):
        for line in sol.figure_lines(lang):
            for link, words in WRONG.items():
                if line.startswith(f"{link} =") or f" {link} =" in line:
                    assert not any(w in line for w in words), (path.stem, line)
