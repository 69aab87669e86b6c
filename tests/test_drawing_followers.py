"""Issue 11 review (hlook11c): the mechanism symbols a teacher reads — every cam figure guides its translating
follower with the one symbol of two hatched bearing walls (200-18's flat-faced follower had a single hatched wall on
one side, the symbol of a slider's guide); the frame AD of a drawn linkage stands on two grounded pivots."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.geometry.primitives import Segment
from geomcon.scene.marks import Bearing, Ground, Guide

from test_drawing_defects import NAMES, figure

CAMS = [n for n in NAMES if load_problem(Path(__file__).parent.parent / "problems" / f"{n}.toml").recipe.startswith("cam.")]


@pytest.mark.parametrize("name", CAMS)
def test_no_cam_figure_guides_its_follower_with_a_slider_s_wall(name):
    fig = figure(name)
    assert not [g.key for g in fig.groups if isinstance(fig.values.get(g.key), Guide)]


def test_200_18_s_flat_faced_follower_has_its_bearing():
    fig = figure("200-18_base_radius_flat_gate2020")
    assert [g.key for g in fig.groups if isinstance(fig.values.get(g.key), Bearing)] == ["guide_mark"]


@pytest.mark.parametrize("name", NAMES)
def test_the_frame_ad_has_a_ground_at_both_ends(name):
    """001-10c drew its designed linkage from A1, a candidate's grey circle with no ground (in the figure and in its
    detail view): the frame AD of a drawn linkage stands on two fixed pivots, each with its ground symbol."""
    fig = figure(name)
    grounds = [fig.values[g.key].at for g in fig.groups if isinstance(fig.values.get(g.key), Ground)]
    for g in fig.groups:
        v = fig.values.get(g.key)
        if g.key.startswith("AD") and "style-frame" in g.classes.split() and isinstance(v, Segment):
            for p in (v.a, v.b):
                assert any(abs(p - q) <= 1e-9 * max(1.0, abs(p)) for q in grounds), (g.key, p)
