"""The flat faces' searches sharing their samples: the contact's extremes over the turn and a segment, ρmin of
the envelope and the places the searches value, against the same searches with nothing shared (every sample
and every candidate computed afresh by the array forms, as before the sharing): the same bits. The shortcuts
of the checks that refuse a cam (the laws' bound of the arm's speed, the first look for backward jumps on
floats) against the full searches."""
from __future__ import annotations

import math

import numpy as np
import pytest

from geomcon.cam.oscillating_flat import FlatArmCam
from geomcon.cam.profile import (Extremum, LineFamily, TWO_PI, backward_jumps, envelope, envelope_rho_min, envelope_terms,
                                 maximise, sample_grid, sample_grids)
from random_programs import random_program
from geomcon.errors import NotAMechanism
from geomcon.geometry import Point
from geomcon.recipes import cam_oscillating_flat as osc_flat
from geomcon.recipes import cam_translating as transl

SEEDS = range(16)


_program = random_program


def _cam(rng: np.random.Generator) -> FlatArmCam:
    return FlatArmCam(100.0, float(rng.uniform(20, 45)), float(rng.uniform(3, 15)), _program(rng),
                      str(rng.choice(["ccw", "cw"])), str(rng.choice(["left", "right"])), float(rng.uniform(-10, 10)))


def _fresh(fam: LineFamily) -> LineFamily:
    """The same lines without any kept samples (each call evaluates anew)."""
    return LineFamily(lambda d: fam.fn(np.array(d, dtype=float)), fam.breaks, fam.fn1)


def _unshared_place_search(cam: FlatArmCam, seg) -> tuple[Extremum, Extremum]:
    """(nearest, farthest) contact by :func:`maximise` on the plain array forms (fresh samples, every candidate
    valued by :func:`face_place` on arrays, or one by one when a few), a segment sampled as densely as the turn
    and the segment end rule of the nearest as :class:`_FaceSearch` applies them."""
    fam = osc_flat.flat_family(cam)
    A0, inv, tau = Point(0.0, cam.a), -float(cam.sigma), cam.tau
    pcs = fam.pieces() if seg is None else osc_flat._segment_pieces(fam, seg)

    def place(d):
        if d.size <= 16:
            return np.array([osc_flat.face_place1(fam, A0, inv, tau, x) for x in d.tolist()])
        return osc_flat.face_place(_fresh(fam), A0, inv, tau, d)

    def slope(d):
        return osc_flat.face_place_slope(_fresh(fam), A0, inv, tau, np.array(d))

    def slope1(sign):
        return lambda d: sign * osc_flat.face_place_slope1(fam, A0, inv, tau, d)

    hi = maximise(place, pcs, slope=slope, slope1=slope1(1.0))
    turn = None if seg is None else sum(b - a for a, b in fam.pieces())     # a segment as densely as the turn
    lo = maximise(lambda d: -place(d), pcs, slope=lambda d: -slope(d), slope1=slope1(-1.0), turn=turn)
    if seg is not None:
        ends = np.array([pcs[0][0], np.nextafter(pcs[-1][1], pcs[-1][0])])
        for lv, d in zip(place(ends), ends):
            if lv <= -lo.value + osc_flat.END_TIE * A0.y:
                lo = Extremum(-float(lv), float(d))
                break
    return Extremum(-lo.value, lo.delta), hi


@pytest.mark.parametrize("seed", SEEDS)
def test_shared_samples_give_the_unshared_searches(seed):
    rng = np.random.default_rng(seed)
    cam = _cam(rng)
    fam = osc_flat.flat_family(cam)              # one family for all: its samples are kept and shared
    A0, inv, tau = Point(0.0, cam.a), -float(cam.sigma), cam.tau
    assert osc_flat.face_extremes(fam, A0, inv, tau) == _unshared_place_search(cam, None)
    for seg in (cam.program.rise, cam.program.ret):
        assert osc_flat.face_nearest(fam, A0, inv, tau, seg) == _unshared_place_search(cam, seg)[0]
    alone = osc_flat.flat_family(cam)
    plain = maximise(lambda d: -envelope(_fresh(alone), np.array(d))[3], alone.pieces(),
                     g1=lambda d: -osc_flat.envelope1(alone.fn1(d))[3])
    assert envelope_rho_min(fam) == Extremum(-plain.value, plain.delta)


@pytest.mark.parametrize("seed", SEEDS)
def test_translating_face_rho_min_shared_or_not(seed):
    rng = np.random.default_rng(seed)
    fam = transl._face_family(_program(rng), float(rng.uniform(1, 30)), float(rng.uniform(20, 80)),
                              float(rng.choice([-1.0, 1.0])))
    first = envelope_rho_min(fam)
    assert envelope_rho_min(fam) == first == envelope_rho_min(_fresh(fam))


def test_place_looks_up_the_samples_and_values_the_rest_by_the_array_form():
    rng = np.random.default_rng(7)
    cam = _cam(rng)
    fam = osc_flat.flat_family(cam)
    A0, inv, tau = Point(0.0, cam.a), -float(cam.sigma), cam.tau
    search = osc_flat._FaceSearch(fam, A0, inv, tau, None)
    grid = sample_grid(tuple(fam.pieces()), 1440)
    search.slope(grid)
    some = np.concatenate([grid[rng.integers(0, grid.size, 40)], rng.uniform(0.0, TWO_PI, 30)])
    for d in (some, some[:5], some[-5:], grid[:3], np.array([grid[-1], 1.0])):
        assert search.place(d).tolist() == osc_flat.face_place(_fresh(fam), A0, inv, tau, d).tolist()


def test_envelope_terms_kept_only_for_read_only_samples():
    fam = LineFamily(lambda d: (d, 1 + 0 * d, 0 * d, 30 + np.sin(d), np.cos(d), -np.sin(d)))
    d = sample_grid(((0.0, math.pi), (math.pi, TWO_PI)), 64)
    assert envelope_terms(fam, d) is envelope_terms(fam, d)
    assert envelope_terms(fam, np.array(d)) is not envelope_terms(fam, np.array(d))
    base = np.array(d)
    view = base[:]
    view.flags.writeable = False                # read-only, but its numbers can change through its base
    first = envelope_terms(fam, view).x.tolist()
    base += 0.5
    assert envelope_terms(fam, view).x.tolist() == envelope(_fresh(fam), np.array(view))[0].tolist() != first
    assert bool(np.all(d == np.concatenate(sample_grids(((0.0, math.pi), (math.pi, TWO_PI)), 64))))
    assert [v.tolist() for v in envelope(fam, d)] == [v.tolist() for v in envelope(_fresh(fam), np.array(d))]


@pytest.mark.parametrize("seed", range(40))
def test_speed_floor_bounds_the_searched_speed(seed):
    """The laws' bound never exceeds what speed_min finds (fast swings included, where both fall below the
    threshold and the search decides the refusal)."""
    rng = np.random.default_rng(seed)
    prog = _program(rng)
    cam = FlatArmCam(100.0, float(rng.uniform(20, 45)), float(rng.uniform(3, 15)) * (1 + 9 * (seed % 4 == 0)), prog,
                     str(rng.choice(["ccw", "cw"])), str(rng.choice(["left", "right"])))
    w, _ = cam.speed_min()
    assert cam.speed_floor() <= w
    if cam.speed_floor() > osc_flat.FLAT_SPEED_MIN:
        assert w > osc_flat.FLAT_SPEED_MIN


def test_a_fast_swing_is_still_refused():
    prog = [{"kind": "rise", "angle": 20, "law": "cycloidal"}, {"kind": "dwell", "angle": 160},
            {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]
    given = {"follower": "flat", "a": 120.0, "r0": 50.0, "h": 40.0, "program": prog, "rotation": "ccw", "arm": "left"}
    for rotation, arm in (("ccw", "left"), ("cw", "left"), ("ccw", "right")):
        g = given | {"rotation": rotation, "arm": arm}
        cam = osc_flat.flat_cam_of(g)
        assert cam.speed_floor() <= osc_flat.FLAT_SPEED_MIN
        if cam.speed_min()[0] <= osc_flat.FLAT_SPEED_MIN:
            with pytest.raises(NotAMechanism, match="runs off to infinity"):
                osc_flat.validate_flat(g)
        else:
            assert osc_flat.validate_flat(g) == []


@pytest.mark.parametrize("seed", SEEDS)
def test_backward_jumps_on_floats_equal_the_array_look(seed):
    """The first look of backward_jumps on the family's scalar form against the family without it (arrays)."""
    rng = np.random.default_rng(100 + seed)
    prog = _program(rng)
    fam = transl._face_family(prog, float(rng.uniform(1, 30)), float(rng.uniform(20, 80)), float(rng.choice([-1.0, 1.0])))
    assert backward_jumps(fam) == backward_jumps(LineFamily(fam.fn, fam.breaks))
    fam = osc_flat.flat_family(_cam(rng))
    assert backward_jumps(fam) == backward_jumps(LineFamily(fam.fn, fam.breaks))


# ------------------------------------------------------------------------------------------- `at` on floats
@pytest.mark.parametrize("seed", range(8))
def test_positions_at_a_few_angles_on_floats_equal_the_arrays(seed):
    """arm_positions, face_pressures_at and face_places_at for a few angles (one by one on floats) against the
    same angles among many (the array forms): the same bits."""
    from geomcon.cam.oscillating import OscillatingCam
    from geomcon.recipes.cam_common import SCALAR_AT, arm_at, arm_positions
    rng = np.random.default_rng(200 + seed)
    flat = _cam(rng)
    roller = OscillatingCam(120.0, 100.0, 50.0, float(rng.uniform(5, 20)), flat.program, flat.rotation, flat.arm)
    few = [float(x) for x in np.round(rng.uniform(0.0, 360.0, 5), 3)] + [0.0, 360.0, flat.program.rise.end]
    many = few + [float(x) for x in rng.uniform(-30.0, 390.0, SCALAR_AT + 3)]
    for cam, B0 in ((flat, Point(-20.0, 60.0)), (roller, Point(-40.0, 30.0))):
        A0 = Point(0.0, cam.a)
        small, big = arm_positions(A0, B0, cam, tuple(few)), arm_positions(A0, B0, cam, tuple(many))
        for key in small:
            assert small[key].tolist() == big[key][:len(few)].tolist(), key
    fam = osc_flat.flat_family(flat)
    A0, inv, tau = Point(0.0, flat.a), -float(flat.sigma), flat.tau
    small = osc_flat.face_pressures_at(fam, arm_at(A0, Point(-20.0, 60.0), flat, tuple(few)))
    big = osc_flat.face_pressures_at(fam, arm_at(A0, Point(-20.0, 60.0), flat, tuple(many)))
    assert small == big[:len(few)]
    assert osc_flat.face_places_at(fam, A0, inv, tau, tuple(few)) == \
        osc_flat.face_places_at(fam, A0, inv, tau, tuple(many))[:len(few)]


def test_atan2_1_is_numpys_arctan2():
    from geomcon.cam.profile import atan2_1
    rng = np.random.default_rng(9)
    y = np.concatenate([rng.normal(size=3000) * 10.0 ** rng.uniform(-300, 300, 3000),
                        [0.0, -0.0, 0.0, -0.0, np.inf, -np.inf, np.inf, 1.0, np.nan, 1.0]])
    x = np.concatenate([rng.normal(size=3000) * 10.0 ** rng.uniform(-300, 300, 3000),
                        [0.0, 0.0, -0.0, -0.0, np.inf, np.inf, -1.0, -np.inf, 1.0, np.nan]])
    want = np.arctan2(y, x)
    got = np.array([atan2_1(a, b) for a, b in zip(y.tolist(), x.tolist())])
    assert np.array_equal(want, got, equal_nan=True) and np.array_equal(np.signbit(want), np.signbit(got))
    assert [math.degrees(v) for v in got[:50].tolist()] == np.degrees(got[:50]).tolist()
    assert [math.radians(v) for v in y[:50].tolist()] == np.radians(y[:50]).tolist()


@pytest.mark.parametrize("seed", range(6))
def test_laid_off_and_speed_ratio_on_floats_equal_the_motion_arrays(seed):
    """The pitch point laid off and the speed ratio at one angle (program.motion1, segment_motion1) against
    the array motion they used before: the same bits, segment ends and out-of-turn angles included."""
    from geomcon.cam.oscillating import OscillatingCam, levels, segment_motion
    from geomcon.geometry import rotate
    from geomcon.recipes.cam_common import laid_off, speed_ratio
    rng = np.random.default_rng(300 + seed)
    flat = _cam(rng)
    cam = OscillatingCam(120.0, 100.0, 50.0, float(rng.uniform(5, 20)), flat.program, flat.rotation, flat.arm)
    ends = [s.start for s in cam.program.segments] + [360.0]
    angles = [float(x) for x in rng.uniform(-20.0, 380.0, 40)] + ends
    C, A = Point(-30.0, 40.0), Point(0.0, 120.0)
    for arm in (cam, flat):
        for d in angles:
            assert laid_off(C, A, arm, d) == rotate(C, A, arm.tau * float(arm.motion(d).psi))
            assert speed_ratio(arm, d) == arm.eps * float(arm.motion(d).d1)
            for part in ("rise", "return"):
                k = next(i for i, s in enumerate(arm.program.segments) if s.kind == part)
                seg = arm.program.segments[k]
                x = min(max((d - seg.start) / seg.angle, 0.0), 1.0)
                want = arm.eps * float(segment_motion(seg, levels(arm.program, arm.h)[k], arm.h, x).d1)
                assert speed_ratio(arm, d, part) == want


@pytest.mark.parametrize("seed", range(6))
def test_the_searchs_slope_on_floats_is_face_place_slope1(seed):
    rng = np.random.default_rng(400 + seed)
    cam = _cam(rng)
    fam = osc_flat.flat_family(cam)
    A0, inv, tau = Point(0.0, cam.a), -float(cam.sigma), cam.tau
    search = osc_flat._FaceSearch(fam, A0, inv, tau, None)
    breaks = np.array(fam.breaks)
    angles = np.concatenate([rng.uniform(0.0, TWO_PI, 300), breaks, np.nextafter(breaks, 0.0), [0.0]]).tolist()
    for sign in (1.0, -1.0):
        fast = search._slope1(sign)
        assert [fast(d) for d in angles] == [sign * osc_flat.face_place_slope1(fam, A0, inv, tau, d) for d in angles]


def _searches(cam: FlatArmCam, order: str = "turn first") -> list[Extremum]:
    fam = osc_flat.flat_family(cam)
    A0, inv, tau = Point(0.0, cam.a), -float(cam.sigma), cam.tau
    segs = [osc_flat.face_nearest(fam, A0, inv, tau, seg) for seg in (cam.program.rise, cam.program.ret)] \
        if order == "segments first" else []
    out = list(osc_flat.face_extremes(fam, A0, inv, tau))
    if not segs:
        segs = [osc_flat.face_nearest(fam, A0, inv, tau, seg) for seg in (cam.program.rise, cam.program.ret)]
    return out + segs


def test_pruned_brackets_change_no_search(monkeypatch):
    """The brackets the shared searches do not refine (they cannot reach the best candidate) change nothing:
    over random arms where some are left out, every search equals maximise's with every bracket refined,
    whichever search runs first."""
    from geomcon.cam import arm_face
    refined = []
    plain = arm_face.illinois1
    monkeypatch.setattr(arm_face, "illinois1", lambda *a: refined.append(a) or plain(*a))
    pruned = 0
    for seed in range(200, 260):
        cam = _cam(np.random.default_rng(seed))
        refined.clear()
        got = _searches(cam)
        with monkeypatch.context() as m:
            m.setattr(arm_face, "PRUNE_GAIN", math.inf)      # nothing left out
            n = len(refined)
            assert _searches(cam, "segments first") == got
            pruned += (len(refined) - n) - n           # refinements with nothing left out, less the pruned run's
        want = [*_unshared_place_search(cam, None), *(_unshared_place_search(cam, seg)[0]
                                                      for seg in (cam.program.rise, cam.program.ret))]
        assert got == want
    assert pruned > 0                                   # the test saw brackets left out


def test_200_07_farthest_contact_leaves_the_roundoff_bracket_out(monkeypatch):
    """200-07's slope of l changes sign a sample from the rise's start by roundoff (l′ ∝ δ there); that
    bracket cannot reach the farthest contact (128.4 mm against l(0) = 103.9 mm) and is not refined."""
    from geomcon.cam import arm_face
    refined = []
    plain = arm_face.illinois1
    monkeypatch.setattr(arm_face, "illinois1", lambda *a: refined.append(a[1]) or plain(*a))
    prog = [{"kind": "rise", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60},
            {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]
    from geomcon.cam.program import parse_program
    cam = FlatArmCam(120.0, 50.0, 15.0, parse_program(prog), offset=10.0)
    got = _searches(cam)
    assert got[0] == _unshared_place_search(cam, None)[0] and got[1] == _unshared_place_search(cam, None)[1]
    assert round(got[1].value, 6) == 128.399117 and 0.0 not in refined
