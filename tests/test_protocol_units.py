"""Every value the construction protocol measures carries its unit, as the Results print it (issue 11,
hsmall11m): 400-01 step 16 printed "Measure vC = pc·μv = 269.795" (Results: "vC = 269.795 mm/s"); every
velocity, acceleration, angular velocity and angular acceleration step of 000-03, 400-01…03 and 001-31b printed
its number bare, and the eccentric cams' v (001-27, 001-27b, 001-30, 001-30b) was a step without a unit although
its answer is in mm/s. Only a ratio prints bare (:data:`RATIOS`): a new bare value fails here."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from geomcon.recipes import get_recipe
from geomcon.render.protocol import format_value, value_reserve, VALUE_RESERVE
from geomcon.render.results import unit_text

GALLERY = Path(__file__).resolve().parents[1] / "gallery"

RATIOS = {
    "K": "the advance-to-return time ratio, (180° + θ)/(180° − θ) or φslow/φquick",
    "scale": "004-03: the design's scale AD/A*D",
    "w3_w1": "400-04: ω3/ω1",
    "w2_w1": "400-04, 400-05: ω2/ω1",
    "i13": "400-04: the transmission ratio ω1/ω3",
}
"""The measured steps whose value is a ratio and prints without a unit, with what each is."""

VALUE = re.compile(r'<tspan class="value"[^>]*>([^<]*)</tspan>')
NUMBER = re.compile(r"^ ?= ([−-]?\d+\.\d{3})(.*)$")


def _stem(path: Path) -> str:
    return re.sub(r"-\d+$", "", path.stem)


def _sheets() -> list[Path]:
    return [p for p in sorted(GALLERY.glob("*.svg")) if (GALLERY / f"{_stem(p)}.json").exists()]


def _values(path: Path) -> list[tuple[str, str, str]]:
    """(step key, number, unit as printed) of every measured value the sheet's protocol prints."""
    out = []
    for key, body in re.findall(r'<g class="proto[^"]*" data-step="\d+" id="proto-([^"]+)">(.*?)</g>', path.read_text(
            encoding="utf-8"), flags=re.S):
        for v in VALUE.findall(body):
            m = NUMBER.match(v)
            assert m, f"{path.name} {key}: {v!r} is no measured number"
            out.append((key, m.group(1), m.group(2)))
    return out


def test_the_review_s_value_prints_its_unit():
    assert ("vC", "269.795", " mm/s") in _values(GALLERY / "400-01_four_bar_velocity_polygons-2.svg")
    assert ("v", "500.000", " mm/s") in _values(GALLERY / "001-27_eccentric_roller_offset-2.svg")


def test_format_value_prints_every_unit():
    assert format_value(-3.3514, "rad/s") == " = -3.351 rad/s"
    assert format_value(2026.2554, "mm/s²") == " = 2026.255 mm/s²"
    assert format_value(12.50559, "deg") == " = 12.506°" and format_value(1.149325, "") == " = 1.149"


def test_a_long_unit_keeps_room_for_its_value():
    assert value_reserve("mm") == value_reserve("deg") == VALUE_RESERVE
    assert value_reserve("rad/s²") > VALUE_RESERVE


@pytest.mark.parametrize("path", _sheets(), ids=lambda p: p.stem)
def test_every_measured_value_in_a_protocol_has_its_unit(path: Path):
    recipe = json.loads((GALLERY / f"{_stem(path)}.json").read_text(encoding="utf-8"))["recipe"]
    units = {q.name: unit_text(q.unit) for q in get_recipe(recipe).answers}
    for key, number, unit in _values(path):
        if key in units:                                  # an answer: the unit its Results line prints
            assert unit == units[key], f"{path.name} step {key} = {number}{unit!r}: the answer is in {units[key]!r}"
        else:
            assert unit or key in RATIOS, f"{path.name} step {key} = {number} prints no unit"


def test_the_bare_values_are_the_ratios_listed():
    bare = {key for p in _sheets() for key, _, unit in _values(p) if not unit}
    assert bare == set(RATIOS)
