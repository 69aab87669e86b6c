"""Crowded knots on a gallery sheet, measured from its SVG (issue 11, hknot11): where pins, grounds, slider blocks and
labels meet so that a reader cannot tell which label names which point.

The rules, each over one figure of the sheet (the main figure, or its detail view):

- a point's label is nearer to its own point than to any other labelled point (the label's box, measured to the
  points' centres; a label joined with a leader is read along the leader and left out; a joined label's part
  ", C4" is measured from its name, not its comma; points closer than a label's height share one label);
- no pin (a hinge's hollow circle) comes within :data:`PIN_GAP` of another point's marker, and no ground symbol or
  slider block overlaps one (a symbol meets the points at its own hinge only);
- no ground symbol touches a dimension's ink away from its hinge, nor a right angle's square (100-02's A hung its
  legs and hatch over the squares of two perpendicular bisectors' feet: one tangle);
- no point's label covers a slider block.

Two pins that meet in the main figure, or a slider block and a pin, that one of the sheet's detail views draws
apart (both there, meeting no more) are read there, as a textbook's 局部放大图 is read: no knot.

Points are read from their markers: a marker is one point, however many steps reach it. Points that coincide
(within :func:`geomcon.render.coincident.same_spot`) share the largest one's marker
(:func:`geomcon.render.coincident.shared_markers`); a step drawing no marker of its own is no point here (its name is
part of the shared label). Two markers centred within :data:`SAME_SPOT` (the SVG's printed precision) are one spot
too: a player's frame draws the current step's marker over the shared one. Any two markers farther apart are two
points, and crowd each other by the rules above (two points 0.5 mm apart do: ``test_gallery_knots``).

Examples
--------
>>> svg = ('<g class="step" data-step="1" id="step-A"><circle class="ink" cx="0" cy="0" fill="#ffffff" r="1.25" />'
...        '<text class="label" font-size="3.6" text-anchor="middle" x="10" y="1"><tspan>A</tspan></text></g>'
...        '<g class="step" data-step="2" id="step-B"><circle class="ink" cx="2.7" cy="0" fill="#ffffff" r="1.25" />'
...        '<text class="label" font-size="3.6" text-anchor="middle" x="4" y="-3"><tspan>B</tspan></text></g>')
>>> [k.what for k in knots(svg)]
['label A nearer B than A', 'pin A meets pin B']
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import shapely

from geomcon.render.coincident import LABEL_HEIGHT
from geomcon.render.labels import text_width
from geomcon.render.style import PAPER

GROUP = re.compile(r'<g class="step([^"]*)" data-step="\d+" id="((?:detail-(?:\d+-)?)?step-[^"]+)">(.*?)</g>', re.S)
AXIS = ("style-tick", "style-division", "style-row-start")
"""A chart's ticks and a cam's division numbers: labelled by a fixed rule (above the tick), not placed."""
CIRCLE = re.compile(r'<circle class="ink[^"]*" cx="([-\d.]+)" cy="([-\d.]+)" fill="((?!none")[^"]*)" r="([\d.]+)"')
TEXT = re.compile(r'<text class="label([^"]*)"([^>]*)>(.*?)</text>', re.S)
PATH = re.compile(r'<path class="ink"[^>]* d="([^"]+)"')
JOINS = (", ", " = ")
SAME_SPOT = 1e-3
"""Paper mm (the SVG's printed precision) within which two markers' centres are one spot, one point."""
COVER = 1.0
"""Paper mm² of a slider block a point's label box may cover (001-05c's "T1 = B1" touches its block's corner with
0.8 mm²): more, the label reads as written on the block (004-02's C1: 1.3 mm² at 1:5, 8.0 mm² in its detail view;
004-01's C1: 3.4 mm²)."""
PIN_GAP = 0.3
"""Least paper mm between a hinge's circle and another point's marker: less, the two read as one blot."""
DIM_TOUCH = 0.2
"""Paper mm within which a ground symbol touches a dimension's ink (its hatch reads as part of the dimension)."""
HINGE = 1.7
"""Paper mm about a ground's hinge left out of its meeting a dimension (one may start at the hinge: r0 from O)."""
MARKER = 2.0
"""The largest radius (paper mm) of a point's marker (a filled circle; an unfilled one is a curve: a roller)."""


@dataclass(frozen=True)
class Knot:
    """One crowding found: the figure (``""`` the main one, ``"detail-"`` the detail view, ``"detail-2-"`` a second
    window) and what meets what."""

    figure: str
    what: str


@dataclass(frozen=True)
class _Point:
    key: str
    name: str
    at: tuple[float, float]
    r: float
    pin: bool
    """A hinge's hollow circle (not a dot)."""


def _attr(attrs: str, name: str, default: str | None = None) -> str | None:
    m = re.search(rf'\b{name}="([^"]*)"', attrs)
    return m.group(1) if m else default


def _label(cls: str, attrs: str, body: str) -> tuple[str, tuple[float, float, float, float]] | None:
    """A label's name and box (as :func:`geomcon.render.figure._text_at` builds it; a joined part's sign left out)."""
    size = float(_attr(attrs, "font-size"))
    runs = [(t, 'font-size' in a) for a, t in re.findall(r'<tspan([^>]*)>([^<]*)</tspan>', body)]
    if not runs:
        return None
    x, y = float(_attr(attrs, "x")), float(_attr(attrs, "y"))
    sub = any(s for _, s in runs)
    w, h = text_width(tuple(runs), size) + 0.3, size * (0.95 if sub else 0.74)
    anchor = _attr(attrs, "text-anchor", "start")
    x0 = x - w / 2 if anchor == "middle" else x - w if anchor == "end" else x - 0.15
    if runs[0][0] in JOINS:                              # ", C4": the name begins after its sign (the box
        sign = text_width(runs[0][0], size)              # shifted by it, it ran the sign's width past the name)
        x0, w, runs = x0 + sign, w - sign, runs[1:]
    elif runs[-1][0] in JOINS:                           # read backwards, "C4, ": the name ends before it
        w, runs = w - text_width(runs[-1][0], size), runs[:-1]
    cy = y - h / 2 + (0.24 * size if sub else 0.0)
    return "".join(t for t, _ in runs), (x0, cy - h / 2, x0 + w, cy + h / 2)


def _polylines(d: str) -> list[list[tuple[float, float]]]:
    """The straight pieces of an SVG path made of M, L, H, V, Z (a ground's or a block's outline)."""
    out: list[list[tuple[float, float]]] = []
    x = y = 0.0
    for op, args in re.findall(r'([MLHVZ])([^MLHVZ]*)', d):
        nums = [float(v) for v in re.findall(r'[-\d.]+', args)]
        if op == "M":
            x, y = nums[0], nums[1]
            out.append([(x, y)])
        elif op == "L":
            for i in range(0, len(nums), 2):
                x, y = nums[i], nums[i + 1]
                out[-1].append((x, y))
        elif op == "H":
            x = nums[0]
            out[-1].append((x, y))
        elif op == "V":
            y = nums[0]
            out[-1].append((x, y))
        elif op == "Z":
            out[-1].append(out[-1][0])
    return [p for p in out if len(p) > 1]


def knots(svg: str) -> list[Knot]:
    """Every crowding of the sheet ``svg`` by the two rules of this module, in the order found."""
    points: dict[str, list[_Point]] = {}
    labels: dict[str, list[tuple[_Point, str, tuple[float, float, float, float]]]] = {}
    symbols: dict[str, list[tuple[str, list[list[tuple[float, float]]]]]] = {}
    dims: dict[str, list[tuple[str, shapely.MultiLineString]]] = {}
    squares: dict[str, list[tuple[str, shapely.MultiLineString]]] = {}
    for classes, gid, body in GROUP.findall(svg):
        fig = gid.split("step-", 1)[0]                 # "", "detail-", a second window's "detail-2-"
        key = gid.split("step-", 1)[1]
        circles = CIRCLE.findall(body)
        texts = TEXT.findall(body)
        if circles and body.startswith("<circle") and float(circles[0][3]) <= MARKER:
            cx, cy, fill, r = circles[0]
            p = _Point(key, key, (float(cx), float(cy)), float(r), fill == PAPER)
            points.setdefault(fig, []).append(p)
            for cls, attrs, inner in texts:
                got = _label(cls, attrs, inner)
                if got is not None and "fan" not in cls and not any(a in classes.split() for a in AXIS):
                    labels.setdefault(fig, []).append((p, got[0], got[1]))
        elif not circles:
            paths = [q for d in PATH.findall(body) for q in _polylines(d)]
            kind = _kind(gid, svg)
            if kind in ("ground", "slider") and paths:
                symbols.setdefault(fig, []).append((f"{kind} {key}", paths))
            if kind == "dim" and paths:
                dims.setdefault(fig, []).append((key, shapely.MultiLineString(paths)))
            if kind == "right-angle" and paths:
                squares.setdefault(fig, []).append((key, shapely.MultiLineString(paths)))
    out: list[Knot] = []
    for fig in sorted(points, key=lambda f: (f != "", f)):
        pts = points[fig]
        named = {id(p) for p, _, _ in labels.get(fig, [])}
        for p, name, box in labels.get(fig, []):
            b = shapely.box(*box)
            own = b.distance(shapely.Point(p.at))
            for q in pts:
                if id(q) in named and q is not p and math.dist(q.at, p.at) >= LABEL_HEIGHT:     # else one label
                    if b.distance(shapely.Point(q.at)) <= own:
                        other = next(n for x, n, _ in labels[fig] if x is q)
                        out.append(Knot(fig, f"label {name} nearer {other} than {name}"))
                        break
        for i, p in enumerate(pts):
            for q in pts[i + 1:]:
                d = math.dist(p.at, q.at)
                if (p.pin or q.pin) and SAME_SPOT < d < p.r + q.r + PIN_GAP:
                    out.append(Knot(fig, f"pin {p.key} meets pin {q.key}"))
        for what, paths in symbols.get(fig, []):
            shape = shapely.MultiLineString(paths)
            if what.startswith("slider"):
                shape = shapely.union_all([shapely.Polygon(q) for q in paths if len(q) >= 4])
            centre = shape.centroid if what.startswith("slider") else None
            hinges = [p for p in pts if (centre is not None and centre.distance(shapely.Point(p.at)) < 0.05)
                      or (centre is None and _at_hinge(p, paths))]
            for q in pts:
                if any(math.dist(q.at, h.at) <= SAME_SPOT for h in hinges):
                    continue
                if shape.distance(shapely.Point(q.at)) < q.r:
                    out.append(Knot(fig, f"{what} meets pin {q.key}"))
            if what.startswith("slider"):
                for p, name, box in labels.get(fig, []):
                    if shapely.box(*box).intersection(shape).area > COVER:
                        out.append(Knot(fig, f"label {name} covers {what}"))
            if what.startswith("ground"):
                apart = shape.difference(shapely.Point(paths[0][1]).buffer(HINGE, 8))   # a dimension from its hinge
                for key, line in dims.get(fig, []):
                    if apart.distance(line) < DIM_TOUCH:
                        out.append(Knot(fig, f"{what} meets dimension {key}"))
                for key, line in squares.get(fig, []):
                    if apart.distance(line) < DIM_TOUCH:
                        out.append(Knot(fig, f"{what} meets right angle {key}"))
    shown = {f: {p.key for p in pts} | {w.split(" ", 1)[1] for w, _ in symbols.get(f, [])}
             for f, pts in points.items() if f}
    return _read_in_detail(out, shown)


def _read_in_detail(found: list[Knot], shown: dict[str, set[str]]) -> list[Knot]:
    """``found`` less the main figure's pins that meet, or slider block and pin, where one of the sheet's detail
    views (its figure prefix → the keys of its points and symbols, ``shown``) draws both and they meet no more: the
    reader reads that knot in the detail, the textbook's 局部放大图 (a sheet may have one per knot: 000-04's B0 at
    2:1, its A0 at 1:1). A block is its joint's: 004-02's E, on C1's pin at 1:5 (1.85 mm from its centre), meets
    C1's block as it meets the pin, and both are read apart in the mechanism's detail at 1:2.5."""
    apart = set()
    for k in found:
        m = re.fullmatch(r"(?:pin|slider) (\S+) meets pin (\S+)", k.what)
        if k.figure != "" or not m:
            continue
        both = (k.what, f"pin {m.group(2)} meets pin {m.group(1)}")
        if any({m.group(1), m.group(2)} <= keys and not any(Knot(f, w) in found for w in both)
               for f, keys in shown.items()):
            apart.add(k)
    return [k for k in found if k not in apart]


def _kind(gid: str, svg: str) -> str | None:
    """``"ground"``, ``"slider"``, ``"dim"`` or ``"right-angle"`` for a step group drawing that symbol, else None."""
    m = re.search(rf'<g class="step[^"]*style-(ground|slider|dim|right-angle)\b[^"]*" data-step="\d+" id="{re.escape(gid)}"',
                  svg)
    return m.group(1) if m else None


def _at_hinge(p: _Point, paths: list[list[tuple[float, float]]]) -> bool:
    """Whether ``p`` is the hinge a ground symbol holds: the legs' apex (the middle vertex of its first piece)."""
    legs = paths[0]
    return len(legs) == 3 and math.dist(legs[1], p.at) <= SAME_SPOT


__all__ = ["Knot", "knots"]
