"""cam.eccentric: the seed problems, random eccentric cams (fixed seed) against the closed forms and an
independent numerical route, the states, and the refusals."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.cam.eccentric import Oscillating, Translating
from geomcon.errors import NotAMechanism, ProblemError
from geomcon.problems import load_problem, problem_from_dict
from geomcon.solve import solve


def _solve(**given):
    return solve(problem_from_dict({"recipe": "cam.eccentric", "given": given}, name="t"))


def _ok(sol):
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad


@pytest.mark.parametrize("name, expect", [
    ("001-25_eccentric_knife_centred", dict(r0=30, h=60, s=37.0820393, alpha=26.5650512)),
    ("001-25b_eccentric_knife_contact_C", dict(s=60, alpha=0)),
    ("001-26_eccentric_knife_offset", dict(r0=20, alpha=41.8103149, delta=60, s=5.0401717, offset_correct=False,
                                           rise_angle=164.4775122)),
    ("001-27_eccentric_roller_offset", dict(r0=50, r0_actual=30, h=104.6007244, alpha=14.4775122, v=500,
                                            rise_angle=200.4059318, alpha_max_return=48.5903779)),
    ("001-28_eccentric_roller_centred", dict(r0=25, h=50, rise_angle=180, alpha=30)),
    ("001-29_eccentric_roller_offset_ccw", dict(r0=25, h=22.4264069, rise_angle=197.3986770,
                                                alpha_max_rise=36.8698976, alpha_min_rise=8.2132107,
                                                alpha_max_return=45.5846914)),
    ("001-29_eccentric_roller_offset_cw", dict(rise_angle=162.6013230, alpha_max_rise=45.5846914,
                                               alpha_min_rise=19.4712206)),
    ("001-30_eccentric_flat_offset", dict(r0=30, s=50, alpha=0, v=500, h=100)),
    ("001-30b_eccentric_flat_R60", dict(r0=10, s=50, v=500, h=100)),
    ("001-31_eccentric_oscillating_roller", dict(r0=30, psi0=16.1951167, psi_max=33.7996824,
                                                 rise_angle=189.3937384, alpha_max_rise=33.2038225,
                                                 alpha_max_return=42.1774186)),
])
def test_seed_problems(name, expect):
    sol = solve(load_problem(f"problems/{name}.toml"))
    _ok(sol)
    for k, v in expect.items():
        assert sol.answers[k] == pytest.approx(v, abs=1e-6), k


def _random_translating(rng):
    R = rng.uniform(10, 200)
    OA = rng.uniform(0.05, 0.9) * R
    follower = rng.choice(["knife", "roller", "flat"])
    rr = rng.uniform(0.05, 0.5) * R if follower == "roller" else 0.0
    r0 = R + rr - OA
    e = rng.uniform(-0.9, 0.9) * r0 if rng.random() < 0.8 else 0.0
    g = dict(R=R, OA=OA, follower=follower, e=e, rotation=rng.choice(["ccw", "cw"]), omega=rng.uniform(1, 50))
    if rr:
        g["rr"] = rr
    state = rng.choice(["delta", "A_angle", "contact_angle", None])
    if state == "delta":
        g["delta"] = rng.uniform(0, 360)
    elif state == "A_angle":
        g["A_angle"] = rng.uniform(-180, 180)
    elif state == "contact_angle":
        g["contact_angle"] = rng.uniform(-60, 60)
    if rng.random() < 0.3:
        g["turn"] = rng.uniform(0, 360)
    return g


@pytest.mark.parametrize("i", range(60))
def test_random_translating_cams_agree_with_the_twin(i):
    g = _random_translating(random.Random(5000 + i))
    _ok(_solve(**g))


def _golden(f, a, b, n=400):
    """Independent numerical extremum: dense grid, then golden section (maximum of f)."""
    xs = [a + (b - a) * i / n for i in range(n + 1)]
    i = max(range(n + 1), key=lambda j: f(xs[j]))
    lo, hi = xs[max(i - 1, 0)], xs[min(i + 1, n)]
    gr = (math.sqrt(5) - 1) / 2
    for _ in range(120):
        x1, x2 = hi - gr * (hi - lo), lo + gr * (hi - lo)
        if f(x1) > f(x2):
            hi = x2
        else:
            lo = x1
    return max(f(xs[i]), f(0.5 * (lo + hi)))


def _pitch_height(R, OA, e, rr, phi):
    """Brute-force intersection: the roller centre on x = e at distance R + rr from A, by bisection on y."""
    ax, ay = OA * math.cos(phi), OA * math.sin(phi)
    lo, hi = ay, ay + R + rr
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if (e - ax) ** 2 + (m - ay) ** 2 < (R + rr) ** 2:
            lo = m
        else:
            hi = m
    return lo


@pytest.mark.parametrize("i", range(25))
def test_random_cams_against_brute_force(i):
    rng = random.Random(7000 + i)
    R = rng.uniform(20, 100)
    OA = rng.uniform(0.1, 0.8) * R
    rr = rng.uniform(0, 0.4) * R
    e = rng.uniform(-0.8, 0.8) * (R + rr - OA)
    cam = Translating(R, OA, e, rr, "roller" if rr else "knife", rng.choice(["ccw", "cw"]))
    y = lambda p: _pitch_height(R, OA, e, rr, p)
    top = _golden(y, -math.pi, math.pi)
    low = -_golden(lambda p: -y(p), -math.pi, math.pi)
    assert cam.h == pytest.approx(top - low, rel=1e-9)
    assert cam.r0 == pytest.approx(math.hypot(e, low), rel=1e-9)
    # the pressure angle by the textbook's formula tan α = |ds/dδ − k·e| / (s0 + s), ds/dδ numerically
    phi = rng.uniform(-math.pi, math.pi)
    k = cam.sense
    dsd = k * (y(phi + 1e-6) - y(phi - 1e-6)) / 2e-6
    assert cam.alpha(phi) == pytest.approx(math.degrees(math.atan2(abs(dsd - k * e), y(phi))), abs=1e-6)
    # α at the rise's worst position by brute force over the rise
    span = math.radians(cam.rise_angle)
    worst = _golden(lambda d: cam.alpha(cam.phi_low + k * d), 0.0, span)
    assert cam.alpha_extremes("rise")["alpha_max_rise"] == pytest.approx(worst, rel=1e-9)


@pytest.mark.parametrize("i", range(15))
def test_random_oscillating_cams(i):
    rng = random.Random(9000 + i)
    R = rng.uniform(20, 60)
    OA = rng.uniform(0.1, 0.6) * R
    rr = rng.uniform(0.05, 0.3) * R
    Rp = R + rr
    a = Rp + OA + rng.uniform(10, 80)
    lo, hi = max(a - (Rp - OA), Rp + OA - a), a + Rp - OA
    L = rng.uniform(lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo))
    g = dict(R=R, OA=OA, follower="roller", rr=rr, a=a, L=L, rotation=rng.choice(["ccw", "cw"]),
             arm=rng.choice(["left", "right"]), delta=rng.uniform(0, 360))
    sol = _solve(**g)
    _ok(sol)
    cam = Oscillating(R, OA, a, L, rr, g["rotation"], g["arm"])
    # the swing at the state, by brute force: the arm angle is extreme at the lowest and highest positions
    psi = [cam.psi(cam.phi_of(d)) for d in range(0, 360)]
    assert max(psi) - min(psi) <= sol.answers["psi_max"] + 1e-9
    assert max(psi) - min(psi) == pytest.approx(sol.answers["psi_max"], rel=1e-3)


def test_flat_face_motion_does_not_depend_on_R():
    a = _solve(R=80, OA=50, follower="flat", e=25, delta=77, omega=3).answers
    b = _solve(R=60, OA=50, follower="flat", e=25, delta=77, omega=3).answers
    assert a["s"] == pytest.approx(b["s"], abs=1e-12) and a["v"] == pytest.approx(b["v"], abs=1e-12)
    assert a["r0"] - b["r0"] == pytest.approx(20)


def test_offset_rule_and_mirror():
    ccw = _solve(R=30, OA=10, e=15, follower="roller", rr=5, rotation="ccw").answers
    cw = _solve(R=30, OA=10, e=-15, follower="roller", rr=5, rotation="cw").answers
    assert ccw["offset_correct"] and cw["offset_correct"]
    assert ccw["alpha_max_rise"] == pytest.approx(cw["alpha_max_rise"], abs=1e-12)


def test_answers_alone_do_not_draw():
    sol = _solve(R=80, OA=50, follower="roller", rr=20, e=25, A_angle=0, omega=10)
    sol.answers
    assert not sol.scene.is_evaluated("mark_alpha") and not sol.scene.is_evaluated("dim_s")


@pytest.mark.parametrize("given, words", [
    (dict(R=30, OA=30), ["OA = 30 ≥ R = 30"]),
    (dict(R=30, OA=10, e=20), ["|e| = 20 ≥ r0", "= 20"]),
    (dict(R=30, OA=10, follower="roller"), ["rr > 0"]),
    (dict(R=30, OA=10, rr=5), ["rr = 5 given for a knife"]),
    (dict(R=30, OA=10, delta=10, A_angle=0), ["at most one state", "delta, A_angle"]),
    (dict(R=40, OA=20, follower="roller", rr=10, a=90), ["both a and L"]),
    (dict(R=40, OA=20, follower="roller", rr=10, a=60, L=70), ["a = 60", "Rp + OA = 70"]),
    (dict(R=40, OA=20, follower="roller", rr=10, a=90, L=200), ["L = 200"]),
    (dict(R=40, OA=20, follower="flat", a=90, L=70), ["flat-faced"]),
])
def test_refusals_name_the_numbers(given, words):
    with pytest.raises(NotAMechanism) as exc:
        _solve(**given).answers
    msg = str(exc.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg


def test_bad_choice_and_zero_eccentricity_are_problem_errors():
    with pytest.raises(ProblemError):
        _solve(R=30, OA=10, follower="mushroom")
    with pytest.raises(ProblemError, match="OA"):
        _solve(R=30, OA=0.0)
