"""Issue 11 (speed): sheet 1's layout search draws a placing set aside (:func:`geomcon.render.svg.aside_views`) only
where its strokes leave room for the results block (:func:`geomcon.render.svg.may_hold_results`): placing a figure's
texts is most of drawing it, and 000-03 placed them on four placings aside where the results and warnings found no
room, 000-05 and 100-07 on two. The check is a necessary condition: texts only take room, so a placing it turns
down would be turned down drawn in full (the gallery's bytes are unchanged)."""
from __future__ import annotations

from pathlib import Path

import pytest

import geomcon.render.svg as svg_module
from geomcon.gallery import gallery_page
from geomcon.problems import load_problem
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"


def _sheets(pid: str) -> None:
    path = next(iter(sorted(PROBLEMS.glob(f"{pid}_*.toml"))))
    solve(load_problem(path)).sheets(gallery_page())


def _drawn(pid: str) -> int:
    """How many figures sheet 1's layout search of ``pid`` draws (texts placed)."""
    calls = []
    real = svg_module.build_figure

    def counted(*args, **kwargs):
        calls.append(args)
        return real(*args, **kwargs)

    svg_module.build_figure = counted
    try:
        _sheets(pid)
    finally:
        svg_module.build_figure = real
    return len(calls)


@pytest.mark.parametrize("pid, most", [("000-03", 2), ("000-05", 2), ("100-07", 2)])
def test_placings_without_room_are_not_drawn(pid: str, most: int) -> None:
    """000-03 drew five figures (centred, then four placings aside: none held the results and its twelve
    warnings; the brief lines then took the first), 000-05 four (with its s–δ sheet's), 100-07 three."""
    assert _drawn(pid) <= most


@pytest.mark.parametrize("pid", ["000-03", "000-05", "100-07", "100-04", "200-14", "200-15"])
def test_may_hold_results_is_necessary(pid: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every placing drawn in full whose results find one box was let through by the check on its strokes alone;
    and the check turns some down (it does the work it is for)."""
    real_may, real_rifr = svg_module.may_hold_results, svg_module.results_in_free_room
    asked: list[tuple] = []
    seen: list[tuple[bool, bool]] = []

    def may(room, info, warnings):                 # let every placing through, remembering what it would say
        asked.append((real_may(room, info, warnings), info, warnings))
        return True

    def rifr(fig, sl, page, info, warnings, *args, **kwargs):
        placed = real_rifr(fig, sl, page, info, warnings, *args, **kwargs)
        if asked and asked[-1][1] is info and asked[-1][2] is warnings:
            ok = placed is not None and not svg_module.split(placed)
            seen.append((asked.pop()[0], ok))
        return placed

    monkeypatch.setattr(svg_module, "may_hold_results", may)
    monkeypatch.setattr(svg_module, "results_in_free_room", rifr)
    _sheets(pid)
    assert seen
    assert all(pre for pre, ok in seen if ok)


def test_may_hold_results_turns_placings_down() -> None:
    """000-03's four placings aside hold the results, or the warnings, but not both apart."""
    calls: list[bool] = []
    real = svg_module.may_hold_results

    def may(room, info, warnings):
        calls.append(real(room, info, warnings))
        return calls[-1]

    svg_module.may_hold_results = may
    try:
        _sheets("000-03")
    finally:
        svg_module.may_hold_results = real
    assert calls.count(False) >= 4


def test_a_figure_rastered_after_its_sketch_is_rastered_the_same() -> None:
    """A room of a finished figure whose strokes (its sketch) were rasterised before adds only the texts to that
    raster (:func:`geomcon.render.free_area._drawn`): the same cells as the figure rasterised whole."""
    from geomcon.render import free_area
    from geomcon.render.figure import build_figure, sketch_figure
    from geomcon.render.shapes import obstacle
    path = next(iter(sorted(PROBLEMS.glob("100-04_*.toml"))))
    sc = solve(load_problem(path)).drawing_scene
    sketch = sketch_figure(sc)
    strokes = tuple(sketch.shapes)
    fig = build_figure(sc, sketch=sketch)
    shapes = tuple(s for g in fig.groups for s in g.shapes)
    assert len(shapes) > len(strokes)
    region = (0.0, 0.0, 300.0, 220.0)
    free_area._DRAWN.clear()
    free_area._drawn(strokes, region)
    sizes, real = [], free_area.raster

    def counted(geoms, at):
        sizes.append(len(geoms))
        return real(geoms, at)

    free_area.raster = counted
    try:
        added = free_area._drawn(shapes, region)
    finally:
        free_area.raster = real
    assert sizes == [len(shapes) - len(strokes)]            # only the texts and leaders rasterised
    whole = free_area.raster([obstacle(s) for s in shapes], region)
    assert added.any() and (added == whole).all()
