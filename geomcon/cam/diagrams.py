"""Motion diagrams of a cam program: s–δ, v–δ (ds/dδ) and a–δ (d²s/dδ²) stacked, as a standalone SVG.

Each segment of the program is plotted on its own (one-sided values at its ends), so the jumps show: a
velocity jump (rigid impact, 刚性冲击) is drawn as a dashed step in v–δ and as an arrow to ±∞ in a–δ; an
acceleration jump (soft impact, 柔性冲击) as a dashed step in a–δ with a small circle. The output is
deterministic (numbers written with fixed precision), so the same program always gives the same bytes.

Examples
--------
>>> from geomcon.cam.program import parse_program
>>> prog = parse_program([{"kind": "rise", "angle": 120, "law": "uniform"}, {"kind": "dwell", "angle": 240}])
>>> svg = motion_diagrams_svg(prog, 16.0, title="uniform")
>>> svg.startswith("<svg") and "rigid" in svg and svg == motion_diagrams_svg(prog, 16.0, title="uniform")
True
"""
from __future__ import annotations


import numpy as np
import svgwrite

from ..render.serial import Element, svg_string
from ..render.zh import zh_brackets
from .program import Program

W, PANEL, GAP, LEFT, TOP = 170.0, 42.0, 14.0, 28.0, 16.0      # mm on paper
PLOT_W = W - LEFT - 10.0
INK, GREY, RED = "#1a1a1a", "#8f959c", "#c92a2a"
FONT = "Noto Sans CJK SC, Noto Sans, DejaVu Sans, sans-serif"


def _f(x: float) -> str:
    return f"{x:.3f}"


def _pieces(program: Program, h: float, n: int = 240) -> list[tuple[np.ndarray, tuple[np.ndarray, ...]]]:
    """(δ in degrees, (s, v, a)) on each segment, ends one-sided."""
    out = []
    for seg in program.segments:
        d = np.linspace(seg.start, seg.end, n + 1)
        r = np.radians(d)
        r[-1] = np.nextafter(r[-1], r[0])
        out.append((d, program.motion(h, r, radians=True)))
    return out


def motion_diagrams_svg(program: Program, h: float, *, title: str = "", unit: str = "mm") -> str:
    """The s–δ, v–δ and a–δ diagrams of ``program`` with stroke ``h`` (``unit``: "mm", or "°" for an
    oscillating follower), impacts marked, as an SVG string."""
    pieces = _pieces(program, h)
    span = program.segments[-1].end
    height = TOP + 3 * PANEL + 2 * GAP + 18.0
    dwg = svgwrite.Drawing(size=(f"{_f(W)}mm", f"{_f(height)}mm"), viewBox=f"0 0 {_f(W)} {_f(height)}", profile="full",
                           debug=False)
    dwg.attribs["font-family"] = FONT
    dwg.add(dwg.rect((0, 0), (W, height), fill="#ffffff"))
    if title:
        dwg.add(dwg.text(zh_brackets(title), insert=(LEFT - 18.0, 8.0), font_size=4.2, font_weight="bold", fill=INK))
    impacts = program.impacts(h)
    names = (("s", f"s ({unit})"), ("v", f"ds/dδ ({unit}/rad)"), ("a", f"d²s/dδ² ({unit}/rad²)"))
    for k, (key, label) in enumerate(names):
        y0 = TOP + k * (PANEL + GAP)
        vals = np.concatenate([p[1][k] for p in pieces])
        lo, hi = float(min(vals.min(), 0.0)), float(max(vals.max(), 0.0))
        if hi - lo <= 1e-12 * max(1.0, abs(h)):
            hi, lo = hi + 1.0, lo - 1.0
        pad = 0.08 * (hi - lo)
        lo, hi = lo - pad, hi + pad

        def X(d):
            return LEFT + PLOT_W * d / span

        def Y(v):
            return y0 + PANEL * (hi - v) / (hi - lo)

        g = dwg.add(dwg.g(id=f"panel-{key}"))
        g.add(dwg.line((_f(LEFT), _f(y0)), (_f(LEFT), _f(y0 + PANEL)), stroke=INK, stroke_width=0.3))
        g.add(dwg.line((_f(LEFT), _f(Y(0.0))), (_f(LEFT + PLOT_W + 4), _f(Y(0.0))), stroke=INK, stroke_width=0.3))
        g.add(dwg.text(label, insert=(_f(LEFT - 18.0), _f(y0 - 2.0)), font_size=3.2, fill=INK))
        g.add(dwg.text("δ (°)", insert=(_f(LEFT + PLOT_W + 1.0), _f(Y(0.0) - 1.5)), font_size=3.0, fill=INK))
        for v in (hi - pad, lo + pad):
            if abs(v) > 1e-12:
                g.add(dwg.line((_f(LEFT - 1.2), _f(Y(v))), (_f(LEFT), _f(Y(v))), stroke=INK, stroke_width=0.25))
                g.add(dwg.text(f"{v:.4g}", insert=(_f(LEFT - 2.0), _f(Y(v) + 1.0)), font_size=2.6, fill=INK,
                               text_anchor="end"))
        for seg in program.segments:
            g.add(dwg.line((_f(X(seg.end)), _f(y0)), (_f(X(seg.end)), _f(y0 + PANEL)), stroke=GREY,
                           stroke_width=0.15, stroke_dasharray="1,1"))
            g.add(dwg.text(f"{seg.end:g}", insert=(_f(X(seg.end)), _f(y0 + PANEL + 3.2)), font_size=2.5, fill=GREY,
                           text_anchor="middle"))
        prev = None
        for d, m in pieces:
            # X and Y of every sample at once: the same operations in the same order, element by element
            pts = [f"{a:.3f},{b:.3f}" for a, b in zip((LEFT + PLOT_W * d / span).tolist(),
                                                       (y0 + PANEL * (hi - m[k]) / (hi - lo)).tolist())]
            first = tuple(pts[0].split(","))
            if prev is not None and prev[1] != first[1]:
                g.add(dwg.line(prev, first, stroke=INK, stroke_width=0.25, stroke_dasharray="0.8,0.6"))
            g.add(Element("polyline", points=" ".join(pts), fill="none", stroke=INK, stroke_width="0.5"))
            prev = tuple(pts[-1].split(","))
        for imp in impacts:
            x = X(imp.angle if imp.angle > 0 or span < 360 else imp.angle)
            if key == "a" and imp.kind == "rigid":
                up = imp.jump > 0
                tip = y0 + (0.0 if up else PANEL)
                g.add(dwg.line((_f(x), _f(Y(0.0))), (_f(x), _f(tip)), stroke=RED, stroke_width=0.4))
                s = -1 if up else 1
                g.add(dwg.polygon([(_f(x), _f(tip)), (_f(x - 1.0), _f(tip - 2.2 * s)), (_f(x + 1.0), _f(tip - 2.2 * s))],
                                  fill=RED))
                g.add(dwg.text(("+∞" if up else "−∞") + " rigid", insert=(_f(x + 1.3), _f(tip - 1.8 * s + 1.0)),
                               font_size=2.6, fill=RED))
            if key == "a" and imp.kind == "soft":
                g.add(dwg.circle((_f(x), _f(Y(0.0))), 0.9, fill="none", stroke=RED, stroke_width=0.3))
                g.add(dwg.text("soft", insert=(_f(x + 1.2), _f(Y(0.0) + 3.2)), font_size=2.6, fill=RED))
    kinds = sorted({i.kind for i in impacts})
    note = "impacts: " + (", ".join(f"{k} ({'刚性冲击' if k == 'rigid' else '柔性冲击'}) at "
                                    + ", ".join(f"{i.angle:g}°" for i in impacts if i.kind == k) for k in kinds)
                          if kinds else "none (无冲击)")
    dwg.add(dwg.text(zh_brackets(note), insert=(_f(LEFT - 18.0), _f(height - 4.0)), font_size=3.0, fill=INK))
    return svg_string(dwg)
