"""Regressions of the 10 000-case hostile fuzz for the cams (mutations of the bundled problems): numbers inside
a program's rows checked like givens, tiny allowed pressure angles of cam.base_radius, a spurious α′ root of a
knife cam whose stroke is far below its base circle, and the eccentric cam at a huge radius."""
from __future__ import annotations

import copy
import math
import tomllib
import warnings
from pathlib import Path

import pytest

from geomcon.errors import GeomconError
from geomcon.problems import problem_from_dict
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"


def _mutated(name: str, **given):
    data = copy.deepcopy(tomllib.loads((PROBLEMS / name).read_text(encoding="utf-8")))
    data["given"].update(given)
    return problem_from_dict(data, name="t")


def _solved(name: str, **given):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sol = solve(_mutated(name, **given))
        assert sol.ok, [c for c in sol.checks if not c["ok"]]
        return sol.answers


def _refusal(name: str, program=None, **given) -> str:
    if program is not None:
        given["program"] = program
    with pytest.raises(GeomconError) as err:
        solve(_mutated(name, **given)).answers
    assert "\n" not in str(err.value)
    return str(err.value)


COSINE = "001-23c_cam_knife_cosine.toml"


@pytest.mark.parametrize("angle, words", [
    (2 ** 1100, ["program[0].angle", "out of range"]),               # beyond float: OverflowError before
    (2 ** 200, ["program[0].angle", "3600"]),                          # a float, but no angle
    (float("nan"), ["program[0].angle", "finite"]),
    (-5, ["program[0].angle", "≥ 1e-06"]),
    (1e-12, ["program[0].angle", "≥ 1e-06"]),                          # a rise lost in the turn's tolerance
    ("120", ["program[0].angle", "number"]),
    (True, ["program[0].angle", "number"]),
])
def test_program_angles_are_checked_like_givens(angle, words):
    prog = [{"kind": "rise", "angle": angle, "law": "cosine"}, {"kind": "dwell", "angle": 60},
            {"kind": "return", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60}]
    msg = _refusal(COSINE, program=prog)
    assert all(w in msg for w in words), msg


def test_a_segment_of_a_millionth_degree_still_solves():
    prog = [{"kind": "rise", "angle": 1e-6, "law": "cosine"}, {"kind": "dwell", "angle": 180},
            {"kind": "return", "angle": 180 - 1e-6, "law": "cosine"}]
    ans = _solved(COSINE, program=prog, at=[0, 10])
    assert ans["s"][1] == pytest.approx(16.0, rel=1e-12)


RISE_RETURN = "200-11_base_radius_rise_and_return.toml"


@pytest.mark.parametrize("key", ["alpha_allow", "alpha_allow_return"])
def test_base_radius_refuses_pressure_angles_below_its_minimum(key):
    msg = _refusal(RISE_RETURN, **{key: 1e-15})          # min() of an empty list for the return before
    assert key in msg and "1e-6" in msg, msg


@pytest.mark.parametrize("h", [1e-6, 30.0, 1e9])
def test_base_radius_refuses_a_base_circle_beyond_the_length_span(h):
    """A return over 0.001° at α ≤ 1e-5°: s′ spreads over 1.9·h/1.7e-5 rad, r0 ≥ 3e11·h."""
    prog = [{"kind": "rise", "angle": 150, "law": "cosine"}, {"kind": "dwell", "angle": 210 - 1e-3},
            {"kind": "return", "angle": 1e-3, "law": "poly345"}]
    msg = _refusal(RISE_RETURN, h=h, program=prog, alpha_allow_return=1e-5)
    assert "alpha_allow_return = 1e-05°" in msg and "1e10·h" in msg, msg
    _solved(RISE_RETURN, h=h, program=prog, alpha_allow_return=1.0)    # r0 ≈ 6e6·h: within the span


UNIFORM_BOTH = [{"kind": "rise", "angle": 150, "law": "uniform"}, {"kind": "dwell", "angle": 30},
                {"kind": "return", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 60}]


@pytest.mark.parametrize("h", [1e-6, 1.0, 1000.0, 1e9])
def test_base_radius_at_the_smallest_pressure_angle_against_its_closed_form(h):
    """Uniform rise and return, cw cam: the rise binds at δ = 0 (s = 0, s′ = vr), the return at its end (s = 0,
    s′ = vt), so O meets both wedges: s0 = (vr − vt)/(tan α_rise + tan α_return). The twin read s0 off the
    steep rise constraint, whose value carries ε·|e|/tan(1e-6°): 5e-9 off."""
    ans = _solved(RISE_RETURN, h=h, program=UNIFORM_BOTH, alpha_allow=1e-6)
    vr, vt = h / math.radians(150), -h / math.radians(120)
    s0 = (vr - vt) / (math.tan(math.radians(1e-6)) + math.tan(math.radians(70)))
    assert ans["s0"] == pytest.approx(s0, rel=1e-12)


UNIFORM_KNIFE = "001-23a_cam_knife_uniform.toml"


@pytest.mark.parametrize("r0", [30.0, 300.0, 1e4])
def test_knife_with_a_stroke_far_below_its_base_circle_finds_alpha_max_at_the_return_end(r0):
    """h = 1e-6 mm: α′ ~ (s′/r0)² ~ 1e-16 lies below the rounding of κ|P′| − ω (both ≈ 1); the slope is the
    tangent's turn relative to the follower's frame. Uniform law: α = s′/(r0 + s) grows as s falls, so the
    largest α of the return is at its end (300°) and of the rise at its start."""
    ans = _solved(UNIFORM_KNIFE, h=1e-6, r0=r0)
    assert ans["delta_alpha_max_return"] == pytest.approx(300.0, abs=1e-9)
    assert ans["delta_alpha_max_rise"] == 0.0


@pytest.mark.parametrize("law", ["cosine", "cycloidal", "parabolic"])
def test_alpha_max_place_of_a_tiny_stroke_agrees_with_the_twin(law):
    prog = [{"kind": "rise", "angle": 120, "law": law}, {"kind": "dwell", "angle": 60},
            {"kind": "return", "angle": 120, "law": law}, {"kind": "dwell", "angle": 60}]
    ans = _solved(UNIFORM_KNIFE, h=1e-6, r0=1e4, program=prog)         # 2.5e-6° apart before
    assert 0.0 < ans["delta_alpha_max_rise"] < 120.0 and 180.0 < ans["delta_alpha_max_return"] < 300.0


ECCENTRIC = "001-26_eccentric_knife_offset.toml"


@pytest.mark.parametrize("R, e", [(1e9, -10.0), (1e9, 10.0), (3e8, -1.0), (1e9, 300.0)])
def test_eccentric_cam_at_a_huge_radius_measures_delta_from_an_exact_tangent_point(R, e):
    """OA = 10, the state A_angle = 0: δ is the turn of O→A from its lowest position, atan2(−√(r0² − e²), −e).
    K0, the follower's foot at its lowest position, was the Thales circle on OB0 (radius 5e8) meeting the
    offset circle (radius 10): turned by ε·5e8/10, δ 2.3e-7° off."""
    ans = _solved(ECCENTRIC, R=R, e=e)
    r0 = R - 10.0
    y_low = math.sqrt((r0 - e) * (r0 + e))
    phi_low = math.atan2(-y_low, -e)                       # O→A at the lowest position (ccw cam)
    delta = math.degrees(0.0 - phi_low) % 360.0            # the state A_angle = 0
    assert ans["delta"] == pytest.approx(delta, abs=1e-11)
