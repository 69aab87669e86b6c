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
    ("200-07_oscillating_flat_face", ("face_min", "face_max", "face_length"), "The flat face in its lowest position"),
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


# ------------------------------------------------------------------ a result read off a later step (issue 11)
def _caption_steps(stem: str) -> list[str]:
    sc = _solution(stem).drawing_scene
    return [sc.caption(g[0].key)[0] for g in sc.frames()]


def _shown_at(stem: str, symbol: str) -> int | None:
    """The first step that shows the quantity ``symbol``: its caption names it with "=" (``AB = NM``, ``r0 =
    OB0``, ``AD = 100``: not a formula's ``tan α = …`` nor a condition ``where a = 0``), or, for a length named
    by two labelled points (``AD``), it draws the segment between them."""
    from geomcon.geometry import Point
    from geomcon.geometry.primitives import Segment

    pat = re.compile(r"(?<!tan )(?<!sin )(?<!cos )(?<![A-Za-z0-9′·])" + re.escape(symbol)
                     + r"(?![A-Za-z0-9′″*,_])\s*=(?!\s*0(?![\d.]))")
    steps = [i for i, c in enumerate(_caption_steps(stem), 1) if pat.search(c)]
    two = re.fullmatch(r"([A-Z][0-9]?)([A-Z][0-9]?)", symbol)
    if two:
        sc = _solution(stem).drawing_scene
        frames = sc.frames()
        labelled: dict[str, Point] = {}
        for g in frames:
            for s in g:
                if s.label and isinstance(v := sc.value(s.key), Point):
                    labelled.setdefault(s.label, v)
        if two[1] in labelled and two[2] in labelled:
            ends = {labelled[two[1]], labelled[two[2]]}
            steps += [i for i, g in enumerate(frames, 1) for s in g
                      if isinstance(v := sc.value(s.key), Segment) and {v.a, v.b} == ends]
    return min(steps, default=None)


@pytest.mark.parametrize("stem", [p.stem for p in sorted((ROOT / "problems").glob("*.toml"))])
def test_no_result_shows_before_the_step_that_reads_it_off(stem):
    """Audit of every problem: a Results row appears no earlier than the first step that shows its quantity
    (:func:`_shown_at`). On the base 34 rows of 15 problems showed early: AB, BC of the θ-circle designs with the
    last candidate (001-10 at 23, "AB = NM, BC = AM" is 27), their AD before "The frame AD", AC1, AC2 of the
    crank-slider designs by K (001-06b, 001-18, 004-01) before they are joined."""
    from geomcon.render.results import name_of

    sol = _solution(stem)
    early = []
    for name, k in _row_steps(stem).items():
        symbol = name_of(name, sol.recipe.name, sol.problem.given).symbol
        at = _shown_at(stem, symbol) if symbol else None
        if at is not None and k < at:
            early.append((name, k, at))
    assert not early, early


THETA_DESIGNS = ["001-10_crank_rocker_design_coupler", "001-10b_crank_rocker_design_frame_and_swing",
                 "001-11_jaw_crusher_design", "001-12_crank_rocker_frame_line", "001-13_radar_antenna_K1",
                 "001-14_crank_rocker_K1_frame_angles", "001-15_crank_rocker_frame_and_position",
                 "001-16_jaw_crusher_AC1", "001-21_cutter_drive_K1", "001-22_crank_rocker_frame_and_position_b"]


@pytest.mark.parametrize("stem", THETA_DESIGNS)
def test_a_theta_circle_design_shows_its_links_where_it_measures_them(stem):
    """AB and BC at "Bisect N … at M: AB = NM, BC = AM", the frame (when not given) at "The frame AD", the flags
    and γmin of the design at the step that chooses it — not with the last candidate (001-10: step 23)."""
    steps, given = _row_steps(stem), _solution(stem).problem.given
    assert steps["AB"] == steps["BC"] == _step_of(stem, "Bisect N and the extended position at M")
    choice = _step_of(stem, "The textbook's choice")
    assert steps["gamma_min"] == steps["C1_folded"] == steps["A_near"] == choice
    if given.get("AD") is None:
        assert steps["AD"] == _step_of(stem, "The frame AD")
    else:                                   # a given frame shows where it is laid off, not later
        assert steps["AD"] < choice


def test_the_other_design_forms_show_their_links_where_they_are_drawn():
    """001-10c (crank and frame given): AB, BC with the crank pins, the design's other values at its choice;
    001-17b (links given): D chosen, then its frame AD."""
    steps = _row_steps("001-10c_crank_rocker_design_crank_and_frame")
    pins = _step_of("001-10c_crank_rocker_design_crank_and_frame", "The crank pins B1")
    choice = _step_of("001-10c_crank_rocker_design_crank_and_frame", "The textbook's choice")
    assert steps["AB"] == steps["BC"] == pins and steps["CD"] == steps["gamma_min"] == choice
    steps = _row_steps("001-17b_crank_rocker_redesign_swing")
    assert steps["AD"] == _step_of("001-17b_crank_rocker_redesign_swing", "The frame AD")
    assert steps["CD"] == steps["gamma_min"] == _step_of("001-17b_crank_rocker_redesign_swing", "The textbook's choice")


def test_a_given_frame_is_not_drawn_twice():
    """001-15 and 001-22 (the frame given) drew "The frame AD" at step 4 and again after the choice. No step
    repeats the caption of another, but 200-11's "…and the one on the other side" (of the rise's tangent, then
    of the return's)."""
    for path in sorted((ROOT / "problems").glob("*.toml")):
        caps = [c for c in _caption_steps(path.stem) if c != "…and the one on the other side"]
        assert len(caps) == len(set(caps)), (path.stem, sorted(c for c in caps if caps.count(c) > 1))


READ_OFF_CURVES = {"s": "sd_curve", "psi": "sd_curve", "pitch_x": "pitch_curve", "pitch_y": "pitch_curve",
                   "profile_x": "profile_curve", "profile_y": "profile_curve"}


@pytest.mark.parametrize("stem", [p.stem for p in sorted((ROOT / "problems").glob("*.toml"))
                                  if "at = [" in p.read_text(encoding="utf-8")])
def test_a_cam_s_list_at_given_angles_shows_with_the_curve_it_is_read_off(stem):
    """s (or ψ) at the cam angles of ``at`` is read off the s–δ (ψ–δ) curve, the pitch points off the pitch
    curve, the profile's off the profile. On the base 15 cams failed: 8 showed s at step 1 (with the cam centre),
    6 ψ, α, the pitch and profile points at step 5 (with the arm's pivot), before any diagram or curve was drawn,
    200-07 ψ and α at step 6, its face contacts at step 2. A single asked position drawn later keeps its own,
    later step (001-24: 15)."""
    sol = _solution(stem)
    sc, steps = sol.drawing_scene, _row_steps(stem)
    listed = [n for n in sol.listed_at() if n in steps]
    assert listed
    for name in listed:
        curve = READ_OFF_CURVES.get(name) or ("profile_curve" if sol.recipe.name == "cam.oscillating"
                                              and sol.problem.given.get("follower") == "flat" else None)
        if curve is None and name == "alpha":
            curve = "pitch_curve" if "pitch_curve" in sc else "profile_curve"
        if curve is None:                       # v, a, ω2, ε2: with the last step
            assert steps[name] == len(sc.frames()), name
            continue
        assert steps[name] >= sc.number(curve), (name, steps[name], curve)
        if len(sol.listed_at()[name]) > 1:
            assert steps[name] == sc.number(curve) or name == "alpha", (name, steps[name], curve)
