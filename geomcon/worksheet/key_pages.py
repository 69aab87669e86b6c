"""The answer key's pages: ``key/<page>.svg`` and ``key.html``, one page per student's sheet, on the same paper
with the same layout, so that a key printed on film lays over the sheet.

A key page holds the sheet's header and statement, each asked answer with its tolerance and points in its box,
the full construction of the chosen solution (the scene's figure as geomcon draws it,
:func:`geomcon.render.figure.build_figure`, at the sheet's scale and through the sheet's own mapping, so its labels
are as high as the sheet's and its points lie on the sheet's: :func:`key_figure`; its view is the construction's
content cut to the frame below the answer boxes, :func:`key_room`; another solution's construction and a cam's
s–δ diagram, which the student does not draw there, are left out) and the overlay: a red tolerance circle around each point the student constructs
(:mod:`.overlay`), its radius the propagated positional tolerance.

Examples
--------
>>> shown(23.14727, 0.42), shown(26.389, 1.2), shown(40.0, 12.0)
('23.15 ± 0.42', '26.4 ± 1.2', '40 ± 12')
"""
from __future__ import annotations

import math
from typing import Any, Callable

import svgwrite

from ..render.style import CSS
from ..render.figure import Figure, build_figure
from ..render.view import grow
from ..scene import Step
from ..render.serial import svg_string
from ..render.shapes import to_svg
from .accept import FIGURE_MARGIN
from .key_extent import compass_extent, key_box, key_content, key_keep, other_solutions
from .overlay import constructed_points, point_keys, position_tolerances
from .pages import ANSWER_H, Rect, u
from .sheets import U, Page, answer_boxes, circle_room, frame, header, page_drawing, pages_html

OVERLAY = "#d0021b"
"""Colour of the tolerance circles."""


def decimals(tol: float) -> int:
    """Decimals that show a tolerance to 2 significant digits (at least 0).

    >>> decimals(0.42), decimals(1.2), decimals(12.0)
    (2, 1, 0)
    """
    return max(0, 1 - math.floor(math.log10(tol))) if tol > 0 else 3


def shown(value: float, tol: float) -> str:
    """An answer as the key page shows it: the value to the last digit of the tolerance (at key.json's 2
    significant digits), ± that tolerance."""
    tol = float(f"{tol:.2g}")
    d = decimals(tol)
    return f"{value:.{d}f} ± {tol:.{d}f}"


def key_room(p: Page) -> Rect:
    """Where the key's construction may run (paper mm): the drawing frame below the answer boxes, left of (or
    above) a cam's s–δ strip beside the figure. A circle too large for the sheet (a θ-circle reaching past the
    frame) ends on the frame line, as the sheet's given circles do (:func:`~.sheets.circle_room`)."""
    x0, _, x1, y1 = circle_room(p)
    rows = 1 + max((r for r, _ in p.lay.slots), default=0)
    return (x0, p.lay.answers_top + rows * ANSWER_H, x1, y1)


def key_view(p: Page, keep: Callable[[Step], bool]) -> tuple[float, float, float, float]:
    """The model box the key draws: the construction's content (:func:`~geomcon.render.figure.content_box`)
    and its compass arcs (:func:`compass_extent`: an arc through a point at the content's edge reaches beyond
    it) with :data:`~.accept.FIGURE_MARGIN` paper mm around them, cut to :func:`key_room` (in model mm, through
    the sheet's own mapping :meth:`~.pages.Layout.to_paper`)."""
    f = p.lay.scale.factor
    cb = key_box(key_content(p.sol, keep), 1.0 / f)
    cb = grow(cb, FIGURE_MARGIN / f)
    rx0, ry0, rx1, ry1 = key_room(p)
    (mx0, my1), (mx1, my0) = to_model(p, rx0, ry0), to_model(p, rx1, ry1)
    return (max(cb[0], mx0), max(cb[1], my0), min(cb[2], mx1), min(cb[3], my1))


def to_model(p: Page, x: float, y: float) -> tuple[float, float]:
    """Model mm of the paper point (x, y): :meth:`~.pages.Layout.to_paper` inverted."""
    lay, f = p.lay, p.lay.scale.factor
    return (lay.box[0] + (x - lay.fig[0] - FIGURE_MARGIN) / f, lay.box[1] + (lay.fig[3] - FIGURE_MARGIN - y) / f)


def key_figure(p: Page) -> tuple[Rect, Figure]:
    """The key's construction drawn at the sheet's scale (1 model mm = the scale's paper mm, so its labels
    are as high as the sheet's), and where it goes on the page (paper mm)."""
    keep = key_keep(p.sol)
    box = key_view(p, keep)
    fig = build_figure(p.sol.drawing_scene, None, box, (0.0, 0.0), mu=1.0 / p.lay.scale.factor, keep=keep)
    (x0, y0), (x1, y1) = p.lay.to_paper(box[0], box[3]), p.lay.to_paper(box[2], box[1])
    return (x0, y0, x1, y1), fig


def figure_group(dwg: svgwrite.Drawing, p: Page) -> Any:
    """The full construction of the chosen solution, nested at the sheet's own mapping, so that it lies over
    the sheet's givens point for point (see :func:`key_figure`)."""
    (x0, y0, x1, y1), fig = key_figure(p)
    vw, vh = fig.view.size
    inner = dwg.svg(insert=(u(x0), u(y0)), size=(u(x1 - x0), u(y1 - y0)), id="construction",
                    viewBox=f"0 0 {vw:.6g} {vh:.6g}")
    for _name, groups in fig.layers():
        for sd in groups:
            g = dwg.g(class_=sd.classes)
            for shape in sd.shapes:
                g.add(to_svg(shape))
            inner.add(g)
    return inner


def overlay_group(dwg: svgwrite.Drawing, p: Page) -> Any:
    """A tolerance circle around each point the student constructs (the figure beneath names the points)."""
    keys = point_keys(p.sol)
    solved = p.variant.solved
    radii = (solved.radii if solved is not None and solved.sol is p.sol
             else position_tolerances(p.sol, p.variant.given, p.lay.scale.factor, keys=keys))
    g = dwg.g(id="overlay", fill="none", stroke=OVERLAY)
    for name, (x, y) in constructed_points(p.sol, keys).items():
        cx, cy = p.lay.to_paper(x, y)
        if not (p.lay.fig[0] <= cx <= p.lay.fig[2] and p.lay.fig[1] <= cy <= p.lay.fig[3]):
            continue                              # another solution's point, outside the sheet's figure
        circle = dwg.circle((u(cx), u(cy)), u(radii[name]), stroke_width=u(0.25))
        circle.attribs["data-point"] = name
        g.add(circle)
    return g


def key_svg(p: Page) -> str:
    """The key page of the sheet ``p`` (see the module)."""
    dwg = page_drawing(p, U)
    dwg.defs.add(dwg.style(CSS))
    dwg.add(frame(dwg, p))
    dwg.add(header(dwg, p, key=True))
    if p.part == "sd":
        return svg_string(dwg) + "\n"
    values = [shown(a.value, a.tol) for a in p.variant.answers]
    dwg.add(answer_boxes(dwg, p, values))
    dwg.add(figure_group(dwg, p))
    dwg.add(overlay_group(dwg, p))
    return svg_string(dwg) + "\n"


def key_files(pages: list[Page], title: str, lang: str) -> dict[str, str]:
    """``key/<page>.svg`` for every sheet with a figure and ``key.html``."""
    svgs = [(p, key_svg(p)) for p in pages if p.part != "sd"]
    files = {f"key/{p.name}.svg": s for p, s in svgs}
    files["key.html"] = pages_html(f"{title} — {'答案' if lang == 'zh' else 'key'}", svgs, lang)
    return files


__all__ = ["OVERLAY", "compass_extent", "decimals", "figure_group", "key_figure", "key_files", "key_keep", "key_room", "key_svg", "key_view",
           "other_solutions", "overlay_group", "shown", "to_model"]
