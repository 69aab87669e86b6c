"""Follower speeds with a given ω (v, a, v_max, a_max; an arm's ω2, ε2 and their maxima) and the handbook and
parametrised motion laws (double-harmonic, modified trapezoid, modified sine, poly, table): the construction
(exact derivatives, maxima at roots of the next derivative) against the twin (laws written again, quadrature,
sampling + golden sections) on random instances to 1e-9; finite differences of s; the handbook constants;
the spline's continuity; refusals."""
from __future__ import annotations

import math
import random

import pytest

from geomcon.analytic import cam_motion
from geomcon.cam.custom_laws import MAX_COEFFICIENTS, MAX_POINTS, _impact, custom_law
from geomcon.cam.kinematics import law_peaks, program_extrema
from geomcon.cam.laws import LAWS, law
from geomcon.cam.program import parse_program
from geomcon.errors import NotAMechanism
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

NAMED = ("uniform", "parabolic", "cosine", "cycloidal", "poly345", "double_harmonic", "modified_trapezoid",
         "modified_sine")


def _poly_row(rng: random.Random) -> dict:
    """A random polynomial law with f(0) = 0, f(1) = 1, f′(0) = f′(1) = 0 (degree 4 to 7)."""
    n = rng.randint(4, 7)
    c = [0.0, 0.0] + [rng.uniform(-3, 3) for _ in range(n - 3)]
    # fix the last two coefficients: Σc = 1 and Σ k c_k = 0
    s0, s1 = sum(c), sum(k * ck for k, ck in enumerate(c))
    m, p = n - 1, n                     # c_m x^m + c_p x^p
    # c_m + c_p = 1 − s0, m c_m + p c_p = −s1
    cp = (-s1 - m * (1 - s0)) / (p - m)
    cm = 1 - s0 - cp
    return {"law": "poly", "coefficients": c + [cm, cp]}


def _table_row(rng: random.Random) -> dict:
    """A random table near a smooth rise (points at least 0.05 apart, f within ±0.03 of 3x² − 2x³): a cam that
    can work (a steep table gives pressure angles near 90°, a badly conditioned cam)."""
    n = rng.randint(3, 9)
    xs = [(i + rng.uniform(-0.25, 0.25)) / (n - 1) for i in range(1, n - 1)]
    return {"law": "table", "points": [[0, 0], *[[x, 3 * x * x - 2 * x ** 3 + rng.uniform(-0.03, 0.03)] for x in xs],
                                       [1, 1]]}


def _law_row(rng: random.Random) -> dict:
    k = rng.randrange(len(NAMED) + 2)
    if k < len(NAMED):
        return {"law": NAMED[k]}
    return _poly_row(rng) if k == len(NAMED) else _table_row(rng)


def _program(rng: random.Random) -> list[dict]:
    rise, ret = rng.uniform(60, 160), rng.uniform(60, 140)
    d1 = rng.uniform(0, 360 - rise - ret - 10)
    segs = [{"kind": "rise", "angle": rise, **_law_row(rng)}]
    if d1 > 1:
        segs.append({"kind": "dwell", "angle": d1})
    segs.append({"kind": "return", "angle": ret, **_law_row(rng)})
    segs.append({"kind": "dwell", "angle": 360 - rise - ret - (d1 if d1 > 1 else 0)})
    return segs


def _checks_ok(sol, names):
    bad = [c for c in sol.checks if not c["ok"]]
    assert not bad, bad
    have = {c["quantity"].split("[")[0] for c in sol.checks}
    assert set(names) <= have, (names, have)


@pytest.mark.parametrize("i", range(24))
def test_translating_speeds_agree_with_the_twin(i):
    rng = random.Random(14100 + i)
    r0 = rng.uniform(30, 80)
    follower = ("knife", "roller", "flat")[i % 3]
    g = {"follower": follower, "r0": r0, "h": rng.uniform(0.1, 0.4) * r0, "program": _program(rng),
         "rotation": rng.choice(["ccw", "cw"]), "omega": rng.uniform(0.5, 200.0),
         "at": [round(rng.uniform(0, 360), 3) for _ in range(6)]}
    if follower != "flat":
        g["e"] = rng.uniform(-0.3, 0.3) * r0
    if follower == "roller":
        g["rr"] = rng.uniform(0.05, 0.15) * r0
    sol = solve(problem_from_dict({"recipe": "cam.translating", "given": g}, name="t"))
    _checks_ok(sol, ("v", "a", "v_max", "a_max", "s", "alpha"))


@pytest.mark.parametrize("i", range(12))
def test_arm_speeds_agree_with_the_twin(i):
    rng = random.Random(14200 + i)
    flat = i % 3 == 2
    g = {"follower": "flat" if flat else ("knife", "roller")[i % 2], "a": 100.0, "r0": rng.uniform(35, 50),
         "h": rng.uniform(8, 20), "program": _program(rng), "rotation": rng.choice(["ccw", "cw"]),
         "arm": rng.choice(["left", "right"]), "omega": rng.uniform(0.5, 100.0),
         "at": [round(rng.uniform(0, 360), 3) for _ in range(5)]}
    if not flat:
        g["L"] = 80.0
    if g["follower"] == "roller":
        g["rr"] = 5.0
    sol = solve(problem_from_dict({"recipe": "cam.oscillating", "given": g}, name="t"))
    _checks_ok(sol, ("omega2", "epsilon2", "omega2_max", "epsilon2_max"))


@pytest.mark.parametrize("i", range(40))
def test_motion_and_maxima_of_random_programs_to_1e_9(i):
    """The program's exact s, s′, s″ and maxima against the twin's, relative 1e-9 of the scale h/Φ^k."""
    rng = random.Random(14300 + i)
    rows = _program(rng)
    h = rng.uniform(1, 50)
    prog = parse_program(rows)
    for d in [rng.uniform(0, 360) for _ in range(30)] + [0.0, 360.0] + [s.start for s in prog.segments]:
        got, want = prog.motion1(h, d), cam_motion.motion(rows, h, d)
        for k, (x, y) in enumerate(zip(got, want)):
            assert abs(x - y) <= 1e-9 * h * 60.0 ** k, (d, k, x, y)
    vm, _, am, _ = program_extrema(prog, h)
    tv, ta = cam_motion.maxima(rows, h)
    assert vm == pytest.approx(tv, rel=1e-9)
    assert am == pytest.approx(ta, rel=1e-9)


@pytest.mark.parametrize("i", range(10))
def test_velocity_is_the_derivative_of_s(i):
    """v and a against central differences of s (an outside check of both routes)."""
    rng = random.Random(14400 + i)
    rows = _program(rng)
    prog = parse_program(rows)
    h, step = 20.0, 1e-4
    for _ in range(20):
        seg = rng.choice([s for s in prog.segments if s.kind != "dwell"])
        d = seg.start + rng.uniform(0.05, 0.95) * seg.angle
        sp, s0, sm = (prog.motion1(h, d + k * step)[0] for k in (1, 0, -1))
        dr = math.radians(step)
        _, v, a = prog.motion1(h, d)
        assert v == pytest.approx((sp - sm) / (2 * dr), rel=1e-6, abs=1e-6 * h)
        big = 1e-2                                         # s″: a wider step (rounding grows as 1/step²)
        if all(abs((d - seg.start) / seg.angle - c) * seg.angle > 3 * big for c in (*seg.law.cuts, 0.0, 1.0)):
            sp, sm = prog.motion1(h, d + big)[0], prog.motion1(h, d - big)[0]
            assert a == pytest.approx((sp - 2 * s0 + sm) / math.radians(big) ** 2, rel=1e-5, abs=1e-5 * h)


def test_speeds_do_not_depend_on_the_sense_of_rotation():
    base = {"follower": "knife", "r0": 40, "h": 15, "omega": 12.0, "at": [20, 100, 200],
            "program": [{"kind": "rise", "angle": 120, "law": "modified_trapezoid"}, {"kind": "dwell", "angle": 60},
                        {"kind": "return", "angle": 120, "law": "double_harmonic"}, {"kind": "dwell", "angle": 60}]}
    a = solve(problem_from_dict({"recipe": "cam.translating", "given": {**base, "rotation": "ccw"}}, name="t")).answers
    b = solve(problem_from_dict({"recipe": "cam.translating", "given": {**base, "rotation": "cw"}}, name="t")).answers
    for k in ("v", "a", "v_max", "a_max"):
        assert a[k] == b[k]
    assert a["v"][0] > 0 and a["v"][2] < 0            # rising, then returning


def test_no_omega_no_speeds():
    g = {"follower": "knife", "r0": 40, "h": 15, "at": [20],
         "program": [{"kind": "rise", "angle": 180, "law": "cosine"}, {"kind": "return", "angle": 180, "law": "cosine"}]}
    ans = solve(problem_from_dict({"recipe": "cam.translating", "given": g}, name="t")).answers
    assert not {"v", "a", "v_max", "a_max"} & set(ans)


# ------------------------------------------------------------------------------------------ the laws
def test_handbook_constants():
    mt, ms, dh = (law_peaks(law(n)) for n in ("modified_trapezoid", "modified_sine", "double_harmonic"))
    assert mt.v == pytest.approx(2.0, rel=1e-14) and mt.x_v == pytest.approx(0.5, abs=1e-12)
    assert mt.a == pytest.approx(8 * math.pi / (math.pi + 2), rel=1e-14)
    assert ms.a == pytest.approx(math.pi * ms.v, rel=1e-13)          # C = π·Cv
    assert (round(ms.v, 4), round(ms.a, 3)) == (1.7596, 5.528)       # the handbooks' Cv = 1.76, Ca = 5.53
    assert dh.a == pytest.approx(math.pi ** 2, rel=1e-14)            # at the end: −π²
    for name in ("modified_trapezoid", "modified_sine"):             # the twin's quadrature amplitude
        assert law_peaks(law(name)).a == pytest.approx(cam_motion._amplitude(name), rel=1e-13)


def test_standard_peaks_are_the_textbook_ones():
    want = {"uniform": (1.0, 0.0), "parabolic": (2.0, 4.0), "cosine": (math.pi / 2, math.pi ** 2 / 2),
            "cycloidal": (2.0, 2 * math.pi), "poly345": (1.875, 10 / math.sqrt(3))}
    for name, (v, a) in want.items():
        p = law_peaks(LAWS[name])
        assert p.v == pytest.approx(v, rel=1e-14) and p.a == pytest.approx(a, rel=1e-14), name
        assert LAWS[name].peak1 == pytest.approx(p.v, rel=1e-15)


def test_impact_classes():
    for name, lw in LAWS.items():
        assert _impact(lw.fn1) == lw.impact, name
    assert [law(n).impact for n in ("double_harmonic", "modified_trapezoid", "modified_sine")] == ["soft", "none", "none"]
    assert custom_law("poly", {"coefficients": [0, 1]}).impact == "rigid"
    assert custom_law("poly", {"coefficients": [0, 0, 3, -2]}).impact == "soft"
    p = parse_program([{"kind": "rise", "angle": 90, "law": "double_harmonic"}, {"kind": "dwell", "angle": 270}])
    assert [(e.angle, e.kind) for e in p.impacts(10.0)] == [(90.0, "soft")]


def test_poly_is_the_345_law_when_given_its_coefficients():
    p = custom_law("poly", {"coefficients": [0, 0, 0, 10, -15, 6]})
    for x in (0.0, 0.13, 0.5, 0.77, 1.0):
        assert p.fn1(x) == pytest.approx(LAWS["poly345"].fn1(x), abs=1e-13)
    assert p is custom_law("poly", {"coefficients": [0, 0, 0, 10.0, -15, 6]})     # cached: one law per numbers


def test_spline_is_clamped_C2_and_reproduces_a_cubic():
    t = custom_law("table", {"points": [[x, 3 * x * x - 2 * x ** 3] for x in (0, 0.1, 0.35, 0.6, 0.9, 1)]})
    for x in (0.0, 0.05, 0.2, 0.5, 0.75, 1.0):
        f, v, a = t.fn1(x)
        assert (f, v, a) == pytest.approx((3 * x * x - 2 * x ** 3, 6 * x - 6 * x * x, 6 - 12 * x), abs=1e-13)
    rng = random.Random(7)
    row = _table_row(rng)
    t = custom_law("table", row)
    assert abs(t.fn1(0.0)[1]) < 1e-13 and abs(t.fn1(1.0)[1]) < 1e-13
    for x, _ in row["points"][1:-1]:
        left, right = t.fn1(math.nextafter(x, 0.0)), t.fn1(x)
        assert left == pytest.approx(right, abs=1e-12)
        assert t.fn3(math.nextafter(x, 0.0)) != pytest.approx(t.fn3(x))    # the jerk jumps at the points


@pytest.mark.parametrize("row, message", [
    ({"law": "poly", "coefficients": [0, 1, 1]}, "add up to 2"),
    ({"law": "poly", "coefficients": [0.5, 0.5]}, "c0 = 0.5 must be 0"),
    ({"law": "poly", "coefficients": [0] * (MAX_COEFFICIENTS + 1)}, f"at most {MAX_COEFFICIENTS}"),
    ({"law": "poly", "coefficients": [0, True]}, "must be a finite number"),
    ({"law": "poly", "coefficients": [0, "1"]}, "must be a finite number"),
    ({"law": "poly"}, "needs coefficients"),
    ({"law": "table", "points": [[0, 0], [0.5, 0.4], [0.5, 0.6], [1, 1]]}, "must be greater than"),
    ({"law": "table", "points": [[0, 0], [0.9, 1.2]]}, "x must run from 0 to 1"),
    ({"law": "table", "points": [[0, 0], [1, 2]]}, "f must run from 0 to 1"),
    ({"law": "table", "points": [[0, 0]] * (MAX_POINTS + 1)}, f"2 to {MAX_POINTS} points"),
    ({"law": "table", "points": [[0, 0, 1], [1, 1]]}, "at most 2"),
    ({"law": "cosine", "points": [[0, 0], [1, 1]]}, "only law = \"table\" takes it"),
    ({"law": "modified_cosine"}, "unknown motion law"),
])
def test_bad_laws_are_refused_naming_the_segment(row, message):
    with pytest.raises(NotAMechanism) as exc:
        parse_program([{"kind": "rise", "angle": 180, **row}, {"kind": "return", "angle": 180, "law": "cosine"}])
    assert "program[0]" in str(exc.value) and message in str(exc.value), str(exc.value)


def test_statements_name_the_new_forms():
    from geomcon.worksheet.statements import answer_words, default_template, fill, shown_givens, template_form
    g = {"follower": "flat", "h": 39.5, "rho_allow": 40, "rotation": "ccw",
         "program": [{"kind": "rise", "angle": 180, "law": "poly", "coefficients": [0, 2, -1]},
                     {"kind": "return", "angle": 180, "law": "table", "points": [[0, 0], [0.5, 0.4], [1, 1]]}]}
    assert template_form("cam.base_radius", g) == "flat"
    en, zh = (fill(t, shown_givens("cam.base_radius", g, lang)) for t, lang in zip(default_template("cam.base_radius", g),
                                                                                  ("en", "zh")))
    assert "c = (0, 2, -1)" in en and "(0.5, 0.4)" in en and "40 mm" in en and "{" not in en
    assert "平底" in zh and "40 mm" in zh and "{" not in zh
    # the pressure-angle forms and an arm without ω have statements of their own now (tests/test_recipes_complete.py)
    assert template_form("cam.base_radius", {"h": 20, "alpha_allow": 30}) == "alpha"
    assert template_form("cam.oscillating", {"follower": "roller", "a": 100}) == ""
    t = {"follower": "knife", "r0": 40, "h": 20, "omega": 12.5, "program": []}
    assert "ω = {omega} rad/s" in default_template("cam.translating", t)[0]
    assert answer_words("v", 1, {"at": [30, 60]}, "en") == "the follower's velocity v at δ = 60°"
    assert answer_words("epsilon2", 0, {"at": [30]}, "zh") == "δ = 30° 时的摆杆角加速度 ε2"


@pytest.mark.parametrize("which", ["modified_trapezoid", "modified_sine", "double_harmonic", "poly", "table"])
def test_array_forms_of_the_custom_laws_are_the_scalar_forms_bit_for_bit(which):
    """The handbook, polynomial and table laws' array forms (one numpy pass, used by the searches' grids) give
    the scalar forms' bits at 20001 points, the pieces' ends and just below them."""
    import numpy as np
    from geomcon.cam.custom_laws import custom_law, law
    lw = (custom_law("poly", {"coefficients": [0, 0, 0, 0, 35, -84, 70, -20]}) if which == "poly" else
          custom_law("table", {"points": [[0, 0], [0.2, 0.06], [0.4, 0.33], [0.6, 0.68], [0.8, 0.94], [1, 1]]})
          if which == "table" else law(which))
    ends = [0.0, 0.125, 0.2, 0.375, 0.4, 0.6, 0.625, 0.8, 0.875, 1.0]
    x = np.concatenate([np.linspace(0.0, 1.0, 20001), ends, [math.nextafter(e, 0.0) for e in ends]])
    got = lw.fn(x)
    for i, xi in enumerate(x.tolist()):
        assert tuple(float(g[i]) for g in got) == lw.fn1(xi), xi
