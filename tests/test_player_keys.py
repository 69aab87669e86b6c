"""Issue 11, "Done when": the step player's keys and buttons work — driven in headless Chromium (Debian package
``chromium``). A probe script appended to a copy of the player presses the keys and clicks the buttons a teacher
uses and writes, after each, the step shown, the highest step drawn, the slider and the address; the page is
read back with ``--dump-dom``. Skipped, saying so, where no Chromium is installed."""
from __future__ import annotations

import html
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

PROBE = r"""<script>//<![CDATA[
(function () {
  var log = [];
  function note(what) {
    var mx = 0;
    document.querySelectorAll('#drawing [data-step]:not(.future)').forEach(function (e) {
      mx = Math.max(mx, parseInt(e.getAttribute('data-step'), 10)); });
    var k = /step (\d+) \//.exec(document.getElementById('count').textContent)[1];
    log.push([what, k, mx, document.getElementById('slider').value, location.hash].join('|'));
  }
  function key(k) { document.dispatchEvent(new KeyboardEvent('keydown', {key: k, bubbles: true, cancelable: true})); }
  function click(id) { document.getElementById(id).click(); }
  note('open');
  key('ArrowRight'); note('right'); key('ArrowDown'); note('down'); key('ArrowLeft'); note('left');
  key('End'); note('end'); key('ArrowRight'); note('right-at-end'); key('Home'); note('home'); key('ArrowUp'); note('up-at-1');
  click('next'); note('next'); click('last'); note('last'); click('prev'); note('prev'); click('first'); note('first');
  var s = document.getElementById('slider'); s.value = 5; s.dispatchEvent(new Event('input')); note('slider');
  click('first'); click('play'); note('play');
  setTimeout(function () {
    note('played'); key(' '); note('paused');
    setTimeout(function () {
      note('still'); var pre = document.createElement('pre'); pre.id = 'probe'; pre.textContent = log.join('\n');
      document.body.appendChild(pre); }, 2500);
  }, 2600);
})();
//]]></script>"""


@pytest.fixture(scope="module")
def log(tmp_path_factory) -> dict[str, tuple[int, int, int, str]]:
    page = solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml")).html()
    i = page.rindex("</body>")
    path = tmp_path_factory.mktemp("keys") / "001-08.html"
    path.write_text(page[:i] + PROBE + page[i:], encoding="utf-8")
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=20000",
                          "--dump-dom", path.as_uri()], capture_output=True, text=True, timeout=180)
    assert out.returncode == 0, out.stderr[-500:]
    found = re.search(r'<pre id="probe">(.*?)</pre>', out.stdout, re.S)
    assert found, "the probe did not finish"
    rows = {}
    for line in html.unescape(found.group(1)).splitlines():
        what, k, shown, slider, hash_ = line.split("|")
        rows[what] = (int(k), int(shown), int(slider), hash_)
    return rows


def test_keys_step_forward_back_and_to_the_ends(log):
    n = log["end"][0]
    assert n > 10
    assert [log[w][0] for w in ("open", "right", "down", "left", "end", "right-at-end", "home", "up-at-1")] == \
        [1, 2, 3, 2, n, n, 1, 1]


def test_buttons_and_slider_step(log):
    n = log["end"][0]
    assert [log[w][0] for w in ("next", "last", "prev", "first", "slider")] == [2, n, n - 1, 1, 5]


def test_play_advances_and_space_pauses(log):
    assert log["play"][0] == 1 and log["played"][0] >= 2          # one step each 1.2 s
    assert log["still"][0] == log["paused"][0]                   # nothing moves after the pause


def test_every_state_draws_exactly_the_steps_up_to_it_and_the_address_follows(log):
    for what, (k, shown, slider, hash_) in log.items():
        assert shown == k and slider == k, what
        if what != "open":
            assert hash_ == f"#step={k}", what
