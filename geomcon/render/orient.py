"""Which way to turn the paper: the orientation whose sheet 1 draws the figure at the larger standard scale.

A cam stands taller than it is wide (the follower's stem and the roller's envelope above the base circle), a
mechanism usually lies wider: on A4 landscape 200-01 is drawn at 1:2 (r0 = 40 as 20 mm, the rollers overlapping
their labels 1′–15′), on A4 portrait at 1:1. :func:`larger_page` renders the sheets on the orientation that draws
larger, landscape on a tie; a cheap bound (:func:`drawing_bound`: the drawing alone on a sheet with no results)
spares the second rendering whenever one orientation cannot beat the other.

Examples
--------
>>> from geomcon.recipes.crank_rocker import construct
>>> from geomcon.render.page import PageSpec
>>> sc = construct({"AB": 40, "BC": 110, "CD": 70, "AD": 120}).scene       # a long frame AD lies wide
>>> str(drawing_bound(sc, PageSpec("A4", "landscape"))), str(drawing_bound(sc, PageSpec("A4", "portrait")))
('1:1', '1:2')
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any

from ..paper import Scale
from ..scene import Scene
from .page import PageSpec
from .svg import _not_diagram, place_figure


def turned(page: PageSpec) -> PageSpec:
    """``page`` with the paper turned a quarter.

    >>> turned(PageSpec("A3", "landscape", "zh"))
    PageSpec(paper='A3', orientation='portrait', lang='zh')
    """
    return replace(page, orientation="portrait" if page.orientation == "landscape" else "landscape")


def drawing_bound(scene: Scene, page: PageSpec) -> Scale:
    """The largest standard scale sheet 1 of ``page`` can draw ``scene`` at: the drawing alone (a cam's s–δ
    diagram left out, which :func:`~geomcon.render.svg.diagram_apart` may move to a sheet of its own) placed with
    no results (:func:`~geomcon.render.svg.place_figure`), whose drawing area holds every other layout's."""
    return place_figure(scene, page, keep=_not_diagram)[1]


def larger_page(sol: Any, page: PageSpec) -> tuple[PageSpec, list[str]]:
    """``page`` or ``page`` turned (:func:`turned`), and its sheets: the turned page when its sheet 1 draws
    ``sol``'s figure at a larger standard scale and still prints the results if ``page``'s does
    (:meth:`Fit.beats <geomcon.render.svg.Fit.beats>`: 000-05's slotter cam stays on landscape at 1:2.5 with its
    results, rather than at 1:2 with them on sheet 2); ``page`` on a tie. The sheets come from
    ``sol.fitted_sheets`` (:meth:`geomcon.solve.Solution.fitted_sheets`). One orientation is rendered when it
    settles the question against the other's :func:`drawing_bound`; both only when the bounds cannot decide
    (results, a detail view or a diagram sheet may take the larger bound's room).

    >>> from geomcon.problems import load_problem
    >>> from geomcon.solve import solve
    >>> sol = solve(load_problem("problems/200-01_cam_roller_offset.toml"))
    >>> page, sheets = larger_page(sol, PageSpec("A4", "landscape"))
    >>> page.orientation, 'height="297mm"' in sheets[0], "1:1" in sheets[0]
    ('portrait', True, True)
    """
    other = turned(page)
    scene = sol.drawing_scene
    bound, bound_other = drawing_bound(scene, page), drawing_bound(scene, other)
    if bound_other > bound:                          # the turned page may draw larger: try it first
        sheets_other, fit_other = sol.fitted_sheets(other)
        if fit_other.scale > bound and fit_other.results:     # larger than page can draw, results kept
            return other, sheets_other
        sheets, fit = sol.fitted_sheets(page)
    else:
        sheets, fit = sol.fitted_sheets(page)
        if not bound_other > fit.scale:
            return page, sheets
        sheets_other, fit_other = sol.fitted_sheets(other)
    return (other, sheets_other) if fit_other.beats(fit) else (page, sheets)
