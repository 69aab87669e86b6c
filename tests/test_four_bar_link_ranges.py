"""``four_bar.link_ranges``: the ranges of one link's length for each type, construction (the textbook's
three cases) against the twin (cuts at ±a ± b ± c, the joints' diagonals), and against the classification of
sampled chains by ``four_bar.analysis``'s twin."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.four_bar_analysis import four_bar_analysis
from geomcon.errors import GeomconError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "four_bar.link_ranges"
KIND = {"crank-rocker": "crank_rocker", "double-crank": "double_crank", "double-rocker": "double_rocker",
        "immovable": "immovable"}


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


def _ok(sol):
    assert sol.checks
    for row in sol.checks:
        assert row["ok"], row


def test_seed_001_02():
    sol = _solve(AB=160, CD=240, AD=210)
    _ok(sol)
    a = sol.answers
    assert a["crank_rocker"] == ((190, 290),)
    assert a["double_crank"] == ()
    assert a["double_rocker"] == ((0, 190), (290, 610))
    assert a["immovable"] == ((610, math.inf),)
    assert a["grashof_ranges"] == ((0, 130), (190, 290))
    assert a["boundaries"] == (190, 290, 610)
    assert sol.to_json()["answers"]["immovable"] == [[610.0, None]]          # unbounded: null in JSON


def test_seed_001_01_unknown_crank():
    sol = _solve(BC=50, CD=35, AD=30)
    _ok(sol)
    a = sol.answers
    assert a["crank_rocker"] == ((0, 15),) and a["double_crank"] == ((45, 55),)
    assert a["double_rocker"] == ((15, 45), (55, 115)) and a["immovable"] == ((115, math.inf),)


@pytest.mark.parametrize("i", range(60))
def test_random_ranges_match_twin_and_sampled_chains(i):
    rng = random.Random(14200 + i)
    names = ["AB", "BC", "CD", "AD"]
    unknown = rng.choice(names)
    known = {n: round(rng.uniform(5, 200), rng.choice([0, 3, 9])) for n in names if n != unknown}
    frame = rng.choice(names)
    sol = _solve(**known, frame=frame)
    _ok(sol)
    a = sol.answers
    top = 1.2 * sum(known.values())
    for _ in range(200):
        x = rng.uniform(1e-3, top)
        if any(abs(x - b) < 1e-6 * top for b in a["boundaries"]):
            continue
        t = four_bar_analysis(**{**known, unknown: x}, frame=frame)["type"]
        if t == "change-point":
            continue
        assert any(lo <= x <= hi for lo, hi in a[KIND[t]]), (x, t, a)


def test_boundaries_are_named_in_the_construction():
    sol = _solve(AB=160, CD=240, AD=210)
    text = sol.scene.caption("boundaries")[0]
    assert "BC = 190 (change-point" in text and "BC = 610 (flat" in text


@pytest.mark.parametrize("given", [dict(AB=1, BC=2), dict(AB=1, BC=2, CD=3, AD=4)])
def test_exactly_one_unknown(given):
    with pytest.raises(GeomconError) as exc:
        _solve(**given)
    assert "exactly three" in str(exc.value)


@pytest.mark.parametrize("unknown", ["AB", "BC", "CD", "AD"])
def test_statement_names_the_unknown_in_both_languages(unknown):
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    g = {n: v for n, v in dict(AB=160, BC=200, CD=240, AD=210).items() if n != unknown} | {"frame": "AD"}
    assert template_form(R, g) == unknown
    en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
    assert f"lengths of {unknown}" in en and f"{unknown} 取何值" in zh and "{" not in en + zh
    for n, v in g.items():
        assert str(v) in en and str(v) in zh
