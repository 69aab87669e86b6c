"""The eccentric cam's arm replayed on floats and arrays (geomcon/cam/arm_replay.py) against the geometry it
replays (rotate, circle_circle, the side rule, angle_at): the same bits at random cam angles and shapes, the
same values or errors where the geometry takes another path (tangency, circles apart, ties), and the same
largest pressure angles as the search on the geometry (np.vectorize and Brent on it, as before); the twin's
samples on arrays (geomcon/cam/eccentric.py) against its floats likewise."""
from __future__ import annotations

import math

import numpy as np
import pytest

from geomcon.cam.arm_replay import ArmReplay
from geomcon.cam.profile import maximise
from geomcon.errors import GeomconError
from geomcon.geometry import Point
from geomcon.recipes.cam_eccentric import osc_arm


def _arm(rng: np.random.Generator, *, near: bool = False) -> ArmReplay:
    """A random arm: pivot Q0 on a circle of radius a about O, the disc's centre A, arm L, pitch radius Rp;
    ``near``: L chosen so that the arm's arc nearly touches the pitch circle somewhere over the turn."""
    a = float(rng.uniform(60, 250))
    t = float(rng.uniform(0, 2 * math.pi))
    Q0 = Point(a * math.cos(t), a * math.sin(t))
    E = float(rng.uniform(5, 0.4 * a))
    u = float(rng.uniform(0, 2 * math.pi))
    A = Point(E * math.cos(u), E * math.sin(u))
    Rp = float(rng.uniform(0.2, 0.8)) * a
    if near:
        L = a + E - Rp + float(rng.choice([-1.0, 1.0])) * 10.0 ** float(rng.uniform(-14, -6)) * a
    else:
        L = float(rng.uniform(a - Rp + E + 1.0, a + Rp - E - 1.0)) if a - Rp + E + 1.0 < a + Rp - E - 1.0 else a
    return osc_arm(Q0, A, Point(0.0, 0.0), L, Rp, bool(rng.integers(0, 2)), float(rng.choice([-1.0, 1.0])))


def _outcome(fn, d):
    try:
        return ("value", fn(d))
    except GeomconError as exc:
        return ("error", type(exc).__name__, str(exc))


@pytest.mark.parametrize("seed", range(30))
def test_floats_and_arrays_give_the_geometrys_bits(seed):
    rng = np.random.default_rng(seed)
    arm = _arm(rng, near=seed % 3 == 0)
    d = np.concatenate([rng.uniform(-0.5, 2 * math.pi + 0.5, 400), [0.0, math.pi, 2 * math.pi]])
    if seed % 3 == 0:                   # around the angle where the pivot is farthest from A (a tangency)
        far = math.atan2(-arm.ay, -arm.ax) - math.atan2(arm.q0y, arm.q0x)
        star = (-far / arm.sense) % (2 * math.pi)
        d = np.concatenate([d, star + np.concatenate([-np.logspace(-12, -2, 30), [0.0], np.logspace(-12, -2, 30)])])
    want = [_outcome(arm.exact, x) for x in d.tolist()]
    assert [_outcome(arm.alpha1, x) for x in d.tolist()] == want
    if all(w[0] == "value" for w in want):
        assert arm.alpha(d).tolist() == [w[1] for w in want]
    else:                               # the first error the geometry meets, as np.vectorize would raise it
        first = next(w for w in want if w[0] == "error")
        with pytest.raises(GeomconError) as info:
            arm.alpha(d)
        assert (type(info.value).__name__, str(info.value)) == first[1:]
        ok = np.array([w[0] == "value" for w in want])
        assert arm.alpha(d[ok]).tolist() == [w[1] for w, k in zip(want, ok) if k]


def test_the_replay_steps_aside_where_the_geometry_does():
    """Tangent and nearly tangent arcs: the replay hands those angles to the geometry (and agrees)."""
    Q0, A = Point(0.0, 100.0), Point(0.0, -20.0)
    calls = []
    arm = osc_arm(Q0, A, Point(0.0, 0.0), 70.0, 50.0, True, 1.0)

    def counted(d):
        calls.append(d)
        return arm.exact(d)

    tangent = ArmReplay(Q0.x, Q0.y, 0.0, 0.0, A.x, A.y, 70.0, 50.0, True, 1.0, counted)
    assert tangent.alpha1(0.0) == arm.exact(0.0) and calls == [0.0]     # |QA| = 120 = L + Rp: tangent at δ = 0
    d = np.array([0.0, 0.5, 1.0])
    assert tangent.alpha(d).tolist() == [arm.exact(x) for x in d.tolist()] and calls[1:] == [0.0]


@pytest.mark.parametrize("seed", range(12))
def test_largest_pressure_angle_as_searched_on_the_geometry(seed):
    rng = np.random.default_rng(100 + seed)
    arm = _arm(rng)
    d = np.linspace(0.0, 2 * math.pi, 50)
    if any(_outcome(arm.exact, x)[0] == "error" for x in d.tolist()):
        pytest.skip("an arm that does not work over the turn")
    for lo, hi in ((0.0, float(rng.uniform(1.0, 4.0))), (float(rng.uniform(1.0, 4.0)), 2 * math.pi)):
        old = maximise(np.vectorize(arm.exact), [(lo, hi)], dense=720, g1=arm.exact)
        assert maximise(arm.alpha, [(lo, hi)], dense=720, g1=arm.alpha1) == old


@pytest.mark.parametrize("seed", range(24))
def test_twins_samples_on_arrays_equal_its_floats(seed):
    """The eccentric twin's α samples on arrays (Oscillating._alphas) against its scalar form, and its largest α
    against the search on np.vectorize (as before): the same bits."""
    from geomcon.cam.eccentric import Oscillating
    from geomcon.errors import NotAMechanism
    rng = np.random.default_rng(500 + seed)
    R = float(rng.uniform(20, 80))
    kw = dict(R=R, OA=R * float(rng.uniform(0.1, 0.7)), a=R * float(rng.uniform(1.8, 3.5)), L=R * float(rng.uniform(1.2, 2.8)),
              rr=R * float(rng.uniform(0.0, 0.4)), rotation=str(rng.choice(["ccw", "cw"])), arm=str(rng.choice(["left", "right"])))
    if seed % 4 == 0:
        kw = {k: (round(v) if isinstance(v, float) else v) for k, v in kw.items()}      # integer givens
    try:
        cam = Oscillating(**kw)
    except NotAMechanism:
        pytest.skip("not an arm that works")
    f1 = lambda d: cam.alpha(cam.phi_of(math.degrees(d)))                           # noqa: E731
    d = np.concatenate([rng.uniform(-1.0, 7.0, 500), [0.0, math.radians(cam.rise_angle), 2 * math.pi]])
    assert cam._alphas(d, f1).tolist() == [f1(x) for x in d.tolist()]
    for part, (d0, d1) in (("rise", (0.0, cam.rise_angle)), ("return", (cam.rise_angle, 360.0))):
        old = maximise(np.vectorize(f1), [(math.radians(d0), math.radians(d1))], dense=720, g1=f1).value
        assert cam.alpha_max(part) == old
