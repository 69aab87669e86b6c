"""Paper-space shapes: what a step draws, before it becomes SVG.

Drawing a value produces a few small frozen shapes in paper mm (y down): polylines, arcs, discs and
texts. The same shapes give the SVG elements and the obstacles the label placer keeps clear of, so what
is avoided is exactly what is drawn.

Examples
--------
>>> pen = Pen("#000", 0.35)
>>> el = to_svg(Poly(((0.0, 0.0), (10.0, 0.0)), pen))
>>> el.tostring()
'<path class="ink" d="M0 0L10 0" fill="none" stroke="#000" stroke-linecap="round" stroke-linejoin="round" stroke-width="0.35" />'
>>> round(obstacle(Poly(((0.0, 0.0), (10.0, 0.0)), pen)).length, 6)
10.0
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Union

import numpy as np
import shapely

from .serial import Element
from .style import HALO, HIGHLIGHT, PAPER
from .view import fmt

XY = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Pen:
    """Stroke colour, width and dash pattern (paper mm), with an opacity."""

    stroke: str
    width: float
    dash: tuple[float, ...] = ()
    opacity: float = 1.0


@dataclass(frozen=True, slots=True)
class Poly:
    """A polyline (or closed polygon) through paper points; ``fill`` only for closed ones."""

    pts: tuple[XY, ...]
    pen: Pen
    closed: bool = False
    fill: str = "none"


@dataclass(frozen=True, slots=True)
class ArcP:
    """A circular arc on paper: centre, radius, start angle and signed sweep (radians, paper orientation:
    positive turns clockwise as seen, since y points down)."""

    c: XY
    r: float
    start: float
    sweep: float
    pen: Pen

    def at(self, f: float) -> XY:
        """The point at fraction ``f`` of the arc."""
        a = self.start + f * self.sweep
        return (self.c[0] + self.r * math.cos(a), self.c[1] + self.r * math.sin(a))


@dataclass(frozen=True, slots=True)
class Disc:
    """A circle on paper: a point marker (``fill`` white for a hinge, ink for a dot) or a whole circle."""

    c: XY
    r: float
    pen: Pen | None
    fill: str = "none"


@dataclass(frozen=True, slots=True)
class Text:
    """A text on paper: ``runs`` of (text, subscript?) anchored at ``x`` (``anchor``) on baseline ``y``.

    ``box`` is its estimated extent (x0, y0, x1, y1) before rotation, used as an obstacle; ``rotate``
    turns text and box about the box's centre, in degrees (clockwise as seen).
    """

    x: float
    y: float
    runs: tuple[tuple[str, bool], ...]
    size: float
    fill: str
    box: tuple[float, float, float, float]
    anchor: str = "middle"
    italic: bool = False
    rotate: float = 0.0
    cls: str = "mark-text"


Shape = Union[Poly, ArcP, Disc, Text]


def recolour(shape: Shape, colour: str = HIGHLIGHT) -> Shape:
    """The shape in another ink (white fills and halos stay white)."""
    pen = getattr(shape, "pen", None)
    if pen is not None:
        shape = replace(shape, pen=replace(pen, stroke=colour))
    if isinstance(shape, (Poly, Disc)) and shape.fill not in ("none", PAPER):
        shape = replace(shape, fill=colour)
    if isinstance(shape, Text):
        shape = replace(shape, fill=colour)
    return shape


# ---------------------------------------------------------------------------------------------- SVG
def _pen_attrs(pen: Pen | None) -> dict[str, str]:
    """A pen's attributes as written (``stroke-width``…), remembered by pen (pens are frozen and few: ~40 a
    gallery job); the caller copies them."""
    out = _PENS.get(pen)
    if out is None:
        if pen is None:
            out = {"stroke": "none"}
        else:
            out = {"stroke": pen.stroke, "stroke-width": fmt(pen.width)}
            if pen.dash:
                out["stroke-dasharray"] = " ".join(fmt(d) for d in pen.dash)
            if pen.opacity != 1.0:
                out["stroke-opacity"] = fmt(pen.opacity)
        if len(_PENS) >= 4096:
            _PENS.clear()
        _PENS[pen] = out
    return out


_PENS: dict[Pen | None, dict[str, str]] = {}


def arc_d(a: ArcP) -> str:
    """SVG path data of an arc (split in two when it is a whole turn)."""
    sweep = a.sweep
    if abs(sweep) >= 2 * math.pi - 1e-9:
        h = ArcP(a.c, a.r, a.start, math.copysign(math.pi, sweep), a.pen)
        rest = ArcP(a.c, a.r, a.start + h.sweep, h.sweep, a.pen)
        return arc_d(h) + " " + arc_d(rest)[arc_d(rest).index("A"):]
    (x0, y0), (x1, y1) = a.at(0.0), a.at(1.0)
    r = fmt(a.r)
    large = 1 if abs(sweep) > math.pi else 0
    flag = 1 if sweep > 0 else 0
    return f"M{fmt(x0)} {fmt(y0)}A{r} {r} 0 {large} {flag} {fmt(x1)} {fmt(y1)}"


def to_svg(shape: Shape) -> Element:
    """The SVG element of a shape (:class:`~geomcon.render.serial.Element`: written as svgwrite writes it)."""
    if isinstance(shape, Poly):
        f = fmt
        d = "M" + "L".join([f"{f(x)} {f(y)}" for x, y in shape.pts]) + ("Z" if shape.closed else "")
        return Element.named("path", {"d": d, "fill": shape.fill, "stroke-linecap": "round",
                                      "stroke-linejoin": "round", "class": "ink", **_pen_attrs(shape.pen)})
    if isinstance(shape, ArcP):
        return Element.named("path", {"d": arc_d(shape), "fill": "none", "stroke-linecap": "round", "class": "ink",
                                      **_pen_attrs(shape.pen)})
    if isinstance(shape, Disc):
        cls = "ink" if shape.fill in ("none", PAPER) else "ink dot"
        return Element.named("circle", {"cx": fmt(shape.c[0]), "cy": fmt(shape.c[1]), "r": fmt(shape.r),
                                        "fill": shape.fill, "class": cls, **_pen_attrs(shape.pen)})
    return _text(shape)


def _text(t: Text) -> Element:
    attrs: dict[str, str | None] = {"x": fmt(t.x), "y": fmt(t.y), "font-size": fmt(t.size), "fill": t.fill,
                                    "stroke": PAPER, "stroke-width": fmt(HALO), "stroke-linejoin": "round",
                                    "paint-order": "stroke", "class": t.cls}
    if t.anchor != "start":
        attrs["text-anchor"] = t.anchor
    if t.italic:
        attrs["font-style"] = "italic"
    if t.rotate:
        cx, cy = (t.box[0] + t.box[2]) / 2, (t.box[1] + t.box[3]) / 2
        attrs["transform"] = f"rotate({fmt(t.rotate)} {fmt(cx)} {fmt(cy)})"
    el = Element.named("text", attrs)
    add_runs(el, t.runs, t.size)
    el.attribs["xml:space"] = "preserve"
    return el


def add_runs(el: Any, runs: tuple[tuple[str, bool], ...], size: float, least: float = 0.0) -> None:
    """Append text runs to a text element: subscripts as smaller tspans (``SUB_SCALE`` of ``size``, at least
    ``least``: a title block squeezed to fit keeps subscripts readable) lowered with ``dy`` (the one shift
    every SVG renderer agrees on), the following run raised back. A component's letter written as a modifier
    letter next to a subscript (aʳB2B3, aᵏB3B2, aEDⁿ, aB3ᵗ) is stacked over it as the textbook prints it: the
    letter as a small raised tspan, the subscript shifted back under it with ``dx`` (:func:`stacked_runs`)."""
    shift = 0.0
    small = fmt(max(size * SUB_SCALE, least))
    named = Element.named
    drop = SUB_DROP * size
    for s, _ in runs:
        if s and (s[0] in SUPERSCRIPTS or s[-1] in SUPERSCRIPTS):
            items = stacked_runs(runs, size, least)
            targets = _stacked_targets(items, size)
            break
    else:                                         # nothing to stack (all but ~1 % of a gallery's texts)
        items = [(s, sub, False, 0.0) for s, sub in runs]
        targets = [drop if sub else 0.0 for _, sub in runs]
    for (s, sub, sup, dx), target in zip(items, targets):
        attrs: dict[str, str | None] = {}
        if dx:
            attrs["dx"] = fmt(dx)
        if target != shift:
            attrs["dy"] = fmt(target - shift)
            shift = target
        if sub or sup:
            attrs["font-size"] = small
        el.add(named("tspan", attrs, s))


def _stacked_targets(items: list[tuple[str, bool, bool, float]], size: float) -> list[float]:
    """Each run's shift below the baseline (paper mm) in a text with a stacked letter: the letter raised
    :data:`SUP_RISE`, the subscript under (or before) it lowered :data:`STACK_DROP` (a visible gap), any other
    subscript :data:`SUB_DROP`."""
    out = []
    for i, (_, sub, sup, _) in enumerate(items):
        if sub:
            stacked = (i and items[i - 1][2]) or (i + 1 < len(items) and items[i + 1][2])
            out.append((STACK_DROP if stacked else SUB_DROP) * size)
        else:
            out.append(-SUP_RISE * size if sup else 0.0)
    return out


SUPERSCRIPTS = {"ʳ": "r", "ᵏ": "k", "ⁿ": "n", "ᵗ": "t"}
"""Modifier letters of an acceleration's component (relative, Coriolis, normal, tangential) and the letter each
stands for when stacked over a subscript."""
SUP_EM = {"r": 0.4, "k": 0.5, "n": 0.56, "t": 0.36}
"""The advance of each stacked letter (em, Noto Sans; narrower than :func:`.labels.char_em`'s safe estimate, so
that the subscript shifted back under it does not run into the letter before)."""


def stacked_runs(runs: tuple[tuple[str, bool], ...], size: float, least: float = 0.0
                 ) -> list[tuple[str, bool, bool, float]]:
    """The runs as (text, subscript, superscript, dx): a modifier letter of :data:`SUPERSCRIPTS` at the end of a
    run followed by a subscript, or at the start of a run that follows one, becomes a superscript run stacked
    over that subscript (the later of the two shifted back by the earlier one's estimated width, and what
    follows shifted on past the wider).

    >>> [r[:3] for r in stacked_runs((("aʳ", False), ("B2B3", True), (" = 1", False)), 3.5)]
    [('a', False, False), ('r', False, True), ('B2B3', True, False), (' = 1', False, False)]
    >>> [r[:3] for r in stacked_runs((("a", False), ("ED", True), ("ⁿ = 2", False)), 3.5)]
    [('a', False, False), ('ED', True, False), ('n', False, True), (' = 2', False, False)]
    >>> stacked_runs((("C", False), ("1", True)), 3.5)
    [('C', False, False, 0.0), ('1', True, False, 0.0)]
    """
    for s, _ in runs:
        if s and (s[0] in SUPERSCRIPTS or s[-1] in SUPERSCRIPTS):
            break
    else:
        return [(s, sub, False, 0.0) for s, sub in runs]   # nothing to stack (all but ~1 % of a gallery's texts)
    from .labels import text_width
    small = max(size * SUB_SCALE, least) / size            # what text_width's 0.72 is here

    def width(s: str) -> float:
        return (SUP_EM[s] * size if s in SUP_EM else text_width(s, size)) * small
    out: list[tuple[str, bool, bool, float]] = []
    carry = 0.0                                           # shift owed by the run that comes next
    for i, (s, sub) in enumerate(runs):
        nxt = runs[i + 1] if i + 1 < len(runs) else None
        if not sub and s and s[-1] in SUPERSCRIPTS and nxt is not None and nxt[1]:
            if s[:-1]:
                out.append((s[:-1], False, False, carry))
                carry = 0.0
            out.append((SUPERSCRIPTS[s[-1]], False, True, carry))
            carry = -width(SUPERSCRIPTS[s[-1]])           # the subscript goes back under it
            continue
        if not sub and s and s[0] in SUPERSCRIPTS and out and out[-1][1]:
            low, sup = out[-1][0], SUPERSCRIPTS[s[0]]
            out.append((sup, False, True, carry - width(low)))
            carry = max(0.0, width(low) - width(sup))
            s = s[1:]
            if not s:
                continue
        elif out and out[-1][2] and sub:                  # the subscript under a superscript
            sup = out[-1][0]
            out.append((s, True, False, carry))
            carry = max(0.0, width(sup) - width(s))
            continue
        out.append((s, sub, False, carry))
        carry = 0.0
    return out


SUB_SCALE = 0.72
SUB_DROP = 0.22
SUP_RISE = 0.42
"""A stacked superscript's rise (of the font size) above the baseline."""
STACK_DROP = 0.24
"""The drop (of the font size) of a subscript stacked under a superscript: with :data:`SUP_RISE` the letter's
foot stands 0.15 of the size above the subscript's cap height (0.714 em at :data:`SUB_SCALE`), a visible gap as
a textbook sets aᵏ over B2B3 (at 0.36 / 0.22 the two touched: hlook11m, 000-03's results). Not more: a results
list's lines are 1.3 sizes apart, and a k over one line's subscript must not reach the subscript above it."""


# ---------------------------------------------------------------------------------------------- obstacles
def _arc_points(a: ArcP) -> list[XY]:
    """Points of an arc every ~1 mm of paper: ``a.at(i / (n - 1))``, written out."""
    n = max(2, int(abs(a.sweep) * a.r / 1.0) + 2)     # a vertex every ~1 mm of paper
    (cx, cy), r, start, sweep, cos, sin = a.c, a.r, a.start, a.sweep, math.cos, math.sin
    return [(cx + r * cos(t), cy + r * sin(t)) for t in (start + (i / (n - 1)) * sweep for i in range(n))]


def _line(pts: list[XY]) -> shapely.Geometry:
    """``shapely.LineString(pts)`` (the same coordinates), made from an array in one call."""
    return shapely.linestrings(np.array(pts, dtype=float))


LEAN_TOLERANCE = 0.01
"""How far (paper mm) the line a label keeps clear of may stray from a long drawn polyline (:func:`lean`): a
fifteenth of the thinnest stroke (0.15 mm), far below what a reader or the placer's :data:`.clearance.ENOUGH` can
tell. At 0.02 mm one label of the gallery (001-23b's 3′) found another place, and two more moved after it; at
0.01 mm none moves, and a cam's curves keep as few vertices (001-24: 4 016 vertices in all, 2 106 at 0.01 mm,
2 090 at 0.02 mm)."""

LEAN_FROM = 64
"""Line strings with more vertices than this are thinned for placement (a cam's profile and pitch curve, 0.2 mm a
segment; an arc's vertices are ~1 mm apart and few)."""


def lean(geoms: list[shapely.Geometry], tolerance: float = LEAN_TOLERANCE) -> list[shapely.Geometry]:
    """``geoms`` with every line string of more than :data:`LEAN_FROM` vertices simplified (Douglas–Peucker,
    ``shapely.simplify``) to within ``tolerance``: what labels keep clear of, with a tenth as many segments to
    measure (a cam's 0.2 mm segments); the drawn stroke itself is unchanged. Areas, points and short lines are returned as they are.

    Examples
    --------
    >>> t = np.linspace(0.0, math.pi, 800)
    >>> arc = shapely.LineString(np.stack([20 * np.cos(t), 20 * np.sin(t)], axis=1))
    >>> thin, = lean([arc])
    >>> int(shapely.get_num_coordinates(thin)), thin.hausdorff_distance(arc) <= 0.01
    (65, True)
    """
    g = np.empty(len(geoms), dtype=object)
    g[:] = geoms
    long = np.flatnonzero((shapely.get_type_id(g) == 1) & (shapely.get_num_coordinates(g) > LEAN_FROM))
    if len(long):
        g[long] = shapely.simplify(g[long], tolerance, preserve_topology=False)
    return g.tolist()


def text_polygon(t: Text) -> shapely.Geometry:
    """The estimated box of a text, rotated as drawn."""
    x0, y0, x1, y1 = t.box
    box = shapely.box(x0, y0, x1, y1)
    if t.rotate:
        from shapely import affinity
        box = affinity.rotate(box, t.rotate, origin="center")
    return box


def _snapped(angle: float) -> tuple[float, float]:
    """Cosine and sine of ``angle`` with those below 5e-16 put to 0 (as GEOS's ``Angle::sinCosSnap``)."""
    c, s = math.cos(angle), math.sin(angle)
    return (0.0 if abs(c) < 5e-16 else c), (0.0 if abs(s) < 5e-16 else s)


_ROUND = np.array([_snapped(-i * (2.0 * math.pi / 32)) for i in (*range(32), 0)])
"""The unit circle as GEOS buffers a point with 8 segments a quadrant: 32 vertices from angle 0 clockwise (on
paper, y down: anticlockwise as seen), the ring closed."""


def disc_polygon(cx: float, cy: float, r: float) -> shapely.Geometry:
    """``shapely.Point(cx, cy).buffer(r, 8)`` (a filled disc as an area), its vertices computed as GEOS computes
    them (``OffsetSegmentGenerator::createCircle``: ``c + r · (cos, sin)`` of the angles ``-i · 2π/32``, each
    snapped): the same coordinates in the same order, without a buffer operation.

    >>> p = disc_polygon(3.7, -1.2, 0.55)
    >>> shapely.get_coordinates(p).tolist() == shapely.get_coordinates(shapely.Point(3.7, -1.2).buffer(0.55, 8)).tolist()
    True
    """
    if not r > 0.0:
        return shapely.Point(cx, cy).buffer(r, 8)
    ring = _ROUND * r
    ring += (cx, cy)
    return shapely.polygons(ring)


_OBSTACLES: dict[int, tuple[Shape, shapely.Geometry]] = {}
""":func:`obstacle` of the shapes met lately, by ``id`` (each entry holds its shape, so that the id is not
reused while it is here; shapes are frozen, and so are shapely geometries): a figure's shapes are measured by
the label placer and again by the free-room search of its sheet."""
_OBSTACLES_MAX = 8192


def obstacle(shape: Shape) -> shapely.Geometry:
    """The shapely geometry a label must keep clear of: strokes as lines, markers and texts as areas (the same
    object for the same shape while it is remembered)."""
    hit = _OBSTACLES.get(id(shape))
    if hit is not None and hit[0] is shape:
        return hit[1]
    geom = _obstacle(shape)
    if len(_OBSTACLES) >= _OBSTACLES_MAX:
        _OBSTACLES.clear()
    _OBSTACLES[id(shape)] = (shape, geom)
    return geom


def _obstacle(shape: Shape) -> shapely.Geometry:
    if isinstance(shape, Poly):
        pts = list(shape.pts) + ([shape.pts[0]] if shape.closed else [])
        if shape.closed and shape.fill != "none" and len(pts) > 3:
            return shapely.Polygon(shape.pts)
        return _line(pts) if len(pts) > 1 else shapely.Point(pts[0])
    if isinstance(shape, ArcP):
        return _line(_arc_points(shape))
    if isinstance(shape, Disc):
        if shape.fill == "none":
            return _line(_arc_points(ArcP(shape.c, shape.r, 0.0, 2 * math.pi, Pen("", 0))))
        return disc_polygon(*shape.c, shape.r + (shape.pen.width / 2 if shape.pen else 0.0))
    return text_polygon(shape)

