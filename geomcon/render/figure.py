"""The figure of a frame: the values of the steps shown, drawn on paper, labelled, sorted into layers.

Building a figure evaluates exactly the steps it shows (and what they depend on); it never looks at a
later step. Labels are placed after every shape of the frame is known, greedily in step order.

Examples
--------
>>> from geomcon.recipes.crank_rocker import construct
>>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
>>> fig = build_figure(sc, upto=3)
>>> [g.key for g in fig.groups][:3]
['A', 'A_ground', 'D']
>>> sc.is_evaluated("C1")
False
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Iterable

import numpy as np
import shapely
import shapely.ops

from ..geometry.primitives import Arc, Circle, Line, Point, Polyline, Ray, Segment
from ..scene import Scene, Step
from ..scene.marks import AngleMark, Dimension, Ground, Guide, RightAngleMark, Rotation, Slider
from .arms import add_arms
from .boxgeom import box_point
from .coincident import NEAR as NEAR_NAMES, Together, dots_above, groups_of, same_spot, shared_markers
from .draw import (RIVAL_REACH, Context, Drawn, TextRequest, _paper_dir, _rivals, compass_half, compass_steps,
                   draw_compass)
from .clearance import ENOUGH, NEAR as HALO
from .candidates import FAR_PENALTY, LEADER_MAX, between
from .placement import AMBIGUOUS, Placer, Request, half_extent, label_distances, nearer_rival
from .rows import SEP, Fan, clusters, fans, row_centre, thinned
from .joined import reads_back, spans
from .keepoff import BAND_WIDTH, RING_WIDTH, kept_off
from .labels import label_extent, text_width
from .shapes import ArcP, Disc, Pen, Poly, Shape, Text, lean, obstacle, recolour
from .style import HIGHLIGHT, INK, LAYERS, PAPER, STYLES, TRIM_OVERSHOOT, highlighted, resolve_style
from .symbols import (HINGE_CUT, dimension_lines, draw, ground_choice, guide_bands, kind_of, right_angle_square,
                      rotation_arcs, rotation_inside, sector)
from .view import FIG_MARGIN, FIG_TARGET, Box, View, choose_scale, grow

WHOLE_CIRCLE_REACH = 0.75   # a whole-drawn circle enlarges the view when r ≤ this × the content's size
CROWDED = 0.5              # a text placed with less clearance (paper mm) tries its shorter form
SOFT = 0.5                 # clearance allowance for crossing a thin construction line (paper mm)
OUTWARD_TURNS = tuple(math.radians(a) for a in (0.0, 25.0, -25.0, 50.0, -50.0))
"""Directions (off the outward ray from a cam's centre) at which a division's number is tried, nearest first."""
LEADER_FROM = 3.0          # a mark text farther than this from its arc gets a leader line (paper mm)
SMALL_CIRCLE = 0.25         # any circle with r ≤ this × the content's size fits in the view


@dataclass
class StepDrawing:
    """One step on paper: its key, protocol number, classes, layer and shapes (placed texts included)."""

    key: str
    number: int
    classes: str
    layer: str
    shapes: list[Shape] = field(default_factory=list)
    arc: bool = False
    """A compass circle's arcs drawn by a later step (the one constructing their point): not a step's group."""

    @property
    def texts(self) -> list[Text]:
        """The step's texts (labels, mark values)."""
        return [s for s in self.shapes if isinstance(s, Text)]


@dataclass
class Figure:
    """A frame's drawing: the view and the step drawings in step order."""

    view: View
    groups: list[StepDrawing]
    values: dict[str, Any]
    shown: int

    def layers(self) -> list[tuple[str, list[StepDrawing]]]:
        """The step drawings by layer, bottom layer first; in the points layer the hinges' before the dots
        (:func:`.coincident.dots_above`)."""
        return [(name, dots_above([g for g in self.groups if g.layer == name], _hollow) if name == "points"
                 else [g for g in self.groups if g.layer == name]) for name in LAYERS]


def _hollow(g: StepDrawing) -> bool:
    """Whether the step draws a hollow marker (a hinge's, a candidate's circle: white inside)."""
    return any(isinstance(sh, Disc) and sh.fill == PAPER for sh in g.shapes)


# ---------------------------------------------------------------------------------------------- extent
def shown_steps(scene: Scene, upto: int | None, keep: Callable[[Step], bool] | None = None
                ) -> tuple[list[tuple[int, Step]], int]:
    """The (number, step) pairs of frames 1…upto (only the steps ``keep`` keeps, when given: a sheet that draws
    part of the construction) and the number of frames shown."""
    frames = scene.frames()
    n = len(frames) if upto is None else max(0, min(int(upto), len(frames)))
    return [(i, s) for i, group in enumerate(frames[:n], 1) for s in group if keep is None or keep(s)], n


def _points_of(v: Any) -> list[Point]:
    if isinstance(v, Point):
        return [v]
    if isinstance(v, (tuple, list)):
        return [p for x in v for p in _points_of(x)]
    if isinstance(v, (Segment, Guide)):
        return [v.a, v.b]
    if isinstance(v, Ray):
        return [v.origin]
    if isinstance(v, Dimension):
        shift = (v.b - v.a).unit().perp() * v.offset if v.a != v.b else Point(0, 0)
        return [v.a, v.b, v.a + shift, v.b + shift]
    if isinstance(v, (Ground, Slider)):
        return [v.at]
    if isinstance(v, (AngleMark, RightAngleMark)):
        return [v.vertex]
    if isinstance(v, Arc):
        return [v.at(i / 8) for i in range(9)]
    if isinstance(v, Polyline):
        return list(v.points)
    return []


def _circles_of(v: Any) -> list[Circle]:
    if isinstance(v, Circle):
        return [v]
    if isinstance(v, (tuple, list)):
        return [c for x in v for c in _circles_of(x)]
    return []


def _bbox(points: Iterable[Point]) -> Box:
    """The bounds of ``points`` (one pass for each coordinate; a cam's profile brings thousands).

    >>> _bbox([Point(1, 5), Point(-2, 3)])
    (-2.0, 3.0, 1.0, 5.0)
    """
    pts = points if isinstance(points, list) else list(points)
    xs = [p.x for p in pts]
    ys = [p.y for p in pts]
    return (min(xs), min(ys), max(xs), max(ys))


def content_box(scene: Scene, steps: list[tuple[int, Step]], values: dict[str, Any]) -> Box:
    """Model box of the drawn points, segments and marks, plus the circles that fit (small ones, and the
    whole-drawn paths and θ-circles not much larger than the rest); other circles and infinite lines are
    clipped to it instead."""
    pts = [p for _, s in steps for p in _points_of(values[s.key])]
    if not pts:
        return (-5.0, -5.0, 5.0, 5.0)
    box = _bbox(pts)
    size = max(box[2] - box[0], box[3] - box[1])
    if size == 0.0:
        size = max(abs(box[0]), abs(box[1]), 1.0) * 0.1
    extra = []
    for _, s in steps:
        for c in _circles_of(values[s.key]):
            style = resolve_style(s.style, s.role, "curve")
            if c.r <= SMALL_CIRCLE * size or (not style.compass and c.r <= WHOLE_CIRCLE_REACH * size):
                extra += [c.center - Point(c.r, c.r), c.center + Point(c.r, c.r)]
    x0, y0, x1, y1 = box
    if extra:               # the points' box and the circles' together (min and max are exact: the same floats)
        c0, d0, c1, d1 = _bbox(extra)
        x0, y0, x1, y1 = min(x0, c0), min(y0, d0), max(x1, c1), max(y1, d1)
    w, h = x1 - x0, y1 - y0
    size = max(w, h, size)
    dw, dh = max(0.0, 0.2 * size - w) / 2, max(0.0, 0.2 * size - h) / 2     # never a flat box
    return (x0 - dw, y0 - dh, x1 + dw, y1 + dh)


def fit_view(content: Box, target: float = FIG_TARGET) -> Box:
    """The view box: the content plus :data:`FIG_MARGIN` paper mm on every side at the scale chosen."""
    w, h = content[2] - content[0], content[3] - content[1]
    mu = choose_scale(w, h, FIG_MARGIN, target)
    return grow(content, FIG_MARGIN * mu)


# ---------------------------------------------------------------------------------------------- building
def build_figure(scene: Scene, upto: int | None = None, viewbox: Box | None = None,
                 origin: tuple[float, float] = (0.0, 0.0), target: float = FIG_TARGET,
                 mu: float | None = None, keep: Callable[[Step], bool] | None = None,
                 room: Box | None = None, sketch: Sketch | None = None) -> Figure:
    """Evaluate frames 1…upto and draw them; the current frame (``upto``, when given) is highlighted;
    ``target`` is the paper width aimed at, unless the scale ``mu`` (model mm per paper mm) is given: then the
    view is ``viewbox``, or the content with :data:`FIG_MARGIN` paper mm around it, drawn at exactly ``mu``;
    ``keep`` draws only the steps it keeps (a cam on one sheet, its s–δ diagram on another); ``room`` is the
    paper box about the view where a text that would meet a link, a ground, a block or a pin in the view may go
    instead (:func:`text_room`). ``sketch``: the figure's strokes drawn already (:func:`sketch_figure` of the same
    arguments), whose texts are placed now."""
    if sketch is None:
        sketch = sketch_figure(scene, upto, viewbox, origin, target, mu, keep)
    _place_texts(sketch.view, sketch.groups, sketch.pending, sketch.apart, room)
    return Figure(sketch.view, sketch.groups, sketch.values, sketch.shown)


@dataclass
class Sketch:
    """A figure before its texts are placed (:func:`sketch_figure`): the view, the step drawings with every stroke,
    marker and symbol (placing the texts only adds texts and leaders to them), what each step's texts ask for, the
    ids of the shapes its own step's text keeps clear of too (an angle's rays), the values and the frames shown.
    A layout search asks it whether the sheet's free room may hold the results before it places the texts
    (:func:`geomcon.render.svg.sheet_one`)."""

    view: View
    groups: list[StepDrawing]
    pending: list[tuple[Drawn, bool]]
    apart: set[int]
    values: dict[str, Any]
    shown: int

    @property
    def shapes(self) -> list[Shape]:
        """Every shape drawn so far (a subset of the finished figure's)."""
        return [s for g in self.groups for s in g.shapes]


def sketch_figure(scene: Scene, upto: int | None = None, viewbox: Box | None = None,
                  origin: tuple[float, float] = (0.0, 0.0), target: float = FIG_TARGET,
                  mu: float | None = None, keep: Callable[[Step], bool] | None = None) -> Sketch:
    """:func:`build_figure` up to placing the texts: the strokes, markers and symbols drawn, the texts asked for."""
    steps, n = shown_steps(scene, upto, keep)
    values = scene.evaluate([s.key for _, s in steps])
    if mu is None:
        box = viewbox or fit_view(content_box(scene, steps, values), target)
        mu = choose_scale(box[2] - box[0], box[3] - box[1], 0.0, target)
    else:
        box = viewbox or grow(content_box(scene, steps, values), FIG_MARGIN * mu)
    view = View(box, mu, origin)
    numbered = [(n, v) for n, s in steps for v in [values[s.key]] if isinstance(v, Point)]
    pts = tuple(p for _, p in numbered)
    ctx = Context(view, pts, _centre(view, pts), links=_links(steps, values, view),
                  frames=_links(steps, values, view, frame=True), numbers=tuple(n for n, _ in numbered),
                  sliders=_sliders(steps, values, view), sectors=_sectors(steps, values, view),
                  curves=_curves(steps, values, view),
                  dims=dimension_lines([m for _, s in steps for m in _all(values[s.key])], view),
                  guides=guide_bands([m for _, s in steps for m in _all(values[s.key])], view))
    ctx.strokes = _strokes(steps, values, ctx)
    ctx.turns = rotation_turns([m for _, s in steps for m in _all(values[s.key])], ctx)
    ctx.sectors += tuple(rotation_inside(a) for a in ctx.turns.values())     # a ground keeps off ω (200-10's O)
    current = n if upto is not None else None
    frame_lines = _frame_lines(steps, values, view)
    labels = merged_labels(steps, values, box)
    together = {t.keys[0]: t for t in _together(steps, values, labels, view)}
    quiet = {k for t in together.values() for k in t.keys[1:]}         # named by the first point's label
    near: dict[str, TextRequest | None] = {k: None for t in together.values() if NEAR_NAMES in t.joins for k in t.keys}
    shared = _shared(steps, values, box, current)
    groups, pending = [], []
    for number, s in steps:
        value = values[s.key]
        kind = kind_of(value)
        style = resolve_style(s.style, s.role, kind)
        is_cur = number == current
        layer = "points" if kind == "point" else (style.layer if kind != "none" else "given")
        cls = f"step role-{s.role.value} style-{style.name if kind != 'none' else (s.style or 'none')}"
        later: list[tuple[int, list[tuple[float, float]]]] = []
        if style.compass and isinstance(value, Circle):      # an arc through a later point: with that point's step
            (_, own), *later = compass_steps(value, ctx, number, compass_half(value, ctx))
            drawn = draw_compass(value, own, highlighted(style) if is_cur else style, ctx)
        else:
            shape = trimmed(scene, s, value, mu) if style.trim and type(value) is Line else value
            own = labels.get(s.key, s.label)
            label = None if s.key in quiet else together[s.key].text if s.key in together else own
            drawn = draw(shape, highlighted(style) if is_cur else style, ctx, label)
            if frame_lines and style.layer == "construction" and kind == "curve":     # not a link on AD
                drawn.shapes = off_frames(drawn.shapes, frame_lines)
            if s.key in together:
                drawn.texts[-1] = _joined(drawn.texts[-1], together[s.key], ctx)
            if s.key in shared:                     # its spot's marker is another point's (one marker, one point)
                drawn.shapes = [sh for sh in drawn.shapes if not isinstance(sh, Disc)]
            if s.key in near:                       # its own label, printed if the joined one finds no room
                near[s.key] = draw(value, highlighted(style) if is_cur else style, ctx, own).texts[-1]
        groups.append(StepDrawing(s.key, number, cls + (" current" if is_cur else ""), layer, list(drawn.shapes)))
        pending.append((drawn, is_cur))
        for m, parts in later:
            arcs = draw_compass(value, parts, highlighted(style) if m == current else style, ctx)
            groups.append(StepDrawing(s.key, m, "arc" + cls[4:] + (" current" if m == current else ""), layer,
                                      list(arcs.shapes), arc=True))
            pending.append((arcs, m == current))
    for head, group in together.items():
        if NEAR_NAMES in group.joins:
            i = next(i for i, g in enumerate(groups) if g.key == head and not g.arc)
            texts = pending[i][0].texts
            texts[-1] = replace(texts[-1], alone=tuple((k, near[k]) for k in group.keys if near[k] is not None))
    rays, moved = add_arms(groups, values)
    for drawn, _ in pending:                    # a mark's text follows its arc drawn smaller
        drawn.texts[:] = [replace(t, request=replace(t.request, anchor=moved[t.request.anchor]))
                          if t.request.anchor in moved else t for t in drawn.texts]
    return Sketch(view, groups, pending, {id(r) for r in rays}, values, n)


def text_room(view: View, area: Box) -> Box:
    """The paper box of sheet 1 a text of its figure that finds no place clear of the links in the view may take
    (:func:`_place_texts`): the view's paper box, widened to the drawing's ``area`` left, right and above (the
    view lies centred in it; below it comes the scale bar). The view's :data:`FIG_MARGIN` is room enough for a
    point's label, not for a mark's value beside a pivot at the drawing's edge: 001-21 printed φ1 across the
    rocker and φ2 on D's ground, the free place by their arcs lying beyond the view box though on the sheet.

    >>> text_room(View((0.0, 0.0, 100.0, 50.0), 1.0, (50.0, 40.0)), (20.0, 10.0, 270.0, 150.0))
    (20.0, 10.0, 270.0, 90.0)
    """
    x0, y0, x1, y1 = view.paper_box
    return (min(x0, area[0]), min(y0, area[1]), max(x1, area[2]), y1)


def _frame_lines(steps: list[tuple[int, Step]], values: dict[str, Any], view: View) -> tuple[tuple[Any, Any], ...]:
    """The lines drawn dash-dot (style ``frame``: the fixed link AD, a frame line given whole) on paper, as
    segments; a line or ray reaching far beyond the view."""
    out = []
    far = 1e3 * max(view.box[2] - view.box[0], view.box[3] - view.box[1], 1.0)
    for _, s in steps:
        if resolve_style(s.style, s.role, "curve").name != "frame":
            continue
        for x in _all(values[s.key]):
            if isinstance(x, Segment) and x.a != x.b:
                out.append((view.p(x.a), view.p(x.b)))
            elif isinstance(x, Line):
                d = x.direction * (far / max(abs(x.direction), 1e-300))
                out.append((view.p(x.point - d), view.p(x.point + d)))
            elif isinstance(x, Ray):
                d = x.direction * (far / max(abs(x.direction), 1e-300))
                out.append((view.p(x.origin), view.p(x.origin + d)))
    return tuple(out)


def off_frames(shapes: list[Shape], frames: tuple[tuple[Any, Any], ...], tol: float = 0.05) -> list[Shape]:
    """``shapes`` with every straight piece (a two-point open :class:`~.shapes.Poly`) cut where it runs along a
    fixed link drawn dash-dot (``frames``, paper segments): a grey line over the frame line AD would show in the
    gaps of its dash-dot. Collinear within ``tol`` paper mm; pieces shorter than 0.1 mm are dropped.

    >>> from geomcon.render.shapes import Pen
    >>> line = Poly(((0.0, 0.0), (10.0, 0.0)), Pen("#000", 0.2))
    >>> [s.pts for s in off_frames([line], (((2.0, 0.0), (5.0, 0.0)),))]
    [((0.0, 0.0), (2.0, 0.0)), ((5.0, 0.0), (10.0, 0.0))]
    >>> [s.pts for s in off_frames([line], (((2.0, 1.0), (5.0, 1.0)),))]       # parallel, 1 mm off: kept
    [((0.0, 0.0), (10.0, 0.0))]
    """
    out: list[Shape] = []
    for sh in shapes:
        if not isinstance(sh, Poly) or sh.closed or len(sh.pts) != 2:
            out.append(sh)
            continue
        (x0, y0), (x1, y1) = sh.pts
        dx, dy = x1 - x0, y1 - y0
        n2 = dx * dx + dy * dy
        if n2 == 0.0:
            out.append(sh)
            continue
        n = math.sqrt(n2)
        cuts = []
        for (ax, ay), (bx, by) in frames:
            if (abs(dx * (ay - y0) - dy * (ax - x0)) > tol * n or abs(dx * (by - y0) - dy * (bx - x0)) > tol * n):
                continue
            ta, tb = ((ax - x0) * dx + (ay - y0) * dy) / n2, ((bx - x0) * dx + (by - y0) * dy) / n2
            cuts.append((min(ta, tb), max(ta, tb)))
        if not cuts:
            out.append(sh)
            continue
        pieces = [(0.0, 1.0)]
        for c0, c1 in cuts:
            pieces = [q for a, b in pieces for q in ((a, min(b, c0)), (max(a, c1), b))]
        for a, b in pieces:
            if (b - a) * n >= 0.1:
                out.append(replace(sh, pts=((x0 + dx * a, y0 + dy * a), (x0 + dx * b, y0 + dy * b))))
    return out


def trimmed(scene: Scene, step: Step, line: Line, mu: float) -> Line | Segment:
    """A trimmed-style line (:attr:`~.style.Style.trim`: a polygon's direction line) as the segment the
    construction needs: from the first to the last of its points — those it is drawn through (its arguments)
    and those found on it (the points of the steps taking it as an argument, evaluated though not yet shown, so
    that every frame draws it alike) — :data:`~.style.TRIM_OVERSHOOT` paper mm (``mu`` model mm per paper mm)
    beyond each; the line itself when fewer than two are known.

    >>> from geomcon.scene import Scene
    >>> from geomcon.geometry import line_line, parallel
    >>> sc = Scene("t")
    >>> p = sc.given_at("p", 0.0, 0.0)
    >>> l1 = sc.add("l1", Line, p, Point(1.0, 0.0), style="direction")
    >>> l2 = sc.add("l2", Line, Point(30.0, -5.0), Point(0.0, 1.0))
    >>> x = sc.add("x", lambda a, b: line_line(a, b)[0], l1, l2)
    >>> trimmed(sc, sc["l1"], sc.value("l1"), 1.0)
    Segment(a=Point(x=-6.0, y=0.0), b=Point(x=36.0, y=0.0))
    """
    deps = set(step.deps())
    keys = [k for k in deps] + [s.key for s in scene.visible_steps() if step.key in s.deps()]
    values = scene.evaluate(keys)
    d = line.direction
    n = abs(d)
    ts = []
    for v in values.values():
        if isinstance(v, Point):
            r = v - line.point
            if abs(r.cross(d)) <= 1e-9 * max(1.0, abs(r)) * n:
                ts.append(r.dot(d) / n)
    if len(ts) < 2 or n == 0.0:
        return line
    u = d * (1.0 / n)
    lo, hi = min(ts) - TRIM_OVERSHOOT * mu, max(ts) + TRIM_OVERSHOOT * mu
    return Segment(line.point + u * lo, line.point + u * hi)


def _links(steps: list[tuple[int, Step]], values: dict[str, Any], view: View, frame: bool = False
           ) -> tuple[tuple[Any, Any], ...]:
    """The links of the frame (segments of a style on the links layer) on paper; with ``frame``, the fixed links
    drawn dash-dot instead (style ``frame``: AD between the pivots)."""
    out = []
    for _, s in steps:
        v = values[s.key]
        segs = [x for x in (v if isinstance(v, (tuple, list)) else (v,)) if isinstance(x, Segment) and x.a != x.b]
        style = resolve_style(s.style, s.role, "curve")
        if segs and (style.name == "frame" if frame else style.layer == "links"):
            out += [(view.p(x.a), view.p(x.b)) for x in segs]
    return tuple(out)


def _curves(steps: list[tuple[int, Step]], values: dict[str, Any], view: View) -> tuple[tuple[Any, ...], ...]:
    """The curves drawn as links (a cam's profile: polylines of a style on the links layer) on paper."""
    out = []
    for _, s in steps:
        v = values[s.key]
        lines = [x for x in (v if isinstance(v, (tuple, list)) else (v,)) if isinstance(x, Polyline)]
        if lines and resolve_style(s.style, s.role, "curve").layer == "links":
            out += [tuple(view.ps(x.points + (x.points[:1] if x.closed else ()))) for x in lines]
    return tuple(out)


def _strokes(steps: list[tuple[int, Step]], values: dict[str, Any], ctx: Context) -> tuple[tuple[Any, float], ...]:
    """The circles, arcs and wide bands of the frame on paper that a ground symbol and a rotation arrow keep off
    (:func:`.keepoff.kept_off`), as (shape, half its pen width); none without a ground or a rotation to draw."""
    if not any(isinstance(m, (Ground, Rotation)) for _, s in steps for m in _all(values[s.key])):
        return ()
    out = []
    for _, s in steps:
        v = values[s.key]
        if kind_of(v) != "curve":
            continue
        style = resolve_style(s.style, s.role, "curve")
        if style.width < RING_WIDTH - 1e-9 or (style.compass and style.width < BAND_WIDTH - 1e-9):
            continue
        out += [(sh, style.width / 2.0) for sh in draw(v, style, ctx).shapes if kept_off(style, sh)]
    return tuple(out)


def rotation_turns(marks: list[Any], ctx: Context) -> dict[tuple[float, float], ArcP]:
    """The arc of the arrow of each sense of rotation among ``marks``, by its paper centre: the first that meets
    least (:func:`.symbols.rotation_arcs`) that the ground at its centre, drawn as if no arrow were there, keeps
    clear of (200-09's O: ω above to the right, as likely as below to the left, left O's ground no room between
    r0's dimension and the limit bands), else the first. Such a ground stays where it is once the arrow is drawn
    (an obstacle more only makes its earlier turns meet more): it is kept in ``ctx.ground_at``."""
    out = {}
    for m in marks:
        if not isinstance(m, Rotation):
            continue
        c = ctx.view.p(m.at)
        arcs = rotation_arcs(m, ctx)
        out[c] = arcs[0]
        grounds = [g for g in marks if isinstance(g, Ground) and ctx.view.p(g.at) == c]
        if len(arcs) < 2 or len(grounds) != 1:
            continue
        hit, drawn = ground_choice(grounds[0], STYLES["ground"], ctx)
        if hit != 0.0:
            continue
        geo = shapely.MultiLineString([list(sh.pts) for sh in drawn.shapes]).difference(shapely.Point(c).buffer(HINGE_CUT, 8))
        for arc in arcs:
            if shapely.intersection(geo, shapely.Polygon(rotation_inside(arc))).length == 0.0:
                out[c] = arc
                ctx.ground_at[(c, grounds[0].angle)] = (STYLES["ground"], drawn)
                break
    return out


def _sliders(steps: list[tuple[int, Step]], values: dict[str, Any], view: View) -> tuple[tuple[Any, Any], ...]:
    """The slider blocks of the frame on paper, as (centre, unit direction)."""
    out = []
    for _, s in steps:
        v = values[s.key]
        for x in (v if isinstance(v, (tuple, list)) else (v,)):
            if isinstance(x, Slider):
                out.append((view.p(x.at), _paper_dir(x.direction)))
    return tuple(out)


def _sectors(steps: list[tuple[int, Step]], values: dict[str, Any], view: View) -> tuple[tuple[Any, ...], ...]:
    """The angle marks of the frame on paper as polygons: the vertex and its arc, at the largest radius the
    mark may take (:func:`geomcon.render.symbols.sector`), then the right angles' squares
    (:func:`geomcon.render.symbols.right_angle_square`)."""
    marks = [m for _, s in steps for m in _all(values[s.key]) if isinstance(m, AngleMark)]
    at: dict[tuple[float, float], int] = {}
    for m in marks:
        key = (round(m.vertex.x, 9), round(m.vertex.y, 9))
        at[key] = at.get(key, 0) + 1
    squares = [q for _, s in steps for m in _all(values[s.key]) if isinstance(m, RightAngleMark)
               for q in [right_angle_square(m, view, 1.0)] if q]      # a right angle's square, 1 mm beyond
    return tuple(p for m in marks for p in [sector(m, view, at[(round(m.vertex.x, 9), round(m.vertex.y, 9))])]
                 if p) + tuple(squares)


def _all(v: Any) -> list[Any]:
    return [m for x in v for m in _all(x)] if isinstance(v, (tuple, list)) else [v]


def merged_labels(steps: list[tuple[int, Any]], values: dict[str, Any], box: Box) -> dict[str, str | None]:
    """Labels of points drawn on top of a labelled candidate point (the textbook's choice among candidates):
    the result carries both, ``"D (D1)"``, and the candidate none, so that two labels never fight for one
    spot. Points coincide within 1e-9 of the drawing's size."""
    eps = 1e-9 * max(box[2] - box[0], box[3] - box[1])
    cands = [(s.key, s.label, values[s.key]) for _, s in steps
             if s.style == "candidate" and s.label and isinstance(values[s.key], Point)]
    out: dict[str, str | None] = {}
    for _, s in steps:
        p = values[s.key]
        if s.style == "candidate" or not s.label or not isinstance(p, Point):
            continue
        same = [(k, lab) for k, lab, q in cands if abs(q - p) <= eps and k not in out]
        if same:
            out[s.key] = f"{s.label} ({same[0][1]})"
            out[same[0][0]] = None
    return out


def _together(steps: list[tuple[int, Step]], values: dict[str, Any], labels: dict[str, str | None], view: View
              ) -> list[Together]:
    """The labelled points of the frame drawn closer than a label's height, grouped (:mod:`.coincident`); the
    numbered rows and axis ticks keep their own labels."""
    pts = []
    for _, s in steps:
        v, label = values[s.key], labels.get(s.key, s.label)
        if isinstance(v, Point) and label:
            style = resolve_style(s.style, s.role, "point")
            if not style.label_optional and style.label_dir is None:
                pts.append((s.key, label, v, style.radius))
    return groups_of(pts, view)


def _shared(steps: list[tuple[int, Step]], values: dict[str, Any], box: Box, current: int | None) -> set[str]:
    """The points drawn with no marker of their own: another point's marks their spot (:mod:`.coincident`)."""
    pts = [(s.key, values[s.key], resolve_style(s.style, s.role, "point").radius) for _, s in steps
           if isinstance(values[s.key], Point)]
    return shared_markers(pts, same_spot(box), {s.key for n, s in steps if n == current})


def _joined(t: TextRequest, group: Together, ctx: Context) -> TextRequest:
    """The label of a group of points: about the group, clear of every marker, in parts (one per point's step);
    its rivals are the other points a box that wide may come near."""
    anchor, gap = group.anchor()
    parts = group.parts()
    runs = tuple(r for _, part in parts for r in part)      # measured as printed: its subscripts hang below
    width, height = label_extent(runs, t.size)
    mates = set(group.at)
    rivals = tuple(q for q in _rivals(anchor, ctx, RIVAL_REACH + width) if q not in mates)
    own = tuple((text_width(part, t.size), p) for (_, part), p in zip(parts, (p for p, n in zip(group.at, group.names)
                                                                               if n)))
    req = replace(t.request, anchor=anchor, gap=gap, rivals=rivals, distances=label_distances(gap),   # within reach
                  width=width, height=height, parts=own)
    return replace(t, runs=runs, request=req, fallback=None, parts=parts)


def _centre(view: View, pts: tuple[Point, ...]) -> tuple[float, float]:
    if not pts:
        x0, y0, x1, y1 = view.paper_box
        return ((x0 + x1) / 2, (y0 + y1) / 2)
    xs = [view.p(p)[0] for p in pts]
    ys = [view.p(p)[1] for p in pts]
    return ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)


def _rows(groups: list[StepDrawing], pending: list[tuple[Drawn, bool]]) -> list[list[tuple[int, TextRequest]]]:
    """The numbered rows of the frame: the optional labels (a cam's divisions, an axis's ticks) of each style,
    in step order, as (group index, text) pairs."""
    rows: dict[str, list[tuple[int, TextRequest]]] = {}
    for i, (g, (drawn, _)) in enumerate(zip(groups, pending)):
        for t in drawn.texts:
            if t.optional:
                style = next((c for c in g.classes.split() if c.startswith("style-")), "")
                rows.setdefault(style, []).append((i, t))
    return list(rows.values())


def _thin(groups: list[StepDrawing], pending: list[tuple[Drawn, bool]]) -> None:
    """Leave out the numbers of a crowded row of counting numbers on a line (a style with ``label_thin``: the
    divisions 1, 2, … of an s–δ diagram's δ axis) but every 2nd, 4th, … (:func:`.rows.thinned`)."""
    rows: dict[str, list[tuple[int, TextRequest]]] = {}
    for i, (g, (drawn, _)) in enumerate(zip(groups, pending)):
        style = next((c[6:] for c in g.classes.split() if c.startswith("style-")), "")
        if style in STYLES and STYLES[style].label_thin:
            rows.setdefault(style, []).extend((i, t) for t in drawn.texts if t.optional)
    for row in rows.values():
        kept = set(thinned([t.request.anchor for _, t in row], [(t.request.width, t.request.height) for _, t in row],
                           SEP))
        for k, (i, t) in enumerate(row):
            if k not in kept:
                pending[i][0].texts.remove(t)


def _outward(groups: list[StepDrawing], pending: list[tuple[Drawn, bool]]) -> None:
    """Number a row going round a centre (a cam's divisions round O: :func:`.rows.row_centre`) as a textbook
    does, outside the profile: each label is tried along its ray from that centre and up to 50° either side of
    it, at most 3 mm beyond its marker (before, a label went away from the drawing's centre, which with the s–δ
    diagram beside the cam put the numbers of its far side inside the profile, next to their neighbours' points)."""
    for row in _rows(groups, pending):
        if any(t.request.candidates for _, t in row):
            continue                                    # an axis's ticks keep their side
        centre = row_centre([t.request.anchor for _, t in row])
        if centre is None:
            continue
        for i, t in row:
            r, texts = t.request, pending[i][0].texts
            (ax, ay) = r.anchor
            if (ax, ay) == centre:
                continue
            away = math.atan2(ay - centre[1], ax - centre[0])
            spots = []
            for turn in OUTWARD_TURNS:                # on the ray, at the ray's end if need be, first
                for d in label_distances(r.gap):
                    ux, uy = math.cos(away + turn), math.sin(away + turn)
                    k = r.gap + half_extent(ux, uy, r.width, r.height) + d
                    spots.append((ax + ux * k, ay + uy * k))
            texts[texts.index(t)] = replace(t, request=replace(r, prefer=away, candidates=tuple(spots)),
                                            fallback=t)         # all round, where outside has no room


def _leading(pending: list[tuple[Drawn, bool]]) -> None:
    """A mark's value placed all round its arc gets a leader beyond :data:`LEADER_FROM` from its arc
    (:func:`_leader`): its request says so, and where the leader may start, so that the placer keeps the leader
    short and off the links, pivots and texts."""
    for drawn, _ in pending:
        for i, t in enumerate(drawn.texts):
            if t.cls == "mark-text" and not t.request.candidates:
                arcs = [sh for sh in drawn.shapes if isinstance(sh, ArcP) and sh.at(0.5) == t.request.anchor]
                starts = tuple(arcs[0].at(k / ARC_STARTS) for k in range(ARC_STARTS + 1)) if arcs else ()
                fb = t.fallback
                if fb is not None and fb.cls == "mark-text" and not fb.request.candidates:
                    fb = replace(fb, request=replace(fb.request, lead=LEADER_FROM, starts=starts))
                drawn.texts[i] = replace(t, request=replace(t.request, lead=LEADER_FROM, starts=starts), fallback=fb)


ARC_STARTS = 8
"""A mark's leader starts at the nearest of 9 points along its arc (ends and eighths): a value beside either end
of its arc needs none, and one farther off reaches its arc the shortest way."""


FanTry = tuple[list[tuple[int, TextRequest]], list[Request], list[tuple[Fan, list[tuple[Request, str]]]]]
"""One crowded cluster of a numbered row: its (group index, text) members, their requests, and the layouts to
try, each with its texts' one-candidate jobs for the placer."""


def _fan_options(groups: list[StepDrawing], pending: list[tuple[Drawn, bool]]) -> list[FanTry]:
    """The crowded clusters of each numbered row (:mod:`.rows`) and the layouts :func:`_fanned` tries for each
    (they depend on the drawing alone: the placer measures them all in one pass with the other texts)."""
    tried = []
    for row in _rows(groups, pending):
        anchors = [t.request.anchor for _, t in row]
        for run in clusters(anchors, [(t.request.width, t.request.height) for _, t in row], SEP):
            members = [row[k] for k in run]
            reqs = [t.request for _, t in members]
            ax = sum(math.cos(r.prefer) for r in reqs)
            ay = sum(math.sin(r.prefer) for r in reqs)
            fixed = all(r.candidates for r in reqs)            # an axis's ticks: on their side only
            options = fans([r.anchor for r in reqs], [(r.width, r.height) for r in reqs],
                           max(max(r.gap for r in reqs) - 0.4, 0.0), (ax, ay), (1,) if fixed else (1, -1))
            tried.append((members, reqs, [(fan, [(_at(r, c), groups[i].key) for (i, _), r, c
                                                 in zip(members, reqs, fan.centres)]) for fan in options]))
    return tried


def _fanned(placer: Placer, tried: list[FanTry]) -> dict[int, TextRequest]:
    """The labels of crowded clusters of each numbered row (:func:`_fan_options`), each at its place on the
    cluster's line of labels: the layout whose worst label is clear (the nearest on the side away from the
    drawing first), else the one whose worst label is the most clear. Keyed by ``id`` of the text replaced."""
    out: dict[int, TextRequest] = {}
    for members, reqs, options in tried:
        best: tuple[float, Fan] | None = None
        for fan, jobs in options:
            worst = min(placer.best(req, key)[1] for req, key in jobs)
            if best is None or worst > best[0] + 1e-9:
                best = (worst, fan)
            if worst >= CROWDED:
                break
        assert best is not None
        for (_, t), r, c in zip(members, reqs, best[1].centres):
            fan_t = out[id(t)] = TextRequest(t.runs, t.size, _at(r, c), italic=t.italic, cls="label fan")
            box = r.box(*c)
            placer.commit(box)
            leader = _fan_leader(fan_t, box)
            if leader is not None:
                placer.commit(obstacle(leader))
    return out


def _at(r: Request, c: tuple[float, float]) -> Request:
    """``r`` placed at the one centre ``c``."""
    return Request(r.anchor, r.width, r.height, r.gap, r.prefer, candidates=(c,))


LED_GAIN = 1.5
"""How much better (score) a point's label must be farther off, with a leader, to leave its point when it is not
clear there either: more than one thin line fewer crossed."""

LED_RIVAL_REACH = 5.0
"""A point's label still on a given or construction line by its point and with its leader (:func:`_led`) is tried
once more farther off with a leader (:meth:`.placement.Placer.past_rivals`), where only a point within this (paper
mm) of its box rivals it, not any nearer it than its own: there the leader says whose it is. 000-02's G sat on the
ram's guide, 2 mm from T and M: every clear place with a leader lay nearer M than G (6 mm from M and more). Not a
label's reach (:data:`.placement.LABEL_REACH`, 3 mm): at 3, 100-04's C1 went beside C′'s label, 3.8 mm from C′, and
read as a pair with it."""

LED_DISTANCES = (0.0, 1.0, 2.0, 3.0, 4.5, 6.0, 8.0, 10.0)
"""Distances beyond its gap at which a row's number with no room by its point is tried (it gets a leader)."""


def _led(t: TextRequest) -> TextRequest:
    """A row's number that found no place by its point (it would cover another text, or sit nearer another
    point), or a point's label that would cover a line there: tried all round at :data:`LED_DISTANCES`, to be
    joined to its point by a leader (which says whose it is, wherever it lands)."""
    r = t.request
    req = Request(r.anchor, r.width, r.height, r.gap, r.prefer, distances=LED_DISTANCES, rivals=r.rivals, lead=r.gap,
                  parts=r.parts)
    return TextRequest(t.runs, t.size, req, italic=t.italic, cls="label fan", parts=t.parts)


def _between(t: TextRequest, free: Callable[[np.ndarray], np.ndarray]) -> TextRequest | None:
    """The leader form (:func:`_led`) of a point's label ``t`` that still meets a link, ground, block or pin
    with it, tried in the sixteen directions halfway between those (:func:`.candidates.between`), at
    :data:`LED_DISTANCES`, each place with the penalty it would have among the others
    (:data:`.candidates.FAR_PENALTY` per distance, the request's spread per direction): only those a reader can
    take for its own, clear, nearer its point than any other and kept by ``free`` (clear of the links, grounds,
    blocks and pins, in the frame, off the texts placed before). A slot narrower than 22.5° seen from the point
    lies between two of the usual directions: 001-31's E0, the contact point on the cam's profile, finds one 11°
    off straight below, inside the disc between the profile and ω's arc. None when no such place is left."""
    r = t.request
    a = np.array(between(r.prefer))
    ux, uy = np.cos(a), np.sin(a)
    hw, hh = r.width / 2, r.height / 2
    with np.errstate(divide="ignore"):
        edge = np.minimum(np.where(np.abs(ux) > 1e-12, hw / np.abs(ux), math.inf),
                          np.where(np.abs(uy) > 1e-12, hh / np.abs(uy), math.inf))
    reach = (r.gap + np.array(LED_DISTANCES))[:, None] + edge[None, :]            # distance × direction
    cx, cy = (r.anchor[0] + ux * reach).ravel(), (r.anchor[1] + uy * reach).ravel()
    cost = (FAR_PENALTY * np.arange(len(LED_DISTANCES))[:, None] + r.spread * np.arange(len(a))[None, :]).ravel()
    keep = np.flatnonzero(~np.array(nearer_rival(r, list(zip(cx.tolist(), cy.tolist()))), dtype=bool))
    if len(keep):
        keep = keep[free(shapely.box(cx[keep] - hw, cy[keep] - hh, cx[keep] + hw, cy[keep] + hh))]
    if not len(keep):
        return None
    req = Request(r.anchor, r.width, r.height, r.gap, r.prefer, rivals=r.rivals, lead=r.gap, parts=r.parts,
                  candidates=tuple(zip(cx[keep].tolist(), cy[keep].tolist())), costs=tuple(cost[keep].tolist()))
    return TextRequest(t.runs, t.size, req, italic=t.italic, cls="label fan", parts=t.parts)


def _led_outward(t: TextRequest) -> TextRequest:
    """A division's number with no room by its point outside the profile (:func:`_outward`): tried along its ray
    and up to 50° either side at :data:`LED_DISTANCES`, joined to its point by a leader."""
    r = t.request
    (ax, ay), away = r.anchor, r.prefer
    spots = []
    for turn in OUTWARD_TURNS:
        for d in LED_DISTANCES:
            ux, uy = math.cos(away + turn), math.sin(away + turn)
            k = r.gap + half_extent(ux, uy, r.width, r.height) + d
            spots.append((ax + ux * k, ay + uy * k))
    req = Request(r.anchor, r.width, r.height, r.gap, away, candidates=tuple(spots), rivals=r.rivals, lead=r.gap)
    return TextRequest(t.runs, t.size, req, italic=t.italic, cls="label fan")


def _fan_leader(t: TextRequest, box: Any) -> Poly | None:
    """A thin leader from a spread-out label's point (off its marker) to its box: every label of a crowded row
    has one, so that none is read as its neighbour's."""
    r = t.request
    anchor = shapely.Point(r.anchor)
    if box.distance(anchor) <= r.gap:
        return None
    _, near = shapely.ops.nearest_points(anchor, box.exterior)
    ax, ay = r.anchor
    dx, dy = near.x - ax, near.y - ay
    n = math.hypot(dx, dy)
    a, b = (r.gap - 0.2) / n, (n - 0.3) / n
    return Poly(((ax + dx * a, ay + dy * a), (ax + dx * b, ay + dy * b)), Pen(INK, 0.15))


def _place_texts(view: View, groups: list[StepDrawing], pending: list[tuple[Drawn, bool]],
                 apart: set[int] = frozenset(), room: Box | None = None) -> None:  # type: ignore[assignment]
    """Place every label and mark text, in step order, clear of all shapes of the frame; the labels of a crowded
    numbered row go on a line beside it, with leaders (:func:`_fanned`). The shapes whose ``id`` is in ``apart``
    (an angle's rays drawn on to its arc: :mod:`.arms`) are kept clear of by their own step's text too. A text
    within :data:`.clearance.NEAR` of another step's link, ground, slider block or mark stroke crosses it (its
    halo would cut into it); not so a point's marker (a label keeps its gap from its own, and a joined label of
    coincident points lies by the others' too) nor the inside of ω's arc. A text that would still meet a link, a
    ground, a block or a pin may go beyond the view, into ``room`` (:func:`text_room`), where that scores better
    by more than :data:`WIDE_GAIN`; one that crosses only thin lines stays in the view, which leaves the sheet's
    free room to the results (200-13's α′max went out and split them in two boxes)."""
    obstacles = [(obstacle(sh), g.key + " ray" if id(sh) in apart else g.key,
                  SOFT if g.layer == "construction" else 0.0, w, w, w >= 2.0 and g.layer != "points")
                 for g in groups for sh in g.shapes for w in (_weight(g, sh),)]
    mech = [g.layer in HARD for g in groups for _ in g.shapes]      # the mechanism's: links, pins, grounds, blocks
    drawn_lines = [g.layer in ("given", "construction") for g in groups for _ in g.shapes]
    obstacles += [(shapely.Polygon(area), g.key, 0.0, KEEP_OUT, KEEP_OUT, False)
                  for g, (drawn, _) in zip(groups, pending) for area in drawn.keep_out]
    thin = lean([o[0] for o in obstacles])      # a cam's long curves by a tenth of their segments
    outlines = [g.layer == "links" for g in groups for _ in g.shapes]     # a value's leader may cross (cheaper)
    placer = Placer([(g,) + o[1:] for g, o in zip(thin, obstacles)], view.paper_box, outlines)
    wide = placer.widened(room) if room is not None and room != view.paper_box else None
    hard: list[Any] = []                        # a tree of the links, grounds, blocks and pins, when asked

    def meets_hard(box: Any, key: str, near: float = HALO) -> bool:
        """Whether ``box`` (of step ``key``'s text) meets another step's link, ground, block or pin (comes within
        ``near`` of a link, ground or block; 0: touches one), as the gallery's rule reads them."""
        if not hard:
            keep = [o for o, m in zip(obstacles, mech) if m and o[3] >= 2.0]
            geoms = np.empty(len(keep), dtype=object)
            geoms[:] = [o[0] for o in keep]
            hard.append((shapely.STRtree(geoms), [o[1] for o in keep], [o[5] for o in keep]))
        tree, owners, halo = hard[0]
        if not near:
            return any(owners[i] != key for i in tree.query(box, predicate="intersects").tolist())
        found = tree.query(box, predicate="dwithin", distance=near).tolist()
        return any(owners[i] != key and (halo[i] or tree.geometries[i].intersects(box)) for i in found)
    lines: list[Any] = []                       # a tree of the given and construction lines, when asked

    def on_lines(boxes: np.ndarray, key: str) -> np.ndarray:
        """Whether each of ``boxes`` (of step ``key``'s text) crosses another step's given or construction line."""
        if not lines:
            keep = [o for o, m in zip(obstacles, drawn_lines) if m and o[3] > 0.0]
            geoms = np.empty(len(keep), dtype=object)
            geoms[:] = [o[0] for o in keep]
            lines.append((shapely.STRtree(geoms), np.array([o[1] for o in keep] + [""], dtype=object)[:-1]))
        tree, owners = lines[0]
        i, j = tree.query(boxes, predicate="intersects")
        out = np.zeros(len(boxes), dtype=bool)
        out[i[owners[j] != key]] = True
        return out
    def on_line(box: Any, key: str) -> bool:
        """Whether ``box`` (of step ``key``'s text) crosses another step's given or construction line."""
        return bool(on_lines(np.array([box], dtype=object), key)[0])
    def free(boxes: np.ndarray, key: str) -> np.ndarray:
        """Whether each of ``boxes`` (axis-parallel, of step ``key``'s text) lies in the frame, off the texts
        placed so far and off every other step's link, ground, block and pin, as :func:`meets_hard` reads them
        (within ``HALO``)."""
        x0, y0, x1, y1 = shapely.bounds(boxes).T
        f = view.paper_box
        out = (f[0] <= x0) & (f[1] <= y0) & (x1 <= f[2]) & (y1 <= f[3])
        if texts:
            tb = shapely.bounds(np.array(texts, dtype=object))
            i, j = np.nonzero((x0[:, None] <= tb[None, :, 2]) & (tb[None, :, 0] <= x1[:, None])
                              & (y0[:, None] <= tb[None, :, 3]) & (tb[None, :, 1] <= y1[:, None]))
            on = shapely.intersects(boxes[i], np.array(texts, dtype=object)[j])
            out[i[on]] = False
        meets_hard(boxes[0], key)               # the tree, built
        tree, owners, halo = hard[0]
        i, j = tree.query(shapely.box(x0 - HALO, y0 - HALO, x1 + HALO, y1 + HALO))     # bounds that come so near
        mine = out[i] & np.array([owners[k] != key for k in j.tolist()], dtype=bool)
        i, j = i[mine], j[mine]
        gap = shapely.distance(tree.geometries[j], boxes[i])
        out[i[((gap <= HALO) & np.array(halo, dtype=bool)[j]) | (gap <= 0.0)]] = False
        return out
    def away(box: Any, key: str) -> tuple[float, float]:
        """The unit direction from the nearest link, ground, block or pin (not of step ``key``) to ``box``."""
        meets_hard(box, key)                    # the tree, built
        tree, owners, _ = hard[0]
        near = [i for i in tree.query(box, predicate="dwithin", distance=HALO).tolist() if owners[i] != key]
        i = min(near, key=lambda j: tree.geometries[j].distance(box))
        p, q = shapely.ops.nearest_points(tree.geometries[i], box)
        dx, dy = q.x - p.x, q.y - p.y
        n = math.hypot(dx, dy)
        return (dx / n, dy / n) if n > 1e-12 else (0.0, 1.0)
    _thin(groups, pending)                      # before measuring: it leaves out a crowded axis's numbers
    _outward(groups, pending)                   # before measuring: it replaces a row's requests
    _leading(pending)
    tried = _fan_options(groups, pending)
    placer.prepare([(t.request, g.key) for g, (drawn, _) in zip(groups, pending) for t in drawn.texts]
                   + [job for _, _, options in tried for _, jobs in options for job in jobs])   # in one pass
    every = [(g, is_cur, t) for g, (drawn, is_cur) in zip(groups, pending) for t in drawn.texts]
    _foresee(placer, [(g.key, t) for g, _, t in every])
    fanned: dict[int, TextRequest] = {}
    texts: list[Any] = []
    steps_of = {g.key: (g, cur) for g, (_, cur) in zip(groups, pending) if not g.arc}     # a label's parts

    def put(g: StepDrawing, is_cur: bool, t: TextRequest) -> None:
        colour = HIGHLIGHT if is_cur else None
        if id(t) in fanned:                     # placed (and recorded by the placer) with its row
            t = fanned[id(t)]
            texts.append(t.request.box(*t.request.candidates[0]))
            leader = _fan_leader(t, texts[-1])
            if leader is not None:
                g.shapes.append(recolour(leader, colour) if colour else leader)
            g.shapes.append(_text_at(t, *t.request.candidates[0], colour))
            return
        centre, score = placer.best(t.request, g.key)
        seen: dict[Any, tuple[tuple[float, float], float]] = {}     # its leader form's best, once
        if t.alone and score < 0.0 and _apart(placer, t, g.key, score, seen):
            for k, a in t.alone:                # near points' own labels instead, each placed as a label is
                put(steps_of[k][0], steps_of[k][1], a)
            return
        outward = t.fallback is not None and t.fallback.runs == t.runs      # a division's number all round
        if outward and score < -AMBIGUOUS:      # no room by its point outside: farther out, with a leader
            led = _led_outward(t)
            alt, alt_score = placer.best(led.request, g.key)
            if alt_score >= CROWDED:
                t, centre, score = led, alt, alt_score
        if t.fallback is not None and score < (-AMBIGUOUS if outward else CROWDED):
            alt, alt_score = placer.best(t.fallback.request, g.key)
            if alt_score > score + 0.3:
                t, centre, score = t.fallback, alt, alt_score
        if t.cls == "label" and not t.optional and not t.request.candidates and score < 0.0:
            led = _led(t)                       # a point's label that covers a line: farther, with a leader
            alt, alt_score = seen.get((led.request, g.key)) or placer.best(led.request, g.key)
            own = t
            if alt_score > score + (0.3 if alt_score >= CROWDED else LED_GAIN) or (
                    alt_score > score and meets_hard(t.request.box(*centre), g.key, 0.0)
                    and not meets_hard(led.request.box(*alt), g.key)):
                t, centre, score = led, alt, alt_score
            if (score < 0.0 and own.request.rivals and not own.request.parts
                    and on_line(t.request.box(*centre), g.key)):
                # still on a given or construction line: farther off, past the near points
                far = _clear(placer.past_rivals(led.request, g.key, LED_RIVAL_REACH, max(0.0, score + 0.3)),
                             lambda boxes: free(boxes, g.key) & ~on_lines(boxes, g.key))
                alt, alt_score = placer.best(far, g.key) if far is not None else (centre, -math.inf)
                if alt_score >= 0.0 and alt_score > score + (0.3 if alt_score >= CROWDED else LED_GAIN):
                    t, centre, score = replace(led, request=far), alt, alt_score    # only a place clear of every line
            if score < 0.0 and meets_hard(t.request.box(*centre), g.key):
                half = _between(own, lambda boxes: free(boxes, g.key))   # still on a link, ground,
                if half is not None:            # block or pin: the slots between its leader form's directions
                    alt, alt_score = placer.best(half.request, g.key)
                    if alt_score > score:
                        t, centre, score = half, alt, alt_score
        if (score < 0.0 and t.cls.startswith("label") and not t.optional and not t.request.candidates
                and meets_hard(t.request.box(*centre), g.key) and not meets_hard(t.request.box(*centre), g.key, 0.0)):
            near = _nudged(t.request, centre, away(t.request.box(*centre), g.key))     # a hair from (not on) a
            # link, ground, block or pin: the slot beside it
            if near is not None:
                alt, alt_score = placer.best(near, g.key)
                if alt_score > score + 1e-9 and not meets_hard(near.box(*alt), g.key):
                    centre, score = alt, alt_score
        if (wide is not None and score < 0.0 and not t.optional and _reaches_out(t.request, view.paper_box, room)
                and meets_hard(t.request.box(*centre), g.key)):
            alt, alt_score = wide.best(t.request, g.key)
            if alt_score > score + WIDE_GAIN:
                centre, score = alt, alt_score
        box = t.request.box(*centre)
        if t.optional and ((texts and shapely.intersects(box, texts).any())
                           or placer.rivalled(t.request, g.key, centre)):
            t = _led(t)                 # a row's number with no room by its point: farther, with a leader
            centre, _ = placer.best(t.request, g.key)
            box = t.request.box(*centre)
            leader = _fan_leader(t, box)
        else:
            leader = _fan_leader(t, box) if t.cls == "label fan" else _leader(t, box)
        if leader is None and t.cls == "label fan":
            t = replace(t, cls="label")         # it found room by its point after all
        texts.append(box)
        placer.commit(box)
        if leader is not None:
            placer.commit(obstacle(leader))
            g.shapes.append(recolour(leader, colour) if colour else leader)
        if t.parts:
            for key, part in _parts_at(t, centre[0], centre[1]):
                owner, cur = steps_of[key]
                owner.shapes.append(recolour(part, HIGHLIGHT) if cur else part)
        else:
            g.shapes.append(_text_at(t, centre[0], centre[1], colour))

    fixed = [x for x in every if x[2].cls == "mark-text" and x[2].request.candidates]
    for x in fixed:                             # a dimension's value first: it has only its few places on its line
        put(*x)
    fanned.update(_fanned(placer, tried))
    for x in every:
        if not (x[2].cls == "mark-text" and x[2].request.candidates):
            put(*x)


NUDGES = (0.1, 0.2, 0.3, 0.4, 0.5)
"""Paper mm a point's label found a hair from a link, a ground, a block or a pin is tried moved, each way and
diagonally (:func:`_nudged`): its places lie a millimetre apart, and the free slot may be narrower."""


def _nudged(r: Request, centre: tuple[float, float], away: tuple[float, float]) -> Request | None:
    """``r`` with the places about ``centre`` (the best of its own, a hair from a link, ground, block or pin):
    moved by :data:`NUDGES` along ``away`` (the unit direction from the nearest of them) and 45° either side,
    nearest first, those that keep it as near its point as its own places may (a label within
    :data:`.placement.LABEL_REACH`, a leader's text within its longest leader) and clear of its marker. 001-06b's
    C3, under the guide with a leader, lay 0.18 mm from the hatch's foot and 0.28 mm from H=101.74's text: 0.1 mm
    lower and aside it is clear of both. None when no such place is left."""
    ux, uy = away
    s = math.sqrt(0.5)
    turns = ((ux, uy), (s * (ux - uy), s * (uy + ux)), (s * (ux + uy), s * (uy - ux)))
    d = np.repeat(np.array(NUDGES), len(turns))
    tx = np.tile([u[0] for u in turns], len(NUDGES))
    ty = np.tile([u[1] for u in turns], len(NUDGES))
    cx, cy = centre[0] + tx * d, centre[1] + ty * d
    hw, hh = r.width / 2, r.height / 2
    k = box_point(cx - hw, cy - hh, cx + hw, cy + hh, r.anchor[0], r.anchor[1])
    hi = LEADER_MAX if r.lead < math.inf else r.gap + max(r.distances) + 1e-9
    keep = (k >= r.gap - 1e-9) & (k <= hi)
    spots = tuple(zip(cx[keep].tolist(), cy[keep].tolist()))
    return replace(r, candidates=spots) if spots else None


def _clear(r: Request | None, clear: Callable[[np.ndarray], np.ndarray]) -> Request | None:
    """``r`` (explicit candidates with their penalties, or None) with only the places ``clear`` keeps (a box of
    them touching a link, a ground, a block, a pin, a text placed or a thin line scores below 0), None when none is
    left: what :meth:`.placement.Placer.best` need not measure."""
    if r is None:
        return None
    boxes = np.empty(len(r.candidates), dtype=object)
    boxes[:] = [r.box(*c) for c in r.candidates]
    keep = clear(boxes).tolist()
    if not any(keep):
        return None
    return replace(r, candidates=tuple(c for c, k in zip(r.candidates, keep) if k),
                   costs=tuple(c for c, k in zip(r.costs, keep) if k))


def _reaches_out(r: Request, inner: Box, outer: Box) -> bool:
    """Whether a candidate box of ``r`` may reach beyond ``inner`` into ``outer`` (a text's room beyond its view):
    an explicit one that does, or its anchor within its farthest reach of a side of ``inner`` that ``outer``
    passes (texts deep in the drawing, as 004-02's C1 and C3, are not tried beyond it at all).

    >>> r = Request((50.0, 50.0), 4.0, 3.0, 1.0, 0.0)
    >>> _reaches_out(r, (0.0, 0.0, 100.0, 100.0), (0.0, 0.0, 150.0, 100.0)), _reaches_out(
    ...     replace(r, anchor=(95.0, 50.0)), (0.0, 0.0, 100.0, 100.0), (0.0, 0.0, 150.0, 100.0))
    (False, True)
    """
    hw, hh = r.width / 2, r.height / 2
    if r.candidates:
        return any(x - hw < inner[0] or y - hh < inner[1] or x + hw > inner[2] or y + hh > inner[3]
                   for x, y in r.candidates)
    reach = r.gap + max(r.distances) + 2.0 * math.hypot(hw, hh)
    if r.lead < math.inf:                           # a leader's text: from the farthest of its starts
        reach += max((math.dist(r.anchor, p) for p in r.starts), default=0.0)
    x, y = r.anchor
    return ((outer[0] < inner[0] and x - reach < inner[0]) or (outer[1] < inner[1] and y - reach < inner[1])
            or (outer[2] > inner[2] and x + reach > inner[2]) or (outer[3] > inner[3] and y + reach > inner[3]))


def _foresee(placer: Placer, texts: list[tuple[str, TextRequest]]) -> None:
    """Prepare together (:meth:`.Placer.prepare`, one pass instead of one each) the other requests that
    ``put`` in :func:`_place_texts` will surely try for ``texts`` (step key, text): those whose best score against
    the drawing alone (:meth:`.Placer.bound`; what is placed later only lowers it) is already below the threshold
    that sends them there: a point's label's leader form (:func:`_led`) below 0, its fallback below
    :data:`CROWDED`, and the own labels of joined near points (:attr:`TextRequest.alone`, then their leader
    forms). Only the work is moved: every score is what preparing each one alone gives."""
    for _ in range(2):
        jobs: list[tuple[Request, str]] = []
        later: list[tuple[str, TextRequest]] = []
        for key, t in texts:
            bound = placer.bound(t.request, key)
            if t.fallback is not None and t.fallback.runs != t.runs and bound < CROWDED:
                jobs.append((t.fallback.request, key))
            if bound >= 0.0:
                continue
            if t.alone:
                jobs += [(a.request, k) for k, a in t.alone]
                later += list(t.alone)
            if t.fallback is None and t.cls == "label" and not t.optional and not t.request.candidates:
                jobs.append((_led(t).request, key))
        placer.prepare(jobs)
        texts = later


def _final(placer: Placer, t: TextRequest, key: str, score: float,
           seen: dict[Any, tuple[tuple[float, float], float]] | None = None) -> float:
    """The score a point's label scoring ``score`` by its point ends with: that of its leader form (:func:`_led`)
    where ``put`` in :func:`_place_texts` would take that (better by more than 0.3 and clear, or by more than
    :data:`LED_GAIN`), else ``score``. A joined label and its points' own labels are weighed so (:func:`_apart`):
    001-06b's "C4" went across the link B2C2 (-7.3) where "M, C4" with a leader finds a clear place (-3.2: its
    leader crosses a thin line), and 200-16's B(75°) and B1* each with its leader (-1.9, -0.1) stay apart. The
    leader form's best goes into ``seen`` (keyed by request and step), for ``put`` to take it from there."""
    if not _leads(t) or score >= 0.0:
        return score
    led = _led(t).request
    if placer.bound(led, key) <= score + 0.3:      # it cannot gain the least it must (what is placed only lowers)
        return score
    found = placer.best(led, key)
    if seen is not None:                            # asked again by ``put`` before anything more is placed
        seen[led, key] = found
    alt = found[1]
    return alt if alt > score + (0.3 if alt >= CROWDED else LED_GAIN) else score


def _apart(placer: Placer, t: TextRequest, key: str, score: float,
           seen: dict[Any, tuple[tuple[float, float], float]]) -> bool:
    """Whether the own labels of near points (:attr:`TextRequest.alone`) do better than their joined label ``t``
    (of step ``key``), scoring ``score`` by its points and in the end :func:`_final`'s (with its leader where it
    takes that; asked only when it may matter): each finds a place scoring more (by its point or with its
    leader, :func:`_final`), by its point nearer its own point than any of the others (or anywhere, when the
    joined label itself lies nearer another point: 004-02 at 1:5, where no place is clear)."""
    points = [a.request.anchor for _, a in t.alone]
    found = []
    for k, a in t.alone:
        centre, s = placer.best(a.request, k)
        tried = s <= score                      # its leader form asked for
        last = _final(placer, a, k, s) if tried else s
        if last <= score:
            return False
        found.append((k, a, centre, s, last, tried))
    top = max(score, placer.bound(_led(t).request, key)) if _leads(t) else score     # the most it may end with
    if top < min(f[4] for f in found) and top < ENOUGH - AMBIGUOUS:
        return True                             # each beats it, whatever its leader form does
    score = _final(placer, t, key, score, seen)
    for k, a, (cx, cy), s, last, tried in found:
        if last <= score and (tried or _final(placer, a, k, s) <= score):
            return False
        if score < ENOUGH - AMBIGUOUS:
            continue
        b = a.request.box(cx, cy)
        own = b.distance(shapely.Point(a.request.anchor))
        if any(b.distance(shapely.Point(p)) <= own + 1e-9 for p in points if p != a.request.anchor):
            return False
    return True


def _leads(t: TextRequest) -> bool:
    """Whether ``t`` is a point's label that may take its leader form (:func:`_led`) in ``put``."""
    return t.cls == "label" and not t.optional and not t.request.candidates


def _weight(g: StepDrawing, sh: Shape) -> float:
    """The crossing weight of a shape (:class:`.Placer`): a link, a point's marker, a ground symbol, and a mark's
    straight strokes (the normal drawn with an angle, a dimension's line and arrows) 2, any other stroke 1 (a
    text's own step's strokes count too: a mark's value across its own arc or normal), a text 0."""
    if isinstance(sh, Text):
        return 0.0
    return 2.0 if g.layer in HARD or (g.layer == "marks" and not isinstance(sh, ArcP)) else 1.0


WIDE_GAIN = 0.3
"""How much better (score) a text's place beyond the view (:func:`text_room`) must be to be taken."""

KEEP_OUT = 3.0
"""The crossing weight of an area no text belongs in (:attr:`.draw.Drawn.keep_out`: the inside of a sense of
rotation's arc), more than a link's: 16 cam figures printed "O" inside the ω arrow's arc, where the centre's label
had a free spot but the empty inside of the arc weighed nothing; and more than coming within
:data:`.clearance.NEAR` of a link or ground costs (200-01's O, a hair from its ground, would go into the arc)."""

HARD = ("links", "points", "ground", "sliders")
"""The layers whose strokes a text crossing them costs twice as much: the mechanism's links, pivots, grounds and
slider blocks (a block weighed as a thin line before, and 001-05c's T1, T2 and 004-01's C1 printed inside one)."""


def _leader(t: TextRequest, box: Any) -> Poly | None:
    """A thin leader from a mark's anchor to its text when the text sits far from it (not for labels)."""
    if t.cls == "label" or t.request.candidates:
        return None
    x0, y0, x1, y1 = box.bounds                 # the start nearest the box, as the placer chose it
    starts = t.request.starts or (t.request.anchor,)
    ds = box_point(x0, y0, x1, y1, np.array([p[0] for p in starts]), np.array([p[1] for p in starts]))
    start = starts[int(np.argmin(ds))]
    anchor = shapely.Point(start)
    if box.distance(anchor) <= LEADER_FROM:
        return None
    _, near = shapely.ops.nearest_points(anchor, box.exterior)
    ax, ay = start
    d = math.hypot(near.x - ax, near.y - ay)
    k = (d - 0.4) / d
    return Poly(((ax, ay), (ax + (near.x - ax) * k, ay + (near.y - ay) * k)), Pen(INK, 0.15))


def _text_at(t: TextRequest, cx: float, cy: float, colour: str | None) -> Text:
    r = t.request
    sub = any(s for _, s in t.runs)
    baseline = cy + r.height / 2 - (0.24 * t.size if sub else 0.0)
    text = Text(cx, baseline, t.runs, t.size, INK, (cx - r.width / 2, cy - r.height / 2, cx + r.width / 2,
                                                  cy + r.height / 2), italic=t.italic, rotate=r.rotate, cls=t.cls)
    return recolour(text, colour) if colour else text


def _parts_at(t: TextRequest, cx: float, cy: float) -> list[tuple[str, Text]]:
    """The parts of a label naming several points (:attr:`TextRequest.parts`) centred at (cx, cy) as one text:
    each starts where the one before ends, on the whole label's baseline, with its step's key. Left of its points
    the label reads backwards ("K0 = D" for "D = K0"), so that the first name, shown alone until the next point
    is drawn, is the one beside the points."""
    whole = _text_at(t, cx, cy, None)
    parts = list(t.parts)
    back = reads_back(cx, t.request.anchor[0], t.request.width)       # mostly left of them
    if back:
        parts = [parts[0]] + [(key, runs[1:] + runs[:1]) for key, runs in parts[1:]]     # the sign after the name
    widths = [text_width(runs, t.size) for _, runs in parts]
    out = []
    for (key, runs), (x, x1) in sorted(zip(parts, spans(whole.box[0], whole.box[2], widths, back)),
                                       key=lambda p: p[1][0]):
        out.append((key, replace(whole, x=x, runs=runs, anchor="start", box=(x, whole.box[1], x1, whole.box[3]))))
    return out


def label_positions(fig: Figure) -> dict[str, list[Text]]:
    """The placed texts of each step (for tests and tools)."""
    return {g.key: g.texts for g in fig.groups if g.texts}


__all__ = ["Figure", "Sketch", "StepDrawing", "build_figure", "content_box", "fit_view", "label_positions",
           "shown_steps", "sketch_figure"]
