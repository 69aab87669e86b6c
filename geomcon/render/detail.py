"""A detail view of the mechanism at a larger standard scale, when the sheet's scale draws a link shorter than
:data:`MIN_LINK` (issue 11, review item A2), or two of its hinges closer than :data:`MIN_KNOT` (a knot: then, where
the whole mechanism finds no room at that scale, a window about the knot, :func:`knot_detail`).

The scale of sheet 1 is the largest that fits everything drawn, and a design by K draws the θ-circle through
C1 and C2 and its construction points P, P′ — at θ = 9.5° (001-10c) a circle ten times the mechanism's size, so
the drawing goes to 1:20 and its shortest link is 3.8 mm on paper. The construction keeps its scale (it
is what the student draws to find A), and the mechanism it finds — the links, their joints, grounds and
sliders — is drawn once more, alone, at the smallest standard scale that gives every link at least
:data:`MIN_LINK` on paper, in a free box of the sheet (:func:`geomcon.render.free_area.free_box`), framed and
captioned with its scale, as a textbook's 局部放大图.

Examples
--------
>>> from geomcon.paper import Scale
>>> str(detail_scale(2.3, Scale(1.0, 20.0))), str(detail_scale(3.8, Scale(1.0, 20.0)))
('1:2.5', '1:5')
>>> detail_scale(12.0, Scale(1.0, 1.0)) is None
True
"""
from __future__ import annotations

import math
from typing import Any, Callable, Sequence

from ..geometry.primitives import Arc, Circle, Line, Point, Polyline, Ray, Segment
from ..paper import STANDARD, Scale
from ..scene import Role, Scene, Step
from ..scene.marks import AngleMark, Dimension, Ground, Guide, Slider
from .figure import Figure, build_figure, content_box, shown_steps
from .labels import text_width
from .shapes import Disc
from .style import INFO_SIZE, PAPER, resolve_style
from .draw import ANGLE_RADIUS, SLIDER
from .view import FIG_MARGIN, Box, clip_interval, grow

MIN_LINK = 10.0
"""The shortest link a drawing should show on paper (mm): shorter, a joint's circle (Ø 2.4 mm), its label and
its neighbour's pile up."""
CAPTION_H = 6.0
"""Room above the detail's drawing for its caption (paper mm)."""


def _items(v: Any) -> list[Any]:
    return list(v) if isinstance(v, (tuple, list)) else [v]


def _is_link(step: Step) -> bool:
    """Whether ``step`` draws links of the mechanism: a segment in a link's style (the links layer, the dash-dot
    frame) that is part of the construction, not an annotation drawn like one — a velocity or acceleration
    polygon's vector (400-01 ``a_nb``: a length in mm/s of the polygon's scale, not of the mechanism) or the
    ordinate of an s–δ diagram at the asked angle (001-24 ``sd_ask_ord``: a follower's displacement)."""
    style = resolve_style(step.style, step.role, "curve")
    return (style.layer == "links" or style.name == "frame") and step.role != Role.ANNOTATION


def mechanism_steps(steps: Sequence[tuple[int, Step]], values: dict[str, Any]
                    ) -> tuple[set[str], set[str], list[float]]:
    """The keys of the steps that draw the mechanism — links (the links layer and the dash-dot frame), the points
    at their ends, grounds and sliders there —, those of the guides its sliders run on, and the model lengths of
    the links that end in a point drawn (a joint: two of them, their labels pile up on a short link). A flat face
    drawn about its follower's foot ends in no point (200-17's face, 7.7 mm at 1:2, asked for a window at 1:1
    that held only the stem and the face, resolving nothing): its length is no link's.

    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> steps, _ = shown_steps(sc, None)
    >>> keys, guides, lengths = mechanism_steps(steps, sc.evaluate([s.key for _, s in steps]))
    >>> {"A", "D", "A_ground"} <= keys, guides, round(min(lengths), 6)
    (True, set(), 50.0)
    """
    keys: set[str] = set()
    ends: list[Point] = []
    links: list[Segment] = []
    for _, s in steps:
        segs = [x for x in _items(values[s.key]) if isinstance(x, Segment) and x.a != x.b]
        if segs and _is_link(s):
            keys.add(s.key)
            ends += [p for x in segs for p in (x.a, x.b)]
            links += segs
    tol = 1e-6 * max((abs(c) for p in ends for c in (p.x, p.y)), default=1.0)
    drawn = [p for _, s in steps for p in _items(values[s.key]) if isinstance(p, Point)]
    lengths = [math.dist((x.a.x, x.a.y), (x.b.x, x.b.y)) for x in links         # a link that ends in a joint
               if any(abs(p.x - e.x) <= tol and abs(p.y - e.y) <= tol for e in (x.a, x.b) for p in drawn)]

    def at_end(p: Point) -> bool:
        return any(abs(p.x - e.x) <= tol and abs(p.y - e.y) <= tol for e in ends)

    blocks = []
    for _, s in steps:                    # an angle marked at a joint (θ at A, ψ at D) is read there, large
        for x in _items(values[s.key]):
            if (isinstance(x, Point) and at_end(x)) or (isinstance(x, (Ground, Slider)) and at_end(x.at)) \
                    or (isinstance(x, AngleMark) and at_end(x.vertex)):
                keys.add(s.key)
                if isinstance(x, Slider):
                    blocks.append(x.at)
    guides = set()
    for _, s in steps:                    # the hatched guide a kept slider runs on
        for x in _items(values[s.key]):
            if isinstance(x, Guide) and any(_on(p, x.a, x.b, tol) for p in blocks):
                guides.add(s.key)
    return keys, guides, lengths


def _on(p: Point, a: Point, b: Point, tol: float) -> bool:
    """Whether ``p`` lies on the segment ``ab`` (within ``tol``)."""
    dx, dy = b.x - a.x, b.y - a.y
    n2 = dx * dx + dy * dy
    if n2 == 0.0:
        return math.hypot(p.x - a.x, p.y - a.y) <= tol
    t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / n2
    return -1e-9 <= t <= 1 + 1e-9 and abs((p.x - a.x) * dy - (p.y - a.y) * dx) / math.sqrt(n2) <= tol


def detail_scale(shortest_paper: float, scale: Scale) -> Scale | None:
    """The smallest standard scale at which a link drawn ``shortest_paper`` mm long at ``scale`` is at least
    :data:`MIN_LINK`; None when it already is (or when no standard scale up to 50:1 makes it so)."""
    if shortest_paper >= MIN_LINK:
        return None
    need = scale.factor * MIN_LINK / shortest_paper
    return next((s for s in STANDARD if s.factor >= need * (1 - 1e-12)), None)


def detail_figure(scene: Scene, fig: Figure, scale: Scale, free: Callable[[float, float], tuple | None],
                  upto: int | None = None) -> tuple[Figure, Scale, Box] | None:
    """The detail view of ``fig``'s mechanism: its figure (drawn at the detail scale, placed in the box that
    ``free(w, h)`` finds for it), the scale and the box on paper (caption included); where the whole mechanism
    needs none or finds no room, the window about its knot (:func:`knot_detail`); None when every link is at
    least :data:`MIN_LINK` and every two hinges :data:`MIN_KNOT` apart on paper already, or when no free box
    holds the detail."""
    values = fig.values
    steps = [(n, s) for n, s in shown_steps(scene, upto)[0] if s.key in values]     # those the figure draws
    keys, guides, lengths = mechanism_steps(steps, values)
    if not keys:                                      # no link drawn
        return None
    big = detail_scale(min(lengths) / fig.view.mu, scale) if lengths else None
    found = knot(steps, values, keys, fig.view)
    apart = None if found is None else detail_scale(found[0] * MIN_LINK / MIN_KNOT, scale)
    if apart is not None and (big is None or apart.factor > big.factor):
        big = apart                                   # the knot's hinges MIN_KNOT apart too
    if big is not None:
        mu = big.real / big.paper
        crowd = crowding(steps, values, keys, fig.view.mu)
        own = content_box(scene, [(n, s) for n, s in steps if s.key in keys], values)   # the mechanism's extent:
        plain = grow(own, FIG_MARGIN * mu)
        near = {k for k in crowd if own[0] <= values[k].x <= own[2] and own[1] <= values[k].y <= own[3]}
        for box in dict.fromkeys((_dimensioned(steps, values, own, plain, mu), plain)):   # its dimensions, if room
            named = within(steps, values, own, _captioned(box, big, mu), mu)
            for drawn in ((keys | guides, keys) if guides else (keys,)):  # its sliders' guides cut to it, when they fit
                drawn = drawn | named | near
                got = _placed(scene, upto, box, mu, big, free, lambda s, drawn=drawn: s.key in drawn)
                if got is not None:
                    return got
    if found is not None and big is not None:
        return knot_detail(scene, fig, steps, found, scale, big, free, upto)
    return point_detail(scene, fig, steps, scale, free, upto)


def point_detail(scene: Scene, fig: Figure, steps: list[tuple[int, Step]], scale: Scale,
                 free: Callable[[float, float], tuple | None], upto: int | None = None, skip: Sequence[Box] = ()
                 ) -> tuple[Figure, Scale, Box] | None:
    """A window about a hinge and a point drawn closer than their markers (:func:`.coincident.tightest`: two
    distinct points, 001-10b's N 0.3 mm from B2's centre at 1:2), at the smallest standard scale that sets them
    apart and a label's height apart (a label each; where that finds no room, just apart), holding what lies
    within that distance of them on the sheet; None when there is none, or no room. ``skip``: model boxes of
    windows the sheet has already (:func:`next_point_detail`), whose points are read there."""
    from .coincident import LABEL_HEIGHT, tightest
    markers = [(fig.values[g.key], sh.c, sh.r, sh.fill == PAPER) for g in fig.groups if g.layer == "points"
               and isinstance(fig.values.get(g.key), Point) for sh in g.shapes[:1] if isinstance(sh, Disc)]
    markers = [m for m in markers if not any(b[0] <= m[0].x <= b[2] and b[1] <= m[0].y <= b[3] for b in skip)]
    found = tightest(markers)
    if found is None:
        return None
    d, need, ends = found
    scales = []
    for apart in (max(need, LABEL_HEIGHT), need):           # a label each where that finds room, else just apart
        big = next((s for s in STANDARD if s.factor >= scale.factor * apart / d * (1 - 1e-12)), None)
        if big is not None and big not in scales:
            scales.append(big)
    for margin in (FIG_MARGIN, TIGHT_MARGIN):              # a narrower margin where the usual one finds no room
        for big in scales:
            got = knot_detail(scene, fig, steps, (d, ends), scale, big, free, upto, reach=need * fig.view.mu,
                              margin=margin)
            if got is not None:
                return got
    return None


TIGHT_MARGIN = 6.0
"""Paper mm about a point window's content when :data:`~geomcon.render.view.FIG_MARGIN` finds it no room: a label
and a ground symbol still fit (000-05's A0 and 1′ at 1:1, 22 mm of room below the results for a window 26 mm
tall)."""


def next_point_detail(scene: Scene, fig: Figure, scale: Scale, free: Callable[[float, float], tuple | None],
                      shown: Sequence[Figure], upto: int | None = None) -> tuple[Figure, Scale, Box] | None:
    """One more window of the sheet: about the tightest hinge and dot (:func:`point_detail`) outside the windows
    ``shown`` already (their model boxes), where the knots lie far apart (000-04's B0 with C1…C3 and B1, read at
    2:1, and A0 with the division 1′ by it, 0.04 mm closer than their markers at 1:2.5, at the arm's other end);
    None when there is no other such knot, or no room."""
    steps = [(n, s) for n, s in shown_steps(scene, upto)[0] if s.key in fig.values]
    return point_detail(scene, fig, steps, scale, free, upto, skip=[d.view.box for d in shown])


def crowding(steps: Sequence[tuple[int, Step]], values: dict[str, Any], keys: set[str], mu: float) -> set[str]:
    """The keys of the construction points (a step drawing one point, not among ``keys``, not a grey candidate)
    drawn closer than :data:`MIN_KNOT` on the sheet (``mu`` model mm per paper mm) to a joint of the mechanism (a
    hinge among ``keys``). :func:`detail_figure` draws those within the mechanism's extent in its detail view too,
    so that it shows apart what crowds a joint on the sheet (001-06b's and 004-02's E, 1.35 mm from B2 at 1:5,
    was left out of the mechanism's detail at 1:2.5).

    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> steps, _ = shown_steps(sc, None)
    >>> values = sc.evaluate([s.key for _, s in steps])
    >>> keys, _, _ = mechanism_steps(steps, values)
    >>> crowding(steps, values, keys, 1.0), crowding(steps, values, keys - {"B"}, 1.0) <= {"B"}
    (set(), True)
    """
    joints = [(p.x, p.y) for _, s in steps if s.key in keys and _pin(s) for p in _items(values[s.key])
              if isinstance(p, Point)]
    reach = MIN_KNOT * mu
    return {s.key for _, s in steps if s.key not in keys and isinstance(values[s.key], Point) and not _grey(s)
            and any(1e-9 * reach < math.dist((values[s.key].x, values[s.key].y), j) < reach for j in joints)}


def within(steps: Sequence[tuple[int, Step]], values: dict[str, Any], own: Box, box: Box, mu: float) -> set[str]:
    """The keys of the named points (a label: a grey candidate's too) lying in model box ``own`` (the mechanism's
    extent), and of the angle marks and dimensions lying wholly in model ``box`` (the window) drawn at ``mu`` model
    mm a paper mm (an angle mark as far as its arc reaches, a dimension as far as its value beyond its line): the
    mechanism's detail view draws them, as a window shows what lies in it (001-06b's and 004-02's M, C4, αmax and
    004-02's H lay in the window at 1:2.5 and were left out, the main view's knot they are part of left untied).
    A point in the window's margin is left out, as the lines it lies on are (001-16's P and candidates A2, A4
    would float by the frame, alone).

    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> steps, _ = shown_steps(sc, None)
    >>> values = sc.evaluate([s.key for _, s in steps])
    >>> box = (-1.0, -1.0, 1.0, 1.0)
    >>> sorted(within(steps, values, box, box, 0.5 / ANGLE_RADIUS)), sorted(within(steps, values, box, box, 0.2))
    (['A', 'mark_theta'], ['A'])
    >>> sorted(within(steps, values, (-1.0, -1.0, -0.5, -0.5), box, 0.5 / ANGLE_RADIUS))
    ['mark_theta']
    >>> {"B1", "mark_psi"} <= within(steps, values, (-1e3, -1e3, 1e3, 1e3), (-1e3, -1e3, 1e3, 1e3), 1.0)
    True
    """
    out = set()
    for _, s in steps:
        xs = _items(values[s.key])
        if all(isinstance(x, Point) for x in xs) and not s.label:
            continue
        if not all(isinstance(x, (Point, AngleMark, Dimension)) for x in xs):
            continue
        if all(isinstance(x, Point) for x in xs):
            if all(own[0] <= p.x <= own[2] and own[1] <= p.y <= own[3] for p in xs):
                out.add(s.key)
            continue
        pts = [p for x in xs for p in _anchors(x, ANGLE_RADIUS * mu)]
        for d in (x for x in xs if isinstance(x, Dimension) and x.a != x.b):    # its line and value
            out_ = (d.b - d.a).unit().perp() * (d.offset + math.copysign(DIM_TEXT * mu, d.offset))
            pts += [d.a + out_, d.b + out_]
        if pts and all(box[0] <= p.x <= box[2] and box[1] <= p.y <= box[3] for p in pts):
            out.add(s.key)
    return out


def _dimensioned(steps: Sequence[tuple[int, Step]], values: dict[str, Any], own: Box, box: Box, mu: float) -> Box:
    """Model ``box`` grown to hold, with a 4 mm margin (room for a mark's value below it), the line and value of
    each dimension whose ends lie in the mechanism's extent ``own`` and which ``box`` does not hold yet (001-06b's
    stroke H = C1C2, its value 10 mm below the guide at 1:2.5)."""
    x0, y0, x1, y1 = box
    for _, s in steps:
        for d in _items(values[s.key]):
            if isinstance(d, Dimension) and d.a != d.b and all(
                    own[0] <= p.x <= own[2] and own[1] <= p.y <= own[3] for p in (d.a, d.b)):
                n = (d.b - d.a).unit().perp()
                if all(box[0] <= p.x <= box[2] and box[1] <= p.y <= box[3]
                       for p in (d.a + n * (d.offset + math.copysign(DIM_TEXT * mu, d.offset)),
                                 d.b + n * (d.offset + math.copysign(DIM_TEXT * mu, d.offset)))):
                    continue                                  # it fits already
                out = n * (d.offset + math.copysign((DIM_TEXT + 4.0) * mu, d.offset))
                for p in (d.a + out, d.b + out):
                    x0, y0, x1, y1 = min(x0, p.x), min(y0, p.y), max(x1, p.x), max(y1, p.y)
    return (x0, y0, x1, y1)


DIM_TEXT = 5.0
"""Paper mm a dimension's value takes beyond its line."""


def _placed(scene: Scene, upto: int | None, box: Box, mu: float, big: Scale,
            free: Callable[[float, float], tuple | None], keep: Callable[[Step], bool]
            ) -> tuple[Figure, Scale, Box] | None:
    """The detail figure of model ``box`` at ``mu`` in the free box ``free`` finds for it (caption above), or None.
    The box is widened about its middle to its caption's width (:func:`_captioned`)."""
    box = _captioned(box, big, mu)
    w, h = (box[2] - box[0]) / mu, (box[3] - box[1]) / mu
    spot = free(w, h + CAPTION_H)
    if spot is None:
        return None
    x, y = spot[0], spot[1]
    detail = build_figure(scene, upto, box, (x, y + CAPTION_H), mu=mu, keep=keep)
    return detail, big, (x, y, x + w, y + h + CAPTION_H)


def _captioned(box: Box, big: Scale, mu: float) -> Box:
    """Model ``box`` widened about its middle, where narrower, to hold the window's caption (its text in both
    languages at ``big``, 1.5 mm in from the frame each side): 200-17's window, 35 mm wide, cut its caption
    between "1:1" and "μl".

    >>> _captioned((0.0, 0.0, 10.0, 5.0), Scale(1.0, 1.0), 1.0)[0] < -20.0, _captioned((0.0, 0.0, 90.0, 5.0), Scale(1.0, 1.0), 1.0)
    (True, (0.0, 0.0, 90.0, 5.0))
    """
    x0, y0, x1, y1 = box
    wide = (text_width(f"Detail 局部放大  {big}   μl = {mu:g} mm/mm", INFO_SIZE) + 3.0) * mu
    if x1 - x0 < wide:
        x0, x1 = (x0 + x1 - wide) / 2, (x0 + x1 + wide) / 2
    return (x0, y0, x1, y1)


MIN_KNOT = 6.0
"""Paper mm two joints of the mechanism should lie apart: closer, their pins (Ø 2.5 mm), the grounds and blocks at
them and their labels make a knot a reader cannot untie (001-19's A and D′ 5.4 mm apart at 1:5, A's ground drawn
shrunk between them; 001-12's A, B1 and B2 3 mm apart at 1:20)."""

KNOT_REACH = 2.0
"""The window of a knot's detail holds the points within this many :data:`MIN_KNOT` (on the sheet) of its two
joints (001-19: C, 10 mm below A, with A and D′)."""


def knot(steps: Sequence[tuple[int, Step]], values: dict[str, Any], keys: set[str], view: Any
         ) -> tuple[float, tuple[Point, Point]] | None:
    """The two joints of the mechanism (points among the steps ``keys`` drawn as a hinge's hollow circle: not a
    dot, not a grey candidate) drawn closest but apart on paper, as their distance on paper and the two points;
    None when every two are :data:`MIN_KNOT` apart or more (000-04's A0 beside its arm's pitch points, drawn as
    dots, is no knot of hinges). A hinge less than :data:`BLOCK_KNOT` off another's slider block is a knot too,
    its distance given as the one that asks for the scale setting it :data:`BLOCK_KNOT` off (the block keeps its
    size on paper): 004-02 (K = 1.5)'s A* and C1.

    >>> from geomcon.recipes.crank_rocker import construct
    >>> from geomcon.render.view import View
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> steps, _ = shown_steps(sc, None)
    >>> values = sc.evaluate([s.key for _, s in steps])
    >>> keys, _, _ = mechanism_steps(steps, values)
    >>> knot(steps, values, keys, View((-100, -100, 100, 100), 1.0, (0, 0))) is None
    True
    >>> d, at = knot(steps, values, keys, View((-100, -100, 100, 100), 20.0, (0, 0)))
    >>> d < MIN_KNOT
    True
    """
    pts = sorted({(p.x, p.y) for _, s in steps if s.key in keys and _pin(s) for p in _items(values[s.key])
                  if isinstance(p, Point)})
    best = None
    for i, a in enumerate(pts):
        for b in pts[i + 1:]:
            d = math.dist(a, b) / view.mu
            if 1e-3 < d < MIN_KNOT and (best is None or d < best[0]):
                best = (d, (Point(*a), Point(*b)))
    for blk in (x for _, s in steps if s.key in keys for x in _items(values[s.key]) if isinstance(x, Slider)):
        for a in pts:                                   # a hinge by another's slider block
            d = math.dist(a, (blk.at.x, blk.at.y)) / view.mu
            gap = _off_block(Point(*a), blk, view.mu)
            if d > 1e-3 and gap < BLOCK_KNOT:
                eq = MIN_KNOT * d / (BLOCK_KNOT + d - gap)          # the scale that sets it BLOCK_KNOT off
                if best is None or eq < best[0]:
                    best = (eq, (Point(*a), blk.at))
    return best


BLOCK_KNOT = 2.5
"""Paper mm a hinge should lie off another hinge's slider block (8 × 5 mm at any scale): nearer, its pin, the block
and their labels knot (004-02's A* 2 mm off C1's block at 1:2, the θ and αmax arcs there cut by the block)."""


def _off_block(p: Point, blk: Slider, mu: float) -> float:
    """Paper mm from ``p`` to the slider block ``blk`` drawn at full size (:data:`~.draw.SLIDER`), ``mu`` model mm
    a paper mm.

    >>> round(_off_block(Point(10.0, 0.0), Slider(Point(0, 0), Point(1, 0)), 1.0), 6)
    6.0
    """
    n = math.hypot(blk.direction.x, blk.direction.y)
    ux, uy = blk.direction.x / n, blk.direction.y / n
    dx, dy = (p.x - blk.at.x) / mu, (p.y - blk.at.y) / mu
    along, across = abs(dx * ux + dy * uy) - SLIDER[0] / 2, abs(-dx * uy + dy * ux) - SLIDER[1] / 2
    return math.hypot(max(along, 0.0), max(across, 0.0))


def knot_detail(scene: Scene, fig: Figure, steps: list[tuple[int, Step]], found: tuple[float, tuple[Point, Point]],
                scale: Scale, big: Scale, free: Callable[[float, float], tuple | None], upto: int | None = None,
                reach: float | None = None, margin: float = FIG_MARGIN) -> tuple[Figure, Scale, Box] | None:
    """A window about the knot of the mechanism (:func:`knot`), drawn at the smallest standard scale that sets its
    joints :data:`MIN_KNOT` apart (and its links :data:`MIN_LINK` long, ``big``, when that is larger), with every
    point, line, ground, slider and angle mark there — the textbook's 局部放大图 of a crowded spot, where the
    mechanism as a whole finds no room at that scale (``found``: :func:`knot`'s answer; ``big``: the scale, which
    :func:`detail_figure` chose for both; ``margin``: paper mm about what it holds). None when no free box holds
    it."""
    values = fig.values
    _, ends = found
    reach = KNOT_REACH * MIN_KNOT * fig.view.mu if reach is None else reach      # model mm about the two
    near = [p for _, s in steps for p in _items(values[s.key])
            if isinstance(p, Point) and min(math.dist((p.x, p.y), (q.x, q.y)) for q in ends) <= reach]
    xs, ys = [p.x for p in near], [p.y for p in near]
    mu = big.real / big.paper
    x0, y0, x1, y1 = grow((min(xs), min(ys), max(xs), max(ys)), margin * mu)
    box = _captioned((x0, y0, x1, y1), big, mu)

    def inside(v: Any) -> bool:
        pts = [p for x in _items(v) for p in _anchors(x, ANGLE_RADIUS * mu)]
        return bool(pts) and all(box[0] <= p.x <= box[2] and box[1] <= p.y <= box[3] for p in pts)

    def keep(s: Step) -> bool:
        v = values.get(s.key)
        if v is None:
            return False
        xs = _items(v)
        if all(isinstance(x, _CLIPPED) for x in xs):
            return any(_meets(x, box) for x in xs)
        if all(isinstance(x, Guide) for x in xs):          # the guide a block runs on, cut to the window
            return any(_meets(Segment(x.a, x.b), box) for x in xs)
        return inside(v)

    return _placed(scene, upto, box, mu, big, free, keep)


def _grey(step: Step) -> bool:
    """Whether ``step`` draws a grey candidate (001-16's A2, A4: a choice not taken, no point of the answer)."""
    return resolve_style(step.style, step.role, "point").name == "candidate"


def _pin(step: Step) -> bool:
    """Whether ``step`` draws its point as a hinge: a hollow circle in ink (a candidate's is grey)."""
    style = resolve_style(step.style, step.role, "point")
    return style.marker == "hollow" and style.name != "candidate"


_CLIPPED = (Segment, Line, Ray, Circle, Arc, Polyline)
"""What a detail's view clips to its box (a link, a construction line, a compass arc, a sampled curve: 200-16's
cam profile, on which B1* and B(75°) lie): drawn whatever its ends."""


def _meets(x: Any, box: Box) -> bool:
    """Whether a line, segment, ray, circle or arc ``x`` (model) passes through ``box`` (an arc as its circle): the
    window draws only those (the others, clipped away, would cost a figure's placement for nothing).

    >>> box = (0.0, 0.0, 10.0, 10.0)
    >>> _meets(Segment(Point(-5, 5), Point(-1, 5)), box), _meets(Line(Point(-5, 5), Point(1, 0)), box)
    (False, True)
    >>> _meets(Circle(Point(5, 5), 20.0), box), _meets(Circle(Point(5, 5), 6.0), box)
    (False, True)
    """
    if isinstance(x, Polyline):
        import shapely
        pts = [(p.x, p.y) for p in x.points + (x.points[:1] if x.closed else ())]
        return bool(shapely.intersects(shapely.LineString(pts), shapely.box(*box)))
    if isinstance(x, (Circle, Arc)):
        cx, cy = x.center.x, x.center.y
        near = math.hypot(cx - min(max(cx, box[0]), box[2]), cy - min(max(cy, box[1]), box[3]))
        far = max(math.hypot(cx - px, cy - py) for px in (box[0], box[2]) for py in (box[1], box[3]))
        return near <= x.r <= far
    if isinstance(x, Segment):
        p, d, lo, hi = x.a, x.b - x.a, 0.0, 1.0
    elif isinstance(x, Ray):
        p, d, lo, hi = x.origin, x.direction, 0.0, math.inf
    else:
        p, d, lo, hi = x.point, x.direction, -math.inf, math.inf
    if d.x == 0.0 and d.y == 0.0:
        return box[0] <= p.x <= box[2] and box[1] <= p.y <= box[3]
    return clip_interval((p.x, p.y), (d.x, d.y), box, lo, hi) is not None


def _anchors(x: Any, arc: float = 0.0) -> list[Point]:
    """Where a drawn value stands: a point, a symbol's or mark's point, a dimension's or guide's ends; [] for a
    value the window does not draw (a number, a curve of many points). An angle mark stands as far as its arc
    reaches: its radius, or ``arc`` (model mm: the paper radius it is drawn at) when it has none (100-03's γmin
    at C′ hung its arc below a window with a narrow margin)."""
    if isinstance(x, Point):
        return [x]
    if isinstance(x, (Ground, Slider)):
        return [x.at]
    if isinstance(x, AngleMark):                  # an arc of a given radius (000-04's ψ0 about A0) kept whole
        r = x.radius or arc
        return [x.vertex + Point(dx * r, dy * r) for dx, dy in ((0, 0), (-1, -1), (1, 1))]
    if isinstance(x, (Guide, Dimension)):
        return [x.a, x.b]
    return []


__all__ = ["BLOCK_KNOT", "CAPTION_H", "KNOT_REACH", "MIN_KNOT", "MIN_LINK", "crowding", "detail_figure", "detail_scale", "knot",
           "knot_detail", "mechanism_steps", "next_point_detail", "point_detail", "within"]
