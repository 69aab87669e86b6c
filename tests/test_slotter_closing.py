"""``slotter.design_by_K`` closing on the crank ``AB`` or the centre distance ``AC`` (the Whitworth design):
construction against the twin on random instances, back-substitution, the stroke 150 / crank 40 / K 2 case."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.errors import GeomconError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "slotter.design_by_K"


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


@pytest.mark.parametrize("i", range(40))
def test_random_whitworth_designs_match_the_twin(i):
    rng = random.Random(14800 + i)
    K = rng.uniform(1.01, 5.0)
    g = {"K": K, "H": rng.uniform(10, 500), rng.choice(["AB", "AC"]): rng.uniform(5, 300)}
    if rng.random() < 0.5:
        g["alpha_allow"] = rng.uniform(3, 40)
    sol = _solve(**g)
    for row in sol.checks:
        assert row["ok"], row
        scale = sol.length_scale if row["unit"] == "mm" else 1.0
        assert abs(row["construction"] - row["analytic"]) <= 1e-9 * max(abs(row["analytic"]), scale), row
    a = sol.answers
    th = math.radians(180 * (K - 1) / (K + 1))
    assert a["AC"] == pytest.approx(a["AB"] * math.sin(th / 2), rel=1e-12)
    assert a["CD"] == pytest.approx(g["H"] / 2, rel=1e-12)


def test_stroke_150_crank_40_k_2():
    a = _solve(K=2, H=150, AB=40).answers
    assert a["AC"] == pytest.approx(20, rel=1e-12) and a["CD"] == pytest.approx(75, rel=1e-12)
    assert a["B1B2"] == pytest.approx(80 * math.cos(math.radians(30)), rel=1e-12)
    same = _solve(K=2, H=150, AC=20).answers
    assert same["AB"] == pytest.approx(40, rel=1e-12)


def test_b1b2_form_is_unchanged():
    a = _solve(K=1.8, H=100, B1B2=120).answers
    assert "B1B2" not in a and a["AB"] == pytest.approx(60 / math.cos(math.radians(180 * 0.8 / 2.8 / 2)), rel=1e-12)


@pytest.mark.parametrize("given", [dict(K=2, H=150), dict(K=2, H=150, AB=40, AC=20), dict(K=2, H=150, AB=40, B1B2=60)])
def test_exactly_one_closing(given):
    with pytest.raises(GeomconError) as exc:
        _solve(**given)
    assert "exactly one of B1B2, AB, AC" in str(exc.value)


def test_statements():
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    # the B1B2 form has a statement of its own too now (tests/test_recipes_complete.py)
    for g, form in ((dict(K=2, H=150, AB=40), "AB"), (dict(K=2, H=150, AC=20), "AC"), (dict(K=2, H=150, B1B2=60), "B1B2")):
        assert template_form(R, g) == form
        en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
        assert "{" not in en + zh and all(str(v) in en and str(v) in zh for v in g.values())
