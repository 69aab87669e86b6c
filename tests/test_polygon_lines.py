"""A velocity or acceleration polygon's direction lines stay in the polygon's panel (review item 37): drawn only
as long as the construction needs, none runs across the mechanism's figure."""
from __future__ import annotations

import functools
from pathlib import Path

import pytest
import shapely

from geomcon.geometry.primitives import Line, Ray
from geomcon.problems import load_problem
from geomcon.render.figure import Figure, build_figure
from geomcon.render.page import PageSpec
from geomcon.render.shapes import Poly, Text, obstacle
from geomcon.render.svg import place_figure
from geomcon.solve import solve

PROBLEMS = Path(__file__).parent.parent / "problems"
MECHANISM = ("given", "ground", "links", "sliders", "points")
"""The layers of a mechanism's drawing: links, frame line, ground symbols, slider blocks, joints."""


@functools.lru_cache(maxsize=None)
def drawn(name: str, upto: int | None = None) -> tuple[Figure, object]:
    """A bundled problem's figure as its sheet 1 draws it (frame ``upto``, or all), and its scene."""
    sol = solve(load_problem(PROBLEMS / f"{name}.toml"))
    sc, page = sol.drawing_scene, PageSpec()
    _, _, view = place_figure(sc, page, sol.figure_lines(page.lang), sol.warnings)
    return build_figure(sc, upto, view.box, view.origin, mu=view.mu), sc


def _poles(sc) -> list[str]:
    """The poles p, p′ of a scene's polygons (placed beside the mechanism)."""
    return [s.key for s in sc.visible_steps() if getattr(s.op, "__name__", "") == "pole_beside"]


def _with_polygons() -> list[str]:
    out = []
    for path in sorted(PROBLEMS.glob("*.toml")):
        sc = solve(load_problem(path)).drawing_scene
        if _poles(sc):
            out.append(path.stem)
    return out


NAMES = _with_polygons()


def test_the_gallery_has_polygon_problems():
    assert {"400-01_four_bar_velocity_polygons", "400-02_crank_slider_velocity_polygons",
            "400-03_guide_bar_coriolis"} <= set(NAMES)


def _lines_and_mechanism(fig: Figure, sc) -> tuple[list[tuple[str, shapely.Geometry]], shapely.Geometry]:
    poles = set(_poles(sc))
    keys = {g.key for g in fig.groups}
    lines = []
    for g in fig.groups:
        v = fig.values.get(g.key)
        if isinstance(v, (Line, Ray)) and poles & set(sc.closure([g.key])):
            lines += [(g.key, shapely.LineString(s.pts)) for s in g.shapes if isinstance(s, Poly)]
    mech = [obstacle(s) for g in fig.groups if g.layer in MECHANISM and not poles & set(sc.closure([g.key]))
            and not isinstance(fig.values.get(g.key), (Line, Ray))         # not a polygon's, not a guide's line
            for s in g.shapes if not isinstance(s, Text)]
    assert mech and keys
    return lines, shapely.box(*shapely.union_all([m for m in mech if m is not None]).bounds)


@pytest.mark.parametrize("name", NAMES)
def test_no_polygon_line_meets_the_mechanism(name):
    """Every drawn line through a polygon's point (a line depending on a pole) keeps off the bounding box of
    the mechanism (its links, joints, frame line, ground symbols and sliders; a slider's infinite guide line
    runs through the whole figure and is left out), on paper."""
    fig, sc = drawn(name)
    lines, mech = _lines_and_mechanism(fig, sc)
    assert lines
    for key, line in lines:
        assert not line.intersects(mech), (name, key, line.bounds, mech.bounds)


@pytest.mark.parametrize("name", NAMES)
def test_a_polygon_line_is_as_long_in_every_frame(name):
    """A direction line drawn before the point it finds is already as long as at the end (frames agree)."""
    last, sc = drawn(name)
    final = {g.key: [s.pts for s in g.shapes if isinstance(s, Poly)] for g in last.groups}
    for k in range(1, last.shown):
        fig, _ = drawn(name, k)
        for g in fig.groups:
            if isinstance(fig.values.get(g.key), Line) and not g.arc:
                assert [s.pts for s in g.shapes if isinstance(s, Poly)] == final[g.key], (name, k, g.key)


@pytest.mark.parametrize("name", NAMES)
def test_no_construction_line_of_the_mechanism_crosses_a_polygon(name):
    """The reverse: a construction line of the mechanism (the guide bar CB through the block) keeps off the
    bounding box of the polygons (their vectors and points), on paper. A given line (a slider's path) may run on."""
    fig, sc = drawn(name)
    poles = set(_poles(sc))
    polygon = [obstacle(s) for g in fig.groups if poles & set(sc.closure([g.key]))
               and not isinstance(fig.values.get(g.key), (Line, Ray)) for s in g.shapes if not isinstance(s, Text)]
    area = shapely.box(*shapely.union_all([m for m in polygon if m is not None]).bounds)
    for g in fig.groups:
        step = sc[g.key]
        if (isinstance(fig.values.get(g.key), (Line, Ray)) and step.role.value == "construction"
                and not poles & set(sc.closure([g.key]))):
            for s in g.shapes:
                if isinstance(s, Poly):
                    assert not shapely.LineString(s.pts).intersects(area), (name, g.key)
