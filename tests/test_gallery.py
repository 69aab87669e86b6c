"""The gallery draws each figure once: its player page embeds that drawing and is the page
``Solution.html()`` makes."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.gallery import gallery_page, player_page
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("pid", ["001-08_crank_rocker", "000-02_slotter_design_by_K", "200-01_cam_roller_offset"])
def test_the_player_page_around_the_drawing_is_the_solutions_page(pid):
    sol = solve(load_problem(ROOT / "problems" / f"{pid}.toml"))
    assert player_page(sol, sol.sheets(gallery_page())) == sol.html(gallery_page())
