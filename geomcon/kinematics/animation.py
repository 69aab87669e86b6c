"""The linkage moving through its cycle as one self-contained HTML page (inline SVG and script, no network):
every link, slider block and fixed pivot, the traced paths of the problem's ``trace`` points, a play/pause
button and a slider over the crank angle. ``#frame=N`` in the address opens (paused) at frame N.

Examples
--------
>>> from .problem import demo_problem
>>> from .result import solve_cycle
>>> p = demo_problem(step=5, trace=["C"])
>>> page = animation_html(solve_cycle(p))
>>> page.startswith("<!DOCTYPE html>") and "src=" not in page and "<link" not in page and '"frames"' in page
True
"""
from __future__ import annotations

import html
import json
import math
from typing import Callable

import numpy as np

from .dyads import PRP, RPR, RRP, RRR, OnLink
from .quantities import value
from .result import CycleResult, scale_of, unit_of
from ..check import rounded, rounder
from ..render.labels import plain_text
from ..render.warning_words import warning_lines

MAX_FRAMES = 360
"""Frames of the animation at most (the table's positions, thinned evenly)."""


def _r(x: float, scale: float) -> float:
    return rounded(float(x), scale) if math.isfinite(x) else 0.0


def _finite(rnd: Callable[[float], float]) -> Callable[[float], float]:
    """:func:`_r` at one scale, with that scale's rounder (:func:`geomcon.check.rounder`)."""
    return lambda x: rnd(x) if math.isfinite(x) else 0.0


def scene_data(r: CycleResult) -> dict:
    """What the page draws: per frame the points (and guide ends, block angles), static fixed pivots, fixed
    guides, segments, blocks and traced paths, with the view box (y up)."""
    m, st = r.problem.mechanism, r.cycle.state
    n = len(r.cycle.phi_deg)
    idx = np.unique(np.linspace(0, n - 1, min(n, MAX_FRAMES)).round().astype(int))
    L = m.scale()
    pts = dict(st.points)
    segs: list[list[str]] = [[m.crank.pivot, m.crank.joint]]
    blocks: list[list[str]] = []          # [point, angle key]
    angles: dict[str, np.ndarray] = {}
    guides: list[list[float]] = []
    extra: dict[str, np.ndarray] = {}
    for el in m.chain:
        if isinstance(el, RRR):
            j = el.joint or el.name
            segs += [[el.p1, j], [el.p2, j]]
        elif isinstance(el, RRP):
            j = el.joint or el.name
            segs.append([el.p, j])
            g = el.guide
            th = st.links[g.link].theta + g.angle if g.link else np.full(n, g.angle)
            angles[j] = th
            blocks.append([j, j])
            if g.link is None:
                guides.append([g.through, g.angle])
        elif isinstance(el, RPR):
            s = st.slips[el.slip or el.name].s
            reach = 1.25 * float(np.nanmax(np.abs(s)))
            th = st.links[el.link].theta
            end = f"_{el.link}_end"
            extra[end] = st.points[el.pivot].p + reach * np.exp(1j * th) * np.sign(el.branch)
            segs.append([el.pivot, end])
            angles[el.slider] = th
            blocks.append([el.slider, el.slider])
        elif isinstance(el, PRP):
            for gd in (el.guide1, el.guide2):
                if gd.link is None:
                    guides.append([gd.through, gd.angle])
        elif isinstance(el, OnLink):
            segs.append([el.base, el.name])
    allp = {**{k: v.p for k, v in pts.items()}, **extra}
    zs = np.concatenate([z[np.isfinite(z)] for z in allp.values()])
    x0, x1, y0, y1 = float(zs.real.min()), float(zs.real.max()), float(zs.imag.min()), float(zs.imag.max())
    pad = 0.08 * max(x1 - x0, y1 - y0, L)
    box = [_r(x0 - pad, L), _r(y0 - pad, L), _r(x1 - x0 + 2 * pad, L), _r(y1 - y0 + 2 * pad, L)]
    frames = []
    cols = list(r.problem.columns)
    colvals = [(value(st, q), scale_of(q, m)) for q in cols]      # each column's scale once, not per frame
    points, turns = sorted(allp.items()), sorted(angles.items())
    # each column as floats once (not a numpy scalar per frame) and its rounding's digits once: the same numbers
    at_l, at_360 = _finite(rounder(L)), _finite(rounder(360.0))
    phis = r.cycle.phi_deg.tolist()
    xy = [(k, z.real.tolist(), z.imag.tolist()) for k, z in points]
    degs = [(k, [math.degrees(x) for x in t.tolist()]) for k, t in turns]
    cols_r = [(v.tolist(), _finite(rounder(sc))) for v, sc in colvals]
    for i in idx.tolist():
        frames.append({"phi": at_360(phis[i]),
                       "p": {k: [at_l(xs[i]), at_l(ys[i])] for k, xs, ys in xy},
                       "a": {k: at_360(d[i]) for k, d in degs},
                       "v": [rnd(v[i]) for v, rnd in cols_r]})
    traces = {t: [[_r(z.real, L), _r(z.imag, L)] for z in pts[t].p if np.isfinite(z)] for t in r.problem.trace}
    fixed = {k: [_r(z.real, L), _r(z.imag, L)] for k, z in sorted(m.fixed.items())
             if k in {s for seg in segs for s in seg}}
    return {"box": box, "size": _r(L, L), "frames": frames, "segments": segs, "blocks": blocks,
            "fixed": fixed, "guides": [[*fixed.get(g, [_r(m.fixed[g].real, L), _r(m.fixed[g].imag, L)]),
                                         _r(math.degrees(a), 360.0)] for g, a in guides],
            "traces": traces, "columns": [f"{q} ({unit_of(q)})" if unit_of(q) else q for q in cols]}


SCRIPT = r"""
(function () {
  const D = JSON.parse(document.getElementById('data').textContent);
  const NS = 'http://www.w3.org/2000/svg';
  const svg = document.getElementById('mech');
  const [bx, by, bw, bh] = D.box;
  svg.setAttribute('viewBox', bx + ' ' + (-by - bh) + ' ' + bw + ' ' + bh);
  const u = D.size / 60;
  const root = document.createElementNS(NS, 'g');
  root.setAttribute('transform', 'scale(1,-1)');
  svg.appendChild(root);
  function el(tag, attrs, parent) {
    const e = document.createElementNS(NS, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    (parent || root).appendChild(e);
    return e;
  }
  const big = 4 * Math.max(bw, bh);
  for (const [x, y, a] of D.guides) {
    const c = Math.cos(a * Math.PI / 180), s = Math.sin(a * Math.PI / 180);
    el('line', {x1: x - big * c, y1: y - big * s, x2: x + big * c, y2: y + big * s, class: 'guide'});
  }
  for (const name in D.traces) {
    el('polyline', {points: D.traces[name].map(p => p.join(',')).join(' '), class: 'trace', 'data-point': name});
  }
  const lines = D.segments.map(([a, b]) => el('line', {class: 'link', 'data-from': a, 'data-to': b}));
  const blocks = D.blocks.map(([p, k]) => el('rect', {class: 'block', width: 3 * u, height: 2 * u,
                                                      x: -1.5 * u, y: -u, 'data-point': p}));
  for (const name in D.fixed) {
    const [x, y] = D.fixed[name];
    el('path', {d: `M${x},${y} l${-1.6 * u},${-2.6 * u} h${3.2 * u} z`, class: 'ground'});
  }
  const joints = {};
  const used = new Set(D.segments.flat().concat(D.blocks.map(b => b[0])));
  for (const name in D.frames[0].p) {
    if (name[0] === '_' || !used.has(name)) continue;
    joints[name] = el('circle', {r: 0.8 * u, class: 'joint', 'data-point': name});
  }
  const labels = {};
  for (const name in joints) {
    const t = el('text', {class: 'label', 'font-size': 3 * u, transform: ''}, svg);
    t.textContent = name;
    labels[name] = t;
  }
  const slider = document.getElementById('phi');
  slider.max = D.frames.length - 1;
  const readout = document.getElementById('readout');
  const num = x => String(x).replace(/^-/, '\u2212');     // a negative number as the sheets print it: minus sign
  function show(k) {
    const f = D.frames[k];
    lines.forEach((l, i) => {
      const [a, b] = D.segments[i];
      l.setAttribute('x1', f.p[a][0]); l.setAttribute('y1', f.p[a][1]);
      l.setAttribute('x2', f.p[b][0]); l.setAttribute('y2', f.p[b][1]);
    });
    blocks.forEach((r, i) => {
      const [p, key] = D.blocks[i];
      r.setAttribute('transform', `translate(${f.p[p][0]},${f.p[p][1]}) rotate(${f.a[key]})`);
    });
    for (const name in joints) {
      joints[name].setAttribute('cx', f.p[name][0]); joints[name].setAttribute('cy', f.p[name][1]);
      labels[name].setAttribute('x', f.p[name][0] + u); labels[name].setAttribute('y', -f.p[name][1] - u);
    }
    slider.value = k;
    svg.setAttribute('data-frame', k);
    readout.textContent = 'φ = ' + num(f.phi) + '°' + D.columns.map((c, i) => '   ' + c + ' = ' + num(Number(f.v[i].toPrecision(6)))).join('');
  }
  let k = 0, playing = true;
  const m = /#frame=(\d+)/.exec(location.hash);
  if (m) { k = Math.min(parseInt(m[1], 10), D.frames.length - 1); playing = false; }
  const button = document.getElementById('play');
  button.textContent = playing ? 'pause' : 'play';
  button.onclick = () => { playing = !playing; button.textContent = playing ? 'pause' : 'play'; };
  slider.oninput = () => { playing = false; button.textContent = 'play'; show(parseInt(slider.value, 10)); };
  show(k);
  let last = 0;
  function tick(t) {
    if (playing && t - last > 40) { k = (k + 1) % D.frames.length; show(k); last = t; }
    requestAnimationFrame(tick);
  }
  requestAnimationFrame(tick);
})();
"""

STYLE = """
body { font-family: "Noto Sans CJK SC", "Noto Sans", "DejaVu Sans", sans-serif; margin: 1em; color: #1a1a1a; }
svg { width: 100%; max-width: 900px; height: 70vh; border: 1px solid #d0d4d9; background: #fff; }
.link { stroke: #1a1a1a; stroke-width: 0.35%; stroke-linecap: round; vector-effect: non-scaling-stroke; }
.link { stroke-width: 3px; }
.guide { stroke: #8f959c; stroke-width: 1px; stroke-dasharray: 6 4; vector-effect: non-scaling-stroke; }
.trace { fill: none; stroke: #1c5fa8; stroke-width: 1.5px; vector-effect: non-scaling-stroke; }
.block { fill: #f1f3f5; stroke: #1a1a1a; stroke-width: 1.5px; vector-effect: non-scaling-stroke; }
.joint { fill: #fff; stroke: #1a1a1a; stroke-width: 1.5px; vector-effect: non-scaling-stroke; }
.ground { fill: #d0d4d9; stroke: #1a1a1a; stroke-width: 1px; vector-effect: non-scaling-stroke; }
.label { fill: #c92a2a; }
#readout { font-family: monospace; white-space: pre-wrap; margin: 0.5em 0; }
"""


def _warnings_html(r: CycleResult) -> list[str]:
    """The Warnings block under the heading, as the plots' sheets print it (English, then Chinese); none
    without warnings."""
    if not r.warnings:
        return []
    items = "".join(f"<li>{html.escape(plain_text(w))}</li>" for w in warning_lines(r.warnings, "both"))
    return [f'<div id="warnings" style="color: #c92a2a"><strong>Warnings  警告</strong><ul>{items}</ul></div>']


def animation_html(r: CycleResult) -> str:
    """The page (deterministic: the data is rounded as every number geomcon writes)."""
    data = json.dumps(scene_data(r), ensure_ascii=False, separators=(",", ":"), sort_keys=True)
    data = data.replace("</", "<\\/")
    title = html.escape(f"{r.problem.id}: {r.problem.title or 'whole cycle'}"
                        + (f"  {r.problem.title_zh}" if r.problem.title_zh else ""))
    return "\n".join([
        "<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">', f"<title>{title}</title>",
        f"<style>{STYLE}</style>", "</head>", "<body>", f"<h1>{title}</h1>", *_warnings_html(r),
        '<div><button id="play" type="button">pause</button> '
        '<input id="phi" type="range" min="0" value="0" step="1" aria-label="crank position"></div>',
        '<div id="readout"></div>', '<svg id="mech" xmlns="http://www.w3.org/2000/svg"></svg>',
        f'<script id="data" type="application/json">{data}</script>', f"<script>{SCRIPT}</script>",
        "</body>", "</html>", ""])
