"""A designed offset reads the same on the drawing and in the Results (hlook11m's review, 200-11): the Results
printed "e = −5.657 mm" under a dimension "e=5.66", the side only in the Chinese sign rule. Now the dimension is
signed as the recipe defines e (> 0: the follower's axis right of O) and the Results line says the side in words,
in English and in Chinese."""
from __future__ import annotations

import json
import re

import pytest

from cam_sheets import GALLERY, text


def texts(stem: str) -> list[str]:
    """Each <text> of sheet 1 of ``stem`` without its markup, U+2212 read as a hyphen."""
    svg = (GALLERY / f"{stem}.svg").read_text(encoding="utf-8").replace("\u2212", "-")
    return [re.sub(r"<[^>]*>", "", t) for t in re.findall(r"<text\b[^>]*>(.*?)</text>", svg, re.S)]

STEMS = sorted(p.stem for p in GALLERY.glob("*.json")
               if json.loads(p.read_text(encoding="utf-8")).get("recipe") == "cam.base_radius"
               and json.loads(p.read_text(encoding="utf-8")).get("answers", {}).get("e"))


def test_a_left_offset_is_among_them():
    assert "200-11_base_radius_rise_and_return" in STEMS
    assert json.loads((GALLERY / "200-11_base_radius_rise_and_return.json").read_text())["answers"]["e"] < 0


@pytest.mark.parametrize("stem", STEMS)
def test_dimension_and_results_agree_on_the_offset_and_name_its_side(stem):
    e = json.loads((GALLERY / f"{stem}.json").read_text(encoding="utf-8"))["answers"]["e"]
    (dim,) = [m[1] for t in texts(stem) if (m := re.fullmatch(r"e=(-?\d+\.\d\d)", t))]
    sheet = text(GALLERY / f"{stem}.svg").replace("\u2212", "-")
    (line,) = re.findall(r"e = (-?\d+\.\d{3}) mm, axis (left|right) of O \(= analytic\)\s*偏距（导路在 O (左|右)侧）",
                         sheet)
    assert float(dim) == pytest.approx(e, abs=0.005) and float(line[0]) == pytest.approx(e, abs=0.0005)
    assert line[1:] == (("left", "左") if e < 0 else ("right", "右"))
