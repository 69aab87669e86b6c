"""An oscillating follower's pressure-angle arc keeps off the base circle (issue 11, hcam11k): 200-06's α′max arc ran
nearly tangent to it, 0.2 mm inside at one end and 1.4 mm outside at the other, so that the two read as one curve.
Read off the sheet-1 SVGs of cam.oscillating: every arc of a pressure-angle mark stays :data:`GAP` mm of paper off
the base circle all along."""
from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
GAP = 2.0
"""Least paper mm between a pressure-angle arc and the base circle: the recipe keeps 0.05·L of model off it (2 mm
on paper at 1:2, 200-06's scale) where the renderer's arc would run nearer; 200-06 before the fix ran 0.2 mm inside,
the slotter's feed cam (000-04…08, at 1:2.5, the renderer's arc shrunk off a point to 0.45 of its ray) 1.99 mm off
(the test allowed 1.9 mm; now drawn at 0.4 of its ray, 2.83 mm off)."""

_ARC = re.compile(r'd="M([-\d.]+) ([-\d.]+)A([-\d.]+) ([-\d.]+) 0 (\d) (\d) ([-\d.]+) ([-\d.]+)"')
_BASE = re.compile(r'id="step-base_circle"><circle class="ink" cx="([-\d.]+)" cy="([-\d.]+)"[^>]* r="([-\d.]+)"')


def _oscillating() -> list[str]:
    out = []
    for p in sorted((ROOT / "problems").glob("*.toml")):
        d = tomllib.loads(p.read_text(encoding="utf-8"))
        if d["recipe"] == "cam.oscillating" and d["given"].get("follower") != "flat" \
                and (GALLERY / f"{p.stem}.svg").exists():
            out.append(p.stem)
    return out


def _arc_points(x1, y1, r, large, sweep, x2, y2, n=33):
    """Points along an SVG arc (circular, no rotation) from its endpoint form."""
    mx, my = (x1 - x2) / 2, (y1 - y2) / 2
    d2 = mx * mx + my * my
    k = math.sqrt(max(r * r / d2 - 1.0, 0.0)) * (-1 if large == sweep else 1)
    cx, cy = (x1 + x2) / 2 + k * my, (y1 + y2) / 2 - k * mx
    a1, a2 = math.atan2(y1 - cy, x1 - cx), math.atan2(y2 - cy, x2 - cx)
    d = a2 - a1
    if sweep and d < 0:
        d += 2 * math.pi
    if not sweep and d > 0:
        d -= 2 * math.pi
    return [(cx + r * math.cos(a1 + d * i / (n - 1)), cy + r * math.sin(a1 + d * i / (n - 1))) for i in range(n)]


FIGURES = _oscillating()


@pytest.mark.parametrize("stem", FIGURES)
def test_a_pressure_angle_arc_keeps_off_the_base_circle(stem: str):
    svg = (GALLERY / f"{stem}.svg").read_text(encoding="utf-8")
    cx, cy, r0 = map(float, _BASE.search(svg).groups())
    for part in ("rise", "return"):
        i = svg.find(f'id="step-mark_alpha_{part}"')
        assert i >= 0, (stem, part)
        m = _ARC.search(svg, i, svg.find("</g>", i))
        x1, y1, r, _, large, sweep, x2, y2 = (float(v) for v in m.groups())
        gap = min(abs(math.hypot(x - cx, y - cy) - r0) for x, y in _arc_points(x1, y1, r, int(large), int(sweep), x2, y2))
        assert gap >= GAP, f"{stem}: the {part}'s α arc runs {gap:.2f} mm from the base circle"


def test_200_06_is_among_them():
    assert "200-06_oscillating_knife_same_sense" in FIGURES and "200-05_oscillating_roller_cam" in FIGURES
