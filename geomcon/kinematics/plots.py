"""The table's quantities against the crank angle as stacked SVG panels (s–v–a, ω, ε), the exact extremes
marked. Deterministic: coordinates written to 0.001 mm of paper.

Examples
--------
>>> from .problem import demo_problem
>>> from .result import solve_cycle
>>> p = demo_problem(step=5, columns=["C.x", "C.vx"], extremes=["C.x"])
>>> svg = cycle_plots_svg(solve_cycle(p))
>>> svg.startswith("<svg") and svg.count("<polyline") == 2 and "max 120" in svg
True
"""
from __future__ import annotations

import math

import numpy as np
import svgwrite

from .quantities import position_name, value
from ..check import rounded
from ..render.serial import svg_string
from ..render.zh import zh_brackets
from .result import CycleResult, scale_of, unit_of

W, PANEL, GAP, LEFT, TOP = 170.0, 34.0, 13.0, 30.0, 16.0      # mm on paper
PLOT_W = W - LEFT - 8.0
INK, GREY, BLUE, RED = "#1a1a1a", "#8f959c", "#1c5fa8", "#c92a2a"
FONT = "Noto Sans CJK SC, Noto Sans, DejaVu Sans, sans-serif"


def _f(x: float) -> str:
    return f"{x:.3f}"


def _g(x: float) -> str:
    """A tick or value label: 4 significant digits, no '-0'."""
    s = f"{x:.4g}"
    return "0" if s in ("-0", "0") else s


def _ticks(lo: float, hi: float) -> list[float]:
    span = hi - lo
    raw = span / 4 if span > 0 else 1.0
    mag = 10 ** math.floor(math.log10(raw))
    step = next(k * mag for k in (1, 2, 2.5, 5, 10) if k * mag >= raw)
    first = math.ceil(lo / step - 1e-9) * step
    return [round(first + i * step, 12) for i in range(int((hi - first) / step + 1e-9) + 1)]


def cycle_plots_svg(r: CycleResult) -> str:
    """One panel per table column against the crank angle; the stationary points of a position quantity (and
    of the positions behind a velocity) marked where they were found."""
    cols = list(r.problem.columns)
    phi = r.cycle.phi_deg
    height = TOP + len(cols) * (PANEL + GAP) + 4.0
    dwg = svgwrite.Drawing(size=(f"{_f(W)}mm", f"{_f(height)}mm"), viewBox=f"0 0 {_f(W)} {_f(height)}",
                           profile="full", debug=False)
    dwg.attribs["font-family"] = FONT
    dwg.add(dwg.rect((0, 0), (W, height), fill="#ffffff"))
    title = f"{r.problem.id}: " + zh_brackets(r.problem.title or "whole cycle")     # Slotting machine（插床）
    title = title if len(title) <= 80 else title[:79] + "…"
    dwg.add(dwg.text(title, insert=(8.0, 8.0), font_size=3.6, font_weight="bold", fill=INK))
    x0, x1 = float(phi[0]), float(phi[-1])

    def X(d: float) -> float:
        return LEFT + (d - x0) / (x1 - x0) * PLOT_W

    for k, q in enumerate(cols):
        y0 = TOP + k * (PANEL + GAP)
        sc = scale_of(q, r.problem.mechanism)      # numbers as the files hold them: no last-bit SIMD noise
        vals = np.array([rounded(float(x), sc) if math.isfinite(x) else math.nan for x in value(r.cycle.state, q)])
        if q.endswith(".angle"):        # drawn continuous: a link through ±180° does not jump
            th = np.unwrap(np.radians(vals))
            vals = np.degrees(th - 2 * np.pi * np.round((th[0] - np.radians(vals[0])) / (2 * np.pi)))
        finite = vals[np.isfinite(vals)]
        lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
        if hi - lo < 1e-12 * max(abs(lo), abs(hi), 1e-300):
            lo, hi = lo - 1.0, hi + 1.0
        pad = 0.06 * (hi - lo)
        lo, hi = lo - pad, hi + pad

        def Y(v: float, y0=y0, lo=lo, hi=hi) -> float:
            return y0 + PANEL - (v - lo) / (hi - lo) * PANEL

        g = dwg.add(dwg.g(id=f"panel-{k + 1}"))
        g.add(dwg.rect((LEFT, y0), (PLOT_W, PANEL), fill="none", stroke=GREY, stroke_width=0.2))
        for t in _ticks(lo, hi):
            g.add(dwg.line((LEFT, Y(t)), (LEFT + PLOT_W, Y(t)), stroke="#e3e6ea", stroke_width=0.15))
            g.add(dwg.text(_g(t), insert=(LEFT - 1.5, Y(t) + 1.0), font_size=2.6, text_anchor="end", fill=INK))
        if lo < 0 < hi:
            g.add(dwg.line((LEFT, Y(0.0)), (LEFT + PLOT_W, Y(0.0)), stroke=GREY, stroke_width=0.25))
        for t in _ticks(x0, x1):
            g.add(dwg.line((X(t), y0 + PANEL), (X(t), y0 + PANEL + 1.0), stroke=INK, stroke_width=0.2))
            g.add(dwg.text(_g(t), insert=(X(t), y0 + PANEL + 4.0), font_size=2.6, text_anchor="middle", fill=INK))
        unit = unit_of(q)
        g.add(dwg.text(f"{q} ({unit})" if unit else q, insert=(LEFT, y0 - 1.5), font_size=3.2, fill=INK))
        pts = [(round(X(d), 3), round(Y(v), 3)) for d, v in zip(phi, vals) if math.isfinite(v)]
        g.add(dwg.polyline(pts, fill="none", stroke=BLUE, stroke_width=0.45))
        base = position_name(q)
        shown = 0
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
            g.add(dwg.circle((X(at), Y(v)), r=0.8, fill=RED))
            if base == q:
                right = X(at) > LEFT + 0.6 * PLOT_W        # labels on the right half read leftwards
                dy = -1.2 if s.kind == "max" or Y(v) > y0 + 4.0 else 3.4
                shown += 1
                dy += 3.2 * ((shown - 1) % 2) * (1 if dy > 0 else -1) if right else 0.0
                g.add(dwg.text(f"{s.kind} {_g(v)} at {at:.3f}°",
                               insert=(X(at) + (-1.4 if right else 1.4), Y(v) + dy), font_size=2.6, fill=RED,
                               text_anchor="end" if right else "start"))
    dwg.add(dwg.text("crank angle φ (°)", insert=(LEFT + PLOT_W, height - 1.5), font_size=2.8, text_anchor="end",
                     fill=INK))
    return svg_string(dwg)
