"""On screen the step player shows a whole sheet in the browser's window — a portrait sheet (200-01, printed on A4
portrait since its cam draws at 1:1 there) as well as a landscape one — so a class stepping through the
construction sees the drawing and its title block without scrolling; printed, the sheets keep their paper size
(``tests/test_print_pdf.py``). Measured in headless Chromium (Debian package ``chromium``): the page's own
layout, read back by a probe script added to a copy; skipped, saying so, without it."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")
PROBE = ('<script>window.addEventListener("load", function () {'
         ' var r = document.querySelector("#drawing svg").getBoundingClientRect();'
         ' document.body.setAttribute("data-probe", [r.top, r.bottom, r.width, window.innerHeight].join(","));'
         ' });</script>')


def _first_sheet_box(html: Path, tmp: Path, size: str) -> tuple[float, float, float, float]:
    """Top, bottom and width (CSS px) of the player's first sheet and the window's inner height."""
    copy = tmp / html.name
    copy.write_text(html.read_text(encoding="utf-8").replace("</body>", PROBE + "</body>"), encoding="utf-8")
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", f"--window-size={size}",
                          "--virtual-time-budget=3000", "--dump-dom", copy.as_uri()], capture_output=True, text=True,
                         timeout=180)
    m = re.search(r'data-probe="([^"]+)"', out.stdout)
    assert m, out.stderr[-500:]
    top, bottom, width, inner = (float(v) for v in m.group(1).split(","))
    return top, bottom, width, inner


@pytest.mark.parametrize("stem", ["200-01_cam_roller_offset", "001-08_crank_rocker"])
@pytest.mark.parametrize("size", ["1200,1000", "1600,900"])
def test_the_first_sheet_fits_the_window(stem, size, tmp_path):
    top, bottom, width, inner = _first_sheet_box(ROOT / "gallery" / f"{stem}.html", tmp_path, size)
    assert top > 0 and bottom <= inner, (top, bottom, inner)
    assert width > 500                           # not shrunk to a thumbnail
