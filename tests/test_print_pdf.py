"""A figure printed to PDF by headless Chromium (Debian package ``chromium``) is an A4 landscape page per sheet,
and a length measured on the printed page — the drawing frame, the scale bar — is what the sheet states,
within 0.2 mm. The page is rasterised with ``pdftoppm`` (Debian package ``poppler-utils``). Skipped, saying
so, where either is missing."""
from __future__ import annotations

import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from geomcon.gallery import problem_sheets
from geomcon.problems import load_problem
from geomcon.render.page import PageSpec
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
PDFTOPPM = shutil.which("pdftoppm")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")
SVG = "{http://www.w3.org/2000/svg}"
PT = 25.4 / 72          # mm per PDF point
DPI = 600
TOL = 0.2               # mm on paper


def _print(tmp: Path, page: PageSpec | None, problem: str = "001-08_crank_rocker") -> tuple[Path, list[str]]:
    """The player page of ``problem`` on ``page`` (None: the gallery's, :func:`geomcon.gallery.problem_sheets`)
    printed to PDF, and its sheets."""
    sol = solve(load_problem(ROOT / "problems" / f"{problem}.toml"))
    if page is None:
        page, sheets = problem_sheets(sol)
    else:
        sheets = sol.sheets(page)
    html = tmp / f"{problem}.html"
    html.write_text(sol.html(page, sheets), encoding="utf-8")
    pdf = tmp / f"{problem}.pdf"
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-pdf-header-footer",
                          f"--print-to-pdf={pdf}", html.as_uri() + "#step=999"], capture_output=True, text=True,
                         timeout=180)
    assert out.returncode == 0 and pdf.is_file(), out.stderr[-500:]
    return pdf, sheets


@pytest.fixture(scope="module")
def printed(tmp_path_factory) -> tuple[Path, list[str]]:
    return _print(tmp_path_factory.mktemp("pdf"), PageSpec("A4", "landscape", "en"))


def _media_boxes(pdf: Path) -> list[tuple[float, float]]:
    data = pdf.read_bytes()
    boxes = re.findall(rb"/MediaBox\s*\[\s*([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s*\]", data)
    return [((float(x1) - float(x0)) * PT, (float(y1) - float(y0)) * PT) for x0, y0, x1, y1 in boxes]


def test_every_printed_page_is_a4_landscape_one_per_sheet(printed):
    pdf, sheets = printed
    boxes = _media_boxes(pdf)
    assert len(boxes) == len(sheets) == 2, boxes
    for w, h in boxes:
        assert abs(w - 297.0) <= TOL and abs(h - 210.0) <= TOL, (w, h)


def _raster(pdf: Path, tmp: Path, page: int = 1) -> np.ndarray:
    """Page ``page`` in grey at :data:`DPI` (a binary PGM from pdftoppm)."""
    stem = tmp / f"page{page}"
    subprocess.run([PDFTOPPM, "-gray", "-r", str(DPI), "-f", str(page), "-l", str(page), "-singlefile", str(pdf), str(stem)],
                   check=True, capture_output=True, timeout=180)
    data = stem.with_suffix(".pgm").read_bytes()
    m = re.match(rb"P5\s+(\d+)\s+(\d+)\s+(\d+)\s", data)
    w, h = int(m.group(1)), int(m.group(2))
    return np.frombuffer(data[m.end():m.end() + w * h], dtype=np.uint8).reshape(h, w)


def _dark_extent(img: np.ndarray, y_mm: float, x0_mm: float, x1_mm: float) -> tuple[float, float]:
    """First and last dark pixel (mm) on the row at ``y_mm`` between ``x0_mm`` and ``x1_mm``."""
    px = DPI / 25.4
    row = img[int(round(y_mm * px)), int(x0_mm * px):int(x1_mm * px)]
    dark = np.nonzero(row < 128)[0]
    assert dark.size, (y_mm, x0_mm, x1_mm)
    return x0_mm + dark[0] / px, x0_mm + (dark[-1] + 1) / px


@pytest.mark.skipif(PDFTOPPM is None, reason="pdftoppm not installed (apt-get install poppler-utils)")
def test_a_length_measured_on_the_printed_page_is_the_stated_one(printed, tmp_path):
    """The drawing frame (267 mm between its lines' centres, 0.7 mm lines) and the scale bar (its stated length
    × the scale, 0.3 mm end ticks) measured on the page rendered at 600 dpi."""
    pdf, sheets = printed
    img = _raster(pdf, tmp_path)
    assert abs(img.shape[1] / DPI * 25.4 - 297.0) <= TOL
    left, right = _dark_extent(img, 105.0, 5.0, 292.0)          # outermost ink across the middle: the frame
    assert abs(left - (20.0 - 0.35)) <= TOL and abs(right - (287.0 + 0.35)) <= TOL, (left, right)
    _check_scale_bar(img, sheets[0])


def _check_scale_bar(img: np.ndarray, sheet: str) -> float:
    """The scale bar of ``sheet`` measured on its printed page is its stated length × the stated scale; returns
    the scale factor (paper / real)."""
    root = ET.fromstring(sheet)
    bar = root.find(f".//{SVG}g[@id='scale']")
    x0, y, x1 = map(float, re.match(r"M([\d.]+) ([\d.]+)H([\d.]+)", bar.find(f"{SVG}path").get("d")).groups())
    stated = float(re.search(r">([\d.]+) mm<", ET.tostring(bar, encoding="unicode")).group(1))
    scale = re.search(r">(\d+(?:\.\d+)?):(\d+(?:\.\d+)?)\s", ET.tostring(bar, encoding="unicode"))
    factor = float(scale.group(1)) / float(scale.group(2))
    a, b = _dark_extent(img, y, x0 - 3.0, x1 + 3.0)
    assert abs((b - a - 0.3) - stated * factor) <= TOL, (b - a - 0.3, stated * factor)
    assert abs(a - (x0 - 0.15)) <= TOL                           # and where the sheet puts it
    assert f"{scale.group(1)}:{scale.group(2)}" in re.sub(r"<[^>]+>", " ", ET.tostring(
        root.find(f".//{SVG}g[@id='title-block']"), encoding="unicode"))   # the title block states the same scale
    return factor


def _dark_run(img: np.ndarray, x_mm: float, y0_mm: float, y1_mm: float) -> float:
    """The centre (mm) of the dark pixels in the column at ``x_mm`` between ``y0_mm`` and ``y1_mm``."""
    px = DPI / 25.4
    col = img[int(y0_mm * px):int(y1_mm * px), int(round(x_mm * px))]
    dark = np.nonzero(col < 160)[0]
    assert dark.size, (x_mm, y0_mm, y1_mm)
    return y0_mm + (dark[0] + dark[-1] + 1) / 2 / px


@pytest.mark.skipif(PDFTOPPM is None, reason="pdftoppm not installed (apt-get install poppler-utils)")
def test_a_cam_is_printed_at_a_scale_to_construct_on(tmp_path):
    """200-01 (r0 = 40 mm) as the gallery prints it, on A4 portrait: the cam alone on sheet 1 at 1:1 — its base
    circle measured on the printed page is 80.0 mm across (it was 40 mm at 1:2 on landscape) — and the s–δ
    diagram on sheet 2 at its own stated scale, whose scale bar measures true."""
    pdf, sheets = _print(tmp_path, None, "200-01_cam_roller_offset")
    boxes = _media_boxes(pdf)
    assert len(boxes) == len(sheets) >= 3 and all(abs(w - 210.0) <= TOL and abs(h - 297.0) <= TOL for w, h in boxes)
    one = _raster(pdf, tmp_path, 1)
    assert _check_scale_bar(one, sheets[0]) == 1.0
    circle = ET.fromstring(sheets[0]).find(f".//{SVG}g[@id='step-base_circle']/{SVG}circle")
    cx, cy, r = (float(circle.get(k)) for k in ("cx", "cy", "r"))
    assert r == 40.0                                             # r0 = 40 mm drawn as 40 mm
    x = cx - 0.3 * r                                             # a chord clear of O's ground symbol and the axes
    half = r * (1 - 0.09) ** 0.5
    top, bottom = _dark_run(one, x, cy - half - 1.0, cy - half + 1.0), _dark_run(one, x, cy + half - 1.0, cy + half + 1.0)
    assert abs((bottom - top) - 2 * half) <= TOL, (bottom - top, 2 * half)
    assert "diagram-head" in sheets[1] and "step-sd_curve" in sheets[1] and "step-sd_curve" not in sheets[0]
    assert _check_scale_bar(_raster(pdf, tmp_path, 2), sheets[1]) == 0.5
