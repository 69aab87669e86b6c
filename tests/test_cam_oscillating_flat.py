"""cam.oscillating with a flat-faced arm against its twin (geomcon/cam/oscillating_flat.py) on random programs
of every law (fixed seed): the envelope's contact points, places along the face and radii of curvature against
the instant-centre closed forms, ψ0 from sin ψ0 = (r0 + f)/a and the construction, the convexity cases built
to trigger, laziness, the problem file and the refusals."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from geomcon.cam.laws import LAW_NAMES
from geomcon.cam.oscillating_flat import FlatArmCam
from geomcon.cam.profile import envelope
from geomcon.cam.program import parse_program
from geomcon.errors import NotAMechanism
from geomcon.geometry import Point
from geomcon.problems import load_problem, problem_from_dict
from geomcon.recipes.cam_oscillating_flat import face_place, flat_family

PROGRAM = [{"kind": "rise", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60},
           {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]
BASE = {"follower": "flat", "a": 120, "r0": 50, "h": 15, "program": PROGRAM}


def _solve(**given):
    from geomcon.solve import solve
    return solve(problem_from_dict({"recipe": "cam.oscillating", "given": given}, name="t"))


def _given(rng: random.Random, i: int) -> dict:
    """A random working flat-faced arm: a big enough base circle, a moderate stroke, any law and sense."""
    a = rng.uniform(60, 250)
    laws = (LAW_NAMES[i % 5], LAW_NAMES[(i // 5) % 5])
    rise, ret = rng.uniform(90, 160), rng.uniform(90, 140)
    d1 = rng.uniform(0, 360 - rise - ret - 10)
    prog = [{"kind": "rise", "angle": rise, "law": laws[0]}]
    if d1 > 1:
        prog.append({"kind": "dwell", "angle": d1})
    prog += [{"kind": "return", "angle": ret, "law": laws[1]},
             {"kind": "dwell", "angle": 360 - rise - ret - (d1 if d1 > 1 else 0)}]
    g = {"follower": "flat", "a": a, "r0": a * rng.uniform(0.3, 0.55), "h": rng.uniform(5, 18), "program": prog,
         "rotation": rng.choice(["ccw", "cw"]), "arm": rng.choice(["left", "right"]),
         "at": [round(rng.uniform(0, 360), 3) for _ in range(4)]}
    if i % 3:
        g["face_offset"] = a * rng.uniform(-0.15, 0.15)
    return g


def _cam(g: dict) -> FlatArmCam:
    return FlatArmCam(g["a"], g["r0"], g["h"], parse_program(g["program"]), g.get("rotation", "ccw"),
                      g.get("arm", "left"), float(g.get("face_offset", 0.0)))


def _inside(cam: FlatArmCam, n: int, rng: random.Random) -> np.ndarray:
    """Cam angles (deg) inside the smooth pieces of the turn, away from their ends."""
    out = []
    for seg in cam.program.segments:
        for _ in range(n):
            x = rng.uniform(0.03, 0.97)
            if seg.law is not None and seg.law.name == "parabolic" and abs(x - 0.5) < 0.03:
                x += 0.06
            out.append(seg.start + seg.angle * x)
    return np.array(out)


# ---------------------------------------------------------------------------------------------- twin
@pytest.mark.parametrize("i", range(30))
def test_random_flat_arms_agree_with_the_twin(i):
    g = _given(random.Random(7100 + i), i)
    sol = _solve(**g)
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    names = {c["quantity"].split("[")[0] for c in sol.checks}
    want = {"psi_max", "psi0", "alpha_max_rise", "alpha_max_return", "rho_min_actual", "convex", "undercut",
            "face_min", "face_max", "face_length", "psi", "alpha", "face_contact"}
    assert want <= names
    assert ("delta_alpha_max_rise" in names) == bool(g.get("face_offset"))
    if not g.get("face_offset"):
        assert sol.answers["alpha_max_rise"] == 0.0 and sol.answers["alpha"] == pytest.approx((0.0,) * 4, abs=1e-9)


@pytest.mark.parametrize("i", range(30))
def test_envelope_contact_points_are_the_instant_centre_closed_form(i):
    """The envelope of the inverted face lines (profile.envelope: λ = p′/β′, ρ = p + d²p/dβ²) against the
    twin (K = A0′ + l·u − f·n with l = a cos φ/(1 − εψ′), ρ = (a sin φ + εl′)/(1 − εψ′) − f) to 1e-9."""
    rng = random.Random(7200 + i)
    g = _given(rng, i)
    cam = _cam(g)
    fam = flat_family(cam)
    d = _inside(cam, 8, rng)
    x, y, _, rho = envelope(fam, np.radians(d))
    kx, ky = cam.contact_point(d)
    scale = g["a"]
    assert np.max(np.hypot(x - kx, y - ky)) <= 1e-9 * scale
    np.testing.assert_allclose(rho, cam.rho(d), rtol=0, atol=1e-9 * scale)
    lv = face_place(fam, Point(0.0, g["a"]), -float(cam.sigma), cam.tau, np.radians(d))
    np.testing.assert_allclose(lv, cam.contact(d), rtol=0, atol=1e-9 * scale)
    # the contact lies on its face line, which is tangent to the profile's base circle at δ = 0
    beta, _, _, p = fam.eval(np.radians(d))[:4]
    np.testing.assert_allclose(kx * np.cos(beta) + ky * np.sin(beta), p, rtol=0, atol=1e-9 * scale)
    assert float(fam.eval(np.array([0.0]))[3][0]) == pytest.approx(g["r0"], rel=1e-12)


@pytest.mark.parametrize("i", range(15))
def test_contact_by_finite_differences(i):
    """l′ and ρ of the twin against finite differences of its own contact point: the profile's tangent is
    along the face (K′·n = 0) and |K′| = |ρ|·|β′|."""
    rng = random.Random(7300 + i)
    cam = _cam(_given(rng, i))
    d = _inside(cam, 5, rng)
    step = 0.01
    h = math.radians(step)
    K = lambda t: np.array(cam.contact_point(t))                      # noqa: E731
    dK = (-K(d + 2 * step) + 8 * K(d + step) - 8 * K(d - step) + K(d - 2 * step)) / (12 * h)
    m = cam.motion(d)
    speed = cam.speed(m)
    np.testing.assert_allclose(np.hypot(*dK), np.abs(cam.rho(d)) * speed, rtol=1e-6)
    dl = (-cam.contact(d + 2 * step) + 8 * cam.contact(d + step) - 8 * cam.contact(d - step)
          + cam.contact(d - 2 * step)) / (12 * h)
    np.testing.assert_allclose(dl, cam.contact_slope_of(m), rtol=1e-6, atol=1e-6 * cam.a)


@pytest.mark.parametrize("i", range(10))
def test_psi0_by_the_tangent_construction(i):
    g = _given(random.Random(7400 + i), i)
    sol = _solve(**g)
    f = float(g.get("face_offset", 0.0))
    assert sol.answers["psi0"] == pytest.approx(math.degrees(math.asin((g["r0"] + f) / g["a"])), rel=1e-11)
    T0 = sol.scene.value("T0")
    assert math.hypot(T0.x, T0.y) == pytest.approx(g["r0"], rel=1e-12)
    assert (T0.x < 0) == (g["arm"] == "left")


def test_extremes_are_extreme():
    for i in range(10):
        cam = _cam(_given(random.Random(7500 + i), i))
        d = np.linspace(0, 360, 72001)[:-1]
        (lo, _), (hi, _) = cam.contact_extremes()
        l = cam.contact(d)
        # one-sided limits at the breaks are approached, not sampled: the grid gets within ~l′·Δδ of them
        assert lo <= l.min() + 1e-12 * cam.a and l.min() <= lo + 1e-4 * cam.a
        assert hi >= l.max() - 1e-12 * cam.a and l.max() >= hi - 1e-4 * cam.a
        assert cam.rho_min()[0] <= cam.rho(d).min() + 1e-12 * cam.a


def test_face_through_the_pivot_has_zero_pressure_angle():
    sol = _solve(**BASE, at=[30, 100, 200])
    a = sol.answers
    assert a["alpha"] == pytest.approx((0.0, 0.0, 0.0), abs=1e-9) and a["alpha_max_rise"] == 0.0 and a["alpha_max_return"] == 0.0
    assert "delta_alpha_max_rise" not in a
    off = _solve(**BASE, face_offset=10, at=[30, 100, 200])
    cam = _cam({**BASE, "face_offset": 10})
    assert off.answers["alpha"] == pytest.approx(tuple(np.degrees(np.arctan(10 / cam.contact([30, 100, 200])))),
                                                 abs=1e-12)
    assert off.answers["alpha_max_rise"] > 0 and off.ok


# ---------------------------------------------------------------------------------------------- convexity
def test_non_convex_built_to_trigger():
    """r0 = 40 is too small for this cycloidal program (ρ < 0 near the rise's end); r0 = 50 is enough."""
    for r0, convex in ((40, False), (50, True)):
        sol = _solve(**{**BASE, "r0": r0})
        assert sol.answers["convex"] is convex and sol.answers["undercut"] is (not convex) and sol.ok
        assert (sol.answers["rho_min_actual"] > 0) is convex
        assert any("cannot follow" in w for w in sol.warnings) is (not convex)
        prof = sol.scene.value("profile")
        assert prof.undercut is (not convex) and prof.ring().is_simple


def test_velocity_drop_jumps_back():
    """A uniform rise: ψ′ drops at its end, the contact jumps back along the face: not convex."""
    prog = [{"kind": "rise", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 60},
            {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]
    cam = _cam({**BASE, "program": prog})
    jumps = cam.backward_jumps()
    assert jumps and cam.rho_min()[0] > 0
    sol = _solve(**{**BASE, "program": prog})
    assert sol.answers["convex"] is False and sol.ok
    assert any("jumps back along the face" in w for w in sol.warnings)


def test_answers_alone_compute_no_profile_nor_drawing():
    sol = _solve(**BASE, face_offset=8, at=[45.0])
    sol.answers
    sol.checks
    assert not sol.scene.is_evaluated("profile") and not sol.scene.is_evaluated("profile_curve")
    assert not sol.scene.is_evaluated("face_d1")
    assert sol.stats["steps_evaluated"] < sol.stats["steps_total"] / 2
    sol.svg()
    assert sol.scene.is_evaluated("profile")


def test_problem_file():
    from geomcon.solve import solve
    sol = solve(load_problem("problems/200-07_oscillating_flat_face.toml"))
    assert sol.ok and sol.answers["convex"] is True
    assert not [w for w in sol.warnings if "published" in w]


# ---------------------------------------------------------------------------------------------- refusals
@pytest.mark.parametrize("change, words", [
    (dict(rr=5), ["rr = 5", "flat-faced arm"]),
    (dict(L=100), ["L = 100", "face_max"]),
    (dict(r0=120), ["r0 + face_offset = 120", "a = 120"]),
    (dict(face_offset=-50), ["face_offset = -50", "−r0 = -50"]),
    (dict(r0=100, h=40), ["ψ0 + h", "90°"]),
    (dict(program=[{"kind": "rise", "angle": 10, "law": "uniform"}, {"kind": "dwell", "angle": 10},
                   {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 220}],
          rotation="cw"), ["1 − εψ′", "δ = 0°", "infinity"]),
    (dict(divisions=0.5), ["divisions", "0.5"]),
])
def test_refusals(change, words):
    g = {**BASE, **change}
    with pytest.raises(NotAMechanism) as exc:
        _solve(**g)
    msg = str(exc.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg, msg


def test_roller_refuses_a_face_offset_and_needs_L():
    g = {"follower": "roller", "a": 100, "L": 80, "r0": 40, "rr": 10, "h": 20, "program": PROGRAM}
    with pytest.raises(NotAMechanism, match="face_offset = 5"):
        _solve(**g, face_offset=5)
    with pytest.raises(NotAMechanism, match="needs L"):
        _solve(**{k: v for k, v in g.items() if k != "L"})
