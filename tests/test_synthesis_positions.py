"""Three-position synthesis of a four-bar (moving pivots given; fixed pivots given, by inversion): designed
linkages recovered to 1e-9 from random positions (fixed seed), construction vs twin, back-substitution,
the branch and order defects on designs made to have them, near-degenerate input, sensitivities, the CLI."""
from __future__ import annotations

import math
import random
from pathlib import Path

import pytest

from geomcon.analytic.fourbar_drive import angle_of, arc_through, assemble, bd_extremes, dead_point_free
from geomcon.analytic.synthesis import circumcentre, three_positions
from geomcon.cli import main
from geomcon.errors import NotAMechanism
from geomcon.problems import load_problem, problem_from_dict
from geomcon.solve import solve

PROBLEMS = Path(__file__).parent.parent / "problems"
R1, R2 = "four_bar.three_positions", "four_bar.three_positions_fixed_pivots"


def _solve(recipe: str, **given):
    return solve(problem_from_dict({"recipe": recipe, "given": {k: list(v) if isinstance(v, tuple) else v
                                                                   for k, v in given.items()}}, name="t"))


def _all_ok(sol):
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    assert sum("back_substitution" in c["quantity"] for c in sol.checks) >= 9


def _linkage(rng: random.Random, crank: bool):
    """A random four-bar (A, D, AB, BC, CD) that can be assembled; a crank-rocker when ``crank``."""
    while True:
        A = (rng.uniform(-100, 100), rng.uniform(-100, 100))
        AD = rng.uniform(40, 120)
        t = rng.uniform(-math.pi, math.pi)
        D = (A[0] + AD * math.cos(t), A[1] + AD * math.sin(t))
        AB, BC, CD = (rng.uniform(0.15, 0.45) * AD if crank else rng.uniform(0.3, 1.2) * AD,
                      rng.uniform(0.5, 1.5) * AD, rng.uniform(0.5, 1.5) * AD)
        ls = sorted((AB, BC, CD, AD))
        grashof_crank = ls[0] == AB and ls[0] + ls[3] < ls[1] + ls[2] - 1e-3 * AD
        if crank == grashof_crank:
            return A, D, AB, BC, CD


def _positions(rng, A, D, AB, BC, CD, branch, spread=(20, 50)):
    """Three assembled positions at increasing crank angles (or None when one cannot be assembled)."""
    phi = rng.uniform(-180, 180)
    out = []
    for k in range(3):
        got = assemble(A, D, AB, BC, CD, phi, branch)
        if got is None:
            return None
        out.append(got)
        phi += rng.uniform(*spread)
    return out


def _clean(rng, crank=True):
    """A design whose three positions are reached in order on one branch and are well conditioned."""
    while True:
        A, D, AB, BC, CD = _linkage(rng, crank)
        pos = _positions(rng, A, D, AB, BC, CD, rng.choice((1, -1)))
        if pos is None:
            continue
        r = three_positions(*(p[0] for p in pos), *(p[1] for p in pos))
        if r["branch_ok"] and r["order_ok"] and r["sens_A"] < 5 and r["sens_D"] < 5:
            return A, D, AB, BC, CD, pos


# ----------------------------------------------------------------------------------------- moving pivots given
@pytest.mark.parametrize("i", range(30))
def test_random_designs_are_recovered(i):
    rng = random.Random(8100 + i)
    A, D, AB, BC, CD, pos = _clean(rng, crank=i % 3 != 0)
    g = {f"B{k}": p[0] for k, p in enumerate(pos, 1)} | {f"C{k}": p[1] for k, p in enumerate(pos, 1)}
    sol = _solve(R1, **g)
    _all_ok(sol)
    a = sol.answers
    for name, want in (("AB", AB), ("BC", BC), ("CD", CD), ("AD", math.dist(A, D))):
        assert a[name] == pytest.approx(want, rel=1e-9), name
    for name, want in (("A", A), ("D", D)):
        assert math.dist(sol.points[name], want) <= 1e-9 * math.dist(A, D) + 1e-9, name
    assert a["branch_ok"] and a["order_ok"] and not sol.warnings


def test_twin_circumcentre_is_the_bisector_meet():
    assert circumcentre((0.0, 0.0), (4.0, 0.0), (0.0, 3.0)) == (2.0, 1.5)


def test_sensitivity_agrees_with_finite_differences():
    B = [(0.0, 30.0), (-20.0, 40.0), (-45.0, 35.0)]
    worst = 0.0
    for k in range(3):
        for t in range(0, 360, 3):
            moved = [list(p) for p in B]
            moved[k][0] += 1e-4 * math.cos(math.radians(t))
            moved[k][1] += 1e-4 * math.sin(math.radians(t))
            worst = max(worst, math.dist(circumcentre(*moved), circumcentre(*B)) * 1e3)     # per 0.1 mm
    r = three_positions(*B, (60.0, 60.0), (50.0, 84.0), (34.0, 101.0))
    assert r["sens_A"] == pytest.approx(worst, rel=1e-3)      # 3° steps of direction, 1e-4 mm: linear


# ----------------------------------------------------------------------------------------- fixed pivots given
@pytest.mark.parametrize("i", range(30))
def test_random_inversions_recover_the_hinge(i):
    rng = random.Random(8200 + i)
    A, D, AB, BC, CD, pos = _clean(rng, crank=i % 3 != 0)
    Bs = [p[0] for p in pos]
    if i % 2:       # a coupler point K off the line BC, rigidly attached
        s, t = rng.uniform(-1, 1), rng.uniform(0.2, 1.0)
        Ks = []
        for B, C in pos:
            u = ((C[0] - B[0]) / BC, (C[1] - B[1]) / BC)
            Ks.append((B[0] + BC * (t * u[0] - s * u[1]), B[1] + BC * (t * u[1] + s * u[0])))
        extra = {f"K{k}": K for k, K in enumerate(Ks, 1)}
    else:           # the coupler's angles: the direction of BC plus a fixed offset
        off = rng.uniform(-90, 90)
        extra = {"coupler_angles": [angle_of(B, C) + off for B, C in pos]}
    sol = _solve(R2, A=A, D=D, **{f"B{k}": B for k, B in enumerate(Bs, 1)}, **extra)
    _all_ok(sol)
    a = sol.answers
    assert a["BC"] == pytest.approx(BC, rel=1e-9) and a["CD"] == pytest.approx(CD, rel=1e-9)
    for k, (_, C) in enumerate(pos, 1):
        assert math.dist(sol.points[f"C{k}"], C) <= 1e-9 * max(BC, CD)
    assert a["branch_ok"] and a["order_ok"]


def test_drafted_coupler_points_warn_and_use_directions():
    sol = solve(load_problem(PROBLEMS / "100-03_four_bar_fixed_pivots_coupler_point.toml"))
    assert sol.ok and any("only the directions" in w for w in sol.warnings)
    assert sol.answers["CD"] == pytest.approx(41.9527, abs=1e-4) and sol.answers["gamma_min"] == pytest.approx(44.0498, abs=1e-4)


# ----------------------------------------------------------------------------------------- defects
def test_branch_defect_is_flagged():
    rng = random.Random(8300)
    A, D, AB, BC, CD, pos = _clean(rng)
    phi2 = angle_of(A, pos[1][0])
    other = assemble(A, D, AB, BC, CD, phi2, -math.copysign(1, (D[0] - pos[0][0][0]) * (pos[0][1][1] - pos[0][0][1])
                                                              - (D[1] - pos[0][0][1]) * (pos[0][1][0] - pos[0][0][0])))
    pos[1] = other
    g = {f"B{k}": p[0] for k, p in enumerate(pos, 1)} | {f"C{k}": p[1] for k, p in enumerate(pos, 1)}
    sol = _solve(R1, **g)
    _all_ok(sol)                                   # the construction is right; the design is not
    assert not sol.answers["branch_ok"] and sol.answers["order_ok"]
    assert any(w.startswith("branch defect") for w in sol.warnings)
    assert any("(other branch)" in c["quantity"] for c in sol.checks)


def test_order_defect_is_flagged():
    # a triple rocker: AB swings between dead points; positions given in the order 1, 3, 2 of its swing
    A, D, AB, BC, CD = (0.0, 0.0), (100.0, 0.0), 70.0, 80.0, 60.0        # s + l = 160 > p + q = 150
    assert sorted((AB, BC, CD, 100.0))[0] + 100.0 > AB + BC
    phis = [40.0, 100.0, 70.0]
    pos = [assemble(A, D, AB, BC, CD, p, 1) for p in phis]
    start, sweep = arc_through(*phis)
    assert not dead_point_free(*bd_extremes(A, D, AB, start, sweep), BC, CD)
    g = {f"B{k}": p[0] for k, p in enumerate(pos, 1)} | {f"C{k}": p[1] for k, p in enumerate(pos, 1)}
    sol = _solve(R1, **g)
    _all_ok(sol)
    a = sol.answers
    assert a["branch_ok"] and not a["order_ok"] and not a["crank"] and a["gamma_min"] == 0.0
    assert any(w.startswith("order defect") for w in sol.warnings)
    in_order = _solve(R1, **{"B1": g["B1"], "C1": g["C1"], "B2": g["B3"], "C2": g["C3"], "B3": g["B2"], "C3": g["C2"]})
    assert in_order.answers["order_ok"] and in_order.answers["gamma_min"] > 0


# ----------------------------------------------------------------------------------------- degenerate input
def test_collinear_positions_are_refused():
    with pytest.raises(NotAMechanism, match="collinear"):
        _solve(R1, B1=(0, 0), B2=(10, 0), B3=(25, 0), C1=(0, 40), C2=(10, 40), C3=(25, 40))


def test_coincident_positions_are_refused():
    with pytest.raises(NotAMechanism, match="B1 = B2"):
        _solve(R1, B1=(0, 0), B2=(0, 0), B3=(25, 5), C1=(0, 40), C2=(40, 0), C3=(25, 45))


def test_nearly_collinear_positions_warn_with_the_condition_number():
    sol = _solve(R1, B1=(-50, 0), B2=(0, 0.5), B3=(50, 0), C1=(-50, 40), C2=(0, 40.5), C3=(50, 40))
    w = [w for w in sol.warnings if "nearly collinear" in w]
    assert len(w) == 2 and "R/h_min" in w[0]
    assert sol.answers["sens_A"] > 10


def test_non_rigid_coupler_is_refused_beyond_one_percent():
    with pytest.raises(NotAMechanism, match=r"not rigid.*1 %"):
        _solve(R1, B1=(0, 0), B2=(-10, 30), B3=(-10, 0), C1=(0, 50), C2=(4, 78), C3=(40, 10))    # |B3C3| = 50.99


def test_input_link_of_changing_length_is_refused_beyond_one_percent():
    with pytest.raises(NotAMechanism, match=r"AB1 = 20.*AB2 = 20\.3.*1 %"):
        _solve(R2, A=(0, 0), D=(50, 0), B1=(20, 0), B2=(0, 20.3), B3=(-20, 0), coupler_angles=[0, 10, 20])


def _drafted(rng, decimals=4):
    """A clean design, its positions rounded to ``decimals`` as a textbook prints them."""
    A, D, AB, BC, CD, pos = _clean(rng)
    r = lambda p: tuple(round(c, decimals) for c in p)     # noqa: E731
    return A, D, AB, BC, CD, [(r(B), r(C)) for B, C in pos]


@pytest.mark.parametrize("i", range(10))
def test_drafted_positions_are_fitted_to_a_rigid_coupler(i):
    # rounded to 4 decimals, |B_iC_i| differ by ~1e-5 mm: accepted with a warning, C_i slid along B_iC_i to
    # the mean BC, and every check (twin and back-substitution) passes on the fitted positions
    A, D, AB, BC, CD, pos = _drafted(random.Random(8400 + i))
    g = {f"B{k}": p[0] for k, p in enumerate(pos, 1)} | {f"C{k}": p[1] for k, p in enumerate(pos, 1)}
    sol = _solve(R1, **g)
    _all_ok(sol)
    lens = [math.dist(B, C) for B, C in pos]
    assert sol.answers["BC"] == pytest.approx(sum(lens) / 3, rel=1e-12)
    assert any("not rigid" in w and "mean BC" in w for w in sol.warnings) or max(lens) - min(lens) <= 1e-9 * BC
    # the fitted design is the drafted one to within the rounding, propagated through the conditioning
    tol = 3 * 5 * math.sqrt(2) * 5e-5 * (max(sol.answers["sens_A"], sol.answers["sens_D"]) / 0.1)
    assert math.dist(sol.answers["A"], A) <= tol and math.dist(sol.answers["D"], D) <= tol


@pytest.mark.parametrize("i", range(10))
def test_drafted_input_positions_are_fitted_to_the_crank_circle(i):
    A, D, AB, BC, CD, pos = _drafted(random.Random(8500 + i))
    r = lambda p: [round(c, 4) for c in p]     # noqa: E731
    off = random.Random(i).uniform(-90, 90)
    sol = _solve(R2, A=r(A), D=r(D), **{f"B{k}": p[0] for k, p in enumerate(pos, 1)},
                 coupler_angles=[round(angle_of(B, C) + off, 4) for B, C in pos])
    _all_ok(sol)
    lens = [math.dist(r(A), B) for B, _ in pos]
    assert sol.answers["AB"] == pytest.approx(sum(lens) / 3, rel=1e-12)
    assert any("does not keep its length" in w and "mean AB" in w for w in sol.warnings)
    assert math.dist(sol.answers["C1"], pos[0][1]) <= 1e-3 * (1 + sol.answers["sens_C"] / 0.1)


def test_twin_fits_drafted_data_like_the_construction():
    from geomcon.analytic.synthesis import rigid_fit, three_positions_fixed_pivots
    pts = rigid_fit([(0.0, 0.0)] * 3, [(20.0, 0.0), (0.0, 20.01), (-19.995, 0.0)])
    assert [math.hypot(*p) for p in pts] == pytest.approx([(20 + 20.01 + 19.995) / 3] * 3, rel=1e-15)
    sol = _solve(R2, A=(0, 0), D=(50, 0), B1=(20, 0), B2=(0, 20.01), B3=(-19.995, 0), coupler_angles=[0, 10, 20])
    twin = three_positions_fixed_pivots((0, 0), (50, 0), [(20, 0), (0, 20.01), (-19.995, 0)], angles=[0, 10, 20])
    assert math.dist(sol.answers["C1"], twin["C1"]) <= 1e-12 * 50 and sol.ok


@pytest.mark.parametrize("extra, words", [
    ({"coupler_angles": [0, 10, 20], "K1": [1, 1], "K2": [2, 2], "K3": [3, 3]}, "not both"),
    ({"K1": [40, 0], "K2": [20, 20]}, "all three"),
    ({}, "either"),
    ({"coupler_angles": [0, 10]}, "three angles"),
    ({"K1": [40, 0], "K2": [20, 40], "K3": [-20, 30]}, "rigid"),
])
def test_bad_coupler_givens_are_refused(extra, words):
    with pytest.raises(NotAMechanism, match=words):
        _solve(R2, A=(0, 0), D=(50, 0), B1=(20, 0), B2=(0, 20), B3=(-20, 0), **extra)


def test_collinear_transferred_points_are_refused():
    # angles chosen so that D3′ falls on the line D D2′: C1 would lie at infinity
    A, D, Bs = (0.0, 0.0), (50.0, 0.0), [(20.0, 0.0), (0.0, 20.0), (-20.0, 0.0)]
    D2 = (Bs[0][0] + D[0] - Bs[1][0], Bs[0][1] + D[1] - Bs[1][1])        # α1 = α2: a pure translation
    r3 = math.dist(D, Bs[2])
    # D3′ = B1 + R(−α3)(D − B3) on the line D→D2: intersect the circle about B1 of radius r3 with that line
    ux, uy = D2[0] - D[0], D2[1] - D[1]
    n = math.hypot(ux, uy)
    ux, uy = ux / n, uy / n
    wx, wy = D[0] - Bs[0][0], D[1] - Bs[0][1]
    b = wx * ux + wy * uy
    t = -b + math.sqrt(b * b - (wx * wx + wy * wy - r3 * r3))
    P = (D[0] + t * ux, D[1] + t * uy)
    a3 = angle_of(Bs[2], D) - angle_of(Bs[0], P)
    with pytest.raises(NotAMechanism, match="collinear"):
        _solve(R2, A=A, D=D, B1=Bs[0], B2=Bs[1], B3=Bs[2], coupler_angles=[0.0, 0.0, a3])


def test_cli_bad_file_exits_2_with_one_line(tmp_path, capsys):
    p = tmp_path / "bad.toml"
    p.write_text('recipe = "four_bar.three_positions"\n[given]\nB1 = [0, 0]\nB2 = [10, 0]\nB3 = [25, 0]\n'
                 'C1 = [0, 40]\nC2 = [10, 40]\nC3 = [25, 40]\n')
    assert main(["solve", str(p), "--json"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: ") and "collinear" in err


@pytest.mark.parametrize("name", ["100-01_four_bar_three_positions", "100-02_four_bar_three_positions_branch_defect",
                                  "100-03_four_bar_fixed_pivots_coupler_point",
                                  "100-04_four_bar_fixed_pivots_coupler_angles"])
def test_bundled_problems_pass(name):
    sol = solve(load_problem(PROBLEMS / f"{name}.toml"))
    assert sol.ok
    assert ("branch_defect" in name) == (not sol.answers["branch_ok"])


# ----------------------------------------------------------------------------------------- bench
def test_engine_agrees_with_sympy_geometry():
    pytest.importorskip("sympy")
    from geomcon.bench.synthesis import CASES, SynthesisRow, engine_answers, synthesis_table

    for recipe, given, fn in (CASES[0], CASES[2]):       # the fast ones (a K case takes seconds in sympy)
        exact = fn(given)
        got = engine_answers(recipe, given, tuple(exact))
        for k, v in exact.items():
            assert got[k] == pytest.approx(v, rel=1e-12), (recipe, k)
    table = synthesis_table([SynthesisRow(R1, "geomcon", 1e-3, 0.0, ("AB",))])
    assert "1 ms" in table and R1 in table
    assert "not measured" in synthesis_table(None)
