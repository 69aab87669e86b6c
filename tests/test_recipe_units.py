"""Every given's and answer's unit says what its meaning says (issue 11, ``geomcon recipes``: the cams' ω was
listed as a "ratio" though its text says rad/s, and ``divisions``, a whole number, as a "ratio" too)."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from geomcon.errors import ProblemError
from geomcon.problems import problem_from_dict
from geomcon.recipes import RECIPES, get_recipe

QUANTITIES = [(name, q) for name in sorted(RECIPES) for qs in (get_recipe(name).givens, get_recipe(name).answers)
              for q in qs]


def test_an_angular_speed_is_in_rad_per_s_and_a_whole_number_is_a_count():
    assert len(QUANTITIES) > 300
    for name, q in QUANTITIES:
        doc = q.doc.lower()
        if re.search(r"\bangular (speed|velocity)\b", doc.split("(")[0]):
            assert q.unit.removesuffix("[]") == "rad/s", (name, q.name, q.unit, q.doc)
        if "a whole number" in doc:
            assert q.unit == "count", (name, q.name, q.unit, q.doc)


def test_the_listing_names_those_units():
    out = subprocess.run([sys.executable, "-m", "geomcon", "recipes"], capture_output=True, text=True, check=True).stdout
    rows = re.findall(r"^    (omega|divisions) +(\S+(?: \S+)?) {2,}", out, re.M)
    assert ("divisions", "whole number") in rows and sum(1 for r in rows if r[0] == "omega") >= 7
    assert all(unit == "rad/s" for n, unit in rows if n == "omega"), rows


def _oscillating(**extra) -> dict:
    return {"recipe": "cam.oscillating", "given": {
        "follower": "roller", "a": 80, "L": 60, "r0": 30, "h": 20, "rr": 5,
        "program": [{"kind": "rise", "angle": 150, "law": "cosine"}, {"kind": "dwell", "angle": 30},
                    {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}], **extra}}


@pytest.mark.parametrize("bad", [0, -3, 1e7])
def test_a_count_and_an_angular_speed_are_still_range_checked(bad):
    """The new units keep the checks the old one gave (the recipe refuses a fractional or too large count)."""
    assert problem_from_dict(_oscillating(divisions=6, omega=2.5), name="demo").given["divisions"] == 6
    with pytest.raises(ProblemError):
        problem_from_dict(_oscillating(divisions=bad), name="demo")
    with pytest.raises(ProblemError):
        problem_from_dict(_oscillating(omega=bad), name="demo")


RATIO_WORDS = re.compile(r"ratio|coefficient|/")
"""What the meaning of a quantity without a unit names: a ratio, a coefficient or a quotient (ω2/ω1)."""


def test_a_quantity_listed_as_a_ratio_is_one_and_a_flag_is_yes_or_no():
    # issue 11 (review of session g): `geomcon recipes` listed crank_rocker.design_by_K's C1_folded and A_near,
    # answers that are 1 or 0 ("1 when C1 is the folded one, else 0"), as "(ratio)"
    for name, q in QUANTITIES:
        if q.unit == "":
            assert RATIO_WORDS.search(q.doc), (name, q.name, q.doc)
        if re.match(r"(yes|1) when\b", q.doc):
            assert q.unit == "bool", (name, q.name, q.unit, q.doc)
    units = {q.name: q.unit for q in get_recipe("crank_rocker.design_by_K").answers}
    assert units["C1_folded"] == units["A_near"] == "bool"


def test_the_listing_gives_every_answer_its_unit_and_meaning_and_a_flag_reads_yes_or_no():
    out = subprocess.run([sys.executable, "-m", "geomcon", "recipes"], capture_output=True, text=True, check=True).stdout
    rows = {}
    for block in out.split("\n\n"):
        if "  answers:" not in block:
            continue
        recipe = block.split()[0]
        for line in block.split("  answers:\n", 1)[1].splitlines():
            m = re.match(r"^    (\S+) +(.+?) {2,}(\S.*)$", line)
            assert m, line
            rows[recipe, m[1]] = (m[2], m[3])
    answers = [(name, q) for name in sorted(RECIPES) for q in get_recipe(name).answers]
    assert set(rows) == {(name, q.name) for name, q in answers}
    for name, q in answers:
        unit, meaning = rows[name, q.name]
        assert meaning == q.doc, (name, q.name)
        assert (unit == "yes/no (JSON true/false)") == (q.unit == "bool"), (name, q.name, unit)
        assert "ratio" not in unit or q.unit == "", (name, q.name, unit)
    assert rows["crank_rocker.design_by_K", "C1_folded"][0].startswith("yes/no")
    assert rows["four_bar.analysis", "type"][0] == ("one of crank-rocker|double-crank|double-rocker|change-point"
                                                    "|immovable")


def test_a_flag_and_its_twin_are_yes_or_no_in_the_solution():
    from geomcon.problems import load_problem
    from geomcon.solve import solve
    problems = Path(__file__).resolve().parents[1] / "problems"
    sol = solve(load_problem(problems / "001-15_crank_rocker_frame_and_position.toml"))
    rows = [r for r in sol.checks if r["quantity"].split(".")[-1] in ("C1_folded", "A_near")]
    assert len(rows) >= 4
    assert all(type(r["construction"]) is bool and type(r["analytic"]) is bool and r["ok"] for r in rows), rows
    assert {type(s[k]) for s in sol.solution_values for k in ("C1_folded", "A_near")} == {bool}
