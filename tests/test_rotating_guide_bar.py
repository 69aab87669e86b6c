"""``rotating_guide_bar.extremes`` (Whitworth): construction against the twin on random instances, Khurmi's
example 5.4 and seed 001-09, the refusal of an oscillating guide bar."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "rotating_guide_bar.extremes"


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


@pytest.mark.parametrize("i", range(50))
def test_random_whitworths_match_the_twin(i):
    rng = random.Random(14400 + i)
    AC = rng.uniform(5, 300)
    given = dict(AB=AC * rng.uniform(1.001, 20.0), AC=AC)
    if rng.random() < 0.6:
        given["CD"] = rng.uniform(10, 500)
    sol = _solve(**given)
    assert sol.checks
    for row in sol.checks:
        assert row["ok"], row
        scale = sol.length_scale if row["unit"] == "mm" else 1.0
        assert abs(row["construction"] - row["analytic"]) <= 1e-9 * max(abs(row["analytic"]), scale), row
    a = sol.answers
    assert a["phi_slow"] + a["phi_quick"] == pytest.approx(360.0, abs=1e-9)
    assert a["K"] == pytest.approx((180 + a["theta"]) / (180 - a["theta"]), rel=1e-12)


def test_khurmi_example_5_4():
    a = _solve(AB=75, AC=50, CD=150).answers
    assert a["K"] == pytest.approx(2.735, abs=5e-4)
    assert a["phi_quick"] == pytest.approx(2 * math.degrees(math.acos(50 / 75)), rel=1e-12)
    assert a["S"] == pytest.approx(300, rel=1e-12)


def test_seed_001_09_stroke():
    a = _solve(AB=120, AC=100, CD=80).answers
    assert a["S"] == pytest.approx(160, rel=1e-12) and a["K"] == pytest.approx(4.364, abs=5e-4)


def test_oscillating_guide_bar_is_refused():
    with pytest.raises(NotAMechanism) as exc:
        _solve(AB=50, AC=75)
    assert "AB = 50 ≤ AC = 75" in str(exc.value) and "guide_bar.extremes" in str(exc.value)


def test_statement_forms():
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    for g, form in ((dict(AB=75, AC=50), ""), (dict(AB=75, AC=50, CD=150), "arm")):
        assert template_form(R, g) == form
        en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
        assert "{" not in en + zh and zh.endswith("。") and all(str(v) in en and str(v) in zh for v in g.values())
