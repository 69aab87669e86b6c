"""The annotated SVG of a scene: title, figure at a nice scale, numbered construction protocol, results.

Every numbered step is one SVG group ``<g id="step-<key>" class="step role-… style-…" data-step="n">`` (n is
the protocol number; steps drawn together share it), so a replay is pure CSS: ``.future`` hides a group,
``.current`` highlights it. Frame k (``upto=k``) evaluates only steps 1…k and what they depend on, draws
them, and highlights frame k. The page is in mm (one user unit = 1 mm of paper). Output is deterministic:
fixed rounding, ids from step keys, no clock.

Examples
--------
>>> from geomcon.recipes.crank_rocker import construct
>>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
>>> svg = render_svg(sc, upto=3)
>>> sc.is_evaluated("theta")
False
>>> 'data-step="3"' in svg and 'data-step="4"' not in svg
True
>>> render_svg(sc) == render_svg(sc)
True
"""
from __future__ import annotations

import re

from pathlib import Path
from typing import Any, Sequence

import svgwrite

from ..scene import Scene
from .figure import Figure, build_figure, content_box, fit_view, shown_steps
from .protocol import info_height, layout, render_info, render_protocol
from .shapes import to_svg
from .style import CSS, FONT_FAMILY, INFO_SIZE, INK, PAPER, TITLE_SIZE
from .view import FIG_TARGET, Box, figure_target, fmt, nice_values

MARGIN = 10.0       # page margin, paper mm
TITLE_H = 12.0      # title band
GAP = 8.0           # between figure and protocol
SCALE_H = 12.0      # scale bar band under the figure


def model_extent(scene: Scene, upto: int | None = None) -> Box:
    """The view box (model mm: xmin, ymin, xmax, ymax) that :func:`render_svg` fits to frames 1…upto.

    Passing it as ``viewbox`` to every frame gives a replay with one fixed view and page size.
    """
    steps, _ = shown_steps(scene, upto)
    values = scene.evaluate([s.key for _, s in steps])
    return fit_view(content_box(scene, steps, values), figure_target(len(scene.frames())))


def step_id(key: str) -> str:
    """The SVG id of a step's group (``step-<key>``, whitespace replaced by ``_``)."""
    return "step-" + "_".join(key.split())


def render_svg(scene: Scene, *, upto: int | None = None, viewbox: Box | None = None, title: str | None = None,
               info: Sequence[str] = (), protocol: bool = True, warnings: Sequence[str] = (),
               info_steps: Sequence[int] | None = None) -> str:
    """One SVG document of the scene, or of its frame ``upto``.

    Parameters
    ----------
    scene : Scene
        The construction.
    upto : int or None
        Draw frames 1…upto only (frame ``upto`` highlighted, class ``current``); None draws everything.
    viewbox : (xmin, ymin, xmax, ymax) or None
        Model box to show; None fits the drawn points, segments and marks (see :func:`model_extent`).
    title : str or None
        Title printed at the top (default: the scene's title).
    info : sequence of str
        Result lines printed under the protocol.
    protocol : bool
        Print the numbered construction protocol beside the figure.
    warnings : sequence of str
        Warnings printed under the results, under their own heading (every frame shows them: they concern
        the problem, not a step).
    info_steps : sequence of int or None
        The frame producing each result line: frame k shows the results of frames 1…k only.

    Returns
    -------
    str
        The SVG document (UTF-8 text, sizes in mm).
    """
    origin = (MARGIN, MARGIN + TITLE_H)
    fig = build_figure(scene, upto, viewbox, origin, figure_target(len(scene.frames())) if protocol else FIG_TARGET)
    fig_w, fig_h = fig.view.size
    lay = layout(scene, fig_h + SCALE_H) if protocol else None
    proto_x = origin[0] + fig_w + GAP
    text_w = lay.width if lay else fig_w
    info_h = info_height(info, text_w, warnings)
    if lay:
        width = proto_x + lay.width + MARGIN
        height = max(origin[1] + fig_h + SCALE_H, origin[1] + lay.height + info_h) + MARGIN
    else:
        width = origin[0] + fig_w + MARGIN
        height = origin[1] + fig_h + SCALE_H + info_h + MARGIN
    width, height = float(fmt(width)), float(fmt(height))
    dwg = svgwrite.Drawing(size=(f"{fmt(width)}mm", f"{fmt(height)}mm"), viewBox=f"0 0 {fmt(width)} {fmt(height)}",
                           profile="full", debug=False)
    dwg.attribs["font-family"] = FONT_FAMILY
    dwg.defs.add(dwg.style(CSS))
    dwg.add(dwg.rect(insert=(0, 0), size=(fmt(width), fmt(height)), fill=PAPER, id="paper"))
    dwg.add(dwg.text(title or scene.title, insert=(fmt(MARGIN), fmt(MARGIN + TITLE_SIZE)), font_size=fmt(TITLE_SIZE),
                     font_weight="bold", fill=INK, id="title"))
    dwg.add(_figure_group(dwg, fig))
    dwg.add(_scale_bar(dwg, fig, origin[0], origin[1] + fig_h + 6.0))
    if lay:
        shown = fig.shown
        dwg.add(render_protocol(dwg, lay, proto_x, origin[1], fig.values, shown, shown if upto is not None else None))
        if info or warnings:
            dwg.add(render_info(dwg, info, proto_x, origin[1] + lay.height, text_w, warnings, info_steps, upto))
    elif info or warnings:
        dwg.add(render_info(dwg, info, origin[0], origin[1] + fig_h + SCALE_H, text_w, warnings, info_steps, upto))
    return dwg.tostring()


def _figure_group(dwg: svgwrite.Drawing, fig: Figure) -> Any:
    root = dwg.g(id="figure")
    for name, groups in fig.layers():
        layer = dwg.g(id=f"layer-{name}")
        for sd in groups:
            g = dwg.g(id=step_id(sd.key), class_=sd.classes)
            g.attribs["data-step"] = str(sd.number)
            for shape in sd.shapes:
                g.add(to_svg(shape))
            layer.add(g)
        root.add(layer)
    return root


def _scale_bar(dwg: svgwrite.Drawing, fig: Figure, x: float, y: float) -> Any:
    """A scale bar of a round model length (about 15–35 mm of paper) and the scale μl."""
    mu = fig.view.mu
    length = max(nice_values(15.0 * mu, 35.0 * mu), default=20.0 * mu)
    L = length / mu
    g = dwg.g(id="scale", stroke=INK, stroke_width="0.3")
    g.add(dwg.path(d=f"M{fmt(x)} {fmt(y)}H{fmt(x + L)}M{fmt(x)} {fmt(y - 1)}V{fmt(y + 1)}"
                     f"M{fmt(x + L / 2)} {fmt(y - 0.6)}V{fmt(y + 0.6)}M{fmt(x + L)} {fmt(y - 1)}V{fmt(y + 1)}",
                   fill="none"))
    size = fmt(INFO_SIZE)
    g.add(dwg.text("0", insert=(fmt(x), fmt(y + 4.0)), font_size=size, text_anchor="middle", stroke="none", fill=INK))
    g.add(dwg.text(f"{length:g} mm", insert=(fmt(x + L), fmt(y + 4.0)), font_size=size, text_anchor="middle",
                   stroke="none", fill=INK))
    g.add(dwg.text(f"μl = {mu:g} mm/mm", insert=(fmt(x + L + 10.0), fmt(y + 1.0)), font_size=size, stroke="none",
                   fill=INK))
    return g


_STEP_TAG = re.compile(r'<([A-Za-z][\w:.-]*)((?:\s+[^\s=<>]+="[^"<>]*")*?)\s+data-step="(\d+)"((?:\s+[^\s=<>]+="[^"<>]*")*)\s*(/?)>')


_CLASS = re.compile(r'(\sclass=")([^"]*)"')


def frame_of(svg: str, k: int) -> str:
    """Frame ``k`` of a full drawing: the very document, each element of a later step marked ``future``
    (hidden) and those of step ``k`` ``current`` (highlighted), exactly as the step player shows step k — one
    rendering and one label placement for all frames, so that frames never disagree and labels never jump.

    >>> frame_of('<svg><g data-step="1" /><g class="a" data-step="2">x</g><text data-step="3">y</text></svg>', 2)
    '<svg><g data-step="1" /><g class="a current" data-step="2">x</g><text class="future" data-step="3">y</text></svg>'
    """
    def mark(m: re.Match) -> str:
        tag, before, step, after, close = m.groups()
        n = int(step)
        extra = "future" if n > k else ("current" if n == k else "")
        attrs = f'{before} data-step="{step}"{after}'
        if extra:
            if _CLASS.search(attrs):
                attrs = _CLASS.sub(lambda c: f'{c.group(1)}{c.group(2)} {extra}"', attrs, count=1)
            else:
                attrs = f' class="{extra}"{attrs}'
        return f"<{tag}{attrs}{' ' if close else ''}{close}>"
    return _STEP_TAG.sub(mark, svg)


def write_frames(scene: Scene, directory: str | Path, *, title: str | None = None,
                 info: Sequence[str] = (), warnings: Sequence[str] = (),
                 info_steps: Sequence[int] | None = None) -> list[Path]:
    """Write one SVG per numbered step: ``step-001.svg`` shows step 1, ``step-k.svg`` steps 1…k with k
    highlighted: the full drawing rendered once, later steps hidden (:func:`frame_of`), so every frame has the
    full drawing's page and labels.

    Every frame is rendered first; then each is written to a temporary file beside its target and renamed
    into place (:func:`geomcon.fileio.write_all`), so a failure leaves no half-written frame.

    Returns
    -------
    list of Path
        The files written, in step order.
    """
    from ..fileio import write_all

    full = render_svg(scene, title=title, info=info, warnings=warnings, info_steps=info_steps)
    files = {Path(directory) / f"step-{k:03d}.svg": frame_of(full, k) for k in range(1, len(scene.frames()) + 1)}
    write_all(files)
    return list(files)
