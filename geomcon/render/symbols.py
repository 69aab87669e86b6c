"""The textbook symbols: ground, slider, guide, angle arcs, right angles, dimensions; and the dispatch from
a value to its drawing.

Symbol sizes are fixed in paper mm, whatever the drawing scale (a hinge is a hinge at any μl).

Examples
--------
>>> from geomcon.geometry import Point
>>> from geomcon.scene.marks import Ground
>>> from geomcon.render.style import STYLES
>>> from geomcon.render.view import View
>>> ctx = Context(View((-10.0, -10.0, 10.0, 10.0), 1.0, (0.0, 0.0)))
>>> len(draw(Ground(Point(0, 0)), STYLES["ground"], ctx).shapes)     # legs, base, five hatch strokes
7
"""
from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
import shapely

from ..geometry.primitives import Arc, Circle, Line, Point, Polyline, Ray, Segment
from ..scene.marks import AngleMark, Bearing, Dimension, Ground, Guide, RightAngleMark, Rotation, Slider, Vector
from .draw import (SLIDER, ANGLE_RADIUS, MIN_ANGLE_RADIUS, least_arc_radius, Context, Drawn, TextRequest, XY, _add, _paper_dir, _unit,
                   draw_arc, draw_circle, draw_line, draw_point, draw_polyline, draw_segment, pen)
from .keepoff import near_strokes, strokes_hit
from .labels import rich_runs, text_width
from .placement import Request
from .shapes import ArcP, Pen, Poly
from .style import MARK_TEXT_SIZE, PAPER, Style
from .view import clip_interval

HATCH = 0.2     # width of hatch strokes
MARK_DISTANCES = (0.0, 2.0, 4.5, 8.0, 12.0, 16.0, 22.0, 30.0)
"""Distances (paper mm beyond the gap) at which an angle's text is tried: farther than a label may go, since
a value always prints (a leader joins a far text to its arc)."""


def draw_ground(g: Ground, style: Style, ctx: Context) -> Drawn:
    """A fixed pivot's ground: two legs from the hinge to a base line, hatched on the ground side at 45° to
    it; turned from its side by the least multiple of 45° (then of 15°, :data:`GROUND_TURNS`) that keeps it off
    every link, frame line, angle mark's sector, guide's hatch (:data:`GUIDE_GAP`) and point of the figure (a
    ground drawn across a link reads as a frame the link cannot pass; one inside an angle's arc hides the
    angle; one by a guide's hatch reads as one frame with it) and :data:`GROUND_ROOM` away from every link and fixed
    link leaving the hinge (the hatch points away from them, not into the corner between two); else the
    multiple of 45° that meets least, then the one with the most room."""
    known = ctx.ground_at.get((ctx.view.p(g.at), g.angle))
    if known is not None and known[0] == style:                  # drawn in that style already
        return Drawn(list(known[1].shapes))
    return ground_choice(g, style, ctx)[1]


def ground_choice(g: Ground, style: Style, ctx: Context) -> tuple[float, Drawn]:
    """The ground symbol :func:`draw_ground` draws, and what it meets (:func:`_collision`; 0: clear)."""
    c = ctx.view.p(g.at)
    near = _near(c, ctx)
    away = _link_directions(c, ctx) + (near.strokes.ways if near.strokes is not None else [])
    best = None
    tried = []                                       # (index, room, drawing): measured the first alone, then
    for i, turn in enumerate(GROUND_TURNS):          # the other multiples of 45°, then the 15° turns together
        angle = g.angle + turn
        room = _angular_room((math.cos(angle), -math.sin(angle)), away)
        if i >= 8 and room < GROUND_ROOM - 1e-9:     # a 15° turn is taken only when clear: not measured
            continue
        tried.append((i, room, _ground_at(c, angle, style)))
    for batch in (tried[:1], [t for t in tried[1:] if t[0] < 8], [t for t in tried if t[0] >= 8]):
        if not batch:
            continue
        for hit, (i, room, out) in zip(_collisions(c, [t[2] for t in batch], near).tolist(), batch):
            if hit == 0.0 and room >= GROUND_ROOM - 1e-9:
                return 0.0, out
            if i >= 8:                               # a 15° turn is taken only when clear
                continue
            if best is None or hit < best[0] - 1e-9 or (abs(hit - best[0]) <= 1e-9 and room > best[1] + 1e-9):
                best = (hit, room, out)
    hit, compact = _compact_ground(g, c, style, away, near)
    return (hit, compact) if compact is not None and hit < best[0] - 1e-9 else (best[0], best[2])


COMPACT_SIZES = (0.8, 0.7, 0.6)
"""The sizes (fractions of the full symbol) a ground symbol shrinks to, largest first, where no turn of the full
one is clear: 001-19's A has D′ 5.4 mm above it, its links leave 108° free and the full symbol's base touched D′'s
pin; 200-03's cam profile runs 5 mm from O, so O's ground hatched across the profile."""

COMPACT_TURNS = tuple(math.radians(d) for d in sorted(range(-175, 181, 5), key=lambda d: (abs(d), -d)))
"""The turns a shrunk ground symbol tries, in 5° steps nearest first (001-19's A is clear only near 144°)."""

COMPACT_HALF = 3.0
"""Half the base of a shrunk ground symbol, in full-size paper mm (the full one's is 4.2, its legs' 2.6): its
corners lie 35.5° off its direction, not 45°, so it fits between links 80° apart."""

COMPACT_ROOM = math.radians(40.6)
"""Least angle between a shrunk ground symbol's direction and a link leaving its hinge: its corners' 35.5° and 5°
(as the full one's 45° and 5°, :data:`GROUND_ROOM`; 001-30b's O, shrunk into its base circle, sat 40° off OA)."""

COMPACT_GAP = (0.8, 2.0)
"""Least paper mm between a shrunk ground symbol and the centre line of a link not at its hinge (half a link's
width, 0.35 mm, half a stroke and a 0.3 mm gap) and a point of the figure (a pin's 1.5 mm radius, its outline and
a gap): shrunk, it stands in a tight place and must read as apart from what is near."""


def _compact_ground(g: Ground, c: XY, style: Style, away: list[XY], near: Near) -> tuple[float, Drawn | None]:
    """The largest shrunk ground symbol (:data:`COMPACT_SIZES`) at paper point ``c`` whose turn
    (:data:`COMPACT_TURNS`) keeps it :data:`COMPACT_GAP` clear of every link and point, out of every angle
    mark's sector and :data:`COMPACT_ROOM` off the links at its hinge, with 0; when none is, the one that meets
    least (:func:`_collision`) and what it meets (200-19's O: every full-size turn meets a dimension's line or
    two limit bands, the shrunk one only a band); (inf, None) when no turn keeps that room.

    A pin 5.4 mm below the hinge: the full symbol (base 4.2 mm out, 8.4 mm long) would touch it; shrunk to 0.8,
    its base 2 × 3.0 × 0.8 = 4.8 mm long,
    and turned 55° (its base's middle 35° below the paper's x axis) it stands clear:

    >>> from geomcon.render.style import STYLES
    >>> from geomcon.render.view import View
    >>> ctx = Context(View((-10.0, -10.0, 10.0, 10.0), 1.0, (0.0, 0.0)), points=(Point(0, 0), Point(0, -5.4)))
    >>> hit, out = _compact_ground(Ground(Point(0, 0)), (10.0, 10.0), STYLES["ground"], [], _near((10.0, 10.0), ctx))
    >>> (a, b) = out.shapes[1].pts
    >>> round(math.dist(a, b), 2), round(math.degrees(math.atan2((a[1] + b[1]) / 2 - 10, (a[0] + b[0]) / 2 - 10)))
    (4.8, 35)
    """
    best: tuple[float, Drawn | None] = (math.inf, None)
    angles = [g.angle + turn for turn in COMPACT_TURNS
              if _angular_room((math.cos(g.angle + turn), -math.sin(g.angle + turn)), away) >= COMPACT_ROOM - 1e-9]
    for size in COMPACT_SIZES:
        for k in range(0, len(angles), COMPACT_BATCH):
            outs = [_ground_at(c, a, style, size, COMPACT_HALF) for a in angles[k:k + COMPACT_BATCH]]
            for hit, out in zip(_collisions(c, outs, near, COMPACT_GAP).tolist(), outs):
                if hit == 0.0:
                    return 0.0, out
                if hit < best[0] - 1e-9:
                    best = (hit, out)
    return best


COMPACT_BATCH = 12
"""How many turns of a shrunk ground symbol are measured at once (:func:`_collisions`)."""


GROUND_TURNS = tuple(math.radians(d) for d in (0, 45, -45, 90, -90, 135, -135, 180)) + tuple(
    math.radians(d) for d in sorted((d for d in range(-165, 181, 15) if d % 45), key=lambda d: (abs(d), -d)))
"""The turns a ground symbol tries, in order: the 8 multiples of 45°, then the 15° steps between them, nearest
first (001-19b's A has its guide bar straight up and its cranks 30° below the horizontal: the clear direction,
up-left at 150°, is no multiple of 45°)."""

GROUND_ROOM = math.radians(50.0)
"""Least angle (radians) between a ground symbol's direction and a link or fixed link leaving its hinge: the base's
corners lie 45° off its direction and the hatch reaches beyond, so a line nearer runs into it (001-16: A's ground
ran into the corner of AB1 and the frame AD)."""


def _link_directions(c: XY, ctx: Context) -> list[XY]:
    """Unit paper directions of the links and fixed links leaving the hinge at paper point ``c`` (a link through
    it counts both ways)."""
    out = []
    for a, b in ctx.links + ctx.frames:
        for p, q in ((a, b), (b, a)):
            d = math.hypot(q[0] - c[0], q[1] - c[1])
            if math.hypot(p[0] - c[0], p[1] - c[1]) <= 0.5 and d > 0.5:
                out.append(((q[0] - c[0]) / d, (q[1] - c[1]) / d))
        seg = (b[0] - a[0], b[1] - a[1])
        n = math.hypot(*seg)
        if n > 1.0:
            t = ((c[0] - a[0]) * seg[0] + (c[1] - a[1]) * seg[1]) / (n * n)
            off = abs((c[0] - a[0]) * seg[1] - (c[1] - a[1]) * seg[0]) / n
            if off <= 0.5 and 0.5 / n < t < 1.0 - 0.5 / n:            # through the hinge
                out += [(seg[0] / n, seg[1] / n), (-seg[0] / n, -seg[1] / n)]
    return out


def _angular_room(u: XY, away: list[XY]) -> float:
    """The least angle (radians) between paper direction ``u`` and the directions ``away`` (π when none).

    >>> round(math.degrees(_angular_room((0.0, 1.0), [(1.0, 0.0), (0.0, -1.0)])), 6)
    90.0
    """
    return min((math.acos(max(-1.0, min(1.0, u[0] * v[0] + u[1] * v[1]))) for v in away), default=math.pi)


POINT_GAP = 2.0
"""Least paper mm between a ground symbol and the centre of another point of the figure: a pin's 1.5 mm radius,
its outline and a visible gap (at 1.5 mm, 001-12's A ground touched B1's pin)."""

GROUND_REACH = 9.0
"""Paper mm from its hinge beyond which nothing can meet a ground symbol (its base's corners lie 5.9 mm out,
its hatch strokes 1.7 mm further)."""


class Near(NamedTuple):
    """What a ground symbol at one hinge may meet (:func:`_near`), with what every turn tried measures alike."""

    links: Any
    pies: Any
    pts: list[XY]
    dims: Any
    guides: Any
    """The guides' hatched bands within reach (:func:`guide_bands`), None without."""
    apart: Any
    """Which of ``links`` do not leave the hinge (kept clear of by a shrunk symbol)."""
    spots: Any
    """``pts`` as one shapely MultiPoint (None without points)."""
    strokes: Any = None
    """The kept-off circles, arcs and bands within reach (:func:`.keepoff.near_strokes`), or None."""
    framed: Any = None
    """Which of ``links`` are fixed links drawn dash-dot (an arrow ω may cross them)."""


def _lines(polylines: Any) -> np.ndarray:
    """``shapely.LineString`` of each of ``polylines`` (the same coordinates), made in one call.

    >>> _lines([((0, 0), (1, 0)), ((0, 1), (1, 1), (2, 2))]).tolist() == [shapely.LineString([(0, 0), (1, 0)]),
    ...                                                                 shapely.LineString([(0, 1), (1, 1), (2, 2)])]
    True
    """
    xy = [np.asarray(q, dtype=float).reshape(-1, 2) for q in polylines]
    return shapely.linestrings(np.concatenate(xy), indices=np.repeat(np.arange(len(xy)), [len(q) for q in xy]))


def _near(c: XY, ctx: Context) -> Near:
    """What a ground symbol at ``c`` may meet, whichever way it turns: the links, fixed links and curves drawn
    as links (a cam's profile), the angle marks' sectors and the dimensions' lines
    within :data:`GROUND_REACH` (as shapely arrays) and the other points within 12 mm."""
    spot = shapely.Point(c)
    lines = ctx.links + ctx.frames + ctx.curves    # a hatch across the frame AD or a cam's profile reads as wrong
    made = ctx.memo.get("lines")                                                 # as across a link
    if made is None or any(a is not b for a, b in zip(made[0], (ctx.links, ctx.frames, ctx.curves))):
        made = ctx.memo["lines"] = ((ctx.links, ctx.frames, ctx.curves), _lines(lines) if lines else None)
    links = made[1]                                # made once a figure (a cam's profile: 1 900 points)
    pies = np.array([shapely.Polygon(p) for p in ctx.sectors], dtype=object) if ctx.sectors else None
    framed = None
    if links is not None:
        reach = shapely.dwithin(links, spot, GROUND_REACH)
        links = links[reach]
        framed = (np.arange(len(lines)) >= len(ctx.links)) & (np.arange(len(lines)) < len(ctx.links) + len(ctx.frames))
        framed = framed[reach]
    if pies is not None:
        pies = pies[shapely.dwithin(pies, spot, GROUND_REACH)]
    pts = [q for q in map(ctx.view.p, ctx.points) if 1e-9 < math.hypot(q[0] - c[0], q[1] - c[1]) <= 12.0]
    dims = _lines(ctx.dims) if ctx.dims else None
    if dims is not None:
        dims = dims[shapely.dwithin(dims, spot, GROUND_REACH)]
    bands = np.array([shapely.Polygon(b) for b in ctx.guides], dtype=object) if ctx.guides else None
    if bands is not None:
        bands = bands[shapely.dwithin(bands, spot, GROUND_REACH + GUIDE_GAP)]
    apart = ~shapely.dwithin(links, spot, 0.5) if links is not None and len(links) else None
    return Near(links, pies, pts, dims, bands, apart, shapely.MultiPoint(pts) if pts else None,
                near_strokes(c, ctx.strokes, GROUND_REACH) if ctx.strokes else None, framed)


def dimension_lines(values: list[Any], view: Any) -> tuple[tuple[XY, XY], ...]:
    """The paper segments of the dimensions among ``values``: each dimension line (the measured points shifted by
    its offset) and, when it stands off them, its two extension lines. A ground symbol keeps off them: 200-09's
    and 200-19's O hung its hatch across the offset e's dimension line, 4 mm below O (issue 11, crowded knots).

    >>> from geomcon.render.view import View
    >>> dimension_lines([Dimension(Point(0, 0), Point(10, 0), "e", 10.0, -4.0)], View((-20, -20, 20, 20), 1.0, (0, 0)))
    (((20.0, 24.0), (30.0, 24.0)), ((20.0, 21.0), (20.0, 24.0)), ((30.0, 21.0), (30.0, 24.0)))
    """
    out: list[tuple[XY, XY]] = []
    for m in values:
        if not isinstance(m, Dimension) or m.a == m.b:
            continue
        shift = (m.b - m.a).unit().perp() * m.offset
        pa, pb, qa, qb = view.p(m.a), view.p(m.b), view.p(m.a + shift), view.p(m.b + shift)
        out.append((qa, qb))
        if view.length(abs(m.offset)) > 1.0:              # drawn from 1 mm off the measured point
            n = _unit(qa[0] - pa[0], qa[1] - pa[1])
            out += [(_add(pa, n, 1.0), qa), (_add(pb, n, 1.0), qb)]
    return tuple(out)


def _collision(c: XY, drawn: Drawn, near: Near, gaps: tuple[float, float] | None = None) -> float:
    """How much a ground symbol at paper point ``c`` meets, away from the hinge it holds: the length of it
    inside angle marks' sectors, plus 10 mm for each link it crosses (or comes within ``gaps[0]`` of, for a link not
    at its hinge) and for each
    other point of the figure it comes within :data:`POINT_GAP` (``gaps[1]``) of (0 when clear), 5 mm for each
    circle or band kept off (:mod:`.keepoff`) it comes near; ``near`` from :func:`_near`."""
    return float(_collisions(c, [drawn], near, gaps)[0])


HINGE_CUT = 1.7
"""Paper mm of a ground symbol's legs next to its hinge left out when measuring what it meets (they meet there)."""


def _toward(p: XY, q: XY, d: float) -> XY:
    """The point ``d`` from ``p`` towards ``q``."""
    n = math.hypot(q[0] - p[0], q[1] - p[1])
    return (p[0] + (q[0] - p[0]) * d / n, p[1] + (q[1] - p[1]) * d / n)


def _collisions(c: XY, drawns: list[Drawn], near: Near, gaps: tuple[float, float] | None = None) -> np.ndarray:
    """:func:`_collision` of each of ``drawns`` (ground symbols at ``c``), measured together (a shrunk symbol's
    turns are tried a dozen at a time)."""
    links, pies, pts, dims = near.links, near.pies, near.pts, near.dims
    parts, counts = [], []
    for d in drawns:                       # the legs (first shape, through the hinge) cut HINGE_CUT from it
        (a, h, b), rest = d.shapes[0].pts, d.shapes[1:]
        parts += [(a, _toward(h, a, HINGE_CUT)), (_toward(h, b, HINGE_CUT), b)] + [s.pts for s in rest]
        counts.append(2 + len(rest))
    lines = shapely.linestrings(np.concatenate([np.asarray(q, dtype=float) for q in parts]),
                                indices=np.repeat(np.arange(len(parts)), [len(q) for q in parts]))
    geo = shapely.multilinestrings(lines, indices=np.repeat(np.arange(len(drawns)), counts))[:, None]
    hit = np.zeros(len(drawns))
    if links is not None and len(links):
        touch = shapely.intersects(geo, links[None, :])
        if gaps is not None:                       # kept apart from links not at its hinge
            touch |= shapely.dwithin(geo, links[None, :], gaps[0]) & near.apart[None, :]
        hit += 10.0 * touch.sum(axis=1)
    if pts:
        hit += 10.0 * shapely.dwithin(geo[:, 0], near.spots, POINT_GAP if gaps is None else gaps[1])
    if pies is not None and len(pies):
        hit += shapely.length(shapely.intersection(geo, pies[None, :])).sum(axis=1)
    if dims is not None and len(dims):
        hit += 10.0 * shapely.dwithin(geo, dims[None, :], DIM_GAP).sum(axis=1)
    if near.guides is not None and len(near.guides):
        hit += 10.0 * shapely.dwithin(geo, near.guides[None, :], GUIDE_GAP).sum(axis=1)
    if near.strokes is not None:                   # a crank's circle, a limit band: 5 mm each, less than a link
        hit += 5.0 * strokes_hit(geo, near.strokes)                # or a dimension's line
    return hit


GUIDE_GAP = 1.5
"""Least paper mm between a ground symbol and a guide's hatched band: closer, the two hatches read as one frame
(000-02's A hung its hatch 1.2 mm above the ram's guide's at 1:5, 004-02 (K = 1.5)'s A* 0.26 mm; 004-02
(K = 1.2)'s A* stands 1.9 mm off its guide's end and reads apart)."""


def guide_bands(values: list[Any], view: Any) -> tuple[tuple[XY, ...], ...]:
    """The paper polygons the guides among ``values`` cover with their surface and hatch (:func:`draw_guide`):
    a ground symbol keeps :data:`GUIDE_GAP` off them.

    >>> from geomcon.render.view import View
    >>> [[tuple(round(c, 2) for c in q) for q in b] for b in guide_bands([Guide(Point(0, 0), Point(10, 0), 1)],
    ...                                                                  View((-20, -20, 20, 20), 1.0, (0, 0)))]
    [[(20.0, 17.5), (30.0, 17.5), (30.0, 16.23), (19.93, 16.23)]]
    """
    out = []
    for m in values:
        if isinstance(m, Guide) and m.a != m.b:
            a2, b2, n, u = _guide_surface(m, view)       # the strokes lean back along a→b: the first starts
            back = GUIDE_FIRST - GUIDE_HATCH_DEPTH          # 1.2 mm in and ends 0.07 mm before a2
            out.append((a2, b2, _add(b2, n, GUIDE_HATCH_DEPTH), _add(_add(a2, n, GUIDE_HATCH_DEPTH), u, min(0.0, back))))
    return tuple(out)


DIM_GAP = 0.5
"""Least paper mm between a ground symbol and a dimension's line or extension line: touching, its hatch reads as
part of the dimension (200-09's O, turned off e's dimension line, touched e's extension line with its base's end)."""


def sector(m: AngleMark, view: Any, nested: int = 1) -> tuple[XY, ...]:
    """The paper polygon an angle mark covers: its vertex and its arc at the largest radius it may be drawn
    with (:func:`_radius` with ``nested`` marks at the vertex), 1 mm beyond; () for a mark of no angle.

    >>> from geomcon.render.view import View
    >>> p = sector(AngleMark(Point(0, 0), Point(1, 0), Point(0, 1), "θ", 90.0), View((-20, -20, 20, 20), 1.0, (0, 0)))
    >>> p[0], len(p) > 10
    ((20.0, 20.0), True)
    """
    if m.a == m.vertex or m.b == m.vertex:
        return ()
    va, vb, _ = angle_rays(m)
    a0 = math.atan2(va.y, va.x)
    phi = sweep(m, va, vb)
    if abs(phi) <= math.radians(0.2):
        return ()
    r = arc_radius(m, vb, phi, view, nested - 1)
    c = view.p(m.vertex)
    arc = ArcP(c, r + 1.0, -a0, -phi, Pen("#000", 0.1))
    n = max(4, int(abs(phi) / math.radians(10.0)) + 1)
    if m.radius and r > ANGLE_RADIUS:           # a far arc of its own radius: the band along it, not the pie
        inner = ArcP(c, r - 1.0, -a0, -phi, Pen("#000", 0.1))     # (001-29's δ0, δ0′ on the offset circle,
        return tuple(arc.at(i / n) for i in range(n + 1)) + tuple(inner.at(1 - i / n) for i in range(n + 1))
    return (c,) + tuple(arc.at(i / n) for i in range(n + 1))         # 15 mm about O, left O's ground no room)


def _ground_at(c: XY, angle: float, style: Style, size: float = 1.0, half: float = 4.2) -> Drawn:
    """The ground symbol at paper point ``c``, the ground towards model angle ``angle``, ``size`` times its
    full size, its base ``half`` × ``size`` long each side (a compact one's base barely overhangs its legs)."""
    u = (math.cos(angle), -math.sin(angle))        # towards the ground, on paper
    n = (-u[1], u[0])
    base = _add(c, u, 4.2 * size)
    p = pen(style)
    legs = Poly((_add(base, n, 2.6 * size), c, _add(base, n, -2.6 * size)), p)
    line = Poly((_add(base, n, -half * size), _add(base, n, half * size)), p)
    out = Drawn([legs, line])
    slant = _unit(u[0] - n[0], u[1] - n[1])
    for k in range(5):
        s = (-half + 1.6 + k * (2.0 * half - 1.6) / 4.0) * size
        q = _add(base, n, s)
        out.shapes.append(Poly((q, _add(q, slant, 1.7 * size)), Pen(style.stroke, HATCH)))
    return out


def draw_slider(s: Slider, style: Style, ctx: Context) -> Drawn:
    """A slider block centred on its joint, its long side along the direction of motion; made smaller where
    another block of the figure comes near, so that the two stay apart by :data:`BLOCK_GAP`
    (:func:`_block_size`).

    >>> from geomcon.geometry import Point
    >>> from geomcon.render.style import STYLES
    >>> from geomcon.render.view import View
    >>> ctx = Context(View((-20.0, -20.0, 20.0, 20.0), 1.0, (0.0, 0.0)), sliders=(((20.0, 20.0), (1.0, 0.0)),
    ...                                                                              ((26.0, 20.0), (1.0, 0.0))))
    >>> xs = [x for x, _ in draw_slider(Slider(Point(0, 0), Point(1, 0)), STYLES["slider"], ctx).shapes[0].pts]
    >>> round(max(xs) - min(xs), 6)                  # 6 mm from the next block: 4.8 mm long, 1.2 mm apart
    4.8
    """
    c = ctx.view.p(s.at)
    u = _paper_dir(s.direction)
    return Drawn([Poly(_block(c, u, *_block_size(c, u, ctx)), pen(style), closed=True, fill=PAPER)])


BLOCK_GAP = 0.8
"""Least paper distance (mm) between two slider blocks on one guide line."""


def _block(c: XY, u: XY, a: float, b: float) -> tuple[XY, ...]:
    n = (-u[1], u[0])
    return tuple(_add(_add(c, u, i * a), n, j * b) for i, j in ((1, 1), (-1, 1), (-1, -1), (1, -1)))


def _block_size(c: XY, u: XY, ctx: Context) -> tuple[float, float]:
    """Half the length and half the width of the block at ``c`` along ``u``: those of :data:`SLIDER`, or less
    where another block of the figure would come nearer than :data:`BLOCK_GAP`. Each pair of blocks shrinks
    alike (first the length, to half of it, then the width, to 60 %), so both ends of a pair agree. A block also
    shortens (not narrows) until it keeps :data:`PIN_CLEAR` from every other point of the figure.

    >>> from geomcon.render.view import View
    >>> ctx = Context(View((-20.0, -20.0, 20.0, 20.0), 1.0, (0.0, 0.0)), points=(Point(0, 0), Point(4.5, 1.0)))
    >>> _block_size((20.0, 20.0), (1.0, 0.0), ctx)           # a pin 4.5 mm along: 2.8 mm half-length, not 4
    (2.8, 2.5)
    >>> _block_size((20.0, 20.0), (1.0, 0.0), Context(ctx.view, points=(Point(0, 0),)))
    (4.0, 2.5)
    """
    a, b = SLIDER[0] / 2, SLIDER[1] / 2
    steps = [(a * f, b) for f in (1.0, 0.9, 0.8, 0.7, 0.6, 0.5)] + [(a / 2, b * f) for f in (0.9, 0.8, 0.7, 0.6)]
    for q, w in ctx.sliders:
        if math.hypot(q[0] - c[0], q[1] - c[1]) <= 1e-6 or math.hypot(q[0] - c[0], q[1] - c[1]) > 2 * (a + b):
            continue
        for i, (sa, sb) in enumerate(steps):
            mine, theirs = shapely.Polygon(_block(c, u, sa, sb)), shapely.Polygon(_block(q, w, sa, sb))
            if mine.distance(theirs) >= BLOCK_GAP or i == len(steps) - 1:
                a, b = min(a, sa), min(b, sb)
                break
    others = [q for q in map(ctx.view.p, ctx.points) if SAME_SPOT < math.hypot(q[0] - c[0], q[1] - c[1]) <= 2 * (a + b)]
    if others:
        spots = shapely.MultiPoint(others)
        lengths = [sa for sa, _ in steps[:6] if sa <= a]            # its width stays: it runs on its guide
        for i, sa in enumerate(lengths):
            if shapely.Polygon(_block(c, u, sa, b)).distance(spots) >= PIN_CLEAR or i == len(lengths) - 1:
                a = sa
                break
    return a, b


SAME_SPOT = 1e-3
"""Paper mm within which a point is the block's own joint (a pin drawn at the block's centre)."""

PIN_CLEAR = 1.6
"""Least paper mm between a slider block and the centre of another point of the figure: a pin's 1.25 mm radius
and a gap. A block is 8 mm long at any scale, and at 1:5 the points a design by K finds beside C1 lie closer:
004-02's B2 pin and E dot sat on C1's block, 001-06b's C3 on its edge (issue 11, crowded knots); the block
shortens as for a neighbouring block (:func:`_block_size`), down to half its length; its width stays, so that it
still runs on its guide's hatched line."""


def draw_guide(g: Guide, style: Style, ctx: Context) -> Drawn:
    """A guide: the surface the slider blocks run on (half a block below the line a–b on its ``side``),
    hatched on that side; cut to the view's paper box (less the hatch's depth)."""
    if g.a == g.b:
        return Drawn()
    a2, b2, n, u = _guide_surface(g, ctx.view)
    x0, y0, x1, y1 = ctx.view.paper_box           # cut to the view, its hatch too (a detail window's at 1:1:
    m = GUIDE_HATCH_DEPTH                         # 004-02's guide runs on far beyond the window about A*, C1)
    cut = clip_interval(a2, (b2[0] - a2[0], b2[1] - a2[1]), (x0 + m, y0 + m, x1 - m, y1 - m), 0.0, 1.0)
    if cut is None:
        return Drawn()
    if cut != (0.0, 1.0):
        a2, b2 = (_add(a2, (b2[0] - a2[0], b2[1] - a2[1]), cut[0]), _add(a2, (b2[0] - a2[0], b2[1] - a2[1]), cut[1]))
    out = Drawn([Poly((a2, b2), pen(style))])
    length = math.hypot(b2[0] - a2[0], b2[1] - a2[1])
    slant = _unit(n[0] - u[0], n[1] - u[1])
    k = GUIDE_FIRST
    while k <= length:
        q = _add(a2, u, k)
        out.shapes.append(Poly((q, _add(q, slant, GUIDE_STROKE)), Pen(style.stroke, HATCH)))
        k += 2.4
    return out


GUIDE_STROKE = 1.8
"""Length of a guide's hatch stroke (paper mm), at 45° to its surface."""

GUIDE_FIRST = 1.2
"""Where a guide's first hatch stroke starts, paper mm from its surface's start (then every 2.4 mm)."""

GUIDE_HATCH_DEPTH = GUIDE_STROKE * math.sqrt(0.5)
"""How far a guide's hatch reaches beyond its surface (paper mm)."""


def _guide_surface(g: Guide, view: Any) -> tuple[XY, XY, XY, XY]:
    """A guide's surface on paper (half a block off the line a–b on its ``side``), the unit normal towards its
    hatch and the unit direction a→b."""
    pa, pb = view.p(g.a), view.p(g.b)
    u = _unit(pb[0] - pa[0], pb[1] - pa[1])
    side = -1.0 if g.side >= 0 else 1.0                 # model left of a→b is paper right-hand (y flipped)
    n = (-u[1] * side, u[0] * side)
    off = SLIDER[1] / 2
    return _add(pa, n, off), _add(pb, n, off), n, u


BEARING = (6.0, 1.6)
"""A bearing block of a follower's guide: its length along the stem and its offset from the stem's axis
(paper mm)."""


def draw_bearing(m: Bearing, style: Style, ctx: Context) -> Drawn:
    """The guide of a translating follower: two short walls either side of the stem, each hatched on its
    outer side at 45°, the strokes of both parallel (two bearing blocks; strokes mirrored about the stem
    read as an arrow's feathers), the same at every scale and in every cam figure."""
    c = ctx.view.p(m.at)
    u = _paper_dir(m.direction)
    out = Drawn()
    length, off = BEARING
    for side in (1.0, -1.0):
        n = (-u[1] * side, u[0] * side)
        a, b = _add(_add(c, n, off), u, -length / 2), _add(_add(c, n, off), u, length / 2)
        out.shapes.append(Poly((a, b), pen(style)))
        slant = _unit(n[0] - side * u[0], n[1] - side * u[1])      # parallel strokes on both sides: no chevrons
        d = 1.6 * math.sqrt(0.5)                                     # a stroke's run along the wall
        k, hi = max(0.0, side * d) + 0.3, min(length, length + side * d)   # both ends beside the wall
        while k <= hi + 1e-9:
            q = _add(a, u, k)
            out.shapes.append(Poly((q, _add(q, slant, 1.6)), Pen(style.stroke, HATCH)))
            k += 1.2
    return out


def angle_rays(m: AngleMark) -> tuple[Point, Point, bool]:
    """The two ray directions the arc of ``m`` spans, and whether the first was reversed.

    A mark whose value is the supplement of the angle between its rays (a transmission angle "in acute
    form" marked on the links B–C and C–D) is drawn where that value is: between the extension of the
    first ray beyond the vertex and the second ray.

    Examples
    --------
    >>> m = AngleMark(Point(0, 0), Point(-1, 0), Point(1, 1), "γ", 45.0)
    >>> angle_rays(m)[2]
    True
    """
    va, vb = m.a - m.vertex, m.b - m.vertex
    geom = math.degrees(abs(math.atan2(va.cross(vb), va.dot(vb))))
    value = m.value if isinstance(m.value, (int, float)) else geom
    flip = abs(value - geom) > 1e-6 * max(1.0, geom) and abs(180.0 - geom - value) < 1e-6 * max(1.0, geom)
    return (-va if flip else va), vb, flip


def sweep(m: AngleMark, va: Point, vb: Point) -> float:
    """The turn (radians, counter-clockwise positive) the arc of ``m`` makes from ray ``va`` to ray ``vb``: the
    smaller one, or the larger one the other way round when the mark's value is that reflex angle (> 180°,
    360° less the angle between its rays: 001-29's rise angle δ0 = 197.40° from K0 to K1).

    >>> reflex, plain = (AngleMark(Point(0, 0), Point(1, 0), Point(0, 1), "δ", v) for v in (270.0, 90.0))
    >>> round(math.degrees(sweep(reflex, reflex.a, reflex.b)), 6), round(math.degrees(sweep(plain, plain.a, plain.b)), 6)
    (-270.0, 90.0)
    """
    phi = math.atan2(va.cross(vb), va.dot(vb))
    value = m.value if isinstance(m.value, (int, float)) else None
    if value is not None and value > 180.0 and abs(360.0 - value - math.degrees(abs(phi))) < 1e-6 * value:
        return phi - math.copysign(math.tau, phi)
    return phi


def arc_radius(m: AngleMark, vb: Point, phi: float, view: Any, nested: int = 0) -> float:
    """Arc radius on paper of mark ``m`` spanning ``phi`` radians towards ray ``vb``: the mark's own, else
    :data:`ANGLE_RADIUS`, shortened for short rays (rays shorter than 4 mm of paper only give a direction), enlarged
    by 3.5 mm for each of ``nested`` earlier marks at the same vertex; never less than
    :func:`~geomcon.render.draw.least_arc_radius` — :data:`MIN_ANGLE_RADIUS` (001-23a's α arcs were 4.5 mm,
    001-24's and 200-01's 3 mm: they barely showed), more for a small angle, whose arc must be long enough to read
    as an arc (001-08's θ = 12.5° at 9 mm was a 2 mm tick).

    >>> from geomcon.render.view import View
    >>> v = View((-50, -50, 50, 50), 1.0, (0, 0))
    >>> m = AngleMark(Point(0, 0), Point(40, 0), Point(40, 10), "θ", 14.04)
    >>> round(arc_radius(m, m.b - m.vertex, math.radians(14.04), v), 3)     # 9 mm would draw 2.2 mm of arc
    14.283
    >>> arc_radius(m, m.b - m.vertex, math.radians(60.0), v)
    9.0
    >>> k = AngleMark(Point(0, 0), Point(5, 0), Point(0, 5), "α", 90.0)     # rays of 5 mm: the arc keeps off their ends
    >>> arc_radius(k, k.b - k.vertex, math.radians(90.0), v)
    5.7
    """
    if m.radius:
        return max(MIN_ANGLE_RADIUS, view.length(m.radius))
    lengths = [view.length(abs(v)) for v in (m.a - m.vertex, vb)]
    rays = [x for x in lengths if x >= 4.0]
    r = min(ANGLE_RADIUS, 0.6 * min(rays)) if rays else ANGLE_RADIUS
    r = max(r, MIN_ANGLE_RADIUS)
    grown = min(least_arc_radius(phi), SMALL_ANGLE_REACH * min(rays, default=0.0))
    if (grown - r) * abs(phi) >= ARC_GAIN:                 # a growth the eye cannot see moves the figure for nothing
        r = grown
    for x in lengths:
        if abs(r - x) < OFF_RAY_END:
            r = x + OFF_RAY_END
    return r + NEST_STEP * nested


ARC_GAIN = 0.5
"""Paper mm of arc length a small angle's arc must gain to be grown at all (004-02's θ would gain 0.06 mm)."""

SMALL_ANGLE_REACH = 0.8
"""A small angle's arc grows (:func:`~geomcon.render.draw.least_arc_radius`) within this part of its shorter ray, so
that it still ends on both lines: 001-08's θ to 16 mm on AC1 = 20 mm; a pressure angle's short rays (a knife's 5 mm)
keep its arc where it was."""

OFF_RAY_END = 0.7
"""Paper mm an arc keeps off the end of one of its rays: there lies a point drawn with a circle (200-01's roller, 5 mm
both at 1:2, hid its αmax arc at B0)."""


def _radius(m: AngleMark, va: Point, vb: Point, phi: float, ctx: Context) -> float:
    """:func:`arc_radius` of ``m`` (its arc from ray ``va`` over ``phi`` radians to ``vb``), counting it among the
    marks drawn at its vertex; drawn smaller where it would run through a point of the figure
    (:func:`_off_points`)."""
    if m.radius:
        return arc_radius(m, vb, phi, ctx.view)
    drawn = ctx.marks_at.setdefault((round(m.vertex.x, 9), round(m.vertex.y, 9)), [])
    r = _off_points(arc_radius(m, vb, phi, ctx.view, len(drawn)), m.vertex, va, phi, ctx)
    for _ in range(len(drawn)):            # nested by count, a small angle's grown arc may still meet an earlier
        near = [x for x in drawn if abs(x - r) < ARC_APART]        # one (200-20's ψ0′ at 18.5 mm, ψ0 at 20)
        if not near:
            break
        inner = min(near) - NEST_STEP
        r = inner if inner >= least_arc_radius(phi) and not [x for x in drawn if abs(x - inner) < ARC_APART] \
            else max(near) + NEST_STEP
    drawn.append(r)
    return r


NEST_STEP = 3.5
"""Paper mm between the arcs of angle marks nested about one vertex (:func:`arc_radius`)."""

ARC_APART = 2.0
"""Paper mm the arcs of two angle marks about one vertex keep apart at least (as an arc keeps :data:`POINT_CLEAR`
from a point): nearer, they read as one double line and which arc names which angle is unclear (001-21's φ1, φ2
arcs on its ψ arc, 200-20's ψ0′ arc 1.5 mm inside its ψ0 arc)."""


POINT_CLEAR = 2.0
"""Paper mm an angle's arc keeps from a point of the figure inside its angle (a hinge's circle is 1.5 mm)."""


def _off_points(r: float, vertex: Point, va: Point, phi: float, ctx: Context) -> float:
    """The radius ``r`` of an arc about ``vertex`` from ray ``va`` over ``phi`` radians, made smaller (not below
    :func:`~geomcon.render.draw.least_arc_radius`) until it runs :data:`POINT_CLEAR` clear of every point of the figure inside the angle:
    001-19's 180° − θ arc about A ran through the pin of C, 10 mm below A at 1:5."""
    a0 = math.atan2(va.y, va.x)
    inside = []
    for p in ctx.points:
        d = ctx.view.length(abs(p - vertex))
        if d <= 1e-9:
            continue
        t = (math.atan2(p.y - vertex.y, p.x - vertex.x) - a0) * (1.0 if phi >= 0 else -1.0)
        if t % math.tau <= abs(phi):
            inside.append(d)
    floor = least_arc_radius(phi)
    for _ in range(len(inside)):
        hit = [d for d in inside if abs(d - r) < POINT_CLEAR]
        if not hit or min(hit) - POINT_CLEAR < floor:
            return r
        r = min(hit) - POINT_CLEAR
    return r


def draw_angle(m: AngleMark, style: Style, ctx: Context) -> Drawn:
    """The arc of a marked angle and its text with its value, as the textbook prints it (``θ=12.51°``),
    placed later near the bisector outside the arc, or farther with a leader where the figure is crowded."""
    if m.a == m.vertex or m.b == m.vertex:
        return Drawn()
    va, vb, flip = angle_rays(m)
    a0 = math.atan2(va.y, va.x)
    phi = sweep(m, va, vb)                               # model, counter-clockwise positive
    r = _radius(m, va, vb, phi, ctx)
    c = ctx.view.p(m.vertex)
    out = Drawn()
    arc = ArcP(c, r, -a0, -phi, pen(style))
    if abs(phi) > math.radians(0.2):
        out.shapes.append(arc)
    if flip:                                              # the extension the arc starts from
        out.shapes.append(Poly((c, _add(c, _paper_dir(va), r + 2.5)), Pen(style.stroke, 0.18, (1.2, 0.8))))
    mid, prefer = arc.at(0.5), -(a0 + phi / 2)
    out.texts.append(_mark_text(rich_runs(m.text), mid, prefer, None))
    return out


def _mark_text(runs: tuple[tuple[str, bool], ...], anchor: XY, prefer: float,
               fallback: TextRequest | None) -> TextRequest:
    sub = any(s for _, s in runs)
    req = Request(anchor, text_width(runs, MARK_TEXT_SIZE) + 0.3, MARK_TEXT_SIZE * (0.95 if sub else 0.78), 0.5,
                  prefer, spread=0.05, distances=MARK_DISTANCES)
    return TextRequest(runs, MARK_TEXT_SIZE, req, cls="mark-text", fallback=fallback)


ROTATION_RADIUS = 6.5
"""Radius (paper mm) of the arrow of a sense of rotation (ω) about its centre."""

ROTATION_SWEEP = math.radians(110.0)
"""The angle the arrow of a sense of rotation spans."""

ROTATION_SIDES = tuple(math.radians(d) for d in (90, 45, 135, 0, 180, 315, 225, 270))
"""The model directions of the middle of the arrow of a sense of rotation, in the order tried: above its centre
first (the ground hangs below), then turned ever further; the first that meets least is drawn (200-09's ω above O
ran across r0's dimension line and s0's arrowhead)."""

ROTATION_WEIGHTS = (4.0, 10.0, 1.0, 4.0)
"""What the arrow meeting one of them costs: a link or a curve drawn as a link (a cam's profile; not a dash-dot
frame line, which an arrow may cross), a dimension's line (most: the arrow reads as the dimension's), a circle or
band kept off (:mod:`.keepoff`: least, the arrow reads across a translucent band), a point of the figure."""

ROTATION_GAP = 1.0
"""Least paper mm between the arrow's arc and a link or a dimension's line (its arrowhead is 1.6 mm wide)."""


def rotation_arc(m: Rotation, ctx: Context) -> ArcP:
    """The arc of the arrow of a sense of rotation: :data:`ROTATION_SWEEP` at :data:`ROTATION_RADIUS` about its
    centre, on the first side (:data:`ROTATION_SIDES`) that meets least (:data:`ROTATION_WEIGHTS`), running the
    way the part turns.

    Alone, the arrow stands above its centre; a link straight up from it turns it to the right (at 45° its arc
    would still cross the link):

    >>> from geomcon.render.style import STYLES
    >>> from geomcon.render.view import View
    >>> ctx = Context(View((-10.0, -10.0, 10.0, 10.0), 1.0, (0.0, 0.0)))
    >>> a = rotation_arc(Rotation(Point(0, 0), 1.0), ctx)
    >>> round(math.degrees(-(a.start + a.sweep / 2)))
    90
    >>> ctx.links = (((10.0, 10.0), (10.0, 0.0)),)
    >>> a = rotation_arc(Rotation(Point(0, 0), 1.0), ctx)
    >>> round(math.degrees(-(a.start + a.sweep / 2)))
    0
    """
    return rotation_arcs(m, ctx)[0]


def rotation_arcs(m: Rotation, ctx: Context) -> list[ArcP]:
    """The arcs the arrow of a sense of rotation may take (:func:`rotation_arc`): the first side that meets
    nothing alone, else every side that meets least, in the order tried (the ground at its centre then takes the
    first that leaves it a clear place, :func:`geomcon.render.figure.rotation_turns`)."""
    c = ctx.view.p(m.at)
    near = _near(c, ctx)
    links = near.links[~near.framed] if near.links is not None else None
    least, out = math.inf, []
    for mid in ROTATION_SIDES:
        lo, hi = mid - ROTATION_SWEEP / 2, mid + ROTATION_SWEEP / 2
        start, end = (lo, hi) if m.sense > 0 else (hi, lo)
        arc = ArcP(c, ROTATION_RADIUS, -start, -(end - start), Pen("#000", 0.25))
        hit = _rotation_hit(arc, near, links)
        if hit == 0.0:
            return [arc]
        if hit < least - 1e-9:
            least, out = hit, [arc]
        elif hit <= least + 1e-9:
            out.append(arc)
    return out


def _rotation_hit(arc: ArcP, near: Near, links: Any) -> float:
    """What the arrow's ``arc`` meets (:data:`ROTATION_WEIGHTS`), ``near`` from :func:`_near` of its centre,
    ``links`` the links and curves drawn as links (not the frame lines) near it."""
    geo = shapely.LineString([arc.at(k / 24) for k in range(25)])
    w_link, w_dim, w_stroke, w_pt = ROTATION_WEIGHTS
    hit = 0.0
    if links is not None and len(links):
        hit += w_link * int(shapely.dwithin(geo, links, ROTATION_GAP).sum())
    if near.dims is not None and len(near.dims):
        hit += w_dim * int(shapely.dwithin(geo, near.dims, ROTATION_GAP).sum())
    if near.strokes is not None:
        hit += w_stroke * int(strokes_hit(np.array([geo])[:, None], near.strokes)[0])
    if near.pts:
        hit += w_pt * int(shapely.dwithin(geo, shapely.points(near.pts), POINT_GAP).sum())
    return hit


def draw_rotation(m: Rotation, style: Style, ctx: Context) -> Drawn:
    """The arrow of a sense of rotation: an arc of 110° about its centre on the side that meets least
    (:func:`rotation_arc`), its arrowhead at the end the part turns towards, and the symbol ω placed beside it."""
    c = ctx.view.p(m.at)
    arc = ctx.turns.get(c) or rotation_arc(m, ctx)
    arc = ArcP(arc.c, arc.r, arc.start, arc.sweep, pen(style))
    tip = arc.at(1.0)
    back = arc.at(0.93)                                                # the tangent's direction, backwards
    out = Drawn([arc, _arrow(tip, back, style)], keep_out=[rotation_inside(arc)])
    runs = rich_runs(m.symbol)
    prefer = arc.start + arc.sweep / 2.0                              # outwards from the arc's middle
    req = Request(arc.at(0.5), text_width(runs, MARK_TEXT_SIZE) + 0.3, MARK_TEXT_SIZE * 0.78, 0.6,
                  -math.pi / 2 if abs(prefer + math.pi / 2) < 1e-9 else prefer, spread=0.05, distances=MARK_DISTANCES)
    out.texts.append(TextRequest(runs, MARK_TEXT_SIZE, req, italic=True, cls="mark-text"))
    return out


def rotation_inside(arc: ArcP, n: int = 12) -> tuple[XY, ...]:
    """The inside of the arc of a sense of rotation, on paper: the sector between its centre and its arc (as
    ``n`` + 1 points along it), where no text belongs (:attr:`.draw.Drawn.keep_out`).

    >>> from geomcon.render.shapes import Pen
    >>> pts = rotation_inside(ArcP((0.0, 0.0), 2.0, 0.0, -math.pi / 2, Pen("#000", 0.2)), 2)
    >>> [(round(x, 3), round(y, 3)) for x, y in pts]
    [(0.0, 0.0), (2.0, 0.0), (1.414, -1.414), (0.0, -2.0)]
    """
    return (arc.c,) + tuple(arc.at(k / n) for k in range(n + 1))


RIGHT_ANGLE = 2.2
"""Side of a right angle's square, paper mm."""


def right_angle_square(m: RightAngleMark, view: Any, grow: float = 0.0) -> tuple[XY, ...]:
    """The paper square a right-angle mark draws (its vertex, then the corners along a, across, along b), each
    side ``grow`` mm longer; () for a mark of no angle. A ground symbol keeps out of it as out of an angle's
    sector: 100-02's A hung its legs and hatch over the marks of two perpendicular bisectors' feet, one tangle.

    >>> from geomcon.render.view import View
    >>> right_angle_square(RightAngleMark(Point(0, 0), Point(1, 0), Point(0, 1)), View((-20, -20, 20, 20), 1.0, (0, 0)))
    ((20.0, 20.0), (22.2, 20.0), (22.2, 17.8), (20.0, 17.8))
    """
    if m.a == m.vertex or m.b == m.vertex:
        return ()
    v = view.p(m.vertex)
    u, w = _paper_dir(m.a - m.vertex), _paper_dir(m.b - m.vertex)
    s = RIGHT_ANGLE + grow
    return (v, _add(v, u, s), _add(_add(v, u, s), w, s), _add(v, w, s))


def draw_right_angle(m: RightAngleMark, style: Style, ctx: Context) -> Drawn:
    """The small square of a right angle."""
    sq = right_angle_square(m, ctx.view)
    return Drawn([Poly(sq[1:], pen(style))]) if sq else Drawn()


def _arrow(tip: XY, toward: XY, style: Style) -> Poly:
    u = _unit(toward[0] - tip[0], toward[1] - tip[1])
    n = (-u[1], u[0])
    back = _add(tip, u, 2.2)
    return Poly((tip, _add(back, n, 0.55), _add(back, n, -0.55)), Pen(style.stroke, 0.1), closed=True,
                fill=style.stroke)


def _reading_angle(u: XY) -> float:
    """The angle (degrees, clockwise as seen) of a text along paper direction ``u``, turned to read from
    left to right or from bottom to top."""
    ang = math.degrees(math.atan2(u[1], u[0]))
    if ang >= 90.0 - 1e-9:
        ang -= 180.0
    elif ang < -90.0 - 1e-9:
        ang += 180.0
    return ang


def draw_dimension(m: Dimension, style: Style, ctx: Context) -> Drawn:
    """A linear dimension: extension lines, the dimension line with arrowheads, and its text along it
    (placed later: centred on the side away from the measured points if free, else shifted or beside). A
    dimension of length 0 (its value prints as 0.00: 001-29's s at δ = 0) draws nothing: arrows on one point
    would sit on the part; the Results say s = 0."""
    if m.a == m.b or f"{abs(m.value):.2f}" == "0.00":
        return Drawn()
    d = (m.b - m.a).unit()
    shift = d.perp() * m.offset
    pa, pb = ctx.view.p(m.a), ctx.view.p(m.b)
    qa, qb = ctx.view.p(m.a + shift), ctx.view.p(m.b + shift)
    n = _paper_dir(d.perp() * (1.0 if m.offset >= 0 else -1.0))   # from the measured points to the line
    p = pen(style)
    out = Drawn()
    if ctx.view.length(abs(m.offset)) > 1.0:
        out.shapes += [Poly((_add(pa, n, 1.0), _add(qa, n, 1.5)), p), Poly((_add(pb, n, 1.0), _add(qb, n, 1.5)), p)]
    out.shapes += [Poly((qa, qb), p), _arrow(qa, qb, style), _arrow(qb, qa, style)]
    u = _unit(qb[0] - qa[0], qb[1] - qa[1])
    ang = _reading_angle(u)
    runs = rich_runs(m.text)
    w, h = text_width(runs, MARK_TEXT_SIZE) + 0.3, MARK_TEXT_SIZE * 0.8
    up = (math.sin(math.radians(ang)), -math.cos(math.radians(ang)))      # the text's "up", on paper
    outward = 1.0 if up[0] * n[0] + up[1] * n[1] >= 0 else -1.0
    cands = []
    for gap in (0.6, 1.8 + h):              # on the dimension line, else a line further out (labels there)
        for side in (outward, -outward):
            for t in (0.5, 0.3, 0.7, 0.15, 0.85):
                base = (qa[0] + (qb[0] - qa[0]) * t, qa[1] + (qb[1] - qa[1]) * t)
                cands.append(_add(base, up, side * (gap + h / 2)))
    for end, way in ((qb, 1.0), (qa, -1.0)):    # a short line: beyond an arrowhead, as a draftsman sets it
        for side in (outward, -outward):        # (001-24's s across the cam's profile: it had no other place)
            cands.append(_add(_add(end, u, way * (w / 2 + 1.0)), up, side * (0.6 + h / 2)))
    req = Request(((qa[0] + qb[0]) / 2, (qa[1] + qb[1]) / 2), w, h, 0.6, 0.0, spread=0.06,
                  candidates=tuple(cands), rotate=round(ang, 6))
    out.texts.append(TextRequest(runs, MARK_TEXT_SIZE, req, cls="mark-text"))
    return out


def draw_vector(v: Vector, style: Style, ctx: Context) -> Drawn:
    """A side of a velocity or acceleration polygon: the segment with an arrowhead at its end."""
    out = draw_segment(v, style, ctx)
    if out.shapes:
        out.shapes.append(_arrow(ctx.view.p(v.b), ctx.view.p(v.a), style))
    return out


def draw(value: Any, style: Style, ctx: Context, label: str | None = None) -> Drawn:
    """Draw any step value: dispatch on its type (tuples draw each member; numbers and None nothing)."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return Drawn()
    if isinstance(value, Point):
        return draw_point(value, style, ctx, label)
    if isinstance(value, (tuple, list)):
        out = Drawn()
        for v in value:
            out.extend(draw(v, style, ctx))
        return out
    fn = _TABLE.get(type(value))
    return fn(value, style, ctx) if fn else Drawn()


_TABLE = {Segment: draw_segment, Polyline: draw_polyline, Line: draw_line, Ray: draw_line, Circle: draw_circle, Arc: draw_arc,
          AngleMark: draw_angle, RightAngleMark: draw_right_angle, Dimension: draw_dimension,
          Ground: draw_ground, Slider: draw_slider, Guide: draw_guide, Bearing: draw_bearing, Vector: draw_vector, Rotation: draw_rotation}


def kind_of(value: Any) -> str:
    """``"point"``, ``"curve"``, a mark class name, or ``"none"`` (numbers, None): chooses the default style."""
    if isinstance(value, Point):
        return "point"
    if isinstance(value, (Segment, Line, Ray, Circle, Arc, Polyline)):
        return "curve"
    if isinstance(value, (tuple, list)):
        return kind_of(value[0]) if value else "none"
    if isinstance(value, (AngleMark, RightAngleMark, Dimension, Ground, Slider, Guide, Bearing, Rotation)):
        return type(value).__name__
    return "none"
