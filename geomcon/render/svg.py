"""The annotated SVG of a scene: figure, numbered construction protocol, results, scale.

Every numbered step is one SVG group ``<g id="step-<key>" class="step role-… style-…" data-step="n">``, so a
step replay is pure CSS (``.future`` hides, ``.current`` highlights). Frame k (``upto=k``) evaluates only
steps 1…k and what they depend on. Output is deterministic: fixed rounding, ids from step keys.

Examples
--------
>>> from geomcon.recipes.guide_bar import construct
>>> sc = construct({"AB": 145.0, "AC": 290.0}).scene
>>> svg = render_svg(sc, upto=3)
>>> sc.is_evaluated("theta")
False
>>> 'data-step="3"' in svg and 'data-step="4"' not in svg
True
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Sequence

import svgwrite

from ..geometry.primitives import Arc, Circle, Line, Point, Ray, Segment
from ..scene import Scene
from ..scene.marks import AngleMark, Dimension, Ground, Guide, Slider
from . import shapes
from .geometry2d import Box, View, clip_line, grow, nice_scale
from .labels import best_offset, split_label
from .style import CSS, stroke_of

MARGIN = 8.0
TITLE_H = 12.0
PROTO_W = 100.0
FIG_TARGET = 150.0
LINE_H = 3.6


# ---------------------------------------------------------------------------------------------- extent
def _points_of(value: Any) -> list[Point]:
    if isinstance(value, Point):
        return [value]
    if isinstance(value, Segment):
        return [value.a, value.b]
    if isinstance(value, Dimension):
        n = (value.b - value.a).unit().perp() * value.offset if value.a != value.b else Point(0, 0)
        return [value.a, value.b, value.a + n, value.b + n]
    if isinstance(value, (Ground, Slider)):
        return [value.at]
    if isinstance(value, Guide):
        return [value.a, value.b]
    if isinstance(value, AngleMark):
        return [value.vertex]
    if isinstance(value, Arc):
        return [value.at(0.0), value.at(0.5), value.at(1.0)]
    return []


def _box(points: Sequence[Point]) -> Box:
    xs, ys = [p.x for p in points], [p.y for p in points]
    return (min(xs), min(ys), max(xs), max(ys))


FULL_CIRCLES = ("path", "theta-circle", "given")


def model_extent(scene: Scene, upto: int | None = None) -> Box:
    """Model box of the drawing of steps 1…upto: points, segments, marks and the circles drawn whole
    (paths, θ-circles; construction circles are drawn as compass arcs), with an 8 % margin."""
    values = _values(scene, upto)
    pts = [p for v in values.values() for p in _points_of(v)]
    if not pts:
        pts = [Point(0, 0), Point(1, 1)]
    box = _box(pts)
    size = max(box[2] - box[0], box[3] - box[1], 1e-300)
    for key, v in values.items():
        if isinstance(v, Circle) and scene[key].style in FULL_CIRCLES and v.r <= 3.0 * size:
            c = v.center
            pts += [Point(c.x - v.r, c.y - v.r), Point(c.x + v.r, c.y + v.r)]
    return grow(_box(pts), 0.08, 1e-9 * size)


def _values(scene: Scene, upto: int | None) -> dict[str, Any]:
    frames = scene.frames()
    shown = [s for group in (frames if upto is None else frames[:upto]) for s in group]
    return scene.evaluate([s.key for s in shown])


# ---------------------------------------------------------------------------------------------- text
def _text_width(s: str, size: float) -> float:
    return sum(size * (1.0 if ord(ch) > 0x2E80 else 0.56) for ch in s)


def wrap(s: str, width: float, size: float) -> list[str]:
    """Split ``s`` into lines no wider than ``width`` (CJK may break anywhere, Latin at spaces)."""
    lines, cur = [], ""
    for token in _tokens(s):
        if cur and _text_width(cur + token, size) > width:
            lines.append(cur.rstrip())
            cur = token.lstrip()
        else:
            cur += token
    if cur.strip():
        lines.append(cur.rstrip())
    return lines or [""]


def _tokens(s: str) -> list[str]:
    out, word = [], ""
    for ch in s:
        if ord(ch) > 0x2E80:
            if word:
                out.append(word)
                word = ""
            out.append(ch)
        elif ch == " ":
            out.append(word + " ")
            word = ""
        else:
            word += ch
    if word:
        out.append(word)
    return out


def _fmt(value: Any, unit: str) -> str:
    if isinstance(value, bool) or value is None or not isinstance(value, (int, float)):
        return ""
    if unit == "deg":
        return f" = {value:.3f}°"
    if unit == "mm":
        return f" = {value:.3f} mm"
    return f" = {value:.4f}"


def _label(dwg, text: str, x: float, y: float):
    base, sub, rest = split_label(text)
    t = dwg.text("", insert=(round(x, 3), round(y, 3)), text_anchor="middle", class_="label")
    t.add(dwg.tspan(base))
    if sub:
        t.add(dwg.tspan(sub, dy=["0.9"], font_size="2.6px"))
    if rest:
        t.add(dwg.tspan(rest, dy=["-0.9"] if sub else None))
    return t


# ---------------------------------------------------------------------------------------------- render
def render_svg(scene: Scene, *, upto: int | None = None, viewbox: Box | None = None, title: str | None = None,
               info: Sequence[str] = (), protocol: bool = True) -> str:
    """One SVG document of the scene, or of its frame ``upto`` (steps 1…upto, the last highlighted)."""
    frames = scene.frames()
    n = len(frames) if upto is None else max(0, min(upto, len(frames)))
    number = {s.key: i for i, group in enumerate(frames[:n], 1) for s in group}
    shown = [s for group in frames[:n] for s in group]
    values = scene.evaluate([s.key for s in shown])
    box = viewbox or model_extent(scene, upto)
    w, h = box[2] - box[0], box[3] - box[1]
    mu = nice_scale(max(w / FIG_TARGET, h / (FIG_TARGET * 0.8)))
    fig_w, fig_h = w / mu, h / mu
    ox, oy = MARGIN, MARGIN + TITLE_H
    view = View(box, mu, (ox, oy))
    proto_x = ox + fig_w + 8.0
    proto_lines = _protocol_lines(scene, frames[:n], values) if protocol else []
    info_lines = [ln for s in info for ln in wrap(s, PROTO_W, 2.9)]
    n_lines = len(proto_lines)
    if protocol and upto is not None:     # frames keep the page of the whole replay: reserve every caption
        n_lines = max(n_lines, _caption_lines(scene, frames) + 2)
    text_h = LINE_H * (n_lines + len(info_lines) + (2 if info_lines else 0))
    width = round(proto_x + (PROTO_W if protocol else 0.0) + MARGIN, 3)
    height = round(max(oy + fig_h + 14.0, oy + text_h + 6.0), 3)
    dwg = svgwrite.Drawing(size=(f"{width}mm", f"{height}mm"), viewBox=f"0 0 {width} {height}", profile="full",
                           debug=False)
    dwg.defs.add(dwg.style(CSS))
    clip = dwg.defs.add(dwg.clipPath(id="fig-clip"))
    clip.add(dwg.rect((ox, oy), (round(fig_w, 3), round(fig_h, 3))))
    dwg.add(dwg.rect((0, 0), (width, height), fill="white"))
    dwg.add(dwg.text(title or scene.title, insert=(MARGIN, MARGIN + 5.0), class_="title"))
    fig = dwg.add(dwg.g(id="figure", clip_path="url(#fig-clip)"))
    labels = _place_labels(shown, values, view)
    for s in shown:
        i = number[s.key]
        g = dwg.g(id=f"step-{s.key}", class_=_classes(s, i, n, upto))
        g.attribs["data-step"] = str(i)
        st = stroke_of(s.style, role=s.role.value)
        value = values[s.key]
        if isinstance(value, Circle) and (s.style or "construction") == "construction":
            value = _compass_arcs(value, values, view)
        for el in shapes.draw(value, view, s.style, st):
            g.add(el)
        if s.key in labels:
            g.add(_label(dwg, s.label, *labels[s.key]))
        fig.add(g)
    _scale_note(dwg, view, mu, oy + fig_h + 6.0)
    if protocol:
        _protocol(dwg, proto_lines, info_lines, proto_x, oy, n, upto)
    return dwg.tostring()


def _compass_arcs(c: Circle, values: dict[str, Any], view: View):
    """A construction circle as the textbook draws it: short compass arcs through the points it carries
    (±12 mm of paper), or the whole circle when no drawn point lies on it."""
    on = sorted({round(math.atan2(p.y - c.center.y, p.x - c.center.x), 12) for p in values.values()
                 if isinstance(p, Point) and abs(abs(p - c.center) - c.r) <= 1e-9 * max(c.r, abs(p))})
    if not on:
        return c
    half = min(math.pi, max(math.radians(8.0), 12.0 / max(view.length(c.r), 1e-9)))
    return tuple(Arc(c.center, c.r, a - half, 2 * half) for a in on)


def _classes(step, i: int, n: int, upto: int | None) -> str:
    cls = f"step role-{step.role.value} style-{step.style or 'default'}"
    return cls + (" current" if upto is not None and i == n else "")


def _place_labels(shown, values, view: View) -> dict[str, tuple[float, float]]:
    segs, circles, pts = [], [], []
    for s in shown:
        v = values[s.key]
        if isinstance(v, Segment):
            segs.append((view.p(v.a.x, v.a.y), view.p(v.b.x, v.b.y)))
        elif isinstance(v, (Line, Ray)):
            part = clip_line((v.origin if isinstance(v, Ray) else v.point).tuple(), v.direction.tuple(), view.box,
                             ray=isinstance(v, Ray))
            if part:
                segs.append((view.p(*part[0]), view.p(*part[1])))
        elif isinstance(v, Circle):
            circles.append((view.p(v.center.x, v.center.y), view.length(v.r)))
        elif isinstance(v, Point):
            pts.append(view.p(v.x, v.y))
        elif isinstance(v, (Ground, Slider)):      # keep labels off the symbols too
            x, y = view.p(v.at.x, v.at.y)
            u = (math.cos(v.angle), -math.sin(v.angle)) if isinstance(v, Ground) else (0.0, 0.0)
            cx, cy = x + u[0] * 3.6, y + u[1] * 3.6
            segs += [((cx - 3.6, cy), (cx + 3.6, cy)), ((x, y), (cx, cy))]
        elif isinstance(v, Guide):
            segs.append((view.p(v.a.x, v.a.y), view.p(v.b.x, v.b.y)))
    out: dict[str, tuple[float, float]] = {}
    taken: list[tuple[float, float]] = []
    for s in shown:
        v = values[s.key]
        if isinstance(v, Point) and s.label:
            p = view.p(v.x, v.y)
            others = [q for q in pts if q != p]
            dx, dy = best_offset(p, segs, circles, others + taken, 3.4)
            pos = (p[0] + dx, p[1] + dy + 1.2)
            taken.append((p[0] + dx, p[1] + dy))
            out[s.key] = pos
    return out


def _scale_note(dwg, view: View, mu: float, y: float) -> None:
    bar = nice_scale(20.0 * mu)                     # a bar of about 20 mm of paper
    L = bar / mu
    x = view.origin[0]
    dwg.add(dwg.line((x, y), (round(x + L, 3), y), stroke="#1a1a1a", stroke_width=0.4))
    for t in (0.0, L):
        dwg.add(dwg.line((round(x + t, 3), y - 1), (round(x + t, 3), y + 1), stroke="#1a1a1a", stroke_width=0.3))
    dwg.add(dwg.text(f"{bar:g} mm      μl = {mu:g} mm/mm", insert=(x, y + 4.5), class_="info"))


def _protocol_lines(scene: Scene, frames, values) -> list[tuple[int, str, str]]:
    lines = []
    for i, group in enumerate(frames, 1):
        s = group[0]
        en, zh = scene.caption(s.key)
        value = _fmt(values[s.key], s.unit)
        for j, ln in enumerate(wrap(f"{i}. {en}{value}", PROTO_W, 2.9)):
            lines.append((i, "en", ln if j == 0 else "    " + ln))
        if zh:
            for ln in wrap(zh, PROTO_W - 4, 2.6):
                lines.append((i, "zh", "    " + ln))
    return lines


def _caption_lines(scene: Scene, frames) -> int:
    """Protocol lines of all frames, counted without the measured values (which would need later steps)."""
    total = 0
    for i, group in enumerate(frames, 1):
        en, zh = scene.caption(group[0].key)
        total += len(wrap(f"{i}. {en} = 000.000 mm", PROTO_W, 2.9)) + (len(wrap(zh, PROTO_W - 4, 2.6)) if zh else 0)
    return total


def _protocol(dwg, lines, info_lines, x: float, y0: float, n: int, upto: int | None) -> None:
    dwg.add(dwg.text("Construction protocol 作图步骤", insert=(x, y0 + 1.0), class_="protocol", font_weight="bold"))
    y = y0 + 1.0 + LINE_H * 1.3
    group = None
    last = None
    for i, lang, text in lines:
        if i != last:
            cls = "protocol" + (" current" if upto is not None and i == n else "")
            group = dwg.add(dwg.g(class_=cls))
            group.attribs["data-step"] = str(i)
            last = i
        t = dwg.text(text, insert=(x, round(y, 3)), class_="zh" if lang == "zh" else "en", xml__space="preserve")
        group.add(t)
        y += LINE_H
    if info_lines:
        y += LINE_H * 0.6
        dwg.add(dwg.text("Results 结果", insert=(x, round(y, 3)), class_="protocol", font_weight="bold"))
        y += LINE_H * 1.2
        for ln in info_lines:
            dwg.add(dwg.text(ln, insert=(x, round(y, 3)), class_="info"))
            y += LINE_H


def write_frames(scene: Scene, directory: str | Path, *, title: str | None = None, info: Sequence[str] = ()) -> list[Path]:
    """One SVG per numbered step in ``directory`` (all with the full drawing's view box), written all or nothing."""
    from ..fileio import write_all

    box = model_extent(scene)
    files = {Path(directory) / f"step-{k:03d}.svg": render_svg(scene, upto=k, viewbox=box, title=title, info=info)
             for k in range(1, len(scene.frames()) + 1)}
    write_all(files)
    return sorted(files)

