"""Function generation and rocker–slider coordination: constructions against their twins on random designs
(fixed seed), the designs recovered, back-substitution, branch and order defects, degenerate refusals and
the sensitivities against finite differences."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.fourbar_drive import angle_of, assemble
from geomcon.analytic.function_generation import function_generation, solve3
from geomcon.analytic.rocker_slider import slider_position, three_positions
from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

FG = "four_bar.function_generation"
RS3 = "rocker_slider.three_positions"
RS2 = "rocker_slider.two_positions"


def _solve(recipe: str, **given):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="t"))


def _all_ok(sol) -> None:
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    assert any("back_substitution" in c["quantity"] for c in sol.checks)


def _psi_of(a, b, c, d, phis, branch):
    return [angle_of((d, 0.0), assemble((0.0, 0.0), (d, 0.0), a, b, c, f, branch)[1]) for f in phis]


def _random_crank_rocker(rng):
    while True:
        a = rng.uniform(10, 40)
        b, c, d = (rng.uniform(a + 15, 150) for _ in range(3))
        ls = sorted((a, b, c, d))
        if ls[0] == a and a + ls[3] < ls[1] + ls[2] - 5:
            return a, b, c, d


# ---------------------------------------------------------------- function generation
@pytest.mark.parametrize("i", range(30))
def test_random_function_generators_recover_the_design(i):
    rng = random.Random(5100 + i)
    a, b, c, d = _random_crank_rocker(rng)
    f1 = rng.uniform(0, 360)
    phis = [f1, f1 + rng.uniform(30, 120), f1 + rng.uniform(150, 300)]
    branch = rng.choice([1, -1])
    beta = rng.uniform(-180, 180)                       # the marked line DE is β away from DC
    psis = [p - beta for p in _psi_of(a, b, c, d, phis, branch)]
    sol = _solve(FG, AD=d, AB=a, phi=phis, psi=psis)
    _all_ok(sol)
    ans = sol.answers
    assert ans["BC"] == pytest.approx(b, rel=1e-9) and ans["CD"] == pytest.approx(c, rel=1e-9)
    assert math.isclose((ans["beta"] - beta + 180) % 360, 180, abs_tol=1e-7)
    assert ans["crank"] and ans["grashof"] and ans["branch_ok"] and ans["order_ok"]


def test_function_generator_freudenstein_textbook_form():
    """β = 0: the twin's unknowns are Freudenstein's K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac)."""
    a, b, c, d = 30.0, 90.0, 70.0, 100.0
    phis = [40.0, 90.0, 140.0]
    psis = _psi_of(a, b, c, d, phis, 1)
    K1, K2, K3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    for f, p in zip(phis, psis):
        f, p = math.radians(f), math.radians(p)
        assert K1 * math.cos(p) - K2 * math.cos(f) + K3 == pytest.approx(math.cos(f - p), abs=1e-12)
    r = function_generation(d, a, phis, psis)
    assert abs(r["beta"]) < 1e-9 and r["BC"] == pytest.approx(b, rel=1e-12)


def test_branch_defect_is_flagged_and_back_substituted_on_its_own_branch():
    a, b, c, d = 30.0, 90.0, 70.0, 100.0
    phis = [40.0, 90.0, 140.0]
    psis = _psi_of(a, b, c, d, phis[:2], 1) + _psi_of(a, b, c, d, phis[2:], -1)
    sol = _solve(FG, AD=d, AB=a, phi=phis, psi=psis)
    _all_ok(sol)
    assert sol.answers["branch_ok"] is False and sol.answers["order_ok"] is True
    assert any(w.startswith("branch defect") and "position 3: right" in w for w in sol.warnings)
    assert any(c["quantity"] == "back_substitution.psi[2].own_branch" for c in sol.checks)


def test_order_defect_is_flagged():
    a, b, c, d = 30.0, 97.8312, 44.7972, 80.0            # non-Grashof: AB only swings
    phis = [90.0, 55.359, 124.641]                       # from 90° down to 55°, then on to 124.6°: round the gap
    psis = _psi_of(a, b, c, d, phis, -1)
    sol = _solve(FG, AD=d, AB=a, phi=phis, psi=psis)
    _all_ok(sol)
    assert sol.answers["branch_ok"] is True and sol.answers["order_ok"] is False
    assert sol.answers["gamma_min"] == 0.0 and not sol.answers["crank"]
    assert any(w.startswith("order defect") for w in sol.warnings)


@pytest.mark.parametrize("given, words", [
    (dict(AD=100, AB=30, phi=[40, 90, 40], psi=[92, 105, 92]), ["positions 1 and 3 are the same"]),
    (dict(AD=100, AB=30, phi=[40, 90], psi=[92, 105]), ["phi must hold 3 angles"]),
    (dict(AD=100, AB=30, phi=[40, 90, 90], psi=[92, 105, 105 + 1e-8]), ["coincide"]),
])
def test_function_generation_refusals(given, words):
    with pytest.raises(NotAMechanism) as exc:
        _solve(FG, **given)
    for w in words:
        assert w in str(exc.value)


def _collinear_psi3(d, a, phis, psi12):
    """ψ3 making B1, B2′, B3′ collinear (bisection on the signed area)."""
    from geomcon.analytic.function_generation import inverted_pins

    def area(p3):
        P = inverted_pins(d, a, phis, (*psi12, p3))
        return (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[1][1] - P[0][1]) * (P[2][0] - P[0][0])

    lo, hi = psi12[1], psi12[1] + 180
    grid = [lo + k * (hi - lo) / 360 for k in range(361)]
    for x, y in zip(grid, grid[1:]):
        if area(x) * area(y) < 0:
            lo, hi = x, y
            break
    for _ in range(200):
        m = (lo + hi) / 2
        lo, hi = (m, hi) if area(lo) * area(m) > 0 else (lo, m)
    return (lo + hi) / 2


def test_collinear_inverted_points_refused_and_near_ones_warned():
    d, a, phis = 100.0, 30.0, [40.0, 90.0, 140.0]
    p3 = _collinear_psi3(d, a, phis, (92.0, 105.0))
    with pytest.raises(NotAMechanism, match="collinear"):
        _solve(FG, AD=d, AB=a, phi=phis, psi=[92.0, 105.0, p3])
    sol = _solve(FG, AD=d, AB=a, phi=phis, psi=[92.0, 105.0, p3 + 0.3])
    assert any("nearly collinear" in w for w in sol.warnings)
    _all_ok(sol)


def test_singular_freudenstein_system_refused():
    with pytest.raises(NotAMechanism, match="singular"):
        solve3([[1.0, 2.0, 1.0], [2.0, 4.0, 2.0], [0.0, 1.0, 1.0]], [1.0, 2.0, 3.0])


def test_sensitivity_matches_finite_differences():
    g = dict(AD=100.0, AB=30.0, phi=[40.0, 90.0, 140.0], psi=[92.16, 105.09, 125.96])
    base = function_generation(g["AD"], g["AB"], g["phi"], g["psi"])
    moves = []
    for key in ("phi", "psi"):
        for k in range(3):
            for h in (0.001, -0.001):
                v = list(g[key])
                v[k] += h
                r = function_generation(**{**g, key: v})
                moves.append(math.dist(r["C1"], base["C1"]) / abs(h) * 0.1)
    assert max(moves) == pytest.approx(base["sens_C1"], rel=1e-3)
    sol = _solve(FG, **g)
    assert sol.answers["sens_C1"] == pytest.approx(base["sens_C1"], rel=1e-9)


# ---------------------------------------------------------------- rocker–slider
def _slider_design(rng):
    D = (rng.uniform(-50, 50), rng.uniform(-50, 50))
    r, l = rng.uniform(30, 80), rng.uniform(90, 180)
    beta, alpha = rng.uniform(-180, 180), rng.uniform(-40, 40)
    h = rng.uniform(-0.8, 0.8) * (l - r)                 # D's height over the guide: the rod always reaches
    e = D[1] - h / math.cos(math.radians(alpha)) - D[0] * math.tan(math.radians(alpha))
    p1 = rng.uniform(0, 360)
    psis = [p1, p1 + rng.uniform(15, 40), p1 + rng.uniform(50, 80)]
    return D, r, l, beta, alpha, e, psis


def _pins(D, r, l, beta, alpha, e, psis, branches):
    out = []
    for p, br in zip(psis, branches):
        F = (D[0] + r * math.cos(math.radians(p + beta)), D[1] + r * math.sin(math.radians(p + beta)))
        s, ok = slider_position(F, l, e, alpha, br)
        assert ok
        out.append(s)
    return out


@pytest.mark.parametrize("i", range(30))
def test_random_rocker_sliders_recover_the_design(i):
    rng = random.Random(5200 + i)
    D, r, l, beta, alpha, e, psis = _slider_design(rng)
    br = rng.choice([1, -1])
    s = _pins(D, r, l, beta, alpha, e, psis, [br] * 3)
    sol = _solve(RS3, D=list(D), psi=psis, e=e, guide_angle=alpha, s=s)
    _all_ok(sol)
    ans = sol.answers
    assert ans["DF"] == pytest.approx(r, rel=1e-9) and ans["EF"] == pytest.approx(l, rel=1e-9)
    assert ans["branch_ok"]


@pytest.mark.parametrize("i", range(20))
def test_random_two_position_rocker_sliders(i):
    rng = random.Random(5300 + i)
    D, r, l, beta, alpha, e, psis = _slider_design(rng)
    s = _pins(D, r, l, beta, alpha, e, psis[:2], [1, 1])
    F1 = [D[0] + r * math.cos(math.radians(psis[0] + beta)), D[1] + r * math.sin(math.radians(psis[0] + beta))]
    offset = rng.uniform(-20, 20)                         # the slider's mark is not the pin
    try:
        sol = _solve(RS2, D=list(D), psi=psis[:2], F1=F1, e=e, guide_angle=alpha, s=[s[0] + offset, s[1] + offset])
    except NotAMechanism as exc:                          # a chord perpendicular to the guide: refused, never silent
        assert "perpendicular" in str(exc) or "coincides" in str(exc)
        return
    _all_ok(sol)
    assert sol.answers["EF"] == pytest.approx(l, rel=1e-8) and sol.answers["s_E1"] == pytest.approx(s[0], rel=1e-8, abs=1e-8 * l)


def test_rocker_slider_branch_defect():
    D, r, l, beta, alpha, e, psis = (0.0, 0.0), 60.0, 130.0, 0.0, 0.0, 45.0, [60.0, 80.0, 100.0]
    s = _pins(D, r, l, beta, alpha, e, psis, [1, 1, -1])
    sol = _solve(RS3, D=list(D), psi=psis, e=e, s=s)
    _all_ok(sol)
    assert not sol.answers["branch_ok"] and any(w.startswith("branch defect") for w in sol.warnings)
    # the pin's side along the guide is ahead or behind, not left or right (session j), said in Chinese too
    from geomcon.render.warning_words import warning_zh
    (w,) = [w for w in sol.warnings if w.startswith("branch defect")]
    assert "ahead" in w and "behind" in w and "left" not in w and "right" not in w, w
    assert "在前" in warning_zh(w) and "在后" in warning_zh(w)


def test_rocker_slider_order_defect():
    D, r, l, beta, alpha, e = (0.0, 0.0), 60.0, 130.0, 0.0, 0.0, 100.0   # the rod cannot follow a full turn
    psis = [80.0, 60.0, 100.0]                            # 80° → 60° clockwise, then on round to 100°
    s = _pins(D, r, l, beta, alpha, e, psis, [1, 1, 1])
    sol = _solve(RS3, D=list(D), psi=psis, e=e, s=s)
    _all_ok(sol)
    assert sol.answers["branch_ok"] and not sol.answers["order_ok"]
    assert any(w.startswith("order defect") for w in sol.warnings)
    twin = three_positions(D, psis, e, 0.0, s)
    assert not twin["order_ok"]


@pytest.mark.parametrize("recipe, given, words", [
    (RS3, dict(D=[0, 0], psi=[60, 60, 60], e=45, s=[10, 20, 30]), ["collinear"]),
    (RS3, dict(D=[0, 0], psi=[60, 80, 60], e=45, s=[10, 20, 10]), ["positions 1 and 3 are the same"]),
    (RS3, dict(D=[0, 0], psi=[60, 80], e=45, s=[10, 20]), ["psi must hold 3 angles"]),
    (RS2, dict(D=[0, 0], psi=[60, 60], F1=[30, 40], e=-20, s=[5, 5]), ["coincides with F1"]),
    (RS2, dict(D=[0, 0], psi=[0, 90], F1=[30, 0], e=-20, s=[0, -30]), ["perpendicular to the guide"]),
])
def test_rocker_slider_refusals(recipe, given, words):
    with pytest.raises(NotAMechanism) as exc:
        _solve(recipe, **given)
    for w in words:
        assert w in str(exc.value)


@pytest.mark.parametrize("name", ["100-05_four_bar_function_generation", "100-06_four_bar_function_log",
                                  "100-07_rocker_slider_three_positions", "100-08_rocker_slider_inclined_guide",
                                  "100-09_rocker_slider_two_positions"])
def test_bundled_problems_pass_every_check(name):
    from pathlib import Path

    from geomcon.problems import load_problem
    sol = solve(load_problem(Path(__file__).parent.parent / "problems" / f"{name}.toml"))
    _all_ok(sol)
    assert sol.answers["branch_ok"] and sol.answers["order_ok"]
    sol.svg()
