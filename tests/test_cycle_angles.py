"""Issue 11 review: an angle of a cycle is stated as a textbook states it, in [0°, 360°).

100-06 printed β = −171.561° for the angle measured counter-clockwise from the pointer DE to DC (188.439°), and
001-26 and 001-29 (cw) printed δ(α′max) = 360° for the return's end, where the textbook says 0° (the start of the
next rise). Every cam angle and every β of every bundled problem now lies in [0°, 360°), the construction and
its analytic twin alike."""
from __future__ import annotations

import copy
import math
import random
import tomllib
from pathlib import Path

import pytest

from geomcon.numeric import deg360
from geomcon.problems import load_problem, problem_from_dict
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"
CYCLE = ("delta_alpha_max_rise", "delta_alpha_max_return", "beta")


def test_deg360_states_a_cycle_angle_in_its_usual_range():
    assert deg360(-171.561) == pytest.approx(188.439, abs=1e-12)
    assert deg360(360.0) == 0.0 and deg360(-1e-17) == 0.0 and deg360(360.0 - 1e-12) == 0.0
    assert deg360(725.0) == 5.0 and deg360(359.5) == 359.5 and deg360(0.0) == 0.0
    rng = random.Random(11)
    for _ in range(2000):
        x = rng.uniform(-1e4, 1e4)
        y = deg360(x)
        assert 0.0 <= y < 360.0 and math.isclose(math.cos(math.radians(y)), math.cos(math.radians(x)), abs_tol=1e-9)


def test_the_log_function_generator_states_beta_counter_clockwise_from_the_pointer():
    sol = solve(load_problem(PROBLEMS / "100-06_four_bar_function_log.toml"))
    assert sol.ok
    assert sol.answers["beta"] == pytest.approx(188.439446731, abs=1e-6)


@pytest.mark.parametrize("name", ["001-26_eccentric_knife_offset", "001-29_eccentric_roller_offset_cw"])
def test_an_eccentric_cam_s_return_ends_at_0_degrees_not_360(name):
    sol = solve(load_problem(PROBLEMS / f"{name}.toml"))
    assert sol.ok
    assert sol.answers["delta_alpha_max_return"] == 0.0


@pytest.mark.parametrize("path", sorted(PROBLEMS.glob("*.toml")), ids=lambda p: p.stem)
def test_every_cycle_angle_of_a_bundled_problem_lies_in_0_to_360(path):
    sol = solve(load_problem(path))
    for k in CYCLE:
        if k in sol.answers:
            assert 0.0 <= sol.answers[k] < 360.0 - 1e-9, (k, sol.answers[k])


ENDS_THE_TURN = [{"kind": "rise", "angle": 180, "law": "uniform"}, {"kind": "return", "angle": 180, "law": "uniform"}]


def _mutated(name: str, **given):
    data = copy.deepcopy(tomllib.loads((PROBLEMS / name).read_text(encoding="utf-8")))
    data["given"].update(given)
    return problem_from_dict(data, name="t")


def test_a_translating_return_that_ends_the_turn_puts_its_worst_place_at_0_degrees():
    """A uniform return ending at 360° has its largest α at its end (α = s′/(r0 + s) grows as s falls): that place
    is 0°, the twin agreeing (it printed δ(α′max) = 360.000° from 359.99999999999994)."""
    sol = solve(_mutated("001-23a_cam_knife_uniform.toml", program=ENDS_THE_TURN))
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    assert sol.answers["delta_alpha_max_return"] == 0.0 and sol.answers["delta_alpha_max_rise"] == 0.0


@pytest.mark.parametrize("name", ["200-05_oscillating_roller_cam.toml", "200-07_oscillating_flat_face.toml"])
def test_an_arm_cam_whose_return_ends_the_turn_states_its_places_in_0_to_360(name):
    sol = solve(_mutated(name, program=ENDS_THE_TURN))
    assert sol.ok, [c for c in sol.checks if not c["ok"]]
    for k in CYCLE:
        if k in sol.answers:
            assert 0.0 <= sol.answers[k] < 360.0 - 1e-9, (k, sol.answers[k])
