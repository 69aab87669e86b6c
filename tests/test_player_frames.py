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

from geomcon.gallery import gallery_page, problem_files
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
    return _solution(pid).sheets(gallery_page())[0]


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
    _, _, view = place_figure(sc, gallery_page())
    fig = build_figure(sc, None, view.box, view.origin, mu=view.mu)
    points = [(g.number, sh.c) for g in fig.groups if g.layer == "points" for sh in g.shapes if isinstance(sh, Disc)]
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
