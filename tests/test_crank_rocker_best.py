"""``crank_rocker.best_by_K``: the design of largest γmin for K, ψ and the frame; construction (A* along the
θ-circles' arcs of a unit design) against the twin (the family in CD with the frame fixed) on random
instances, the issue's example, and optimality against neighbouring designs of the family."""
from __future__ import annotations

import random

import pytest

from geomcon.analytic.crank_rocker_best import designs_at
from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "crank_rocker.best_by_K"


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


def test_issue_example():
    sol = _solve(K=10 / 9, psi=80, AD=120)
    a = sol.answers
    assert (round(a["AB"], 2), round(a["BC"], 2), round(a["CD"], 2), round(a["gamma_min"], 2)) == (46.67, 116.16, 73.88, 37.73)
    assert all(r["ok"] for r in sol.checks)


@pytest.mark.parametrize("i", range(30))
def test_random_optima_match_the_twin(i):
    rng = random.Random(14700 + i)
    g = dict(K=rng.uniform(1.01, 3.0), psi=rng.uniform(10, 150), AD=rng.uniform(10, 500))
    sol = _solve(**g)
    for row in sol.checks:
        assert row["ok"], row
        scale = g["AD"] if row["unit"] == "mm" else 1.0
        assert abs(row["construction"] - row["analytic"]) <= 1e-9 * max(abs(row["analytic"]), scale), row
    a = sol.answers
    for f in (0.97, 0.99, 1.01, 1.03):                  # no neighbouring design of the family does better
        for d in designs_at(g["K"], g["psi"], g["AD"], a["CD"] * f):
            assert d["gamma_min"] <= a["gamma_min"] + 1e-9


def test_k_one_is_refused():
    from geomcon.errors import GeomconError
    with pytest.raises(GeomconError) as exc:
        _solve(K=1.0, psi=40, AD=100)
    assert "'K'" in str(exc.value)
    with pytest.raises(NotAMechanism):
        _solve(K=1.5, psi=190, AD=100)


def test_statement():
    from geomcon.worksheet.statements import default_template, fill, shown_givens
    g = dict(K=1.5, psi=40, AD=100)
    en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
    assert "K = 1.5" in en and "ψ = 40°" in zh and "{" not in en + zh
