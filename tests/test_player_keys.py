"""The step player's keys and buttons, pressed in headless Chromium (Debian package ``chromium``): → ↓ ← ↑ Home
End, the buttons first / previous / next / last, the slider, play / pause (button and space bar) and the address
fragment. After every action the shown step, the counter, the slider, the address (``#step=k``) and the
drawing (steps ≤ k shown, > k hidden, k highlighted) agree. A probe script is put into the page and the result
read with ``--dump-dom``; timers run on Chromium's virtual clock (``--virtual-time-budget``), so play's 1.2 s
per step takes no real time. Skipped, saying so, where no Chromium is installed."""
from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")

_PROBE = r"""<script>//<![CDATA[
(function () {
  var log = [];
  function state(what) {
    var k = parseInt(/step (\d+) \//.exec(document.getElementById("count").textContent)[1], 10), agree = true;
    document.querySelectorAll("#drawing [data-step]").forEach(function (e) {
      var s = parseInt(e.getAttribute("data-step"), 10);
      if (e.classList.contains("future") !== (s > k) || e.classList.contains("current") !== (s === k)) agree = false;
    });
    log.push({what: what, k: k, hash: location.hash, slider: parseInt(document.getElementById("slider").value, 10),
              drawing: agree, play: document.getElementById("play").textContent});
  }
  function key(k, target) {
    (target || document).dispatchEvent(new KeyboardEvent("keydown", {key: k, bubbles: true, cancelable: true}));
    state(k);
  }
  function click(id) { document.getElementById(id).click(); state(id); }
  window.addEventListener("load", function () {
    state("open");
    key("ArrowRight"); key("ArrowDown"); key("ArrowLeft"); key("ArrowUp"); key("ArrowUp");
    key("End"); key("ArrowRight"); key("Home"); key("ArrowLeft");
    click("next"); click("next"); click("prev"); click("last"); click("next"); click("prev"); click("first"); click("prev");
    var s = document.getElementById("slider");
    s.value = 5; s.dispatchEvent(new Event("input", {bubbles: true})); state("slider");
    key("ArrowRight", s);                                  /* the slider moves itself: the page ignores it */
    location.hash = "#step=7";
    setTimeout(function () {
      state("hash");
      click("play");
      setTimeout(function () {
        state("played 2.6 s"); key(" ");
        setTimeout(function () {
          state("paused 3 s"); click("last"); click("play");
          setTimeout(function () {
            state("played 1.3 s from the last");
            var pre = document.createElement("pre"); pre.id = "log"; pre.textContent = JSON.stringify(log);
            document.body.appendChild(pre);
          }, 1300);
        }, 3000);
      }, 2600);
    }, 50);
  });
})();
//]]></script>"""


@pytest.fixture(scope="module")
def log(tmp_path_factory) -> list[dict]:
    page = solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml")).html()
    i = page.rindex("</body>")
    path = tmp_path_factory.mktemp("keys") / "001-08.html"
    path.write_text(page[:i] + _PROBE + page[i:], encoding="utf-8")
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=20000",
                          "--dump-dom", path.as_uri()], capture_output=True, text=True, timeout=180)
    assert out.returncode == 0, out.stderr[-500:]
    found = re.search(r'<pre id="log">(.*?)</pre>', out.stdout, re.S)
    assert found, out.stdout[-500:]
    return json.loads(html.unescape(found.group(1)))


def test_every_key_and_button_moves_to_its_step(log):
    n = len(solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml")).frames())
    expected = [("open", 1), ("ArrowRight", 2), ("ArrowDown", 3), ("ArrowLeft", 2), ("ArrowUp", 1),
                ("ArrowUp", 1), ("End", n), ("ArrowRight", n), ("Home", 1), ("ArrowLeft", 1),
                ("next", 2), ("next", 3), ("prev", 2), ("last", n), ("next", n), ("prev", n - 1), ("first", 1),
                ("prev", 1), ("slider", 5), ("ArrowRight", 5), ("hash", 7), ("play", 7),
                ("played 2.6 s", 9), (" ", 9), ("paused 3 s", 9), ("last", n), ("play", 1),
                ("played 1.3 s from the last", 2)]
    assert n > 10
    assert [(e["what"], e["k"]) for e in log] == expected


def test_the_counter_slider_address_and_drawing_follow_the_step(log):
    """The address is ``#step=k`` once a step was chosen (opened without a fragment, it stays bare)."""
    for e in log:
        assert e["slider"] == e["k"] and e["drawing"], e
        assert e["hash"] == ("" if e["what"] == "open" else f"#step={e['k']}"), e


def test_play_and_pause_name_themselves(log):
    """The play button reads ⏸ pause while playing and ▶ play when stopped (by space, a step key or the end)."""
    playing = {e["what"]: "pause" in e["play"] for e in log}
    assert playing["played 2.6 s"] and playing["played 1.3 s from the last"]
    assert not playing[" "] and not playing["paused 3 s"] and not playing["open"]
