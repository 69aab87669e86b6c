"""The cams' scalar paths (one angle on floats, no numpy call) against the array paths they stand for.

Where a scalar form is said to give the same bits as its array form (the laws, a program's motion, the
inversion, the slopes the root searches bisect), the tests compare with ``==``; where it rounds differently
on purpose (math's hypot and complex numbers in the twins), to 1e-15 relative. The searches' refinements
(Illinois with a step inside, Brent) are compared with dense grids and with the array refinements.
"""
from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from geomcon.cam.laws import LAWS, LAW_NAMES
from geomcon.cam.oscillating import OscillatingCam, segment_motion, segment_motion1, levels
from geomcon.cam.oscillating_flat import FlatArmCam
from geomcon.cam.profile import (LineFamily, PitchCurve, _bisect_all, backward_jumps, brent_max1, envelope,
                                 envelope1, frame_pressure_angle_slope, frame_pressure_angle_slope1, illinois1,
                                 inverted, inverted1, inverted_relative, inverted_relative1, pow1, rho_min,
                                 JUMP_REL, TWO_PI, _DENSE, Extremum, envelope_rho_min)
from geomcon.cam.program import parse_program
from geomcon.cam.translating import TranslatingCam, _max_by_root
from geomcon.problems import load_problem, problem_from_dict
from geomcon.recipes import cam_oscillating_flat as osc_flat
from geomcon.recipes import cam_translating as transl
from geomcon.solve import solve

SEEDS = range(12)


def _program(rng: np.random.Generator, *, short: bool = False):
    """A random full-turn program (rise, dwell, return, dwell; any laws), or a lone rise."""
    if short:
        return parse_program([{"kind": "rise", "angle": float(rng.uniform(30, 300)), "law": str(rng.choice(LAW_NAMES))}])
    a = rng.dirichlet([2, 1, 2, 1]) * 360.0
    a[-1] = 360.0 - a[:-1].sum()
    kinds = ("rise", "dwell", "return", "dwell")
    return parse_program([{"kind": k, "angle": float(x), **({"law": str(rng.choice(LAW_NAMES))} if k != "dwell" else {})}
                          for k, x in zip(kinds, a)])


def _arm_cam(rng: np.random.Generator, prog) -> OscillatingCam:
    """A random oscillating roller cam that can be assembled (|a − L| < r0 < a)."""
    a = float(rng.uniform(80, 200))
    cam = OscillatingCam(a, float(rng.uniform(0.7, 1.0)) * a, float(rng.uniform(0.32, 0.6)) * a,
                         float(rng.uniform(5, 25)), prog, str(rng.choice(["ccw", "cw"])), str(rng.choice(["left", "right"])))
    assert math.isfinite(cam.psi0)
    return cam


def _translating_curve(rng: np.random.Generator):
    """A random translating cam's program, sense (inv) and pitch curve (offset |e| < 0.8 r0)."""
    prog, h = _program(rng), float(rng.uniform(1.0, 40.0))
    r0 = float(rng.uniform(h, 4 * h))
    e = float(rng.uniform(-0.8, 0.8)) * r0
    inv = float(rng.choice([-1.0, 1.0]))
    return prog, inv, transl._pitch_curve(prog, h, e, math.sqrt(r0 * r0 - e * e), inv)


def _angles(rng: np.random.Generator, prog, radians: bool) -> np.ndarray:
    """Random angles over the turn and a little beyond, every segment end and parabolic middle and their
    neighbouring floats."""
    turn = TWO_PI if radians else 360.0
    conv = math.radians if radians else float
    marks = [conv(s.start) for s in prog.segments] + [conv(prog.segments[-1].end)]
    marks += [conv(s.start + s.angle / 2) for s in prog.segments]
    marks = np.array(marks)
    return np.concatenate([rng.uniform(-0.2 * turn, 1.2 * turn, 400), [0.0, turn], marks,
                           np.nextafter(marks, -np.inf), np.nextafter(marks, np.inf)])


# ------------------------------------------------------------------------------------------- laws, programs
def test_law_scalar_forms_give_the_array_bits():
    x = np.concatenate([np.random.default_rng(0).uniform(0.0, 1.0, 20000), [0.0, 1.0, 0.5, np.nextafter(0.5, 0)]])
    for law in LAWS.values():
        arrays = law.derivatives(x)
        scalars = np.array([law.fn1(v) for v in x.tolist()]).T
        for a, b in zip(arrays, scalars):
            assert np.array_equal(a, b), law.name


@pytest.mark.parametrize("seed", SEEDS)
def test_motion1_and_every_array_route_give_the_same_bits(seed):
    rng = np.random.default_rng(seed)
    prog, h = _program(rng, short=seed % 4 == 3), float(rng.uniform(0.1, 50.0))
    for radians in (False, True):
        d = _angles(rng, prog, radians)
        scalar = np.array([prog.motion1(h, v, radians) for v in d.tolist()]).T
        masks = prog.motion(h, rng.permutation(d), radians=radians)        # unsorted: the masked route
        order = np.argsort(d, kind="stable")
        sorted_ = prog.motion(h, d[order], radians=radians)                 # sorted: slices per segment
        for i in range(3):
            back = np.empty_like(d)
            back[order] = sorted_[i]
            assert np.array_equal(back, scalar[i])
        perm_check = prog.motion(h, d, radians=radians)
        for i in range(3):
            assert np.array_equal(perm_check[i], scalar[i])
            assert np.array_equal(np.sort(masks[i]), np.sort(scalar[i]))
        few = d[:7]                                                         # a few angles: one by one
        for a, b in zip(prog.motion(h, few, radians=radians), scalar[:, :7]):
            assert np.array_equal(a, b)


# ------------------------------------------------------------------------------------------- inversion, slopes
@pytest.mark.parametrize("seed", SEEDS)
def test_translating_pitch_curve_scalar_form_gives_the_array_bits(seed):
    rng = np.random.default_rng(seed)
    prog, inv, curve = _translating_curve(rng)
    d = np.sort(rng.uniform(0.0, TWO_PI, 300))
    c6, rel = curve.eval(d), curve.relative(d)
    ux, uy = transl._axis(inv, d)
    slope = frame_pressure_angle_slope(c6, rel, ux, uy)
    for i, x in enumerate(d.tolist()):
        assert curve.fn1(x) == tuple(float(v[i]) for v in c6)
        assert curve.relative1(x) == (float(rel[0][i]), float(rel[1][i]))
        s1 = frame_pressure_angle_slope1(curve.fn1(x), curve.relative1(x), -math.sin(inv * x), math.cos(inv * x))
        assert s1 == float(slope[i])


def test_inversion_scalar_forms_give_the_array_bits():
    rng = np.random.default_rng(5)
    for rotation in ("ccw", "cw"):
        for _ in range(200):
            d = float(rng.uniform(-7, 7))
            q, dq, ddq = [tuple(rng.normal(0, 30, 2).tolist()) for _ in range(3)]
            arr = inverted(np.array([d]), rotation, *[(np.array([a]), np.array([b])) for a, b in (q, dq, ddq)])
            assert inverted1(d, rotation, q, dq, ddq) == tuple(float(v[0]) for v in arr)
            rel = inverted_relative(np.array([d]), rotation, *[(np.array([a]), np.array([b])) for a, b in (dq, ddq)])
            assert inverted_relative1(d, rotation, dq, ddq) == (float(rel[0][0]), float(rel[1][0]))


@pytest.mark.parametrize("seed", SEEDS)
def test_oscillating_scalar_forms_give_the_array_bits(seed):
    rng = np.random.default_rng(seed)
    prog = _program(rng)
    cam = _arm_cam(rng, prog)
    d = np.sort(rng.uniform(0.0, TWO_PI, 200))
    vec = cam.pitch_of(cam.motion_rad(d))
    fn1 = cam.pitch1_fn()
    for i, x in enumerate(d.tolist()):
        assert fn1(x) == tuple(float(v[i]) for v in vec)
    slope1 = cam._tan_slope1()
    lev = levels(prog, cam.h)
    for k, seg in enumerate(prog.segments):
        x = rng.uniform(0.0, 1.0, 50)
        m = segment_motion(seg, lev[k], cam.h, x)
        n, dd, n1, d1 = cam.tan_pressure_parts(m)
        vec_slope = np.sign(n) * (n1 * dd - n * d1)
        arg_slope = cam.pressure_arg_slope(m)
        kappa = cam.convex_curvature_complex(m)
        for i, xi in enumerate(x.tolist()):
            m1 = segment_motion1(seg, lev[k], cam.h, xi)
            assert m1 == (float(m.delta[i]), float(m.psi[i]), float(m.d1[i]), float(m.d2[i]))
            assert slope1(m1) == float(vec_slope[i])
            assert cam.pressure_arg_slope1()(m1) == pytest.approx(float(arg_slope[i]), rel=1e-12, abs=1e-12)
            assert cam.convex_curvature_complex1()(m1) == pytest.approx(float(kappa[i]), rel=1e-13)


@pytest.mark.parametrize("seed", SEEDS)
def test_flat_faces_scalar_forms_give_the_array_bits(seed):
    rng = np.random.default_rng(seed)
    prog = _program(rng)
    cam = FlatArmCam(100.0, float(rng.uniform(20, 45)), float(rng.uniform(3, 15)), prog,
                     str(rng.choice(["ccw", "cw"])), str(rng.choice(["left", "right"])), float(rng.uniform(-10, 10)))
    fam = osc_flat.flat_family(cam)
    d = np.sort(rng.uniform(0.0, TWO_PI, 200))
    lines, env = fam.eval(d), envelope(fam, d)
    from geomcon.geometry import Point
    A0 = Point(0.0, 100.0)
    inv, tau = -float(cam.sigma), cam.tau
    place, slope = osc_flat.face_place(fam, A0, inv, tau, d), osc_flat.face_place_slope(fam, A0, inv, tau, d)
    for i, x in enumerate(d.tolist()):
        f6 = fam.fn1(x)
        assert f6 == tuple(float(v[i]) for v in lines)
        assert envelope1(f6) == tuple(float(v[i]) for v in env)
        assert osc_flat.face_place1(fam, A0, inv, tau, x) == float(place[i])
        assert osc_flat.face_place_slope1(fam, A0, inv, tau, x) == float(slope[i])
    contact1, slope1, rho1 = cam.scalar_forms()
    lev = levels(prog, cam.h)
    for k, seg in enumerate(prog.segments):
        x = rng.uniform(0.0, 1.0, 30)
        m = segment_motion(seg, lev[k], cam.h, x)
        for i, xi in enumerate(x.tolist()):
            m1 = segment_motion1(seg, lev[k], cam.h, xi)
            assert (contact1(m1), slope1(m1), rho1(m1)) == (float(cam.contact_of(m)[i]),
                                                          float(cam.contact_slope_of(m)[i]), float(cam.rho_of(m)[i]))


def test_pow1_is_numpys_power():
    x = np.random.default_rng(2).uniform(1e-3, 1e3, 20000)
    for y in (1.5, 3.0):
        assert np.array_equal(x ** y, np.array([pow1(v, y) for v in x.tolist()]))


def test_pow1_is_numpys_power_at_the_edges():
    """Signs, tiny and huge numbers (overflow to ±inf, underflow), zeros, infinities and nan: numpy's bits
    whichever route pow1 takes (math.pow raises where numpy returns inf or nan)."""
    rng = np.random.default_rng(5)
    x = np.concatenate([rng.uniform(-1e3, 1e3, 5000), 10.0 ** rng.uniform(-320, 308, 2000) * rng.choice([-1, 1], 2000),
                        [0.0, -0.0, np.inf, -np.inf, np.nan, 1e103, -1e103, 1e-110, 5e-324]])
    with np.errstate(all="ignore"):
        for y in (1.5, 3.0, 2.0, -1.0):
            want = x ** y if y not in (2.0, -1.0) else np.power(x, y)
            got = np.array([pow1(v, y) for v in x.tolist()])
            assert np.array_equal(want, got, equal_nan=True)
            assert np.array_equal(np.signbit(want), np.signbit(got))


# ------------------------------------------------------------------------------------------- the refinements
def test_illinois1_ends_at_a_sign_change_between_adjacent_floats_and_agrees_with_the_array_bisection():
    rng = np.random.default_rng(3)
    for _ in range(300):
        c, w, p = rng.uniform(0.2, 5.0), rng.uniform(0.3, 3.0), rng.uniform(-1.0, 1.0)

        def f1(t):
            return math.sin(w * (c - t)) + 0.3 * p * math.sin(w * (c - t)) ** 3

        lo, hi = c - rng.uniform(0.01, 0.5) / w, c + rng.uniform(0.01, 0.5) / w
        calls = []
        x = illinois1(lambda t: calls.append(t) or f1(t), lo, hi, f1(lo), f1(hi))
        below = math.nextafter(x, -math.inf)
        assert f1(x) <= 0.0 < f1(below)
        assert len(calls) < 40
        ref = _bisect_all(lambda t: np.sin(w * (c - t)) + 0.3 * p * np.sin(w * (c - t)) ** 3,
                          np.array([lo]), np.array([hi]))[0]
        assert abs(x - ref) <= 4 * math.ulp(x)          # the same root (the sign may flicker in the last ulps)


def test_brent_max1_finds_the_dense_grid_maximum():
    rng = np.random.default_rng(4)
    for _ in range(200):
        a, b, c = rng.uniform(0.5, 3.0, 3)

        def g1(t):
            return math.exp(-a * (t - b) ** 2) * (1.0 + 0.2 * math.cos(c * t))

        grid = np.linspace(b - 0.5, b + 0.5, 200001)
        values = np.exp(-a * (grid - b) ** 2) * (1.0 + 0.2 * np.cos(c * grid))
        i = int(np.argmax(values))
        x, v = brent_max1(g1, float(grid[i] - 1e-3), float(grid[i]), float(grid[i] + 1e-3), float(values[i]))
        assert v >= float(values[i]) - 1e-16 and abs(x - float(grid[i])) < 1e-5
        assert v == pytest.approx(max(g1(x + k * 1e-9) for k in range(-50, 51)), rel=1e-15)


@pytest.mark.parametrize("seed", SEEDS)
def test_rho_min_by_brent_on_floats_equals_golden_sections_on_arrays(seed):
    rng = np.random.default_rng(seed)
    prog, h = _program(rng), float(rng.uniform(1.0, 40.0))
    r0 = float(rng.uniform(h, 4 * h))
    e = float(rng.uniform(-0.8, 0.8)) * r0
    curve = transl._pitch_curve(prog, h, e, math.sqrt(r0 * r0 - e * e), float(rng.choice([-1.0, 1.0])))
    plain = PitchCurve(curve.fn, curve.breaks, curve.relative)          # without the scalar form
    fast, slow = rho_min(curve), rho_min(plain)
    assert fast.value == pytest.approx(slow.value, rel=1e-14)


@pytest.mark.parametrize("seed", SEEDS)
def test_slope_roots_on_floats_equal_the_array_refinement(seed):
    rng = np.random.default_rng(seed)
    prog, inv, curve = _translating_curve(rng)
    plain = PitchCurve(curve.fn, curve.breaks, curve.relative)
    for seg in (prog.rise, prog.ret):
        fast = transl.worst_alpha(curve, inv, seg.start, seg.end)
        slow = transl.worst_alpha(plain, inv, seg.start, seg.end)
        assert fast.value == pytest.approx(slow.value, rel=1e-14)
        assert fast.delta == pytest.approx(slow.delta, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("seed", SEEDS)
def test_axis_slope_in_the_followers_frame_equals_the_turned_slope(seed):
    """α′ sampled before the turn (the translating α search's grid) is the turned form's to roundoff."""
    from geomcon.cam.profile import frame_pressure_angle_slope
    rng = np.random.default_rng(seed)
    prog, inv, curve = _translating_curve(rng)
    d = np.linspace(0.0, 2 * math.pi, 2001)[:-1]
    turned = frame_pressure_angle_slope(curve.eval(d), curve.relative(d), *transl._axis(inv, d))
    fast = curve.axis_slope(d)
    scale = float(np.abs(turned).max())
    assert np.allclose(fast, turned, rtol=1e-12, atol=1e-12 * scale)


@pytest.mark.parametrize("seed", SEEDS)
def test_oscillating_searches_on_floats_equal_the_array_searches(seed):
    rng = np.random.default_rng(seed)
    prog = _program(rng)
    cam = _arm_cam(rng, prog)
    for kind in ("rise", "return"):
        fast = cam.worst_pressure(kind)

        def slope(m):
            n, d, n1, d1 = cam.tan_pressure_parts(m)
            return np.sign(n) * (n1 * d - n * d1)

        slow = cam.segment_max(kind, cam.pressure_of, slope)    # bisection to the last bit on arrays
        # the scalar path refines by Brent to 1e-15 of the segment: the flat maximum's value to rounding
        assert fast[0] == pytest.approx(slow[0], rel=1e-14) and fast[1] == pytest.approx(slow[1], abs=1e-11)
        twin = cam.worst_pressure(kind, route="arg")
        assert twin[0] == pytest.approx(fast[0], rel=1e-12) and twin[1] == pytest.approx(fast[1], abs=1e-7)
    golden = cam.turn_max(cam.convex_curvature_complex)
    brent = cam.turn_max(cam.convex_curvature_complex, cam.convex_curvature_complex1())
    assert brent[0] == pytest.approx(golden[0], rel=1e-13)


@pytest.mark.parametrize("seed", SEEDS)
def test_translating_twin_on_floats_equals_its_array_form(seed):
    rng = np.random.default_rng(seed)
    prog, h = _program(rng), float(rng.uniform(1.0, 40.0))
    r0 = float(rng.uniform(h, 4 * h))
    cam = TranslatingCam(prog, h, r0, float(rng.uniform(-0.8, 0.8)) * r0, str(rng.choice(["ccw", "cw"])))
    for kind in ("rise", "return"):
        seg = prog.rise if kind == "rise" else prog.ret

        def g(d):
            s, v, _ = cam._rad(d)
            return np.degrees(np.arctan2(np.abs(v - cam.k * cam.e), cam.s0 + s))

        def dg(d):
            s, v, a = cam._rad(d)
            E = v - cam.k * cam.e
            return np.sign(E) * (a * (cam.s0 + s) - E * v)

        slow = _max_by_root(g, dg, math.radians(seg.start), math.radians(seg.end))
        assert cam.alpha_max(kind) == (slow[0], math.degrees(slow[1]))
    assert cam.rho_min_pitch() == pytest.approx(TranslatingCam(prog, h, r0, cam.e, cam.rotation)._rho_min_pitch(), rel=1e-15)


# ------------------------------------------------------------------------------------------- shortcuts
def _backward_jumps_in_full(fam: LineFamily) -> tuple[Extremum, ...]:
    """backward_jumps as it was written before its shortcut: every sample of the range, always."""
    cuts = [0.0] + [x for x in sorted(fam.breaks) if 0.0 < x < TWO_PI]
    after = np.array(cuts)
    before = np.nextafter(np.array([b if b > 0.0 else TWO_PI for b in cuts]), 0.0)
    grid = np.linspace(0.0, TWO_PI, _DENSE, endpoint=False)
    lam = envelope(fam, np.concatenate([after, before, grid]))[2]
    span = float(np.nanmax(lam) - np.nanmin(lam))
    la, lb = lam[:len(cuts)], lam[len(cuts):2 * len(cuts)]
    dphi = fam.eval(after)[1]
    return tuple(Extremum(float((x1 - x0) * math.copysign(1.0, w)), b)
                 for b, x0, x1, w in zip(cuts, lb.tolist(), la.tolist(), dphi.tolist())
                 if (x1 - x0) * math.copysign(1.0, w) < -JUMP_REL * span)


@pytest.mark.parametrize("seed", SEEDS)
def test_backward_jumps_shortcut_changes_nothing(seed):
    rng = np.random.default_rng(seed)
    prog = _program(rng)
    fam = transl._face_family(prog, float(rng.uniform(1, 30)), float(rng.uniform(20, 80)), float(rng.choice([-1.0, 1.0])))
    assert backward_jumps(fam) == _backward_jumps_in_full(fam)
    cam = FlatArmCam(100.0, float(rng.uniform(20, 45)), float(rng.uniform(3, 15)), prog)
    fam = osc_flat.flat_family(cam)
    assert backward_jumps(fam) == _backward_jumps_in_full(fam)
    fam = osc_flat.flat_family(cam)
    envelope_rho_min(fam)                       # the turn's samples kept: the pieces' ends read from them
    assert backward_jumps(fam) == _backward_jumps_in_full(fam)


def _given(name: str) -> dict:
    """The givens as the problem file writes them."""
    with open(f"problems/{name}.toml", "rb") as f:
        return tomllib.load(f)["given"]


@pytest.mark.parametrize("name", ["200-01_cam_roller_offset", "200-02_cam_flat_face", "200-05_oscillating_roller_cam",
                                  "200-07_oscillating_flat_face"])
def test_warnings_are_the_same_with_or_without_the_checks_first(name):
    """The warnings reuse the checks' twin (or the construction's searches) within a solve: the same text as
    when they are made alone, on another problem object, first."""
    given = _given(name)
    given["alpha_allow"] = 5.0                  # every allowance exceeded: the warnings search α too
    alone = solve(problem_from_dict({"recipe": load_problem(f"problems/{name}.toml").recipe, "given": given}, name="a"))
    first = alone.warnings
    both = solve(problem_from_dict({"recipe": alone.recipe.name, "given": _given(name) | {"alpha_allow": 5.0}},
                                   name="b"))
    assert both.checks and both.warnings == first


@pytest.mark.parametrize("name", ["200-01_cam_roller_offset", "200-05_oscillating_roller_cam", "200-07_oscillating_flat_face"])
def test_answers_alone_compute_no_profile_and_stay_lazy(name):
    sol = solve(load_problem(f"problems/{name}.toml"))
    sol.answers
    assert not sol.scene.is_evaluated("profile")
    stats = sol.stats
    assert stats["steps_evaluated"] < stats["steps_total"]
