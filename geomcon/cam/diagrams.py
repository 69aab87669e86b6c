"""Motion diagrams of a cam program: s–δ, v–δ (ds/dδ) and a–δ (d²s/dδ²) stacked on an A4 portrait sheet with the
title block of the drawings; for an oscillating follower ψ–δ, dψ/dδ–δ, d²ψ/dδ²–δ in degrees.

Each segment of the program is plotted on its own (one-sided values at its ends), so the jumps show: a
velocity jump (rigid impact, 刚性冲击) is drawn as a dashed step in v–δ and as an arrow to ±∞ in a–δ; an
acceleration jump (soft impact, 柔性冲击) as a dashed step in a–δ with a small circle. Impacts closer than their
label's width share one label ("soft at 0°, 5°, 10°"); δ tick labels that would run together are staggered; no
two texts overlap. The output is deterministic (numbers written with fixed precision), so the same program always
gives the same bytes.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 240}])
>>> svg = motion_diagrams_svg(prog, 16.0, title="uniform")
>>> svg.startswith("<svg") and "rigid" in svg and svg == motion_diagrams_svg(prog, 16.0, title="uniform")
True
>>> 'width="210mm"' in svg and 'height="297mm"' in svg
True
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np

from ..render.charts import Texts, box_of, chart_area, chart_sheet, plain, runs_width, text_el
from ..render.labels import text_width
from ..render.serial import Element, svg_string
from ..render.zh import zh_brackets
from .program import Impact, Program

AREA = chart_area()                                            # (24, 14, 196, 255) on A4 portrait
LEFT = AREA[0] + 18.0                                          # the vertical axes
PLOT_W = AREA[2] - 16.0 - LEFT                                 # δ = 0 … span
TOP, PANEL, GAP = AREA[1] + 14.0, 50.0, 24.0                   # first panel's top, a panel's height, between
MOTION_LINE = 4.5                                              # a line of the follower's motion under the heading
INK, GREY, RED = "#1a1a1a", "#8f959c", "#c92a2a"
LABEL, TICK, NOTE = 3.5, 2.5, 3.0                              # text sizes (mm on paper, ISO 3098 ≥ 2.5)


@dataclass(frozen=True)
class DiagramAxes:
    """How a cam's s–δ (ψ–δ) diagram beside its construction is drawn, in model mm: the axes' crossing
    (``x0``, ``y0``), ``per_deg`` mm of δ axis per degree of cam angle, ``per_unit`` mm of ordinate per unit of the
    stroke ``h`` (mm or degrees), its ``symbol`` (s or ψ) and ``unit`` ("mm" or "°"). The diagram's sheet ticks
    its axes and states their scales from it.

    >>> a = DiagramAxes(0.0, 0.0, 0.5, 1.0, 16.0, "s", "mm")
    >>> a.length_axis, a.at(90.0, 16.0)
    (True, (45.0, 16.0))
    """

    x0: float
    y0: float
    per_deg: float
    per_unit: float
    h: float
    symbol: str
    unit: str

    @property
    def length_axis(self) -> bool:
        """The ordinate is a length (a translating follower's s): the drawing's scale holds for it."""
        return self.unit == "mm"

    def at(self, delta: float, s: float) -> tuple[float, float]:
        """The model point of cam angle ``delta`` (deg) and ordinate ``s``."""
        return (self.x0 + delta * self.per_deg, self.y0 + s * self.per_unit)


def _f(x: float) -> str:
    return f"{x:.3f}"


def _line(x1: str, y1: str, x2: str, y2: str, **attribs: str) -> Element:
    """A line as svgwrite's ``dwg.line((x1, y1), (x2, y2), **attribs)`` is written (:class:`Element`: without
    svgwrite's set-up of an element, about ten times as costly to make)."""
    return Element("line", x1=x1, y1=y1, x2=x2, y2=y2, **attribs)


def _pieces(program: Program, h: float, n: int = 240) -> list[tuple[np.ndarray, tuple[np.ndarray, ...]]]:
    """(δ in degrees, (s, v, a)) on each segment, ends one-sided."""
    out = []
    for seg in program.segments:
        d = np.linspace(seg.start, seg.end, n + 1)
        r = np.radians(d)
        r[-1] = np.nextafter(r[-1], r[0])
        out.append((d, program.motion(h, r, radians=True)))
    return out


def names(symbol: str, unit: str) -> tuple[tuple[tuple[str, bool], ...], ...]:
    """The three panels' headings as typeset runs.

    >>> [''.join(s for s, _ in r) for r in names("ψ", "°")]
    ['ψ (°)', 'dψ/dδ (°/rad)', 'd²ψ/dδ² (°/rad²)']
    """
    return (((f"{symbol} ({unit})", False),), ((f"d{symbol}/dδ ({unit}/rad)", False),),
            ((f"d²{symbol}/dδ² ({unit}/rad²)", False),))


def clusters(impacts: list[Impact], x_of, width_of) -> list[list[Impact]]:
    """Impacts of one kind in runs whose neighbours lie closer on paper than the label of one (plus 1 mm)."""
    out: list[list[Impact]] = []
    for imp in impacts:
        last = out[-1] if out else None
        if last and last[-1].kind == imp.kind and x_of(imp.angle) - x_of(last[-1].angle) < width_of(last[-1]) + 1.0:
            last.append(imp)
        else:
            out.append([imp])
    return out


def motion_diagrams_svg(program: Program, h: float, *, title: str = "", unit: str = "mm", symbol: str | None = None,
                        problem: str = "", recipe: str = "", motion: Sequence[str] = ()) -> str:
    """The s–δ, v–δ and a–δ diagrams of ``program`` with stroke ``h`` (``unit``: "mm", or "°" for an
    oscillating follower, whose symbol is then ψ), impacts marked, as an A4 portrait SVG sheet whose title block
    holds ``title`` (the problem's; English above Chinese when it holds both, on two lines), ``problem`` (its
    file) and ``recipe``; ``motion``: lines under the heading that say the follower's motion in words
    (:func:`follower_motion`), the three panels each a little lower to make room."""
    symbol = symbol or ("ψ" if unit == "°" else "s")
    pieces = _pieces(program, h)
    span = program.segments[-1].end
    dwg = chart_sheet(zh_brackets(title or "Motion diagrams"), problem or "—", recipe or "—")   # 等速（…）
    texts = Texts()
    head = f"Motion diagrams {symbol}–δ, d{symbol}/dδ–δ, d²{symbol}/dδ²–δ  运动线图"
    dwg.add(text_el(head, AREA[0], AREA[1] + 4.0, LABEL, INK, bold=True, cls="chart-head"))
    texts.take(box_of(AREA[0], AREA[1] + 4.0, LABEL, text_width(head, LABEL) * 1.12))
    top, panel = TOP + MOTION_LINE * len(motion), PANEL - MOTION_LINE * len(motion) / 3.0
    for i, line in enumerate(motion):
        y = AREA[1] + 4.0 + MOTION_LINE * (i + 1)
        dwg.add(text_el(line, AREA[0], y, NOTE, INK, cls="chart-motion"))
        texts.take(box_of(AREA[0], y, NOTE, text_width(line, NOTE)))
    impacts = program.impacts(h)

    def X(d):
        return LEFT + PLOT_W * d / span

    for k, runs in enumerate(names(symbol, unit)):
        key = "sva"[k]
        y0 = top + k * (panel + GAP)
        vals = np.concatenate([p[1][k] for p in pieces])
        lo, hi = float(min(vals.min(), 0.0)), float(max(vals.max(), 0.0))
        flat = hi - lo <= 1e-12 * max(1.0, abs(h))          # zero but for its impacts: no value ticks
        if flat:
            hi, lo = hi + 1.0, lo - 1.0
        pad = 0.08 * (hi - lo)
        lo, hi = lo - pad, hi + pad

        def Y(v, y0=y0, lo=lo, hi=hi):
            return y0 + panel * (hi - v) / (hi - lo)

        g = dwg.add(dwg.g(id=f"panel-{key}"))
        g.add(_line(_f(LEFT), _f(y0), _f(LEFT), _f(y0 + panel), stroke=INK, stroke_width="0.3"))
        g.add(_line(_f(LEFT), _f(Y(0.0)), _f(LEFT + PLOT_W + 4), _f(Y(0.0)), stroke=INK, stroke_width="0.3"))
        g.add(text_el(runs, AREA[0], y0 - 3.0, LABEL, INK, cls="panel-head"))
        texts.take(box_of(AREA[0], y0 - 3.0, LABEL, runs_width(runs, LABEL)))
        dl = "δ (°)"
        g.add(text_el(dl, LEFT + PLOT_W + 1.0, Y(0.0) - 1.5, NOTE, INK))
        texts.take(box_of(LEFT + PLOT_W + 1.0, Y(0.0) - 1.5, NOTE, text_width(dl, NOTE)))
        for v in (hi - pad, lo + pad):
            if abs(v) > 1e-12 and not flat:
                g.add(_line(_f(LEFT - 1.2), _f(Y(v)), _f(LEFT), _f(Y(v)), stroke=INK, stroke_width="0.25"))
                s = plain(v)
                x, y, a = texts.place(text_width(s, TICK), TICK, [(LEFT - 2.0, Y(v) + 0.9, "end")])
                g.add(text_el(s, x, y, TICK, INK, anchor=a))
        # δ ticks: 0 and every segment's end, a label that would run into the one before on a lower row
        for d in [0.0] + [seg.end for seg in program.segments]:
            if d > 0:
                g.add(_line(_f(X(d)), _f(y0), _f(X(d)), _f(y0 + panel), stroke=GREY, stroke_width="0.15",
                            stroke_dasharray="1,1"))
            s = f"{d:g}"
            spots = [(X(d), y0 + panel + 3.4 + 3.0 * r, "middle") for r in range(4)]
            x, y, a = texts.place(text_width(s, TICK), TICK, spots)
            g.add(text_el(s, x, y, TICK, GREY, anchor=a))
        prev = None
        for d, m in pieces:
            # X and Y of every sample at once: the same operations in the same order, element by element
            pts = [f"{a:.3f},{b:.3f}" for a, b in zip((LEFT + PLOT_W * d / span).tolist(),
                                                       (y0 + panel * (hi - m[k]) / (hi - lo)).tolist())]
            first = tuple(pts[0].split(","))
            if prev is not None and prev[1] != first[1]:
                g.add(_line(*prev, *first, stroke=INK, stroke_width="0.25", stroke_dasharray="0.8,0.6"))
            g.add(Element("polyline", points=" ".join(pts), fill="none", stroke=INK, stroke_width="0.5"))
            prev = tuple(pts[-1].split(","))
        if key != "a":
            continue
        limits = (AREA[0], y0 - 1.0, AREA[2], y0 + panel + 1.0)
        for imp in impacts:
            x = X(imp.angle)
            if imp.kind == "rigid":
                up = imp.jump > 0
                tip = y0 + (0.0 if up else panel)
                g.add(_line(_f(x), _f(Y(0.0)), _f(x), _f(tip), stroke=RED, stroke_width="0.4"))
                s = -1 if up else 1
                g.add(dwg.polygon([(_f(x), _f(tip)), (_f(x - 1.0), _f(tip - 2.2 * s)),
                                   (_f(x + 1.0), _f(tip - 2.2 * s))], fill=RED))
            else:
                g.add(dwg.circle((_f(x), _f(Y(0.0))), 0.9, fill="none", stroke=RED, stroke_width=0.3))

        def word(i: Impact) -> str:
            return (("+∞" if i.jump > 0 else "−∞") + " rigid") if i.kind == "rigid" else "soft"

        for run in clusters(impacts, X, lambda i: text_width(word(i), TICK)):
            first = run[0]
            s = word(first) if len(run) == 1 else word(first) + " at " + ", ".join(f"{i.angle:g}°" for i in run)
            x = X(run[-1].angle)                      # right of the last circle: the text covers none
            if first.kind == "rigid":
                up = first.jump > 0
                base = y0 + (1.8 if up else panel - 1.0)
                step = 3.2 if up else -3.2
            else:
                base, step = Y(0.0) + 3.2, 3.2
            spots = ([(x + 1.3, base + r * step, "start") for r in range(4)]
                     + [(X(first.angle) - 1.3, base + r * step, "end") for r in range(4)]
                     + [(x + 1.3, Y(0.0) - 1.6 - r * 3.2, "start") for r in range(4)])
            tx, ty, a = texts.place(text_width(s, TICK), TICK, spots, limits)
            g.add(text_el(s, tx, ty, TICK, RED, anchor=a, cls="impact"))
    kinds = sorted({i.kind for i in impacts})
    lines = ([f"impacts: {k} ({'刚性冲击' if k == 'rigid' else '柔性冲击'}) at "
              + ", ".join(f"{i.angle:g}°" for i in impacts if i.kind == k) for k in kinds] if kinds
             else ["impacts: none (无冲击)"])
    y = top + 3 * panel + 2 * GAP + 15.0
    for line in lines:
        dwg.add(text_el(zh_brackets(line), AREA[0], y, NOTE, INK, cls="impacts"))
        y += 5.0
    return svg_string(dwg)


_DWELL_ZH = ("近休止角", "远休止角")


def follower_motion(program: Program, h: float, unit: str = "mm") -> tuple[str, str]:
    """The follower's motion in words, English and Chinese, as a textbook's heading states a cam's program: each
    segment's kind and angle, the stroke with the rise (a dwell after a rise is the outer dwell, 远休止角).

    >>> from geomcon.cam.program import parse_program
    >>> en, zh = follower_motion(parse_program([{"kind": "rise", "angle": 90, "law": "cosine"},
    ...     {"kind": "dwell", "angle": 90}, {"kind": "return", "angle": 90, "law": "cosine"},
    ...     {"kind": "dwell", "angle": 90}]), 20.0)
    >>> en
    'Follower motion: rise h = 20 mm over 90°, dwell 90°, return over 90°, dwell 90°'
    >>> zh
    '从动件运动：推程运动角 90°，升程 h = 20 mm；远休止角 90°；回程运动角 90°；近休止角 90°'
    """
    stroke = f"h = {h:g} mm" if unit == "mm" else f"ψmax = {h:g}°"
    en, zh, up = [], [], False
    for seg in program.segments:
        a = f"{seg.angle:g}°"
        if seg.kind == "rise":
            en.append(f"rise {stroke} over {a}")
            zh.append(f"推程运动角 {a}，{'升程' if unit == 'mm' else '摆幅'} {stroke}")
            up = True
        elif seg.kind == "return":
            en.append(f"return over {a}")
            zh.append(f"回程运动角 {a}")
            up = False
        else:
            en.append(f"dwell {a}")
            zh.append(f"{_DWELL_ZH[up]} {a}")
    return "Follower motion: " + ", ".join(en), "从动件运动：" + "；".join(zh)
