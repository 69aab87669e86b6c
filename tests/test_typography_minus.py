"""Issue 11: a negative number prints with a minus sign on sheets and players, as textbooks print it.

Sheets printed "-3.545 mm", "-0.22 %", "min -0.2698°" with the ASCII hyphen (a short dash). The rule, on the
drawn text only (every ``<text>`` of a sheet, joined over its tspans; a player's text and step captions; the
cycle player's read-out): a hyphen right before a number (a digit, or a point and a digit) is a minus sign
U+2212 unless it follows a word character (letter, digit, underscore: "3-4-5", "4-5-6-7", "K-2",
"000-02_slotter", "5.1e-16" are word hyphens and stay). The JSON, the CSV, the terminal and answer files keep
the ASCII "-"; grading reads either.
"""
from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from geomcon.grading.cells import read_cell
from geomcon.render.labels import text_width, wrap
from geomcon.render.player import caption_html
from geomcon.render.serial import minus_signs, typeset

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
HYPHEN_MINUS = re.compile(r"(?<!\w)-(?=\.?\d)")
"""An ASCII hyphen where a minus belongs (the module's rule)."""
WORD_MINUS = re.compile(r"(?<=[^\W_])\u2212(?=\.?\d)")
"""A minus sign where a word hyphen belongs (between a letter or digit and a digit)."""


def test_the_rule_tells_a_minus_from_a_word_hyphen():
    assert minus_signs("AC = -3.545 mm (textbook 161, -0.21 %)") == "AC = −3.545 mm (textbook 161, −0.21 %)"
    assert minus_signs("-229.2") == "−229.2" and minus_signs("A = (-5.000, 15.0), x=-.5") == "A = (−5.000, 15.0), x=−.5"
    for word in ("3-4-5 rise", "the 4-5-6-7 polynomial", "000-02_slotter", "K-2", "5.1e-16", "s-δ", "crank-rocker",
                 "|BC - CD|"):
        assert minus_signs(word) == word
    assert typeset("S = 2·CD - 1, ω = -3") == "S = 2⋅CD - 1, ω = −3"
    assert caption_html("ψ1 − ψ2 = -12.93°") == "ψ<sub>1</sub> − ψ<sub>2</sub> = −12.93°"


def test_a_minus_is_measured_as_the_sheet_prints_it():
    """As wide as "+" (Noto Sans CJK draws U+2212 so), wider than the hyphen's old estimate: layouts still fit."""
    assert text_width("-3.5", 3.5) == text_width("−3.5", 3.5) == text_width("+3.5", 3.5)
    assert text_width("3-4-5", 3.5) < text_width("3−4−5", 3.5)
    assert text_width((("v", False), ("C", True), (" = -1.5", False)), 3.5) == \
        text_width((("v", False), ("C", True), (" = +1.5", False)), 3.5)
    line = "x = -123.456 mm " * 4
    assert wrap(line, 60.0, 3.5) == [s.replace("−", "-") for s in wrap(line.replace("-", "−"), 60.0, 3.5)]


def _texts(page: str) -> list[str]:
    """The drawn texts of an SVG sheet or an HTML player: each ``<text>`` joined over its tspans, the HTML's text
    outside scripts and styles, and a player's step captions (tags dropped)."""
    out = []
    steps = re.search(r"var STEPS = (\[.*?\]);\n", page)
    if steps:
        out += [re.sub(r"<[^>]+>", "", c) for step in json.loads(steps.group(1)) for c in step]
    body = re.sub(r"<(script|style)\b.*?</\1>", "", page, flags=re.S)
    out += ["".join(re.findall(r">([^<]*)<", t)) for t in re.findall(r"<text\b.*?</text>", body, flags=re.S)]
    out += re.findall(r">([^<]+)<", re.sub(r"<text\b.*?</text>", "", body, flags=re.S))
    return [html.unescape(t) for t in out]


PAGES = sorted(p for p in GALLERY.glob("*") if p.suffix in (".svg", ".html") and p.name != "bench_cycle.svg")


@pytest.mark.parametrize("path", PAGES, ids=lambda p: p.name)
def test_no_sheet_or_player_prints_a_hyphen_for_a_minus(path):
    """bench_cycle.svg is the benchmark's chart (DejaVu Sans, "5.1e-16"), not a sheet."""
    bad = [t for t in _texts(path.read_text(encoding="utf-8")) if HYPHEN_MINUS.search(t) or WORD_MINUS.search(t)]
    assert not bad, bad[:5]


def test_the_gallery_has_negative_numbers_on_its_sheets():
    """The rule above is not vacuous: sheets, charts and captions print negative numbers."""
    texts = _texts((GALLERY / "100-05_four_bar_function_generation.svg").read_text(encoding="utf-8"))
    assert any(t.startswith("CD = 70.008 mm (= analytic; textbook 70, −0.01 %)") for t in texts)
    assert "about D through ψ1 − ψ2 = −12.93°" in texts
    assert "−50" in _texts((GALLERY / "002-01_conveyor_cycle_motion.svg").read_text(encoding="utf-8"))


def test_json_keeps_the_ascii_hyphen():
    texts = [p.read_text(encoding="utf-8") for p in sorted(GALLERY.glob("*.json"))]
    assert not [t for t in texts if re.search(r"\u2212\.?\d", t)]
    assert sum(bool(re.search(r"[:\[,]\s*-\d", t)) for t in texts) > 10      # negative numbers, as JSON writes them
    one = (GALLERY / "100-05_four_bar_function_generation.json").read_text(encoding="utf-8")
    assert '"rel_deviation": -0.0001158' in one          # the sheet's "textbook 70, −0.01 %"


def test_the_cycle_notes_print_max_and_min_with_the_same_decimals():
    """002-01's φDC panel said "max 92.91°" beside "min -0.2698°" (each to 4 significant digits of itself)."""
    texts = _texts((GALLERY / "002-01_conveyor_cycle_motion.svg").read_text(encoding="utf-8"))
    assert "max 92.91° at φ = 231.65°" in texts and "min −0.27° at φ = 348.74°" in texts


@pytest.mark.parametrize("raw, unit, value", [("−3.545 mm", "mm", -3.545), ("−0.27°", "deg", -0.27),
                                              ("(−12,5; −3)", "point", (-12.5, -3.0)), ("-3.545", "mm", -3.545),
                                              ("－3.545", "mm", -3.545)])
def test_grading_reads_a_minus_sign(raw, unit, value):
    """A student copying a value off a sheet (or a word processor) writes U+2212: read as "-"."""
    assert read_cell(raw, unit).value == value


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed (apt-get install chromium)")
def test_the_cycle_players_readout_prints_a_minus_sign():
    page = GALLERY / "002-01_conveyor_cycle_cycle.html"
    out = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom",
                          page.as_uri() + "#frame=170"], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-500:]
    readout = html.unescape(re.search(r'id="readout"[^>]*>([^<]*)<', out.stdout).group(1))
    assert "= −" in readout and not HYPHEN_MINUS.search(readout), readout


def test_the_terminal_keeps_the_ascii_hyphen(capsys):
    """The text ``geomcon solve`` prints is machine-readable (grep, a spreadsheet): "-", as the JSON."""
    from geomcon.cli import main
    assert main(["solve", str(ROOT / "problems" / "000-04_slotter_cam_psi0.toml")]) == 0
    out = capsys.readouterr().out
    assert "ρa,min = -3.545 mm" in out and "textbook 13.59, -28.78 %" in out and "\u2212" not in out


def test_an_extreme_s_note_gives_value_and_angle_with_the_same_decimals():
    """000-09 printed "min −5.55 mm at φ = 115.771°" (hlook11m's review): a note's crank angle has 2 decimals, as
    every angle a drawing marks, and so has a value of the usual size beside it."""
    import re
    from pathlib import Path
    gallery = Path(__file__).resolve().parents[1] / "gallery"
    notes = [re.sub(r"<[^>]*>", "", t) for f in sorted(gallery.glob("*_cycle_motion*.svg"))
             for t in re.findall(r'<text class="extreme"[^>]*>(.*?)</text>', f.read_text(encoding="utf-8"), re.S)]
    assert len(notes) >= 8
    for n in notes:
        m = re.fullmatch(r"(?:max|min) \S+ ?\S* at φ = \d+\.(\d+)°", n)
        assert m and len(m[1]) == 2, n
    assert any(re.fullmatch(r"min −5\.55 mm at φ = 115\.77°", n) for n in notes)
