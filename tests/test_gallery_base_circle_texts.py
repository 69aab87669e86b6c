"""Which label or angle value of a cam figure sits across its base circle (issue 11, hsmall11m): 200-06's α′max
value lies across the base circle (its arc was moved clear of it the session before, the text was not), and reads as
part of it. Ten sheet-1 figures do so, each listed in :data:`KNOWN` with what was tried; a new one fails here, and
a listed one that comes clear must leave the list. Read off every sheet-1 SVG of the gallery that draws a base
circle, with the text boxes of :mod:`test_gallery_text_across`.

Tried (not kept): weighing a text's crossing of the base circle (a style of its own) more in the placer
(``figure._weight``): at 1.5 no text moves; at 1.75 and 1.9 200-05's value leaves the circle for O's ground (the
defect test_gallery_text_across guards); at 2 200-06 comes clear (under O's ground, 3 mm from its arc) but 200-05
goes onto O's ground and 200-16's s=10.00 onto its pitch curve; at 3 the slotter cams' value goes 12 mm off with a
leader across the profile and the pitch curve. A weight is no fix: the place beside the arc is crowded on every side.
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely

from test_gallery_text_across import NS, text_box

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
_BASE = re.compile(r'id="step-base_circle"><circle class="ink" cx="([-\d.]+)" cy="([-\d.]+)"[^>]* r="([-\d.]+)"')

_TRIED = "; raising the base circle's crossing weight moved it onto O's ground or far off (see the module)"
KNOWN: dict[str, str] = {
    **{f"000-0{k}_{name}": "α′max=82.12°: its arc lies among the return's pitch points, the value beside it across "
       "the base circle" + _TRIED
       for k, name in ((4, "slotter_cam_psi0"), (5, "slotter_cam_motion_law"), (6, "slotter_cam_pitch_points"),
                       (7, "slotter_cam_actual_profile"), (8, "slotter_cam_pressure_angle"))},
    "200-05_oscillating_roller_cam": "α′max=40.12°: its '°' on the base circle under O's ground" + _TRIED,
    "200-06_oscillating_knife_same_sense": "α′max=30.15°: below its arc with a leader, across the base circle "
                                           "(the review's)" + _TRIED,
    "001-24_cam_displacement_at_100": "αmax=13.56° (on its portrait sheet at 1:1; B(100°) crossed it at 1:2 on "
                                      "landscape): inside the base circle by its contact point B1*, not examined "
                                      "further",
    "200-14_oscillating_arm_speeds": "α′max=33.23°: not examined further (issue 11, hsmall11m ran out of time)",
}
"""Figures whose text still crosses the base circle, with why it stays."""


def _sheets() -> list[Path]:
    return [p for p in sorted(GALLERY.glob("*.svg")) if _BASE.search(p.read_text(encoding="utf-8"))]


def crossing(svg: str) -> list[str]:
    """The labels and mark values whose boxes cross the figure's base circle."""
    cx, cy, r = map(float, _BASE.search(svg).groups())
    ring = shapely.Point(cx, cy).buffer(r, 256).exterior
    return ["".join(el.itertext()) for el in ET.fromstring(svg).iter(f"{NS}text")
            if (el.get("class") or "").split()[:1] in (["label"], ["mark-text"]) and text_box(el).intersects(ring)]


def test_the_rule_reads_the_cams():
    assert len(_sheets()) >= 20 and "200-06_oscillating_knife_same_sense" in {p.stem for p in _sheets()}


@pytest.mark.parametrize("path", _sheets(), ids=lambda p: p.stem)
def test_no_text_sits_across_the_base_circle(path: Path):
    found = crossing(path.read_text(encoding="utf-8"))
    if path.stem in KNOWN:
        assert found, f"{path.stem} is clear now: take it off KNOWN"
    else:
        assert not found, f"{path.stem}: {found} across the base circle"
