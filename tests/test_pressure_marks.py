"""A translating cam's figure marks the largest pressure angle of the rise and of the return, each where it occurs
and named as its answer (αmax, α′max); the worksheet key marks what its answer boxes ask (issue 11: the key marked
the whole cycle's α at B* beside a box asking for the rise's αmax)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.scene.marks import AngleMark
from geomcon.solve import solve

ROOT = Path(__file__).parent.parent
TRANSLATING = [p for p in sorted((ROOT / "problems").glob("*.toml"))
               if load_problem(p).recipe == "cam.translating" and load_problem(p).given.get("follower") != "flat"]


def test_there_are_translating_cams_with_a_rise_and_a_return():
    assert len(TRANSLATING) >= 8


@pytest.mark.parametrize("path", TRANSLATING, ids=lambda p: p.stem)
def test_each_part_s_largest_pressure_angle_is_marked_at_its_own_position(path):
    sol = solve(load_problem(path))
    sc = sol.drawing_scene
    parts = [p for p in ("rise", "return") if f"mark_alpha_{p}" in sc]
    assert parts and "mark_alpha" not in sc
    for part in parts:
        v = sc.evaluate([f"mark_alpha_{part}", f"P_alpha_{part}"])
        mark, at = v[f"mark_alpha_{part}"], v[f"P_alpha_{part}"]
        assert isinstance(mark, AngleMark) and mark.vertex == at
        assert mark.value == pytest.approx(sol.answers[f"alpha_max_{part}"], rel=1e-9)
        assert mark.symbol == ("αmax" if part == "rise" else "α′max")
    steps = {s.key: s for s in sc.steps}
    labels = [steps[f"P_alpha_{p}"].label for p in parts]
    assert len(set(labels)) == len(labels)


def _printed(svg: str) -> str:
    return re.sub(r"<[^>]+>", "", svg)


def test_the_worksheet_key_marks_the_pressure_angle_its_box_asks_for():
    keys = sorted((ROOT / "gallery" / "worksheet" / "key").glob("*.svg"))
    asked = 0
    for page in keys:
        svg = page.read_text(encoding="utf-8")
        for name, mark in (("αmax (rise) =", "αmax="), ("αmax (return) =", "α′max=")):
            plain = _printed(svg)                   # the box's label is typeset (αmax with a subscript tspan)
            if name not in plain:
                continue
            box = re.search(re.escape(name) + r".*?(-?[\d.]+) ± ", plain, re.S)
            assert box, page.name
            marks = re.findall(r'<text class="mark-text"[^>]*>(.*?)</text>', svg)
            printed = [_printed(m) for m in marks]
            assert f"{mark}{box.group(1)}°" in printed, (page.name, printed)
            asked += 1
    assert asked >= 1
