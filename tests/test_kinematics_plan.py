"""The fast path (geomcon.kinematics.plan: the chain compiled into real-arithmetic kernels run in chunks) against
the reference path (geomcon.kinematics.chain.solve_chain, complex arrays): the same description gives the same
motion, positions to 1e-15 of the linkage's size on random four-bars, crank-sliders, guide-bars (offset) and
general seven-link chains in both branches of every dyad; velocities and accelerations as exact as the
reference's, both measured against the 60-digit Newton-and-differences twin (tests/kinematics_twin.py)."""
from __future__ import annotations

import cmath
import math
import random

import numpy as np
import pytest

from geomcon.errors import ProblemError
from geomcon.kinematics.chain import Mechanism, solve_chain
from geomcon.kinematics.dyads import PRP, RPR, RRP, RRR, Crank, Guide, OnLink
from geomcon.kinematics.plan import compile_chain, solve_fast

import kinematics_twin as mp_twin
from test_kinematics_chain import _random_general

PHI = np.radians(np.linspace(0.0, 360.0, 721))
WELL = 0.25
"""Positions are compared where every dyad is well conditioned: its assembly margin at least this (a dyad's
joint moves by √(rounding / margin) of its size under a rounding of its inputs, so near a dead point both
paths are only as exact as that) and an RRR's base p1p2 at least this fraction of its longer link (its joint
turns with the direction of p1p2, which a rounding of p1 or p2 turns by rounding / |p1p2|)."""


def _four_bar(rng: random.Random, branch: int) -> Mechanism:
    AB, BC, CD, AD = (rng.uniform(10, 200) for _ in range(4))
    A = complex(rng.uniform(-300, 300), rng.uniform(-300, 300))
    D = A + AD * cmath.exp(1j * rng.uniform(-math.pi, math.pi))
    return Mechanism({"A": A, "D": D}, Crank("AB", "A", "B", AB, rng.uniform(-50, 50), rng.uniform(-100, 100)),
                     (RRR("C", "B", "D", BC, CD, branch, "BC", "DC"),
                      OnLink("E", "BC", "B", BC * rng.uniform(0.2, 1.5), rng.uniform(-3, 3))))


def _crank_slider(rng: random.Random, branch: int) -> Mechanism:
    G = complex(rng.uniform(-100, 100), rng.uniform(-100, 100))
    return Mechanism({"A": 0j, "G": G}, Crank("AB", "A", "B", rng.uniform(10, 100), rng.uniform(-50, 50),
                                               rng.uniform(-100, 100)),
                     (RRP("C", "B", rng.uniform(10, 300), Guide("G", rng.uniform(-3, 3)), branch, "BC"),))


def _guide_bar(rng: random.Random, branch: int) -> Mechanism:
    C = complex(rng.uniform(-200, 200), rng.uniform(-200, 200))
    return Mechanism({"A": 0j, "C": C}, Crank("AB", "A", "B", rng.uniform(10, 100), rng.uniform(-50, 50),
                                               rng.uniform(-100, 100)),
                     (RPR("guide", "B", "C", "CB", branch, rng.uniform(-20, 20)),
                      OnLink("F", "CB", "C", rng.uniform(50, 300), rng.uniform(-1, 1))))


def _both(m: Mechanism, phi: np.ndarray = PHI, **kw):
    with np.errstate(all="ignore"):
        return solve_chain(m, phi), compile_chain(m, **kw).solve(phi)


def _assert_positions_agree(m: Mechanism, ref, fast, tol: float = 1e-15) -> int:
    """Positions, link angles and slips of the two paths to ``tol`` of the linkage's size where every margin is
    at least WELL; returns how many crank angles were compared."""
    ok = np.ones(PHI.shape, dtype=bool)
    for v in ref.margins.values():
        ok &= v >= WELL
    for el in m.chain:
        if isinstance(el, RRR):
            ok &= np.abs(ref.points[el.p2].p - ref.points[el.p1].p) >= WELL * max(el.l1, el.l2)
    L = m.scale()
    for k, pm in ref.points.items():
        err = np.abs(pm.p - fast.points[k].p)[ok] / np.maximum(np.abs(pm.p[ok]), L)
        assert err.size == 0 or err.max() <= tol, (k, err.max())
    for k, lk in ref.links.items():
        d = np.abs((lk.theta - fast.links[k].theta + math.pi) % (2 * math.pi) - math.pi)[ok]
        assert d.size == 0 or d.max() <= 2 * tol * math.pi, (k, d.max())
    for k, sl in ref.slips.items():
        err = np.abs(sl.s - fast.slips[k].s)[ok] / np.maximum(np.abs(sl.s[ok]), L)
        assert err.size == 0 or err.max() <= tol, (k, err.max())
    for k, mg in ref.margins.items():
        assert np.abs(mg - fast.margins[k])[ok].max(initial=0.0) <= 1e-13, k
    return int(ok.sum())


@pytest.mark.parametrize("make", [_four_bar, _crank_slider, _guide_bar])
@pytest.mark.parametrize("branch", [1, -1])
def test_fast_positions_equal_reference_on_random_linkages(make, branch):
    rng = random.Random(f"{make.__name__}{branch}")
    compared = 0
    for _ in range(40):
        m = make(rng, branch)
        ref, fast = _both(m)
        assert set(ref.points) == set(fast.points) and set(ref.links) == set(fast.links)
        assert set(ref.slips) == set(fast.slips) and set(ref.margins) == set(fast.margins)
        compared += _assert_positions_agree(m, ref, fast)
    assert compared > 40 * 721 // 4               # most instances assemble over much of the turn


def test_fast_positions_equal_reference_on_random_general_chains():
    """RRR, RPR with offset about a moving pivot, RRP on a carried guide, PRP between a fixed and a carried
    guide: every branch of every dyad drawn at random (100 chains). These chains carry points up to 200 mm
    along links as short as 20 mm and hang each dyad on such points, so a rounding of a link's direction
    (the same in both paths, in a different place) moves the last joints by up to ten times more: 1e-14."""
    rng = random.Random(150)
    compared, branches = 0, set()
    for _ in range(100):
        m = _random_general(rng)
        branches |= {(type(el).__name__, el.branch) for el in m.chain if hasattr(el, "branch")}
        ref, fast = _both(m)
        compared += _assert_positions_agree(m, ref, fast, 1e-14)
    assert compared > 1000 and len(branches) == 6


def test_fast_motion_is_as_exact_as_the_reference_against_the_60_digit_twin():
    """Positions, velocities and accelerations of every point, link and slip at random crank angles: both paths
    within 2e-14 of the 60-digit twin (relative to the largest of that quantity over the points), the fast one
    no further than the reference. Velocities and accelerations divide by the sine of the angle between two
    links and take short links as differences of long position vectors, so the two paths, rounding in
    different places, differ by more than their positions do (up to 1e-14 of the largest velocity over a
    cycle); which of them is nearer the truth varies (measured: fast 8.4e-15, reference 1.03e-14)."""
    rng = random.Random(151)
    worst = {"fast": 0.0, "ref": 0.0}
    n = tried = 0
    while n < 30:
        tried += 1
        assert tried < 5000
        m = _random_general(rng) if n % 2 else _four_bar(rng, (1, -1)[n // 2 % 2])
        phi = rng.uniform(0, 360)
        ref, fast = _both(m, np.radians([phi]))
        if min(float(v[0]) for v in ref.margins.values()) < 0.02:
            continue
        rp, rl, rs = mp_twin.motion(m, phi, mp_twin.guess_of(ref))
        L, w, e = m.scale(), abs(m.crank.omega), abs(m.crank.epsilon)
        for j, q in enumerate("pva"):
            sc = max([abs(complex(rp[k][j])) for k in rp] + [L if j == 0 else 0.0])
            for tag, st in (("fast", fast), ("ref", ref)):
                err = max(abs(complex(getattr(pm, q)[0]) - complex(rp[k][j])) for k, pm in st.points.items())
                worst[tag] = max(worst[tag], err / sc)
        for j, q in enumerate(("omega", "epsilon")):
            sc = max(abs(float(rl[k][j + 1])) for k in rl) or 1.0
            for tag, st in (("fast", fast), ("ref", ref)):
                err = max(abs(float(getattr(lk, q)[0]) - float(rl[k][j + 1])) for k, lk in st.links.items())
                worst[tag] = max(worst[tag], err / sc)
        if rs:
            for j, q in enumerate("sva"):
                sc = max(abs(float(rs[k][j])) for k in rs) + (L if j == 0 else L * w if j == 1 else L * (w * w + e))
                for tag, st in (("fast", fast), ("ref", ref)):
                    err = max(abs(float(getattr(sl, q)[0]) - float(rs[k][j])) for k, sl in st.slips.items())
                    worst[tag] = max(worst[tag], err / sc)
        n += 1
    assert worst["fast"] <= 2e-14 and worst["ref"] <= 2e-14, worst
    assert worst["fast"] <= 1.5 * worst["ref"], worst


def test_chunks_positions_only_and_angles_change_no_bit():
    rng = random.Random(152)
    m = _random_general(rng)
    with np.errstate(all="ignore"):
        whole = compile_chain(m).solve(PHI)
        for chunk in (1, 7, 720, 722):
            part = compile_chain(m, chunk=chunk).solve(PHI)
            for k, pm in whole.points.items():
                for q in "pva":
                    assert np.array_equal(getattr(pm, q), getattr(part.points[k], q), equal_nan=True), (chunk, k)
            for k, lk in whole.links.items():
                for q in ("theta", "omega", "epsilon"):
                    assert np.array_equal(getattr(lk, q), getattr(part.links[k], q), equal_nan=True), (chunk, k)
        pos = compile_chain(m).solve(PHI, derivatives=False)
        bare = compile_chain(m).solve(PHI, angles=False)
    for k, pm in whole.points.items():
        assert np.array_equal(pm.p, pos.points[k].p, equal_nan=True)
        assert pos.points[k].v is None or k in m.fixed
        assert np.array_equal(pm.a, bare.points[k].a, equal_nan=True)
    for k, lk in whole.links.items():
        assert np.array_equal(lk.theta, pos.links[k].theta, equal_nan=True) and pos.links[k].omega is None
        assert bare.links[k].theta is None and np.array_equal(lk.epsilon, bare.links[k].epsilon, equal_nan=True)
    for k, sl in whole.slips.items():
        assert np.array_equal(sl.s, pos.slips[k].s, equal_nan=True) and pos.slips[k].v is None


def test_shapes_and_a_dyad_between_two_fixed_points():
    m = Mechanism({"A": 0j, "P": 10 + 0j, "Q": 10 + 20j}, Crank("AB", "A", "B", 5.0, 3.0, 1.0),
                  (RRR("C", "P", "Q", 15.0, 10.0, 1, "PC", "QC"), RRR("E", "B", "C", 20.0, 12.0, -1, "BE", "CE"),
                   PRP("S", Guide("A", 0.3), Guide("E", 1.2, "CE"), "s1", "s2")))
    phi = np.radians(np.linspace(0, 360, 12).reshape(3, 4))
    ref, fast = _both(m, phi)
    for k, pm in ref.points.items():
        for q in "pva":
            assert getattr(fast.points[k], q).shape == (3, 4)
            assert np.allclose(getattr(fast.points[k], q), getattr(pm, q), rtol=0, atol=1e-12), (k, q)
    one = solve_fast(m, np.radians(30.0))
    assert one.points["E"].p.shape == () and complex(one.points["E"].p) == pytest.approx(
        complex(solve_chain(m, np.radians(30.0)).points["E"].p), abs=1e-12)


def test_compile_refuses_what_the_chain_refuses():
    m = Mechanism({"A": 0j}, Crank("AB", "A", "B", 1.0, 1.0), (RRR("C", "B", "D", 1.0, 1.0, 1, "BC", "DC"),))
    with pytest.raises(ProblemError, match="point 'D' is not placed before it"):
        compile_chain(m)
    with pytest.raises(ValueError, match="chunk"):
        compile_chain(Mechanism({"A": 0j}, Crank("AB", "A", "B", 1.0, 1.0), ()), chunk=0)
