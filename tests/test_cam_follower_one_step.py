"""A cam's follower in its starting position is drawn whole, in one step of the player (issue 11, hcam11k): 200-02's
and 200-17's flat face appeared at step 13 (12), eight steps after its stem; the oscillating roller followers
(200-05, 200-14, the slotter's feed cam 000-04…08) drew their arm with no roller at all. Over every cam figure of
the gallery: the parts of the follower in its starting position — stem or arm, and its roller or face — share a
frame, and a roller follower has its roller there."""
from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from geomcon.geometry import Circle
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]

BODY = ("stem", "arm0", "arm")
"""The follower's stem (translating) or arm (oscillating) in its starting position, by step key."""
PARTS = ("face_start", "face0", "face_seg", "face", "roller_start", "roller")
"""Its roller or face there."""


def _cams() -> list[str]:
    out = []
    for p in sorted((ROOT / "problems").glob("*.toml")):
        d = tomllib.loads(p.read_text(encoding="utf-8"))
        if d["recipe"].startswith("cam.") and (ROOT / "gallery" / f"{p.stem}.json").exists():
            out.append(p.stem)
    return out


CAMS = _cams()


@pytest.mark.parametrize("pid", CAMS)
def test_the_follower_is_drawn_whole_in_one_step(pid: str):
    sol = solve(load_problem(ROOT / "problems" / f"{pid}.toml"))
    sc = sol.drawing_scene
    frame = {s.key: k for k, group in enumerate(sc.frames(), 1) for s in group}
    body = [frame[k] for k in BODY if k in frame]
    if not body:                                # a base-circle design (200-09 …) draws no follower
        return
    parts = {k: frame[k] for k in PARTS if k in frame}
    assert set(parts.values()) <= {body[0]}, (pid, body, parts)
    follower = sol.problem.given.get("follower")
    if follower == "roller":
        assert any(isinstance(sc.value(k), Circle) for k in parts), f"{pid}: a roller follower drawn without its roller"
    if follower == "flat":
        assert parts, f"{pid}: a flat-faced follower drawn without its face"


def test_the_review_s_figures_are_covered():
    assert {"200-02_cam_flat_face", "200-17_cam_table_law", "200-05_oscillating_roller_cam",
            "000-04_slotter_cam_psi0"} <= set(CAMS)
