"""The drawing styles: one table from style name to pen, point marker and layer, plus the page constants.

All sizes are in mm of paper (one SVG user unit = 1 mm). Recipes name a style per step; an empty or
unknown name falls back to a default chosen by the step's role and the kind of value it holds.

Examples
--------
>>> STYLES["link"].width
0.7
>>> from geomcon.scene import Role
>>> resolve_style("", Role.CONSTRUCTION, "curve").name
'construction'
>>> resolve_style("no-such-style", Role.RESULT, "point").name
'joint'
>>> resolve_style("", Role.ANNOTATION, "Ground").name
'ground'
"""
from __future__ import annotations

import math

from dataclasses import dataclass, replace

from ..scene.step import Role

FONT_FAMILY = "Noto Sans CJK SC, Noto Sans, DejaVu Sans, sans-serif"
"""Font stack of every text (a CJK font first, so that Chinese captions never fall back to boxes)."""

INK = "#1a1a1a"
HIGHLIGHT = "#d9480f"
"""Colour of the current step of a frame (orange-red)."""
GREY_TEXT = "#5c6370"
PAPER = "#ffffff"

# Text sizes on paper, mm: the ISO 3098 series (2.5, 3.5, 5, 7). No text is smaller than 2.5 mm, a
# subscript included (3.5 × the subscript scale 0.72 = 2.52 mm).
LABEL_SIZE = 3.6        # point labels
MARK_TEXT_SIZE = 3.5    # angle and dimension texts
TITLE_SIZE = 5.0
PROTO_SIZE = 3.5        # protocol line, first language
PROTO_ZH_SIZE = 3.5     # Chinese protocol line under the English one
INFO_SIZE = 3.5
HALO = 0.9              # width of the white halo drawn behind texts
TRIM_OVERSHOOT = 6.0    # paper mm a trimmed line runs beyond the last point on it

LAYERS = ("construction", "given", "ground", "links", "marks", "sliders", "points")
"""Drawing layers, bottom to top; every step group lives in exactly one of them."""


@dataclass(frozen=True, slots=True)
class Style:
    """One named drawing style.

    Parameters
    ----------
    name : str
        The style name (also the ``style-<name>`` class of the step group).
    stroke : str
        Line colour.
    width : float
        Line width, paper mm.
    dash : tuple of float
        Dash pattern, paper mm; empty for a solid line.
    marker : str
        How a point of this style is drawn: ``"hollow"`` (a hinge circle) or ``"dot"``.
    radius : float
        Marker radius, paper mm.
    marker_width : float
        Outline width of a hollow marker, paper mm.
    layer : str
        Layer of curves and marks of this style (one of :data:`LAYERS`; points are always on top).
    opacity : float
        Stroke opacity.
    compass : bool
        Circles of this style are drawn as short compass arcs through the points lying on them (the
        textbook way of drawing an auxiliary circle) rather than whole.
    label_dir : float or None
        Where a point's label goes, radians on paper (y down: π/2 is below); None places it away from the
        figure's centre. A fixed direction is held to firmly (tick labels of a diagram's axis).
    label_size : float or None
        Font size of a point's label, paper mm (None: :data:`LABEL_SIZE`).
    label_optional : bool
        A point of a numbered row (the divisions 1′, 2′, … of a cam): its label is left out where it would
        cover another text (the row is crowded), never printed on top of it.
    trim : bool
        Lines of this style are drawn only as long as the construction needs: between the points they are drawn
        through and those found on them, :data:`TRIM_OVERSHOOT` paper mm beyond
        (:func:`~geomcon.render.figure.trimmed`; a polygon's direction lines stay in the polygon's panel
        instead of running across the mechanism).
    label_whole : bool
        A label naming the point twice ("B (P12)": a joint that is also an instant centre) always prints whole:
        its bracketed name is an answer, never dropped for room as a candidate's ("N (E1)" → "N") is.
    label_thin : bool
        A row of counting numbers on a line (the divisions 1, 2, … of an s–δ diagram's δ axis): where two
        neighbours' numbers would not fit side by side, only every 2nd (4th, …) of that crowded run is printed, as a
        textbook numbers a crowded axis (:func:`~geomcon.render.rows.thinned`), instead of spreading all of them
        out with leaders.
    """

    name: str
    stroke: str = INK
    width: float = 0.35
    dash: tuple[float, ...] = ()
    marker: str = "dot"
    radius: float = 0.7
    marker_width: float = 0.3
    layer: str = "given"
    opacity: float = 1.0
    compass: bool = False
    label_dir: float | None = None
    label_size: float | None = None
    label_optional: bool = False
    trim: bool = False
    label_whole: bool = False
    label_thin: bool = False


STYLES: dict[str, Style] = {s.name: s for s in (
    # points
    Style("pivot", marker="hollow", radius=1.5, marker_width=0.4),
    Style("joint", marker="hollow", radius=1.25, marker_width=0.55),
    Style("point", marker="dot", radius=0.55),
    Style("candidate", stroke="#7d8590", marker="hollow", radius=1.0, marker_width=0.3, layer="construction"),
    Style("given", marker="dot", radius=0.75),
    Style("tick", marker="dot", radius=0.45, label_dir=math.pi / 2, label_size=2.6, label_optional=True),
    Style("tick-division", marker="dot", radius=0.45, label_dir=math.pi / 2, label_size=2.6, label_optional=True,
          label_thin=True),
    Style("division", marker="dot", radius=0.55, label_optional=True),
    Style("row-start", marker="dot", radius=0.45, label_dir=math.pi, label_size=2.6),
    # the end of a table's number lines, named by the quantity they measure at their right, as an s–δ chart
    # names its δ axis (001-02 named no variable: "BC (mm)")
    Style("row-end", marker="dot", radius=0.45, label_dir=0.0, label_size=2.6, label_whole=True),
    # the points of an instant-centre problem named as centres too ("B (P12)", "P34 (∞)"): the name in brackets
    # is the answer asked for, so the label prints whole
    Style("pivot-centre", marker="hollow", radius=1.5, marker_width=0.4, label_whole=True),
    Style("joint-centre", marker="hollow", radius=1.25, marker_width=0.55, label_whole=True),
    Style("point-centre", marker="dot", radius=0.55, label_whole=True),
    # the start of a table's row (001-02's link ranges): its name at its left, right-aligned with the other
    # rows' names and centred on its line, as a textbook's table heads its rows
    # curves
    Style("frame", width=0.25, dash=(6.0, 1.2, 1.0, 1.2)),
    Style("construction", stroke="#8f959c", width=0.18, layer="construction", compass=True),
    Style("direction", stroke="#8f959c", width=0.18, layer="construction", trim=True),
    # a velocity or acceleration polygon's direction line: from its point to where it meets the other, a little beyond
    Style("theta-circle", stroke="#5f7f9f", width=0.25, layer="construction"),
    Style("link", width=0.7, marker="hollow", radius=1.25, marker_width=0.55, layer="links"),
    Style("link-alt", stroke="#1c4e80", width=0.7, marker="hollow", radius=1.25, marker_width=0.55, layer="links"),
    Style("link-2", stroke="#3f6f9f", width=0.55, marker="hollow", radius=1.2, marker_width=0.5, layer="links"),
    Style("link-3", stroke="#8aa7c4", width=0.5, marker="hollow", radius=1.15, marker_width=0.45, layer="links"),
    # three positions of a synthesised linkage, in graded tones (position 1 darkest)
    Style("pos1", stroke="#1a1a1a", width=0.7, marker="hollow", radius=1.25, marker_width=0.55, layer="links"),
    Style("pos2", stroke="#4f6d8f", width=0.6, marker="hollow", radius=1.15, marker_width=0.5, layer="links"),
    Style("pos3", stroke="#8fa6bf", width=0.55, marker="hollow", radius=1.1, marker_width=0.45, layer="links"),
    Style("ghost", stroke="#6f767e", width=0.3, dash=(2.0, 1.0), layer="construction"),
    Style("path", stroke="#6f767e", width=0.22, dash=(1.6, 1.0), layer="construction"),
    Style("admissible", stroke="#2f9e44", width=1.6, opacity=0.45, layer="construction"),
    # marks
    Style("ground", width=0.3, layer="ground"),
    Style("guide", width=0.4, layer="ground"),
    Style("slider", width=0.45, layer="sliders"),
    Style("slider-2", stroke="#4f6d8f", width=0.4, layer="sliders"),
    Style("slider-3", stroke="#8fa6bf", width=0.35, layer="sliders"),
    # the blocks of positions 2 and 3 (pos2, pos3), in their link's tone: which rod ends in which block
    Style("angle", width=0.25, layer="marks"),
    Style("dim", width=0.2, layer="marks"),
    Style("vector", stroke="#1c4e80", width=0.45, layer="links"),
    Style("right-angle", width=0.25, layer="marks"),
)}
"""The style table: every style name the recipes use."""

_ROLE_DEFAULTS: dict[tuple[Role, str], str] = {
    (Role.GIVEN, "point"): "given",
    (Role.GIVEN, "curve"): "given",
    (Role.CONSTRUCTION, "point"): "point",
    (Role.CONSTRUCTION, "curve"): "construction",
    (Role.RESULT, "point"): "joint",
    (Role.RESULT, "curve"): "link",
    (Role.ANNOTATION, "point"): "point",
    (Role.ANNOTATION, "curve"): "given",
    (Role.MEASUREMENT, "point"): "point",
    (Role.MEASUREMENT, "curve"): "construction",
}

MARK_DEFAULTS: dict[str, str] = {
    "AngleMark": "angle", "RightAngleMark": "right-angle", "Dimension": "dim",
    "Ground": "ground", "Slider": "slider", "Guide": "guide", "Bearing": "guide",
}
"""Default style of each mark type (by class name)."""


def resolve_style(name: str, role: Role, kind: str) -> Style:
    """The style to draw a step with.

    Parameters
    ----------
    name : str
        The step's style name ("" for none).
    role : Role
        The step's role, deciding the default when ``name`` is empty or unknown.
    kind : str
        ``"point"``, ``"curve"`` or a mark class name (``"Ground"``, ``"AngleMark"``...).

    Returns
    -------
    Style
        ``STYLES[name]`` when known, else the default for the mark type, else for the role and kind.
    """
    if name in STYLES:
        return STYLES[name]
    if kind in MARK_DEFAULTS:
        return STYLES[MARK_DEFAULTS[kind]]
    return STYLES[_ROLE_DEFAULTS.get((role, kind), "construction")]


def highlighted(style: Style) -> Style:
    """The same style in the highlight colour (the current step of a frame), at least medium width.

    Examples
    --------
    >>> s = highlighted(STYLES["construction"])
    >>> s.stroke == HIGHLIGHT, s.width
    (True, 0.3)
    """
    return replace(style, stroke=HIGHLIGHT, width=max(style.width, 0.3), opacity=max(style.opacity, 0.6))


CSS = f"""
.current .ink {{ stroke: {HIGHLIGHT}; }}
.current .dot {{ fill: {HIGHLIGHT}; }}
.current text, .proto.current text {{ fill: {HIGHLIGHT}; }}
.future {{ display: none; }}
.stepcap {{ display: none; }}
.stepcap.current {{ display: inline; }}
"""
"""Replay styles: the HTML player toggles ``current`` and ``future`` on groups (presentation attributes
lose against any CSS rule, so these recolour without touching the drawing)."""
