"""The rise and return angles an eccentric cam's problem asks are marked at O (hlook11m's review: 001-29 asked
δ0 and δ0′ and printed them, but its figure marked neither). They are marked on the sheet of the lowest position
(no state given), inside the offset circle, δ0 from K0 to K1 against ω, δ0′ back: one of them is a reflex angle,
whose arc turns the long way round (:func:`geomcon.render.symbols.sweep`)."""
from __future__ import annotations

import json
import math
import re

import pytest

from cam_sheets import GALLERY
from geomcon.geometry.primitives import Point
from geomcon.scene.marks import AngleMark
from geomcon.render.symbols import sweep


def texts(stem: str) -> list[str]:
    """Each <text> of sheet 1 of ``stem`` without its markup."""
    svg = (GALLERY / f"{stem}.svg").read_text(encoding="utf-8")
    return [re.sub(r"<[^>]*>", "", t) for t in re.findall(r"<text\b[^>]*>(.*?)</text>", svg, re.S)]


@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_001_29_marks_the_rise_and_return_angles_it_asks(sense):
    stem = f"001-29_eccentric_roller_offset_{sense}"
    ans = json.loads((GALLERY / f"{stem}.json").read_text(encoding="utf-8"))["answers"]
    shown = texts(stem)
    assert f"δ0={ans['rise_angle']:.2f}°" in shown and f"δ0′={ans['return_angle']:.2f}°" in shown, shown


@pytest.mark.parametrize("stem", ["001-26_eccentric_knife_offset", "001-27_eccentric_roller_offset"])
def test_a_sheet_of_a_given_position_does_not_mark_them(stem):
    assert not [t for t in texts(stem) if re.match(r"δ0′?=\d", t)]


def test_a_reflex_value_turns_the_long_way():
    o, a, b = Point(0, 0), Point(1, 0), Point(0, 1)
    assert math.degrees(sweep(AngleMark(o, a, b, "δ0", 270.0), a, b)) == pytest.approx(-270.0)
    assert math.degrees(sweep(AngleMark(o, b, a, "δ0′", 90.0), b, a)) == pytest.approx(-90.0)
    assert math.degrees(sweep(AngleMark(o, a, b, "θ", 90.0), a, b)) == pytest.approx(90.0)
