"""A self-contained HTML step player: the full drawing inline, first / previous / play / next / last buttons,
keyboard arrows, a slider and the current step's number. The current step's caption, in English and Chinese,
is the one on the sheet (as in ``geomcon solve --steps`` frame k): the page prints it once, not again above
the drawing (the slider reads it to a screen reader). It opens at step 1, or at step N when the address ends
in ``#step=N`` (the address follows the steps shown, so a step can be linked to).

The replay is pure CSS: every step group and protocol entry carries ``data-step``; the script only sets
the classes ``future`` (hidden) and ``current`` (highlighted) by comparing it with the current step. No
network: no external script, style sheet or font. Printed, the page is the sheets as they are (every step, none
highlighted), whatever step is shown (:data:`_PRINT_CSS`). The page is polyglot markup: it parses as HTML and as XML
(void elements closed, the script in a CDATA section), so any XML tool can read it.

Examples
--------
>>> from geomcon.recipes.crank_rocker import construct
>>> page = render_html(construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene, title="demo")
>>> page.startswith("<!DOCTYPE html>") and "<script src" not in page and "<link" not in page
True
>>> import xml.etree.ElementTree as ET
>>> ET.fromstring(page).tag
'{http://www.w3.org/1999/xhtml}html'
"""
from __future__ import annotations

import html
import json
from typing import Sequence

from ..scene import Scene
from .labels import rich_runs
from .page import PageSpec, print_css, zh_punct
from .serial import typeset
from .shapes import stacked_runs
from .style import FONT_FAMILY
from .svg import render_sheets

_CSS = """
body { font-family: %(font)s; margin: 1em 1.5em; color: #1a1a1a; background: #fafafa; }
#bar { display: flex; gap: .4em; align-items: center; flex-wrap: wrap; margin: .4em 0; }
#bar button { font: inherit; padding: .15em .7em; min-width: 2.4em; cursor: pointer; }
#slider { flex: 1 1 16em; max-width: 40em; }
#count { font-variant-numeric: tabular-nums; min-width: 6em; }
#drawing { background: #fff; border: 1px solid #ddd; overflow: auto; }
#drawing svg { display: block; width: 100%%; height: auto; max-height: calc(100vh - 4.5em); margin: 0 auto; }
#drawing .page + .page { border-top: 1px solid #ddd; }
.future { display: none; }
"""

_PRINT_CSS = """
@media print {
  #drawing .future { display: revert-layer; }
  #drawing .current .ink { stroke: revert-layer; }
  #drawing .current .dot, #drawing .current text { fill: revert-layer; }
  #drawing text.stepcap { display: none; }
}
"""
"""Printing the player prints the sheets as they are (``geomcon solve`` writes them), whatever step is shown:
every step drawn, nothing highlighted, no step caption — a teacher who prints the player opened at step 1
gets the whole construction, not point A. ``revert-layer`` undoes the replay rules of :data:`~.style.CSS`
(the step's classes stay; the drawing's own presentation attributes come back)."""

_SCRIPT = """
(function () {
  "use strict";
  var STEPS = %(steps)s;
  var N = STEPS.length;
  var k = 1, timer = null;
  if (N === 0) return;
  var items = Array.prototype.slice.call(document.querySelectorAll("#drawing [data-step]"));
  function $(id) { return document.getElementById(id); }
  function fromHash() {
    var m = /(?:^#|&)step=(\\d+)/.exec(window.location.hash);
    return m ? parseInt(m[1], 10) : 1;
  }
  function show(j, keepUrl) {
    k = Math.max(1, Math.min(N, j));
    if (!keepUrl && window.history && window.history.replaceState) {
      try { window.history.replaceState(null, "", "#step=" + k); } catch (err) { /* a page without a URL */ }
    }
    items.forEach(function (el) {
      var s = parseInt(el.getAttribute("data-step"), 10);
      el.classList.toggle("future", s > k);
      el.classList.toggle("current", s === k);
    });
    $("slider").value = k;
    $("count").textContent = "step " + k + " / " + N;
    var c = STEPS[k - 1];
    var plain = document.createElement("span");
    plain.innerHTML = k + ". " + c[0] + (c[1] ? " " + c[1] : "");
    $("slider").setAttribute("aria-valuetext", plain.textContent);
  }
  function stop() {
    if (timer) { clearInterval(timer); timer = null; }
    $("play").textContent = "\\u25B6 play";
  }
  function play() {
    if (timer) { stop(); return; }
    if (k >= N) show(1);
    $("play").textContent = "\\u275A\\u275A pause";
    timer = setInterval(function () { if (k >= N) stop(); else show(k + 1); }, 1200);
  }
  $("first").onclick = function () { stop(); show(1); };
  $("prev").onclick = function () { stop(); show(k - 1); };
  $("next").onclick = function () { stop(); show(k + 1); };
  $("last").onclick = function () { stop(); show(N); };
  $("play").onclick = play;
  $("slider").oninput = function (e) { stop(); show(parseInt(e.target.value, 10)); };
  document.addEventListener("keydown", function (e) {
    if (e.target && e.target.tagName === "INPUT" && e.key !== " ") return;
    if (e.key === "ArrowLeft" || e.key === "ArrowUp") { stop(); show(k - 1); e.preventDefault(); }
    else if (e.key === "ArrowRight" || e.key === "ArrowDown") { stop(); show(k + 1); e.preventDefault(); }
    else if (e.key === "Home") { stop(); show(1); e.preventDefault(); }
    else if (e.key === "End") { stop(); show(N); e.preventDefault(); }
    else if (e.key === " ") { play(); e.preventDefault(); }
  });
  window.addEventListener("hashchange", function () { stop(); show(fromHash(), true); });
  show(fromHash(), true);
})();
"""

_PAGE = """<!DOCTYPE html>
<html lang="%(lang)s" xmlns="http://www.w3.org/1999/xhtml">
<head>
<meta charset="utf-8" />
<meta name="viewport" content="width=device-width, initial-scale=1" />
<title>%(title)s</title>
<style>%(css)s%(print)s%(replay_print)s</style>
</head>
<body>
<div id="bar">
<button id="first" type="button" title="first step (Home)">|\u25C0</button>
<button id="prev" type="button" title="previous step (\u2190)">\u25C0</button>
<button id="play" type="button" title="play / pause (space)">\u25B6 play</button>
<button id="next" type="button" title="next step (\u2192)">\u25B6</button>
<button id="last" type="button" title="last step (End)">\u25B6|</button>
<input id="slider" type="range" min="1" max="%(n)d" value="%(n)d" aria-label="step" />
<span id="count">step %(n)d / %(n)d</span>
</div>
<div id="drawing">
%(svg)s
</div>
<script>//<![CDATA[
%(script)s
//]]></script>
</body>
</html>
"""


def caption_html(text: str) -> str:
    """A caption as the player's slider reads it out (its caption is the sheet's): escaped, subscripts as ``<sub>``, and a component's
    letter stacked over its subscript as the figure stacks it (:func:`~.shapes.stacked_runs`).

    >>> caption_html("Join AC2")
    'Join AC<sub>2</sub>'
    >>> caption_html("aʳB2B3 < 1")
    'a<span class="stack"><span>r</span><span>B2B3</span></span> &lt; 1'
    """
    runs = stacked_runs(rich_runs(typeset(text)), 1.0)
    out, i = [], 0
    while i < len(runs):
        s, sub, sup, _ = runs[i]
        nxt = runs[i + 1] if i + 1 < len(runs) else None
        if nxt is not None and (sup and nxt[1] or sub and nxt[2]):
            top, low = (s, nxt[0]) if sup else (nxt[0], s)
            out.append(f'<span class="stack"><span>{html.escape(top)}</span><span>{html.escape(low)}</span></span>')
            i += 2
            continue
        out.append(f"<sub>{html.escape(s)}</sub>" if sub else f"<sup>{html.escape(s)}</sup>" if sup else html.escape(s))
        i += 1
    return "".join(out)


def step_captions(scene: Scene, lang: str = "both") -> list[tuple[str, str]]:
    """The caption of every numbered step, in protocol order (branch rules included), as the player's slider
    reads it out: (English, Chinese) for ``both``, (English, "") for ``en``, (Chinese, "") for ``zh``."""
    out = []
    for group in scene.frames():
        en, zh = scene.caption(group[0].key)
        zh = zh_punct(zh) if zh else zh
        out.append((en, zh) if lang == "both" else (en, "") if lang == "en" else (zh or en, ""))
    return out


def render_html(scene: Scene, *, title: str | None = None, info: Sequence[str] = (),
                svg: str | Sequence[str] | None = None, warnings: Sequence[str] = (),
                info_steps: Sequence[int] | None = None, page: PageSpec = PageSpec(), problem: str = "",
                recipe: str = "") -> str:
    """The step player page of the whole scene: every sheet, one under the other on screen, one per printed
    page at 100 % (CSS ``@page`` of the sheet's paper and orientation).

    Parameters
    ----------
    scene : Scene
        The construction (every step is evaluated).
    title : str or None
        Page and drawing title (default: the scene's title).
    info : sequence of str
        Result lines.
    warnings, info_steps, page, problem, recipe
        As :func:`~geomcon.render.svg.render_sheets` takes them.
    svg : str, sequence of str, or None
        The sheets, when they are rendered already: ``render_sheets(scene, title=title, info=info, …)`` (the
        page embeds exactly those documents; passing them saves drawing the scene twice).

    Returns
    -------
    str
        One self-contained HTML document.

    Examples
    --------
    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> render_html(sc, svg=render_sheets(sc)) == render_html(sc)
    True
    """
    if svg is None:
        svg = render_sheets(scene, title=title, info=info, warnings=warnings, info_steps=info_steps, page=page,
                            problem=problem, recipe=recipe)
    sheets = [svg] if isinstance(svg, str) else list(svg)
    body = "\n".join(f'<div class="page" id="page-{i}">{s[s.index("<svg"):]}</div>' for i, s in enumerate(sheets, 1))
    steps = json.dumps([[caption_html(s) for s in c] for c in step_captions(scene, page.lang)], ensure_ascii=False).replace("</", "<\\/").replace("]]>", "]]\\u003e")
    css = _CSS % {"font": ", ".join(f'"{f.strip()}"' if " " in f.strip() else f.strip()
                                    for f in FONT_FAMILY.split(","))}
    return _PAGE % {"title": html.escape(typeset((title or scene.title).replace("\n", "  "))), "css": css, "print": print_css(page), "replay_print": _PRINT_CSS,
                    "lang": "zh-Hans" if page.lang == "zh" else "en", "n": len(scene.frames()), "svg": body,
                    "script": _SCRIPT % {"steps": steps}}
