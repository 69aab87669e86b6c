"""Printing (issue 11): sheets of A4/A3 paper in mm, the drawing at a standard scale that is true on paper,
a title block stating it, text no smaller than 2.5 mm, the protocol flowing onto further sheets, results as a
textbook prints them, and the languages."""
from __future__ import annotations

import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.paper import STANDARD
from geomcon.problems import load_problem
from geomcon.render.page import MIN_TEXT, PageSpec, frame_box, title_block_box, zh_punct
from geomcon.render.results import NAMES
from geomcon.render.svg import place_figure, render_sheets
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
SVG = "{http://www.w3.org/2000/svg}"
SAMPLE = ("001-08_crank_rocker", "100-04_four_bar_fixed_pivots_coupler_angles", "200-01_cam_roller_offset",
          "200-12_oscillating_base_radius", "000-02_slotter_design_by_K")


def _sol(pid: str):
    return solve(load_problem(ROOT / "problems" / f"{pid}.toml"))


def _mm_per_unit(root: ET.Element) -> float:
    w = root.get("width")
    assert w.endswith("mm"), w
    return float(w[:-2]) / float(root.get("viewBox").split()[2])


def _problem_sheets() -> list[Path]:
    """The problems' sheets: files named for a problem (``<nnn>-…``), not the laws', the s–v–a diagrams or the
    bench figure (``bench_cycle.svg``, a chart on screen, not a drawing sheet)."""
    return sorted(p for p in GALLERY.glob("*.svg") if p.name[:1].isdigit() and "_motion" not in p.name)


# ------------------------------------------------------------------------------------------- page and scale
def test_every_gallery_sheet_is_an_a4_page_in_mm():
    # landscape, or portrait where that draws the figure larger (tests/test_gallery_orientation.py)
    sheets = _problem_sheets()
    assert len(sheets) > 100
    for p in sheets:
        root = ET.parse(p).getroot()
        assert (root.get("width"), root.get("height"), root.get("viewBox")) in (
            ("297mm", "210mm", "0 0 297 210"), ("210mm", "297mm", "0 0 210 297")), p


@pytest.mark.parametrize("paper,orientation", [("A4", "landscape"), ("A4", "portrait"), ("A3", "landscape"),
                                               ("A3", "portrait")])
@pytest.mark.parametrize("pid", SAMPLE)
def test_the_drawing_is_at_a_standard_scale_inside_the_frame_and_clear_of_the_title_block(pid, paper, orientation):
    sol = _sol(pid)
    page = PageSpec(paper, orientation, "en")
    sl, scale, view = place_figure(sol.drawing_scene, page, sol.figure_lines("en"), sol.warnings)
    assert scale in STANDARD and math.isclose(view.mu, scale.real / scale.paper)
    x0, y0, x1, y1 = view.paper_box
    fx0, fy0, fx1, fy1 = frame_box(page.sheet)
    tb = title_block_box(page.sheet)
    assert fx0 <= x0 and x1 <= fx1 and fy0 <= y0 and y1 <= tb[1], (x0, y0, x1, y1)
    # the largest standard scale: the next one up would not fit the same area
    bigger = [s for s in STANDARD if s > scale]
    if bigger:
        w, h = (view.box[2] - view.box[0]) / view.mu, (view.box[3] - view.box[1]) / view.mu
        k = bigger[0].factor / scale.factor
        assert w * k - 20.0 * (k - 1) > sl.area[2] - sl.area[0] + 1e-9 or \
            h * k - 20.0 * (k - 1) > sl.area[3] - sl.area[1] + 1e-9


def _pivot_centre(root: ET.Element, key: str) -> tuple[float, float]:
    g = root.find(f".//{SVG}g[@id='step-{key}']")
    c = g.find(f"{SVG}circle")
    return float(c.get("cx")), float(c.get("cy"))


def test_a_length_of_the_drawing_is_its_real_length_times_the_stated_scale():
    """001-08: the frame AD = 90 mm drawn between the pivots' centres, the scale bar, the title block and μl all
    agree, in mm of paper (the PDF test checks the paper)."""
    sheet = _sol("001-08_crank_rocker").svg()
    root = ET.fromstring(sheet)
    k = _mm_per_unit(root)
    (ax, ay), (dx, dy) = _pivot_centre(root, "A"), _pivot_centre(root, "D")
    stated = re.search(r"Scale\s+比例 (\d+(?:\.\d+)?):(\d+(?:\.\d+)?)<", sheet)
    paper, real = float(stated.group(1)), float(stated.group(2))
    assert abs(math.hypot(dx - ax, dy - ay) * k - 90.0 * paper / real) <= 0.01
    assert f"μl = {real / paper:g} mm/mm" in re.sub(r"<[^>]+>", "", sheet)      # μ with subscript l: two runs
    bar = root.find(f".//{SVG}g[@id='scale']")
    m = re.match(r"M([\d.]+) ([\d.]+)H([\d.]+)", bar.find(f"{SVG}path").get("d"))
    drawn = (float(m.group(3)) - float(m.group(1))) * k
    label = float(re.search(r">([\d.]+) mm<", ET.tostring(bar, encoding="unicode")).group(1))
    assert abs(drawn - label * paper / real) <= 0.01


def test_a_cam_is_drawn_large_enough_to_construct_on():
    """200-01: r0 = 40 was drawn as 16 mm; now at the largest standard scale that fits A4 with its s–δ diagram."""
    sol = _sol("200-01_cam_roller_offset")
    _, scale, _ = place_figure(sol.drawing_scene, PageSpec(), sol.figure_lines(), sol.warnings)
    assert scale.to_paper(40.0) >= 20.0


# ------------------------------------------------------------------------------------------- text
def test_no_text_on_any_sheet_is_smaller_than_2_5_mm():
    """ISO 3098: every font size (labels, marks, results, protocol, title block, subscripts), in mm of paper."""
    files = sorted(GALLERY.glob("*.svg"))
    assert files
    for p in files:
        root = ET.parse(p).getroot()
        k = _mm_per_unit(root)
        sizes = [float(el.get("font-size")) * k for el in root.iter() if el.get("font-size")]
        assert sizes and min(sizes) >= MIN_TEXT - 1e-9, (p.name, min(sizes))


# ------------------------------------------------------------------------------------------- protocol sheets
def test_a_long_protocol_flows_onto_further_sheets_each_step_once_within_the_frame():
    sol = _sol("100-04_four_bar_fixed_pivots_coupler_angles")
    for page in (PageSpec("A4", "landscape"), PageSpec("A4", "portrait", "en"), PageSpec("A3", "landscape", "zh")):
        sheets = sol.sheets(page)
        n = len(sol.drawing_scene.frames())
        assert len(sheets) >= 2
        seen = []
        tb = title_block_box(page.sheet)
        for i, s in enumerate(sheets, 1):
            root = ET.fromstring(s)
            assert f"{i}/{len(sheets)}" in s
            for g in root.iter(f"{SVG}g"):
                if (g.get("class") or "").split()[:1] == ["proto"]:
                    seen.append(int(g.get("data-step")))
                    ys = [float(t.get("y")) for t in g.iter(f"{SVG}text")]
                    assert max(ys) <= tb[1], (page, i, g.get("id"))
        assert sorted(seen) == list(range(1, n + 1)), page
    def fullest(page: PageSpec) -> int:          # the most protocol steps one sheet holds
        return max(s.count('<g class="proto" ') for s in sol.sheets(page))
    assert fullest(PageSpec("A3", "landscape")) > fullest(PageSpec("A4", "portrait"))    # 44 > 38


def test_svg_writes_the_protocol_sheets_beside_the_drawing(tmp_path):
    p = ROOT / "problems" / "001-08_crank_rocker.toml"
    out = subprocess.run([sys.executable, "-m", "geomcon", "solve", str(p), "--svg", str(tmp_path / "f.svg"),
                          "--paper", "A3", "--portrait", "--lang", "zh"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert sorted(f.name for f in tmp_path.iterdir()) == ["f-2.svg", "f.svg"]
    root = ET.parse(tmp_path / "f.svg").getroot()
    assert (root.get("width"), root.get("height")) == ("297mm", "420mm")
    assert "作图步骤" in (tmp_path / "f-2.svg").read_text(encoding="utf-8")
    bad = subprocess.run([sys.executable, "-m", "geomcon", "solve", str(p), "--svg", str(tmp_path / "g.svg"),
                          "--paper", "A5"], capture_output=True, text=True)
    assert bad.returncode == 2 and not (tmp_path / "g.svg").exists()
    (tmp_path / "h-2.svg").mkdir()                                   # sheet 2's path is taken: nothing written
    taken = subprocess.run([sys.executable, "-m", "geomcon", "solve", str(p), "--svg", str(tmp_path / "h.svg")],
                           capture_output=True, text=True)
    assert taken.returncode == 2 and taken.stderr.count("\n") == 1 and "sheet 2" in taken.stderr
    assert not (tmp_path / "h.svg").exists()


# ------------------------------------------------------------------------------------------- results
_INFO = re.compile(r'<text class="info"[^>]*>(.*?)</text>', re.S)


def _info_texts(svg: str) -> list[str]:
    return [re.sub(r"<[^>]+>", "", t) for t in _INFO.findall(svg)]


def test_results_read_as_a_textbook_prints_them():
    """θ, γmin, ∠C1AD, 'C1 folded: yes' — never gamma_min, C1_folded = 1.0000, or '✓ twin' beside a false answer."""
    lines = []
    for p in _problem_sheets():
        lines += _info_texts(p.read_text(encoding="utf-8"))
    assert len(lines) > 200
    names = {q for q in NAMES if "_" in q}
    for ln in lines:
        assert "twin" not in ln and "✓" not in ln and "= 1.0000" not in ln and "= 0.0000" not in ln, ln
        assert not any(re.search(rf"(?<![\w]){re.escape(q)}(?![\w])", ln) for q in names), ln
    text = "\n".join(lines)
    for want in ("θ = 12.506° (= analytic", "∠C1AD = 54.315°", "C1 folded: ", "one assembly branch: no (= analytic)"):
        assert want in text.replace("C<tspan", "C"), want


def test_every_answer_of_every_recipe_has_a_printed_name():
    from geomcon.recipes import RECIPES
    missing = sorted({q.name for r in RECIPES.values() for q in r.answers} - set(NAMES))
    assert not missing


def test_a_yes_no_answer_reads_yes_or_no_in_each_language():
    sol = _sol("001-08_crank_rocker")
    from geomcon.render.results import result_line
    assert result_line("C1_folded", 1.0, "", twin=True) == "C1 folded: yes (= analytic)"
    assert result_line("crank", False, "bool", twin=False, lang="zh") == "AB 为曲柄：否（与解析解不符）"
    assert all("（" in ln and "）" in ln and "(" not in ln for ln in sol.figure_lines("zh"))


# ------------------------------------------------------------------------------------------- languages
_CJK = re.compile(r"[\u3000-\u303f\u4e00-\u9fff\uff00-\uffef]")


def test_lang_en_prints_no_chinese_and_zh_prints_chinese_protocol_with_full_width_punctuation():
    sol = _sol("001-08_crank_rocker")
    en = "".join(sol.sheets(PageSpec(lang="en")))
    assert not _CJK.search(re.sub(r"font-family=\"[^\"]*\"", "", en))
    zh = sol.sheets(PageSpec(lang="zh"))
    body = "".join(zh)
    assert "作图步骤" in body and "Construction protocol" not in body and "Circle about D" not in body
    texts = ["".join(t.itertext()) for s in zh for t in ET.fromstring(s).iter(f"{SVG}text")]
    for t in texts:
        if _CJK.search(t):
            for m in re.finditer(r"[,;:]", t):
                near = t[max(0, m.start() - 1):m.start()] + t[m.end():m.end() + 1]
                assert not _CJK.search(near), t
            for m in re.finditer(r"\(([^()]*)\)", t):
                assert not _CJK.search(m.group(1)), t
    assert zh_punct("取 D,使 AD = 90(机架)") == "取 D，使 AD = 90（机架）"
    both = "".join(sol.sheets(PageSpec(lang="both")))
    assert "作图步骤" in both and "Construction protocol" in both


def test_the_player_prints_one_sheet_a_page_at_the_sheet_size():
    sol = _sol("001-08_crank_rocker")
    page = sol.html(PageSpec("A3", "portrait", "zh"))
    assert "@page { size: A3 portrait; margin: 0; }" in page
    assert "#drawing svg.sheet { width: 297mm; height: 420mm;" in page
    assert page.count('<div class="page" id="page-') == len(sol.sheets(PageSpec("A3", "portrait", "zh")))
    assert '<html lang="zh-Hans"' in page


def test_frame_k_shows_the_caption_of_step_k_only_and_the_full_drawing_none():
    """The protocol is on sheet 2, so a --steps frame (sheet 1 at step k) says what step k does, in its language."""
    from geomcon.render.svg import frame_of

    sol = _sol("001-08_crank_rocker")
    full = sol.svg(page=PageSpec(lang="en"))
    caps = re.compile(r'<text class="stepcap( current)?" data-step="(\d+)"[^>]*>(.*?)</text>', re.S)
    assert caps.findall(full) and not [c for c in caps.findall(full) if c[0]]
    for k in (1, 14, 25):
        shown = [(int(n), re.sub(r"<[^>]+>", "", t)) for cur, n, t in caps.findall(frame_of(full, k)) if cur]
        assert shown and {n for n, _ in shown} == {k}
        assert shown[0][1].startswith(f"{k}. ")
    at14 = [re.sub(r"<[^>]+>", "", t) for cur, n, t in caps.findall(frame_of(full, 14)) if cur]
    assert at14[0].startswith("14. Measure θ")
    assert ".stepcap.current { display: inline; }" in full and ".stepcap { display: none; }" in full


def test_the_protocol_takes_as_many_columns_as_the_sheet_holds():
    """A4 portrait holds two 82 mm columns, A4 landscape three: a long protocol fills them before a new sheet."""
    from geomcon.render.protocol import COL_GAP, COL_W, paginate

    sc = _sol("100-04_four_bar_fixed_pivots_coupler_angles").drawing_scene
    for page, cols in ((PageSpec("A4", "portrait", "zh"), 2), (PageSpec("A4", "landscape", "both"), 3)):
        fx0, fy0, fx1, _ = frame_box(page.sheet)
        width = fx1 - fx0 - 8.0
        assert cols * COL_W + (cols - 1) * COL_GAP <= width
        pages = paginate(sc, width, title_block_box(page.sheet)[1] - fy0 - 8.0, page.lang)
        assert all(p.columns == cols for p in pages[:-1]) and pages[0].columns == cols, [p.columns for p in pages]


def test_no_gallery_drawing_is_wider_or_taller_than_its_paper():
    """Issue 11 found 48 of 89 figures wider than A4 landscape: every problem's drawing now lies in the frame,
    above the title block, at a standard scale (on the gallery's page: A4, landscape or portrait)."""
    from gallery_pages import page_of

    files = sorted((ROOT / "problems").glob("*.toml"))
    assert len(files) > 60
    for p in files:
        page = page_of(p.stem)
        fx0, fy0, fx1, _ = frame_box(page.sheet)
        tb = title_block_box(page.sheet)
        sol = solve(load_problem(p))
        _, scale, view = place_figure(sol.drawing_scene, page, sol.figure_lines(page.lang), sol.warnings)
        x0, y0, x1, y1 = view.paper_box
        assert scale in STANDARD and fx0 <= x0 and x1 <= fx1 and fy0 <= y0 and y1 <= tb[1], (p.name, view.paper_box)


def test_a_file_name_with_control_characters_gives_well_formed_sheets(tmp_path):
    """The title block prints the problem file's name: a name holding U+0001 or a newline (found by the fuzz)
    is written escaped, and every sheet and the player stay well-formed XML."""
    import subprocess
    import sys
    import xml.dom.minidom

    f = tmp_path / "weird\x01name\nx.toml"
    f.write_text('recipe = "guide_bar.extremes"\n[given]\nAB = 50\nAC = 100\n', encoding="utf-8")
    r = subprocess.run([sys.executable, "-m", "geomcon", "solve", str(f), "--svg", str(tmp_path / "s.svg"),
                        "--html", str(tmp_path / "p.html")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    outs = sorted(tmp_path.glob("s*.svg")) + [tmp_path / "p.html"]
    assert len(outs) >= 3
    for out in outs:
        xml.dom.minidom.parse(str(out))
    assert "weird\\x01name\\nx" in (tmp_path / "s.svg").read_text(encoding="utf-8")
