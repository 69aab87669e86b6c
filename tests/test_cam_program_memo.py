"""parse_program keeps the Program of tables it has parsed: the same content gives the same object, any
difference that could parse differently (a value's type included) gives its own, and a refused program is
refused every time."""
from __future__ import annotations

import copy

import pytest

from geomcon.cam.program import _parse_program, parse_program
from geomcon.errors import GeomconError

SPEC = [{"kind": "rise", "angle": 120, "law": "poly345"}, {"kind": "dwell", "angle": 60},
        {"kind": "return", "angle": 120, "law": "cycloidal"}, {"kind": "dwell", "angle": 60}]


def test_the_same_content_is_parsed_once():
    first = parse_program(SPEC)
    assert parse_program(copy.deepcopy(SPEC)) is first
    assert first == _parse_program(SPEC, "program")


@pytest.mark.parametrize("change", [
    {"angle": 120.0},                       # equal to 120 but a float
    {"law": "cosine"},
    {"law": "cycloidal"},
    {"law": "poly", "coefficients": [0, 0, 0, 10, -15, 6]},
])
def test_another_content_is_its_own_program(change):
    other = [dict(SPEC[0], **change)] + SPEC[1:]
    assert parse_program(other) is not parse_program(SPEC)
    assert parse_program(other) == _parse_program(other, "program")


def test_a_refused_program_is_refused_every_time():
    bad = [dict(SPEC[0], angle=True)] + SPEC[1:]         # True == 1, but not an angle
    for _ in range(2):
        with pytest.raises(GeomconError):
            parse_program(bad)
    with pytest.raises(GeomconError):
        _parse_program(bad, "program")
    bad = [dict(SPEC[0], law="nope")] + SPEC[1:]
    for _ in range(2):
        with pytest.raises(GeomconError, match="nope"):
            parse_program(bad)


def test_unhashable_values_are_parsed_every_time():
    odd = [dict(SPEC[0], angle=bytearray(b"1"))] + SPEC[1:]
    with pytest.raises(GeomconError):
        parse_program(odd)
