"""The plot of ``geomcon bench``: run time against error, log–log, one series per method per problem.

Everything in the SVG is fixed by the measured numbers: no random ids, no dates, a fixed order.

Examples
--------
>>> superscript(-17)
'10⁻¹⁷'
>>> time_label(-4), time_label(-3), time_label(0)
('100 µs', '1 ms', '1 s')
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import svgwrite

from .measure import Case, ErrorRow

FLOOR = 1e-17
"""Errors below this (exact zeros included) are drawn on the floor line."""

EPS = 2.220446049250313e-16
COLORS = ("#1f6fb4", "#c8372d", "#2a9a3a", "#8a4fb0", "#d08a12")
WIDTH, HEIGHT = 1040, 660
LEFT, RIGHT, TOP, BOTTOM = 92, 700, 78, 578  # the plot area
FONT = "DejaVu Sans, Arial, Helvetica, sans-serif"
NOTES = (
    "sweep: the crank turned through N equal",
    "steps, extremes by arg-max/arg-min;",
    "construction: the recipe's scene built",
    "and evaluated for its answers.",
    "",
    "A sweep's θ is off by up to one step,",
    "360°/N, anywhere in that range by luck:",
    "the guide-bar's θ = 60° is a whole number",
    "of steps for N = 360·10ᵏ (θ exact; what",
    "shows is ψ's O(1/N²) error).",
)
FULL_NOTE = ("At N = 10⁶ it is not, and the error", "jumps up.")
"""Added to the notes when N = 10⁶ is plotted."""
"""The reading notes under the legend."""


def superscript(k: int) -> str:
    """``10^k`` with Unicode superscript digits."""
    table = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
    return "10" + str(k).translate(table)


def time_label(k: int) -> str:
    """10^k seconds in s, ms, µs or ns, e.g. ``100 µs``."""
    for unit, e in (("s", 0), ("ms", -3), ("µs", -6), ("ns", -9)):
        if k >= e:
            return f"{10 ** (k - e)} {unit}"
    return superscript(k) + " s"


@dataclass(frozen=True)
class LogAxis:
    """A log10 scale mapping [10^lo, 10^hi] to pixels [p0, p1]."""

    lo: int
    hi: int
    p0: float
    p1: float

    def __call__(self, v: float) -> float:
        t = (math.log10(v) - self.lo) / (self.hi - self.lo)
        return round(self.p0 + t * (self.p1 - self.p0), 2)


def _decades(values: Sequence[float], *, floor: int | None = None, room: float = 0.0) -> tuple[int, int]:
    """Whole decades covering ``values`` with ``room`` decades to spare on the right (for point labels)."""
    lo = min(math.floor(math.log10(v)) for v in values)
    hi = max(math.ceil(math.log10(v) + room) for v in values)
    lo = floor if floor is not None else lo
    return lo, max(hi, lo + 1)


def clipped(err: float) -> float:
    """The error as plotted: at least ``FLOOR``."""
    return max(err, FLOOR)


def _text(dwg: svgwrite.Drawing, s: str, x: float, y: float, *, size: int = 11, anchor: str = "start",
          fill: str = "#222", **extra: str) -> svgwrite.text.Text:
    return dwg.text(s, insert=(round(x, 2), round(y, 2)), font_size=size, text_anchor=anchor, fill=fill, **extra)


def _axes(dwg: svgwrite.Drawing, xa: LogAxis, ya: LogAxis) -> svgwrite.container.Group:
    g = dwg.g(class_="axes", font_family=FONT)
    g.add(dwg.rect((LEFT, TOP), (RIGHT - LEFT, BOTTOM - TOP), fill="white", stroke="#444"))
    for k in range(xa.lo, xa.hi + 1):
        x = xa(10.0 ** k)
        g.add(dwg.line((x, TOP), (x, BOTTOM), stroke="#e3e3e3"))
        g.add(dwg.line((x, BOTTOM), (x, BOTTOM + 5), stroke="#444"))
        g.add(_text(dwg, time_label(k), x, BOTTOM + 19, anchor="middle"))
        for m in range(2, 10):
            if k < xa.hi:
                xm = xa(m * 10.0 ** k)
                g.add(dwg.line((xm, BOTTOM), (xm, BOTTOM + 3), stroke="#888"))
    step = 1 if ya.hi - ya.lo <= 12 else 2
    for k in range(ya.lo, ya.hi + 1):
        y = ya(10.0 ** k)
        g.add(dwg.line((LEFT, y), (RIGHT, y), stroke="#e3e3e3"))
        g.add(dwg.line((LEFT - 5, y), (LEFT, y), stroke="#444"))
        if 10.0 ** k >= FLOOR and ((k - ya.hi) % step == 0 or 10.0 ** k == FLOOR):
            g.add(_text(dwg, superscript(k), LEFT - 8, y + 4, anchor="end"))
    g.add(_text(dwg, "run time per solve (best of several runs), log scale", (LEFT + RIGHT) / 2, BOTTOM + 42,
                size=12, anchor="middle"))
    ylab = _text(dwg, "largest relative |error| of θ and ψ or H against the analytic twin, log scale",
                 0, 0, size=12, anchor="middle")
    ylab.rotate(-90)
    ylab.translate(-(TOP + BOTTOM) / 2, LEFT - 58)
    g.add(ylab)
    return g


def _guides(dwg: svgwrite.Drawing, ya: LogAxis) -> svgwrite.container.Group:
    g = dwg.g(class_="guides", font_family=FONT)
    yf = ya(FLOOR)
    g.add(dwg.rect((LEFT, yf), (RIGHT - LEFT, BOTTOM - yf), fill="#eeeeee", stroke="none"))
    g.add(dwg.line((LEFT, yf), (RIGHT, yf), stroke="#555", stroke_width=1.2, stroke_dasharray="6,4"))
    g.add(_text(dwg, "floor 10⁻¹⁷: smaller errors, exact 0 included, are drawn on the dashed line",
                LEFT + 6, (yf + BOTTOM) / 2 + 4, size=10, fill="#555"))
    ye = ya(EPS)
    g.add(dwg.line((LEFT, ye), (RIGHT, ye), stroke="#999", stroke_dasharray="2,3"))
    g.add(_text(dwg, "double-precision ε = 2.2·10⁻¹⁶", RIGHT - 6, ye - 5, size=10, anchor="end", fill="#777"))
    return g


def _marker(dwg: svgwrite.Drawing, method: str, x: float, y: float, color: str):
    if method == "construction":
        r = 7.0
        pts = [(x, y - r), (x + r, y), (x, y + r), (x - r, y)]
        return dwg.polygon([(round(a, 2), round(b, 2)) for a, b in pts], fill=color, stroke="white",
                           stroke_width=1)
    return dwg.circle((x, y), 4, fill="white", stroke=color, stroke_width=2)


Box = tuple[float, float, float, float]
OFFSETS = ((7, -6, "start"), (7, 13, "start"), (-7, -6, "end"), (-7, 13, "end"), (9, 4, "start"),
           (-9, 4, "end"), (0, -10, "middle"), (0, 20, "middle"))
"""Where a point's label may go, in order of preference: (dx, dy of the baseline, text anchor)."""


def _label_box(x: float, y: float, text: str, dx: float, dy: float, anchor: str) -> Box:
    w = 6.0 * len(text)  # 10 px sans-serif, roughly
    x0 = {"start": x + dx, "end": x + dx - w, "middle": x + dx - w / 2}[anchor]
    return x0, y + dy - 9, x0 + w, y + dy + 2


def _hits(box: Box, other: Box) -> bool:
    return box[0] < other[2] and other[0] < box[2] and box[1] < other[3] and other[1] < box[3]


def _polyline_boxes(pts: Sequence[tuple[float, float]]) -> list[Box]:
    """Small boxes every few pixels along a polyline and around its vertices: obstacles for labels."""
    boxes = [(x - 5, y - 5, x + 5, y + 5) for x, y in pts]
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        k = max(1, int(math.hypot(x1 - x0, y1 - y0) / 4))
        boxes += [(x0 + (x1 - x0) * i / k - 1, y0 + (y1 - y0) * i / k - 1,
                   x0 + (x1 - x0) * i / k + 1, y0 + (y1 - y0) * i / k + 1) for i in range(k + 1)]
    return boxes


def place_labels(points: Sequence[tuple[float, float, str]], obstacles: list[Box]) -> list[tuple[float, float, str]]:
    """Put each label beside its point where it overlaps the fewest obstacles and earlier labels, inside
    the plot area; returns (x, y, anchor) of each text.

    Examples
    --------
    >>> place_labels([(300.0, 300.0, "N = 360")], [])
    [(307.0, 294.0, 'start')]
    """
    placed: list[tuple[float, float, str]] = []
    taken = list(obstacles)
    for x, y, text in points:
        def cost(o: tuple[float, float, str]) -> int:
            box = _label_box(x, y, text, *o)
            outside = box[0] < LEFT or box[2] > RIGHT or box[1] < TOP or box[3] > BOTTOM
            return 1000 * outside + sum(_hits(box, b) for b in taken)
        best = min(OFFSETS, key=cost)  # min keeps the first of equal costs: the preferred place
        taken.append(_label_box(x, y, text, *best))
        placed.append((x + best[0], y + best[1], best[2]))
    return placed


def _series(dwg: svgwrite.Drawing, rows: Sequence[ErrorRow], pts: Sequence[tuple[float, float]], color: str,
            labels: Sequence[tuple[float, float, str] | None]) -> svgwrite.container.Group:
    case, method = rows[0].case, rows[0].method
    g = dwg.g(class_="series", id=f"series-{method}-{case.recipe}", font_family=FONT,
              **{"data-method": method, "data-recipe": case.recipe})
    if len(pts) > 1:
        g.add(dwg.polyline(pts, fill="none", stroke=color, stroke_width=1.6, stroke_opacity=0.8))
    for r, (x, y), at in zip(rows, pts, labels):
        g.add(_marker(dwg, method, x, y, color))
        if at is not None:
            g.add(_text(dwg, f"N = {r.n:,}", at[0], at[1], size=10, fill=color, anchor=at[2]))
    return g


def _legend(dwg: svgwrite.Drawing, keys: Sequence[tuple[Case, str]], colors: dict[str, str], *, full: bool):
    g = dwg.g(class_="legend", font_family=FONT)
    x0, y0 = RIGHT + 22, TOP + 4
    g.add(_text(dwg, "problem · method", x0, y0 + 4, size=12, font_weight="bold"))
    for i, (case, method) in enumerate(keys):
        y = y0 + 26 + 24 * i
        color = colors[case.recipe]
        if method == "sweep":
            g.add(dwg.line((x0, y), (x0 + 26, y), stroke=color, stroke_width=1.6))
        g.add(_marker(dwg, method, x0 + 13, y, color))
        g.add(_text(dwg, f"{case.label} · {method}", x0 + 36, y + 4))
    y = y0 + 26 + 24 * len(keys) + 8
    for line in NOTES + (FULL_NOTE if full else ()):
        g.add(_text(dwg, line, x0, y, size=10, fill="#555"))
        y += 14
    return g


def render_plot(rows: Sequence[ErrorRow], *, quick: bool = False) -> str:
    """The SVG text of the time–error plot of ``rows`` (one series per method per problem).

    Parameters
    ----------
    rows : sequence of ErrorRow
        Part (a) of the benchmark, in the order :func:`~geomcon.bench.measure.measure_extremes` gives.
    quick : bool
        Say in the subtitle that this was a ``--quick`` run.
    """
    keys: list[tuple[Case, str]] = []
    for r in rows:
        if (r.case, r.method) not in keys:
            keys.append((r.case, r.method))
    recipes = list(dict.fromkeys(r.case.recipe for r in rows))
    colors = {name: COLORS[i % len(COLORS)] for i, name in enumerate(recipes)}
    xa = LogAxis(*_decades([r.seconds for r in rows], room=0.4), LEFT, RIGHT)
    ya = LogAxis(*_decades([clipped(r.rel_error) for r in rows], floor=round(math.log10(FLOOR)) - 1), BOTTOM, TOP)

    dwg = svgwrite.Drawing(size=(WIDTH, HEIGHT), profile="full", debug=False)
    dwg.viewbox(0, 0, WIDTH, HEIGHT)
    dwg.add(dwg.rect((0, 0), (WIDTH, HEIGHT), fill="white"))
    dwg.add(_text(dwg, "geomcon bench: run time against error of the extreme positions", LEFT, 30, size=18,
                  font_weight="bold", font_family=FONT))
    sub = "exact construction vs sweeping the crank through N steps"
    sub += " — quick run (N ≤ 36,000)" if quick else ""
    dwg.add(_text(dwg, sub, LEFT, 52, size=12, fill="#444", font_family=FONT))
    dwg.add(_axes(dwg, xa, ya))
    dwg.add(_guides(dwg, ya))
    groups = [[r for r in rows if r.case == case and r.method == method] for case, method in keys]
    pts = [[(xa(r.seconds), ya(clipped(r.rel_error))) for r in group] for group in groups]
    obstacles = [b for p in pts for b in _polyline_boxes(p)]
    wanted = [(x, y, f"N = {r.n:,}") for group, p in zip(groups, pts) for r, (x, y) in zip(group, p)
              if r.n is not None]
    spots = iter(place_labels(wanted, obstacles))
    for (case, method), group, p in zip(keys, groups, pts):
        labels = [None if r.n is None else next(spots) for r in group]
        dwg.add(_series(dwg, group, p, colors[case.recipe], labels))
    dwg.add(_legend(dwg, keys, colors, full=any(r.n == 1_000_000 for r in rows)))
    return '<?xml version="1.0" encoding="utf-8"?>\n' + dwg.tostring() + "\n"
