"""cam.base_radius with a curvature limit for an oscillating follower (issue 14): the centre moved from the
pressure angle's best one perpendicular to the arm A0B0 until the pitch curve's ρmin reaches ρallow. Problem
200-20, random instances against the twin (its own family in closed form, its own ρmin route), the design
checked on cam.oscillating (the limits hold, ρ reaches ρallow, no smaller circle of the family meets it), the
refusals, the statement and the declared mistakes."""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from geomcon.cam.arm_twin import arm_rho_min
from geomcon.errors import GeomconError
from geomcon.problems import load_problem, problem_from_dict
from geomcon.recipes.cam_base_radius import arm_cam
from geomcon.recipes.cam_base_radius_arm_rho import grown
from geomcon.solve import solve

ROOT = Path(__file__).parents[1]
P = ROOT / "problems" / "200-20_oscillating_base_radius_rho.toml"
LAWS = ("cosine", "cycloidal", "poly345", "modified_sine")


def _given(path):
    return {k: v for k, v in load_problem(path).given.items() if v is not None and v is not False}


def _solve(g):
    return solve(problem_from_dict({"recipe": "cam.base_radius", "given": g}, name="t"))


def _design_holds(g, ans):
    cam = arm_cam(g, ans["a"], ans["r0"], ans["psi0"])
    assert cam.worst_pressure("rise")[0] <= g["alpha_allow"] * (1 + 1e-9)
    if g.get("alpha_allow_return") is not None:
        assert cam.worst_pressure("return")[0] <= g["alpha_allow_return"] * (1 + 1e-9)
    rho = arm_rho_min(cam)
    assert rho >= g["rho_allow"] * (1 - 1e-9)
    return rho


def test_problem_200_20_the_curvature_binds():
    sol = solve(load_problem(P))
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    ans = sol.answers
    assert ans["r0_rho"] > 1.5 * ans["r0_alpha"] and ans["r0"] == ans["r0_rho"]
    assert ans["rho_min_pitch"] == pytest.approx(40.0, rel=1e-12)
    assert _design_holds(dict(sol.problem.given), ans) == pytest.approx(40.0, rel=1e-12)


@pytest.mark.parametrize("i", range(6))
def test_random_arms_against_the_twin(i):
    rng = random.Random(14700 + i)
    rise = rng.uniform(120, 200)
    g = {"motion": "oscillating", "L": rng.uniform(60, 140), "h": rng.uniform(12, 30),
         "program": [{"kind": "rise", "angle": rise, "law": rng.choice(LAWS)},
                     {"kind": "return", "angle": 360 - rise, "law": rng.choice(LAWS)}],
         "alpha_allow": rng.uniform(30, 40), "alpha_allow_return": rng.uniform(40, 50),
         "rotation": rng.choice(["ccw", "cw"]), "arm": rng.choice(["left", "right"])}
    base = _solve(g).answers
    g["rho_allow"] = base["rho_min_pitch"] * rng.uniform(1.2, 1.8)
    sol = _solve(g)
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    ans = sol.answers
    twin = sol.analytic[0]
    for k in ("r0", "a", "psi0", "rho_min_pitch", "r0_alpha", "r0_rho"):
        assert ans[k] == pytest.approx(twin[k], rel=1e-9), k
    assert ans["r0_alpha"] == pytest.approx(base["r0"], rel=1e-12)
    assert ans["rho_min_pitch"] == pytest.approx(g["rho_allow"], rel=1e-9)      # the limit is reached
    _design_holds(g, ans)
    lo, hi = 0.0, 4.0 * ans["r0"]                         # the distance the centre moved, from the design's r0
    while hi - lo > 1e-12 * hi:
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if grown(base["a"], base["psi0"], g["L"], mid)[1] < ans["r0"] else (lo, mid)
    for k in range(1, 8):                                 # no smaller circle of the family meets the limit
        t = hi * k / 8
        cam = arm_cam(g, *grown(base["a"], base["psi0"], g["L"], t))
        assert arm_rho_min(cam) < g["rho_allow"], (k, t)


def test_curvature_limit_not_binding_keeps_the_pressure_angle_design():
    g = _given(P)
    base = _solve({k: v for k, v in g.items() if k != "rho_allow"}).answers
    g["rho_allow"] = 0.5 * base["rho_min_pitch"]
    ans = _solve(g).answers
    assert ans["r0"] == ans["r0_alpha"] == ans["r0_rho"] == pytest.approx(base["r0"], rel=1e-12)
    assert ans["a"] == pytest.approx(base["a"], rel=1e-12)


@pytest.mark.parametrize("extra, words", [({"a": 110.0}, "a = 110 is given with rho_allow"),
                                          ({"alpha_allow": None}, "alpha_allow is missing")])
def test_refusals(extra, words):
    g = {**_given(P), **extra}
    g = {k: v for k, v in g.items() if v is not None}
    with pytest.raises(GeomconError, match=words):
        _solve(g).answers


def test_statement_form():
    from geomcon.worksheet.statements import default_template, fill, shown_givens, template_form
    R = "cam.base_radius"
    g = _given(P)
    assert template_form(R, g) == "arm+rho"
    en, zh = (fill(t, shown_givens(R, g, lang)) for t, lang in zip(default_template(R, g), ("en", "zh")))
    assert "40 mm" in en and "L = 100 mm" in zh and "{" not in en + zh


def test_declared_mistakes_diagnosed():
    """The centre distance and ψ0 of the pressure angle's design (not moved), and its base circle, diagnosed;
    the wrong values come from the problem solved without ρallow (a separate solve)."""
    from geomcon.grading import grade
    from geomcon.grading.answers import read_answers
    from geomcon.grading.keyfile import key_from_problem
    from geomcon.grading.tables import grades_data
    g = _given(P)
    base = _solve({k: v for k, v in g.items() if k != "rho_allow"}).answers
    right = solve(load_problem(P)).answers
    key = key_from_problem(P)
    text = ("id,r0,a,psi0\n" f"1,{right['r0']!r},{right['a']!r},{right['psi0']!r}\n"
            f"2,{base['r0']!r},{base['a']!r},{base['psi0']!r}\n")
    rows = [r["answers"] for r in grades_data(grade(key, read_answers(text.encode())))["rows"]]
    assert [rows[0][k]["verdict"] for k in ("r0", "a", "psi0")] == ["correct"] * 3
    assert rows[1]["r0"]["diagnosis"] == "alpha_limit_only"
    assert rows[1]["a"]["diagnosis"] == rows[1]["psi0"]["diagnosis"] == "centre_not_moved"


def test_eccentric_acceleration_with_omega_not_squared_is_diagnosed():
    """Seed 001-27 (ω = 10 rad/s): a and a_max given as ω·s″ (the closed form divided by ω) are diagnosed."""
    from geomcon.cam.eccentric import Translating
    from geomcon.cam.eccentric_speeds import translating_maxima, translating_speeds
    from geomcon.grading import grade
    from geomcon.grading.answers import read_answers
    from geomcon.grading.keyfile import key_from_problem
    from geomcon.grading.tables import grades_data
    p = ROOT / "problems" / "001-27_eccentric_roller_offset.toml"
    g = _given(p)
    cam = Translating(g["R"], g["OA"], g["e"], g["rr"], g["follower"], g["rotation"])
    w = g["omega"]
    phi = cam.phi_from(delta=g.get("delta"), A_angle=g.get("A_angle"), contact_angle=g.get("contact_angle"),
                       turn=g.get("turn") or 0.0)
    a = translating_speeds(cam, phi, w)[1]
    a_max = translating_maxima(cam, w)[1]
    text = f"id,a,a_max\n1,{a!r},{a_max!r}\n2,{a / w!r},{a_max / w!r}\n"
    rows = [r["answers"] for r in grades_data(grade(key_from_problem(p), read_answers(text.encode())))["rows"]]
    assert rows[0]["a"]["verdict"] == rows[0]["a_max"]["verdict"] == "correct"
    assert rows[1]["a"]["diagnosis"] == rows[1]["a_max"]["diagnosis"] == "omega_not_squared"
