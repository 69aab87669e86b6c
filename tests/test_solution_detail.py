"""``--solution N`` sheets follow the detail-view rule of the gallery's sheets (tests/test_gallery_detail.py,
issue 11 review item 3): every link of the drawing is at least :data:`~geomcon.render.detail.MIN_LINK` on paper,
or sheet 1 shows a detail view that draws it so, or the sheet's free room (clear of the figure, the results, title
block, scale bar and captions) holds no box of the detail's size. A sheet of another solution is laid out by the
same path as the textbook's (:meth:`geomcon.solve.Solution.sheets`), so only the room differs: 001-16's solutions
2 and 4 asked 76.6 × 135.4 and 77.9 × 100.6 mm at 1:5, where the room right of the drawing, under the results, is
about 118 × 94 mm, and showed none; now the detail view is placed first when it finds no room after the results
(:func:`geomcon.render.svg._detail_first`), and a sheet without one must show that neither order fits."""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import pytest

from geomcon.gallery import gallery_page
from geomcon.paper import Scale
from geomcon.problems import load_problem
from geomcon.render.detail import MIN_LINK, detail_figure, mechanism_steps
from geomcon.render.figure import build_figure, shown_steps
from geomcon.render.results import brief_warnings
from geomcon.render.svg import _detail_first, place_figure
from geomcon.render.warning_words import warning_lines
from geomcon.solve import solve
from sheet_room import results_and_room

ROOT = Path(__file__).resolve().parents[1]
SEVERAL = ["001-10_crank_rocker_design_coupler", "001-11_jaw_crusher_design", "001-12_crank_rocker_frame_line",
           "001-15_crank_rocker_frame_and_position", "001-16_jaw_crusher_AC1", "001-17b_crank_rocker_redesign_swing",
           "001-22_crank_rocker_frame_and_position_b"]


@lru_cache(maxsize=None)
def _base(pid: str):
    return solve(load_problem(ROOT / "problems" / f"{pid}.toml"))


def _cases() -> list[tuple[str, int]]:
    out = []
    for pid in SEVERAL:
        sol = _base(pid)
        try:
            out += [(pid, n) for n in range(1, len(sol.solution_values) + 1) if n == 1 or sol.as_solution(n)]
        except Exception:                 # a recipe that draws one solution only: the textbook's
            out.append((pid, 1))
    return out


def _detail_scale(svg: str) -> Scale | None:
    m = re.search(r'class="detail-head"[^>]*>(?:<tspan>)?[^<]*?(\d+(?:\.\d+)?:\d+(?:\.\d+)?)', svg)
    return Scale.parse(m.group(1)) if m else None


@pytest.mark.parametrize("pid, n", _cases())
def test_a_solution_sheet_shows_short_links_in_a_detail_view_where_room_allows(pid, n):
    sol = _base(pid).as_solution(n)
    page = gallery_page()
    sc = sol.drawing_scene
    info, warnings = sol.figure_lines(page.lang), warning_lines(sol.warnings, page.lang)
    sl, scale, view = place_figure(sc, page, info, warnings)
    steps, _ = shown_steps(sc, None)
    _, _, lengths = mechanism_steps(steps, sc.evaluate([s.key for _, s in steps]))
    svg = sol.sheets(page)[0]
    detail = _detail_scale(svg)
    if not lengths or min(lengths) / view.mu >= MIN_LINK - 1e-9:
        assert detail is None
        return
    shortest = min(lengths) / view.mu
    if detail is not None:
        assert shortest * detail.factor / scale.factor >= MIN_LINK - 1e-9 and detail > scale
        return
    fig = build_figure(sc, None, view.box, view.origin, mu=view.mu)
    sl, room = results_and_room(fig, sl, page, scale, info, warnings, sol)
    asked: list[tuple[float, float]] = []
    assert detail_figure(sc, fig, scale, lambda w, h: asked.append((w, h)), None) is None
    assert asked, (pid, n, round(shortest, 2))                  # a detail was asked for ...
    for w, h in asked:
        assert room.find([(w, h)]) is None, (pid, n, w, h)     # ... and no free box holds it
    brief = (sol.figure_lines(page.lang, brief=True), brief_warnings(sol.warnings, page.lang, 2))
    assert _detail_first(sc, fig, sl, page, [(info, warnings), brief], scale, sol.info_steps(), None) is None


def test_every_solution_of_001_16_shows_its_detail_view():
    """001-16's four solutions draw AB about 5.5 and 8.6 mm long at 1:10; each sheet enlarges it in a detail view
    (solutions 2 and 4 had none)."""
    base = _base("001-16_jaw_crusher_AC1")
    shown = [_detail_scale(base.as_solution(n).sheets(gallery_page())[0]) is not None for n in (1, 2, 3, 4)]
    assert shown == [True] * 4
