"""The step player driven in headless Chromium (Debian package ``chromium``): it opens at step 1, ``#step=N``
opens at N, and what is shown is exactly the steps up to the current one. Skipped, saying so, where no Chromium
is installed (``apt-get install chromium``)."""
from __future__ import annotations

import html
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.render.svg import frame_of
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")


def _dom(page: Path, fragment: str = "") -> str:
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom",
                          page.as_uri() + fragment], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-500:]
    return out.stdout


def _shown(dom: str) -> tuple[int, int, set[int]]:
    """(current step, steps, the data-step numbers of drawing elements not hidden as future)."""
    k, n = map(int, re.search(r'id="count">step (\d+) / (\d+)<', dom).groups())
    drawing = dom[dom.index('id="drawing"'):]
    shown = set()
    for tag in re.finditer(r"<g\b[^>]*>", drawing):
        attrs = tag.group(0)
        step = re.search(r'data-step="(\d+)"', attrs)
        if step and "future" not in (re.search(r'class="([^"]*)"', attrs) or [None, ""])[1]:
            shown.add(int(step.group(1)))
    return k, n, shown


@pytest.fixture(scope="module")
def page(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("player") / "001-08.html"
    path.write_text(solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml")).html(), encoding="utf-8")
    return path


def test_the_player_opens_at_step_1(page):
    k, n, shown = _shown(_dom(page))
    assert k == 1 and n > 10 and shown and max(shown) == 1


def test_a_step_fragment_opens_at_that_step_and_is_clamped(page):
    k, n, shown = _shown(_dom(page, "#step=3"))
    assert k == 3 and max(shown) == 3 and {1, 2, 3} <= shown
    k, n, shown = _shown(_dom(page, "#step=999"))
    assert k == n and max(shown) == n


def _states(markup: str) -> list[tuple[int, bool, bool]]:
    out = []
    for tag in re.finditer(r"<[a-z]+\b[^>]*\bdata-step=\"(\d+)\"[^>]*>", markup):
        cls = re.search(r'class="([^"]*)"', tag.group(0))
        words = cls.group(1).split() if cls else []
        out.append((int(tag.group(1)), "future" in words, "current" in words))
    return out


def test_the_player_s_frame_k_is_the_steps_frame_k(page):
    """Issue 11: one rendering path — the elements shown, hidden and highlighted at player step k are those of
    `geomcon solve --steps` frame k."""
    sol = solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml"))
    frames = sol.frames()
    for k in (1, 7, 14, len(frames)):
        dom = _dom(page, f"#step={k}")
        drawing = dom[dom.index('id="page-1"'):dom.index('id="page-2"')]      # sheet 1: the drawing
        frame = frames[k - 1]
        assert _states(drawing) == _states(frame[frame.index("<svg"):]), k


_HARNESS = """<!DOCTYPE html><html><body><pre id="out"></pre>%s
<script>
window.addEventListener("load", function () {
  var out = [];
  Array.prototype.forEach.call(document.querySelectorAll("iframe"), function (f) {
    var s = [];
    f.contentDocument.querySelectorAll("#page-1 [data-step]").forEach(function (e) {
      s.push(e.getAttribute("data-step") + (e.classList.contains("future") ? "f" : "")
             + (e.classList.contains("current") ? "c" : ""));
    });
    out.push(f.getAttribute("src") + " " + s.join(","));
  });
  document.getElementById("out").textContent = out.join("\\n");
});
</script></body></html>"""


def _player_states(tmp: Path, jobs: list[tuple[str, int]]) -> dict[tuple[str, int], list[str]]:
    """The (data-step, future?, current?) of every element of sheet 1 in the gallery player ``pid`` at ``#step=k``,
    for every (pid, k) of ``jobs``, read in one headless Chromium (the players in iframes of a harness page)."""
    for pid, _ in jobs:
        if not (tmp / f"{pid}.html").exists():
            (tmp / f"{pid}.html").write_text((ROOT / "gallery" / f"{pid}.html").read_text(encoding="utf-8"),
                                             encoding="utf-8")
    frames = "".join(f'<iframe src="{pid}.html#step={k}"></iframe>' for pid, k in jobs)
    harness = tmp / "harness.html"
    harness.write_text(_HARNESS % frames, encoding="utf-8")
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--allow-file-access-from-files",
                          "--dump-dom", harness.as_uri()], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-500:]
    text = html.unescape(re.search(r'<pre id="out">(.*?)</pre>', out.stdout, re.S).group(1))
    states = {}
    for line in text.splitlines():
        src, _, items = line.partition(" ")
        pid, k = src.split(".html#step=")
        states[(pid, int(k))] = items.split(",") if items else []
    return states


def _frame_states(frame: str) -> list[str]:
    return [f"{n}{'f' if fut else ''}{'c' if cur else ''}" for n, fut, cur in _states(frame[frame.index("<svg"):])]


def test_every_gallery_player_s_frame_k_is_its_steps_frame_k(tmp_path):
    """Issue 11's "frame k of the player equals --steps frame k", for every gallery player (cams included) at
    steps 1, the middle one and the last: what the player shows, hides and highlights on sheet 1 (figure,
    step caption, Results and Warnings lines) is what ``geomcon solve --steps`` frame k shows (``Solution.frames``:
    :func:`~geomcon.render.svg.frame_of` of sheet 1, the gallery's sheet)."""
    players = sorted(p.stem for p in (ROOT / "gallery").glob("*.html")
                     if (ROOT / "gallery" / f"{p.stem}.svg").exists())
    sheets = {pid: (ROOT / "gallery" / f"{pid}.svg").read_text(encoding="utf-8") for pid in players}
    jobs = []
    for pid in players:
        n = max(int(s) for s in re.findall(r'data-step="(\d+)"', sheets[pid]))
        jobs += [(pid, k) for k in sorted({1, (n + 1) // 2, n})]
    assert len(players) >= 90
    states: dict[tuple[str, int], list[str]] = {}
    for i in range(0, len(jobs), 60):
        states.update(_player_states(tmp_path, jobs[i:i + 60]))
    for pid, k in jobs:
        assert states[(pid, k)] == _frame_states(frame_of(sheets[pid], k)), (pid, k)
