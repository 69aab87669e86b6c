"""The worksheet's pages (issue 12): the students' sheets and the key pages — determinism of every byte, the
add-a-student property, no answer in any student file, one sheet per page, true scale, nothing overlapping."""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from geomcon.paper import Scale
from geomcon.worksheet import make_worksheet
from geomcon.worksheet.givens_figure import place_labels
from geomcon.worksheet.key_pages import decimals
from geomcon.worksheet.roster import Student, numbered
from geomcon.worksheet.sheets import make_pages, page_name
from geomcon.worksheet.spec import load_spec, parse_spec

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "tests" / "data" / "worksheet_class.toml"
U = 100.0


@pytest.fixture(scope="module")
def spec():
    return load_spec(SPEC)


@pytest.fixture(scope="module")
def six(spec):
    return make_worksheet(spec, numbered(6))


@pytest.fixture(scope="module")
def key6(six):
    return json.loads(six.files["key.json"])


def _student_files(files: dict[str, str]) -> dict[str, str]:
    return {k: v for k, v in files.items() if k.startswith("sheets/") or k == "sheets.html"}


def test_every_output_byte_is_deterministic(spec, six):
    again = make_worksheet(spec, numbered(6))
    assert again.files == six.files
    pages = {f"{i}{'' if n == 1 else f'-{n}'}.svg" for i in range(1, 7) for n in (1, 2, 3)}   # sheets/<id>.svg, <id>-2 …
    assert {n for n in six.files if n.startswith("sheets/")} >= {f"sheets/{p}" for p in pages}
    assert {f"key/{p}" for p in pages} == {n for n in six.files if n.startswith("key/")}


def test_adding_a_student_changes_no_one_else_s_pages(spec, six):
    seven = make_worksheet(spec, numbered(7))
    for name, text in six.files.items():
        if name.startswith(("sheets/", "key/")):
            assert seven.files[name] == text, name
    sections = re.findall(r'<section class="sheet[^"]*" id="([^"]+)">', six.files["sheets.html"])
    for sid in sections:
        one = re.search(rf'<section[^>]* id="{re.escape(sid)}">.*?</section>', six.files["sheets.html"], re.S)
        assert one.group(0) in seven.files["sheets.html"], sid
    assert "sheets/7.svg" in seven.files and "sheets/7-2.svg" in seven.files


def _shown_forms(answer: dict) -> set[str]:
    """Every string by which a key shows an answer: key.json's value, and the value at 0 … 4 decimals (the key
    page shows it at the tolerance's last digit)."""
    v = answer["value"]
    forms = {repr(v), f"{v:.{decimals(answer['tol'])}f}"}
    forms |= {f"{v:.{d}f}" for d in range(1, 5)}
    return {f for f in forms if "." in f}


def test_no_answer_in_any_student_file(six, key6):
    forms = {f for s in key6["students"] for ex in s["exercises"] for a in ex["answers"].values() for f in _shown_forms(a)}
    assert len(forms) > 50
    student = _student_files(six.files)
    for name, text in student.items():
        for f in forms:
            assert not re.search(rf"(?<![\d.]){re.escape(f)}(?!\d)", text), (name, f)
    # the test can fail: the key pages do show the answers
    key1 = six.files["key/1.svg"]
    a = key6["students"][0]["exercises"][0]["answers"]["AB"]
    assert f"{a['value']:.{decimals(a['tol'])}f}" in key1


def test_a_student_sheet_holds_only_integers_outside_its_text(six):
    svg = six.files["sheets/1.svg"]
    attrs = " ".join(re.findall(r'\s(?:d|x|y|cx|cy|r|width|height|font-size|stroke-width|dy)="([^"]*)"', svg))
    assert attrs and not re.search(r"\d\.\d", attrs)


def test_one_sheet_per_page_and_pages_per_student(six, key6):
    html = six.files["sheets.html"]
    sections = re.findall(r'<section class="sheet ([^"]+)" id="([^"]+)">', html)
    files = sorted(n for n in six.files if n.startswith("sheets/"))
    assert sorted(f"sheets/{sid}.svg" for _, sid in sections) == files
    articles = re.findall(r'<article class="student" data-id="([^"]+)">', html)
    assert articles == [s["id"] for s in key6["students"]]
    assert html.count("break-after: page") == 1 and "@page A4-portrait { size: A4 portrait; margin: 0; }" in html
    for s in key6["students"]:                         # each exercise's sheet, and a cam's s–δ page when needed
        mine = [sid for _, sid in sections if sid == s["id"] or sid.startswith(f"{s['id']}-")]
        assert [m for m in mine if not m.endswith("-sd")] == [s["id"], f"{s['id']}-2", f"{s['id']}-3"]
        for m in mine:                                 # an s–δ page follows its exercise's page, named after it
            if m.endswith("-sd"):
                assert mine[mine.index(m) - 1] == m.removesuffix("-sd")
    keys = sorted(n for n in six.files if n.startswith("key/"))
    assert keys == sorted(f"key/{sid}.svg" for _, sid in sections if not sid.endswith("-sd"))


def _paths(svg: str, group: str) -> list[list[tuple[float, float]]]:
    body = svg[svg.index(f'id="{group}"'):]
    body = body[:body.index("</g>")]
    out = []
    for d in re.findall(r'<path d="([^"]+)"', body):
        out.append([(float(x) / U, float(y) / U) for x, y in re.findall(r"(-?\d+) (-?\d+)", d)])
    return out


def _length(pts):
    return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))


def _radii(svg: str) -> list[float]:
    """Radii (paper mm) of the circles drawn: ``<circle>`` elements and given circles (paths of arcs)."""
    return ([float(r) / U for r in re.findall(r'<circle[^>]* r="(\d+)"', svg)]
            + [float(re.search(r"A(\d+) ", d).group(1)) / U
               for d in re.findall(r'<path class="given-circle" d="([^"]+)"', svg)])


def test_the_givens_are_drawn_to_true_scale(six, key6):
    """Design by K: DC1 and DC2 are CD long at the variant's scale; extremes: the frame AD and the circles AB,
    CD; a cam: the base circle r0 — measured in the SVG, in paper mm (the page is its paper's size in mm)."""
    for s in key6["students"]:
        e1, e2, e3 = s["exercises"]
        f1, f2, f3 = (Scale.parse(e["scale"]).factor for e in (e1, e2, e3))
        svg1 = six.files[f"sheets/{s['id']}.svg"]
        head = svg1[:svg1.index(">")]
        w, h = (re.search(rf' {k}="(\d+)mm"', head).group(1) for k in ("width", "height"))
        assert f'viewBox="0 0 {w}00 {h}00"' in head and {w, h} == {"210", "297"}
        lengths = sorted(_length(p) for p in _paths(svg1, "givens"))
        assert lengths == pytest.approx([e1["given"]["CD"] * f1] * 2, abs=0.02)
        svg2 = six.files[f"sheets/{s['id']}-2.svg"]
        assert [_length(p) for p in _paths(svg2, "givens")] == pytest.approx([e2["given"]["AD"] * f2], abs=0.02)
        radii = sorted(r for r in _radii(svg2) if r > 2)
        assert radii == pytest.approx(sorted([e2["given"]["AB"] * f2, e2["given"]["CD"] * f2]), abs=0.01)
        svg3 = six.files[f"sheets/{s['id']}-3.svg"]
        radii = sorted(r for r in _radii(svg3) if r > 2)
        offset = [e3["given"]["e"] * f3] if e3["given"]["e"] * f3 > 2 else []
        assert radii == pytest.approx(sorted([e3["given"]["r0"] * f3] + offset), abs=0.01)


def test_nothing_overlaps_on_a_page(spec, six):
    """The figure (with its margin) lies below the answer boxes and inside the frame; no label collides; the
    s–δ axes lie outside the figure; the key page lays over the sheet (the same layout)."""
    a = six.assignment
    pages = make_pages(spec, a, "both")
    for p in pages:
        lay = p.lay
        x0, y0, x1, y1 = lay.frame
        rows = 1 + max(r for r, _ in lay.slots)
        answers_bottom = lay.answers_top + 13.0 * rows
        if p.part != "sd":
            assert lay.fig[1] >= answers_bottom - 1e-9 and lay.fig[3] <= y1 + 1e-9, p.name
            assert lay.fig[0] >= x0 - 1e-9 and lay.fig[2] <= x1 + 1e-9, p.name
            _, bad = place_labels(p.items, lay.to_paper)
            assert bad == [], p.name
            for lab in p.labels:
                assert x0 <= lab.box[0] and lab.box[2] <= x1 and lay.fig[1] <= lab.box[1] and lab.box[3] <= y1, p.name
        if lay.diagram is not None and p.part != "sd":
            d = lay.diagram
            assert d[0] >= lay.fig[2] - 1e-9 or d[1] >= lay.fig[3] - 1e-9, p.name


def test_the_key_page_nests_the_construction_at_the_sheet_s_scale(six, key6):
    svg = six.files["key/1.svg"]
    m = re.search(r'<svg height="(\d+)" id="construction" viewBox="0 0 ([\d.]+) ([\d.]+)" width="(\d+)" x="(\d+)" '
                  r'y="(\d+)"', svg)
    assert m, svg[:2000]
    h, vw, vh, w = (float(m.group(i)) for i in (1, 2, 3, 4))
    assert w / h == pytest.approx(vw / vh, rel=1e-4)
    assert 'id="overlay"' in svg and svg.count('stroke="#d0021b"') == 1
    e = key6["students"][0]["exercises"][0]
    for name, a in e["answers"].items():
        assert f"{a['value']:.{decimals(a['tol'])}f} ± {a['tol']:.{decimals(a['tol'])}f}" in svg


def test_page_names_stay_inside_the_folder_and_never_clash():
    ids = ["2023001", "../etc/passwd", "A1", "a1", "张三", "x/y", "a.b"]
    names = [page_name(i, 1) for i in ids]
    assert len(set(names)) == len(names)
    assert all(re.fullmatch(r"[a-z0-9_.-]+", n) and not n.startswith(".") and "/" not in n for n in names)
    assert page_name("2023001", 1) == "2023001" and page_name("2023001", 2) == "2023001-2"
    # no id's first page is another id's further page: ids ending as a further page does are hashed
    ids = ["1", "1-2", "1-sd", "1-2-sd", "2023-001", "2023-15", "x-20", "x-21"]
    pages = [page_name(i, n) + sd for i in ids for n in range(1, 21) for sd in ("", "-sd")]
    assert len(set(pages)) == len(pages)
    assert [page_name(i, 1) for i in ("2023-001", "x-21")] == ["2023-001", "x-21"]
    assert all("." in page_name(i, 1) for i in ("1-2", "1-sd", "1-2-sd", "2023-15", "x-20"))


def test_names_and_ids_are_escaped(tmp_path):
    spec = parse_spec('''
title = "Guide bar <b>&"
[[exercise]]
recipe = "guide_bar.extremes"
ask = ["theta"]
[exercise.given]
AB = {min = 100, max = 140, step = 10}
AC = 290
''')
    w = make_worksheet(spec, [Student("<x>", "A & <B>")], lang="en")
    html = w.files["sheets.html"]
    assert "<x>" not in html and "<B>" not in html and "&lt;B&gt;" in html and "<b>&" not in html


def test_crowded_labels_are_found_and_free_ones_placed_clear():
    from geomcon.worksheet.givens_figure import Item, given_gap

    crowd = [Item("point", ((2.0 * math.cos(2 * math.pi * k / 7), 2.0 * math.sin(2 * math.pi * k / 7)),), label=f"C{k}")
             for k in range(7)]
    placed, bad = place_labels(crowd, lambda x, y: (x, -y))
    assert bad and len(placed) == 7
    assert given_gap(crowd)[2] == pytest.approx(2 * 2.0 * math.sin(math.pi / 7), rel=1e-9)
    apart = [Item("point", ((0.0, 0.0),), label="A"), Item("point", ((30.0, 0.0),), label="D"),
             Item("segment", ((0.0, 0.0), (30.0, 0.0)))]
    placed, bad = place_labels(apart, lambda x, y: (x, -y))
    assert bad == []
    for p in placed:                   # clear of the frame line AD and of both dots
        assert p.box[3] <= 0.0 - 0.8 or p.box[1] >= 0.8


def test_a_statement_too_long_for_the_sheet_is_refused_in_one_line(tmp_path):
    import subprocess
    import sys

    spec = tmp_path / "long.toml"
    words = " ".join(["The crank turns slowly."] * 150)
    spec.write_text(f'''
title = "Long"
[[exercise]]
recipe = "crank_rocker.extremes"
ask = ["theta"]
statement = "{words} AB = {{AB}} mm."
[exercise.given]
AB = 25
BC = 85
CD = 70
AD = 70
''', encoding="utf-8")
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "geomcon", "worksheet", str(spec), "--out", str(out), "--count", "2"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    assert "exercise 1" in r.stderr and "do not fit" in r.stderr and not out.exists()


def test_pages_reuse_what_judging_solved_with_the_same_numbers(spec, six):
    """A page draws the solution its variant was judged on, and the overlay's circles come from the drafting
    ends the answers' tolerances solved (lean scenes): the same box, given items and radii, to the last bit,
    as solving the variant and every drafting end afresh in full."""
    from geomcon.worksheet.overlay import position_tolerances
    from geomcon.worksheet.key_extent import figure_box
    from geomcon.worksheet.givens_figure import given_items
    from geomcon.worksheet.solving import solve_given
    for ex, v in zip(spec.exercises, six.assignment.variants[0]):
        assert v.solved is not None
        fresh = solve_given(ex.recipe, v.given)
        assert v.solved.box == figure_box(fresh, [r.name for r in ex.ask], v.scale.factor)
        assert v.solved.items == tuple(given_items(fresh))
        radii = position_tolerances(fresh, v.given, v.scale.factor)
        assert radii and v.solved.radii == radii, ex.recipe


def test_a_cam_key_leaves_out_the_s_delta_diagram_outside_its_figure(six):
    """The key's figure is clipped to the sheet's model box, which excludes a cam's s–δ diagram: its steps are
    not drawn (nothing beyond the nested viewBox), the cam's own are."""
    svg = six.files["key/1-3.svg"]
    inner = svg[svg.index('id="construction"'):]
    assert ">1′<" in inner and ">15′<" in inner                # the pitch points' labels
    assert ">δ<" not in inner and ">s<" not in inner          # the diagram's axis labels


def _header_texts(svg: str) -> list[str]:
    """The visible texts of a page's header group: title, exercise line, name line and statement lines."""
    group = re.search(r'<g id="header">(.*?)</g>', svg, re.S).group(1)
    return [re.sub(r"<[^>]+>", "", t) for t in re.findall(r"<text[^>]*>(.*?)</text>", group)]


@pytest.mark.parametrize("lang", ["en", "zh", "both"])
def test_a_page_header_is_in_the_page_s_language(spec, lang):
    """Issue 11: under ``--lang zh`` the header read "Name 姓名 / ID 学号 / Variant 变体" in both languages. Its
    words are now Chinese only under zh, English only under en and both under both, on every sheet and key page
    (the title is the teacher's own text and stays as written)."""
    w = make_worksheet(spec, numbered(1), lang=lang)
    pages = {n: t for n, t in w.files.items() if n.endswith(".svg") and n.startswith(("sheets/", "key/"))}
    assert len(pages) >= 6 and {n.split('/')[0] for n in pages} == {"sheets", "key"}
    english = re.compile(r"\b(KEY|Exercise|continued|scale|Name|ID|Variant|portrait|landscape|rise|return)\b")
    chinese = re.compile(r"答案|题|续|比例|姓名|学号|变体|纵向|横向")
    for name, svg in pages.items():
        title, exercise, who, *_ = _header_texts(svg)
        words = [title.replace(spec.title, ""), exercise, who]
        if lang == "zh":
            assert not any(english.search(t) for t in words), (name, words)
            assert all(chinese.search(t) for t in words[1:]) and ": " not in who, (name, words)
            assert "(rise)" not in svg and "(return)" not in svg            # answer boxes: αmax（推程）
        elif lang == "en":
            assert not any(chinese.search(t) for t in words), (name, words)
            assert all(english.search(t) for t in words[1:]), (name, words)
        else:
            assert all(english.search(t) and chinese.search(t) for t in words[1:]), (name, words)
        if name.startswith("key/"):
            assert ("答案" in title) == (lang != "en") and ("KEY" in title) == (lang != "zh")


_MOVE = re.compile(r"M(-?\d+) (-?\d+)")
_ARC_END = re.compile(r"A\d+ \d+ 0 [01] [01] (-?\d+) (-?\d+)")


def test_a_given_circle_is_whole_or_ends_on_the_frame_and_every_sheet_clips_to_its_own_area(six):
    """hlook11 item 42: a given circle ran into the invisible clip rectangle of the figure area and ended in
    mid-air; and sheets.html, inlining every page, clipped each page with the first page's ``figure-area``. Now
    every given circle is a path of explicit arcs, whole or ending on the drawing frame (or on the figure area's
    top, under the answer boxes), never a clipped ``<circle>``; and every clip path id is defined once in
    sheets.html."""
    ids = re.findall(r'<clipPath id="([^"]+)"', six.files["sheets.html"])
    assert ids and len(ids) == len(set(ids))
    circles = 0
    for name, svg in six.files.items():
        if not (name.startswith("sheets/") and name.endswith(".svg")) or 'id="givens"' not in svg:
            continue
        givens = svg[svg.index('id="givens"'):]
        assert not [r for r in re.findall(r'<circle[^>]*\br="(\d+)"', givens) if int(r) >= 100], name   # dots only
        h, w, x0, y0 = (float(v) / U for v in re.search(r'<rect fill="none" height="(\d+)" stroke="#000" '
                                                      r'stroke-width="\d+" width="(\d+)" x="(\d+)" y="(\d+)"',
                                                      svg).groups())
        top = float(re.search(r'<clipPath id="[^"]+"><rect height="\d+" width="\d+" x="\d+" y="(\d+)"',
                              svg).group(1)) / U
        for d in re.findall(r'<path class="given-circle" d="([^"]+)"', svg):
            circles += 1
            moves = [tuple(map(int, m)) for m in _MOVE.findall(d)]
            ends = [tuple(map(int, m)) for m in _ARC_END.findall(d)]
            if len(moves) == 1 and ends[-1] == moves[0]:
                continue                                               # drawn whole
            for x, y in moves + ends:
                x, y = x / U, y / U
                on_frame = min(abs(x - x0), abs(x - (x0 + w)), abs(y - (y0 + h))) < 0.02
                assert on_frame or abs(y - top) < 0.02, (name, x, y)
    assert circles > 0
