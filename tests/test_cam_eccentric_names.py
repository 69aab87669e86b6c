"""The eccentric cam's protocol calls each point by the label its sheet prints (issue 11, a class replays the
steps against the drawing). hsheet11k's player review found 001-25 captioning the farthest point "B1" where
the sheet labels it C (the statement's name), the contact point "B" where the sheet labels it D, and a
"foot D of the follower's axis" at O for a centred follower: two points called D."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]


def _captions_and_labels(stem: str) -> tuple[str, set[str]]:
    sc = solve(load_problem(ROOT / "problems" / f"{stem}.toml")).drawing_scene
    groups = sc.frames()
    text = "\n".join(sc.caption(g[0].key)[0] for g in groups)
    labels = {s.label for g in groups for s in g if s.label}
    return text, labels


@pytest.mark.parametrize("stem, far, contact", [
    ("001-25_eccentric_knife_centred", "C", "D"),
    ("001-25b_eccentric_knife_contact_C", "C", "C"),
    ("001-26_eccentric_knife_offset", "B1", "C")])
def test_captions_name_the_points_as_labelled(stem, far, contact):
    text, labels = _captions_and_labels(stem)
    assert {far, contact} <= labels
    assert f"meets it at {far}, its farthest point" in text
    assert f"meets the pitch curve at {contact}" in text
    assert f"normal at {contact} passes" in text
    named = set(re.findall(r"(?<![A-Za-z0-9])(B1|B|C|D|F)(?![A-Za-z0-9′])", text))
    assert named <= labels, (named - labels, stem)


def test_a_centred_follower_names_no_foot():
    text, labels = _captions_and_labels("001-25_eccentric_knife_centred")
    assert "Foot" not in text and "guide through O (centred" in text
    assert "B1" not in text and "OB −" not in text


def test_no_hidden_step_carries_a_caption():
    """A caption on a step that is not drawn never prints (hsheet11k's review: 000-03's and 400-01…03's
    velocity and acceleration scales, 200-07's "Divide the circle of radius a …"): every problem's captions
    are on drawn steps."""
    lost = []
    for path in sorted((ROOT / "problems").glob("*.toml")):
        sc = solve(load_problem(path)).drawing_scene
        drawn = {s.key for s in sc.visible_steps()}
        for s in sc.steps:
            if s.key not in drawn and isinstance(s.caption, tuple) and s.caption and s.caption[0]:
                lost.append((path.stem, s.key, s.caption[0][:40]))
    assert not lost
