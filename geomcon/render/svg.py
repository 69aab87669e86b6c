"""The printed sheets of a scene: sheet 1 the drawing at a standard scale (ISO 5455, :mod:`geomcon.paper`)
with its scale bar, results, warnings and title block; the numbered construction protocol on the sheets that
follow (:mod:`geomcon.render.page`).

Every numbered step is one SVG group ``<g id="step-<key>" class="step role-… style-…" data-step="n">`` (n is
the protocol number; steps drawn together share it), so a replay is pure CSS: ``.future`` hides a group,
``.current`` highlights it. Frame k (``upto=k``) evaluates only steps 1…k and what they depend on, draws
them, and highlights frame k. A sheet is in mm (one user unit = 1 mm of paper; printed at 100 % a length of
the drawing is its real length × the scale). Output is deterministic:
fixed rounding, ids from step keys, no clock.

Examples
--------
>>> from geomcon.recipes.crank_rocker import construct
>>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
>>> svg = render_svg(sc, upto=3)
>>> sc.is_evaluated("theta")
False
>>> max(int(n) for n in re.findall(r'<g class="step[^"]*" data-step="(\\d+)"', svg))
3
>>> render_svg(sc) == render_svg(sc)
True
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Callable, Sequence

import svgwrite

from ..paper import STANDARD, Scale, Sheet, choose_scale
from ..scene import Scene
from .figure import Figure, Sketch, build_figure, content_box, shown_steps, sketch_figure, text_room
from .page import (INSET, TB_H, PageSpec, TitleBlock, centred, document, frame_box, text, title_block,
                   title_block_box)
from .serial import Element, svg_string
from .protocol import BLOCK_GAP, info_height, paginate, render_info, render_protocol
from .labels import rich_runs, text_width
from .shapes import add_runs, to_svg
from .style import CSS, HIGHLIGHT, INFO_SIZE, INK
from .view import FIG_MARGIN, Box, View, fmt, grow, nice_values

SCALE_H = 12.0      # scale bar band under the figure
CAP_H = 9.0         # the current step's caption above the drawing (two lines; shown in frames and the player)
CAP_MIN_W = 60.0    # ... or left of the title block, when this much room is there
SIDE_MIN = 90.0     # the results go beside the title block when this much room is left of it, else above
RIGHT_W = 95.0      # width of the results column at the right of the drawing
INFO_SHARE = 0.4    # results taller than this share of the frame go onto a sheet of their own


def model_extent(scene: Scene, upto: int | None = None, page: PageSpec = PageSpec()) -> Box:
    """The view box (model mm: xmin, ymin, xmax, ymax) that :func:`render_svg` fits to frames 1…upto.

    Passing it as ``viewbox`` to every frame gives a replay with one fixed view and page size.
    """
    steps, _ = shown_steps(scene, upto)
    values = scene.evaluate([s.key for _, s in steps])
    content = content_box(scene, steps, values)
    return grow(content, FIG_MARGIN * _mu(_best_layout(page, (), (), content, FIG_MARGIN)[1]))


def step_id(key: str) -> str:
    """The SVG id of a step's group (``step-<key>``, whitespace replaced by ``_``)."""
    return "step-" + "_".join(key.split())


@dataclass(frozen=True)
class SheetLayout:
    """Where things go on sheet 1: the drawing ``area``, the results' corner, width and height, whether they
    are on sheet 1 at all (too many go onto a sheet of their own), and the box of the current step's caption."""

    area: Box
    info_at: tuple[float, float]
    info_w: float
    info_h: float
    info_here: bool
    caption: Box
    pieces: tuple[Piece, ...] = ()
    """The results and warnings in several free boxes of the drawing's area (when no one box holds them)."""


@dataclass(frozen=True)
class Piece:
    """A part of the results block set in a free box of its own: its corner (as ``render_info`` takes it), width
    and height, the result rows it holds (indices into the results, in their frames' order), whether it holds
    the warnings. When the results are split, their headings are numbered (1/2, 2/2): the pieces lie where the
    room is, not in reading order."""

    x: float
    y: float
    w: float
    h: float
    rows: tuple[int, ...]
    warnings: bool


def _layouts(page: PageSpec, info: Sequence[str], warnings: Sequence[str]) -> list[SheetLayout]:
    """The ways to share sheet 1 between drawing and results: results above the title block (beside it when
    there is room), in a column at the right, or on a sheet of their own (the last resort: chosen only when it
    draws at a larger scale, or when the results fit nowhere on sheet 1). The current step's caption goes left
    of the title block when that corner is free and wide enough, else in a band above the drawing."""
    sheet = page.sheet
    fx0, fy0, fx1, fy1 = frame_box(sheet)
    tb = title_block_box(sheet)
    corner = tb[0] - fx0 - 2 * INSET >= CAP_MIN_W

    def area(right: float, bottom: float, corner_free: bool) -> tuple[Box, Box]:
        if corner_free and corner:
            return (fx0 + INSET, fy0 + INSET, right, bottom), (fx0 + INSET, tb[1] + 1.0, tb[0] - INSET, fy1 - 1.0)
        return (fx0 + INSET, fy0 + INSET + CAP_H, right, bottom), (fx0 + INSET, fy0 + INSET - 1.0, fx1 - INSET,
                                                                  fy0 + INSET + CAP_H - 1.0)

    if not (info or warnings):
        return [SheetLayout(*area(fx1 - INSET, tb[1] - SCALE_H, True)[:1], (fx0, fy0), 0.0, 0.0, True,
                            area(fx1 - INSET, tb[1] - SCALE_H, True)[1])]
    side = tb[0] - fx0 - 2 * INSET
    beside = side >= SIDE_MIN
    w = side if beside else fx1 - fx0 - 2 * INSET
    h = info_height(info, w, warnings)
    out = []
    if h <= INFO_SHARE * (fy1 - fy0):
        band = max(TB_H, h + INSET) if beside else TB_H + h + INSET
        at = (fx0 + INSET, fy1 - band) if beside else (fx0 + INSET, fy1 - TB_H - h - INSET)
        box, cap = area(fx1 - INSET, fy1 - band - SCALE_H, not beside)
        out.append(SheetLayout(box, at, w, h, True, cap))
    rh = info_height(info, RIGHT_W, warnings)
    if rh <= tb[1] - fy0 - 2 * INSET - CAP_H:
        x = fx1 - INSET - RIGHT_W
        box, cap = area(x - INSET, tb[1] - SCALE_H, True)
        out.append(SheetLayout(box, (x, box[1] - 4.0), RIGHT_W, rh, True, cap))
    full = fx1 - fx0 - 2 * INSET
    box, cap = area(fx1 - INSET, tb[1] - SCALE_H, True)
    out.append(SheetLayout(box, (fx0 + INSET, fy0 + INSET), full, info_height(info, full, warnings), False, cap))
    return out


def _best_layout(page: PageSpec, info: Sequence[str], warnings: Sequence[str], content: Box,
                 margin: float) -> tuple[SheetLayout, Scale]:
    """The layout of :func:`_layouts` that draws ``content`` at the largest standard scale (the first on a tie)."""
    best: tuple[SheetLayout, Scale] | None = None
    for sl in _layouts(page, info, warnings):
        scale = figure_scale(content, sl.area, margin)
        if best is None or scale > best[1]:
            best = (sl, scale)
    assert best is not None
    return best


def figure_scale(content: Box, area: Box, margin: float = FIG_MARGIN) -> Scale:
    """The largest standard scale (:data:`geomcon.paper.STANDARD`) at which the model box ``content``, with
    ``margin`` paper mm around it, fits the paper box ``area``; the smallest scale when nothing fits.

    >>> str(figure_scale((0.0, 0.0, 400.0, 100.0), (0.0, 0.0, 259.0, 130.0)))
    '1:2'
    """
    try:
        return choose_scale((content[2] - content[0], content[3] - content[1]),
                            (area[2] - area[0], area[3] - area[1]), margin=margin)
    except ValueError:
        return STANDARD[0]


def _mu(scale: Scale) -> float:
    """μl of a scale: model mm per paper mm."""
    return scale.real / scale.paper


def place_figure(scene: Scene, page: PageSpec = PageSpec(), info: Sequence[str] = (), warnings: Sequence[str] = (),
                 upto: int | None = None, viewbox: Box | None = None, keep: Callable[[Any], bool] | None = None
                 ) -> tuple[SheetLayout, Scale, View]:
    """Where sheet 1 puts the drawing: the layout, the standard scale, and the view (model box, μl, top-left
    corner on paper) — the drawing centred in the layout's area.

    >>> from geomcon.recipes.crank_rocker import construct
    >>> sl, scale, view = place_figure(construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene)
    >>> str(scale), view.mu
    ('1:1', 1.0)
    """
    steps, _ = shown_steps(scene, upto if keep is None else None, keep)
    content = viewbox or content_box(scene, steps, scene.evaluate([s.key for _, s in steps]))
    sl, scale = _best_layout(page, info, warnings, content, 0.0 if viewbox else FIG_MARGIN)
    mu = _mu(scale)
    box = viewbox or grow(content, FIG_MARGIN * mu)
    return sl, scale, View(box, mu, centred(((box[2] - box[0]) / mu, (box[3] - box[1]) / mu), sl.area))


def _keepouts(fig: Figure | Sketch, sl: SheetLayout, page: PageSpec, scale: Scale) -> list[Box]:
    """What a box set into the drawing's free room must not meet besides the figure: the title block, the scale
    bar and the step captions' box."""
    tb = title_block_box(page.sheet)
    x, y = fig.view.origin[0], fig.view.origin[1] + fig.view.size[1] + 6.0          # as :func:`_scale_bar`
    bar = (x - 2.0, y - 2.0, x + _bar_length(fig.view.mu) + 12.0
           + text_width(f"{scale}   μl = {fig.view.mu:g} mm/mm", INFO_SIZE), y + 5.5)
    return [(tb[0] - INSET, tb[1] - INSET, tb[2], tb[3]), bar, sl.caption]


def mechanism_detail(scene: Scene, fig: Figure, sl: SheetLayout, page: PageSpec, info: Sequence[str],
                     warnings: Sequence[str], scale: Scale, upto: int | None = None,
                     asked: list[tuple[float, float]] | None = None,
                     accept: Callable[[tuple[float, float, float, float]], bool] | None = None,
                     shown: Sequence[tuple[Figure, Scale, Box]] = ()) -> tuple[Figure, Scale, Box] | None:
    """The detail view of the mechanism (:func:`geomcon.render.detail.detail_figure`) in a free box of sheet 1
    clear of the figure, the results and warnings, the title block, scale bar and captions; None when every
    link is long enough on paper or no free box holds it (``asked`` collects the sizes of the boxes looked for:
    none when every link is long enough). ``accept``: whether a free box ``(x, y, w, h)`` will do (the results
    still find room beside it, :func:`_detail_first`); up to :data:`PLACES` free boxes, each clear of the
    ones refused, are offered to it before a window's size is given up (and the next window, at another scale,
    is tried). ``shown``: the windows the sheet has already; then the next one, about a knot outside them
    (:func:`geomcon.render.detail.next_point_detail`), clear of them too."""
    from .detail import detail_figure, next_point_detail
    from .free_area import FreeRoom
    fx0, fy0, fx1, fy1 = frame_box(page.sheet)
    keep = _keepouts(fig, sl, page, scale)
    if sl.info_here and (info or warnings):
        x, y = sl.info_at
        keep.append((x - INSET, y, x + sl.info_w + INSET, y + sl.info_h + INSET))
        keep += [(pc.x - INSET, pc.y, pc.x + pc.w + INSET, pc.y + pc.h + INSET) for pc in sl.pieces]
    keep += [(b[0] - INSET, b[1] - INSET, b[2] + INSET, b[3] + INSET) for _, _, b in shown]
    shapes = [s for g in fig.groups for s in g.shapes]
    region = (fx0 + INSET, fy0 + INSET, fx1 - INSET, fy1 - INSET)
    rooms: list[Any] = []                       # rasterised once, at the first size asked

    def free(w: float, h: float) -> tuple[float, float, float, float] | None:
        if asked is not None:
            asked.append((w, h))
        if not rooms:
            rooms.append(FreeRoom(shapes, region, keep))
        room = rooms[0]
        for _ in range(PLACES if accept is not None else 1):
            spot = room.find([(w, h)])
            if spot is None or accept is None or accept(spot):
                return spot
            room = room.without((spot[0], spot[1], spot[0] + spot[2], spot[1] + spot[3]))
        return None

    if shown:
        return next_point_detail(scene, fig, scale, free, [d[0] for d in shown], upto)
    return detail_figure(scene, fig, scale, free, upto)


WINDOWS = 3
"""At most this many detail windows on a sheet (a textbook's 局部放大图 are one or two)."""


def more_details(scene: Scene, fig: Figure, sl: SheetLayout, page: PageSpec, info: Sequence[str],
                 warnings: Sequence[str], scale: Scale, upto: int | None, first: tuple[Figure, Scale, Box]
                 ) -> list[tuple[Figure, Scale, Box]]:
    """The sheet's detail windows: ``first`` and, up to :data:`WINDOWS`, one more about each knot of a hinge and a
    point lying outside those (:func:`geomcon.render.detail.next_point_detail`) that finds a free box clear of
    them (000-04, 000-05, 000-08: B0's knot and A0's, at the arm's two ends)."""
    out = [first]
    while len(out) < WINDOWS:
        nxt = mechanism_detail(scene, fig, sl, page, info, warnings, scale, upto, shown=out)
        if nxt is None:
            break
        out.append(nxt)
    return out


PLACES = 6
"""The free boxes a detail window's size is offered in (each clear of those refused, nearest a corner first)
before it is given up: 100-03's window at 5:1 took the top right corner, where the results then found no room."""


def _detail_first(scene: Scene, fig: Figure, sl: SheetLayout, page: PageSpec,
                  blocks: Sequence[tuple[Sequence[str], Sequence[str]]], scale: Scale,
                  steps: Sequence[int] | None, upto: int | None
                  ) -> tuple[SheetLayout, tuple[Figure, Scale, Box], Sequence[str], Sequence[str]] | None:
    """The detail view placed before the results, when placed after them it finds no room: its box, then the
    results and warnings (the first of ``blocks``, full or brief, that fits) in the drawing's free room left
    (001-16's solution 4: a 77.9 × 100.6 mm detail view at 1:5 did not fit under the results' column). Every
    window the detail offers (its scales, :func:`geomcon.render.detail.point_detail`) is tried in every free box
    of its size (:data:`PLACES`) until the results find room beside it (100-03: C2 and C′ at 5:1 in the top right
    corner left none; at 2.5:1 elsewhere they do). None when none does: the detail, the layout, the results'
    lines."""
    bare = replace(sl, info_here=False, pieces=())
    base = _free_room(fig, bare, page, scale)
    sizes = [_info_sizes(info, warnings) for info, warnings in blocks]

    def leaves_room(spot: tuple[float, float, float, float]) -> bool:   # the results fit beside the window
        x, y, w, h = spot
        room = base.without((x - INSET, y - INSET, x + w + INSET, y + h + INSET))
        return any(room.find(one) is not None for one in sizes) or any(      # one box each first: quicker
            results_in_free_room(fig, bare, page, info, warnings, scale, steps, room=room) is not None
            for info, warnings in blocks)

    det = mechanism_detail(scene, fig, bare, page, (), (), scale, upto, accept=leaves_room)
    if det is None:
        return None
    x0, y0, x1, y1 = det[2]
    taken = [(x0 - INSET, y0 - INSET, x1 + INSET, y1 + INSET)]
    for info, warnings in blocks:
        placed = results_in_free_room(fig, bare, page, info, warnings, scale, steps, taken)
        if placed is not None:
            return placed, det, info, warnings
    return None


def _detail_group(dwg: svgwrite.Drawing, fig: Figure, scale: Scale, box: Box, lang: str, name: str = "detail"
                  ) -> Any:
    """The detail view: a thin frame, its caption with the scale, and the mechanism's steps (ids ``detail-…``;
    a second window's ``detail-2-…``: ``name``). The caption's baseline lies 4 mm below the frame's top: its
    letters 1.5 mm in from the frame, as from its left side, and 1.5 mm clear above the drawing's texts, which may
    reach :data:`~geomcon.render.detail.CAPTION_H` below the frame's top (200-13's αmax value touched a caption
    set 0.5 mm lower)."""
    from .protocol import _line
    g = dwg.g(id=name)
    first = str(min(sd.number for sd in fig.groups))      # frame and caption show from the detail's first step
    rect = dwg.rect(insert=(fmt(box[0]), fmt(box[1])), size=(fmt(box[2] - box[0]), fmt(box[3] - box[1])),
                    fill="none", stroke=INK, stroke_width="0.25", id=f"{name}-frame")
    head = _line(dwg, f"{text('Detail', '局部放大', lang)}  {scale}   μl = {fig.view.mu:g} mm/mm", box[0] + 1.5,
                 box[1] + 4.0, INFO_SIZE, INK, "detail-head")
    for el in (rect, head):
        el.attribs["data-step"] = first
        g.add(el)
    g.add(_figure_group(dwg, fig, f"{name}-"))
    return g


def results_in_free_room(fig: Figure, sl: SheetLayout, page: PageSpec, info: Sequence[str],
                         warnings: Sequence[str], scale: Scale, steps: Sequence[int] | None = None,
                         avoid: Sequence[Box] = (), room: Any = None) -> SheetLayout | None:
    """``sl`` with the results and warnings on sheet 1, in a box of the frame that meets no drawn element of
    ``fig``, the title block, the scale bar or the step captions (:class:`geomcon.render.free_area.FreeRoom`);
    None when there is no such box. The drawing keeps its scale: 001-13 is drawn at 1:5 with its results in
    the free top-left corner, where reserving a column for them would draw it at 1:10. When no one box holds
    them, they are set in up to :data:`MAX_PIECES` boxes (:func:`_pieces`): the results, then the warnings
    (000-04), or the results continued in a second box (``steps``: the frame of each result, which orders them).
    ``avoid``: boxes placed before them (a detail view); ``room``: the free room of ``fig`` with them, when built
    already (:func:`_free_room`)."""
    room = room if room is not None else _free_room(fig, sl, page, scale, avoid)
    spot = room.find(_info_sizes(info, warnings))
    if spot is not None:
        x, y, w, h = spot
        return replace(sl, info_at=(x, y - 4.0), info_w=w, info_h=h + 4.0, info_here=True)
    pieces = _pieces(room, info, warnings, steps)
    if pieces is not None and sum(bool(pc.rows) for pc in pieces) > 1:       # the results split: outside the figure
        pieces = _pieces(outside_hull(room, fig), info, warnings, steps)
    if pieces is None:
        return None
    first = pieces[0]
    return replace(sl, info_at=(first.x, first.y), info_w=first.w, info_h=first.h, info_here=True,
                   pieces=tuple(pieces))


def _free_room(fig: Figure | Sketch, sl: SheetLayout, page: PageSpec, scale: Scale, avoid: Sequence[Box] = ()
               ) -> Any:
    """The free room of sheet 1 about ``fig`` (:class:`~geomcon.render.free_area.FreeRoom`): clear of its drawn
    elements, the title block, the scale bar, the step captions and the boxes ``avoid`` (of a sketch, its strokes:
    a room holding the finished figure's)."""
    from .free_area import FreeRoom
    fx0, fy0, fx1, fy1 = frame_box(page.sheet)
    return FreeRoom([s for g in fig.groups for s in g.shapes], (fx0 + INSET, fy0 + INSET, fx1 - INSET, fy1 - INSET),
                    _keepouts(fig, sl, page, scale) + list(avoid))


def may_hold_results(room: Any, info: Sequence[str], warnings: Sequence[str]) -> bool:
    """Whether :func:`results_in_free_room` may set ``info`` and ``warnings`` in ``room`` without splitting the
    results (a piece of warnings apart is allowed), where ``room`` holds at least the free room it will be given:
    False only where it surely cannot. It finds them one box, or the results one box and the warnings another
    clear of it (:func:`_pieces`); those boxes take free places of ``room`` too, two boxes that do not overlap
    lie apart along x or along y, so some result box's and some warnings box's places must lie so. A room with
    less taken (the strokes of a figure whose texts are not placed yet) answers for one with more.

    >>> from geomcon.render.free_area import FreeRoom
    >>> room = FreeRoom([], (0.0, 0.0, 130.0, 100.0), [(0.0, 0.0, 30.0, 100.0)])     # 95 mm × 100 mm free
    >>> info, warned = ["s = 1 mm"] * 12, ["check it"] * 8        # 95 × 60.2 mm and 95 × 42 mm: each alone fits
    >>> may_hold_results(room, info, warned), may_hold_results(room, info, warned[:2])
    (False, True)
    """
    from .free_area import WIDTHS
    if room.find(_info_sizes(info, warnings)) is not None:
        return True
    if not (info and warnings):
        return False
    rs = [(w, h, sp) for w in WIDTHS for h in [_height(tuple(info), w, ()) - 4.0]
          if (sp := room.span(w, h)) is not None]
    ws = [(w, h, sp) for w in WIDTHS for h in [_height((), w, tuple(warnings)) - 4.0]
          if (sp := room.span(w, h)) is not None]
    # warnings left of, right of, above or below the results: (least x, greatest x, least y, greatest y) of each
    return any(q[0] + qw <= r[1] or r[0] + rw <= q[1] or q[2] + qh <= r[3] or r[2] + rh <= q[3]
               for rw, rh, r in rs for qw, qh, q in ws)


def _info_sizes(info: Sequence[str], warnings: Sequence[str]) -> list[tuple[float, float]]:
    """The boxes one block of the results and warnings may take: each width of
    :data:`~geomcon.render.free_area.WIDTHS` and the height its lines wrap to."""
    from .free_area import WIDTHS
    info, warnings = tuple(info), tuple(warnings)
    return [(w, _height(info, w, warnings) - 4.0) for w in WIDTHS]


@functools.lru_cache(maxsize=4096)
def _height(info: tuple[str, ...], width: float, warnings: tuple[str, ...]) -> float:
    """:func:`~geomcon.render.protocol.info_height`, remembered (a function of the lines and the width alone): a
    layout search asks the height of the same lines in every free room it tries (000-06's detail window tried in
    seven places, the results split two ways in each)."""
    return info_height(info, width, warnings)


MAX_PIECES = 2
"""At most this many boxes share the results and warnings on sheet 1 (300-01 had three, one inside its figure)."""


def outside_hull(room: Any, fig: Figure) -> Any:
    """``room`` (:class:`~geomcon.render.free_area.FreeRoom`) without the convex hull of ``fig``'s drawn elements:
    a piece of a split Results block lies outside the figure, never in a gap between its links (300-01's third
    piece lay inside the four-bar ABCD)."""
    import numpy as np
    import shapely
    from .free_area import CELL, FreeRoom
    from .shapes import obstacle
    hull = shapely.convex_hull(shapely.GeometryCollection([obstacle(s) for g in fig.groups for s in g.shapes]))
    grid = room.grid.copy()
    ny, nx = grid.shape
    x0, y0 = room.grown[0], room.grown[1]
    xs, ys = np.meshgrid(x0 + (np.arange(nx) + 0.5) * CELL, y0 + (np.arange(ny) + 0.5) * CELL)
    grid[shapely.contains_xy(hull.buffer(CELL), xs, ys)] = 1      # every cell the hull touches
    return FreeRoom((), room.region, (), grid)


def _pieces(room: Any, info: Sequence[str], warnings: Sequence[str], steps: Sequence[int] | None
            ) -> list[Piece] | None:
    """The results (in their frames' order) and the warnings laid into free boxes of ``room``, greedily: all
    that is left in one box if one holds it; else the results left in one box, the warnings after; else the
    longest run of results that one box holds (the widest run over :data:`~geomcon.render.free_area.WIDTHS`),
    the rest continued. None when :data:`MAX_PIECES` boxes do not hold them, or not in reading order
    (:func:`_reading_order`: 200-15's first part lay below its second)."""
    from .free_area import WIDTHS
    order = sorted(range(len(info)), key=lambda i: (steps[i] if steps is not None else None) or 0)

    def height(rows: Sequence[int], w: float, warn: bool) -> float:
        return _height(tuple([info[i] for i in rows]), w, tuple(warnings) if warn else ()) - 4.0

    def piece(spot: tuple[float, float, float, float], rows: Sequence[int], warn: bool) -> Piece:
        x, y, w, h = spot
        return Piece(x, y - 4.0, w, h + 4.0, tuple(rows), warn)

    whole = room
    out: list[Piece] = []
    rest, warn = list(order), bool(warnings)
    while len(out) < MAX_PIECES:
        spot = room.find([(w, height(rest, w, warn)) for w in WIDTHS])
        if spot is not None:
            out.append(piece(spot, rest, warn))
            return _reading_order(whole, out, order, height)
        if not rest:
            return None
        best: tuple[int, tuple[float, float, float, float]] | None = None
        if warn:                                                  # all the results, the warnings after
            spot = room.find([(w, height(rest, w, False)) for w in WIDTHS])
            if spot is not None:
                best = (len(rest), spot)
        if best is None:
            for w in WIDTHS:                                      # the longest run one box holds
                lo, hi, found = 1, len(rest) - 1, None
                while lo <= hi:
                    k = (lo + hi) // 2
                    spot = room.find([(w, height(rest[:k], w, False))])
                    if spot is not None:
                        found, lo = (k, spot), k + 1
                    else:
                        hi = k - 1
                if found is not None and (best is None or found[0] > best[0]):
                    best = found
        if best is None:
            return None
        k, spot = best
        out.append(piece(spot, rest[:k], False))
        x, y, w, h = spot
        room = room.without((x - INSET, y - INSET, x + w + INSET, y + h + INSET))
        rest = rest[k:]
    return None


def reads_before(a: Piece, b: Piece) -> bool:
    """Whether ``a`` is read before ``b``: top to bottom (``a`` wholly above ``b``), then, side by side, left to
    right.

    >>> reads_before(Piece(200.0, 10.0, 60.0, 30.0, (), False), Piece(20.0, 50.0, 60.0, 30.0, (), False))
    True
    >>> reads_before(Piece(200.0, 10.0, 60.0, 30.0, (), False), Piece(20.0, 20.0, 60.0, 30.0, (), False))
    False
    """
    if a.y + a.h <= b.y or b.y + b.h <= a.y:
        return a.y < b.y
    return a.x < b.x


def _reading_order(room: Any, pieces: Sequence[Piece], order: Sequence[int],
                   height: Callable[[Sequence[int], float, bool], float]) -> list[Piece] | None:
    """``pieces`` (found greedily: the largest run first, wherever it fits) that hold results put in reading order
    (:func:`reads_before`; a box of the warnings alone stays after them) and the results (``order``: their frames' order) refilled into them in that order, so
    that "Results (1/3)" is read first and holds the first results: each box keeps its corner and width and takes
    a run of the results that fits below its corner in ``room`` (clear of the others), at least one each, the
    earlier boxes as full as the later ones allow (every split tried, the earliest boxes' longest runs first).
    None when no split fits."""
    from functools import cmp_to_key
    ranked = sorted((pc for pc in pieces if pc.rows), key=cmp_to_key(lambda a, b: -1 if reads_before(a, b) else 1))
    ranked += [pc for pc in pieces if not pc.rows]            # the warnings set apart: after the results
    holders = [i for i, pc in enumerate(ranked) if pc.rows]

    def box(pc: Piece) -> tuple[float, float, float, float]:
        return (pc.x - INSET, pc.y + 4.0 - INSET, pc.x + pc.w + INSET, pc.y + pc.h + INSET)

    rooms = {}                           # each holder's room: clear of the warnings box and the other holders'
    for i in holders:                    # corners (a box grows down from its corner, never into another's)
        free = room
        for j, pc in enumerate(ranked):
            if j != i:
                free = free.without(box(pc) if not pc.rows else (pc.x - INSET, pc.y + 4.0 - INSET, pc.x + pc.w + INSET,
                                                                 pc.y + 4.0 + INSET))
        rooms[i] = free

    def grown(i: int, lo: int, hi: int) -> tuple[float, float, float, float] | None:
        """Holder ``i``'s box with the results ``lo:hi`` (INSET around), None when it does not fit its room."""
        pc = ranked[i]
        h = height(order[lo:hi], pc.w, pc.warnings)
        if not rooms[i].fits(pc.x, pc.y + 4.0, pc.w, h):
            return None
        return (pc.x - INSET, pc.y + 4.0 - INSET, pc.x + pc.w + INSET, pc.y + 4.0 + h + INSET)

    def meets(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
        return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]

    def split(n: int, lo: int, placed: list[tuple[float, ...]]) -> list[int] | None:
        """Ends of the runs of holders n… from result ``lo`` on: each box as full as the rest allows, none
        meeting a box placed before it."""
        last = n == len(holders) - 1
        for hi in ([len(order)] if last else range(len(order) - (len(holders) - n - 1), lo, -1)):
            b = grown(holders[n], lo, hi)
            if b is None or any(meets(b, p) for p in placed):
                continue
            rest = [] if last else split(n + 1, hi, placed + [b])
            if rest is not None:
                return [hi] + rest
        return None

    ends = split(0, 0, [box(pc) for pc in ranked if not pc.rows])
    if ends is None:
        return None
    out, lo = list(ranked), 0
    for i, hi in zip(holders, ends):
        pc = ranked[i]
        out[i] = Piece(pc.x, pc.y, pc.w, height(order[lo:hi], pc.w, pc.warnings) + 4.0, tuple(order[lo:hi]),
                       pc.warnings)
        lo = hi
    return out


def step_captions_group(dwg: svgwrite.Drawing, scene: Scene, box: Box, lang: str, upto: int | None = None) -> Any:
    """Every numbered step's caption in ``box``, each line ``<text class="stepcap" data-step="k">``, hidden
    unless it is the current step: frame k and the player's step k show what step k does; the full drawing
    shows none. Rendered as frame ``upto``: the captions up to it, that of ``upto`` current."""
    from .labels import wrap
    from .page import fitted, zh_punct
    from .protocol import _line
    width, lh = box[2] - box[0], INFO_SIZE * 1.25
    most = max(1, int((box[3] - box[1]) // lh))
    g = dwg.g(id="captions")
    for k, group in enumerate(scene.frames(), 1):
        if upto is not None and k > upto:
            break
        en, zh = scene.caption(group[0].key)
        zh = zh_punct(zh) if zh else ""
        first = f"{k}. {(zh or en) if lang == 'zh' else en}"
        parts = [(first, wrap(first, width, INFO_SIZE))] + ([(zh, wrap(zh, width, INFO_SIZE))]
                                                            if lang == "both" and zh else [])
        lines = [ln for _, part in parts for ln in part]
        if len(lines) > most:                  # the rest on the last line, cut short: each text as it was written
            tail, n = [], 0
            for src, part in parts:
                if part[max(0, most - 1 - n):]:
                    tail.append(rejoined(src, part[max(0, most - 1 - n):]))
                n += len(part)
            lines = lines[:most - 1] + [fitted(" ".join(tail), width, INFO_SIZE, least=INFO_SIZE)]
        for i, ln in enumerate(lines):
            el = _line(dwg, ln, box[0], box[1] + INFO_SIZE + i * lh, INFO_SIZE, HIGHLIGHT,
                       "stepcap current" if k == upto else "stepcap")
            el.attribs["data-step"] = str(k)
            g.add(el)
    return g


@dataclass(frozen=True)
class SheetOne:
    """Sheet 1 as :func:`render_sheets` lays it out before the detail view: the layout (where the results are,
    :attr:`SheetLayout.info_here` False when sheet 1 has no room for them in full), the scale, the view, the
    figure, the document it is drawn into, the figure's group and the s–δ chart's marks beside it (None without
    one), whether a cam's s–δ diagram is on a sheet of its own (``apart``: the cam alone on sheet 1)."""

    layout: SheetLayout
    scale: Scale
    view: View
    fig: Figure
    dwg: Any
    drawn: Any
    marks: Any
    apart: bool
    info: Sequence[str] = ()
    """The result lines sheet 1 prints (the brief ones when the full ones find no room there)."""
    warnings: Sequence[str] = ()


def sheet_one(scene: Scene, page: PageSpec = PageSpec(), info: Sequence[str] = (), warnings: Sequence[str] = (),
              info_steps: Sequence[int] | None = None, upto: int | None = None, viewbox: Box | None = None,
              brief: tuple[Sequence[str], Sequence[str]] | None = None) -> SheetOne:
    """Where sheet 1 puts the drawing and the results: the layout at the largest standard scale
    (:func:`place_figure`, :func:`diagram_apart`), and when that reserves no room for the results, a reader reads
    one block: one box of the drawing's free room (:func:`results_in_free_room`), the drawing centred, else set
    aside against a side of its area (:func:`aside_views`: 100-04 at 1:1 with its results in a column at the
    right, where centred it left 41 mm on either side); else two boxes of the free room outside the centred
    figure; else the ``brief`` lines (results, warnings; ``{sheet}`` in them the number of the sheet with the full
    ones) in one box of the free room, centred or set aside (100-07 at 1:1); else room reserved for them at whatever
    scale (300-01: 2.5:1 → 1:1, in a band above the title block; else they had no place on sheet 1); else on a
    sheet of their own (``layout.info_here`` False). The drawing keeps its scale before the results keep one
    block: 100-04 and 100-07 were drawn at 1:2 with their results in one block in reserved room, half the sheet
    empty and 100-07's three rods EF read as one thick line."""
    sl, scale, view = place_figure(scene, page, info, warnings, upto, viewbox)
    apart = None if viewbox is not None else diagram_apart(scene, page, info, warnings, scale)
    if apart is not None:                                  # the cam alone on sheet 1, its s–δ diagram on sheet 2
        sl, scale, view = apart
    keep = None if apart is None else _not_diagram
    fig = build_figure(scene, upto, view.box, view.origin, mu=view.mu, keep=keep, room=text_room(view, sl.area))
    dwg = document(page.sheet)
    drawn, marks = _figure_and_marks(dwg, scene, fig, scale, apart is None)
    if not sl.info_here and (info or warnings):            # the drawing's free room, before a sheet of their own
        from .free_area import WIDTHS
        lines = min([(info, warnings)] + ([brief] if brief is not None else []),
                    key=lambda b: info_height(b[0], max(WIDTHS), b[1]))
        least = (min(WIDTHS) - 2 * FIG_MARGIN, info_height(lines[0], max(WIDTHS), lines[1]) - 4.0 - 2 * FIG_MARGIN)
        fy0, fy1 = frame_box(page.sheet)[1::2]
        tall = fy1 - fy0 - 2 * INSET                        # a block taller than the frame fits no placing
        views = [view] + aside_views(view, sl.area, least)
        built: dict[int, Drawn] = {0: (scale, view, fig, (drawn, marks))}      # each placing's drawing, once drawn
        sketches: dict[int, tuple[Sketch, Any]] = {}                 # its strokes and their free room, before
        tried: dict[tuple[int, int], SheetLayout | None] = {}        # (placing, lines) → the results placed

        def drawing(i: int) -> Drawn:
            """Placing ``i``'s drawing (0 centred, then set aside), its texts placed once, when first asked for."""
            if i not in built:
                v = views[i]
                sk = sketches.pop(i, (None, None))[0]
                f = build_figure(scene, upto, v.box, v.origin, mu=v.mu, keep=keep, room=text_room(v, sl.area),
                                 sketch=sk)
                built[i] = (scale, v, f, _figure_and_marks(dwg, scene, f, scale, apart is None))
            return built[i]

        def may_hold(i: int, lines: Sequence[str], warned: Sequence[str]) -> bool:
            """Whether the lines may find one box about placing ``i`` (a drawing set aside, not yet drawn): its
            texts only take room, so where its strokes alone leave none (:func:`may_hold_results`) they will
            not be placed at all (000-03's four placings aside, 100-07's two)."""
            if i in built:
                return True
            if i not in sketches:
                v = views[i]
                sk = sketch_figure(scene, upto, v.box, v.origin, mu=v.mu, keep=keep)
                sketches[i] = (sk, _free_room(sk, sl, page, scale))
            return may_hold_results(sketches[i][1], lines, warned)

        def first(lines: Sequence[str], warned: Sequence[str], boxes: int) -> tuple[SheetLayout, Drawn] | None:
            centred = boxes > 1 or info_height(lines, max(WIDTHS), warned) - 4.0 > tall
            for i in range(1 if centred else len(views)):
                if (i, id(lines)) not in tried:
                    if boxes == 1 and not may_hold(i, lines, warned):
                        tried[i, id(lines)] = None
                        continue
                    d = drawing(i)
                    tried[i, id(lines)] = results_in_free_room(d[2], sl, page, lines, warned, scale, info_steps,
                                                               _boxes(d[3][1]))
                placed = tried[i, id(lines)]
                if placed is not None and (boxes > 1 or not split(placed)):
                    return placed, built[i]
            return None

        found = first(info, warnings, 1) or first(info, warnings, 2)     # one box, else two (centred)
        if found is None and brief is not None:              # else in brief, in full on the results sheet
            short = tuple([ln.replace("{sheet}", str(2 + int(apart is not None))) for ln in lines] for lines in brief)
            got = first(short[0], short[1], 1)
            if got is not None:
                placed, (_, view, fig, (drawn, marks)) = got
                return SheetOne(placed, scale, view, fig, dwg, drawn, marks, apart is not None, *short)
        if found is None:                                    # else one block at whatever scale reserved room has
            found = _in_reserved_room(scene, dwg, page, info, warnings, upto, viewbox, keep, STANDARD[0])
        if found is not None:
            sl = found[0]
            scale, view, fig, (drawn, marks) = found[1]
    return SheetOne(sl, scale, view, fig, dwg, drawn, marks, apart is not None, info, warnings)


def aside_views(view: View, area: Box, least: tuple[float, float] = (1.0, 1.0)) -> list[View]:
    """``view`` (centred in the drawing's ``area``) set against the area's left, right, top and bottom side, in
    that order: where it moves by ``least`` (width, height; paper mm) or more. Centred, a drawing shares its free
    room out on both sides; set aside it leaves one box as wide as both (100-04 at 1:1: 83 mm at the right, not
    41 mm each side). :func:`sheet_one` asks for a move that frees room a results block can take: the block's
    least width (height) less the view's margins, :data:`~geomcon.render.view.FIG_MARGIN`, on either side.

    >>> v = View((0.0, 0.0, 100.0, 50.0), 1.0, (50.0, 10.0))
    >>> [a.origin for a in aside_views(v, (0.0, 0.0, 200.0, 70.0))]
    [(0.0, 10.0), (100.0, 10.0), (50.0, 0.0), (50.0, 20.0)]
    >>> [a.origin for a in aside_views(v, (0.0, 0.0, 200.0, 70.0), (45.0, 30.0))]
    [(0.0, 10.0), (100.0, 10.0)]
    >>> aside_views(v, (50.0, 10.0, 150.0, 60.0))
    []
    """
    (w, h), (x, y) = view.size, view.origin
    wide, tall = area[2] - area[0] - w >= least[0], area[3] - area[1] - h >= least[1]
    spots = [(area[0], y), (area[2] - w, y)] * wide + [(x, area[1]), (x, area[3] - h)] * tall
    return [replace(view, origin=o) for o in spots if abs(o[0] - x) + abs(o[1] - y) >= 1.0]


def rejoined(src: str, lines: Sequence[str]) -> str:
    """Consecutive wrapped ``lines`` of the text ``src`` set on one line again, as ``src`` has them: with the space
    the break dropped between Latin words, none between Chinese ones (a truncated step caption read
    "以 O 为圆心 作基圆" for "以 O 为圆心作基圆").

    >>> rejoined("以 O 为圆心作基圆，交于 B0", ["为圆心", "作基圆，交于 B0"]), rejoined("a long one", ["long", "one"])
    ('为圆心作基圆，交于 B0', 'long one')
    """
    out, at = "", None
    for ln in lines:
        i = src.find(ln, at or 0)
        if i < 0:                               # not found as written: keep it apart
            out, at = (out + " " if out else "") + ln, at
            continue
        out += (src[at:i] if at is not None and out else "") + ln
        at = i + len(ln)
    return out


@dataclass(frozen=True)
class Fit:
    """How sheet 1 holds a figure: the standard ``scale`` it draws at and whether it prints the results
    (``results``: in full or in brief; True when there are none) — what :func:`geomcon.render.orient.larger_page`
    weighs when it turns the paper.

    >>> Fit(Scale(1.0, 1.0), False).beats(Fit(Scale(1.0, 2.0), True)), Fit(Scale(1.0, 1.0), True).beats(
    ...     Fit(Scale(1.0, 2.0), True))
    (False, True)
    """

    scale: Scale
    results: bool

    def beats(self, other: Fit) -> bool:
        """Whether this sheet 1 draws larger than ``other`` and keeps the results if ``other`` does."""
        return self.scale > other.scale and (self.results or not other.results)


def fitted_sheets(scene: Scene, *, upto: int | None = None, viewbox: Box | None = None, title: str | None = None,
                  info: Sequence[str] = (), protocol: bool = True, warnings: Sequence[str] = (),
                  info_steps: Sequence[int] | None = None, page: PageSpec = PageSpec(), problem: str = "",
                  recipe: str = "", brief: tuple[Sequence[str], Sequence[str]] | None = None
                  ) -> tuple[list[str], Fit]:
    """The printed sheets of the scene (or of its frame ``upto``): sheet 1 the drawing at a standard scale
    with its scale bar, results, warnings and title block; a cam's s–δ diagram on sheet 2 at its own scale when
    that draws the cam larger (:func:`diagram_apart`); then the construction protocol's sheets.

    Parameters
    ----------
    scene : Scene
        The construction.
    upto : int or None
        Draw frames 1…upto only (frame ``upto`` highlighted, class ``current``); None draws everything.
    viewbox : (xmin, ymin, xmax, ymax) or None
        Model box to show; None fits the drawn points, segments and marks (see :func:`model_extent`).
    title : str or None
        Title in the title block (default: the scene's title).
    info : sequence of str
        Result lines printed under the heading Results.
    protocol : bool
        Add the sheets of the numbered construction protocol.
    warnings : sequence of str
        Warnings printed under the results, under their own heading, from the last frame on (they concern the
        whole answer, not a step).
    info_steps : sequence of int or None
        The frame producing each result line: frame k shows the results of frames 1…k only, packed (the
        lines are set in the order of their frames).
    page : PageSpec
        Paper, orientation and language.
    problem, recipe : str
        The problem file and recipe named in the title block.
    brief : (result lines, warnings) or None
        The short results and warnings sheet 1 prints when ``info`` and ``warnings`` find no room there (one
        line per result, as ``info``; ``{sheet}`` in them becomes the number of the results sheet, which holds
        the full lines, :func:`info_pages`).

    Returns
    -------
    list of str
        The SVG documents, one per sheet (UTF-8 text; width and height in mm of paper, 1 user unit = 1 mm).
    Fit
        The standard scale sheet 1 draws at and whether it prints the results (what
        :func:`geomcon.render.orient.larger_page` compares).
    """
    sheet, lang = page.sheet, page.lang
    last = len(scene.frames())             # the warnings show with the last frame
    one = sheet_one(scene, page, info, warnings, info_steps, upto, viewbox, brief)
    sl, scale, view, fig, dwg, drawn, marks = one.layout, one.scale, one.view, one.fig, one.dwg, one.drawn, one.marks
    apart = one.apart
    here = None if brief is None else tuple([ln.replace("{sheet}", str(2 + int(apart))) for ln in lines]
                                            for lines in brief)
    origin = view.origin
    fx0, fy0, fx1, fy1 = frame_box(sheet)
    tb = title_block_box(sheet)
    extra = int(apart)
    shown_info, shown_warnings = one.info, one.warnings       # what sheet 1 prints
    moved = (not sl.info_here and bool(info or warnings)) or shown_info is not info   # the results head a text sheet
    asked: list[tuple[float, float]] = []
    detail = None if viewbox is not None else mechanism_detail(scene, fig, sl, page, shown_info, shown_warnings,
                                                                scale, upto, asked)
    if detail is None and asked and sl.info_here and (info or warnings):
        first = _detail_first(scene, fig, sl, page, [(info, warnings)] + ([here] if here is not None else []),
                              scale, info_steps, upto)
        if first is not None:                                # the detail view first, the results in the room left
            sl, detail, shown_info, shown_warnings = first
            moved = moved or shown_info is not info
    text_w, text_h = fx1 - fx0 - 2 * INSET, tb[1] - fy0 - 2 * INSET
    chunks = info_pages(info, warnings, info_steps, text_w, text_h) if moved else []
    skip = chunks[-1][2] + BLOCK_GAP if chunks else 0.0      # the protocol's heading as far below as Warnings'

    notes = diagram_notes(scene, 2) if apart else None
    pages = paginate(scene, text_w, text_h, lang, skip, notes) if protocol else []
    lead = max(len(chunks) - 1, 0)                          # sheets of results alone before the protocol's first
    n = 1 + extra + lead + max(len(pages), int(moved))
    block = TitleBlock(title or scene.title, problem or "—", recipe or "—", scale, str(sheet), 1, n, lang)

    dwg.defs.add(dwg.style(CSS))
    dwg.attribs["class"] = "sheet"
    dwg.add(step_captions_group(dwg, scene, sl.caption, lang, upto))
    dwg.add(drawn)
    dwg.add(_scale_bar(dwg, fig, origin[0], origin[1] + fig.view.size[1] + 6.0, scale))
    if marks is not None:
        dwg.add(marks)
    if detail is not None:
        for i, d in enumerate(more_details(scene, fig, sl, page, shown_info, shown_warnings, scale, upto, detail)):
            dwg.add(_detail_group(dwg, *d, lang, "detail" if i == 0 else f"detail-{i + 1}"))
    see = 2 + int(apart) if shown_info is not info and lang == "both" else None    # brief: the words are there
    if sl.info_here and sl.pieces:
        n_info, parts = 0, sum(bool(pc.rows) for pc in sl.pieces)
        for pc in sl.pieces:
            rows = [shown_info[i] for i in pc.rows]
            at = [info_steps[i] for i in pc.rows] if info_steps is not None else None
            n_info += bool(rows)
            name = "warnings" if not rows else "info" if n_info == 1 else f"info-{n_info}"
            dwg.add(render_info(dwg, rows, pc.x, pc.y, pc.w, shown_warnings if pc.warnings else (), at, upto, lang, last,
                                id_=name, part=(n_info, parts) if rows and parts > 1 else None, see=see))
    elif sl.info_here and (info or warnings):
        dwg.add(render_info(dwg, shown_info, *sl.info_at, sl.info_w, shown_warnings, info_steps, upto, lang, last,
                            see=see))
    dwg.add(title_block(dwg, sheet, block))
    out = [svg_string(dwg)]
    if apart:
        out.append(_diagram_sheet(scene, page, replace(block, sheet=2), upto))
    shown = fig.shown
    values = fig.values if not apart else scene.evaluate([st.key for _, st in shown_steps(scene, upto)[0]])
    for number in range(2 + extra, n + 1):
        d = _text_sheet(sheet, replace(block, sheet=number, scale=None))
        top = fy0 + INSET
        j = number - 2 - extra
        if j < len(chunks):
            rows, warned, h = chunks[j]
            d.add(render_info(d, [info[i] for i in rows], fx0 + INSET, top - 4.0, text_w, [warnings[i] for i in warned],
                              [info_steps[i] for i in rows] if info_steps is not None else None, upto, lang, last,
                              id_="info" if j == 0 else f"info-{j + 1}"))
            top += skip
        k = j - lead
        if 0 <= k < len(pages) and pages[k].entries:      # none: the protocol starts on the next sheet
            d.add(render_protocol(d, pages[k], fx0 + INSET, top, values, shown,
                                  shown if upto is not None else None, lang))
        out.append(svg_string(d))
    return out, Fit(scale, sl.info_here or not (info or warnings))


def render_sheets(scene: Scene, *, upto: int | None = None, viewbox: Box | None = None, title: str | None = None,
                  info: Sequence[str] = (), protocol: bool = True, warnings: Sequence[str] = (),
                  info_steps: Sequence[int] | None = None, page: PageSpec = PageSpec(), problem: str = "",
                  recipe: str = "", brief: tuple[Sequence[str], Sequence[str]] | None = None) -> list[str]:
    """:func:`fitted_sheets` without the fit: the printed sheets of the scene.

    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> render_sheets(sc) == fitted_sheets(sc)[0]
    True
    """
    return fitted_sheets(scene, upto=upto, viewbox=viewbox, title=title, info=info, protocol=protocol,
                         warnings=warnings, info_steps=info_steps, page=page, problem=problem, recipe=recipe,
                         brief=brief)[0]


def split(sl: SheetLayout) -> bool:
    """Whether ``sl`` sets the results in more than one box (the warnings in a box of their own do not count)."""
    return sum(bool(pc.rows) for pc in sl.pieces) > 1


Drawn = tuple[Scale, View, Figure, tuple[Any, Any]]
"""A drawing of sheet 1 at one scale: the scale, the view, the figure, its group and chart marks."""


def _in_reserved_room(scene: Scene, dwg: svgwrite.Drawing, page: PageSpec, info: Sequence[str],
                      warnings: Sequence[str], upto: int | None, viewbox: Box | None,
                      keep: Callable[[Any], bool] | None, least: Scale) -> tuple[SheetLayout, Drawn] | None:
    """The layout that reserves room for the results on sheet 1 (a band above the title block, a column at the
    right: :func:`_layouts`) drawing at the largest standard scale, if that is at least ``least``; with the
    drawing at that scale. None without such a layout."""
    steps, _ = shown_steps(scene, upto if keep is None else None, keep)
    content = viewbox or content_box(scene, steps, scene.evaluate([s.key for _, s in steps]))
    best: tuple[SheetLayout, Scale] | None = None
    for layout in _layouts(page, info, warnings):
        s = figure_scale(content, layout.area, 0.0 if viewbox else FIG_MARGIN)
        if layout.info_here and s >= least and (best is None or s > best[1]):
            best = (layout, s)
    if best is None:
        return None
    layout, s = best
    mu = _mu(s)
    box = viewbox or grow(content, FIG_MARGIN * mu)
    view = View(box, mu, centred(((box[2] - box[0]) / mu, (box[3] - box[1]) / mu), layout.area))
    fig = build_figure(scene, upto, view.box, view.origin, mu=view.mu, keep=keep, room=text_room(view, layout.area))
    return layout, (s, view, fig, _figure_and_marks(dwg, scene, fig, s, keep is None))


def _figure_and_marks(dwg: svgwrite.Drawing, scene: Scene, fig: Figure, scale: Scale, beside: bool
                      ) -> tuple[Any, Any]:
    """The figure's group and, when a cam's s–δ diagram is drawn ``beside`` it on sheet 1, the diagram's axes
    marks and caption row (:func:`geomcon.render.charts.diagram_axes_marks`; None without one), set clear of the
    figure's texts. Made before the results are placed: the results keep off the caption row (001-24, 200-03 and
    200-17 printed "Results 结果" over "δ: 360° = 82.5 mm;  s 1:2")."""
    drawn = _figure_group(dwg, fig)
    if not beside or "sd_axes" not in scene:
        return drawn, None
    from .charts import diagram_axes_marks, text_boxes
    axes = scene.evaluate(["sd_axes"])["sd_axes"]
    ax, ay = fig.view.xy(*axes.at(0.0, 0.0))
    return drawn, diagram_axes_marks(dwg, fig.view, axes, scale, ax, ay + 15.0, _step_number(fig, "sd_delta_axis"),
                                     text_boxes(drawn))


CAPTION_GAP = 1.0
"""Paper mm between a chart's caption row and a block set in the free room below it (the free room's clearance,
:data:`~geomcon.render.free_area.CLEAR`, is for strokes; a caption and a heading are apart at a line's spacing)."""


def _boxes(group: Any) -> list[Box]:
    """The paper boxes of the texts of ``group`` (none for None), shrunk so that a block placed after it in the
    free room keeps :data:`CAPTION_GAP` from them."""
    if group is None:
        return []
    from .charts import text_boxes
    from .free_area import CLEAR
    d = CLEAR - CAPTION_GAP
    return [(b[0] + d, b[1] + d, max(b[0] + d, b[2] - d), max(b[1] + d, b[3] - d)) for b in text_boxes(group)]


def info_pages(info: Sequence[str], warnings: Sequence[str], steps: Sequence[int] | None, width: float,
               height: float) -> list[tuple[list[int], list[int], float]]:
    """The results (in their frames' order) and the warnings set on text sheets ``width`` × ``height`` paper mm:
    per sheet the indices of its result lines and of its warnings and the height the block takes
    (:func:`~geomcon.render.protocol.info_height`), as many lines on a
    sheet as fit (a block's heading repeated on the sheet that continues it; a line never split). 000-06's
    results and warnings are 350 mm tall: they ran over the title block of their one sheet.

    >>> [(len(r), len(w), round(h, 2)) for r, w, h in info_pages(["a"] * 20, ["w"] * 30, None, 259.0, 150.0)]
    [(20, 9, 151.15), (0, 21, 105.15)]
    """
    order = sorted(range(len(info)), key=lambda i: (steps[i] if steps is not None else None) or 0)
    items = [(0, i) for i in order] + [(1, i) for i in range(len(warnings))]
    out: list[tuple[list[int], list[int], float]] = []
    rows: list[int] = []
    warned: list[int] = []

    def tall(r: Sequence[int], w: Sequence[int]) -> float:
        return info_height([info[i] for i in r], width, [warnings[i] for i in w]) - 4.0

    for kind, i in items:
        r, w = (rows + [i], warned) if kind == 0 else (rows, warned + [i])
        if (rows or warned) and tall(r, w) > height:
            out.append((rows, warned, tall(rows, warned) + 4.0))
            rows, warned = ([i], []) if kind == 0 else ([], [i])
        else:
            rows, warned = list(r), list(w)
    if rows or warned:
        out.append((rows, warned, tall(rows, warned) + 4.0))
    return out


DIAGRAM = "sd_"
"""Key prefix of the steps of a cam's s–δ (ψ–δ) diagram (:func:`geomcon.recipes.cam_common.add_motion_diagram`)."""


def diagram_notes(scene: Scene, sheet: int) -> dict[str, tuple[str, str]]:
    """Where the protocol says a cam's s–δ diagram is, when it has a sheet of its own (number ``sheet``): each step
    whose caption names the diagram — the one that starts it (200-05 step 8, "Displacement diagram ψ–δ: δ axis …")
    and those of the cam's sheet that read it (step 13, "lay off the arm angles … of the ψ–δ diagram") — names the
    sheet (the steps after step 8 continue the diagram on that sheet: the protocol stays as short as it can).

    >>> from geomcon.problems import load_problem
    >>> from geomcon.solve import solve
    >>> sc = solve(load_problem("problems/200-05_oscillating_roller_cam.toml")).drawing_scene
    >>> notes = diagram_notes(sc, 2)
    >>> notes["sd_delta_axis"], notes["B_d1"]
    ((' (on sheet 2)', '（画在第 2 张）'), (' (diagram on sheet 2)', '（线图见第 2 张）'))
    """
    out = {}
    for group in scene.frames():
        key = group[0].key
        if "diagram" in scene.caption(key)[0]:
            out[key] = ((f" (on sheet {sheet})", f"（画在第 {sheet} 张）") if key.startswith(DIAGRAM) else
                        (f" (diagram on sheet {sheet})", f"（线图见第 {sheet} 张）"))
    return out


def _not_diagram(step: Any) -> bool:
    return not step.key.startswith(DIAGRAM)


def _diagram(step: Any) -> bool:
    return step.key.startswith(DIAGRAM)


def diagram_apart(scene: Scene, page: PageSpec, info: Sequence[str], warnings: Sequence[str],
                  together: Scale) -> tuple[SheetLayout, Scale, View] | None:
    """Where sheet 1 puts a cam drawn without its s–δ diagram, when the diagram shares the figure and leaving it
    to a sheet of its own (:func:`_diagram_sheet`) draws the cam at a larger standard scale than ``together``
    (200-01 on A4 landscape: 1:2 either way; 001-23a: 1:2 → 1:1; on A4 portrait 200-01: 1:2 → 1:1); else None."""
    if not any(s.key.startswith(DIAGRAM) for group in scene.frames() for s in group):
        return None
    alone = place_figure(scene, page, info, warnings, keep=_not_diagram)
    return alone if alone[1] > together else None


def _diagram_sheet(scene: Scene, page: PageSpec, block: TitleBlock, upto: int | None) -> str:
    """The sheet of a cam's s–δ diagram: drawn at the largest standard scale that fits the sheet (its own, stated
    in the title block and by a scale bar; the s axis at the cam's scale times its ratio), every step a group
    with its protocol number, as on sheet 1, so the player and the frames replay it."""
    sheet = page.sheet
    sl = _layouts(page, (), ())[0]
    steps, _ = shown_steps(scene, None, _diagram)
    content = content_box(scene, steps, scene.evaluate([s.key for _, s in steps]))
    scale = figure_scale(content, sl.area)
    mu = _mu(scale)
    box = grow(content, FIG_MARGIN * mu)
    origin = centred(((box[2] - box[0]) / mu, (box[3] - box[1]) / mu), sl.area)
    fig = build_figure(scene, upto, box, origin, mu=mu, keep=_diagram)
    axes = scene.evaluate(["sd_axes"])["sd_axes"] if "sd_axes" in scene else None
    length = axes is None or axes.length_axis       # ψ in degrees: no drawing scale holds for the diagram
    d = _text_sheet(sheet, replace(block, scale=scale if length else None))
    fx0, fy0, _, _ = frame_box(sheet)
    from .protocol import _line
    head = _line(d, text("Displacement diagram", "位移线图", page.lang), fx0 + INSET, fy0 + INSET + 4.0, INFO_SIZE,
                 INK, "diagram-head")
    head.attribs["font-weight"] = "bold"
    d.add(head)
    drawn = d.add(_figure_group(d, fig))
    below = origin[1] + fig.view.size[1] + 6.0
    if axes is not None:        # δ ticked in degrees, h on the ordinate, what a printed mm is on each axis
        from .charts import diagram_axes_marks, text_boxes
        d.add(diagram_axes_marks(d, fig.view, axes, scale, origin[0], below + (12.0 if length else 0.0),
                                 _step_number(fig, "sd_delta_axis"), text_boxes(drawn)))
    if length:
        d.add(_scale_bar(d, fig, origin[0], below, scale))
    return svg_string(d)


def _step_number(fig: Figure, key: str) -> int | None:
    """The protocol number of step ``key`` as drawn in ``fig`` (None when the figure does not draw it)."""
    return next((sd.number for _, groups in fig.layers() for sd in groups if sd.key == key), None)


def _text_sheet(sheet: Sheet, block: TitleBlock) -> svgwrite.Drawing:
    d = document(sheet)
    d.defs.add(d.style(CSS))
    d.attribs["class"] = "sheet"
    d.add(title_block(d, sheet, block))
    return d


def render_svg(scene: Scene, *, upto: int | None = None, viewbox: Box | None = None, title: str | None = None,
               info: Sequence[str] = (), protocol: bool = True, warnings: Sequence[str] = (),
               info_steps: Sequence[int] | None = None, page: PageSpec = PageSpec(), problem: str = "",
               recipe: str = "") -> str:
    """Sheet 1 of :func:`render_sheets`: the drawing, its scale bar, results, warnings and title block (the
    protocol is on the sheets that follow; ``protocol`` only changes the sheet count in the title block)."""
    return render_sheets(scene, upto=upto, viewbox=viewbox, title=title, info=info, protocol=protocol,
                         warnings=warnings, info_steps=info_steps, page=page, problem=problem, recipe=recipe)[0]


def _figure_group(dwg: svgwrite.Drawing, fig: Figure, prefix: str = "") -> Any:
    """The figure's layers, each step a group (ids prefixed by ``prefix``: a detail view draws steps again)."""
    root = Element.named("g", {"id": f"{prefix}figure"})
    for name, groups in fig.layers():
        layer = Element.named("g", {"id": f"{prefix}layer-{name}"})
        for sd in groups:
            g = Element.named("g", {"id": prefix + (f"arc-{step_id(sd.key)[5:]}-{sd.number}" if sd.arc
                                                    else step_id(sd.key)),
                                    "class": sd.classes, "data-step": str(sd.number)})
            for shape in sd.shapes:
                g.add(to_svg(shape))
            layer.add(g)
        root.add(layer)
    return root


def _bar_length(mu: float) -> float:
    """Paper length of the scale bar at μl = ``mu``: a round model length of about 15–35 mm of paper."""
    return max(nice_values(15.0 * mu, 35.0 * mu), default=20.0 * mu) / mu


def _scale_bar(dwg: svgwrite.Drawing, fig: Figure, x: float, y: float, scale: Scale) -> Any:
    """A scale bar of a round model length (about 15–35 mm of paper), the scale and μl: true on paper when
    the sheet is printed at 100 %."""
    mu = fig.view.mu
    length = max(nice_values(15.0 * mu, 35.0 * mu), default=20.0 * mu)
    L = length / mu
    g = dwg.g(id="scale", stroke=INK, stroke_width="0.3")
    g.attribs["data-length-mm"] = fmt(L)
    g.add(Element("path", d=f"M{fmt(x)} {fmt(y)}H{fmt(x + L)}M{fmt(x)} {fmt(y - 1)}V{fmt(y + 1)}"
                            f"M{fmt(x + L / 2)} {fmt(y - 0.6)}V{fmt(y + 0.6)}M{fmt(x + L)} {fmt(y - 1)}V{fmt(y + 1)}",
                  fill="none", id="scale-bar"))
    size = fmt(INFO_SIZE)
    g.add(Element("text", "0", x=fmt(x), y=fmt(y + 4.5), font_size=size, text_anchor="middle", stroke="none",
                  fill=INK))
    g.add(Element("text", f"{length:g} mm", x=fmt(x + L), y=fmt(y + 4.5), font_size=size, text_anchor="middle",
                  stroke="none", fill=INK))
    t = Element("text", fill=INK, font_size=size, stroke="none", x=fmt(x + L + 10.0), y=fmt(y + 1.2))
    add_runs(t, rich_runs(f"{scale}   μl = {mu:g} mm/mm"), INFO_SIZE)        # μ with subscript l
    t.attribs["xml:space"] = "preserve"
    g.add(t)
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
