"""What every chart sheet shares (a cam's s–δ, v–δ, a–δ diagrams, a motion law's, a linkage's cycle plots): an A4
portrait sheet with the drawing frame and the title block of the drawings (:mod:`geomcon.render.page`), numbers
written without e-notation, typeset symbols, and text placed so that no two texts overlap.

Examples
--------
>>> plain(12500.0), plain(2.5e6), plain(-0.000123456), plain(-0.0), plain(229.18311805)
('12500', '2500000', '-0.0001235', '0', '229.2')
>>> axis_factor(2.5e6), axis_factor(980.0), axis_factor(0.0004)
(1000, 1, 1)
>>> t = Texts()
>>> t.free((0.0, 0.0, 10.0, 3.0)), t.take((0.0, 0.0, 10.0, 3.0)), t.free((5.0, 1.0, 12.0, 4.0))
(True, None, False)
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Sequence

import svgwrite

from .labels import text_width
from .page import MIN_TEXT, PageSpec, TitleBlock, document, frame_box, title_block, title_block_box
from .serial import Element
from .shapes import add_runs
from .view import Box, fmt

SPEC = PageSpec("A4", "portrait", "both")
"""The paper of every chart: A4 portrait, headings in both languages."""
SHEET = SPEC.sheet
INSET = 4.0            # free paper between the frame and the chart
Runs = tuple[tuple[str, bool], ...]


def plain(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant digits in plain decimals: never e-notation, never ``-0``."""
    if not math.isfinite(x):
        return "∞" if x > 0 else "−∞" if x < 0 else "?"
    if x == 0:
        return "0"
    places = max(0, digits - 1 - math.floor(math.log10(abs(x))))
    s = f"{round(x, places):.{places}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "0", "") else s


def axis_factor(hi: float) -> int:
    """The power of 1000 an axis' numbers are divided by, so that none needs more than 4 digits before the
    decimal point (``×10³``, ``×10⁶`` written with the quantity's unit); 1 when they fit."""
    k = 0
    while abs(hi) / 1000 ** k >= 1e4:
        k += 1
    return 1000 ** k


SUPER = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def factor_text(f: int) -> str:
    """``×10³`` for 1000, ``""`` for 1."""
    return "" if f == 1 else "×10" + str(round(math.log10(f))).translate(SUPER)


def box_of(x: float, y: float, size: float, width: float, anchor: str = "start") -> Box:
    """The box (x0, y0, x1, y1) of a text of ``width`` at baseline ``(x, y)``: ascent 0.8, descent 0.25 of the
    size (a subscript's drop included)."""
    x0 = x - (width if anchor == "end" else width / 2 if anchor == "middle" else 0.0)
    return (x0, y - 0.8 * size, x0 + width, y + 0.25 * size)


@dataclass
class Texts:
    """The boxes of the texts already on a sheet: a new text takes the first of its candidate places that
    overlaps none (and stays inside ``limits`` when given)."""

    boxes: list[Box] = field(default_factory=list)

    def free(self, b: Box, gap: float = 0.3) -> bool:
        return all(b[2] + gap <= o[0] or o[2] + gap <= b[0] or b[3] + gap <= o[1] or o[3] + gap <= b[1]
                   for o in self.boxes)

    def take(self, b: Box) -> None:
        self.boxes.append(b)

    def place(self, width: float, size: float, spots: Sequence[tuple[float, float, str]],
              limits: Box | None = None) -> tuple[float, float, str]:
        """The first spot ``(x, y, anchor)`` where the text is free (and inside ``limits``), taken; else the last."""
        for x, y, a in spots:
            b = box_of(x, y, size, width, a)
            inside = limits is None or (limits[0] <= b[0] and b[2] <= limits[2] and limits[1] <= b[1]
                                        and b[3] <= limits[3])
            if inside and self.free(b):
                self.take(b)
                return x, y, a
        x, y, a = spots[-1]
        self.take(box_of(x, y, size, width, a))
        return x, y, a


def runs_width(runs: Runs, size: float) -> float:
    return text_width(runs, size)


def text_el(runs: Runs | str, x: float, y: float, size: float, fill: str, anchor: str = "start",
            cls: str = "", bold: bool = False) -> Any:
    """A text element of typeset ``runs`` (a subscript as a smaller lowered tspan, as the Results print it)."""
    size = max(size, MIN_TEXT)
    attrs: dict[str, Any] = {"x": fmt(x), "y": fmt(y), "font_size": fmt(size), "fill": fill}
    if anchor != "start":
        attrs["text_anchor"] = anchor
    if cls:
        attrs["class_"] = cls
    if bold:
        attrs["font_weight"] = "bold"
    if isinstance(runs, str):
        return Element("text", runs, **attrs)
    t = Element("text", **attrs)
    add_runs(t, runs, size, least=MIN_TEXT)
    t.attribs["xml:space"] = "preserve"
    return t


def chart_sheet(title: str, problem: str, recipe: str, number: int = 1, count: int = 1) -> svgwrite.Drawing:
    """An empty A4 portrait chart sheet: frame and title block (``title`` the problem's title; no drawing
    scale: a chart's axes are not lengths)."""
    d = document(SHEET)
    d.attribs["class"] = "sheet chart"
    d.add(title_block(d, SHEET, TitleBlock(title, problem, recipe, None, str(SHEET), number, count, SPEC.lang)))
    return d


def chart_area() -> Box:
    """Where a chart sheet may draw: inside the frame, above the title block, :data:`INSET` clear of both."""
    x0, y0, x1, _ = frame_box(SHEET)
    return (x0 + INSET, y0 + INSET, x1 - INSET, title_block_box(SHEET)[1] - INSET)


__all__ = ["SHEET", "SPEC", "Texts", "axis_factor", "box_of", "chart_area", "chart_sheet", "factor_text", "plain",
           "runs_width", "text_boxes", "text_el", "diagram_axes_marks"]


def text_boxes(svg: str | Element) -> list[Box]:
    """The paper box of every text element of an SVG document or fragment (each tspan measured at its own size),
    as :func:`box_of` estimates it. The fragment may be given as a tree of :class:`~.serial.Element`: its texts
    are read as the written fragment would be parsed (the text typeset, an attribute's None or "" absent),
    without writing and parsing it.

    >>> text_boxes('<g><text x="10" y="20" font-size="2.5" text-anchor="middle">90°</text></g>')
    [(7.85, 18.0, 12.15, 20.625)]
    >>> g = Element("g")
    >>> _ = g.add(Element("text", "90°", x="10", y="20", font_size="2.5", text_anchor="middle"))
    >>> text_boxes(g)
    [(7.85, 18.0, 12.15, 20.625)]
    """
    if isinstance(svg, str):
        import xml.etree.ElementTree as ET
        texts = [(t.get, t.text or "", [(u.text or "", u.get) for u in t if u.tag.endswith("tspan")])
                 for t in ET.fromstring(svg).iter() if t.tag.endswith("text")]
    else:
        texts = _texts_of(svg)
        if texts is None:                       # an svgwrite element inside: read the fragment as written
            from .serial import svg_string
            return text_boxes(svg_string(svg))
    out = []
    for get, text, spans in texts:
        size = float(get("font-size") or 3.0)
        parts = [(text, size)] + [(s, float(sget("font-size") or size)) for s, sget in spans]
        if not "".join(p for p, _ in parts).strip():
            continue
        width = sum(text_width(p, z) for p, z in parts)
        out.append(box_of(float(get("x") or 0.0), float(get("y") or 0.0), size, width, get("text-anchor") or "start"))
    return out


def _texts_of(root: Any) -> list[tuple[Any, str, list[tuple[str, Any]]]] | None:
    """The text elements of a tree of :class:`~.serial.Element` in document order, as :func:`text_boxes` reads
    them: each with its attribute getter, its typeset text and its tspans' (typeset text, getter). None when the
    tree holds another kind of element."""
    from .serial import typeset
    out = []
    stack = [root]
    while stack:
        el = stack.pop()
        if type(el) is not Element:
            return None
        if el.elementname.endswith("text"):
            spans = [(typeset(u.text) if u.text else "", u.attribs.get) for u in el.elements
                     if type(u) is Element and u.elementname.endswith("tspan")]
            out.append((el.attribs.get, typeset(el.text) if el.text else "", spans))
        stack.extend(reversed(el.elements))
    return out


def diagram_axes_marks(dwg: svgwrite.Drawing, view: Any, axes: Any, scale: Any, x: float, y: float,
                       step: int | None = None, avoid: Sequence[Box] = ()) -> Any:
    """The ticks and the scale statement of a cam's s–δ (ψ–δ) diagram drawn by ``view`` (model → paper):
    the δ axis labelled in degrees (0°, 90°, … 360°) on a row below its division numbers, the stroke ticked on
    the ordinate axis (h = 16 mm, ψmax = 20°), and at paper ``(x, y)`` what a printed millimetre means on each
    axis — ``δ: 360° = 180 mm`` and ``s 1:1`` (a length axis at the drawing's ``scale``, as its scale bar) or
    ``ψ: 10° = 9 mm`` (an axis in degrees: no drawing scale holds, no scale bar).

    ``axes`` is a :class:`geomcon.cam.diagrams.DiagramAxes`; ``step`` the protocol number of the step drawing the
    δ axis: the marks show from that step on in the player and the frames, never before the axis. ``avoid``: the
    boxes of the texts already on the sheet (a diagram beside its cam): a degree label that would cover one is
    left out, and the statement moves down until it covers none."""
    placed = Texts(list(avoid))
    from .labels import rich_runs
    g = Element.named("g", {"id": "diagram-axes", "class": "diagram-axes"})
    if step is not None:
        g.attribs["data-step"] = str(step)
    ax, ay = view.xy(*axes.at(0.0, 0.0))
    for d in (0, 90, 180, 270, 360):
        px, _ = view.xy(*axes.at(float(d), 0.0))
        g.add(Element("line", x1=fmt(px), y1=fmt(ay + 5.0), x2=fmt(px), y2=fmt(ay + 6.2), stroke="#1a1a1a",
                      stroke_width="0.2"))
        b = box_of(px, ay + 8.8, 2.5, text_width(f"{d}°", 2.5), "middle")
        if not placed.free(b):
            continue
        placed.take(b)
        g.add(text_el(f"{d}°", px, ay + 8.8, 2.5, "#1a1a1a", anchor="middle", cls="delta-tick"))
    hx, hy = view.xy(*axes.at(0.0, axes.h))
    g.add(Element("line", x1=fmt(hx - 1.5), y1=fmt(hy), x2=fmt(hx), y2=fmt(hy), stroke="#1a1a1a", stroke_width="0.3"))
    words = f"h = {axes.h:g} mm" if axes.length_axis else f"ψmax = {axes.h:g}°"
    g.add(text_el(rich_runs(words), hx - 2.2, hy + 0.9, 2.5, "#1a1a1a", anchor="end", cls="h-tick"))
    mu = view.mu
    along = f"δ: 360° = {plain(360.0 * axes.per_deg / mu)} mm"
    if axes.length_axis:
        up = f"{axes.symbol} {scale}"
    else:
        up = f"{axes.symbol}: 10° = {plain(10.0 * axes.per_unit / mu, 3)} mm"
    said = rich_runs(f"{along};  {up}")
    x, y, _ = placed.place(text_width(said, 3.0), 3.0, [(x, y + 4.0 * k, "start") for k in range(12)])
    g.add(text_el(said, x, y, 3.0, "#1a1a1a", cls="diagram-scales"))
    return g
