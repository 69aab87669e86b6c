"""cam.oscillating against its twin on random programs of every law (fixed seed): the inversion's points
(rotations) against the parametric pitch curve, ψ, α, ρ against the closed forms, α and ψ0 by independent
numeric routes (numerically differentiated pitch curve, arccos), the sense rule, the slotter seed (000-04 …
000-08), the undercut built to trigger, laziness, and the refusals."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from geomcon.cam.laws import LAW_NAMES
from geomcon.cam.oscillating import OscillatingCam, psi0_rad
from geomcon.cam.profile import validate_roller
from geomcon.cam.program import parse_program
from geomcon.errors import NotAMechanism
from geomcon.problems import load_problem, problem_from_dict
from geomcon.solve import solve

SEED_PROGRAM = [{"kind": "rise", "angle": 10, "law": "parabolic"}, {"kind": "dwell", "angle": 160},
                {"kind": "return", "angle": 10, "law": "parabolic"}, {"kind": "dwell", "angle": 180}]
SEED = {"follower": "roller", "a": 150, "L": 132, "r0": 50, "rr": 5, "h": 20, "program": SEED_PROGRAM}


def _program(rng: random.Random, laws: tuple[str, str]) -> list[dict]:
    rise, ret = rng.uniform(60, 160), rng.uniform(60, 140)
    d1 = rng.uniform(0, 360 - rise - ret - 10)
    segs = [{"kind": "rise", "angle": rise, "law": laws[0]}]
    if d1 > 1:
        segs.append({"kind": "dwell", "angle": d1})
    segs.append({"kind": "return", "angle": ret, "law": laws[1]})
    segs.append({"kind": "dwell", "angle": 360 - rise - ret - (d1 if d1 > 1 else 0)})
    return segs


def _given(rng: random.Random, i: int) -> dict:
    a = rng.uniform(40, 300)
    L = a * rng.uniform(0.55, 1.1)
    lo = abs(a - L)
    r0 = lo + (min(a, a + L) - lo) * rng.uniform(0.25, 0.7)
    laws = (LAW_NAMES[i % 5], LAW_NAMES[(i // 5) % 5])
    g = {"follower": "roller" if i % 2 == 0 else "knife", "a": a, "L": L, "r0": r0, "h": rng.uniform(8, 30),
         "program": _program(rng, laws), "rotation": rng.choice(["ccw", "cw"]), "arm": rng.choice(["left", "right"]),
         "at": [round(rng.uniform(0, 360), 3) for _ in range(4)]}
    if g["follower"] == "roller":
        g["rr"] = r0 * rng.uniform(0.05, 0.25)
    return g


def _solve(**given):
    return solve(problem_from_dict({"recipe": "cam.oscillating", "given": given}, name="t"))


def _cam(g: dict) -> OscillatingCam:
    return OscillatingCam(g["a"], g["L"], g["r0"], g["h"], parse_program(g["program"]), g.get("rotation", "ccw"),
                          g.get("arm", "left"))


def _numeric_alpha(cam: OscillatingCam, d: np.ndarray, step: float = 1e-3) -> np.ndarray:
    """α from the numerically differentiated pitch curve (5-point stencil) and the arm A0′B: the acute angle
    between the tangent and the arm (normal ⊥ tangent, velocity ⊥ arm)."""
    P = lambda x: np.array(cam.pitch(x))                       # noqa: E731
    T = (-P(d + 2 * step) + 8 * P(d + step) - 8 * P(d - step) + P(d - 2 * step)) / 12.0
    arm = P(d) - np.array(cam.pivot(d))
    c = np.abs((T * arm).sum(0)) / np.hypot(*T) / np.hypot(*arm)
    return np.degrees(np.arccos(np.clip(c, 0.0, 1.0)))


def _smooth_angles(cam: OscillatingCam, n: int, rng: random.Random, margin: float = 0.05) -> np.ndarray:
    """Cam angles (deg) inside the rise and the return, away from the pieces' ends."""
    out = []
    for seg in cam.program.segments:
        if seg.kind != "dwell":
            for _ in range(n):
                x = rng.uniform(margin, 1 - margin)
                if seg.law.name == "parabolic" and abs(x - 0.5) < margin:
                    x += 2 * margin
                out.append(seg.start + seg.angle * x)
    return np.array(out)


# ---------------------------------------------------------------------------------------------- twin
@pytest.mark.parametrize("i", range(30))
def test_random_cams_agree_with_the_twin(i):
    rng = random.Random(6200 + i)
    g = _given(rng, i)
    sol = _solve(**g)
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    names = {c["quantity"].split("[")[0] for c in sol.checks}
    want = {"psi_max", "psi0", "alpha_max_rise", "delta_alpha_max_rise", "alpha_max_return", "delta_alpha_max_return",
            "rho_min_pitch", "rho_min_actual", "undercut", "psi", "alpha", "pitch_x", "pitch_y"}
    assert want <= names
    assert ("profile_x" in names) == (g["follower"] == "roller")


@pytest.mark.parametrize("i", range(30))
def test_inversion_points_are_the_parametric_pitch_curve(i):
    """Every point the construction lays off (rotations of A0 and B0, ψ laid off at A0′) equals the closed
    form B(δ) to 1e-9 mm; ψ and α measured on them equal the formulas."""
    rng = random.Random(6300 + i)
    g = _given(rng, i)
    sol = _solve(**g)
    cam, sc = _cam(g), sol.scene
    keys = [k.key for k in sc.steps if k.key.startswith("B_d")]
    divs = [s for s in sc.steps if s.key.startswith("A_d")]
    assert keys and len(keys) == len(divs)
    vals = sc.evaluate(keys + [s.key for s in divs])
    for key, step in zip(keys, divs):
        d = step.args[3]
        x, y = cam.pitch(d)
        ax, ay = cam.pivot(d)
        B, A = vals[key], vals[step.key]
        assert math.hypot(B.x - float(x), B.y - float(y)) <= 1e-9 * max(1.0, g["a"])
        assert math.hypot(A.x - float(ax), A.y - float(ay)) <= 1e-9 * max(1.0, g["a"])
    at = np.array(g["at"])
    ans = sol.answers
    np.testing.assert_allclose(ans["psi"], np.degrees(cam.motion(at).psi), rtol=0, atol=1e-9)
    np.testing.assert_allclose(ans["alpha"], cam.pressure_angle(at), rtol=0, atol=1e-9)
    x, y = cam.pitch(at)
    np.testing.assert_allclose(ans["pitch_x"], x, rtol=0, atol=1e-9 * g["a"])
    np.testing.assert_allclose(ans["pitch_y"], y, rtol=0, atol=1e-9 * g["a"])


@pytest.mark.parametrize("i", range(25))
def test_pressure_angle_by_numeric_differentiation(i):
    """α closed form (tan) = α complex form (arg) = α from the numerically differentiated pitch curve."""
    rng = random.Random(6400 + i)
    cam = _cam(_given(rng, i))
    d = _smooth_angles(cam, 6, rng)
    m = cam.motion(d)
    np.testing.assert_allclose(cam.pressure_of(m), cam.pressure_arg(m), rtol=0, atol=1e-9)
    np.testing.assert_allclose(cam.pressure_of(m), _numeric_alpha(cam, d), rtol=0, atol=2e-6)


@pytest.mark.parametrize("i", range(25))
def test_derivatives_and_curvature(i):
    """Exact B′, B″ against finite differences; 1/ρ by the vector and the complex route agree to 1e-9."""
    rng = random.Random(6500 + i)
    cam = _cam(_given(rng, i))
    d = _smooth_angles(cam, 5, rng)
    x, y, dx, dy, ddx, ddy = cam.pitch_of(cam.motion(d))
    step = 0.02                                                       # degrees
    P = lambda t: np.array(cam.pitch(t))                             # noqa: E731
    h = math.radians(step)
    T = (-P(d + 2 * step) + 8 * P(d + step) - 8 * P(d - step) + P(d - 2 * step)) / (12 * h)
    N = (-P(d + 2 * step) + 16 * P(d + step) - 30 * P(d) + 16 * P(d - step) - P(d - 2 * step)) / (12 * h * h)
    scale = cam.a + cam.L
    np.testing.assert_allclose(T, [dx, dy], rtol=0, atol=1e-6 * scale)
    np.testing.assert_allclose(N, [ddx, ddy], rtol=0, atol=1e-4 * scale)
    m = cam.motion(d)
    k1, k2 = cam.convex_curvature_of(m), cam.convex_curvature_complex(m)
    np.testing.assert_allclose(k1, k2, rtol=1e-9, atol=1e-12 / scale)


@pytest.mark.parametrize("i", range(20))
def test_extrema_are_extreme(i):
    """α_max and ρmin against a dense sampling of the closed forms; the worst places by both routes."""
    rng = random.Random(6600 + i)
    cam = _cam(_given(rng, i))
    for part in ("rise", "return"):
        seg = next(s for s in cam.program.segments if s.kind == part)
        a1, d1 = cam.worst_pressure(part)
        a2, d2 = cam.worst_pressure(part, route="arg")
        assert a1 == pytest.approx(a2, rel=1e-12) and d1 == pytest.approx(d2, rel=1e-9, abs=1e-9)
        dense = cam.pressure_angle(np.linspace(seg.start, np.nextafter(seg.end, 0), 20001))
        assert dense.max() <= a1 + 1e-10 and dense.max() >= a1 - 1e-4
    rho, at = cam.rho_min()
    dense = cam.rho(np.linspace(0, 360, 36001))
    assert np.min(dense[dense > 0]) >= rho * (1 - 1e-10)
    assert rho == pytest.approx(cam.rho_min(cam.convex_curvature_complex)[0], rel=1e-9)


@pytest.mark.parametrize("i", range(20))
def test_psi0_by_arccos_and_by_the_construction(i):
    rng = random.Random(6700 + i)
    g = _given(rng, i)
    a, L, r0 = g["a"], g["L"], g["r0"]
    law_of_cosines = math.degrees(math.acos((a * a + L * L - r0 * r0) / (2 * a * L)))
    assert math.degrees(psi0_rad(a, L, r0)) == pytest.approx(law_of_cosines, rel=1e-11)
    sol = _solve(**g)
    B0 = sol.scene.value("B0")
    assert math.hypot(B0.x, B0.y) == pytest.approx(r0, rel=1e-12)
    assert math.hypot(B0.x, B0.y - a) == pytest.approx(L, rel=1e-12)
    assert sol.answers["psi0"] == pytest.approx(law_of_cosines, rel=1e-10)
    assert (B0.x < 0) == (g["arm"] == "left")


def test_textbook_frame_formula():
    """ccw cam, left arm: x = a sin δ − L sin(δ + ψ0 + ψ), y = a cos δ − L cos(δ + ψ0 + ψ)."""
    g = dict(SEED)
    cam = _cam(g)
    d = np.linspace(0, 360, 73)
    phi = cam.psi0 + cam.motion(d).psi
    t = np.radians(d)
    x, y = cam.pitch(d)
    np.testing.assert_allclose(x, 150 * np.sin(t) - 132 * np.sin(t + phi), atol=1e-12)
    np.testing.assert_allclose(y, 150 * np.cos(t) - 132 * np.cos(t + phi), atol=1e-12)
    assert cam.eps == -1


def test_mirror_images_have_the_same_pressure_angles():
    prog = parse_program(SEED_PROGRAM)
    d = np.linspace(0, 359, 200)
    c1 = OscillatingCam(100, 80, 40, 20, prog, "ccw", "left")
    c2 = OscillatingCam(100, 80, 40, 20, prog, "cw", "right")
    x1, y1 = c1.pitch(d)
    x2, y2 = c2.pitch(d)
    np.testing.assert_allclose(x1, -x2, atol=1e-12)
    np.testing.assert_allclose(y1, y2, atol=1e-12)
    np.testing.assert_allclose(c1.pressure_angle(d), c2.pressure_angle(d), atol=1e-12)


@pytest.mark.parametrize("a, L, r0, acute", [(100, 80, 40, False), (100, 110, 60, True)])
def test_sense_rule(a, L, r0, acute):
    """With ∠OB0A0 acute (L − a cos ψ0 > 0) a rise in the cam's sense (ε = +1) lowers the rise's α_max; with it
    obtuse the opposite sense does."""
    prog = parse_program([{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
                          {"kind": "return", "angle": 90, "law": "cycloidal"}, {"kind": "dwell", "angle": 90}])
    same = OscillatingCam(a, L, r0, 20, prog, "cw", "left")
    opposite = OscillatingCam(a, L, r0, 20, prog, "ccw", "left")
    assert (same.eps, opposite.eps) == (1, -1)
    assert (L - a * math.cos(same.psi0) > 0) == acute
    lower = same if acute else opposite
    higher = opposite if acute else same
    assert lower.worst_pressure("rise")[0] < higher.worst_pressure("rise")[0]


# ---------------------------------------------------------------------------------------------- seed
def test_slotter_seed_numbers():
    sol = _solve(**SEED, at=[2, 4, 6, 8, 10], alpha_allow=45)
    a = sol.answers
    assert a["psi0"] == pytest.approx(19.0822031254, abs=1e-9)
    assert (a["alpha_max_rise"], a["delta_alpha_max_rise"]) == (pytest.approx(82.1513343684, abs=1e-9),
                                                                pytest.approx(5.0, abs=1e-9))
    assert (a["alpha_max_return"], a["delta_alpha_max_return"]) == (pytest.approx(82.12452845, abs=1e-8),
                                                                    pytest.approx(175.0, abs=1e-9))
    assert a["rho_min_pitch"] == pytest.approx(1.45471156551, abs=1e-9) and a["undercut"] is True
    assert a["psi"] == pytest.approx((1.6, 6.4, 13.6, 18.4, 20.0), abs=1e-12)
    assert a["pitch_x"][0] == pytest.approx(-45.6668455891, abs=1e-9)
    assert a["profile_y"][0] == pytest.approx(32.094203363, abs=1e-8)
    assert sum("exceeds the allowance" in w for w in sol.warnings) == 2
    assert any(w.startswith("undercut") for w in sol.warnings)
    assert sol.ok
    # the printed ψ0 needs r0 = 37.85 mm
    assert math.degrees(psi0_rad(150, 132, 37.8513)) == pytest.approx(13.59, abs=1e-3)
    assert math.degrees(psi0_rad(150, 123, 50)) == pytest.approx(17.8232, abs=1e-4)


@pytest.mark.parametrize("name", ["000-04_slotter_cam_psi0", "000-05_slotter_cam_motion_law",
                                  "000-06_slotter_cam_pitch_points", "000-07_slotter_cam_actual_profile",
                                  "000-08_slotter_cam_pressure_angle", "200-05_oscillating_roller_cam",
                                  "200-06_oscillating_knife_same_sense"])
def test_problem_files(name):
    sol = solve(load_problem(f"problems/{name}.toml"))
    assert sol.ok
    if name.startswith("000"):
        assert any("82.151°" in w for w in sol.warnings)   # the Results' 3 decimals


# ---------------------------------------------------------------------------------------------- undercut
def test_undercut_built_to_trigger():
    base = dict(SEED)
    base["program"] = [{"kind": "rise", "angle": 60, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
                       {"kind": "return", "angle": 60, "law": "cycloidal"}, {"kind": "dwell", "angle": 180}]
    rho = _cam(base).rho_min()[0]
    for rr, cut in ((rho * 1.05, True), (rho * 0.95, False)):
        sol = _solve(**{**base, "rr": rr})
        assert sol.answers["undercut"] is cut and sol.ok
        assert any(w.startswith("undercut") for w in sol.warnings) == cut
        assert any("is below 3·rr" in w for w in sol.warnings) == (not cut)
        prof = sol.scene.value("profile")
        assert prof.trimmed == cut and prof.ring().is_simple
        check = validate_roller(prof, _cam(base).pitch_curve(), rr)
        assert check["max_interference"] <= prof.tolerance
        if not cut:
            assert check["max_lift"] <= prof.tolerance


def test_answers_alone_compute_no_profile_nor_drawing():
    sol = _solve(**SEED, at=[3.0])
    sol.answers
    sol.checks
    assert not sol.scene.is_evaluated("profile") and not sol.scene.is_evaluated("pitch_curve")
    assert sol.stats["steps_evaluated"] < sol.stats["steps_total"]
    sol.svg()
    assert sol.scene.is_evaluated("profile")


# ---------------------------------------------------------------------------------------------- refusals
@pytest.mark.parametrize("change, words", [
    (dict(r0=300), ["r0 = 300", "a + L = 282"]),
    (dict(L=40, r0=100), ["r0 = 100", "|a − L| = 110"]),
    (dict(L=100, r0=50), ["r0 = 50", "|a − L| = 50"]),
    (dict(L=300, r0=160), ["r0 = 160", "a = 150", "inside the base circle"]),
    (dict(h=170), ["ψ0 + h", "170°", "180°"]),
    (dict(rr=None), ["roller follower needs rr"]),
    (dict(follower="knife"), ["rr = 5", "knife"]),
    (dict(rr=50), ["rr = 50", "r0 = 50"]),
    (dict(divisions=2.5), ["divisions", "2.5"]),
    (dict(program=[{"kind": "rise", "angle": 10, "law": "parabolic"}, {"kind": "dwell", "angle": 350}]),
     ["return"]),
    (dict(program=[{"kind": "rise", "angle": 10, "law": "parabolic"}, {"kind": "return", "angle": 10, "law": "cosine"}]),
     ["20°", "360°"]),
])
def test_refusals(change, words):
    g = {**SEED, **change}
    g = {k: v for k, v in g.items() if v is not None}
    with pytest.raises(NotAMechanism) as exc:
        _solve(**g)
    msg = str(exc.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg, msg
