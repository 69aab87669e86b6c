"""cam.translating against its closed-form twin on random programs of every law (fixed seed): the pitch
points of the inversion steps, s, α, ρ; the cases built to trigger undercut and a non-convex flat face;
the profile's accuracy (chord error vs tolerance) and validation; laziness; the CSV export; refusals."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from geomcon.cam.diagrams import motion_diagrams_svg
from geomcon.cam.laws import LAW_NAMES
from geomcon.cam.profile import (STRICT_TOLERANCE_REL, TOLERANCE_REL, chord_error, curvature, pressure_angle, rho_min,
                                 validate_roller)
from geomcon.cam.program import parse_program
from geomcon.cam.translating import TranslatingCam
from geomcon.cli import main
from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.recipes.cam_common import division_angles
from geomcon.solve import solve


def _program(rng: random.Random) -> list[dict]:
    rise, ret = rng.uniform(60, 160), rng.uniform(60, 140)
    d1 = rng.uniform(0, 360 - rise - ret - 10)
    segs = [{"kind": "rise", "angle": rise, "law": rng.choice(LAW_NAMES)}]
    if d1 > 1:
        segs.append({"kind": "dwell", "angle": d1})
    segs.append({"kind": "return", "angle": ret, "law": rng.choice(LAW_NAMES)})
    segs.append({"kind": "dwell", "angle": 360 - rise - ret - (d1 if d1 > 1 else 0)})
    return segs


def _given(rng: random.Random, follower: str) -> dict:
    r0 = rng.uniform(20, 80)
    g = {"follower": follower, "r0": r0, "h": rng.uniform(0.1, 0.6) * r0, "program": _program(rng),
         "rotation": rng.choice(["ccw", "cw"]), "e": rng.uniform(-0.4, 0.4) * r0,
         "at": [round(rng.uniform(0, 360), 3) for _ in range(5)]}
    if follower == "roller":
        g["rr"] = rng.uniform(0.05, 0.3) * r0
    return g


def _solve(**given):
    return solve(problem_from_dict({"recipe": "cam.translating", "given": given}, name="t"))


@pytest.mark.parametrize("i", range(36))
def test_random_cams_agree_with_the_twin(i):
    rng = random.Random(5100 + i)
    follower = ("knife", "roller", "flat")[i % 3]
    g = _given(rng, follower)
    sol = _solve(**g)
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    names = {c["quantity"].split("[")[0] for c in sol.checks}
    assert {"h", "alpha_max_rise", "alpha_max_return", "rho_min_actual", "undercut", "s", "alpha"} <= names
    assert ("rho_min_pitch" in names) == (follower != "flat")
    assert ("face_width" in names) == (follower == "flat")


@pytest.mark.parametrize("i", range(12))
def test_inversion_points_equal_the_parametric_pitch_curve(i):
    rng = random.Random(5200 + i)
    g = _given(rng, "roller" if i % 2 else "knife")
    sol = _solve(**g)
    prog = parse_program(g["program"])
    cam = TranslatingCam(prog, g["h"], g["r0"], g["e"], g["rotation"])
    divs = division_angles(prog)
    for k, dv in enumerate(divs, 1):
        B = sol.scene.value(f"B{k}")
        x, y = cam.pitch(dv)
        assert math.hypot(B.x - float(x), B.y - float(y)) <= 1e-9, (k, dv)
    # the profile machinery's curve: points, curvature and pressure angle against the closed forms
    curve = sol.scene.value("pitch")
    d = np.radians(np.array([rng.uniform(0, 360) for _ in range(50)]))
    c6 = curve.eval(d)
    X, Y = cam.pitch(np.degrees(d))
    assert np.abs(c6[0] - X).max() <= 1e-9 * g["r0"] and np.abs(c6[1] - Y).max() <= 1e-9 * g["r0"]
    k_machine = curve.orientation * curvature(c6)
    assert np.allclose(k_machine, cam.pitch_curvature(d), rtol=1e-9, atol=1e-12 / g["r0"])
    inv = -1.0 if g["rotation"] == "ccw" else 1.0
    a = np.degrees(pressure_angle(c6, -np.sin(inv * d), np.cos(inv * d)))
    assert np.allclose(a, cam.alpha(np.degrees(d)), rtol=1e-9, atol=1e-9)
    assert rho_min(curve).value == pytest.approx(cam.rho_min_pitch(), rel=1e-9)


def test_offset_side_convention():
    """逆转右偏, 顺转左偏: the right offset lowers the rise's α for a ccw cam, the left one for a cw cam."""
    prog = [{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
            {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]

    def rise(rotation, e):
        return _solve(follower="knife", r0=40, h=20, e=e, rotation=rotation, program=prog).answers["alpha_max_rise"]

    centred = rise("ccw", 0.0)
    assert rise("ccw", 8.0) < centred < rise("ccw", -8.0)
    assert rise("cw", -8.0) < centred < rise("cw", 8.0)


def test_seed_001_23_and_001_24_values():
    s_cos = [0, 0.609, 2.3431, 4.9385, 8, 11.0615, 13.6569, 15.391, 16]
    sol = solve(problem_from_dict({"recipe": "cam.translating", "given": {
        "follower": "knife", "r0": 30, "h": 16, "rotation": "ccw", "at": [15 * k for k in range(9)],
        "program": [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
                    {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}]}}, name="t"))
    assert np.allclose(sol.answers["s"], s_cos, atol=5e-5)
    # the seed's pitch points (r0 + s)(sin δ, cos δ): 15° → (7.9222, 29.566), 105° → (43.8444, −11.7481)
    divs = division_angles(parse_program(sol.problem.given["program"]))
    B1, B7 = sol.scene.value(f"B{divs.index(15.0) + 1}"), sol.scene.value(f"B{divs.index(105.0) + 1}")
    assert (round(B1.x, 4), round(B1.y, 3)) == (7.9222, 29.566)
    assert (round(B7.x, 4), round(B7.y, 4)) == (43.8444, -11.7481)
    from geomcon.problems import load_problem
    s100 = solve(load_problem("problems/001-24_cam_displacement_at_100.toml")).answers["s"][0]
    assert s100 == pytest.approx(15 - 2 * 15 * (50 / 150) ** 2, rel=1e-12)


UNDERCUT = {"follower": "roller", "r0": 30, "rr": 20, "h": 30, "rotation": "ccw",
            "program": [{"kind": "rise", "angle": 60, "law": "cycloidal"}, {"kind": "dwell", "angle": 30},
                        {"kind": "return", "angle": 60, "law": "cycloidal"}, {"kind": "dwell", "angle": 210}]}


def test_undercut_is_detected_trimmed_and_validated():
    sol = _solve(**UNDERCUT)
    assert sol.answers["undercut"] is True and sol.answers["rho_min_actual"] < 0
    assert any("undercut" in w for w in sol.warnings)
    prof = sol.scene.value("profile")
    assert prof.trimmed and prof.undercut and prof.ring().is_simple
    v = validate_roller(prof, sol.scene.value("pitch"), 20.0)
    assert v["simple"] and v["max_interference"] <= prof.tolerance     # no roller cuts into the cam
    assert v["max_lift"] > 0.1 and len(v["lift_at"]) > 0                # but it lifts off where undercut
    # just below the limit: no undercut, a warning that ρmin < 3·rr
    rho = sol.answers["rho_min_pitch"]
    ok = _solve(**{**UNDERCUT, "rr": 0.97 * rho})
    assert ok.answers["undercut"] is False and any("below 3·rr" in w for w in ok.warnings)
    prof = ok.scene.value("profile")
    v = validate_roller(prof, ok.scene.value("pitch"), 0.97 * rho)
    assert v["simple"] and v["max_interference"] <= prof.tolerance and v["max_lift"] <= prof.tolerance


@pytest.mark.parametrize("strict", [False, True])
def test_profile_error_is_within_tolerance(strict):
    rng = random.Random(77)
    for follower in ("roller", "knife"):
        g = _given(rng, follower)
        g["program"] = [{"kind": "rise", "angle": 140, "law": "poly345"}, {"kind": "dwell", "angle": 40},
                        {"kind": "return", "angle": 100, "law": "cosine"}, {"kind": "dwell", "angle": 80}]
        sol = _solve(**g, strict=strict)
        prof = sol.scene.value("profile")
        size = g["r0"] + g["h"] + g.get("rr", 0.0)                # the tolerance scales with the cam
        assert prof.tolerance == pytest.approx((STRICT_TOLERANCE_REL if strict else TOLERANCE_REL) * size, rel=1e-15)
        d = np.linspace(0.0, 2 * math.pi, 400_000, endpoint=False)
        x, y = sol.scene.value("pitch").eval(d)[:2]
        err = chord_error(prof.xy, np.column_stack([x, y]), g.get("rr", 0.0))
        assert err <= prof.tolerance * 1.05
        assert err >= prof.tolerance * 0.05          # the sample count is chosen, not excessive


def test_flat_face_convexity_cases():
    base = {"follower": "flat", "h": 20, "rotation": "ccw",
            "program": [{"kind": "rise", "angle": 90, "law": "cosine"}, {"kind": "dwell", "angle": 30},
                        {"kind": "return", "angle": 90, "law": "cosine"}, {"kind": "dwell", "angle": 150}]}
    # r0 + s + s″ at the rise's end: r0 + 20 − 20·π²/2/(π/2)² = r0 − 20
    bad = _solve(**base, r0=15)
    assert bad.answers["convex"] is False and bad.answers["rho_min_actual"] == pytest.approx(-5.0, rel=1e-9)
    assert any("cannot follow" in w for w in bad.warnings)
    prof = bad.scene.value("profile")
    assert prof.trimmed and prof.ring().is_simple
    good = _solve(**base, r0=25)
    assert good.answers["convex"] is True and good.answers["rho_min_actual"] == pytest.approx(5.0, rel=1e-9)
    assert good.answers["face_width_right"] == pytest.approx(20 * math.pi / 2 / (math.pi / 2), rel=1e-9)
    # a uniform law makes the velocity drop: never convex, whatever r0
    uni = _solve(**{**base, "r0": 60, "program": [{"kind": "rise", "angle": 90, "law": "uniform"},
                                                  {"kind": "dwell", "angle": 270 - 90},
                                                  {"kind": "return", "angle": 90, "law": "cycloidal"}]})
    assert uni.answers["convex"] is False and uni.answers["rho_min_actual"] > 0
    assert all(c["ok"] for c in uni.checks)


def test_answers_never_compute_the_profile_or_the_drawing():
    sol = _solve(**UNDERCUT)
    sol.answers, sol.checks
    assert not sol.scene.is_evaluated("profile") and not sol.scene.is_evaluated("profile_curve")
    assert not sol.scene.is_evaluated("mark_alpha") and not sol.scene.is_evaluated("roller0")
    few = sol.stats["steps_evaluated"]
    assert few < sol.stats["steps_total"] / 3
    sol.svg()
    assert sol.scene.is_evaluated("profile") and sol.stats["steps_evaluated"] > few


def test_profile_csv(tmp_path, capsys):
    out = tmp_path / "p.csv"
    assert main(["solve", "problems/200-01_cam_roller_offset.toml", "--profile-csv", str(out)]) == 0
    rows = out.read_text().splitlines()
    assert rows[0] == "x_mm,y_mm,delta_deg"
    xyd = np.array([[float(v) for v in r.split(",")] for r in rows[1:]])
    assert len(xyd) > 200 and np.all(np.diff(xyd[:, 2]) >= 0) and xyd[-1, 2] <= 360.0
    sol = solve(problem_from_dict({"recipe": "cam.translating", "given": {
        "follower": "roller", "r0": 40, "e": 10, "rr": 10, "h": 20, "rotation": "ccw",
        "program": [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
                    {"kind": "return", "angle": 90, "law": "cycloidal"}, {"kind": "dwell", "angle": 90}]}}, name="t"))
    d = np.linspace(0, 2 * math.pi, 200_000, endpoint=False)
    x, y = sol.scene.value("pitch").eval(d)[:2]
    assert chord_error(xyd[:, :2], np.column_stack([x, y]), 10.0) <= 1.05e-3
    bad = tmp_path / "no.csv"
    assert main(["solve", "problems/001-08_crank_rocker.toml", "--profile-csv", str(bad)]) == 2
    assert "no cam profile" in capsys.readouterr().err and not bad.exists()


PROG = [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
        {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}]


@pytest.mark.parametrize("given, words", [
    ({"follower": "knife", "rr": 5}, "only a roller follower"),
    ({"follower": "roller"}, "needs rr"),
    ({"follower": "knife", "e": 30}, "misses the base circle"),
    ({"follower": "roller", "rr": 31}, "would vanish"),
    ({"follower": "knife", "program": PROG[:3]}, "not 360°"),
    ({"follower": "knife", "program": [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 240}]},
     "needs a return"),
    ({"follower": "knife", "program": [{"kind": "rise", "angle": 120, "law": "sine-ish"}] + PROG[1:]},
     "unknown motion law"),
])
def test_refusals_are_one_line(given, words):
    g = {"r0": 30, "h": 16, "program": PROG, **given}
    with pytest.raises(NotAMechanism) as exc:
        _solve(**g).answers
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_motion_diagrams_are_deterministic_and_mark_impacts():
    prog = parse_program(PROG)
    a = motion_diagrams_svg(prog, 16.0, title="cosine")
    assert a == motion_diagrams_svg(prog, 16.0, title="cosine")
    assert "soft" in a and "rigid" not in a.replace("刚性", "")
    uni = motion_diagrams_svg(parse_program([{**s, "law": "uniform"} if "law" in s else s for s in PROG]), 16.0)
    assert uni.count("rigid") >= 4
