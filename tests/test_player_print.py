"""Printing the step player prints the whole construction — the sheets as ``geomcon solve`` writes them — at
whatever step it is opened (issue 11: a teacher who opened the player at step 1 and printed it got a sheet with
point A only). Printed to PDF by headless Chromium (Debian package ``chromium``), read back with ``pdftoppm`` and
``pdftotext`` (``poppler-utils``); skipped, saying so, where either is missing."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from geomcon.problems import load_problem
from geomcon.render.page import PageSpec
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
PDFTOPPM, PDFTOTEXT = shutil.which("pdftoppm"), shutil.which("pdftotext")
pytestmark = [pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)"),
              pytest.mark.skipif(PDFTOPPM is None or PDFTOTEXT is None,
                                 reason="pdftoppm / pdftotext not installed (apt-get install poppler-utils)")]


def _print(html: Path, fragment: str, pdf: Path) -> Path:
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-pdf-header-footer",
                          f"--print-to-pdf={pdf}", html.as_uri() + fragment], capture_output=True, text=True,
                         timeout=180)
    assert out.returncode == 0 and pdf.is_file(), out.stderr[-500:]
    return pdf


def _pages(pdf: Path) -> list[bytes]:
    """Every page of ``pdf`` in colour at 60 dpi (PPM bytes)."""
    stem = pdf.with_suffix("")
    subprocess.run([PDFTOPPM, "-r", "60", str(pdf), str(stem)], check=True, capture_output=True, timeout=180)
    return [p.read_bytes() for p in sorted(pdf.parent.glob(f"{stem.name}-*.ppm"))]


@pytest.fixture(scope="module")
def printed(tmp_path_factory) -> tuple[dict[str, Path], list[str], Path]:
    """001-08's player printed opened at step 1, at step 7 and at the last step, and its sheets printed from the
    same page without the player's script (nothing hidden or highlighted: the sheets as they are)."""
    tmp = tmp_path_factory.mktemp("player_print")
    sol = solve(load_problem(ROOT / "problems" / "001-08_crank_rocker.toml"))
    page = PageSpec("A4", "landscape", "en")
    sheets = sol.sheets(page)
    player = tmp / "player.html"
    player.write_text(sol.html(page, sheets), encoding="utf-8")
    plain = tmp / "sheets.html"
    text, n = re.subn(r"<script>.*?</script>", "", player.read_text(encoding="utf-8"), flags=re.S)
    assert n == 1
    plain.write_text(text, encoding="utf-8")
    pdfs = {f: _print(player, f, tmp / f"player{f.replace('#step=', '-')}.pdf") for f in ("", "#step=7", "#step=999")}
    pdfs["sheets"] = _print(plain, "", tmp / "sheets.pdf")
    return pdfs, sheets, tmp


def test_the_player_prints_the_sheets_at_any_step(printed):
    """Opened at step 1 (the address without a fragment), at step 7 or at the last step, the printed pages are
    those of the sheets themselves, pixel for pixel: every step drawn, none highlighted, no step caption."""
    pdfs, sheets, _ = printed
    reference = _pages(pdfs["sheets"])
    assert len(reference) == len(sheets) == 2
    for fragment in ("", "#step=7", "#step=999"):
        assert _pages(pdfs[fragment]) == reference, fragment or "opened at step 1"


def test_the_player_opened_at_step_1_prints_the_last_step_s_results(printed):
    """The printed text of the player as opened (step 1) holds what the last steps produce: every Results line
    (γmin is measured at the last step) and the labels of the last points drawn."""
    pdfs, sheets, tmp = printed
    text = subprocess.run([PDFTOTEXT, str(pdfs[""]), "-"], capture_output=True, text=True, check=True).stdout
    for line in ("γmin = 29.995°", "ψ = 77.886°", "K = 1.149", "γ2=42.18°", "B′′", "C′′"):
        assert line in text, line
    assert "1. Fixed pivot A" not in text.split("Construction protocol")[0]   # no step caption on sheet 1
