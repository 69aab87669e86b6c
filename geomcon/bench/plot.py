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
WIDTH, HEIGHT = 980, 660
LEFT, RIGHT, TOP, BOTTOM = 92, 690, 78, 578  # the plot area
FONT = "DejaVu Sans, Arial, Helvetica, sans-serif"


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


def _decades(values: Sequence[float], *, floor: int | None = None) -> tuple[int, int]:
    lo = min(math.floor(math.log10(v)) for v in values)
    hi = max(math.ceil(math.log10(v)) for v in values)
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
        if (k - ya.hi) % step == 0 or k == ya.lo:
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
    g.add(dwg.line((LEFT, yf), (RIGHT, yf), stroke="#555", stroke_width=1.2, stroke_dasharray="6,4"))
    g.add(_text(dwg, "floor 10⁻¹⁷: smaller errors, exact 0 included, are drawn on this line",
                RIGHT - 6, yf - 6, size=10, anchor="end", fill="#555"))
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


def _series(dwg: svgwrite.Drawing, rows: Sequence[ErrorRow], color: str, xa: LogAxis, ya: LogAxis,
            label_dy: float) -> svgwrite.container.Group:
    case, method = rows[0].case, rows[0].method
    g = dwg.g(class_="series", id=f"series-{method}-{case.recipe}", font_family=FONT,
              **{"data-method": method, "data-recipe": case.recipe})
    pts = [(xa(r.seconds), ya(clipped(r.rel_error))) for r in rows]
    if len(pts) > 1:
        g.add(dwg.polyline(pts, fill="none", stroke=color, stroke_width=1.6, stroke_opacity=0.8))
    for r, (x, y) in zip(rows, pts):
        g.add(_marker(dwg, method, x, y, color))
        if r.n is not None:
            g.add(_text(dwg, f"N = {r.n:,}", x + 7, y + label_dy, size=10, fill=color))
    return g


def _legend(dwg: svgwrite.Drawing, keys: Sequence[tuple[Case, str]], colors: dict[str, str]):
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
    for line in ("sweep: crank turned through N equal", "steps, extremes by arg-max/arg-min;",
                 "construction: the recipe's scene", "built and evaluated for its answers"):
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
    xa = LogAxis(*_decades([r.seconds for r in rows]), LEFT, RIGHT)
    ya = LogAxis(*_decades([clipped(r.rel_error) for r in rows], floor=round(math.log10(FLOOR))), BOTTOM, TOP)

    dwg = svgwrite.Drawing(size=(WIDTH, HEIGHT), profile="full", debug=False)
    dwg.viewbox(0, 0, WIDTH, HEIGHT)
    dwg.add(dwg.rect((0, 0), (WIDTH, HEIGHT), fill="white"))
    dwg.add(_text(dwg, "geomcon bench: run time against error of the extreme positions", LEFT, 30, size=18,
                  font_weight="bold", font_family=FONT))
    sub = "exact construction vs sweeping the crank through N steps" + (" — quick run (N ≤ 36,000)" if quick else "")
    dwg.add(_text(dwg, sub, LEFT, 52, size=12, fill="#444", font_family=FONT))
    dwg.add(_axes(dwg, xa, ya))
    dwg.add(_guides(dwg, ya))
    for i, (case, method) in enumerate(keys):
        series = [r for r in rows if r.case == case and r.method == method]
        dwg.add(_series(dwg, series, colors[case.recipe], xa, ya, label_dy=-6 if i % 2 else 12))
    dwg.add(_legend(dwg, keys, colors))
    return '<?xml version="1.0" encoding="utf-8"?>\n' + dwg.tostring() + "\n"
