"""The class-II chain (geomcon.kinematics) against independent routes: the closed-form one-position twins of
geomcon.analytic.kinematics (four-bar, crank-slider, guide-bar) and a 60-digit Newton-and-differences solution of
every loop (tests/kinematics_twin.py) for the general dyads, on random instances in both branches and all
quadrants, to 1e-9 of scale."""
from __future__ import annotations

import cmath
import math
import random

import numpy as np
import pytest

from geomcon.analytic import kinematics as twin
from geomcon.errors import NotAMechanism, ProblemError
from geomcon.kinematics.chain import Mechanism, check_chain, solve_chain
from geomcon.kinematics.cycle import DeadPoint, assembly
from geomcon.kinematics.dyads import PRP, RPR, RRP, RRR, Crank, Guide, OnLink

import kinematics_twin as mp_twin

TOL = 1e-9


def close(x: float, ref: float, scale: float, tol: float = TOL) -> bool:
    return abs(x - ref) <= tol * max(abs(ref), scale)


def four_bar(AB, BC, CD, AD, omega, epsilon, branch, rot=0.0, shift=0j):
    """A four-bar with A at ``shift``, D at AD from it in the direction ``rot`` (rad)."""
    D = shift + AD * cmath.exp(1j * rot)
    return Mechanism({"A": shift, "D": D}, Crank("AB", "A", "B", AB, omega, epsilon),
                     (RRR("C", "B", "D", BC, CD, branch, "BC", "DC"), OnLink("E", "BC", "B", 0.7 * BC, 0.4)))


def test_four_bar_random_against_closed_form_twin():
    rng = random.Random(15)
    n = 0
    while n < 60:
        AB, BC, CD, AD = (rng.uniform(10, 200) for _ in range(4))
        phi = rng.uniform(0, 360)
        omega = rng.choice((-1, 1)) * rng.uniform(0.5, 50)
        eps = rng.uniform(-100, 100)
        branch = rng.choice((1, -1))
        rot, shift = rng.uniform(-math.pi, math.pi), complex(rng.uniform(-300, 300), rng.uniform(-300, 300))
        try:
            ref = twin.four_bar(AB, BC, CD, AD, phi, omega, eps, "above" if branch == 1 else "below",
                                BE=0.7 * BC, angle_CBE=math.degrees(0.4))
        except NotAMechanism:
            continue
        m = four_bar(AB, BC, CD, AD, omega, eps, branch, rot, shift)
        st = solve_chain(m, np.radians([phi]) + rot)     # the crank angle measured from A→D
        if float(st.margins["C"][0]) < 1e-3:
            continue
        L = max(AB, BC, CD, AD)
        turn = cmath.exp(-1j * rot)
        C = (st.points["C"].p[0] - shift) * turn
        assert close(C.real, ref["Cx"], L) and close(C.imag, ref["Cy"], L)
        for k, name in (("2", "BC"), ("3", "DC")):
            lk = st.links[name]
            assert close(lk.omega[0], ref["omega" + k], abs(omega)), (name, lk.omega[0], ref["omega" + k])
            assert close(lk.epsilon[0], ref["epsilon" + k], omega ** 2 + abs(eps))
            th = math.degrees(lk.theta[0] - rot)
            assert abs((th - ref["theta" + k] + 180) % 360 - 180) < 1e-9 * 360
        for P in ("C", "E"):
            v, a = st.points[P].v[0] * turn, st.points[P].a[0] * turn
            assert close(v.real, ref[f"v{P}x"], L * abs(omega)) and close(v.imag, ref[f"v{P}y"], L * abs(omega))
            acc = L * (omega ** 2 + abs(eps))
            assert close(a.real, ref[f"a{P}x"], acc) and close(a.imag, ref[f"a{P}y"], acc)
        n += 1


def test_crank_slider_and_guide_bar_random_against_closed_form_twins():
    rng = random.Random(16)
    n = 0
    while n < 40:
        AB, BC, e = rng.uniform(10, 100), rng.uniform(10, 300), rng.uniform(-80, 80)
        phi, omega, eps = rng.uniform(0, 360), rng.choice((-1, 1)) * rng.uniform(0.5, 50), rng.uniform(-100, 100)
        try:
            ref = twin.crank_slider(AB, BC, e, phi, omega, eps)
        except NotAMechanism:
            continue
        m = Mechanism({"A": 0j, "G": complex(0, -e)}, Crank("AB", "A", "B", AB, omega, eps),
                      (RRP("C", "B", BC, Guide("G", 0.0), 1, "BC"),))
        st = solve_chain(m, np.radians([phi]))
        if float(st.margins["C"][0]) < 1e-3:
            continue
        L = max(AB, BC, abs(e))
        assert close(st.points["C"].p[0].real, ref["xC"], L)
        assert close(st.points["C"].v[0].real, ref["vC"], L * abs(omega))
        assert close(st.points["C"].a[0].real, ref["aC"], L * (omega ** 2 + abs(eps)))
        assert close(st.slips["C"].v[0], ref["vC"], L * abs(omega))
        assert close(st.links["BC"].omega[0], ref["omega2"], abs(omega))
        assert close(st.links["BC"].epsilon[0], ref["epsilon2"], omega ** 2 + abs(eps))
        n += 1
    n = 0
    while n < 40:
        AB, AC = rng.uniform(10, 100), rng.uniform(10, 300)
        phi, omega, eps = rng.uniform(0, 360), rng.choice((-1, 1)) * rng.uniform(0.5, 50), rng.uniform(-100, 100)
        ref = twin.guide_bar(AB, AC, phi, omega, eps)
        m = Mechanism({"A": 0j, "C": complex(0, -AC)}, Crank("AB", "A", "B", AB, omega, eps),
                      (RPR("guide", "B", "C", "CB", 1),))
        st = solve_chain(m, np.radians([phi]))
        if float(st.margins["guide"][0]) < 1e-3 or ref["CB"] < 0.05 * AC:
            continue
        lk, sl = st.links["CB"], st.slips["guide"]
        assert abs((math.degrees(lk.theta[0]) - ref["theta3"] + 180) % 360 - 180) < 1e-9 * 360
        assert close(lk.omega[0], ref["omega3"], abs(omega))
        assert close(lk.epsilon[0], ref["epsilon3"], omega ** 2 + abs(eps))
        assert close(sl.s[0], ref["CB"], AC) and close(sl.v[0], ref["v_slip"], AB * abs(omega))
        assert close(sl.a[0], ref["a_slip"], AB * (omega ** 2 + abs(eps)))
        n += 1


def _random_general(rng: random.Random) -> Mechanism:
    """A six- or seven-link chain using every dyad: crank, RRR, RPR with an offset (guide carried about a moving
    pivot), RRP on a guide carried by a link, PRP between a fixed and a carried guide."""
    def pt():
        return complex(rng.uniform(-150, 150), rng.uniform(-150, 150))
    br = lambda: rng.choice((1, -1))       # noqa: E731
    A, D, G = pt(), pt(), pt()
    AB = rng.uniform(10, 40)
    dist = abs(D - A)
    BC = rng.uniform(dist * 0.6 + AB, dist * 0.6 + AB + 100)
    CD = rng.uniform(abs(BC - dist) + AB + 5, BC + dist - AB - 5) if BC + dist - AB - 5 > abs(BC - dist) + AB + 5 \
        else BC
    return Mechanism(
        {"A": A, "D": D, "G": G},
        Crank("AB", "A", "B", AB, rng.choice((-1, 1)) * rng.uniform(1, 30), rng.uniform(-50, 50)),
        (RRR("C", "B", "D", BC, CD, br(), "BC", "DC"),
         OnLink("E", "DC", "D", rng.uniform(20, 200), rng.uniform(-3, 3)),
         RPR("guideE", "E", "B", "BE", br(), rng.uniform(-5, 5)),
         OnLink("K", "BE", "B", rng.uniform(10, 100), rng.uniform(-3, 3)),
         RRP("F", "K", rng.uniform(150, 400), Guide("E", rng.uniform(-3, 3), "DC"), br(), "KF"),
         PRP("P", Guide("G", rng.uniform(-3, 3)), Guide("F", rng.uniform(0.5, 2.5), "KF"), "s1", "s2")))


def test_general_chains_random_against_60_digit_newton_twin():
    rng = random.Random(17)
    n = tried = 0
    while n < 25:
        tried += 1
        assert tried < 5000
        m = _random_general(rng)
        check_chain(m)
        phi = rng.uniform(0, 360)
        with np.errstate(all="ignore"):
            st = solve_chain(m, np.radians([phi]))
        if min(float(v[0]) for v in st.margins.values()) < 0.02:
            continue
        rp, rl, rs = mp_twin.motion(m, phi, mp_twin.guess_of(st))
        L, w, e = m.scale(), abs(m.crank.omega), abs(m.crank.epsilon)
        for name, pm in st.points.items():
            for got, want, sc in ((pm.p[0], rp[name][0], L), (pm.v[0], rp[name][1], L * w),
                                  (pm.a[0], rp[name][2], L * (w * w + e))):
                want = complex(want)
                assert abs(got - want) <= TOL * max(abs(want), sc), (name, got, want)
        for name, lk in st.links.items():
            th, dw, de = (float(x) for x in rl[name])
            assert abs((lk.theta[0] - th + math.pi) % (2 * math.pi) - math.pi) < TOL
            assert close(lk.omega[0], dw, w) and close(lk.epsilon[0], de, w * w + e), (name, lk.omega[0], dw)
        for name, sl in st.slips.items():
            s, dv, da = (float(x) for x in rs[name])
            assert close(sl.s[0], s, L) and close(sl.v[0], dv, L * w) and close(sl.a[0], da, L * (w * w + e))
        n += 1


def test_branch_is_the_named_side():
    rng = random.Random(18)
    for _ in range(50):
        m = _random_general(rng)
        with np.errstate(all="ignore"):
            st = solve_chain(m, np.radians(np.linspace(0, 360, 37)))
        rrr = m.chain[0]
        B, D, C = (st.points[k].p for k in ("B", "D", "C"))
        side = np.sign(((D - B).real * (C - B).imag - (D - B).imag * (C - B).real))
        ok = st.margins["C"] > 1e-6
        assert np.all(side[ok] == rrr.branch)


def test_dead_points_of_a_double_rocker_are_the_analytic_limit_angles():
    # AB + AD > BC + CD: the crank stops where B, C, D are collinear (BD = BC + CD)
    AB, BC, CD, AD = 60.0, 50.0, 45.0, 70.0
    m = four_bar(AB, BC, CD, AD, 10.0, 0.0, 1)
    with pytest.raises(DeadPoint) as err:
        assembly(m, 0.0, 2 * math.pi)
    phi = math.degrees(math.acos((AB ** 2 + AD ** 2 - (BC + CD) ** 2) / (2 * AB * AD)))
    msg = str(err.value)
    assert "dyad 'C'" in msg and f"{phi:.6f}°" in msg and f"{360 - phi:.6f}°" in msg


def test_change_point_of_a_parallelogram_is_reported_and_the_branch_kept():
    m = four_bar(30.0, 80.0, 30.0, 80.0, 5.0, 0.0, 1)
    changes = assembly(m, 0.0, 2 * math.pi)
    angles = sorted(round(c.phi_deg, 5) % 360 for c in changes)
    assert angles == [0.0, 180.0]


def test_chain_refuses_names_used_before_they_are_placed():
    m = Mechanism({"A": 0j}, Crank("AB", "A", "B", 1.0, 1.0), (RRR("C", "B", "D", 1.0, 1.0, 1, "BC", "DC"),))
    with pytest.raises(ProblemError, match="point 'D' is not placed before it"):
        check_chain(m)


def test_positions_only_are_the_same_positions():
    rng = random.Random(19)
    m = _random_general(rng)
    phi = np.radians(np.linspace(0, 360, 73))
    full, pos = solve_chain(m, phi), solve_chain(m, phi, derivatives=False)
    for k, pm in full.points.items():
        assert np.array_equal(pm.p, pos.points[k].p, equal_nan=True)
        assert pos.points[k].v is None or k in m.fixed
    for k, lk in full.links.items():
        assert np.array_equal(lk.theta, pos.links[k].theta, equal_nan=True)


def test_rocker_extremes_are_where_crank_and_coupler_are_collinear():
    from geomcon.kinematics.cycle import stationary_points
    rng = random.Random(20)
    n = 0
    while n < 12:
        AB, BC, CD, AD = rng.uniform(5, 40), rng.uniform(60, 150), rng.uniform(40, 150), rng.uniform(60, 150)
        if not (AB + max(BC, CD, AD) < min(BC, CD, AD) + sorted((BC, CD, AD))[1]):    # Grashof, AB the crank
            continue
        m = four_bar(AB, BC, CD, AD, rng.choice((-1, 1)) * 7.0, 0.0, rng.choice((1, -1)),
                     rng.uniform(-3, 3), complex(rng.uniform(-50, 50), rng.uniform(-50, 50)))
        try:
            assembly(m, 0.0, 2 * math.pi)
        except DeadPoint:
            continue
        pts = [p for p in stationary_points(m, "DC.angle") if p.kind in ("max", "min")]
        assert len(pts) == 2
        st = solve_chain(m, np.radians([p.phi_deg for p in pts]))
        AC = np.abs(st.points["C"].p - m.fixed["A"])
        assert sorted(AC.tolist()) == pytest.approx([BC - AB, BC + AB], rel=1e-9)
        n += 1
