"""``sheets.html`` (and ``key.html``) printed to PDF in headless Chromium (Debian package ``chromium``): one sheet of paper per page
(one page per student for a one-exercise spec), A4 at its size, and the true scale measured in the printed
page (the drawing frame's width, 180 mm on A4 portrait, found in a 254 dpi rendering by ``pdftoppm``). Skipped,
saying so, where no Chromium is installed (``apt-get install chromium``)."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from geomcon.worksheet import make_worksheet
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.spec import load_spec, parse_spec

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
PDFTOPPM = shutil.which("pdftoppm")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")

ONE = '''
title = "Design by K"
[[exercise]]
recipe = "crank_rocker.design_by_K"
ask = ["AB", "AD"]
[exercise.given]
K = [1.25, 1.4, 1.5]
CD = {min = 60, max = 120, step = 5}
psi = 40
BC = {min = 50, max = 150, step = 5}
'''


def _print(files: dict[str, str], out: Path, name: str = "sheets") -> bytes:
    page = out / f"{name}.html"
    page.write_text(files[f"{name}.html"], encoding="utf-8")
    pdf = out / f"{name}.pdf"
    run = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-pdf-header-footer",
                          f"--print-to-pdf={pdf}", page.as_uri()], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0 and pdf.is_file(), run.stderr[-500:]
    return pdf.read_bytes()


def _pages(pdf: bytes) -> int:
    return len(re.findall(rb"/Type\s*/Page(?![s\w])", pdf))


def _a4(pdf: bytes) -> None:
    for box in re.findall(rb"/MediaBox\s*\[([^\]]*)\]", pdf):
        x0, y0, x1, y1 = (float(v) for v in box.split())
        w, h = sorted(((x1 - x0) * 25.4 / 72, (y1 - y0) * 25.4 / 72))
        assert w == pytest.approx(210.0, abs=0.5) and h == pytest.approx(297.0, abs=0.5)


def test_one_page_per_student_at_a4_and_true_scale(tmp_path):
    w = make_worksheet(parse_spec(ONE), numbered(5), lang="en")
    pdf = _print(w.files, tmp_path)
    assert _pages(pdf) == 5 == w.files["sheets.html"].count('<section class="sheet')
    _a4(pdf)
    if PDFTOPPM is None:
        pytest.skip("pdftoppm (poppler-utils) not installed: the printed scale is not measured")
    subprocess.run([PDFTOPPM, "-gray", "-r", "254", "-f", "1", "-l", "1", str(tmp_path / "sheets.pdf"),
                    str(tmp_path / "p")], check=True, timeout=120)
    pgm = next(tmp_path.glob("p*.pgm")).read_bytes()
    m = re.match(rb"P5\s+(\d+)\s+(\d+)\s+(\d+)\s", pgm)
    width, height = int(m.group(1)), int(m.group(2))
    img = np.frombuffer(pgm[m.end():m.end() + width * height], dtype=np.uint8).reshape(height, width)
    dark = (img < 128).mean(axis=0)                # share of dark pixels in each column
    cols = np.flatnonzero(dark > 0.8)              # the frame's two vertical sides (10 px per mm)
    assert cols.size >= 2
    left, right = cols.min(), cols.max()
    assert left / 10 == pytest.approx(20.0, abs=0.5)
    assert (right - left) / 10 == pytest.approx(180.0, abs=0.5)      # true scale: the frame is 180 mm wide


def test_the_sample_class_prints_every_page(tmp_path):
    w = make_worksheet(load_spec(ROOT / "tests" / "data" / "worksheet_class.toml"), numbered(3))
    pdf = _print(w.files, tmp_path)
    sheets = sum(1 for n in w.files if n.startswith("sheets/"))
    assert _pages(pdf) == sheets == w.files["sheets.html"].count('<section class="sheet')
    _a4(pdf)
    keys = _print(w.files, tmp_path, "key")
    assert _pages(keys) == sum(1 for n in w.files if n.startswith("key/")) == 9
    _a4(keys)
