"""Issue 11, ``--lang zh|en|both``: the problem's title. A problem file's ``title_zh`` (schema-checked) titles its
sheets, players and text in Chinese; ``both`` prints the two titles, English above Chinese; a file without one
falls back to English with a note. English titles hold no Chinese (the Chinese name is ``title_zh``'s: the old
"Slotting machine (插床)" glosses were used in 6 of 95 titles)."""
from __future__ import annotations

import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from geomcon.gallery import gallery_page, problem_files
from geomcon.problems import LIMITS, load_problem, problem_from_dict, title_in
from geomcon.solve import solve

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "problems"
GALLERY = ROOT / "gallery"
SVG = "{http://www.w3.org/2000/svg}"
HAN = re.compile("[\u4e00-\u9fff]")
ALL = sorted(PROBLEMS.glob("*.toml")) + sorted((PROBLEMS / "cycles").glob("*.toml"))
GOOD = 'recipe = "crank_rocker.extremes"\ntitle = "Crank-rocker"\n%s[given]\nAB = 50\nBC = 70\nCD = 80\nAD = 90\n'


def _title_lines(svg: str) -> list[str]:
    """The title block's title lines (``tb-0-0``: one, or English then Chinese)."""
    root = ET.fromstring(svg)
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text") if "tb-0-0" in (t.get("class") or "").split()]


def _typeset(title: str) -> str:
    """A title as a sheet prints it (:func:`geomcon.render.serial.typeset`: U+22C5 for a product's dot)."""
    from geomcon.render.serial import typeset
    return typeset(title)


def _html(title: str) -> str:
    """A title as the player's page writes it (typeset: U+22C5 for a product's dot, U+2212 for minus; escaped)."""
    import html
    from geomcon.render.serial import typeset
    return html.escape(typeset(title))


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "geomcon.cli", *args], capture_output=True, text=True, cwd=ROOT)


@pytest.mark.parametrize("path", ALL, ids=[p.stem for p in ALL])
def test_every_problem_has_a_chinese_title_and_an_english_title_without_chinese(path):
    import tomllib
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    zh, en = data.get("title_zh", ""), data["title"]
    assert HAN.search(zh), f"{path.name}: title_zh {zh!r}"
    assert not HAN.search(en), f"{path.name}: the English title holds Chinese ({en!r}): the Chinese name is title_zh's"


def test_every_gallery_zh_sheet_is_titled_in_chinese():
    """Every problem's sheets in Chinese (``geomcon gallery --lang zh``): the title block holds title_zh only."""
    page = gallery_page("zh")
    for path in problem_files(PROBLEMS):
        sol = solve(load_problem(path))
        sheets = sol.sheets(page)
        for n, svg in enumerate(sheets, 1):
            lines = _title_lines(svg)              # a long title wraps to two lines (issue 11, hsmall11m)
            assert len(lines) <= 2 and "".join(lines) == _typeset(sol.problem.title_zh), (path.name, n, lines)
        assert f"<title>{_html(sol.problem.title_zh)}</title>" in sol.html(page, sheets), path.name


def test_every_gallery_sheet_in_both_languages_prints_the_two_titles():
    """The gallery (both languages): English above Chinese on every problem's sheet, its s–v–a sheet and the
    cycles' plots; the player's page title holds both."""
    seen = 0
    for path in ALL:
        p = load_problem(path) if path.parent == PROBLEMS else None
        data = __import__("tomllib").loads(path.read_text(encoding="utf-8"))
        for svg in sorted(GALLERY.glob(f"{path.stem}*.svg")):
            if svg.stem[len(path.stem):] not in ("", "_motion") and not re.fullmatch(r"(_motion)?-\d+",
                                                                                     svg.stem[len(path.stem):]):
                continue                                 # another problem whose name begins as this one's
            assert _title_lines(svg.read_text(encoding="utf-8")) == [_typeset(data["title"]), _typeset(data["title_zh"])], \
                svg.name
            seen += 1
        if p is not None:
            page = (GALLERY / f"{path.stem}.html").read_text(encoding="utf-8")
            assert f"<title>{_html(data['title'] + '  ' + data['title_zh'])}</title>" in page, path.name
    assert seen > 200                                    # 249 sheets on 2026-11-27


def test_the_title_in_each_language():
    p = load_problem(PROBLEMS / "001-08_crank_rocker.toml")
    assert p.title_in("en") == p.title and p.title_in("zh") == p.title_zh == "曲柄摇杆机构 50/70/80/90：极限位置、K 与 γmin"
    assert p.title_in("both") == f"{p.title}\n{p.title_zh}"
    assert title_in("Crank-rocker", "", "zh") == title_in("Crank-rocker", "", "both") == "Crank-rocker"


def test_another_solution_says_so_in_each_language():
    sol = solve(load_problem(PROBLEMS / "001-10_crank_rocker_design_coupler.toml"))
    other = sol.as_solution(2)
    count = len(sol.solution_values)
    assert other.title("zh") == f"{sol.problem.title_zh}——解 2（共 {count} 个）"
    assert other.title("both") == f"{sol.problem.title} — solution 2 of {count}\n{sol.problem.title_zh}——解 2（共 {count} 个）"
    assert sol.title("zh") == sol.problem.title_zh


BAD = {
    "not a string": ("title_zh = 5\n", "'title_zh' must be a string, got 5"),
    "too long": (f'title_zh = "{"曲柄" * (LIMITS["title_zh_chars"] // 2 + 1)}"\n',
                 f"'title_zh' has {LIMITS['title_zh_chars'] + 2} characters; a title is at most "
                 f"{LIMITS['title_zh_chars']}"),
    "no Chinese": ('title_zh = "Crank-rocker"\n', "'title_zh' holds no Chinese character"),
    "half-width": ('title_zh = "曲柄摇杆机构: 极限位置"\n', "'title_zh' uses half-width punctuation next to Chinese: "
                                                         "write '曲柄摇杆机构：极限位置'"),
    "two lines": ('title_zh = "曲柄\\n摇杆"\n', "'title_zh' must be one line"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_a_bad_title_zh_is_one_error_line_and_exit_2(tmp_path, case):
    text, msg = BAD[case]
    f = tmp_path / "p.toml"
    f.write_text(GOOD % text, encoding="utf-8")
    r = _run("solve", str(f), "--lang", "zh")
    assert r.returncode == 2 and r.stdout == "", (r.returncode, r.stdout)
    assert r.stderr.startswith(f"error: {f}: {msg}") and r.stderr.count("\n") == 1, r.stderr


def test_a_bad_title_zh_of_a_cycle_problem_or_a_worksheet_is_refused_too():
    from geomcon.errors import ProblemError
    import tomllib
    from geomcon.kinematics.problem import cycle_from_dict
    from geomcon.worksheet.spec import parse_spec
    cycle = tomllib.loads((PROBLEMS / "cycles" / "000-09_slotter_cycle.toml").read_text(encoding="utf-8"))
    assert cycle_from_dict(cycle, name="c").title_zh == "插床：曲柄转一周时刀具的运动"
    with pytest.raises(ProblemError, match="'title_zh' must be a string"):
        cycle_from_dict({**cycle, "title_zh": 3}, name="c")
    with pytest.raises(ProblemError, match="'title_zh' holds no Chinese"):
        parse_spec('title_zh = "Guide bar"\n[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n'
                   '[exercise.given]\nAB = 100\nAC = 290\n')


def test_without_title_zh_a_chinese_sheet_falls_back_to_english_and_says_so(tmp_path):
    f = tmp_path / "p.toml"
    f.write_text(GOOD % "", encoding="utf-8")
    r = _run("solve", str(f), "--lang", "zh", "--svg", str(tmp_path / "p.svg"))
    assert r.returncode == 0 and r.stderr == f"note: {f}: no title_zh: the title stays in English\n", r.stderr
    assert _title_lines((tmp_path / "p.svg").read_text(encoding="utf-8")) == ["Crank-rocker"]
    assert r.stdout.startswith("p: crank_rocker.extremes — Crank-rocker\n")
    r = _run("solve", str(f), "--lang", "both")
    assert r.returncode == 0 and r.stderr == ""                 # both: the English title is a title of both
    f.write_text(GOOD % 'title_zh = "曲柄摇杆机构"\n', encoding="utf-8")
    r = _run("solve", str(f), "--lang", "zh")
    assert r.returncode == 0 and r.stderr == "" and r.stdout.startswith("p: crank_rocker.extremes — 曲柄摇杆机构\n")


def test_the_json_carries_the_chinese_title():
    import json
    data = json.loads((GALLERY / "001-08_crank_rocker.json").read_text(encoding="utf-8"))
    assert data["title_zh"] == "曲柄摇杆机构 50/70/80/90：极限位置、K 与 γmin"


def test_a_worksheet_prints_its_title_in_the_page_s_language():
    from types import SimpleNamespace as NS
    from geomcon.worksheet.sheets import header_lines
    from geomcon.worksheet.spec import parse_spec
    spec = parse_spec('title = "Guide bar"\ntitle_zh = "导杆机构"\n[[exercise]]\nrecipe = "guide_bar.extremes"\n'
                      'ask = ["theta"]\n[exercise.given]\nAB = 100\nAC = 290\n')
    assert [spec.title_in(lg) for lg in ("en", "zh", "both")] == ["Guide bar", "导杆机构", "Guide bar  导杆机构"]
    p = NS(lang="zh", title=spec.title_in("zh"), part="", ex=NS(n=1), count=1, variant=NS(scale="1:2"),
           lay=NS(sheet="A4 portrait"), student=NS(name="", id="7"), code="AB")
    assert header_lines(p)[0] == "导杆机构" and header_lines(p, key=True)[0] == "答案 — 导杆机构"


def test_no_title_line_of_a_sheet_in_both_languages_is_below_the_smallest_text():
    from geomcon.render.page import MIN_TEXT
    svg = (GALLERY / "001-08_crank_rocker.svg").read_text(encoding="utf-8")
    sizes = [float(t.get("font-size")) for t in ET.fromstring(svg).iter(f"{SVG}text")
             if "tb-0-0" in (t.get("class") or "")]
    assert len(sizes) == 2 and min(sizes) >= MIN_TEXT


def test_a_worksheet_header_s_title_never_runs_into_its_exercise_line():
    """The gallery's worksheet (both languages: "Linkages and cams — worksheet 3  连杆机构与凸轮机构——练习 3") and
    a longer title: the title is set smaller or cut, and ends before "Exercise 题 1/3 · scale …" begins (it ran
    over it once the Chinese title was added)."""
    from geomcon.render.charts import text_boxes
    from geomcon.worksheet import make_worksheet
    from geomcon.worksheet.roster import numbered
    from geomcon.worksheet.spec import load_spec

    def overlaps(svg: str) -> bool:
        head = re.search(r'<g id="header">.*?</g>', svg, re.S).group(0)
        (tx0, _, tx1, _), (ex0, _, _, _) = text_boxes(head)[:2]
        return tx0 + (tx1 - tx0) * 1.12 > ex0                      # the title is bold: 1.12 times as wide

    pages = sorted((GALLERY / "worksheet").rglob("*.svg"))
    assert pages and not [p.name for p in pages if overlaps(p.read_text(encoding="utf-8"))]
    spec = load_spec(ROOT / "tests" / "data" / "worksheet_class.toml")
    long = type(spec)(spec.name, spec.title * 3, spec.seed, spec.exercises, spec.sha256, spec.title_zh * 2)
    files = make_worksheet(long, numbered(1), lang="both").files
    assert not [k for k, v in files.items() if k.endswith(".svg") and overlaps(v)]
