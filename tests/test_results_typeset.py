"""Results read as a textbook prints them (issue 11, hlook11 items 4, 5, 6, 16, 17, 18, 44, 47): every rule is
checked over every recipe or over the whole gallery, so a defect that comes back anywhere fails here.

- a vector result prints as the function of the cam angle it is (``s(0°, 15°) = 0.000, 2.000 mm``), a point
  as ``(x, y)``, a union of intervals as mathematics writes it, an empty one as ``none``/``无``, a yes/no answer's
  printed value as yes/no (never ``textbook 0``);
- each answer of a recipe has its own printed symbol (γmin and the working range's γw,min; x_p and x_a …);
- identifiers are typeset: no ``vmax``, ``rr,max``, ``φslow``, ``C2,3``, point ``min`` left outside a subscript;
- no ``-0.000`` / ``-0.00 %``; the Warnings quote a value with the Results' 3 decimals; α′ for the return;
- Chinese inside an English text sits in full-width brackets （）;
- the protocol's first step of a design by K ends with its formula (``θ = 180°(K − 1)/(K + 1) = 16.364°``).
The JSON answer names are a contract: only their printing changes."""
from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

from geomcon.recipes import RECIPES
from geomcon.render.results import name_of, result_line, shown_printed, shown_value

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SUBSCRIPT = re.compile(r"<tspan[^>]*font-size[^>]*>[^<]*</tspan>")
"""A subscript run (the only tspans given their own font size)."""
RAW = re.compile(r"[A-Za-zα-ωΑ-Ω0-9′\x00],[a-zα-ω]|\bsE\d|\bF[fn]\b|[A-Z\x00]\d*,\d"
                 r"|(?<=[A-Za-zα-ω0-9′])(?:max|min|slow|quick)\b|^(?:max|min)$")
"""An identifier left raw outside a subscript (``\\x00`` stands for a subscript): ``rr,max``, ``ω2,max`` (comma
outside), ``vmax``, ``φslow``, ``C2,3``, ``Ff``, ``sE1``, a point called ``min``."""


def _svgs() -> list[Path]:
    files = sorted(GALLERY.rglob("*.svg"))
    assert len(files) > 250
    return files


def _texts(path: Path) -> list[tuple[str, str]]:
    """Each ``<text>`` of an SVG: (its text outside subscripts, subscripts as ``\\x00``; its whole text)."""
    out = []
    for m in re.finditer(r"<text[^>]*>(.*?)</text>", path.read_text(encoding="utf-8"), re.S):
        inner = m.group(1)
        main = html.unescape(re.sub(r"<[^>]+>", "", SUBSCRIPT.sub("\x00", inner)))
        out.append((main, html.unescape(re.sub(r"<[^>]+>", "", inner))))
    return out


@pytest.fixture(scope="module")
def texts() -> dict[str, list[tuple[str, str]]]:
    return {str(p.relative_to(GALLERY)): _texts(p) for p in _svgs()}


def test_every_recipe_prints_each_numeric_answer_with_its_own_symbol():
    """hlook11 item 5: γmin twice in 100-01…04, ΔC1 twice in 100-05/06, x and y twice in 200-05/14, l twice in
    200-07, αmax twice in 001-25…29."""
    dupes = {}
    for name in RECIPES:
        symbols = [name_of(q.name, name).symbol for q in RECIPES[name].answers if q.unit != "bool"]
        symbols = [s for s in symbols if s]
        seen = {s for s in symbols if symbols.count(s) > 1}
        if seen:
            dupes[name] = sorted(seen)
    assert not dupes


def test_no_visible_text_leaves_an_identifier_outside_its_subscript(texts):
    """hlook11 items 6 and 44: vmax, amax, lmin, rr,max (comma outside the subscript), r0,ρ, ω2,max, φslow,
    C2,3, Ff/Fn, a point called "min"; the worksheet's γmin, αmax in statements and answer boxes."""
    raw = {f"{name}: {main.replace(chr(0), '·')}" for name, ts in texts.items() for main, _ in ts if RAW.search(main)}
    assert not raw, sorted(raw)[:20]


def test_the_worksheet_types_its_point_names_and_symbols(texts):
    """hlook11 item 44: "C1", "DC1", "AC1 = BC − AB", "r0" in the statements were printed without subscripts."""
    raw = {f"{name}: {main}" for name, ts in texts.items() if name.startswith("worksheet/")
           for main, _ in ts[3:] if re.search(r"(?<![A-Za-z])(?:[A-Z]+\d|r0)\b(?! (?:portrait|landscape))", main)}
    assert not raw, sorted(raw)[:20]


def test_no_negative_zero_and_no_python_lists(texts):
    """hlook11 items 4 and 16: ``-0.00 %``, ``-0.000`` in a vector, ``[[190.000, 290.000]] mm``, ``[] mm``."""
    bad = re.compile(r"-0\.0+(?![0-9]*[1-9])(?![0-9])|\[\[|= \[\]|= \[-?\d[^\]]*,[^\]]*,")
    hits = {f"{name}: {full}" for name, ts in texts.items() for _, full in ts if bad.search(full)}
    assert not hits, sorted(hits)[:20]


def test_the_return_is_alpha_prime_everywhere(texts):
    """hlook11 item 17: the Results print α′max for the return, the Warnings printed "αmax of the return"."""
    hits = {f"{name}: {full}" for name, ts in texts.items() for _, full in ts
            if re.search(r"αmax of the return|回程最大压力角 αmax", full)}
    assert not hits, sorted(hits)[:10]


def test_chinese_in_english_text_sits_in_full_width_brackets(texts):
    """hlook11 item 18: the law charts' titles read "正弦加速度(摆线)运动规律", "impacts: soft (柔性冲击)"; the
    Warnings' hint "(增大基圆或减小滚子半径)". Problem titles (the problem file's words) are left as written."""
    ascii_zh = re.compile(r"\([^()]*[\u4e00-\u9fff][^()]*\)")
    hits = {f"{name}: {full}" for name, ts in texts.items() if "_motion" in name or name.startswith("law_")
            for _, full in ts if ascii_zh.search(full)}
    hits |= {f"{name}: {full}" for name, ts in texts.items() for _, full in ts
             if "(增大" in full or "减小滚子半径)" in full}
    assert not hits, sorted(hits)[:10]


def test_the_first_step_of_a_design_by_k_ends_with_its_formula(texts):
    """hlook11 item 47: "with K =\\n1.2 = 16.364°" read as K = 1.2 = 16.364°; the s–δ diagram was said to be
    "beside the cam" on a sheet where it is not."""
    hits = {f"{name}: {full}" for name, ts in texts.items() for _, full in ts
            if re.search(r"with K = [\d.]+$|K = [\d.]+ = |beside the cam|在凸轮旁", full)}
    assert not hits, sorted(hits)[:10]


def test_results_lines_read_as_mathematics():
    """Item 4, line by line: a list at the asked cam angles, a point, a set of intervals, an empty set, a yes/no
    printed by the textbook as 0/1, a value that rounds to zero."""
    assert result_line("s", (0.0, 2.0), "mm[]", at=(0.0, 15.0)) == "s(0°, 15°) = 0.000, 2.000 mm"
    assert result_line("alpha", (8.411,), "deg[]", at=(100.0,)) == "α(100°) = 8.411°"
    assert result_line("A", (64.375, 60.0), "mm[]") == "A = (64.375, 60.000) mm"
    assert result_line("phi", (-137.015, 163.5, 0.0), "deg[]") == "φ1 = -137.015°, φ2 = 163.500°, φ3 = 0.000°"
    assert result_line("immovable", [(610.0, float("inf"))], "interval[]") == "immovable = [610.000, ∞) mm"
    assert result_line("double_crank", [], "interval[]", lang="zh") == "双曲柄机构的杆长范围：无"
    assert shown_printed(0, "bool") == "no" and shown_printed(1, "bool", "zh") == "是"
    assert shown_value((-1e-9, 0.0), "mm/s[]") == "0.000, 0.000 mm/s"
