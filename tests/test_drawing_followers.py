"""Issue 11 review (hlook11c): every cam figure guides its translating follower with the one symbol of two hatched
bearing walls (200-18's flat-faced follower had a single hatched wall on one side, the symbol of a slider's guide)."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.scene.marks import Bearing, Guide

from test_drawing_defects import NAMES, figure

CAMS = [n for n in NAMES if load_problem(Path(__file__).parent.parent / "problems" / f"{n}.toml").recipe.startswith("cam.")]


@pytest.mark.parametrize("name", CAMS)
def test_no_cam_figure_guides_its_follower_with_a_slider_s_wall(name):
    fig = figure(name)
    assert not [g.key for g in fig.groups if isinstance(fig.values.get(g.key), Guide)]


def test_200_18_s_flat_faced_follower_has_its_bearing():
    fig = figure("200-18_base_radius_flat_gate2020")
    assert [g.key for g in fig.groups if isinstance(fig.values.get(g.key), Bearing)] == ["guide_mark"]
