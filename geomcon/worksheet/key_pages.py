"""The answer key's pages: ``key/<page>.svg`` and ``key.html``, one page per student's sheet, on the same paper
with the same layout, so that a key printed on film lays over the sheet.

A key page holds the sheet's header and statement, each asked answer with its tolerance and points in its box,
the full construction (the scene's figure as geomcon draws it, :func:`geomcon.render.figure.build_figure`,
nested in an ``<svg>`` whose viewBox maps the sheet's model box onto the sheet's figure area: 1 real mm =
the scale's paper mm; a cam's s–δ diagram, which lies outside that box, is left out) and the overlay: a red tolerance circle around each point the student constructs
(:mod:`.overlay`), its radius the propagated positional tolerance.

Examples
--------
>>> shown(23.14727, 0.42), shown(26.389, 1.2), shown(40.0, 12.0)
('23.15 ± 0.42', '26.4 ± 1.2', '40 ± 12')
"""
from __future__ import annotations

import math
from typing import Any

import svgwrite

from ..render.figure import build_figure
from ..render.serial import svg_string
from ..render.shapes import to_svg
from ..render.style import CSS
from .accept import FIGURE_MARGIN
from .overlay import constructed_points, point_keys, position_tolerances
from .pages import u
from .readability import DIAGRAM_PREFIX
from .sheets import U, Page, answer_boxes, frame, header, page_drawing, pages_html

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


def _in_figure(step: Any) -> bool:
    """Whether the key's figure draws a step: every step but a cam's s–δ diagram (``sd_…``), which lies
    beside the cam, outside the sheet's model box (:func:`~.readability.extent`), where the nested ``<svg>``
    would clip it away."""
    return not step.key.startswith(DIAGRAM_PREFIX)


def figure_group(dwg: svgwrite.Drawing, p: Page) -> Any:
    """The full construction, nested so that the sheet's model box fills the sheet's figure area."""
    f = p.lay.scale.factor
    m = FIGURE_MARGIN / f
    b = p.lay.box
    box = (b[0] - m, b[1] - m, b[2] + m, b[3] + m)
    x0, y0, x1, y1 = p.lay.fig
    fig = build_figure(p.sol.drawing_scene, None, box, (0.0, 0.0), x1 - x0, keep=_in_figure)
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


__all__ = ["OVERLAY", "decimals", "figure_group", "key_files", "key_svg", "overlay_group", "shown"]
