"""Every visible text of the gallery reads as the textbook prints it: no identifier written with an underscore
(issue 11: 000-04's protocol printed "the return's α_max" where the figure prints α with the subscript max).

Code is left as code: file and recipe names (``000-04_slotter_cam_psi0.toml``, ``cam.base_radius``), a problem's
id, a motion law's key (``modified_sine``, as a problem file names it) and the grading and bench reports' codes
(mistake codes, the benchmarked functions' names)."""
from __future__ import annotations

import re
from pathlib import Path

from geomcon.gallery import _law_names

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
RAW = re.compile(r"[^\s(),=:;，：（）]*[A-Za-zα-ωΑ-Ω′]_[A-Za-z0-9][^\s(),=:;，：（）]*")
"""A word with an underscore after a letter: ``α_max``, ``gamma_allow``, ``profile_x[0]``."""
CODE_FILES = ("grading_", "bench_")
"""Reports whose tables list codes on purpose (mistake codes, function names)."""


def visible_texts(text: str) -> list[str]:
    """The text nodes of an SVG or HTML file, scripts and style sheets left out."""
    text = re.sub(r"<script.*?</script>|<style.*?</style>", "", text, flags=re.S)
    return [t for t in re.findall(r">([^<>]+)<", text) if t.strip()]


def is_code(word: str, problem_ids: set[str], laws: set[str]) -> bool:
    """A file, recipe or problem name, or a motion law's key."""
    core = word.strip("'\"[]")
    return (re.search(r"\.[A-Za-z]", core) is not None or core in problem_ids or core in laws
            or re.match(r"\d{3}-\d{2}", core) is not None)


def test_no_visible_text_of_the_gallery_shows_a_raw_underscore_name():
    problem_ids = {p.stem for p in (GALLERY.parent / "problems").glob("*.toml")}
    laws = set(_law_names())
    files = [f for f in sorted(GALLERY.rglob("*")) if f.suffix in (".svg", ".html")]
    assert len(files) > 300
    raw = {}
    for f in files:
        if f.name.startswith(CODE_FILES):
            continue
        for t in visible_texts(f.read_text(encoding="utf-8")):
            for w in RAW.findall(t):
                if not is_code(w, problem_ids, laws):
                    raw.setdefault(w, f.name)
    assert not raw, raw


POINT_SYMBOL = re.compile(r"(?<![A-Za-z0-9])[valn][A-Z][A-Z0-9]*|(?<![A-Za-z0-9])[va][ⁿᵗʳᵏ][A-Z]+|μ[val](?![A-Za-z])"
                          r"|(?<![A-Za-z_\d.])[a-z]\d+(?![\d.])|[A-Z]d\d+")
"""A symbol whose index the textbook prints as a subscript, written on the line: a velocity, acceleration,
length or polygon normal with its points (``vC``, ``aCBᵗ``, ``aʳB2B3``, ``lAB``, the point ``nB``), a scale
(``μv``, ``μa``, ``μl``), a small letter's digits (``r0``, ``s1``, ``i13``, the polygon points ``b3``, ``n2``) and
a dead point (``Cd1``)."""


def main_runs(svg: str) -> list[str]:
    """The runs of an SVG's texts printed full size: subscript tspans (a font size of their own) left out."""
    svg = re.sub(r"<script.*?</script>|<style.*?</style>", "", svg, flags=re.S)
    svg = re.sub(r"<tspan[^>]*font-size[^>]*>[^<]*</tspan>", "<sub/>", svg)
    return [t for t in re.findall(r">([^<>]+)<", svg) if t.strip()]


def test_no_visible_text_of_the_gallery_writes_a_kinematic_symbol_without_its_subscript():
    # issue 11: 400-02 printed "vC = -233.724 mm/s", "aC = …" and a point labelled "nB" (n with subscript B);
    # captions, results and title blocks printed r0, μl, b3, i13, arB2B3 and the dead point Cd1 flat
    files = [f for f in sorted(GALLERY.glob("*.svg")) if not f.name.startswith(CODE_FILES)]
    raw = {}
    for f in files:
        for t in main_runs(f.read_text(encoding="utf-8")):
            for w in POINT_SYMBOL.findall(t):
                if not is_code(w, set(), set()):
                    raw.setdefault(w, f.name)
    assert not raw, raw


def test_link_range_rows_are_headed_by_their_names_like_a_table():
    # issue 11: 001-02's row names sat below-left of each row at scattered places, two with leaders; a table
    # heads each row with its name: right-aligned at the row's start, on its line
    from geomcon.render.labels import text_width
    svg = (GALLERY / "001-02_four_bar_link_ranges.svg").read_text(encoding="utf-8")
    rows = [(float(x0), float(y)) for x0, y in re.findall(r'id="step-row\d+"><path class="ink" d="M([\d.]+) ([\d.]+)L[\d.]+ \2"', svg)]
    assert len(rows) == 5                  # the rows are number lines (style given), no longer dash-dot frames
    names = ("crank-rocker 曲柄摇杆", "double-crank 双曲柄", "double-rocker 双摇杆", "immovable 不能运动",
             "Grashof 满足杆长条件")               # as the Results name them, in both languages (session m)
    rights = []
    for name in names:
        m = re.search(r'font-size="([\d.]+)"[^>]*text-anchor="middle" x="([\d.]+)"[^>]*y="([\d.]+)"><tspan>'
                      + re.escape(name) + "<", svg)
        assert m, name
        size, x, y = map(float, m.groups())
        right = x + text_width(name, size) / 2
        x0, ly = min(rows, key=lambda r: abs(r[1] - y))
        assert 0.0 < x0 - right < 3.5, (name, x0, right)
        assert abs(y - size * 0.35 - ly) < 0.6, (name, y, ly)
        rights.append(right)
    assert max(rights) - min(rights) < 0.5
