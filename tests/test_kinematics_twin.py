"""The closed-form one-position kinematics (geomcon.analytic.kinematics) against an independent route: positions
written here separately (real trigonometry, the law of cosines), differentiated in time by five-point central
differences along the crank's motion φ(t) = φ0 + ωt + ½εt².

Velocities are compared with the differences of the separately written positions (step 5e-4 rad of crank angle:
agreement seen ≤ 1.5e-10 of the motion's scale, asserted at 1e-9). Accelerations are compared with the
differences of those velocities, once they have passed (a second difference of positions would only reach ~1e-7:
ε/h² rounding), agreement seen ≤ 1e-9, asserted at 1e-8.
"""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic.kinematics import crank_slider, four_bar, four_bar_instant_centres, guide_bar
from geomcon.errors import NotAMechanism


RATE = [1.0]
"""The crank's angular rate scale of the case under test: steps are small in crank angle, not in time."""


def d1(f, h=5e-4):
    h /= RATE[0]
    return (f(-2 * h) - 8 * f(-h) + 8 * f(h) - f(2 * h)) / (12 * h)


def unwrap(a, ref):
    """``a`` (rad) shifted by whole turns to lie within π of ``ref``."""
    return a + 2 * math.pi * round((ref - a) / (2 * math.pi))


def fourbar_pose(AB, BC, CD, AD, phi, sign):
    """(θ2, θ3, Cx, Cy) by the law of cosines in triangle BCD (radians)."""
    bx, by = AB * math.cos(phi), AB * math.sin(phi)
    d = math.hypot(AD - bx, AD * 0 - by)
    base = math.atan2(-by, AD - bx)
    beta = math.acos(max(-1.0, min(1.0, (BC * BC + d * d - CD * CD) / (2 * BC * d))))
    t2 = base + sign * beta
    cx, cy = bx + BC * math.cos(t2), by + BC * math.sin(t2)
    return t2, math.atan2(cy, cx - AD), cx, cy


def motion(phi0, omega, epsilon):
    RATE[0] = max(abs(omega), math.sqrt(abs(epsilon)), 1e-3)
    return lambda t: phi0 + omega * t + 0.5 * epsilon * t * t


def random_fourbar(rng):
    while True:
        AB, BC, CD, AD = (rng.uniform(10, 200) for _ in range(4))
        phi = rng.uniform(0, 360)
        bx, by = AB * math.cos(math.radians(phi)), AB * math.sin(math.radians(phi))
        d = math.hypot(AD - bx, by)
        if abs(BC - CD) + 0.05 * d < d < BC + CD - 0.05 * d:      # assembled, away from a dead point
            return AB, BC, CD, AD, phi


@pytest.mark.parametrize("seed", range(40))
@pytest.mark.parametrize("branch", ["above", "below"])
def test_four_bar_against_differences(seed, branch):
    rng = random.Random(seed)
    AB, BC, CD, AD, phi = random_fourbar(rng)
    omega, epsilon = rng.uniform(-20, 20), rng.uniform(-50, 50)
    BE, ang = rng.uniform(10, 100), rng.uniform(-180, 180)
    r = four_bar(AB, BC, CD, AD, phi, omega, epsilon, branch=branch, BE=BE, angle_CBE=ang)
    sign = 1.0 if branch == "above" else -1.0
    ph = motion(math.radians(phi), omega, epsilon)
    t2_0, t3_0, cx0, cy0 = fourbar_pose(AB, BC, CD, AD, ph(0.0), sign)
    assert math.isclose(math.radians(r["theta2"]), unwrap(t2_0, math.radians(r["theta2"])), abs_tol=1e-12)
    assert math.isclose(r["Cx"], cx0, abs_tol=1e-9 * AD) and math.isclose(r["Cy"], cy0, abs_tol=1e-9 * AD)
    t2 = lambda t: unwrap(fourbar_pose(AB, BC, CD, AD, ph(t), sign)[0], t2_0)
    t3 = lambda t: unwrap(fourbar_pose(AB, BC, CD, AD, ph(t), sign)[1], t3_0)
    wscale = abs(omega) * (1 + AB / min(BC, CD)) + 1e-300
    assert abs(r["omega2"] - d1(t2)) <= 1e-9 * wscale
    assert abs(r["omega3"] - d1(t3)) <= 1e-9 * wscale
    at = lambda t: four_bar(AB, BC, CD, AD, math.degrees(ph(t)), omega + epsilon * t, epsilon, branch=branch,
                            BE=BE, angle_CBE=ang)
    escale = (omega * omega + abs(epsilon)) * (1 + AB / min(BC, CD)) ** 2
    assert abs(r["epsilon2"] - d1(lambda t: at(t)["omega2"])) <= 1e-8 * escale
    assert abs(r["epsilon3"] - d1(lambda t: at(t)["omega3"])) <= 1e-8 * escale

    def E(t):
        a2 = t2(t) + math.radians(ang)
        p = ph(t)
        return AB * math.cos(p) + BE * math.cos(a2), AB * math.sin(p) + BE * math.sin(a2)

    vx, vy = d1(lambda t: E(t)[0]), d1(lambda t: E(t)[1])
    vs = wscale * (AB + BE + BC)
    assert abs(r["vEx"] - vx) <= 1e-9 * vs and abs(r["vEy"] - vy) <= 1e-9 * vs
    assert math.isclose(r["vE"], math.hypot(vx, vy), rel_tol=0, abs_tol=1e-9 * vs)
    as_ = escale * (AB + BE + BC)
    assert abs(r["aEx"] - d1(lambda t: at(t)["vEx"])) <= 1e-8 * as_
    assert abs(r["aEy"] - d1(lambda t: at(t)["vEy"])) <= 1e-8 * as_
    # C moves on its circle about D: vC = |ω3|·CD
    assert math.isclose(r["vC"], abs(r["omega3"]) * CD, rel_tol=1e-12)
    assert math.isclose(r["aC"], CD * math.hypot(r["epsilon3"], r["omega3"] ** 2), rel_tol=1e-12)


@pytest.mark.parametrize("seed", range(30))
def test_instant_centres_give_the_velocity_ratios(seed):
    rng = random.Random(100 + seed)
    AB, BC, CD, AD, phi = random_fourbar(rng)
    for branch in ("above", "below"):
        r = four_bar(AB, BC, CD, AD, phi, 1.0, branch=branch)
        ic = four_bar_instant_centres(AB, BC, CD, AD, phi, branch=branch)
        assert math.isclose(ic["w3_w1"], r["omega3"], rel_tol=1e-9, abs_tol=1e-9)
        assert math.isclose(ic["w2_w1"], r["omega2"], rel_tol=1e-9, abs_tol=1e-9)
        # Kennedy: P13 lies on BC and on AD, P24 on AB and on CD
        P13, P24, B, C = ic["P13"], ic["P24"], ic["P12"], ic["P23"]
        if P13 is not None:
            assert abs(P13.imag) <= 1e-9 * max(abs(P13), AD)
            assert abs(((P13 - B).conjugate() * (C - B)).imag) <= 1e-9 * abs(P13 - B) * abs(C - B) * 10


@pytest.mark.parametrize("seed", range(40))
def test_crank_slider_against_differences(seed):
    rng = random.Random(200 + seed)
    while True:
        AB, BC, e = rng.uniform(10, 100), rng.uniform(50, 300), rng.uniform(-40, 40)
        phi = rng.uniform(0, 360)
        h = AB * math.sin(math.radians(phi)) + e
        if abs(h) < 0.9 * BC:
            break
    omega, epsilon = rng.uniform(-20, 20), rng.uniform(-50, 50)
    r = crank_slider(AB, BC, e, phi, omega, epsilon)
    ph = motion(math.radians(phi), omega, epsilon)

    def x(t):
        p = ph(t)
        hh = AB * math.sin(p) + e
        return AB * math.cos(p) + math.sqrt(BC * BC - hh * hh)

    def th(t):
        p = ph(t)
        return math.asin(-(AB * math.sin(p) + e) / BC)

    assert math.isclose(r["xC"], x(0.0), rel_tol=1e-12)
    vs = abs(omega) * AB * (1 + AB / BC) + 1e-300
    assert abs(r["vC"] - d1(x)) <= 1e-9 * vs
    assert abs(r["omega2"] - d1(th)) <= 1e-9 * vs / BC
    at = lambda t: crank_slider(AB, BC, e, math.degrees(ph(t)), omega + epsilon * t, epsilon)
    as_ = (omega * omega + abs(epsilon)) * AB * (1 + AB / BC) ** 2
    assert abs(r["aC"] - d1(lambda t: at(t)["vC"])) <= 1e-8 * as_
    assert abs(r["epsilon2"] - d1(lambda t: at(t)["omega2"])) <= 1e-8 * as_ / BC


@pytest.mark.parametrize("seed", range(40))
def test_guide_bar_against_differences(seed):
    rng = random.Random(300 + seed)
    AB, AC = rng.uniform(10, 200), rng.uniform(10, 200)
    phi = rng.uniform(0, 360)
    if abs(AB - AC) < 5:
        AC += 10
    omega, epsilon = rng.uniform(-20, 20), rng.uniform(-50, 50)
    r = guide_bar(AB, AC, phi, omega, epsilon)
    ph = motion(math.radians(phi), omega, epsilon)

    def pose(t):
        p = ph(t)
        bx, by = AB * math.cos(p), AB * math.sin(p) + AC
        return math.atan2(by, bx), math.hypot(bx, by)

    a0 = pose(0.0)[0]
    ang = lambda t: unwrap(pose(t)[0], a0)
    s = lambda t: pose(t)[1]
    scale = abs(omega) * AB * (1 + AB / abs(AB - AC)) + 1e-300
    assert abs(r["v_slip"] - d1(s)) <= 1e-9 * scale
    assert abs(r["omega3"] - d1(ang)) <= 1e-9 * scale / abs(AB - AC)
    at = lambda t: guide_bar(AB, AC, math.degrees(ph(t)), omega + epsilon * t, epsilon)
    acc = (omega * omega + abs(epsilon)) * AB * (1 + AB / abs(AB - AC)) ** 2
    assert abs(r["a_slip"] - d1(lambda t: at(t)["v_slip"])) <= 1e-8 * acc
    assert abs(r["epsilon3"] - d1(lambda t: at(t)["omega3"])) <= 1e-8 * acc / abs(AB - AC)
    assert math.isclose(r["a_coriolis"], 2 * r["omega3"] * r["v_slip"], rel_tol=1e-12, abs_tol=1e-300)


def test_refusals_name_the_numbers():
    with pytest.raises(NotAMechanism, match="does not close"):
        four_bar(10, 20, 30, 100, 0, 1)
    with pytest.raises(NotAMechanism, match="more than BC"):
        crank_slider(100, 50, 0, 90, 1)
