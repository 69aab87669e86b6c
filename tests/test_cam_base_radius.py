"""cam.base_radius: the ds/dδ–s construction against the minimisation twin on random programs (fixed
seed), the active constraint at the answer, no smaller base circle admissible, and the refusals."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from geomcon.cam.base_radius import ArmProgram, ArmTwin, arm_a_min, arm_best, best_base, limits
from geomcon.cam.oscillating import OscillatingCam, psi0_rad
from geomcon.cam.program import parse_program
from geomcon.cam.translating import TranslatingCam
from geomcon.errors import GeomconError, NotAMechanism
from geomcon.geometry import Point, rotate
from geomcon.problems import load_problem, problem_from_dict
from geomcon.recipes.cam_base_radius import arm_position, velocity_image
from geomcon.solve import solve

LAWS = ("parabolic", "cosine", "cycloidal", "poly345")
ARM_PROGRAM = [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
               {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]


def _solve(**given):
    return solve(problem_from_dict({"recipe": "cam.base_radius", "given": given}, name="t"))


def _ok(sol):
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    assert any("back_substitution" in c["quantity"] for c in sol.checks)


def _random_given(rng):
    rise, ret = rng.uniform(60, 180), rng.uniform(60, 150)
    d1 = rng.uniform(0, 360 - rise - ret - 10)
    prog = [{"kind": "rise", "angle": rise, "law": rng.choice(LAWS)}, {"kind": "dwell", "angle": d1 + 5},
            {"kind": "return", "angle": ret, "law": rng.choice(LAWS)},
            {"kind": "dwell", "angle": 360 - rise - ret - d1 - 5}]
    g = dict(h=rng.uniform(5, 80), program=prog, alpha_allow=rng.uniform(15, 40), rotation=rng.choice(["ccw", "cw"]))
    if rng.random() < 0.5:
        g["alpha_allow_return"] = rng.uniform(40, 75)
    if rng.random() < 0.25:
        g["e"] = rng.uniform(-0.3, 0.3) * g["h"]
    return g


def _alpha_over(g, r0, e):
    """Largest α − α_allow over the constrained parts, by cam.translating's closed form."""
    cam = TranslatingCam(parse_program(g["program"]), g["h"], r0, e, g["rotation"])
    over = cam.alpha_max("rise")[0] - g["alpha_allow"]
    if g.get("alpha_allow_return") is not None:
        over = max(over, cam.alpha_max("return")[0] - g["alpha_allow_return"])
    return over


@pytest.mark.parametrize("i", range(30))
def test_random_programs(i):
    g = _random_given(random.Random(3100 + i))
    sol = _solve(**g)
    _ok(sol)
    a = sol.answers
    assert _alpha_over(g, a["r0"], a["e"]) == pytest.approx(0.0, abs=1e-9)      # the limit is active
    # any smaller base circle, at any offset, violates a limit
    for e in np.linspace(a["e"] - a["r0"], a["e"] + a["r0"], 41) if "e" not in g else [g["e"]]:
        r = 0.999 * a["r0"]
        if abs(e) < r:
            assert _alpha_over(g, r, float(e)) > 0


def test_classic_h20_cycloidal_120_alpha30():
    sol = solve(load_problem("problems/200-09_base_radius_cycloidal.toml"))
    _ok(sol)
    a = sol.answers
    # the optimum is the meeting point of the two support lines, one of them through B0: e = r0·sin 30°
    assert a["e"] == pytest.approx(a["r0"] / 2, rel=1e-12)
    assert a["r0"] == pytest.approx(14.0239020717, rel=1e-10)
    centred = solve(load_problem("problems/200-10_base_radius_centred.toml")).answers
    assert centred["r0"] == pytest.approx(24.2901109085, rel=1e-10) and centred["e"] == 0


def test_brute_force_minimum():
    prog = parse_program([{"kind": "rise", "angle": 150, "law": "cosine"}, {"kind": "dwell", "angle": 30},
                          {"kind": "return", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60}])
    d = np.linspace(0, 150, 30001)
    s, v, _ = prog.motion(30.0, d)
    t = math.tan(math.radians(30))
    r0 = lambda ke: math.hypot(ke, float(np.max(np.abs(v - ke) / t - s)))   # convex in ke: golden section
    lo, hi = -30.0, 30.0
    for _ in range(100):
        m1, m2 = lo + 0.382 * (hi - lo), hi - 0.382 * (hi - lo)
        lo, hi = (lo, m2) if r0(m1) < r0(m2) else (m1, hi)
    brute = r0(0.5 * (lo + hi))
    best = best_base(prog, 30.0, alpha_allow=30.0)["r0"]
    assert best == pytest.approx(brute, abs=1e-6)     # the grid over δ slightly underestimates s0


def test_wide_angle_takes_the_foot_of_the_perpendicular():
    """α_allow ≥ 45°: the nearest admissible point is the foot on one support line, not the vertex."""
    prog = [{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 240}]
    sol = _solve(h=20, program=prog, alpha_allow=60)
    _ok(sol)
    assert sol.answers["e"] != pytest.approx(sol.answers["r0"] * math.sin(math.radians(60)), rel=1e-3)


def test_uniform_rise_takes_the_foot_on_the_line_through_its_start():
    """A uniform rise's curve is the segment x = h/Φ: the best centre is the foot of the perpendicular from
    B0 on the support line through (h/Φ, 0); α = α_allow over the whole rise."""
    prog = [{"kind": "rise", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 240}]
    sol = _solve(h=20, program=prog, alpha_allow=30)
    _ok(sol)
    w = 20 / math.radians(120)
    t = math.tan(math.radians(30))
    assert sol.answers["e"] == pytest.approx(w / (1 + t * t), rel=1e-12)
    assert sol.answers["s0"] == pytest.approx(w * t / (1 + t * t), rel=1e-12)


def test_answers_alone_do_not_draw():
    sol = _solve(h=20, program=[{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 240}],
                 alpha_allow=30)
    sol.answers
    assert not sol.scene.is_evaluated("dim_r0") and not sol.scene.is_evaluated("base")


@pytest.mark.parametrize("given, words", [
    (dict(h=20, program=[{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 240}],
          alpha_allow=95), ["'alpha_allow'", "≤ 90", "95"]),
    (dict(h=20, program=[{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 240}],
          alpha_allow=90), ["alpha_allow = 90°", "(0°, 90°)"]),
    (dict(h=20, program=[{"kind": "rise", "angle": 120, "law": "cosine"}], alpha_allow=30), ["full turn"]),
    (dict(motion="oscillating", h=20, program=ARM_PROGRAM, alpha_allow=35), ["needs L"]),
    (dict(motion="oscillating", L=100, h=20, program=ARM_PROGRAM, alpha_allow=35, e=5.0), ["e = 5", "no offset"]),
    (dict(motion="oscillating", L=100, h=190, program=ARM_PROGRAM, alpha_allow=35), ["h = 190°"]),
    (dict(motion="oscillating", L=100, h=20, program=ARM_PROGRAM, alpha_allow=35, a=40.0), ["a = 40 mm ≤", "no centre"]),
    (dict(h=20, program=ARM_PROGRAM, alpha_allow=30, L=100), ["L = 100 is given for a translating follower"]),
])
def test_refusals(given, words):
    with pytest.raises(GeomconError) as exc:
        _solve(**given).answers
    assert "\n" not in str(exc.value)
    for w in words:
        assert w in str(exc.value)


# ---------------------------------------------------------------------------- oscillating follower
def _random_arm(rng, free):
    rise, ret = rng.uniform(80, 160), rng.uniform(80, 150)
    d1 = rng.uniform(0, 360 - rise - ret - 10)
    prog = [{"kind": "rise", "angle": rise, "law": rng.choice(LAWS)}, {"kind": "dwell", "angle": d1 + 5},
            {"kind": "return", "angle": ret, "law": rng.choice(LAWS)},
            {"kind": "dwell", "angle": 360 - rise - ret - d1 - 5}]
    g = dict(motion="oscillating", L=rng.uniform(60, 150), h=rng.uniform(10, 30), program=prog,
             alpha_allow=rng.uniform(28, 45), rotation=rng.choice(["ccw", "cw"]), arm=rng.choice(["left", "right"]))
    if rng.random() < 0.5:
        g["alpha_allow_return"] = rng.uniform(40, 70)
    if not free:
        motion = ArmProgram(g["h"], parse_program(prog), g["rotation"], g["arm"])
        lims = limits(motion.program, g["alpha_allow"], g.get("alpha_allow_return"))
        g["a"] = arm_a_min(motion, g["L"], lims) * rng.uniform(1.05, 1.6)
    return g


def _arm_over(g, a, r0):
    """Largest α − α_allow over the constrained parts by cam.oscillating (its tan route)."""
    cam = OscillatingCam(a, g["L"], r0, g["h"], parse_program(g["program"]), g["rotation"], g["arm"])
    over = cam.worst_pressure("rise")[0] - g["alpha_allow"]
    if g.get("alpha_allow_return") is not None:
        over = max(over, cam.worst_pressure("return")[0] - g["alpha_allow_return"])
    return over


def _smaller_violates(g, a, r0):
    """Every centre at 0.999·r0 from B0 (at the given a, or at any a) breaks a limit."""
    r = 0.999 * r0
    for x in ([a] if "a" in g else np.linspace(abs(g["L"] - r), g["L"] + r, 41)[1:-1]):
        cam_ok = psi0_rad(x, g["L"], r)
        if math.isfinite(cam_ok) and math.degrees(cam_ok) + g["h"] < 180 and r < x:
            assert _arm_over(g, x, r) > 0, (x, r)


@pytest.mark.parametrize("seed, free", [(5200 + i, False) for i in range(12)] + [(5300 + i, True) for i in range(4)])
def test_random_arm(seed, free):
    """At a given a (12 programs) and with a free (4): the twin agrees, the limit is active, and no base
    circle 0.1 % smaller is admissible."""
    g = _random_arm(random.Random(seed), free=free)
    sol = _solve(**g)
    _ok(sol)
    a = sol.answers
    if not free:
        assert a["a"] == pytest.approx(g["a"], rel=1e-12)
    assert _arm_over(g, a["a"], a["r0"]) == pytest.approx(0.0, abs=1e-9)          # the limit is active
    _smaller_violates(g, a["a"], a["r0"])


def test_problem_200_12_both_limits_bind():
    """The best centre is the vertex of the region: a rise position and a return position bind at once."""
    sol = solve(load_problem("problems/200-12_oscillating_base_radius.toml"))
    _ok(sol)
    a = sol.answers
    assert a["r0"] == pytest.approx(21.7916098892, rel=1e-9) and a["a"] == pytest.approx(106.826053834, rel=1e-9)
    g = sol.problem.given
    cam = OscillatingCam(a["a"], g["L"], a["r0"], g["h"], parse_program(g["program"]), g["rotation"], g["arm"])
    assert cam.worst_pressure("rise")[0] == pytest.approx(35.0, abs=1e-9)
    assert cam.worst_pressure("return")[0] == pytest.approx(45.0, abs=1e-9)
    assert [p for p, _ in sol.scene.evaluate(["binding"])["binding"]] == ["rise", "return"]


@pytest.mark.parametrize("rotation, arm", [("ccw", "left"), ("ccw", "right"), ("cw", "left"), ("cw", "right")])
def test_velocity_image_line_makes_the_pressure_angle(rotation, arm):
    """The line from K (BK = L·ψ′ on the arm) to O makes with the arm's normal the pressure angle of
    cam.oscillating, at any cam angle and for any centre."""
    prog = parse_program([{"kind": "rise", "angle": 140, "law": "poly345"}, {"kind": "dwell", "angle": 40},
                          {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}])
    cam = OscillatingCam(120.0, 90.0, 45.0, 25.0, prog, rotation, arm)
    motion = ArmProgram(25.0, prog, rotation, arm)
    A0, B0 = Point(0.0, 0.0), Point(motion.tau * 90.0, 0.0)
    O = rotate(B0, A0, -motion.tau * cam.psi0).__mul__(120.0 / 90.0)
    for d in (10.0, 55.0, 139.0, 200.0, 250.0):
        m = cam.motion(d)
        B = arm_position(B0, A0, motion.tau, math.degrees(float(m.psi)))
        K = velocity_image(A0, B, motion.eps * float(m.d1))
        u = (O - K).unit()
        along = abs(u.dot((B - A0).unit()))
        assert math.degrees(math.asin(min(along, 1.0))) == pytest.approx(float(cam.pressure_angle(d)), abs=1e-9)


def test_twin_agrees_with_the_wedge_route():
    prog = parse_program([{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
                          {"kind": "return", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60}])
    for a in (None, 150.0):
        main = arm_best(prog, 25.0, 120.0, alpha_allow=40.0, rotation="cw", arm="right", a=a)
        twin = ArmTwin(prog, 25.0, 120.0, alpha_allow=40.0, rotation="cw", arm="right").best(a)
        for k in ("r0", "a", "psi0"):
            assert main[k] == pytest.approx(twin[k], rel=1e-9)
