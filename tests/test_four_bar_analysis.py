"""``four_bar.analysis``: the chain's type with any frame, its turning joints, θ/ψ/K, γmin, dead points, γ
and α at a position; construction against the twin on random chains, the seeds, and the boundary cases."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.four_bar_analysis import four_bar_analysis, joint_turns_fully
from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

R = "four_bar.analysis"


def _solve(**given):
    return solve(problem_from_dict({"recipe": R, "given": given}, name="t"))


def _assert_twin(sol, rel=1e-9):
    assert sol.checks
    for row in sol.checks:
        assert row["ok"], row
        if isinstance(row["construction"], (int, float)) and not isinstance(row["construction"], bool):
            assert abs(row["construction"] - row["analytic"]) <= rel * max(abs(row["analytic"]), 90.0), row


@pytest.mark.parametrize("i", range(80))
def test_random_chains_match_the_twin(i):
    rng = random.Random(14000 + i)
    L = {n: rng.uniform(5, 200) for n in ("AB", "BC", "CD", "AD")}
    frame = rng.choice(["AB", "BC", "CD", "AD"])
    given = {**L, "frame": frame, "branch": rng.choice(["above", "below"])}
    if rng.random() < 0.5:
        given["driver"] = {"AD": "CD", "AB": "AD", "BC": "AB", "CD": "BC"}[frame]
    sol = _solve(**given)
    _assert_twin(sol)
    s = sorted(L.values())
    assert sol.answers["grashof"] == (s[0] + s[3] <= s[1] + s[2])
    if s[3] < s[0] + s[1] + s[2]:
        # a random position the driver reaches: γ and α at phi, α = 90° − γ
        for _ in range(20):
            phi = rng.uniform(0, 360)
            try:
                sol = _solve(**given, phi=phi)
            except NotAMechanism:
                continue
            _assert_twin(sol)
            assert sol.answers["alpha"] == pytest.approx(90 - sol.answers["gamma"], abs=1e-12)
            break


def _turns_fully_by_sampling(x, y, z, w, n=20000):
    """Drive the joint between x and y through 360° and see whether the dyad z, w closes everywhere."""
    for k in range(n):
        a = 2 * math.pi * k / n
        diag = math.sqrt(x * x + y * y - 2 * x * y * math.cos(a))
        if not abs(z - w) <= diag <= z + w:
            return False
    return True


@pytest.mark.parametrize("i", range(40))
def test_joint_rule_agrees_with_driving_the_chain(i):
    rng = random.Random(14500 + i)
    x, y, z, w = (rng.uniform(5, 100) for _ in range(4))
    s = sorted((x, y, z, w))
    if s[3] >= s[0] + s[1] + s[2]:
        return
    assert joint_turns_fully(x, y, z, w) == _turns_fully_by_sampling(x, y, z, w)


def test_seed_001_03_inversions_of_one_chain():
    L = dict(AB=28, BC=52, CD=50, AD=72)
    a = _solve(**L)
    assert a.answers["type"] == "crank-rocker" and a.answers["grashof"]
    assert (a.answers["A_full"], a.answers["B_full"], a.answers["C_full"], a.answers["D_full"]) == (True, True, False, False)
    assert a.answers["theta"] == pytest.approx(18.5617, abs=1e-4)
    assert a.answers["psi"] == pytest.approx(70.5582, abs=1e-4)
    assert a.answers["K"] == pytest.approx(1.23, abs=1e-3)
    assert a.answers["gamma_min"] == pytest.approx(22.7342, abs=1e-4)
    b = _solve(**L, frame="AB")
    assert b.answers["type"] == "double-crank" and b.answers["A_full"] and b.answers["B_full"]
    assert "theta" not in b.answers
    c = _solve(**L, frame="CD")
    assert c.answers["type"] == "double-rocker" and not c.answers["C_full"] and not c.answers["D_full"]
    assert c.answers["dead_points"] and c.answers["gamma_min"] == pytest.approx(0, abs=1e-9)
    for s in (a, b, c):
        _assert_twin(s)


def test_heu_double_rocker_driven_by_the_rocker():
    sol = _solve(AB=50, BC=50, CD=30, AD=90, driver="CD", phi=90)
    _assert_twin(sol)
    assert sol.answers["type"] == "double-rocker" and not sol.answers["grashof"]
    assert sol.answers["alpha"] == pytest.approx(math.degrees(math.atan2(4, 3)), abs=1e-9)      # 53.13°
    assert sol.answers["dead_points"] and sol.answers["gamma_min"] == pytest.approx(0, abs=1e-9)   # α = 90° reached
    p = sol.points
    assert p["B"] == pytest.approx((40, 30), abs=1e-9) and p["C"] == pytest.approx((90, 30), abs=1e-9)


def test_crank_rocker_agrees_with_the_extremes_recipe():
    g = dict(AB=50, BC=70, CD=80, AD=90)
    ex = solve(problem_from_dict({"recipe": "crank_rocker.extremes", "given": g}, name="t")).answers
    an = _solve(**g).answers
    for k in ("theta", "psi", "K", "gamma_min"):
        assert an[k] == pytest.approx(ex[k], rel=1e-12)
    assert not an["dead_points"]
    assert _solve(**g, driver="CD").answers["dead_points"]        # the rocker drives: dead points


def test_rocker_crank_has_its_crank_at_D():
    sol = _solve(AB=70, BC=80, CD=50, AD=90)
    _assert_twin(sol)
    assert sol.answers["type"] == "crank-rocker" and sol.answers["output_crank"] and not sol.answers["input_crank"]
    assert sol.answers["dead_points"]                              # AB (a rocker) drives by default


@pytest.mark.parametrize("given, kind", [
    (dict(AB=15, BC=50, CD=35, AD=30), "change-point"),          # 15 + 50 = 35 + 30 (seed 001-01)
    (dict(AB=40, BC=90, CD=40, AD=90), "change-point"),          # parallelogram
    (dict(AB=10, BC=20, CD=30, AD=60), "immovable"),             # 60 = 10 + 20 + 30: flat
    (dict(AB=10, BC=20, CD=30, AD=500), "immovable"),
    (dict(AB=35, BC=50, CD=60, AD=20), "double-crank"),
    (dict(AB=60, BC=20, CD=50, AD=55), "double-rocker"),         # coupler shortest, Grashof
])
def test_boundary_and_degenerate_chains_are_classified_not_refused(given, kind):
    sol = _solve(**given)
    assert sol.answers["type"] == kind
    _assert_twin(sol)


def test_change_point_crank_keeps_theta_and_has_gamma_zero():
    sol = _solve(AB=15, BC=50, CD=35, AD=30)
    assert sol.answers["theta"] == pytest.approx(64.6231, abs=1e-4)
    assert sol.answers["gamma_min"] == pytest.approx(0, abs=1e-6)
    assert any("change-point" in w for w in sol.warnings)


@pytest.mark.parametrize("given, words", [
    (dict(AB=50, BC=50, CD=30, AD=90, phi=180), ["phi = 180", "cannot be assembled", "[20, 80]"]),
    (dict(AB=50, BC=70, CD=80, AD=90, driver="BC"), ["driver = BC", "AB and CD"]),
    (dict(AB=10, BC=20, CD=30, AD=500, phi=10), ["cannot be assembled"]),
])
def test_impossible_positions_are_refused_with_numbers(given, words):
    with pytest.raises(NotAMechanism) as exc:
        _solve(**given)
    for w in words:
        assert w in str(exc.value)


def test_crank_forms_name_the_failed_grashof_sum():
    with pytest.raises(NotAMechanism) as exc:
        solve(problem_from_dict({"recipe": "crank_rocker.extremes",
                                 "given": dict(AB=50, BC=50, CD=30, AD=90)}, name="t"))
    assert "30 + 90 > 50 + 50" in str(exc.value) and "strictly shortest" not in str(exc.value)


def test_statement_in_both_languages():
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    g = dict(AB=28, BC=52, CD=50, AD=72, frame="CD")
    assert template_form(R, g) == ""
    en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
    assert "with CD fixed as the frame" in en and "以 CD 为机架" in zh and zh.endswith("。")
