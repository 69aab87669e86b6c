"""Drawing one step's value: primitives and marks become paper shapes, labels become placement requests.

Every function takes the value, its :class:`~geomcon.render.style.Style` and the :class:`Context` of the
figure, and returns a :class:`Drawn`: the shapes to draw now and the texts whose position the label placer
decides later. The marks (ground, slider, angle...) are in :mod:`geomcon.render.symbols`.

Examples
--------
>>> from geomcon.geometry import Point, Segment
>>> from geomcon.render.style import STYLES
>>> from geomcon.render.view import View
>>> ctx = Context(View((0.0, 0.0, 100.0, 100.0), 1.0, (0.0, 0.0)))
>>> d = draw_segment(Segment(Point(0, 0), Point(50, 0)), STYLES["link"], ctx)
>>> d.shapes[0].pts
((0.0, 100.0), (50.0, 100.0))
"""
from __future__ import annotations

import math
from typing import Any
from dataclasses import dataclass, field, replace

from ..geometry.primitives import Arc, Circle, Line, Point, Polyline, Ray, Segment
from .labels import Runs, label_extent, label_runs, text_width
from .placement import Request, half_extent, label_distances
from .shapes import Disc, ArcP, Pen, Poly, Shape
from .style import LABEL_SIZE, PAPER, Style
from .view import TAU, View, clip_arc, clip_interval

XY = tuple[float, float]
SLIDER = (8.0, 5.0)            # slider block, paper mm (along, across the guide)
ANGLE_RADIUS = 9.0             # default radius of an angle mark's arc, paper mm
MIN_ANGLE_RADIUS = 5.0         # the smallest radius of an angle mark's arc, paper mm (a smaller one barely shows)
ARC_LENGTH = 3.5               # the least length of an angle mark's arc, paper mm (a shorter one reads as a tick)
SMALL_ANGLE_RADIUS = 20.0      # the largest radius a small angle's arc takes to reach ARC_LENGTH, paper mm
COMPASS_HALF = 11.0            # half length of a compass arc through a point, paper mm


def least_arc_radius(sweep: float) -> float:
    """The least paper radius of an angle mark's arc spanning ``sweep`` radians: :data:`MIN_ANGLE_RADIUS`, or
    more for a small angle, so that its arc is :data:`ARC_LENGTH` long, up to :data:`SMALL_ANGLE_RADIUS`.
    At 9 mm, 001-08's θ = 12.5° was an arc of 2 mm and read as a tick; 35 of the gallery's 148 arcs were
    shorter than 3 mm.

    >>> least_arc_radius(math.radians(90.0)), round(least_arc_radius(math.radians(12.5)), 3)
    (5.0, 16.043)
    >>> least_arc_radius(math.radians(2.0))          # a tiny angle: as large as allowed
    20.0
    """
    phi = abs(sweep)
    if phi <= 0.0:
        return MIN_ANGLE_RADIUS
    return max(MIN_ANGLE_RADIUS, min(SMALL_ANGLE_RADIUS, ARC_LENGTH / phi))


@dataclass(frozen=True, slots=True)
class TextRequest:
    """A text still to be placed: its runs, font size and placement request."""

    runs: Runs
    size: float
    request: Request
    italic: bool = False
    cls: str = "label"
    fallback: TextRequest | None = None
    """A shorter text used when this one finds no free place."""
    optional: bool = False
    """Left out where it would cover another text (a label of a crowded numbered row)."""
    parts: tuple[tuple[str, Runs], ...] = ()
    """(step key, runs) of each part of a label naming several points (:mod:`.coincident`): each part prints
    with its point's step; empty: the whole text prints with the step drawing it."""
    alone: tuple[tuple[str, TextRequest], ...] = ()
    """(step key, own label) of each point a label naming near (not coincident) points names: printed instead,
    each by its point, where the joined label finds no clear place and they do."""


@dataclass
class Drawn:
    """What one value draws: shapes now, texts after placement, and the areas texts keep out of."""

    shapes: list[Shape] = field(default_factory=list)
    texts: list[TextRequest] = field(default_factory=list)
    keep_out: list[tuple[XY, ...]] = field(default_factory=list)
    """Paper polygons no text belongs in, though nothing is drawn there: the inside of the arc of a sense of
    rotation (an "O" printed there reads as part of the arrow). A text's box meeting one costs as much as one
    across a link (:func:`geomcon.render.figure._place_texts`)."""

    def extend(self, other: Drawn) -> None:
        """Append another drawing."""
        self.shapes += other.shapes
        self.texts += other.texts
        self.keep_out += other.keep_out


@dataclass
class Context:
    """What drawing a value may look at besides the value: the view, the points drawn in the figure (a
    construction circle is drawn as compass arcs through them), the centre of the drawing (labels prefer
    to point away from it), the angle marks drawn so far at each vertex (nested marks get larger arcs) and
    the links and fixed links of the figure on paper (a ground symbol turns away from them and from the angle
    marks' sectors) and its slider blocks."""

    view: View
    points: tuple[Point, ...] = ()
    centre: XY = (0.0, 0.0)
    marks_at: dict[tuple[float, float], list[float]] = field(default_factory=dict)
    """The paper radii of the angle marks' arcs drawn so far about each vertex (model point, rounded)."""
    links: tuple[tuple[XY, XY], ...] = ()
    frames: tuple[tuple[XY, XY], ...] = ()
    """The fixed links drawn dash-dot (AD): a ground symbol's hatch keeps off them too."""
    numbers: tuple[int, ...] = ()
    """The step number of each of ``points`` (empty: every point counts as drawn already)."""
    sliders: tuple[tuple[XY, XY], ...] = ()
    """The slider blocks of the figure on paper, as (centre, unit direction): blocks close on one guide
    shorten so that they never overlap."""
    sectors: tuple[tuple[XY, ...], ...] = ()
    """The angle marks of the figure on paper, as polygons (the vertex and its arc): a ground symbol keeps out."""
    curves: tuple[tuple[XY, ...], ...] = ()
    """The curves drawn as links (a cam's profile) on paper, as point chains: a ground symbol's hatch keeps off
    them (200-03's O hatched across its small cam's profile)."""
    dims: tuple[tuple[XY, XY], ...] = ()
    """The dimensions of the figure on paper, as segments (each dimension line and its extension lines): a ground
    symbol keeps off them (:func:`geomcon.render.symbols.dimension_lines`)."""
    guides: tuple[tuple[XY, ...], ...] = ()
    """The guides' hatched bands on paper, as polygons (the surface and its hatch strokes): a ground symbol keeps
    off them (:func:`geomcon.render.symbols.guide_bands`)."""
    turns: dict[XY, Any] = field(default_factory=dict)
    """The arc chosen for the arrow of a sense of rotation about each paper point (:func:`.figure.rotation_turns`)."""
    ground_at: dict[tuple[XY, float], tuple[Any, Any]] = field(default_factory=dict)
    """Ground symbols already chosen (style, drawing), by paper hinge and model direction
    (:func:`.figure.rotation_turns`)."""
    memo: dict[str, Any] = field(default_factory=dict)
    """What a ground symbol's search makes once a figure (the links, frames and curves as shapely lines)."""
    strokes: tuple[tuple[Any, float], ...] = ()
    """The circles, arcs and wide bands drawn (paper shape, half its pen width) a ground symbol and a rotation
    arrow keep off (:mod:`geomcon.render.keepoff`)."""


def pen(style: Style) -> Pen:
    """The style's pen."""
    return Pen(style.stroke, style.width, style.dash, style.opacity)


def _unit(x: float, y: float) -> XY:
    n = math.hypot(x, y)
    return (x / n, y / n) if n > 0 else (1.0, 0.0)


def _add(p: XY, u: XY, k: float = 1.0) -> XY:
    return (p[0] + u[0] * k, p[1] + u[1] * k)


def _paper_dir(d: Point) -> XY:
    """A model direction on paper (y flipped), as a unit vector."""
    return _unit(d.x, -d.y)


# ---------------------------------------------------------------------------------------------- primitives
def draw_point(p: Point, style: Style, ctx: Context, label: str | None) -> Drawn:
    """A hinge circle or a dot, and its label to be placed."""
    c = ctx.view.p(p)
    if style.marker == "hollow":
        shapes: list[Shape] = [Disc(c, style.radius, Pen(style.stroke, style.marker_width), PAPER)]
    else:
        shapes = [Disc(c, style.radius, None, style.stroke)]
    out = Drawn(shapes)
    if label:
        runs = label_runs(label)
        size = style.label_size or LABEL_SIZE
        (w, h), gap = label_extent(runs, size), style.radius + 0.4
        if style.label_dir is not None:     # a fixed place (axis ticks): there, or a line further out
            u = (math.cos(style.label_dir), math.sin(style.label_dir))
            d = gap + half_extent(u[0], u[1], w, h)
            spots = tuple(_add(c, u, d + k * h) for k in (0, 1))
            req = Request(c, w, h, gap, style.label_dir, candidates=spots)
        else:
            away = math.atan2(c[1] - ctx.centre[1], c[0] - ctx.centre[0]) if c != ctx.centre else -math.pi / 4
            req = Request(c, w, h, gap, away, distances=label_distances(gap), rivals=_rivals(c, ctx))
        short = None
        tail = label[:-1].split(" (", 1)[-1] if label.endswith(")") and " (" in label else ""
        if tail and not style.label_whole:  # "N (E1)": just "N" where both find no room (an instant centre's
            # "B (P12)" prints whole: the style says so)
            head = label_runs(label.split(" (", 1)[0])
            short = TextRequest(head, size, replace(req, width=text_width(head, size) + 0.3), italic=True)
        out.texts.append(TextRequest(runs, size, req, italic=True, optional=style.label_optional, fallback=short))
    return out


RIVAL_REACH = 15.0
"""Points within this (paper mm) of a point compete for its label's place (:class:`~.placement.Request`)."""


def _rivals(c: XY, ctx: Context, reach: float = RIVAL_REACH) -> tuple[XY, ...]:
    """The other points of the figure within ``reach`` of paper point ``c``, on paper."""
    out = []
    cx, cy = c
    for q in ctx.view.ps(ctx.points):
        d = math.hypot(q[0] - cx, q[1] - cy)
        if 1e-9 < d <= reach:
            out.append(q)
    return tuple(sorted(set(out)))


def _line_part(p: Point, d: Point, lo: float, hi: float, style: Style, ctx: Context) -> Drawn:
    box = ctx.view.box
    t = clip_interval(p.tuple(), d.tuple(), box, lo, hi)
    if t is None:
        return Drawn()
    return Drawn([Poly((ctx.view.p(p + d * t[0]), ctx.view.p(p + d * t[1])), pen(style))])


def draw_segment(s: Segment, style: Style, ctx: Context) -> Drawn:
    """A link or a construction segment (clipped to the view box)."""
    if s.a == s.b:
        return Drawn()
    return _line_part(s.a, s.b - s.a, 0.0, 1.0, style, ctx)


def draw_line(v: Line | Ray, style: Style, ctx: Context) -> Drawn:
    """An infinite line or a ray, clipped to the view box."""
    if isinstance(v, Ray):
        return _line_part(v.origin, v.direction, 0.0, math.inf, style, ctx)
    return _line_part(v.point, v.direction, -math.inf, math.inf, style, ctx)


def _arcs(center: Point, r: float, parts: list[tuple[float, float]], style: Style, ctx: Context) -> Drawn:
    out = Drawn()
    c, rp = ctx.view.p(center), ctx.view.length(r)
    for start, sweep in parts:
        for a0, sw in clip_arc(center, r, ctx.view.box, start, sweep):
            if sw >= TAU - 1e-12:
                out.shapes.append(Disc(c, rp, pen(style)))
            else:       # model counter-clockwise = negative paper angles
                out.shapes.append(ArcP(c, rp, -a0, -sw, pen(style)))
    return out


def compass_parts(c: Circle, points: tuple[Point, ...], half: float) -> list[tuple[float, float]]:
    """Angular intervals (start, sweep) of the short arcs of ``c`` through the ``points`` lying on it,
    each ``half`` radians either side, merged where they overlap; the whole circle when none lies on it.

    Examples
    --------
    >>> compass_parts(Circle(Point(0, 0), 1.0), (Point(1, 0),), 0.1)
    [(-0.1, 0.2)]
    """
    tol = 1e-9 * max(c.r, abs(c.center.x), abs(c.center.y))
    on = sorted({math.atan2(p.y - c.center.y, p.x - c.center.x) for p in points
                 if abs(math.hypot(p.x - c.center.x, p.y - c.center.y) - c.r) <= tol})
    if not on or half * 2 * len(on) >= TAU:
        return [(0.0, TAU)]
    parts: list[list[float]] = []
    for a in on:
        if parts and a - half <= parts[-1][1]:
            parts[-1][1] = a + half
        else:
            parts.append([a - half, a + half])
    if len(parts) > 1 and parts[-1][1] - TAU >= parts[0][0]:
        last = parts.pop()
        parts[0][0] = last[0] - TAU
    return [(a, b - a) if b - a < TAU else (0.0, TAU) for a, b in parts]


def _spans(parts: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Intervals (start, sweep) as sorted [a, b] spans within [0, 2π)."""
    out = []
    for start, sweep in parts:
        a = start % TAU
        b = a + sweep
        out += [(a, min(b, TAU))] + ([(0.0, b - TAU)] if b > TAU else [])
    return sorted(out)


def arc_difference(parts: list[tuple[float, float]], minus: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The arcs of ``parts`` not covered by ``minus`` (both as (start, sweep) radians), pieces shorter than
    1e-9 rad dropped, a piece crossing angle 0 kept whole.

    >>> [(round(a, 6), round(s, 6)) for a, s in arc_difference([(-0.1, 0.5)], [(0.2, 0.1)])]
    [(-0.1, 0.3), (0.3, 0.1)]
    >>> arc_difference([(0.0, 1.0)], [(-0.5, 2.0)])
    []
    """
    cut = _spans(minus)
    left = []
    for a, b in _spans(parts):
        for c, d in cut:
            if d <= a or c >= b:
                continue
            if c > a:
                left.append((a, c))
            a = max(a, d)
            if a >= b:
                break
        if b - a > 1e-9:
            left.append((a, b))
    if len(left) > 1 and left[0][0] == 0.0 and left[-1][1] == TAU:       # one piece across angle 0
        left = [(left[-1][0] - TAU, left[0][1])] + left[1:-1]
    return [(a, b - a) for a, b in sorted(left)]


def compass_steps(c: Circle, ctx: Context, own: int, half: float) -> list[tuple[int, list[tuple[float, float]]]]:
    """The compass arcs of ``c`` (drawn at step ``own``) by the step that draws them, in step order: with the
    circle's own step the arcs through the points on it drawn by then (or, when there are none, through the
    first point a later step constructs on it: the arc a draftsman swings where the next intersection will
    be), and every other arc with the step that constructs its point, so no frame shows an arc through a
    point that does not exist yet. A circle no point lies on is whole, at its own step.

    >>> from geomcon.render.view import View
    >>> ctx = Context(View((-2.0, -2.0, 2.0, 2.0), 0.01, (0.0, 0.0)), (Point(1, 0), Point(-1, 0)), numbers=(5, 9))
    >>> [(n, [(round(a, 3), round(s, 3)) for a, s in parts]) for n, parts in compass_steps(Circle(Point(0, 0), 1.0), ctx, 4, 0.1)]
    [(4, [(-0.1, 0.2)]), (9, [(3.042, 0.2)])]
    """
    numbers = ctx.numbers or (own,) * len(ctx.points)
    tol = 1e-9 * max(c.r, abs(c.center.x), abs(c.center.y))
    on = [(n, p) for p, n in zip(ctx.points, numbers)
          if abs(math.hypot(p.x - c.center.x, p.y - c.center.y) - c.r) <= tol]
    if not on:
        return [(own, compass_parts(c, (), half))]
    first = own if any(n <= own for n, _ in on) else min(n for n, _ in on)
    out, before = [], []
    for step in sorted({own} | {n for n, _ in on if n > first}):
        parts = compass_parts(c, tuple(p for n, p in on if n <= max(step, first)), half)
        new = arc_difference(parts, before) if before else parts
        if new:
            out.append((step, new))
        before = parts
    return out


def compass_half(c: Circle, ctx: Context) -> float:
    """Half the angle of a compass arc of ``c`` through a point: :data:`COMPASS_HALF` paper mm, 6° at least."""
    return max(math.radians(6.0), min(math.pi, COMPASS_HALF / max(ctx.view.length(c.r), 1e-12)))


def draw_compass(c: Circle, parts: list[tuple[float, float]], style: Style, ctx: Context) -> Drawn:
    """The arcs ``parts`` (start, sweep) of a compass-style circle, clipped to the view box."""
    return _arcs(c.center, c.r, parts, style, ctx)


def draw_circle(c: Circle, style: Style, ctx: Context) -> Drawn:
    """A circle, clipped to the view box; compass-style circles as short arcs through their points."""
    parts = [(0.0, TAU)]
    if style.compass:
        parts = compass_parts(c, ctx.points, compass_half(c, ctx))
    return _arcs(c.center, c.r, parts, style, ctx)


def draw_arc(a: Arc, style: Style, ctx: Context) -> Drawn:
    """An arc (e.g. the admissible arc of a θ-circle), clipped to the view box."""
    return _arcs(a.center, a.r, [(a.start, a.sweep)], style, ctx)


def draw_polyline(pl: Polyline, style: Style, ctx: Context) -> Drawn:
    """A sampled curve (pitch curve, cam profile, path) as one SVG polyline (its points are part of the view's
    content box); in a detail window, which shows a part of it, the pieces within the view box
    (:func:`clip_polyline`)."""
    q = ctx.view.ps(pl.points)
    x0, y0, x1, y1 = ctx.view.paper_box
    xs, ys = zip(*q)
    if x0 <= min(xs) and max(xs) <= x1 and y0 <= min(ys) and max(ys) <= y1:
        return Drawn([Poly(tuple(q), pen(style), closed=pl.closed)])
    return Drawn([Poly(piece, pen(style)) for piece in clip_polyline(q + q[:1] if pl.closed else q,
                                                                    (x0, y0, x1, y1))])


def clip_polyline(pts: list[tuple[float, float]], box: tuple[float, float, float, float]
                  ) -> list[tuple[tuple[float, float], ...]]:
    """The pieces of the chain ``pts`` inside ``box`` (each segment clipped, :func:`~.view.clip_interval`).

    >>> clip_polyline([(-1.0, 1.0), (1.0, 1.0), (3.0, 1.0), (3.0, 5.0), (1.0, 5.0)], (0.0, 0.0, 2.0, 2.0))
    [((0.0, 1.0), (1.0, 1.0), (2.0, 1.0))]
    """
    pieces: list[tuple[tuple[float, float], ...]] = []
    cur: list[tuple[float, float]] = []
    for a, b in zip(pts, pts[1:]):
        d = (b[0] - a[0], b[1] - a[1])
        got = clip_interval(a, d, box, 0.0, 1.0)
        if got is None:
            continue
        t0, t1 = got
        p0 = a if t0 == 0.0 else (a[0] + t0 * d[0], a[1] + t0 * d[1])
        p1 = b if t1 == 1.0 else (a[0] + t1 * d[0], a[1] + t1 * d[1])
        if not (cur and t0 == 0.0 and cur[-1] == p0):
            if len(cur) > 1:
                pieces.append(tuple(cur))
            cur = [p0]
        cur.append(p1)
        if t1 < 1.0:
            pieces.append(tuple(cur))
            cur = []
    if len(cur) > 1:
        pieces.append(tuple(cur))
    return pieces
