"""Regression tests for defects the hostile fuzz found in the synthesis recipes: four_bar.function_generation
with AD = 1e9 (γmin from two sides of 1e9 mm that hold their difference only to the last bit, in both routes)
and back-substitutions that read NaN where the rebuilt linkage (at perturbed answers) cannot be assembled."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import mpmath
import pytest

from geomcon.analytic.fourbar_drive import assemble
from geomcon.problems import problem_from_dict
from geomcon.recipes import four_bar_function, four_bar_positions, rocker_slider
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"


def _given(stem: str) -> dict:
    with open(PROBLEMS / f"{stem}.toml", "rb") as fh:
        return tomllib.load(fh)


def _mp_function_generation(AD, AB, phi, psi):
    """(BC, CD, γmin) at 50 digits: Freudenstein's linear system, γ at the ends of the crank's arc (no full turn,
    the frame line not on the arc in the cases below)."""
    with mpmath.workdps(50):
        d, a = mpmath.mpf(AD), mpmath.mpf(AB)
        ph = [mpmath.radians(mpmath.mpf(v)) for v in phi]
        ps = [mpmath.radians(mpmath.mpf(v)) for v in psi]
        M = mpmath.matrix([[mpmath.cos(p) / a - mpmath.cos(f - p) / d, -(mpmath.sin(p) / a + mpmath.sin(f - p) / d), 1]
                           for f, p in zip(ph, ps)])
        U, V, W = mpmath.lu_solve(M, mpmath.matrix([mpmath.cos(f) for f in ph]))
        c = mpmath.sqrt(U * U + V * V)
        b = mpmath.sqrt(a * a + c * c + d * d - 2 * a * d * W)
        gammas = []
        for f in (ph[0], ph[2]):
            bd2 = a * a + d * d - 2 * a * d * mpmath.cos(f)
            g = mpmath.degrees(mpmath.acos((b * b + c * c - bd2) / (2 * b * c)))
            gammas.append(min(g, 180 - g))
        return float(b), float(c), float(min(gammas))


@pytest.mark.parametrize("AD", [80.0, 1e6, 1e8, 1e9])
def test_function_generation_with_a_long_frame(AD):
    """problems/100-06 with the frame stretched to 1e9 mm (BC ~ 1e9, CD ~ 150): γmin of the twin to 1e-11 of
    itself against 50 digits, the construction's to its C1 (the circumcentre of points 1e9 mm from A, beta
    to ~2e-7°), and no check fails."""
    g = {**_given("100-06_four_bar_function_log")["given"], "AD": AD}
    sol = solve(problem_from_dict({"recipe": "four_bar.function_generation", "given": g}, name="t"))
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    b, c, gamma = _mp_function_generation(AD, g["AB"], g["phi"], g["psi"])
    twin = sol.analytic[0]
    assert twin["gamma_min"] == pytest.approx(gamma, rel=1e-11)
    assert twin["CD"] == pytest.approx(c, rel=1e-12)
    assert sol.answers["gamma_min"] == pytest.approx(gamma, rel=1e-6 if AD >= 1e8 else 1e-9)
    assert all(math.isfinite(r["construction"]) for r in sol.checks)


def test_function_generation_back_check_is_finite_off_the_assembly_range():
    """The solver's condition of a back-substitution row rebuilds the linkage at answers moved by 1e-6 of
    themselves; at AD = 1e9 that is BC ± 1000 mm and the linkage cannot be assembled: the rows read the
    nearest dead point, a finite angle that misses, not NaN."""
    g = {**_given("100-06_four_bar_function_log")["given"], "AD": 1e9}
    ans = dict(solve(problem_from_dict({"recipe": "four_bar.function_generation", "given": g}, name="t")).answers)
    for k in (1 + 1e-6, 1 - 1e-6):
        rows = four_bar_function.back_check(g, {**ans, "BC": ans["BC"] * k})
        assert all(math.isfinite(v) for _, v, _, _ in rows)
        assert max(abs(v - want) for _, v, want, _ in rows) > 1e-3       # it misses, visibly


def test_assemble_nearest_is_the_dead_point_nearest_to_the_position():
    """BD = 103 > BC + CD = 20: C on the line D→B at CD from D; nested circles: C on the side nearest the
    other circle; assemblable positions are unchanged by ``nearest``."""
    A, D = (0.0, 0.0), (90.0, 0.0)
    B, C = assemble(A, D, 50.0, 10.0, 10.0, 90.0, +1, nearest=True)
    bd = math.dist(B, D)
    assert C == pytest.approx((D[0] + 10.0 * (B[0] - D[0]) / bd, D[1] + 10.0 * (B[1] - D[1]) / bd), rel=1e-15)
    B, C = assemble(A, D, 50.0, 500.0, 10.0, 90.0, +1, nearest=True)         # circle about D inside B's
    assert math.dist(B, C) == pytest.approx(math.dist(B, D) + 10.0, rel=1e-15)
    assert assemble(A, D, 50.0, 70.0, 80.0, 90.0, +1, nearest=True) == assemble(A, D, 50.0, 70.0, 80.0, 90.0, +1)


@pytest.mark.parametrize("stem,module,key", [("100-01_four_bar_three_positions", four_bar_positions, "BC"),
                                             ("100-07_rocker_slider_three_positions", rocker_slider, "EF")])
def test_other_back_checks_are_finite_off_the_assembly_range(stem, module, key):
    """A rebuilt linkage that cannot reach its positions (a rod 1/1000 of its length) reads finite numbers."""
    data = _given(stem)
    sol = solve(problem_from_dict({"recipe": data["recipe"], "given": data["given"]}, name="t"))
    ans = dict(sol.answers)
    recipe = module.RECIPE if module is four_bar_positions else module.THREE
    rows = recipe.back_check(sol.problem.given, {**ans, key: ans[key] * 1e-3})
    assert rows and all(math.isfinite(v) for _, v, _, _ in rows)


def test_rocker_slider_with_a_far_guide():
    """problems/100-08 with the guide 1e9 mm from D (found by the hostile fuzz, β 2.6e-6° apart): the twin's
    rows differenced before the squares of 1e9 are formed, β to 1e-12 of a 50-digit solution of the same
    equations G·(Q_i − Q_1) = (|P_i|² − |P_1|²)/2 (G = F1 − D, P_i = E_i − D, Q_i = P_i turned by ψ1 − ψi)."""
    data = _given("100-08_rocker_slider_inclined_guide")
    g = {**data["given"], "e": 1e9}
    sol = solve(problem_from_dict({"recipe": data["recipe"], "given": g}, name="t"))
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    with mpmath.workdps(50):
        Dx, Dy = (mpmath.mpf(v) for v in g["D"])
        a = mpmath.radians(g["guide_angle"])
        P = [(si * mpmath.cos(a) - Dx, g["e"] + si * mpmath.sin(a) - Dy) for si in map(mpmath.mpf, g["s"])]
        t = [mpmath.radians(g["psi"][0] - p) for p in g["psi"]]
        Q = [(x * mpmath.cos(ti) - y * mpmath.sin(ti), x * mpmath.sin(ti) + y * mpmath.cos(ti)) for (x, y), ti in zip(P, t)]
        M = mpmath.matrix([[Q[i][0] - Q[0][0], Q[i][1] - Q[0][1]] for i in (1, 2)])
        r = mpmath.matrix([(P[i][0] ** 2 + P[i][1] ** 2 - P[0][0] ** 2 - P[0][1] ** 2) / 2 for i in (1, 2)])
        G = mpmath.lu_solve(M, r)
        beta = float(mpmath.degrees(mpmath.atan2(G[1], G[0])) - g["psi"][0])
    assert sol.analytic[0]["beta"] == pytest.approx(beta, rel=1e-12)
    assert sol.answers["beta"] == pytest.approx(beta, rel=1e-7)      # the construction's F1 from points 1e9 mm out


def test_function_generation_with_every_angle_within_a_tenth_of_a_degree():
    """problems/100-06 with every given × 0.001 (found by the hostile fuzz): the U column of Freudenstein's
    system is the W column plus O(angle²); the twin's rows differenced as products of sines keep C1 and β to
    1e-12 of a 50-digit solution (the construction had them; the twin lost C1's height to 4e-4)."""
    data = _given("100-06_four_bar_function_log")
    g = {k: ([x * 1e-3 for x in v] if isinstance(v, list) else v * 1e-3) for k, v in data["given"].items()}
    sol = solve(problem_from_dict({"recipe": data["recipe"], "given": g}, name="t"))
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    with mpmath.workdps(50):
        d, a = mpmath.mpf(g["AD"]), mpmath.mpf(g["AB"])
        ph = [mpmath.radians(mpmath.mpf(v)) for v in g["phi"]]
        ps = [mpmath.radians(mpmath.mpf(v)) for v in g["psi"]]
        M = mpmath.matrix([[mpmath.cos(p) / a - mpmath.cos(f - p) / d, -(mpmath.sin(p) / a + mpmath.sin(f - p) / d), 1]
                           for f, p in zip(ph, ps)])
        U, V, _ = mpmath.lu_solve(M, mpmath.matrix([mpmath.cos(f) for f in ph]))
        y = float(U * mpmath.sin(ps[0]) + V * mpmath.cos(ps[0]))
        beta = float(mpmath.degrees(mpmath.atan2(V, U)) % 360)   # β in [0°, 360°), as the answer states it
    for values in (sol.answers, sol.analytic[0]):
        assert values["C1"][1] == pytest.approx(y, rel=1e-9)
        assert values["beta"] == pytest.approx(beta, rel=1e-12)


def test_function_generation_with_a_tiny_crank():
    """problems/100-06 with AB = 1e-6 (AD = 80; the hinge falls 5e-6 mm from D): the bisectors met in the
    drawing's coordinates held C1 only to the last bit of |D| (1e-14 mm), β 5.8e-7° and γmin 5.8e-7° off and
    the check failed (exit 1); the hinge found from D keeps β, CD and γmin to 1e-11 of 50 digits."""
    g = {**_given("100-06_four_bar_function_log")["given"], "AB": 1e-6}
    sol = solve(problem_from_dict({"recipe": "four_bar.function_generation", "given": g}, name="t"))
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    b, c, gamma = _mp_function_generation(g["AD"], g["AB"], g["phi"], g["psi"])
    with mpmath.workdps(50):
        d, a = mpmath.mpf(g["AD"]), mpmath.mpf(g["AB"])
        ph = [mpmath.radians(mpmath.mpf(v)) for v in g["phi"]]
        ps = [mpmath.radians(mpmath.mpf(v)) for v in g["psi"]]
        M = mpmath.matrix([[mpmath.cos(p) / a - mpmath.cos(f - p) / d, -(mpmath.sin(p) / a + mpmath.sin(f - p) / d), 1]
                           for f, p in zip(ph, ps)])
        U, V, _ = mpmath.lu_solve(M, mpmath.matrix([mpmath.cos(f) for f in ph]))
        beta = float(mpmath.degrees(mpmath.atan2(V, U)) % 360)   # β in [0°, 360°), as the answer states it
    for values in (sol.answers, sol.analytic[0]):
        assert values["beta"] == pytest.approx(beta, rel=1e-12)
        assert values["CD"] == pytest.approx(c, rel=1e-11)
        assert values["BC"] == pytest.approx(b, rel=1e-13)
        assert values["gamma_min"] == pytest.approx(gamma, rel=1e-11)
