"""The gallery draws each figure once: its player page embeds that drawing and is the page
``Solution.html()`` makes."""
from __future__ import annotations

from pathlib import Path

import pytest

from gallery_pages import page_of
from geomcon.gallery import problem_gallery
from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("pid", ["001-08_crank_rocker", "000-02_slotter_design_by_K", "200-01_cam_roller_offset"])
def test_the_player_page_around_the_drawing_is_the_solutions_page(pid):
    path = ROOT / "problems" / f"{pid}.toml"
    files, _ = problem_gallery(path)
    assert files[f"{pid}.html"] == solve(load_problem(path)).html(page_of(pid))   # on its own page (200-01: portrait)
