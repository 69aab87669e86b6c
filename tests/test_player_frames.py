"""Issue 11, the step player and the frames, over every gallery problem: a frame shows nothing a later step
makes — no compass arc through a point not constructed yet (001-08 step 14 showed the rocker circle's arc at C′,
which step 19 constructs), no result and no warning before the step that produces it — and the rows shown at a
frame are packed (no blank row for a result still to come)."""
from __future__ import annotations

import math
import re
from functools import lru_cache
from pathlib import Path

import pytest

from gallery_pages import page_of
from geomcon.gallery import problem_files
from geomcon.geometry import Point
from geomcon.problems import load_problem
from geomcon.render.draw import COMPASS_HALF
from geomcon.render.figure import build_figure
from geomcon.render.shapes import ArcP, Disc
from geomcon.render.svg import frame_of, place_figure
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = [p.stem for p in problem_files(ROOT / "problems")]


@lru_cache(maxsize=None)
def _solution(pid: str):
    return solve(load_problem(ROOT / "problems" / f"{pid}.toml"))


@lru_cache(maxsize=None)
def _sheet(pid: str) -> str:
    """The sheet holding the Results (sheet 1, or the first text sheet when they do not fit beside the figure)."""
    sheets = _solution(pid).sheets(page_of(pid))
    return next((s for s in sheets if '<g id="info">' in s or '<g id="warnings">' in s), sheets[0])


def _gap(angle: float, start: float, sweep: float) -> float:
    """Angular distance (radians) from ``angle`` to the arc (start, sweep)."""
    a0, a1 = (start, start + sweep) if sweep >= 0 else (start + sweep, start)
    a = (angle - a0) % math.tau
    return 0.0 if a <= a1 - a0 else min(a - (a1 - a0), math.tau - a)


@pytest.mark.parametrize("pid", PROBLEMS)
def test_no_compass_arc_is_drawn_before_the_point_it_is_swung_for(pid):
    """Every compass arc shown at frame m passes through a point drawn by frame m — or through the first point a
    later step constructs on its circle (the arc the draftsman swings where the next intersection will be)."""
    sc = _solution(pid).drawing_scene
    _, _, view = place_figure(sc, page_of(pid))
    fig = build_figure(sc, None, view.box, view.origin, mu=view.mu)
    points = [(g.number, sh.c) for g in fig.groups if g.layer == "points" for sh in g.shapes if isinstance(sh, Disc)]
    points += [(g.number, fig.view.p(fig.values[g.key])) for g in fig.groups      # a point sharing another's marker
               if g.layer == "points" and isinstance(fig.values.get(g.key), Point)     # (drawn at its own frame)
               and not any(isinstance(sh, Disc) for sh in g.shapes)]
    for g in fig.groups:
        arcs = [sh for sh in g.shapes if isinstance(sh, ArcP)] if "style-construction" in g.classes.split() else []
        for arc in arcs:
            half = max(math.radians(6.0), min(math.pi, COMPASS_HALF / arc.r)) + 1e-6
            on = [(n, math.atan2(p[1] - arc.c[1], p[0] - arc.c[0])) for n, p in points
                  if abs(math.dist(p, arc.c) - arc.r) <= 1e-3]
            if not on:
                continue                                  # a circle no point lies on: whole, at its own step
            first = min(n for n, _ in on)
            through = [n for n, a in on if _gap(a, arc.start, arc.sweep) <= half]
            assert through, (pid, g.key)
            assert min(through) <= g.number or (min(through) == first and not g.arc), \
                (pid, g.key, g.number, sorted(through))


_ROW = re.compile(r'<(?:text|g)\b[^>]*\bclass="(info-head|info|warning-head|warning)((?: [a-z-]+)*)"[^>]*>')


def _info_rows(svg: str) -> list[tuple[str, int | None, bool]]:
    """The Results / Warnings block's headings and lines in document order: (kind, data-step, shown)."""
    blocks = []
    for m in re.finditer(r'<g id="(?:info|info-\d+|warnings)">', svg):   # split over free boxes on sheet 1
        block = svg[m.start():]
        blocks.append(block[:block.index("</g>")])
    block = "".join(blocks)
    out = []
    for m in _ROW.finditer(block):
        step = re.search(r'data-step="(\d+)"', m.group(0))
        out.append((m.group(1), int(step.group(1)) if step else None, "future" not in m.group(2).split()))
    return out


def _depends_on_frame(sc, key: str, k: int) -> bool:
    """Whether step ``key`` is, or depends on, a visible step of frame ``k``."""
    frame = {s.key: i for i, group in enumerate(sc.frames(), 1) for s in group}
    seen, todo = set(), [key]
    while todo:
        x = todo.pop()
        if x in seen:
            continue
        seen.add(x)
        if frame.get(x) == k:
            return True
        todo += list(sc._rec[x][7])
    return False


@pytest.mark.parametrize("pid", PROBLEMS)
def test_a_result_shows_from_the_step_that_produces_it_and_a_warning_from_the_last(pid):
    """Each result line is tagged with a frame whose visible step it depends on, or the first frame that draws a
    step computed from it (200-07's α_max with its worst position, step 17, no longer step 2: hsheet11k), or the
    step the recipe reads it off (:meth:`~geomcon.scene.Scene.read_off`: 001-10's AB at "AB = NM", step 27) (an
    answer no drawn step makes — 200-05's δ(α_max), computed from the givens — is tagged with the last frame,
    never frame 1), and each warning, with its heading, with the last frame: 200-05 showed both at step 1."""
    sol = _solution(pid)
    sc = sol.drawing_scene
    n = len(sc.frames())
    maps = sol.construction.solutions or (sol.construction.answers,)
    answers = [q.name for q in sol.sheet_answers()]          # a knife edge's ρa,min and undercut: not on it
    for name, step in zip(answers, sol.info_steps(), strict=True):
        keys = [m[name] for m in maps if name in m]
        drawn = sc.drawn_from(sol.construction.answers[name]) if name in sol.construction.answers else None
        read = sc.read_at(sol.construction.answers[name]) if name in sol.construction.answers else None
        assert step == n or step in (drawn, read) or any(_depends_on_frame(sc, k, step) for k in keys), (pid, name, step)
    rows = _info_rows(_sheet(pid))
    assert all(step is not None for _, step, _ in rows), pid
    assert {step for kind, step, _ in rows if kind == "info"} == set(sol.info_steps()), pid
    assert all(step == n for kind, step, _ in rows if kind.startswith("warning")), pid
    assert bool(sol.warnings or sol.info_steps()) == bool(rows), pid
    assert bool(sol.warnings) == any(kind == "warning" for kind, _, _ in rows), pid


@pytest.mark.parametrize("pid", PROBLEMS)
def test_every_frame_shows_the_results_and_warnings_of_its_steps_packed(pid):
    """At every frame k (``--steps`` frame k, the player's step k), the Results / Warnings lines shown are those
    of steps ≤ k and they come first, under their heading: no blank row for a result still to come, no heading
    without a line (001-08 step 14 had blank rows between ∠C2AD and θ)."""
    sheet = _sheet(pid)
    n = len(_solution(pid).drawing_scene.frames())
    for k in range(1, n + 1):
        rows = _info_rows(frame_of(sheet, k))
        assert all(shown == (step <= k) for _, step, shown in rows), (pid, k)
        shown = [s for _, _, s in rows]
        assert shown == sorted(shown, reverse=True), (pid, k, rows)      # the shown lines are the first ones
        heads = [i for i, (kind, _, _) in enumerate(rows) if kind.endswith("-head")]
        for i in heads:
            assert not rows[i][2] or (i + 1 < len(rows) and rows[i + 1][2]), (pid, k)


@pytest.mark.parametrize("pid", PROBLEMS)
def test_the_player_prints_the_step_caption_once_on_the_sheet(pid):
    """The current step's caption is the sheet's (as in ``--steps`` frame k), not printed again in a panel above
    the drawing (hlook11 item 41): outside the sheets and the script, the page holds no caption."""
    page = (ROOT / "gallery" / f"{pid}.html").read_text(encoding="utf-8")
    outside = re.sub(r"<script>.*?</script>", "", page[:page.index('<div id="drawing">')], flags=re.S)
    sheet = page[page.index('id="page-1"'):]
    caps = re.findall(r'<text class="stepcap" data-step="1"[^>]*>(.*?)</text>', sheet, re.S)
    assert caps and 'id="caption"' not in outside, pid
    words = re.sub(r"<[^>]+>", "", caps[0]).split(". ", 1)[-1]
    assert words and words not in outside, pid
