"""A self-contained HTML step player: the full drawing inline, previous / next / play, a slider, the current
step's caption in English and Chinese. No network: no external script, style or font.

Examples
--------
>>> from geomcon.recipes.guide_bar import construct
>>> page = render_html(construct({"AB": 145.0, "AC": 290.0}).scene, title="demo")
>>> page.startswith("<!DOCTYPE html>") and "<script src" not in page
True
"""
from __future__ import annotations

import html
import json
from typing import Sequence

from ..scene import Scene
from .svg import render_svg

_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title>
<style>
body {{ font-family: "Noto Sans CJK SC", "Noto Sans", "DejaVu Sans", sans-serif; margin: 1em; color: #1a1a1a; }}
#bar {{ display: flex; gap: .6em; align-items: center; margin: .5em 0; }}
#bar button {{ font-size: 1em; padding: .2em .8em; }}
#caption {{ min-height: 3.2em; margin: .3em 0 .6em 0; }}
#caption .zh {{ color: #5c6370; }}
#drawing svg {{ max-width: 100%; height: auto; border: 1px solid #ddd; }}
.step.future, .protocol.future {{ display: none; }}
</style></head>
<body>
<h1 style="font-size:1.2em">{title}</h1>
<div id="bar"><button id="prev" title="previous step (←)">◀</button><button id="play" title="play (space)">▶ play</button>
<button id="next" title="next step (→)">▶</button><input id="slider" type="range" min="0" max="{n}" value="{n}">
<span id="count"></span></div>
<div id="caption"><div class="en"></div><div class="zh"></div></div>
<div id="drawing">{svg}</div>
<script>
const CAPTIONS = {captions};
const N = {n};
let k = N, timer = null;
function show(j) {{
  k = Math.max(0, Math.min(N, j));
  document.querySelectorAll("[data-step]").forEach(function (el) {{
    const s = parseInt(el.getAttribute("data-step"), 10);
    el.classList.toggle("future", s > k);
    el.classList.toggle("current", s === k);
  }});
  document.getElementById("slider").value = k;
  document.getElementById("count").textContent = "step " + k + " / " + N;
  const c = k > 0 ? CAPTIONS[k - 1] : ["", ""];
  document.querySelector("#caption .en").textContent = k > 0 ? k + ". " + c[0] : "";
  document.querySelector("#caption .zh").textContent = c[1];
}}
function play() {{
  if (timer) {{ clearInterval(timer); timer = null; document.getElementById("play").textContent = "▶ play"; return; }}
  if (k >= N) show(0);
  document.getElementById("play").textContent = "❚❚ pause";
  timer = setInterval(function () {{ if (k >= N) {{ play(); }} else {{ show(k + 1); }} }}, 1200);
}}
document.getElementById("prev").onclick = function () {{ show(k - 1); }};
document.getElementById("next").onclick = function () {{ show(k + 1); }};
document.getElementById("play").onclick = play;
document.getElementById("slider").oninput = function (e) {{ show(parseInt(e.target.value, 10)); }};
document.addEventListener("keydown", function (e) {{
  if (e.key === "ArrowLeft") show(k - 1);
  else if (e.key === "ArrowRight") show(k + 1);
  else if (e.key === " ") {{ e.preventDefault(); play(); }}
}});
show(N);
</script>
</body></html>
"""


def render_html(scene: Scene, *, title: str | None = None, info: Sequence[str] = ()) -> str:
    """The step player page of the whole scene."""
    svg = render_svg(scene, title=title, info=info)
    svg = svg[svg.index("<svg"):] if "<svg" in svg else svg
    frames = scene.frames()
    captions = [list(scene.caption(group[0].key)) for group in frames]
    return _PAGE.format(title=html.escape(title or scene.title), n=len(frames), svg=svg,
                        captions=json.dumps(captions, ensure_ascii=False).replace("</", "<\\/"))
