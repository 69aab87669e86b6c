"""A result appears in the player, the ``--steps`` frames and the sheet's frames with the step that constructs
it, not with the step where its inputs are known (issue 11: "Each result appears at the step that produces it;
nothing later shows early"). Found in hsheet11k's player review: 200-07 showed α_max, α′max and where they occur,
and the face's least and largest reach, from step 2, though its worst positions are drawn at steps 17 and 18 and
the face at step 9; 001-24 and 200-16 showed s at the asked position from step 1, laid off at step 15; 001-21
its DE at step 9, the output arm drawn at step 18 (:meth:`geomcon.scene.Scene.drawn_from`)."""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]


@lru_cache(maxsize=None)
def _solution(stem: str):
    return solve(load_problem(ROOT / "problems" / f"{stem}.toml"))


def _row_steps(stem: str) -> dict[str, int]:
    sol = _solution(stem)
    return dict(zip([q.name for q in sol.sheet_answers()], sol.info_steps()))


def _step_of(stem: str, start: str) -> int:
    sc = _solution(stem).drawing_scene
    found = [i for i, g in enumerate(sc.frames(), 1) if sc.caption(g[0].key)[0].startswith(start)]
    assert len(found) == 1, (start, found)
    return found[0]


@pytest.mark.parametrize("stem, names, start", [
    ("200-07_oscillating_flat_face", ("alpha_max_rise", "delta_alpha_max_rise"), "The rise's worst position"),
    ("200-07_oscillating_flat_face", ("alpha_max_return", "delta_alpha_max_return"), "The return's worst position"),
    ("200-07_oscillating_flat_face", ("face_min", "face_max"), "The flat face in its lowest position"),
    ("001-24_cam_displacement_at_100", ("s",), "The asked position δ = 100°"),
    ("200-16_cam_poly_4567", ("s",), "The asked position δ = 75°"),
    ("001-21_cutter_drive_K1", ("DE",), "Output arm")])
def test_a_result_shows_with_the_step_that_constructs_it(stem, names, start):
    steps, at = _row_steps(stem), _step_of(stem, start)
    assert {steps[n] for n in names} == {at}


def test_the_sheet_shows_200_07_s_alpha_max_with_its_worst_position():
    """The Results lines of 200-07's sheet carry the step of the worst position (data-step), so the player and
    the frames show α_max from step 17 on, no longer from step 2."""
    svg = (ROOT / "gallery" / "200-07_oscillating_flat_face.svg").read_text(encoding="utf-8")
    rows = re.findall(r'<text class="info" data-step="(\d+)"[^>]*>(.*?)</text>', svg)
    alpha = [int(k) for k, body in rows if "推程最大压力角" in re.sub(r"<[^>]+>", "", body)]
    assert alpha == [_step_of("200-07_oscillating_flat_face", "The rise's worst position")]


def test_no_result_shows_before_a_step_drawn_from_it():
    for path in sorted((ROOT / "problems").glob("*.toml")):
        sol = _solution(path.stem)
        sc = sol.drawing_scene
        for (name, k) in _row_steps(path.stem).items():
            first = sc.drawn_from(sol.construction.answers[name]) if name in sol.construction.answers else None
            assert first is None or k >= first, (path.stem, name, k, first)
