"""The mechanism symbols a teacher found missing or wrong (issue 11, review items 3, 8, 9, 19, 20, 25, 31, 37),
checked over every gallery figure: every prismatic joint is a block on its guide, blocks never overlap, every
kinematics problem shows the crank's ω, the quick-return figures mark θ."""
from __future__ import annotations

import itertools
from pathlib import Path

import pytest
import shapely

from geomcon.geometry.primitives import Point
from geomcon.problems import load_problem
from geomcon.render.shapes import ArcP, Poly
from geomcon.scene.marks import AngleMark, Rotation, Slider

from test_drawing_defects import NAMES, _members, figure, runs

PROBLEMS = Path(__file__).parent.parent / "problems"

PRISMATIC = {
    "guide_bar.extremes": ("B1", "B2", "D1", "D2"),
    "guide_bar.design_by_K": ("B1", "B2"),
    "guide_bar.kinematics": ("B",),
    "rotating_guide_bar.extremes": ("B1", "B2", "D1", "D2"),
    "shaper.design_by_K": ("B1", "B2", "E1"),
    "slotter.design_by_K": ("B1", "B2", "E"),
    "slotter.kinematics": ("B", "E"),
    "crank_slider.extremes": ("C1", "C2"),
    "crank_slider.design_by_K": ("C1", "C2"),
    "crank_slider.best_by_K": ("C1", "C2"),
    "crank_slider.kinematics": ("C",),
    "crank_slider.instant_centres": ("C",),
    "rocker_slider.three_positions": ("E1", "E2", "E3"),
    "rocker_slider.two_positions": ("E1", "E2"),
}
"""The prismatic joints of each linkage recipe with a slider: the points of its figure where a block slides
(those of them the figure draws: D1, D2 only when a lever is given, E only when the coupler is sized)."""

KINEMATICS = ("four_bar.kinematics", "crank_slider.kinematics", "guide_bar.kinematics", "slotter.kinematics")


def recipe(name: str) -> str:
    return load_problem(PROBLEMS / f"{name}.toml").recipe


def test_every_gallery_recipe_with_a_slider_is_listed():
    """A new recipe whose name says it has a slider or a guide bar cannot skip the block check below."""
    names = {recipe(n) for n in NAMES}
    sliding = {r for r in names if any(w in r for w in ("slider", "guide_bar", "shaper", "slotter"))}
    assert sliding <= set(PRISMATIC)


@pytest.mark.parametrize("name", [n for n in NAMES if recipe(n) in PRISMATIC])
def test_every_prismatic_joint_is_drawn_as_a_block(name):
    """001-04, 001-05c, 001-09, 300-02, 400-05 drew the sliders B1, B2 (and C) as bare pins: every prismatic joint
    of the figure carries a slider block centred on it (that the block runs along a drawn bar or guide is
    :func:`test_drawing_defects.test_every_slider_lies_on_a_drawn_bar_or_guide_along_its_motion`)."""
    fig = figure(name)
    size = max(fig.view.box[2] - fig.view.box[0], fig.view.box[3] - fig.view.box[1])
    blocks = [m.at for g in fig.groups for m in _members(fig.values[g.key]) if isinstance(m, Slider)]
    joints = [k for k in PRISMATIC[recipe(name)]                  # a construction point (style-point) is no joint
              if any(g.key == k and g.shapes and " style-point" not in g.classes for g in fig.groups)]
    assert joints
    for k in joints:
        assert any(abs(fig.values[k] - q) <= 1e-9 * size for q in blocks), (name, k)


@pytest.mark.parametrize("name", NAMES)
def test_no_two_slider_blocks_overlap(name):
    """000-02 drew the blocks B1, D1 (and B2, D2) on top of each other, 001-09 the blocks B1, D1 touching: the
    blocks of a figure are disjoint on paper."""
    fig = figure(name)
    blocks = [shapely.Polygon(sh.pts) for g in fig.groups if isinstance(fig.values[g.key], Slider)
              for sh in g.shapes if isinstance(sh, Poly) and sh.closed]
    assert not [(a, b) for a, b in itertools.combinations(blocks, 2) if a.intersects(b)]


@pytest.mark.parametrize("name", [n for n in NAMES if recipe(n) in KINEMATICS])
def test_every_kinematics_figure_shows_the_crank_omega(name):
    """000-03, 400-01…400-03 gave ω but drew no arrow: the input crank carries ω1 at its pivot A, turning the way
    the given ω's sign says."""
    fig = figure(name)
    problem = load_problem(PROBLEMS / f"{name}.toml")
    (rot,) = [fig.values[g.key] for g in fig.groups if isinstance(fig.values[g.key], Rotation)]
    assert rot.at == fig.values["A"]
    assert rot.sense == (1.0 if problem.given["omega"] > 0 else -1.0)
    (group,) = [g for g in fig.groups if g.key == "omega1"]
    assert [runs(t) for t in group.texts] == ["ω1"]
    assert sum(isinstance(s, ArcP) for s in group.shapes) == 1


@pytest.mark.parametrize("name", ["001-09_slotter_rotating_guide_bar_stroke", "300-02_whitworth_khurmi_5_4"])
def test_the_rotating_guide_bar_marks_theta(name):
    """001-09 and 300-02 gave θ in the Results but marked only φ_quick: θ is marked at A between AB2 and B1A
    extended, with the value the Results print."""
    fig = figure(name)
    (m,) = [fig.values[g.key] for g in fig.groups if g.key == "mark_theta"]
    assert isinstance(m, AngleMark)
    assert abs(m.value - (180.0 - fig.values["phi_quick"])) < 1e-9
    assert [runs(t) for g in fig.groups if g.key == "mark_theta" for t in g.texts] == [f"θ={m.value:.2f}°"]
