"""Design by K: every recipe against its closed-form twin on random problems (fixed seed), the
back-substitution of every solution through the core's extreme-position constructions, the seed answers,
and the edge cases (K = 1, K near 3 and beyond, e at its largest value, closing conditions off the circle,
huge and tiny scales)."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.errors import GeomconError, NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve


def _solve(recipe: str, **given):
    return solve(problem_from_dict({"recipe": recipe, "given": given}, name="t"))


def _assert_all_checks(sol):
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    assert any(c["quantity"].split(".")[-2:-1] == ["back_substitution"] or "back_substitution" in c["quantity"]
               for c in sol.checks)


# ---------------------------------------------------------------- crank-slider
@pytest.mark.parametrize("i", range(40))
def test_random_crank_slider_designs(i):
    rng = random.Random(4000 + i)
    K, H = rng.uniform(1.02, 2.8), rng.uniform(5, 500)
    th = math.radians(180 * (K - 1) / (K + 1))
    which = rng.choice(["e", "AB", "BC"])
    t = rng.uniform(0.05, 0.95)
    value = {"e": t * H / math.tan(th),
             "AB": H / 2 * math.tan(th / 2) + t * (H / 2 - H / 2 * math.tan(th / 2)),
             "BC": H / 2 + t * (H / 2 / math.tan(th / 2) - H / 2)}[which]
    sol = _solve("crank_slider.design_by_K", K=K, H=H, **{which: value})
    _assert_all_checks(sol)
    assert sol.answers[which] == pytest.approx(value, rel=1e-9)


def test_crank_slider_design_seed_001_18():
    a = _solve("crank_slider.design_by_K", K=1.5, H=50, e=20).answers
    assert a["AB"] == pytest.approx(21.5067, abs=1e-4) and a["BC"] == pytest.approx(46.5171, abs=1e-4)
    assert a["alpha_max"] == pytest.approx(63.1624, abs=1e-4)


def test_crank_slider_design_at_the_end_of_the_arc_is_tangent():
    K, H = 1.5, 50
    e_max = H / math.tan(math.radians(36))
    sol = _solve("crank_slider.design_by_K", K=K, H=H, e=e_max)
    assert sol.answers["alpha_max"] == pytest.approx(90, abs=1e-5)
    assert any("end Q" in w for w in sol.warnings)


@pytest.mark.parametrize("given, words", [
    (dict(K=1.5, H=50, e=80), ["e = 80", "(0, 68.8191]"]),
    (dict(K=1.5, H=50, AB=30), ["AB = 30", "[8.12299, 25)"]),
    (dict(K=1.5, H=50, BC=200), ["BC = 200", "(25, 76.9421]"]),
    (dict(K=2.9975, H=50, e=10), ["≤ 2.99746", "2.9975"]),
    (dict(K=1.5, H=50), ["exactly one of e, AB, BC"]),
    (dict(K=1.5, H=50, e=10, AB=20), ["exactly one of e, AB, BC"]),
    (dict(K=1.0, H=50, e=10), ["K = 1"]),
])
def test_crank_slider_design_refusals_name_the_range(given, words):
    with pytest.raises(GeomconError) as exc:
        _solve("crank_slider.design_by_K", **given)
    for w in words:
        assert w in str(exc.value)


@pytest.mark.parametrize("K", [1.0, 1.00065, 1.001, 1.01])
def test_crank_slider_design_K_to_one(K):
    sol = _solve("crank_slider.design_by_K", K=K, H=50, BC=60)
    _assert_all_checks(sol)
    assert sol.answers["AB"] == pytest.approx(25, rel=1e-3)


@pytest.mark.parametrize("recipe, given", [
    ("crank_slider.design_by_K", dict(H=50, BC=60)),
    ("crank_rocker.design_by_K", dict(CD=290, psi=32, BC=260)),
    ("guide_bar.design_by_K", dict(AC=100)),
])
@pytest.mark.parametrize("K", [1.0 + 1e-12, 1.0 + 1e-9, 1.0 + 1e-6, 1.0006])
def test_K_just_above_one_is_refused_clearly(recipe, given, K):
    with pytest.raises(NotAMechanism, match="give K = 1"):
        _solve(recipe, K=K, **given)


@pytest.mark.parametrize("K", [2.5, 2.9, 2.99, 2.9974])
def test_crank_slider_design_K_near_three(K):
    th = math.radians(180 * (K - 1) / (K + 1))
    sol = _solve("crank_slider.design_by_K", K=K, H=50, e=0.5 * 50 / math.tan(th))
    _assert_all_checks(sol)


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e6])
def test_crank_slider_design_scales(scale):
    base = _solve("crank_slider.design_by_K", K=1.5, H=50, e=20).answers
    sol = _solve("crank_slider.design_by_K", K=1.5, H=50 * scale, e=20 * scale)
    _assert_all_checks(sol)
    assert sol.answers["AB"] == pytest.approx(base["AB"] * scale, rel=1e-12)
    assert sol.answers["alpha_max"] == pytest.approx(base["alpha_max"], rel=1e-12)


def test_gamma_allow_warns_when_the_design_is_below_it():
    sol = _solve("crank_slider.design_by_K", K=1.5, H=50, e=20, gamma_allow=40)
    assert any("below gamma_allow" in w for w in sol.warnings)


# ---------------------------------------------------------------- crank-rocker
SEEDS = [  # (given, expected answers of the textbook's choice, number of solutions)
    (dict(K=1.25, CD=290, psi=32, BC=260), dict(AB=66.9811, AD=261.0127), 2),
    (dict(K=1.2, CD=300, psi=35, AB=80), dict(BC=303.6776, AD=309.2894), 2),
    (dict(K=1.4, CD=300, psi=35, AC1=225), dict(AB=55.4551, BC=280.4551, AD=188.6790), 4),
    (dict(K=1.4, CD=500, phi1=90, phi2=45, frame_line=True), dict(AB=82.3549, BC=672.3694, AD=313.2364), 2),
    (dict(K=1, CD=525, psi=30, AD=800), dict(AB=135.8800, BC=618.7393), 1),
    (dict(K=1, CD=50, phi1=30, phi2=90, frame_line=True), dict(AB=25, BC=75, AD=86.6025), 1),
    (dict(K=1.5, CD=75, AD=100, phi=45), dict(AB=49.3118, BC=120.1524), 2),
    (dict(K=1.5, CD=85, AD=120, phi=45), dict(AB=58.2456, BC=143.0986), 2),
]


@pytest.mark.parametrize("given, expected, n", SEEDS)
def test_crank_rocker_design_seeds(given, expected, n):
    sol = _solve("crank_rocker.design_by_K", **given)
    _assert_all_checks(sol)
    assert len(sol.solution_values) == n
    for k, v in expected.items():
        assert sol.answers[k] == pytest.approx(v, abs=1e-4)


def _random_crank_rocker(rng: random.Random) -> tuple[float, ...]:
    """AB, BC, CD, AD of a random Grashof crank-rocker (5 mm from the Grashof limit) and its own K and ψ."""
    while True:
        AB = rng.uniform(10, 50)
        BC, CD, AD = (rng.uniform(AB * 1.2, 300) for _ in range(3))
        ls = sorted([BC, CD, AD])
        if AB + ls[2] < ls[0] + ls[1] - 5:
            break
    ex = _solve("crank_rocker.extremes", AB=AB, BC=BC, CD=CD, AD=AD)
    K, psi = ex.answers["K"], ex.answers["psi"]
    return AB, BC, CD, AD, K, psi


@pytest.mark.parametrize("i", range(40))
def test_random_crank_rocker_designs(i):
    rng = random.Random(5000 + i)
    # a random crank-rocker gives its own K, ψ and closing values: the design must find it again
    AB, BC, CD, AD, K, psi = _random_crank_rocker(rng)
    if K < 1 + 1e-6:
        pytest.skip("this random linkage has no quick return")
    which = rng.choice(["BC", "AB"])
    sol = _solve("crank_rocker.design_by_K", K=K, CD=CD, psi=psi, **{which: {"BC": BC, "AB": AB}[which]})
    _assert_all_checks(sol)
    found = [s for s in sol.solution_values if abs(s["AD"] - AD) <= 1e-6 * AD]
    assert found, (AD, [s["AD"] for s in sol.solution_values])
    assert found[0]["AB"] == pytest.approx(AB, rel=1e-8) and found[0]["BC"] == pytest.approx(BC, rel=1e-8)


@pytest.mark.parametrize("i", range(30))
def test_random_crank_rocker_links_form(i):
    """Links form (AB, BC, K, ψ → CD, AD): a random crank-rocker's own K and ψ must give its CD and AD back."""
    rng = random.Random(7000 + i)
    AB, BC, CD, AD, K, psi = _random_crank_rocker(rng)
    if K < 1 + 1e-3:
        pytest.skip("this random linkage has (almost) no quick return")
    sol = _solve("crank_rocker.design_by_K", K=K, AB=AB, BC=BC, psi=psi)
    _assert_all_checks(sol)
    found = [s for s in sol.solution_values if abs(s["AD"] - AD) <= 1e-7 * AD]
    assert found, (AD, [s["AD"] for s in sol.solution_values])
    assert found[0]["CD"] == pytest.approx(CD, rel=1e-8)


def test_crank_rocker_links_form_seed_001_17():
    sol = _solve("crank_rocker.design_by_K", K=1.1155098391166032, AB=240, BC=600, psi=45)
    _assert_all_checks(sol)
    assert [round(s["AD"], 2) for s in sol.solution_values] == [762.77, 911.62]
    assert {round(s["CD"], 2) for s in sol.solution_values} == {639.12}


def test_crank_rocker_design_refuses_a_coupler_no_point_satisfies():
    with pytest.raises(NotAMechanism) as exc:
        _solve("crank_rocker.design_by_K", K=1.25, CD=290, psi=32, BC=10).answers
    assert "BC = 10" in str(exc.value)


@pytest.mark.parametrize("given, words", [
    (dict(K=1.25, CD=290, BC=260), ["extreme positions"]),
    (dict(K=1.25, CD=290, psi=32), ["exactly one closing condition"]),
    (dict(K=1.25, CD=290, psi=32, BC=260, AB=60), ["exactly one closing condition"]),
    (dict(K=1.25, CD=290, psi=200, BC=260), ["psi = 200"]),
    (dict(K=1.25, CD=290, psi=32, frame_line=True), ["frame_line needs"]),
    (dict(K=1.25, psi=32, BC=260), ["without CD"]),
    (dict(K=1.0, psi=32, BC=260, AB=60), ["K > 1"]),
    (dict(K=1.25, psi=32, BC=60, AB=60), ["AB = 60 must be shorter"]),
])
def test_crank_rocker_design_bad_forms(given, words):
    with pytest.raises(NotAMechanism) as exc:
        _solve("crank_rocker.design_by_K", **given)
    for w in words:
        assert w in str(exc.value)


# ---------------------------------------------------------------- guide bars and shapers
@pytest.mark.parametrize("i", range(20))
def test_random_guide_bar_and_shaper_designs(i):
    rng = random.Random(6000 + i)
    K = rng.uniform(1.05, 2.9)
    which = rng.choice(["AC", "AB"])
    v = rng.uniform(10, 400)
    _assert_all_checks(_solve("guide_bar.design_by_K", K=K, **{which: v}))
    extra = rng.choice([{}, {"alpha_allow": rng.uniform(5, 40)}, {"DE": rng.uniform(400, 900)}])
    _assert_all_checks(_solve("shaper.design_by_K", K=K, H=rng.uniform(50, 500), **{which: v}, **extra))


def test_shaper_seed_001_20():
    a = _solve("shaper.design_by_K", K=2, H=300, AB=75, DE=100).answers
    assert (a["AC"], a["CD"]) == (pytest.approx(150), pytest.approx(300))
    assert a["h"] == pytest.approx(279.9038, abs=1e-4) and a["alpha_max"] == pytest.approx(11.5932, abs=1e-4)


# ---------------------------------------------------------------- the optimum of seed 004
SEED_004 = {1.05: (49.6035, 171.403, 20.6058, 80.2599), 1.2: (48.9077, 87.8994, 15.0286, 67.3296),
            1.5: (48.5932, 61.7558, 8.5375, 49.5627), 1.7: (48.7431, 56.2763, 5.7545, 40.1922)}


@pytest.mark.parametrize("K", sorted(SEED_004))
def test_best_by_K_matches_the_seeds_independent_table(K):
    sol = _solve("crank_slider.best_by_K", K=K, H=100)
    _assert_all_checks(sol)
    a = sol.answers
    for got, want in zip((a["AB"], a["BC"], a["e"], a["gamma_w_min"]), SEED_004[K]):
        assert got == pytest.approx(want, rel=5e-6, abs=6e-5)   # the seed prints 6 digits or 4 decimals
    assert 48 <= a["AB"] < 50                     # the paper's legible a* column: 48 or 49 mm
    assert a["gamma_min"] < a["gamma_w_min"]      # the cycle's γmin falls in the return stroke


@pytest.mark.parametrize("K", [1.1, 1.35, 1.6])
def test_best_by_K_beats_every_point_of_a_dense_scan(K):
    from geomcon.analytic.design_by_k import working_stroke_gamma
    best = _solve("crank_slider.best_by_K", K=K, H=100).answers["gamma_w_min"]
    th = math.radians(180 * (K - 1) / (K + 1))
    lo, hi = 50 * math.tan(th / 2), 50.0
    scan = max(working_stroke_gamma(K, 100, lo + (hi - lo) * i / 20000)[0] for i in range(1, 20000))
    assert best >= scan - 1e-9 and best - scan < 0.02      # the optimum is a kink: the grid only nears it


def test_best_by_K_respects_the_offset_band():
    a = _solve("crank_slider.best_by_K", K=1.2, H=100, e_max=12).answers
    assert a["e"] == pytest.approx(12, abs=1e-9)
    free = _solve("crank_slider.best_by_K", K=1.2, H=100).answers
    assert a["gamma_w_min"] < free["gamma_w_min"]
    with pytest.raises(NotAMechanism, match="e_min"):
        _solve("crank_slider.best_by_K", K=1.5, H=100, e_min=200)      # H·cot θ = 137.6


def test_the_chosen_crank_rocker_pivot_lies_on_an_admissible_arc():
    sol = _solve("crank_rocker.design_by_K", K=1.2, CD=300, psi=35, AB=80, gamma_allow=40)
    arcs = sol.scene.value("narcs_ok")
    A = sol.scene.value("A")
    assert arcs and all(abs(abs(A - a.center) - a.r) < 1e-9 * a.r for a in arcs[:1])
    ang = math.atan2(A.y - arcs[0].center.y, A.x - arcs[0].center.x)
    assert any((ang - a.start) % (2 * math.pi) <= a.sweep for a in arcs)
    assert sol.scene.value("farcs_ok") == ()        # the far design has γmin = 32.9° < 40°


@pytest.mark.parametrize("i", range(10))
def test_random_slotter_designs(i):
    rng = random.Random(7000 + i)
    sol = _solve("slotter.design_by_K", K=rng.uniform(1.05, 2.5), H=rng.uniform(50, 300),
                 B1B2=rng.uniform(100, 600), alpha_allow=rng.uniform(5, 30))
    _assert_all_checks(sol)


def test_slotter_seed_001_19():
    a = _solve("slotter.design_by_K", K=1.5, H=154, B1B2=308, alpha_allow=10).answers
    assert (round(a["AB"], 2), round(a["AC"], 2), a["CD"], round(a["DE"], 1)) == (161.93, 50.04, 77.0, 443.4)


def test_output_arm_of_the_cutter_drive_seed_001_21():
    sol = _solve("crank_rocker.design_by_K", K=1, CD=200, phi1=140, phi2=95, frame_line=True, H_out=300)
    _assert_all_checks(sol)
    assert sol.answers["DE"] == pytest.approx(300 / (2 * math.sin(math.radians(22.5))), rel=1e-12)
    E1, E2 = (sol.scene.evaluate([k])[k] for k in ("E1", "E2"))
    assert abs(E2 - E1) == pytest.approx(300, rel=1e-12)


def test_output_arm_needs_the_positions_form():
    with pytest.raises(NotAMechanism, match="H_out"):
        _solve("crank_rocker.design_by_K", K=1.2, CD=50, AD=80, phi=60, H_out=30)


@pytest.mark.parametrize("recipe, given, limit", [
    ("crank_slider.design_by_K", dict(H=50, e=10), "2.99746"),
    ("crank_slider.best_by_K", dict(H=50), "2.99746"),
    ("guide_bar.design_by_K", dict(AC=50), "3"),
    ("shaper.design_by_K", dict(H=50, AC=50), "3"),
    ("slotter.design_by_K", dict(H=50, B1B2=30), "6282.19"),
    ("crank_rocker.design_by_K", dict(CD=50, psi=40, BC=50), "6282.19"),
])
def test_every_design_by_K_names_its_largest_K(recipe, given, limit):
    with pytest.raises(GeomconError, match=f"'K' must be ≤ {limit}, got"):
        _solve(recipe, K=1e12, **given)


# ---------------------------------------------------------------- the golden-section search
def _golden_every_step(f, lo, hi, width, iterations):
    """The search as written before it learned to stop at a cycle: every step taken."""
    from geomcon.recipes.search import _GOLD
    x1, x2 = hi - _GOLD * (hi - lo), lo + _GOLD * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(iterations):
        if f1 < f2:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + _GOLD * (hi - lo)
            f2 = f(x2)
        else:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - _GOLD * (hi - lo)
            f1 = f(x1)
        if hi - lo <= width:
            break
    return (lo + hi) / 2


@pytest.mark.parametrize("i", range(30))
def test_golden_search_stopping_at_its_cycle_gives_every_steps_result(i):
    from geomcon.recipes.search import maximise
    rng = random.Random(9100 + i)
    c, k = rng.uniform(-5, 5), rng.uniform(0.1, 10)
    lo, hi = c - rng.uniform(0, 3), c + rng.uniform(0, 3)
    f = rng.choice((lambda t: -abs(t - c) * k, lambda t: -k * (t - c) ** 2, lambda t: min(t - c, k * (c - t)),
                    lambda t: round(-(t - c) ** 2, 3)))                      # kinks, plateaus of equal values
    for width, n in ((0.0, 400), (0.0, 401), (0.0, 97), (4e-16, 200), (1e-9, 60)):
        assert maximise(f, lo, hi, width=width, iterations=n) == _golden_every_step(f, lo, hi, width, n)
