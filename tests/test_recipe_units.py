"""Every given's and answer's unit says what its meaning says (issue 11, ``geomcon recipes``: the cams' ω was
listed as a "ratio" though its text says rad/s, and ``divisions``, a whole number, as a "ratio" too)."""
from __future__ import annotations

import re
import subprocess
import sys

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
