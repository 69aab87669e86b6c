"""Issue 11: the s–v–a sheets of the motion laws (``gallery/law_*.svg``) were titled in lowercase ("cosine law
余弦加速度（简谐）运动规律, impact: soft") and their title block's problem read "h = 20 mm, 90° each". They are
headed as a textbook heads a law's diagrams, in English and Chinese, the follower's motion stated in words."""
from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SVG = "{http://www.w3.org/2000/svg}"


def _title_lines(svg: str) -> list[str]:
    root = ET.fromstring(svg)
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text") if "tb-0-0" in (t.get("class") or "").split()]


LAW_TITLES = {"uniform": "Uniform velocity motion law", "cosine": "Cosine acceleration (simple harmonic) motion law",
              "cycloidal": "Sine acceleration (cycloidal) motion law", "poly345": "3-4-5 polynomial motion law"}


@pytest.mark.parametrize("name", sorted(p.stem.removeprefix("law_") for p in GALLERY.glob("law_*.svg")))
def test_a_law_sheet_is_headed_as_a_textbook_heads_it(name):
    svg = (GALLERY / f"law_{name}.svg").read_text(encoding="utf-8")
    en, zh = _title_lines(svg)
    assert not en[0].islower() and en.endswith(" motion law") and "impact" not in en, en
    assert LAW_TITLES.get(name, en) == en
    assert zh.endswith("运动规律") and "(" not in zh and ")" not in zh, zh          # full-width brackets
    texts = ["".join(t.itertext()) for t in ET.fromstring(svg).iter(f"{SVG}text")]
    assert "Follower motion: rise h = 20 mm over 90°, dwell 90°, return over 90°, dwell 90°" in texts
    assert "从动件运动：推程运动角 90°，升程 h = 20 mm；远休止角 90°；回程运动角 90°；近休止角 90°" in texts
    assert not any("each" in t for t in texts), [t for t in texts if "each" in t]          # "h = 20 mm, 90° each"


