"""The terminal's header says which of several valid solutions it reports (issue 11, hsmall11m): `geomcon solve
FILE --solution 2` printed the bare title although the sheet of solution 2 is titled "… — solution 2 of 4"; the
header now says it in the language asked, and for the textbook's choice too ("— solution 1 of 4"). A problem with
one solution keeps its bare title."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.cli import main

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"
JAW = PROBLEMS / "001-16_jaw_crusher_AC1.toml"


def _header(capsys, *args: str) -> str:
    assert main(["solve", *args]) == 0
    return capsys.readouterr().out.splitlines()[0]


@pytest.mark.parametrize("n", [1, 2, 4])
def test_the_header_names_the_solution_shown(n, capsys):
    head = _header(capsys, str(JAW), "--solution", str(n), "--lang", "en")
    assert head.endswith(f"AC1 = 225 — solution {n} of 4")


def test_the_header_says_it_in_each_language(capsys):
    assert _header(capsys, str(JAW), "--solution", "3", "--lang", "zh").endswith("——解 3（共 4 个）")
    both = _header(capsys, str(JAW), "--solution", "3", "--lang", "both")
    assert "— solution 3 of 4  按 K" in both and both.endswith("——解 3（共 4 个）")


def test_without_solution_the_header_names_the_textbook_s_choice(capsys):
    assert _header(capsys, str(JAW), "--lang", "en").endswith("— solution 1 of 4")


def test_one_solution_keeps_the_bare_title(capsys):
    head = _header(capsys, str(PROBLEMS / "001-08_crank_rocker.toml"), "--lang", "en")
    assert head.endswith("extreme positions, K and γmin") and "solution" not in head
