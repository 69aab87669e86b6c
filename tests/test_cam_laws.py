"""Motion laws and programs: end values, derivatives against finite differences, continuity, the impact class
of each law, one-sided values in radians, and the refusal of bad programs with one-line messages."""
from __future__ import annotations

import math

import numpy as np
import pytest

from geomcon.cam.laws import LAW_NAMES, law
from geomcon.cam.program import parse_program
from geomcon.errors import NotAMechanism


@pytest.mark.parametrize("name", LAW_NAMES)
def test_law_end_values_and_derivatives(name):
    lw = law(name)
    f, d1, d2 = lw.derivatives(np.array([0.0, 1.0]))
    assert f.tolist() == [0.0, 1.0]
    x = np.linspace(0.013, 0.987, 77)
    x = x[np.abs(x - 0.5) > 1e-3]          # the parabolic law's f″ jumps at ½
    hstep = 1e-5
    fp, fm = lw.derivatives(x + hstep)[0], lw.derivatives(x - hstep)[0]
    f, d1, d2 = lw.derivatives(x)
    assert np.allclose((fp - fm) / (2 * hstep), d1, atol=1e-8)
    assert np.allclose((fp - 2 * f + fm) / hstep ** 2, d2, atol=2e-4)
    # f and f′ are continuous everywhere inside (also at the parabolic law's middle)
    mid = lw.derivatives(np.array([0.5 - 1e-12, 0.5]))
    assert abs(mid[0][1] - mid[0][0]) < 1e-10 and abs(mid[1][1] - mid[1][0]) < 1e-10


@pytest.mark.parametrize("name, ends, middle", [
    ("uniform", "rigid", False), ("parabolic", "soft", True), ("cosine", "soft", False),
    ("cycloidal", None, False), ("poly345", None, False)])
def test_impacts_per_law(name, ends, middle):
    prog = parse_program([{"kind": "rise", "angle": 120, "law": name}, {"kind": "dwell", "angle": 60},
                          {"kind": "return", "angle": 120, "law": name}, {"kind": "dwell", "angle": 60}])
    assert law(name).impact == (ends or "none")
    got = {(i.angle, i.kind) for i in prog.impacts(16.0)}
    want = set()
    if ends:
        want |= {(a, ends) for a in (0.0, 120.0, 180.0, 300.0)}
    if middle:
        want |= {(60.0, "soft"), (240.0, "soft")}
    assert got == want


def test_seed_001_24_and_aliases():
    prog = parse_program([{"kind": "rise", "angle": 150, "law": "等加速等减速"}, {"kind": "dwell", "angle": 30},
                          {"kind": "return", "angle": 120, "law": "constant_velocity"}, {"kind": "dwell", "angle": 60}])
    s = float(prog.motion(15.0, 100.0)[0])
    assert abs(s - (15 - 2 * 15 * (50 / 150) ** 2)) < 1e-12
    assert [(i.angle, i.kind) for i in prog.impacts(15.0)] == [
        (0.0, "soft"), (75.0, "soft"), (150.0, "soft"), (180.0, "rigid"), (300.0, "rigid")]


def test_radians_are_one_sided_at_segment_ends():
    prog = parse_program([{"kind": "rise", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 240}])
    end = math.radians(120.0)
    before = prog.motion(16.0, np.array([np.nextafter(end, 0.0)]), radians=True)
    at = prog.motion(16.0, np.array([end]), radians=True)
    assert before[1][0] == pytest.approx(16.0 / end) and at[1][0] == 0.0
    assert before[0][0] == pytest.approx(16.0, abs=1e-12) and at[0][0] == 16.0
    d = np.linspace(0, 360, 97)
    for a, b in zip(prog.motion(16.0, d), prog.motion(16.0, np.radians(d), radians=True)):
        assert np.allclose(a, b, rtol=0, atol=1e-12)


@pytest.mark.parametrize("tables, words", [
    ([{"kind": "rise", "angle": 120, "law": "uniform"}, {"kind": "return", "angle": 200, "law": "uniform"}],
     "add up to 320"),
    ([{"kind": "rise", "angle": 120, "law": "nope"}, {"kind": "dwell", "angle": 240}], "unknown motion law"),
    ([{"kind": "lift", "angle": 120}], "kind must be"),
    ([{"kind": "rise", "angle": -5, "law": "uniform"}], "angle must be"),
    ([{"kind": "dwell", "angle": 60, "law": "uniform"}], "a dwell has no law"),
    ([{"kind": "return", "angle": 180, "law": "uniform"}, {"kind": "rise", "angle": 180, "law": "uniform"}],
     "return must follow"),
    ([{"kind": "rise", "angle": 120, "law": "uniform", "speed": 3}], "unknown key"),
])
def test_bad_programs_refused_in_one_line(tables, words):
    with pytest.raises(NotAMechanism) as exc:
        parse_program(tables)
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_peak1_is_the_largest_slope():
    """Law.peak1 bounds |f′| on [0, 1] and is reached (to 1e-9 on a dense grid)."""
    x = np.linspace(0.0, 1.0, 200001)
    for name in LAW_NAMES:
        lw = law(name)
        f1 = np.abs(lw.derivatives(x)[1])
        assert f1.max() <= lw.peak1 and f1.max() >= lw.peak1 - 1e-9
        assert max(abs(lw.fn1(v)[1]) for v in x[::97].tolist()) <= lw.peak1


def test_a_segment_angle_passes_the_checks_every_given_passes():
    """_angle's shortcut for a plain number in range against the full checks (problems.check_number, then
    ≥ MIN_ANGLE): the same angle or the same refusal for every kind of value."""
    from geomcon.cam.program import MIN_ANGLE, _DEG_MAX, _angle
    from geomcon.errors import GeomconError
    from geomcon.problems import RANGES, check_number
    assert _DEG_MAX == RANGES["deg"][1]

    def full(value):
        angle = check_number("deg", value, "p[0].angle")
        if not angle >= MIN_ANGLE:
            raise NotAMechanism(f"p[0].angle must be ≥ {MIN_ANGLE:g}° (degrees of cam rotation), got {angle:g}")
        return angle

    def outcome(fn, value):
        try:
            v = fn(value)
            return ("ok", type(v), v)
        except GeomconError as exc:
            return ("error", type(exc), str(exc))

    values = [0, 1, 360, 3600, 3601, -1, 0.0, -0.0, 1e-7, 1e-6, 0.5e-6, 3600.0, 3600.0000000001, 359.99, 1e300, 10 ** 400,
              True, False, float("nan"), float("inf"), -float("inf"), np.float64(120.0), np.float64(1e5), "120", None]
    values += [float(x) for x in np.random.default_rng(0).uniform(-10, 4000, 200)]
    for v in values:
        if v is None:
            continue
        assert outcome(lambda x: _angle(x, "p[0].angle"), v) == outcome(full, v), v
