"""Chinese text uses full-width punctuation (issue 12): every zh statement template of every recipe, every word
a statement is built from, every printed answer name, and statements rendered with numbers filled in."""
from __future__ import annotations

import re

import pytest

from geomcon.render.page import zh_punct
from geomcon.render.results import NAMES, RECIPE_NAMES
from geomcon.worksheet import statements as st

def half_width(text: str) -> list[str]:
    """The places in ``text`` where Chinese text uses half-width punctuation: where :func:`zh_punct` (the rule:
    a comma, semicolon, colon, question or exclamation mark touching Chinese, brackets around Chinese or opened
    right after it) would change it. A formula or a point's coordinates after a letter, D(0, 0), stay ASCII."""
    fixed = zh_punct(text)
    if fixed == text:
        return []
    i = next(k for k, (a, b) in enumerate(zip(text, fixed)) if a != b) if len(fixed) == len(text) else 0
    return [text[max(0, i - 8):i + 8]]


def _zh_words() -> list[tuple[str, str]]:
    out = [(f"{r} {f or '-'}", zh) for r, forms in st.TEMPLATES.items() for f, (_, zh) in forms.items()]
    out += [(f"CHOICE {r}", zh) for r, (_, zh) in st.CHOICE.items()]
    out += [(f"ANSWER_WORDS {k}", zh) for k, (_, zh) in st.ANSWER_WORDS.items()]
    out += [(f"AT_WORDS {k}", zh) for k, (_, zh) in st.AT_WORDS.items()]
    for name in ("LAWS", "FOLLOWERS", "ROTATION"):
        out += [(f"{name} {k}", zh) for k, (_, zh) in getattr(st, name).items()]
    out += [(name, getattr(st, name)[1]) for name in ("ROLLER", "OMEGA_WORDS", "CAM_DRAW")]
    out += [(f"result {k}", n.zh) for k, n in {**NAMES, **{"/".join(k): v for k, v in RECIPE_NAMES.items()}}.items()]
    return out


def test_the_detector_can_fail():
    assert half_width("摇杆长 CD = 90 mm,摆角") and half_width("曲柄(AC > AB)") and half_width("机构?")
    assert not half_width(zh_punct("摇杆长 CD = 90 mm,摆角 ψ = 40°(极限位置 DC1、DC2); K = (1 + x)/2"))


@pytest.mark.parametrize("where, zh", _zh_words(), ids=[w for w, _ in _zh_words()])
def test_every_zh_text_is_full_width(where, zh):
    assert not half_width(zh), f"{where}: {half_width(zh)}"


def test_rendered_statements_are_full_width():
    from tests.test_worksheet_statements import FORMS
    from geomcon.worksheet.accept import Accepted
    from geomcon.worksheet.key import statement
    from geomcon.worksheet.spec import parse_spec
    for (recipe, form), (given, ask) in sorted(FORMS.items()):
        spec = parse_spec(f'[[exercise]]\nrecipe = "{recipe}"\nask = {ask!r}\n[exercise.given]\n{given}\n'.replace("'", '"'))
        ex = spec.exercises[0]
        zh = statement(ex, Accepted(0, ex.given_of(0), None, None, (), True), "zh")
        assert not half_width(zh), f"{recipe} {form}: {half_width(zh)}"
        assert zh.endswith("。") and "，" in zh


def test_a_spec_statement_in_chinese_is_made_full_width():
    from geomcon.worksheet.accept import Accepted
    from geomcon.worksheet.key import statement
    from geomcon.worksheet.spec import parse_spec
    spec = parse_spec('[[exercise]]\nrecipe = "crank_rocker.extremes"\nask = ["theta"]\n'
                      'statement = {en = "AB = {AB}.", zh = "曲柄 AB = {AB} mm,求极位夹角(用作图法)?"}\n'
                      '[exercise.given]\nAB = 50\nBC = 70\nCD = 80\nAD = 90\n')
    ex = spec.exercises[0]
    zh = statement(ex, Accepted(0, ex.given_of(0), None, None, (), False), "zh")
    assert zh == "曲柄 AB = 50 mm，求极位夹角（用作图法）？"


def test_no_line_of_any_gallery_svg_begins_with_closing_punctuation():
    """Chinese line breaking: a wrapped line never starts with ，。、；：）etc. (the warnings block of 001-23a
    once printed a lone '）' on a line of its own)."""
    import xml.etree.ElementTree as ET
    from pathlib import Path

    closing = "，。、；：）」』！？》】"      # full-width; a caption may begin with "…" on purpose ("…and through B1")

    gallery = Path(__file__).resolve().parents[1] / "gallery"
    bad = []
    for p in sorted(gallery.rglob("*.svg")):
        for el in ET.parse(p).getroot().iter("{http://www.w3.org/2000/svg}text"):
            line = "".join(el.itertext()).lstrip()
            if line[:1] and line[0] in closing:
                bad.append((p.name, line[:20]))
    assert not bad, bad[:5]


def test_the_zh_remark_rule_lives_with_the_other_bracket_rules_and_a_text_solve_loads_no_svgwrite():
    """A branch's remark joins a Chinese caption's bracket by a rule of Chinese text (``render/zh.zh_remark``,
    beside ``zh_brackets``; it was ``scene._remark_zh``): the scene takes it from there, and a text solve still
    loads no svgwrite."""
    import subprocess
    import sys
    from pathlib import Path

    import geomcon.scene.scene as scene
    from geomcon.render import zh
    assert scene.zh_remark is zh.zh_remark and not hasattr(scene, "_remark_zh")
    assert zh.zh_remark("交摇杆圆于 C1(曲柄与连杆重叠共线)", "较近的交点") == "交摇杆圆于 C1(曲柄与连杆重叠共线;较近的交点)"
    code = ("import sys; from geomcon.cli import main; main(['solve', 'problems/001-08_crank_rocker.toml', '--lang', "
            "'zh']); print('svgwrite' in sys.modules, 'geomcon.render.zh' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       cwd=Path(__file__).resolve().parents[1])
    assert r.stdout.strip().endswith("False True"), r.stdout[-200:]


def test_a_subscripts_comma_stays_ascii():
    """hlook11m: 001-31b's step 31 printed "ω2，max：取 ε2 = 0 处" (sheet 1, protocol, player): zh_punct took the comma
    inside the subscript ω2,max for punctuation; the statements wrote ρa，min, ω2，max, ε2，max. A comma of a
    subscript (…,min / …,max / max,turn / r0,ρ) is kept, in every gallery text, so rich_runs prints it subscripted."""
    assert zh_punct("ω2,max:取 ε2 = 0 处") == "ω2,max：取 ε2 = 0 处"
    assert zh_punct("压力角 αmax,turn,摆杆 r0,α") == "压力角 αmax,turn，摆杆 r0,α"
    assert zh_punct("在机架线上取 D,OD = e") == "在机架线上取 D，OD = e"      # punctuation still full-width
    from pathlib import Path
    gallery = Path(__file__).parent.parent / "gallery"
    bad = re.compile(r"[A-Za-z0-9](?:</tspan><tspan[^>]*>)?，(?:</tspan><tspan[^>]*>)?(?:min|max|turn)(?![A-Za-z])"
                     r"|r(?:</tspan><tspan[^>]*>)?0，[αρ]")
    hits = [p.name for p in sorted(gallery.rglob("*")) if p.suffix in (".svg", ".html", ".json", ".xml", ".md")
            and bad.search(p.read_text(encoding="utf-8"))]
    assert not hits, hits
