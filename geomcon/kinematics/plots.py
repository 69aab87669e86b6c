"""The table's quantities against the crank angle as stacked panels on A4 portrait sheets (the title block of the
drawings, five panels a sheet), the exact extremes marked. Headings typeset as the Results print symbols (φDC,
ωBC, xF with subscripts), numbers without e-notation (an axis of large values carries a ×10³ factor with its
unit), the min/max notes inside the plot clear of its frame, the curve and each other. Deterministic:
coordinates written to 0.001 mm of paper.

Examples
--------
>>> from .problem import demo_problem
>>> from .result import solve_cycle
>>> p = demo_problem(step=5, columns=["C.x", "C.vx"], extremes=["C.x"])
>>> sheets = cycle_plot_sheets(solve_cycle(p))
>>> len(sheets), sheets[0].count("<polyline") == 2 and "max 120" in sheets[0], 'height="297mm"' in sheets[0]
(1, True, True)
>>> ''.join(s for s, _ in heading("DC.angle")), heading("F.vx"), heading("gamma(BC,DC)")[0]
('φDC (°)', (('v', False), ('Fx', True), (' (mm/s)', False)), ('γ', False))
"""
from __future__ import annotations

import math
import re
from typing import Sequence

import numpy as np

from .quantities import parse_name, position_name, value
from ..check import rounded, rounder
from ..render.charts import Texts, axis_factor, box_of, chart_area, chart_sheet, factor_text, plain, runs_width, text_el
from ..render.labels import rich_runs, text_width, wrap
from ..render.warning_words import warning_lines
from ..render.serial import svg_string
from ..render.zh import zh_brackets
from .result import CycleResult, scale_of, unit_of

AREA = chart_area()                             # (24, 14, 196, 255) on A4 portrait
LEFT = AREA[0] + 14.0
PLOT_W = AREA[2] - 2.0 - LEFT
PANEL, GAP, PER_SHEET = 30.0, 15.0, 5          # a panel's height, from one panel to the next, panels a sheet
HEAD, LABEL, TICK, NOTE = 3.5, 3.5, 2.5, 2.5   # text sizes, mm on paper (ISO 3098: ≥ 2.5)
INK, GREY, BLUE, RED = "#1a1a1a", "#8f959c", "#1c5fa8", "#c92a2a"
Runs = tuple[tuple[str, bool], ...]

_SYMBOL = {"angle": "φ", "omega": "ω", "epsilon": "ε", "x": "x", "y": "y", "s": "s", "v": "v", "a": "a",
           "vx": "v", "vy": "v", "ax": "a", "ay": "a"}


def _f(x: float) -> str:
    return f"{x:.3f}"


def extreme_text(v: float, big: float, digits: int = 4) -> str:
    """An extreme's value as a panel's note prints it: the decimals of ``digits`` significant digits of ``big``
    (the panel's largest magnitude), the same for the panel's max and min, trailing zeros kept and never ``-0``
    (002-01's notes printed "max 92.91°" beside "min -0.2698°", each to 4 significant digits of itself).

    >>> extreme_text(92.9111, 92.9111), extreme_text(-0.26981, 92.9111), extreme_text(-0.001, 92.9)
    ('92.91', '-0.27', '0.00')
    >>> extreme_text(662.44, 1225.2), extreme_text(0.5, 0.0)
    ('662', '0')
    """
    places = max(0, digits - 1 - math.floor(math.log10(big))) if big > 0 and math.isfinite(big) else 0
    out = f"{v:.{places}f}"
    return out[1:] if out.startswith("-") and float(out) == 0 else out


def unit_words(q: str, factor: int = 1) -> str:
    """The unit of ``q`` as a heading prints it (° for degrees), after the axis factor when there is one."""
    u = unit_of(q)
    u = "°" if u == "deg" else u
    f = factor_text(factor)
    return f"{f} {u}".strip()


def heading(q: str, factor: int = 1) -> Runs:
    """A panel's heading: the quantity's symbol with its subscript (φDC, ωBC, vFx, γ between two links) and
    its unit, as typeset runs."""
    obj, fld = parse_name(q)
    unit = unit_words(q, factor)
    tail = f" ({unit})" if unit else ""
    if obj == "gamma":
        a, b = fld.split(",")
        return (("γ", False), (f" between {a} and {b}{tail}", False))
    sub = obj + (fld[1] if fld in ("vx", "vy", "ax", "ay") else "")
    return ((_SYMBOL.get(fld, fld), False), (sub, True), (tail, False))


def _ticks(lo: float, hi: float) -> list[float]:
    span = hi - lo
    raw = span / 4 if span > 0 else 1.0
    mag = 10 ** math.floor(math.log10(raw))
    step = next(k * mag for k in (1, 2, 2.5, 5, 10) if k * mag >= raw)
    first = math.ceil(lo / step - 1e-9) * step
    return [round(first + i * step, 12) for i in range(int((hi - first) / step + 1e-9) + 1)]


def _wrap(s: str, width: float, size: float) -> list[str]:
    """``s`` broken at spaces into lines no wider than ``width`` (bold)."""
    lines, cur = [], ""
    for w in s.split(" "):
        t = f"{cur} {w}" if cur else w
        if cur and text_width(t, size) * 1.12 > width:
            lines.append(cur)
            cur = w
        else:
            cur = t
    return lines + [cur]


def _free_of_curve(b: tuple[float, float, float, float], xs: np.ndarray, ys: np.ndarray, gap: float = 0.6) -> bool:
    inside = (xs > b[0] - gap) & (xs < b[2] + gap) & (ys > b[1] - gap) & (ys < b[3] + gap)
    return not bool(inside.any())


def _note_spot(texts: Texts, s: str, px: float, py: float, frame: tuple[float, float, float, float],
               xs: np.ndarray, ys: np.ndarray) -> tuple[float, float, str]:
    """Where a min/max note of the point (px, py) goes: near it, inside ``frame`` (inset 1 mm), clear of the
    curve and of every text placed before; the nearest such place."""
    w = text_width(s, NOTE)
    lim = (frame[0] + 1.0, frame[1] + 1.0, frame[2] - 1.0, frame[3] - 1.0)
    spots = []
    for dy in (-1.6, 3.6, -4.6, 6.6, -7.6, 9.6, -10.6, 12.6, -13.6, 15.6, -16.6, 18.6, -19.6, 21.6, -22.6, 24.6):
        for dx in (1.6, 6.0, 12.0, 20.0, 30.0, 45.0):
            spots += [(px + dx, py + dy, "start"), (px - dx, py + dy, "end")]
    # the nearest first: the distance from the point to the middle of the text
    spots.sort(key=lambda p: math.hypot(p[0] + (w / 2 if p[2] == "start" else -w / 2) - px, p[1] - 0.3 * NOTE - py))
    for x, y, a in spots:
        b = box_of(x, y, NOTE, w, a)
        if lim[0] <= b[0] and b[2] <= lim[2] and lim[1] <= b[1] and b[3] <= lim[3] and texts.free(b) \
                and _free_of_curve(b, xs, ys):
            texts.take(b)
            return x, y, a
    for x, y, a in spots:                       # no room clear of the curve: inside the frame, clear of texts
        b = box_of(x, y, NOTE, w, a)
        if lim[0] <= b[0] and b[2] <= lim[2] and lim[1] <= b[1] and b[3] <= lim[3] and texts.free(b):
            texts.take(b)
            return x, y, a
    x, y, a = spots[0]
    texts.take(box_of(x, y, NOTE, w, a))
    return x, y, a


def _panel(dwg, texts: Texts, r: CycleResult, q: str, y0: float, x0: float, x1: float) -> None:
    phi = r.cycle.phi_deg
    sc = scale_of(q, r.problem.mechanism)      # numbers as the files hold them: no last-bit SIMD noise
    rnd = rounder(sc)
    vals = np.array([rnd(x) if math.isfinite(x) else math.nan for x in value(r.cycle.state, q).tolist()])
    if q.endswith(".angle"):        # drawn continuous: a link through ±180° does not jump
        th = np.unwrap(np.radians(vals))
        vals = np.degrees(th - 2 * np.pi * np.round((th[0] - np.radians(vals[0])) / (2 * np.pi)))
    finite = vals[np.isfinite(vals)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    big = max(abs(lo), abs(hi))                 # the extremes' notes print its decimals (extreme_text)
    if hi - lo < 1e-12 * max(abs(lo), abs(hi), 1e-300):
        lo, hi = lo - 1.0, hi + 1.0
    pad = 0.06 * (hi - lo)
    lo, hi = lo - pad, hi + pad
    edge = max(abs(t) for t in _ticks(lo, hi) + [lo, hi])       # the widest tick label decides the factor
    factor = axis_factor(edge)
    lo, hi = lo / factor, hi / factor

    def X(d: float) -> float:
        return LEFT + (d - x0) / (x1 - x0) * PLOT_W

    def Y(v: float) -> float:
        return y0 + PANEL - (v / factor - lo) / (hi - lo) * PANEL

    k = r.problem.columns.index(q)
    g = dwg.add(dwg.g(id=f"panel-{k + 1}"))
    g.add(dwg.rect((LEFT, y0), (PLOT_W, PANEL), fill="none", stroke=GREY, stroke_width=0.2))
    for t in _ticks(lo, hi):
        g.add(dwg.line((LEFT, round(Y(t * factor), 3)), (LEFT + PLOT_W, round(Y(t * factor), 3)), stroke="#e3e6ea",
                       stroke_width=0.15))
        s = plain(t)
        x, y, a = texts.place(text_width(s, TICK), TICK, [(LEFT - 1.5, Y(t * factor) + 0.9, "end")])
        g.add(text_el(s, x, y, TICK, INK, anchor=a))
    if lo < 0 < hi:
        g.add(dwg.line((LEFT, round(Y(0.0), 3)), (LEFT + PLOT_W, round(Y(0.0), 3)), stroke=GREY, stroke_width=0.25))
    for t in _ticks(x0, x1):
        g.add(dwg.line((round(X(t), 3), y0 + PANEL), (round(X(t), 3), y0 + PANEL + 1.0), stroke=INK, stroke_width=0.2))
        s = plain(t)
        x, y, a = texts.place(text_width(s, TICK), TICK, [(X(t), y0 + PANEL + 4.0, "middle")])
        g.add(text_el(s, x, y, TICK, INK, anchor=a))
    runs = heading(q, factor)
    g.add(text_el(runs, LEFT, y0 - 2.0, LABEL, INK, cls="panel-head"))
    texts.take(box_of(LEFT, y0 - 2.0, LABEL, runs_width(runs, LABEL)))
    pts = [(round(X(d), 3), round(Y(v), 3)) for d, v in zip(phi, vals) if math.isfinite(v)]
    g.add(dwg.polyline(pts, fill="none", stroke=BLUE, stroke_width=0.45))
    xs, ys = np.array([p[0] for p in pts]), np.array([p[1] for p in pts])
    base = position_name(q)
    unit = unit_words(q)
    for s in r.stationary:
        if s.quantity != base:
            continue
        if base == q:
            v = rounded(s.value, sc)
        else:
            v = 0.0 if q.split(".")[1] in ("vx", "vy", "omega", "v") else None
            if v is None:
                continue
        at = rounded(s.phi_deg, 360.0)
        if not (x0 <= at <= x1):
            continue
        g.add(dwg.circle((round(X(at), 3), round(Y(v), 3)), r=0.8, fill=RED))
        if base == q:
            note = f"{s.kind} {extreme_text(v, big)}{'' if unit == '°' else ' '}{unit} at φ = {at:.{PHI_PLACES}f}°"
            tx, ty, a = _note_spot(texts, note, X(at), Y(v), (LEFT, y0, LEFT + PLOT_W, y0 + PANEL), xs, ys)
            g.add(text_el(note, tx, ty, NOTE, RED, anchor=a, cls="extreme"))


PHI_PLACES = 2
"""Decimals of the crank angle an extreme's note gives, as a drawing's angle marks print an angle (θ=12.51°): 000-09
printed "min −5.55 mm at φ = 115.771°", the value to 2 decimals and its angle to 3."""

WARN_LINE = 1.4 * NOTE
"""From one warning line to the next (mm on paper)."""


def warning_block(r: CycleResult) -> list[str]:
    """The lines of the Warnings block under the last panel: the heading, then each warning in English and
    Chinese (a warning no rule translates stays English), wrapped to the chart area, as a drawing's sheet
    prints them (:func:`~geomcon.render.warning_words.warning_lines`); none without warnings.

    >>> from .problem import demo_problem
    >>> from .result import solve_cycle
    >>> warning_block(solve_cycle(demo_problem(step=5, columns=["C.x"])))
    []
    """
    if not r.warnings:
        return []
    names = {q for w in r.warnings for q in re.findall(r"'([^']+)'", w)}
    flat = {q: "".join(t for t, _ in _symbol(q)) for q in names}
    out = ["Warnings  警告"]
    for w in warning_lines(r.warnings, "both"):
        for q in sorted(names, key=len, reverse=True):        # 'F.x' → xF, as the panel's heading names it
            w = w.replace(f"'{q}'", flat[q]).replace(q, flat[q])
        out += wrap(w, AREA[2] - AREA[0], NOTE)
    return out


def _symbol(q: str) -> Runs:
    """The symbol of a quantity as its panel's heading prints it, without the unit (xF, φDC, γ between BC and DC)."""
    obj, fld = parse_name(q)
    if obj == "gamma":
        return heading(q)[:1] + ((" between {} and {}".format(*fld.split(",")), False),)
    return heading(q)[:2]


def _typeset(line: str, names: Sequence[str]) -> Runs:
    """A warning line as runs: the quantities' symbols (:func:`_symbol`) typeset, the rest as :func:`rich_runs`."""
    flat = {"".join(t for t, _ in _symbol(q)): _symbol(q) for q in names}
    out: list[tuple[str, bool]] = []
    pos = 0
    for m in (re.finditer("|".join(re.escape(f) for f in sorted(flat, key=len, reverse=True)), line) if flat else ()):
        out += rich_runs(line[pos:m.start()]) if m.start() > pos else ()
        out += flat[m.group(0)]
        pos = m.end()
    return tuple(out) + (rich_runs(line[pos:]) if pos < len(line) else ())


def _heads(title: str, n: int, count: int) -> list[str]:
    """The chart's heading: the title (English above Chinese when it holds both), never cut: a long one wraps.
    A later sheet's title says so in each language: "(continued, 2/3)" after the English, "（续，2/3）" after the
    Chinese (hlook11m: 000-09's sheet 2 said it in English only)."""
    width = AREA[2] - AREA[0]
    first, *rest = title.split("\n")
    lines = _continued(list(_wrap(first, width, HEAD)), f" (continued, {n + 1}/{count})", width) if n else \
        list(_wrap(first, width, HEAD))
    for part in rest:
        wrapped = list(_wrap(part, width, HEAD))
        lines += _continued(wrapped, f"（续，{n + 1}/{count}）", width) if n else wrapped
    return lines


def _continued(lines: list[str], cont: str, width: float) -> list[str]:
    """``lines`` with ``cont`` whole after the last: on it when it fits, else on a line of its own."""
    joined = f"{lines[-1]}{cont}"
    return lines[:-1] + ([joined] if len(_wrap(joined, width, HEAD)) == 1 else [lines[-1], cont.strip()])


def _layout(r: CycleResult, title: str, block: list[str]) -> tuple[int, int]:
    """(sheets, panels a sheet): :data:`PER_SHEET` panels at most on a sheet, and one sheet more when the
    Warnings ``block`` does not fit under the last sheet's panels."""
    cols = len(r.problem.columns)
    count = max(1, math.ceil(cols / PER_SHEET))
    while True:
        per = math.ceil(cols / count) if cols else 0
        last = max(0, cols - per * (count - 1))
        bottom = AREA[1] + 4.0 + 5.0 * len(_heads(title, count - 1, count)) + 5.0 + last * (PANEL + GAP) - GAP + 9.0
        if not block or bottom + 8.0 + 5.0 + WARN_LINE * (len(block) - 2) <= AREA[3]:
            return count, per
        count += 1


def cycle_plot_sheets(r: CycleResult) -> list[str]:
    """One panel per table column against the crank angle, :data:`PER_SHEET` panels (at most) on each A4
    portrait sheet, the stationary points of a position quantity (and of the positions behind a velocity)
    marked where they were found; the warnings under the last panel (:func:`warning_block`)."""
    cols = list(r.problem.columns)
    phi = r.cycle.phi_deg
    x0, x1 = float(phi[0]), float(phi[-1])
    p = r.problem               # the sheets are in both languages: the English title above the Chinese one
    title = zh_brackets(p.title or "Whole cycle") + (f"\n{p.title_zh}" if p.title_zh else "")
    problem = r.problem.id + ".toml"
    block = warning_block(r)
    count, per = _layout(r, title, block)
    out = []
    for n in range(count):
        dwg = chart_sheet(title, problem, "cycle", n + 1, count)
        texts = Texts()
        y = AREA[1] + 4.0
        for line in _heads(title, n, count):
            dwg.add(text_el(line, AREA[0], y, HEAD, INK, bold=True, cls="chart-head"))
            texts.take(box_of(AREA[0], y, HEAD, text_width(line, HEAD) * 1.12))
            y += 5.0
        y0 = y + 5.0
        for q in cols[n * per:(n + 1) * per]:
            _panel(dwg, texts, r, q, y0, x0, x1)
            y0 += PANEL + GAP
        label = "crank angle φ (°)  曲柄转角"
        dwg.add(text_el(label, LEFT + PLOT_W, y0 - GAP + 9.0, NOTE, INK, anchor="end"))
        if n == count - 1 and block:
            g = dwg.g(id="warnings", class_="warnings")
            y = y0 - GAP + 9.0 + 8.0
            g.add(text_el(block[0], AREA[0], y, LABEL, RED, bold=True, cls="warning-head"))
            y += 5.0
            names = sorted({q for w in r.warnings for q in re.findall(r"'([^']+)'", w)})
            for line in block[1:]:
                g.add(text_el(_typeset(line, names), AREA[0], y, NOTE, RED, cls="warning"))
                y += WARN_LINE
            dwg.add(g)
        out.append(svg_string(dwg))
    return out


def cycle_plots_svg(r: CycleResult) -> str:
    """Sheet 1 of :func:`cycle_plot_sheets` (the name the gallery's index and older scripts use)."""
    return cycle_plot_sheets(r)[0]
