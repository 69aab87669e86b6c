"""An offset on the wrong side is warned of (hlook11m's review, 001-26): the Results answered "offset on the
correct side: no" and no Warnings block said it is a design fault. Every eccentric cam whose offset lies on the
wrong side for its sense (逆转右偏，顺转左偏) now carries the warning, and its sheet prints it in both languages."""
from __future__ import annotations

import json

import pytest

from cam_sheets import GALLERY, text

ECCENTRIC = sorted(p.stem for p in GALLERY.glob("*.json")
                   if json.loads(p.read_text(encoding="utf-8")).get("recipe") == "cam.eccentric")


def _wrong(stem: str) -> tuple[bool | None, list[str]]:
    d = json.loads((GALLERY / f"{stem}.json").read_text(encoding="utf-8"))
    return d["answers"].get("offset_correct"), [w for w in d["warnings"] if w.startswith("offset on the wrong side")]


def test_the_review_s_case_and_the_cw_cam_of_001_29_are_among_the_wrong_ones():
    assert {s for s in ECCENTRIC if _wrong(s)[0] is False} >= {"001-26_eccentric_knife_offset",
                                                              "001-29_eccentric_roller_offset_cw"}


@pytest.mark.parametrize("stem", ECCENTRIC)
def test_a_wrong_offset_and_only_it_is_warned_of(stem):
    correct, warned = _wrong(stem)
    assert len(warned) == (correct is False), (stem, correct, warned)


def test_001_26_prints_the_warning_in_both_languages():
    sheet = text(GALLERY / "001-26_eccentric_knife_offset.svg")
    assert "Warnings" in sheet and "offset on the wrong side" in sheet.replace("\n", " ")
    assert "偏置方位错误" in sheet and "应逆转右偏、顺转左偏" in sheet
