"""An angle written through another turn (± 360°) is named ``turn`` and earns half (100-06's β = 188.439°,
counter-clockwise from DE, written as −171.561°: the same direction, not the convention the answer states)."""
from __future__ import annotations

import json

from geomcon.grading.credit import PARTIAL
from geomcon.grading.diagnosis import match, prepare
from geomcon.grading.keyfile import key_from_json

THETA = 26.4098557731


def _prepared():
    key = key_from_json(json.dumps({"students": [{"id": "1", "exercises": [{"n": 1, "recipe": "crank_rocker.extremes",
        "given": {"AB": 25, "BC": 85, "CD": 70, "AD": 70},
        "answers": {"theta": {"value": THETA, "tol": 0.88, "points": 2}}}]}]}))
    return prepare(key.students["1"].exercises[0])


def test_an_angle_one_turn_off_is_named_turn_either_way():
    alts = _prepared().alts["1.theta"]
    assert match(alts, THETA - 360.0 + 0.5).code == "turn"
    assert match(alts, THETA + 360.0 - 0.5).code == "turn"
    assert match(alts, THETA - 360.0 + 2.0) is None or match(alts, THETA - 360.0 + 2.0).code != "turn"


def test_a_turn_earns_half_as_a_reading_slip():
    assert PARTIAL["turn"] == 0.5
