"""Every link of a gallery drawing is at least 10 mm long on paper (issue 11, review item A2): where the sheet's
scale, set by the construction (a θ-circle ten times the mechanism's size), draws a link shorter, sheet 1 adds a
detail view of the mechanism at the smallest standard scale that draws every link 10 mm or longer
(:mod:`geomcon.render.detail`). The drawings listed below have no free box for such a view: they are named,
with the reason, and the list may only shrink."""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import pytest

from geomcon.gallery import gallery_page, problem_files
from geomcon.paper import Scale
from geomcon.problems import load_problem
from geomcon.render.detail import MIN_LINK, mechanism_steps
from geomcon.render.figure import shown_steps
from geomcon.render.svg import _not_diagram, diagram_apart, place_figure
from geomcon.render.warning_words import warning_lines
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
PROBLEMS = [p.stem for p in problem_files(ROOT / "problems")]
NO_ROOM = {
    "000-03_slotter_velocity_polygons": "a polygon vector of 0.7 mm would need 5:1; the polygons fill the sheet",
    "001-10_crank_rocker_design_coupler": "1:10, needs 1:5: the θ-circle and the results leave no box that large",
    "001-11_jaw_crusher_design": "1:10, needs 1:5: no free box that large",
    "001-12_crank_rocker_frame_line": "1:20, needs 1:5: no free box that large",
    "001-24_cam_displacement_at_100": "the follower's stem at 1:2 (5.8 mm); the cam at 1:1 fits no free box",
    "200-07_oscillating_flat_face": "the arm at 1:2 (5 mm); the cam at 1:1 fits no free box",
    "200-16_cam_poly_4567": "the follower's stem at 1:2 (5 mm); the cam at 1:1 fits no free box",
    "400-01_four_bar_velocity_polygons": "a polygon vector at 1:2 (4.5 mm) would need 2:1",
    "400-02_crank_slider_velocity_polygons": "1:5, needs 1:2.5: the polygons fill the sheet",
    "400-03_guide_bar_coriolis": "1:5, needs 1:2.5: the polygons fill the sheet",
}


@lru_cache(maxsize=None)
def _shortest(pid: str) -> tuple[float, Scale] | None:
    """The shortest link of sheet 1's figure on paper (mm) and the sheet's scale; None without links."""
    sol = solve(load_problem(ROOT / "problems" / f"{pid}.toml"))
    page = gallery_page()
    sc = sol.drawing_scene
    info, warnings = sol.figure_lines(page.lang), warning_lines(sol.warnings, page.lang)
    sl, scale, view = place_figure(sc, page, info, warnings)
    apart = diagram_apart(sc, page, info, warnings, scale)
    keep = None
    if apart is not None:
        sl, scale, view = apart
        keep = _not_diagram
    steps, _ = shown_steps(sc, None, keep)
    values = sc.evaluate([s.key for _, s in steps])
    _, _, lengths = mechanism_steps(steps, values)
    return (min(lengths) / view.mu, scale) if lengths else None


def _detail_scale(svg: str) -> Scale | None:
    m = re.search(r'class="detail-head"[^>]*>(?:<tspan>)?[^<]*?(\d+(?:\.\d+)?:\d+(?:\.\d+)?)', svg)
    return Scale.parse(m.group(1)) if m else None


@pytest.mark.parametrize("pid", PROBLEMS)
def test_every_link_is_ten_mm_on_paper_or_shown_in_a_detail_view(pid):
    svg_path = GALLERY / f"{pid}.svg"
    if not svg_path.exists():
        pytest.skip("no drawing")
    got = _shortest(pid)
    if got is None:
        return
    shortest, scale = got
    detail = _detail_scale(svg_path.read_text(encoding="utf-8"))
    if shortest >= MIN_LINK - 1e-9:
        assert detail is None, (pid, shortest)            # no detail where the drawing is readable already
        assert pid not in NO_ROOM, pid
        return
    if pid in NO_ROOM:
        assert detail is None, pid                        # the list may only shrink
        return
    assert detail is not None, (pid, round(shortest, 2), str(scale))
    assert shortest * detail.factor / scale.factor >= MIN_LINK - 1e-9, (pid, str(detail))
    assert detail > scale
