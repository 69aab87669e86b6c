"""cam.eccentric with ω: a, v_max, a_max (translating) and ω2, ε2 and their maxima (oscillating). The
construction solves the equivalent linkage's velocity, acceleration and jerk polygons; the twin differentiates the
exact motion by hand: random cams agree to 1e-9 of the quantity's scale. The hand derivatives are checked against finite
differences of the exact motion, and the flat face against its closed form (a Scotch yoke)."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.cam.eccentric import Oscillating, Translating
from geomcon.cam.eccentric_speeds import arm_derivatives, translating_derivatives, translating_maxima
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

SPEEDS = ("v", "a", "v_max", "a_max", "omega2", "epsilon2", "omega2_max", "epsilon2_max")


def _solve(**given):
    return solve(problem_from_dict({"recipe": "cam.eccentric", "given": given}, name="t"))


def _translating(rng):
    R = rng.uniform(10, 80)
    OA = R * rng.uniform(0.05, 0.9)
    follower = rng.choice(["knife", "roller", "flat"])
    g = dict(R=R, OA=OA, follower=follower, rotation=rng.choice(["ccw", "cw"]), omega=rng.uniform(0.5, 50),
             delta=rng.uniform(0, 360))
    if follower == "roller":
        g["rr"] = rng.uniform(1, 20)
    if follower != "flat":
        Rp = R + g.get("rr", 0.0)
        g["e"] = rng.uniform(-0.9, 0.9) * (Rp - OA)
    return g


def _oscillating(rng):
    R = rng.uniform(20, 60)
    OA = R * rng.uniform(0.1, 0.7)
    rr = rng.uniform(2, 10)
    Rp = R + rr
    a = (Rp + OA) * rng.uniform(1.1, 2.5)
    r0, top = Rp - OA, Rp + OA
    lo, hi = max(a - r0, top - a), a + r0
    L = rng.uniform(lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo))
    return dict(R=R, OA=OA, follower="roller", rr=rr, a=a, L=L, rotation=rng.choice(["ccw", "cw"]),
                arm=rng.choice(["left", "right"]), omega=rng.uniform(0.5, 50), delta=rng.uniform(0, 360))


@pytest.mark.parametrize("i", range(40))
def test_random_cams_construction_against_twin(i):
    rng = random.Random(14300 + i)
    g = _translating(rng) if i % 2 == 0 else _oscillating(rng)
    sol = _solve(**g)
    twin = sol.analytic[0]
    got = sol.answers
    names = [k for k in SPEEDS if k in twin]
    assert set(names) == {k for k in SPEEDS if k in got}
    scale = {"v": twin.get("v_max"), "a": twin.get("a_max"), "omega2": twin.get("omega2_max"),
             "epsilon2": twin.get("epsilon2_max")}
    for k in names:
        ref = scale.get(k) or abs(twin[k])
        assert abs(got[k] - twin[k]) <= 1e-9 * ref, (k, got[k], twin[k])
    assert all(r["ok"] for r in sol.checks), [r for r in sol.checks if not r["ok"]]


@pytest.mark.parametrize("i", range(20))
def test_hand_derivatives_against_finite_differences_of_the_motion(i):
    """y′, y″, y‴ (and ψ′, ψ″) against central differences of y(φ) (ψ(φ)), to the differences' accuracy."""
    rng = random.Random(14400 + i)
    g = _translating(rng)
    cam = Translating(g["R"], g["OA"], g.get("e", 0.0), g.get("rr", 0.0), g["follower"], g["rotation"])
    phi, h = rng.uniform(0, 2 * math.pi), 1e-3
    y = [cam.y(phi + k * h) for k in (-2, -1, 0, 1, 2)]
    d1, d2, d3 = translating_derivatives(cam, phi)
    scale = cam.OA + abs(d3) + abs(d2)
    assert abs((y[3] - y[1]) / (2 * h) - d1) < 1e-5 * scale
    assert abs((y[3] - 2 * y[2] + y[1]) / h ** 2 - d2) < 1e-5 * scale
    assert abs((y[4] - 2 * y[3] + 2 * y[1] - y[0]) / (2 * h ** 3) - d3) < 1e-4 * scale
    o = _oscillating(rng)
    arm = Oscillating(o["R"], o["OA"], o["a"], o["L"], o["rr"], o["rotation"], o["arm"])
    p = [math.radians(arm.psi(phi + k * h)) for k in (-1, 0, 1)]
    p1, p2 = arm_derivatives(arm, phi)
    assert abs((p[2] - p[0]) / (2 * h) - p1) < 1e-6 and abs((p[2] - 2 * p[1] + p[0]) / h ** 2 - p2) < 1e-5


def test_flat_face_is_a_scotch_yoke():
    """A flat face: y = OA·sin φ + R, so v_max = ω·OA and a_max = ω²·OA exactly."""
    cam = Translating(40.0, 12.5, follower="flat")
    assert translating_maxima(cam, 3.0) == pytest.approx((37.5, 112.5), rel=1e-15)
    sol = _solve(R=40, OA=12.5, follower="flat", omega=3.0, delta=30)
    assert sol.answers["v_max"] == pytest.approx(37.5, rel=1e-12)
    assert sol.answers["a_max"] == pytest.approx(112.5, rel=1e-10)


def test_seed_001_27_speeds():
    """Seed 001-27 (ω = 10 rad/s, printed v = 500 mm/s): v, a, vmax, amax of the construction and the twin."""
    from geomcon.problems import load_problem
    sol = solve(load_problem("problems/001-27_eccentric_roller_offset.toml"))
    assert sol.answers["v"] == pytest.approx(500.0, rel=1e-12)
    assert all(r["ok"] for r in sol.checks)
    for k in ("a", "v_max", "a_max"):
        assert sol.answers[k] == pytest.approx(sol.analytic[0][k], rel=1e-9)


def test_problem_001_31b_arm_speeds():
    """001-31's cam at ω = 10 rad/s, δ = 60°: ω2, ε2 and their maxima, construction against twin; ω2 against
    the drawn instant centre P (ω2 = ω·OP/QP, the arm swinging out)."""
    from geomcon.problems import load_problem
    sol = solve(load_problem("problems/001-31b_eccentric_oscillating_roller_speeds.toml"))
    assert all(r["ok"] for r in sol.checks)
    for k in ("omega2", "epsilon2", "omega2_max", "epsilon2_max"):
        assert sol.answers[k] == pytest.approx(sol.analytic[0][k], rel=1e-9)
    P = sol.evaluate(["P"])["P"]
    assert sol.answers["omega2"] == pytest.approx(10.0 * abs(P.y) / abs(90.0 - P.y), rel=1e-12)
    assert sol.answers["omega2"] > 0
