"""``slotter.kinematics``: the slotter's polygons (guide bar with its Coriolis component, then the ram's RRP dyad)
against three routes — the complex-loop twin, the whole-cycle chain solver (geomcon.kinematics, built as a crank,
an RPR guide, a carried point and an RRP ram) and positions differentiated numerically — on random instances in
both branches, every quadrant of the crank, both senses of ω, with and without crank acceleration; refusals."""
from __future__ import annotations

import cmath
import math
import random

import numpy as np
import pytest

from geomcon.analytic.kinematics import slotter
from geomcon.errors import GeomconError, NotAMechanism
from geomcon.kinematics.chain import Mechanism, solve_chain
from geomcon.kinematics.dyads import RPR, RRP, Crank, Guide, OnLink
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

NAMES = ("AB", "AC", "CD", "DE", "CF", "phi", "omega", "epsilon", "branch")


def _solve(g: dict):
    return solve(problem_from_dict({"recipe": "slotter.kinematics", "given": g}, name="t"))


def _instance(rng: random.Random) -> dict:
    """A random slotter whose ram reaches its path with room (|h| < 0.9·DE) and whose block is off the pivot."""
    while True:
        AB, AC = rng.uniform(10, 200), rng.uniform(10, 200)
        if abs(AB - AC) < 0.1 * AC:
            continue
        g = {"AB": AB, "AC": AC, "CD": rng.uniform(20, 250), "DE": rng.uniform(20, 200),
             "phi": rng.uniform(-180, 360), "omega": rng.choice((-1, 1)) * rng.uniform(0.5, 50),
             "branch": rng.choice(("above", "below"))}
        if rng.random() < 0.6:
            g["epsilon"] = rng.uniform(-200, 200)
        # the path's distance beyond C: somewhere D can reach at this angle
        a = math.radians(g["phi"])
        bx, by = AB * math.cos(a) + AC, AB * math.sin(a)
        dx = -g["CD"] * bx / math.hypot(bx, by)              # D − C, horizontally
        g["CF"] = -dx + rng.uniform(-0.9, 0.9) * g["DE"]
        return g


def _scales(g: dict) -> dict[str, float]:
    w, e = abs(g["omega"]), abs(g.get("epsilon", 0.0))
    a = math.radians(g["phi"])
    CB = math.hypot(g["AB"] * math.cos(a) + g["AC"], g["AB"] * math.sin(a))
    lever = 1 + g["AB"] / CB                                  # the guide turns faster as B nears C
    arm = 1 + g["CD"] / g["DE"]
    h = g["AC"] + g["CF"] + (-g["AC"] - g["CD"] * (g["AB"] * math.cos(a) + g["AC"]) / CB)
    steep = 1 / math.sqrt(1 - min(h * h / g["DE"] ** 2, 0.99))   # the coupler near perpendicular to the path
    W, A = w * lever, (w * w + e) * lever ** 2
    L = g["AB"] + g["CD"]
    return {"omega3": W, "epsilon3": A, "v_slip": W * L, "a_slip": A * L, "a_coriolis": A * L, "vB3": W * L,
            "vD": W * L, "aD": A * L, "omega4": W * arm * steep, "epsilon4": A * arm * steep ** 3,
            "vE": W * L * steep, "aE": A * L * steep ** 3, "mu_v": w, "mu_a": w * w + e}


@pytest.mark.parametrize("seed", range(60))
def test_polygons_agree_with_the_twin(seed):
    rng = random.Random(1500 + seed)
    g = _instance(rng)
    sol = _solve(g)
    ex = slotter(g["AB"], g["AC"], g["CD"], g["DE"], g["CF"], g["phi"], g["omega"], g.get("epsilon", 0.0), g["branch"])
    sc = _scales(g)
    for n, got in sol.answers.items():
        ref = ex[n] if n in ex else {"mu_v": abs(g["omega"]), "mu_a": math.hypot(g["omega"] ** 2, g.get("epsilon", 0.0))}[n]
        assert abs(got - ref) <= 1e-9 * sc[n], (n, got, ref, g)
    # the Coriolis term is 2·ω3·v_slip, read off the polygons
    assert math.isclose(sol.answers["a_coriolis"], 2 * sol.answers["omega3"] * sol.answers["v_slip"],
                        rel_tol=1e-9, abs_tol=1e-9 * sc["a_coriolis"])
    assert sol.ok


def test_both_branches_and_every_quadrant_are_drawn():
    seen = set()
    rng = random.Random(7)
    while len(seen) < 8:
        g = _instance(rng)
        seen.add((g["branch"], int((g["phi"] % 360) // 90)))
        assert _solve(g).ok
    assert len(seen) == 8


def _chain(g: dict) -> Mechanism:
    """The same linkage as a crank and dyads of the whole-cycle solver (the seed 000-09 description)."""
    AC, CF = g["AC"], g["CF"]
    return Mechanism({"A": 0j, "C": complex(-AC, 0), "F": complex(-AC - CF, 0)},
                     Crank("AB", "A", "B", g["AB"], g["omega"], g.get("epsilon", 0.0)),
                     (RPR("guide", "B", "C", "CB", 1), OnLink("D", "CB", "C", g["CD"], math.pi),
                      RRP("E", "D", g["DE"], Guide("F", math.pi / 2), 1 if g["branch"] == "above" else -1, "DE")))


@pytest.mark.parametrize("seed", range(30))
def test_twin_agrees_with_the_whole_cycle_solver(seed):
    rng = random.Random(2600 + seed)
    g = _instance(rng)
    ex = slotter(g["AB"], g["AC"], g["CD"], g["DE"], g["CF"], g["phi"], g["omega"], g.get("epsilon", 0.0), g["branch"])
    st = solve_chain(_chain(g), np.radians([g["phi"]]))
    sc = _scales(g)
    E, D, guide, coupler = st.points["E"], st.points["D"], st.links["CB"], st.links["DE"]
    pairs = (("omega3", guide.omega[0]), ("epsilon3", guide.epsilon[0]), ("v_slip", st.slips["guide"].v[0]),
             ("vD", abs(D.v[0])), ("aD", abs(D.a[0])), ("omega4", coupler.omega[0]), ("epsilon4", coupler.epsilon[0]),
             ("vE", E.v[0].imag), ("aE", E.a[0].imag))
    for n, got in pairs:
        assert abs(got - ex[n]) <= 1e-9 * sc[n], (n, got, ex[n], g)
    assert abs(E.p[0].imag - ex["yE"]) <= 1e-9 * (g["AB"] + g["CD"] + g["DE"])
    assert abs(E.v[0].real) <= 1e-9 * sc["vE"]                # the ram stays on its path


def _positions(g: dict, phi: float) -> tuple[float, float, float]:
    """The guide bar's angle, the block's distance CB, the coupler's angle and the ram's height at ``phi`` (rad),
    written with the law of cosines and atan2 only (no loop, no complex numbers)."""
    AB, AC, CD, DE = g["AB"], g["AC"], g["CD"], g["DE"]
    bx, by = AB * math.cos(phi) + AC, AB * math.sin(phi)
    th3 = math.atan2(by, bx)
    Dx, Dy = -AC - CD * math.cos(th3), -CD * math.sin(th3)
    h = -(AC + g["CF"]) - Dx
    up = math.sqrt(DE * DE - h * h) * (1 if g["branch"] == "above" else -1)
    return th3, math.hypot(bx, by), math.atan2(up, h), Dy + up


def test_twin_agrees_with_positions_differentiated_numerically():
    rng = random.Random(31)
    for _ in range(25):
        g = _instance(rng)
        w, e = g["omega"], g.get("epsilon", 0.0)
        p0 = math.radians(g["phi"])
        ex = slotter(g["AB"], g["AC"], g["CD"], g["DE"], g["CF"], g["phi"], w, e, g["branch"])
        dt = 1e-4 / abs(w)
        at = [_positions(g, p0 + w * t + 0.5 * e * t * t) for t in (-dt, 0.0, dt)]
        unwrap = lambda x: (x + math.pi) % (2 * math.pi) - math.pi
        for i, (wn, en) in enumerate(((("omega3", "epsilon3")), ("v_slip", "a_slip"), ("omega4", "epsilon4"), ("vE", "aE"))):
            f = [at[0][i], at[1][i], at[2][i]]
            d1 = (unwrap(f[2] - f[1]) + unwrap(f[1] - f[0])) / (2 * dt) if i in (0, 2) else (f[2] - f[0]) / (2 * dt)
            d2 = (unwrap(f[2] - f[1]) - unwrap(f[1] - f[0])) / dt ** 2 if i in (0, 2) else (f[2] - 2 * f[1] + f[0]) / dt ** 2
            sc = _scales(g)
            assert abs(d1 - ex[wn]) <= 1e-5 * sc[wn], (wn, d1, ex[wn])
            assert abs(d2 - ex[en]) <= 1e-3 * sc[en], (en, d2, ex[en])


def test_a_wrong_coriolis_sense_would_be_seen():
    """The test above can fail: a twin with the Coriolis term's sign turned differs in ε3 by 4·ω3·v_slip/CB."""
    g = {"AB": 70, "AC": 161, "CD": 115, "DE": 46, "CF": 115.4, "phi": 150, "omega": 4.8147, "branch": "above"}
    r = slotter(**g)
    assert abs(4 * r["omega3"] * r["v_slip"] / r["CB"]) > 1.0      # rad/s², far above the tolerances used


@pytest.mark.parametrize("g, words", [
    ({"AB": 50, "AC": 50, "CD": 80, "DE": 40, "CF": 80, "phi": 180, "omega": 1}, "B lies on C"),
    ({"AB": 70, "AC": 161, "CD": 115, "DE": 46, "CF": 115.4, "phi": 0, "omega": 0}, "omega = 0"),
    ({"AB": 70, "AC": 161, "CD": 115, "DE": 46, "CF": 300, "phi": 0, "omega": 1}, "not less than DE"),
])
def test_refusals(g, words):
    with pytest.raises(GeomconError, match=words):
        _solve(g)


def test_twin_refuses_what_the_recipe_refuses():
    with pytest.raises(NotAMechanism):
        slotter(70, 161, 115, 46, 300, 0, 1)
    with pytest.raises(NotAMechanism):
        slotter(50, 50, 80, 40, 80, 180, 1)


def test_seed_000_09_table_rows():
    """Rows of the seed's printed table (QO2A, W4, W5, YC, VCY, ACY) with YC measured from the program's origin:
    the twin at the seed's own data reproduces the whole-cycle solver, which reproduces the table (000-09)."""
    g = {"AB": 70, "AC": 161, "CD": 115, "DE": 46, "CF": 115.4, "omega": 4.8147, "branch": "above"}
    for phi in (0, 50, 115.77, 180, 244.23, 300):
        ex = slotter(phi=phi, **g)
        st = solve_chain(_chain({**g, "phi": phi}), np.radians([phi]))
        assert math.isclose(ex["omega3"], st.links["CB"].omega[0], rel_tol=1e-12, abs_tol=1e-12)
        assert math.isclose(ex["vE"], st.points["E"].v[0].imag, rel_tol=1e-12, abs_tol=1e-10)
    # the extreme positions of the ram: vE = 0 at the crank angles 000-09 prints (115.77°, 244.23°)
    assert abs(slotter(phi=115.77, **g)["vE"]) < 0.05 and abs(slotter(phi=244.23, **g)["vE"]) < 0.05
