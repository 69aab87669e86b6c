"""cam.base_radius with a curvature limit (issue 14): a flat face's r0 = ρallow − min(s + s″) (GATE 2020: 48 mm),
a knife or roller cam's r0 grown from the pressure angle's until the pitch curve's ρmin reaches ρallow; each
against its twin on random instances, checked on a grid of the designed cam (the limit holds everywhere, is
reached, and no smaller circle at that offset meets it), and the refusals."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from geomcon.cam.program import parse_program
from geomcon.cam.translating import TranslatingCam
from geomcon.errors import GeomconError
from geomcon.problems import load_problem, problem_from_dict
from geomcon.solve import solve
from pathlib import Path

ROOT = Path(__file__).parents[1]
LAWS = ("cosine", "cycloidal", "poly345", "modified_sine", "modified_trapezoid", "double_harmonic", "parabolic")


def _solve(g):
    return solve(problem_from_dict({"recipe": "cam.base_radius", "given": g}, name="t"))


def _program(rng):
    rise, ret = rng.uniform(70, 150), rng.uniform(70, 150)
    dw = 360 - rise - ret
    return [{"kind": "rise", "angle": rise, "law": rng.choice(LAWS)}, {"kind": "dwell", "angle": dw / 2},
            {"kind": "return", "angle": ret, "law": rng.choice(LAWS)}, {"kind": "dwell", "angle": dw / 2}]


def test_gate_2020_flat_face():
    sol = solve(load_problem(ROOT / "problems" / "200-18_base_radius_flat_gate2020.toml"))
    assert sol.ok
    assert sol.answers["r0"] == pytest.approx(48.0, abs=1e-12)
    assert sol.answers["rho_min_profile"] == pytest.approx(40.0, abs=1e-12)


@pytest.mark.parametrize("i", range(12))
def test_random_flat_faces(i):
    rng = random.Random(14500 + i)
    g = {"follower": "flat", "h": rng.uniform(5, 40), "rho_allow": rng.uniform(5, 60), "program": _program(rng),
         "rotation": rng.choice(["ccw", "cw"])}
    sol = _solve(g)
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    r0 = sol.answers["r0"]
    prog = parse_program(g["program"])
    ends = [math.nextafter(math.radians(seg.end), 0.0) for seg in prog.segments]    # one-sided limits at the ends
    mids = [math.radians(seg.start + seg.angle / 2) for seg in prog.segments]        # (a parabolic law's jump)
    ends += mids + [math.nextafter(m, 0.0) for m in mids]
    d = np.sort(np.concatenate([np.linspace(0.0, 2 * math.pi, 20001), ends]))
    s, _, a = prog.motion(g["h"], d, radians=True)
    rho = r0 + s + a
    assert rho.min() >= g["rho_allow"] - 1e-9 * r0
    assert rho.min() <= g["rho_allow"] + 1e-4 * r0            # reached (to the grid's resolution)


@pytest.mark.parametrize("i", range(10))
def test_random_rollers_with_both_limits(i):
    rng = random.Random(14600 + i)
    h = rng.uniform(8, 25)
    g = {"h": h, "program": _program(rng), "alpha_allow": rng.uniform(25, 40), "rho_allow": rng.uniform(0.5, 2.5) * h,
         "rotation": rng.choice(["ccw", "cw"])}
    if i % 3 == 2:
        g["e"] = rng.uniform(-0.2, 0.2) * h
    sol = _solve(g)
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    ans = sol.answers
    assert ans["r0"] == max(ans["r0_alpha"], ans["r0_rho"])
    prog = parse_program(g["program"])
    cam = TranslatingCam(prog, h, ans["r0"], ans["e"], g["rotation"])
    assert cam.alpha_max("rise")[0] <= g["alpha_allow"] * (1 + 1e-9)
    assert cam.rho_min_pitch() >= g["rho_allow"] * (1 - 1e-9)
    if ans["r0_rho"] > ans["r0_alpha"] * (1 + 1e-9):             # the curvature binds: nothing smaller meets it
        for r in np.linspace(ans["r0_alpha"], ans["r0"], 12)[:-1]:
            assert TranslatingCam(prog, h, float(r), ans["e"], g["rotation"]).rho_min_pitch() < g["rho_allow"]


def test_the_curvature_limit_binds_in_the_bundled_example():
    sol = solve(load_problem(ROOT / "problems" / "200-19_base_radius_alpha_and_rho.toml"))
    assert sol.ok and sol.answers["r0_rho"] > sol.answers["r0_alpha"]
    assert sol.answers["rho_min_pitch"] == pytest.approx(18.0, rel=1e-12)


def test_a_loose_curvature_limit_leaves_the_pressure_angle_design():
    base = {"h": 20, "alpha_allow": 30, "rotation": "ccw",
            "program": [{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
                        {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]}
    plain = _solve(base).answers
    both = _solve({**base, "rho_allow": 1.0}).answers
    for k in ("r0", "e", "s0", "rho_min_pitch"):
        assert both[k] == plain[k]
    assert both["r0_rho"] == both["r0_alpha"] == plain["r0"]


@pytest.mark.parametrize("extra, message", [
    ({"follower": "flat"}, "needs rho_allow"),
    ({"follower": "flat", "rho_allow": 30, "alpha_allow": 30}, "alpha_allow = 30 is given for a flat-faced follower"),
    ({"follower": "flat", "rho_allow": 30, "e": 5}, "e = 5 is given for a flat-faced follower"),
    ({"rho_allow": 30}, "alpha_allow is missing"),
    ({"rho_allow": 30, "alpha_allow": 30, "motion": "oscillating", "L": 50, "a": 60}, "a = 60 is given with rho_allow"),
    ({"rho_allow": 30, "alpha_allow": 30, "motion": "oscillating", "L": 50, "follower": "flat"},
     "is given for an oscillating follower"),
    ({}, "alpha_allow is missing"),
])
def test_refusals(extra, message):
    g = {"h": 20, "program": [{"kind": "rise", "angle": 180, "law": "cosine"}, {"kind": "return", "angle": 180, "law": "cosine"}],
         **extra}
    with pytest.raises(GeomconError) as exc:
        _solve(g)
    assert message in str(exc.value), str(exc.value)


def test_a_velocity_drop_is_refused_for_a_flat_face():
    g = {"follower": "flat", "h": 20, "rho_allow": 30,
         "program": [{"kind": "rise", "angle": 180, "law": "uniform"}, {"kind": "dwell", "angle": 180}]}
    with pytest.raises(GeomconError) as exc:
        _solve(g)
    assert "velocity drops at δ = 180°" in str(exc.value)
