"""The cam recipes' new declared mistakes diagnosed when grading (issue 14 on issue 13's contract). The wrong
values are computed here from the laws' closed forms, independently of the scene replays that diagnose them:
Khurmi's valve cam (200-13, cosine rise 50 mm over 120°, return over 60°, 100 rpm) with a = ω·s″, with the
rise's maxima only, with 100 rpm taken as 100 rad/s; GATE 2020 (200-18) with r0 = 40 + (−8) = 32 mm; and the
base circle of the pressure angle alone for 200-19."""
from __future__ import annotations

import math

from geomcon.grading import grade
from geomcon.grading.answers import read_answers
from geomcon.grading.keyfile import key_from_problem
from geomcon.grading.tables import grades_data
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = __import__("pathlib").Path(__file__).resolve().parents[1]


def _graded(problem: str, header: list[str], rows: list[list[float]]) -> list[dict]:
    key = key_from_problem(ROOT / "problems" / problem)
    text = ",".join(["id"] + header) + "\n" + "".join(
        ",".join([str(i + 1)] + [repr(v) for v in r]) + "\n" for i, r in enumerate(rows))
    return [row["answers"] for row in grades_data(grade(key, read_answers(text.encode())))["rows"]]


def test_valve_cam_speed_mistakes():
    w, h = 100 * 2 * math.pi / 60, 50.0
    rise, ret = math.radians(120), math.radians(60)
    a_max = math.pi ** 2 / 2 * h / ret ** 2 * w ** 2                # the return's start: the cycle's largest
    v_rise, a_rise = math.pi / 2 * h / rise * w, math.pi ** 2 / 2 * h / rise ** 2 * w ** 2
    v_max = math.pi / 2 * h / ret * w
    rpm = 100.0
    got = _graded("200-13_cam_valve_speeds.toml", ["v_max", "a_max"],
                  [[v_max, a_max], [v_max, a_max / w], [v_rise, a_rise], [v_max * rpm / w, a_max * (rpm / w) ** 2]])
    assert [g["a_max"]["verdict"] for g in got] == ["correct", "wrong", "wrong", "wrong"]
    assert got[1]["a_max"]["diagnosis"] == "omega_not_squared"
    assert got[2]["v_max"]["diagnosis"] == got[2]["a_max"]["diagnosis"] == "rise_only"
    assert got[3]["v_max"]["diagnosis"] == "rpm_as_rad_s"


def test_gate_flat_face_sign_mistake():
    got = _graded("200-18_base_radius_flat_gate2020.toml", ["r0"], [[48.0], [32.0]])
    assert got[0]["r0"]["verdict"] == "correct"
    assert (got[1]["r0"]["verdict"], got[1]["r0"]["diagnosis"]) == ("wrong", "floor_sign")


def test_base_circle_of_the_pressure_angle_alone():
    ans = solve(load_problem(ROOT / "problems/200-19_base_radius_alpha_and_rho.toml")).answers
    got = _graded("200-19_base_radius_alpha_and_rho.toml", ["r0"], [[ans["r0_alpha"]]])
    assert (got[0]["r0"]["verdict"], got[0]["r0"]["diagnosis"]) == ("wrong", "alpha_limit_only")
