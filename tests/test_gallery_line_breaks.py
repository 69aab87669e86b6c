"""Every wrapped text line of the gallery breaks where a textbook would (issue 11, reviewer of session g): no line
ends with an opening bracket or a bracket's short first word ("… exceeds the allowance 45° (at" / "δ = 5.000°)",
"（即"), none starts with a bracket's one-character last word ("（δ = 5.000°" / "处）"), with closing punctuation
or with a unit that belongs to the number before it ("360° = 450" / "mm", "-28.78" / "%"), and an operator set
between spaces never ends or begins a line ("δ =" / "120°").

The rules are checked over every ``<text>`` line of every SVG sheet and of every player (HTML) of the gallery, the
worksheets' too, in both languages; the point labels, the angle marks' values, the diagrams' tick numbers and a
worksheet's answer fields are not wrapped text and are left out."""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

from geomcon.render.zh_words import words

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SVG_NS = "{http://www.w3.org/2000/svg}"
NOT_WRAPPED = ("label", "mark-text", "num", "delta-tick", "h-tick")
"""Classes of texts that are not wrapped lines (a label, an angle's value, a tick number)."""

UNIT = re.compile(r"^(?:mm/mm|mm/s²|mm/s|m/s²|m/s|rad/s²|rad/s|rad|rpm|r/min|\(mm/s²?\)/mm|mm|cm|°|张)"
                  r"(?=$|[\s,;:.)\]）；，：。、])")
"""A line that begins with a unit: the unit of a number that ended the line before."""
CLOSING = re.compile(r"^(?:[)\]）］】」』》”’，。、；：！？,;:!?%‰]|…(?!\w))")
"""A line that begins with closing punctuation or a per cent sign (an ellipsis too, but not one that opens a
caption continuing another: "…and in the s–δ diagram")."""
LAST_CHAR = re.compile("^[\u3400-\u9fff\uf900-\ufaff][）)]")
"""A line that begins with a bracket's one-character last word: "（δ = 5.000°" / "处）"."""
OPERATOR = re.compile(r"(?:^|\s)[=+−×÷≤≥<>≈≠]$|^[=+−×÷≤≥<>≈≠](?:\s|$)|第$")
"""A line that ends or begins with an operator set between spaces, or ends with an ordinal's 第."""
OPENERS, CLOSERS = "([（［【「『《“‘", ")]）］】」』》”’"
HAN = re.compile("[\u3400-\u9fff\uf900-\ufaff]+")


def ends_in_open_bracket(line: str) -> bool:
    """Whether ``line`` ends inside a bracket after at most its short first word: the bracket alone, a Latin
    word of at most 4 characters ("(at", "(the", "(C1", "[190,") or a single Chinese word ("（即", "（位于").

    >>> [ends_in_open_bracket(s) for s in ("allowance 45° (at", "（位于", "(a) b", "（位于直线", "(intersection")]
    [True, True, False, False, False]
    """
    at = max(line.rfind(c) for c in OPENERS)
    if at < 0:
        return False
    inner = line[at + 1:].strip().rstrip(",;:，、")
    if any(c in CLOSERS for c in inner) or " " in inner:
        return False
    if HAN.search(inner):
        return HAN.fullmatch(inner) is not None and len(words(inner)) == 1
    return len(inner) <= 4


CLOSING_WORD = re.compile("^[^\\s(\\[\u2e80-\u9fff\uf900-\uffef]+[)\\]]")
"""A line that begins with a bracket's closing Latin word: "analytic)", "form) = 29.995°"."""
OPENING_WORD = re.compile("[(\\[][^\\s)\\]\u2e80-\u9fff\uf900-\uffef]*$")
"""A line that ends with a bracket's opening mark and at most its first Latin word: "(=", "(closed"."""


def splits_a_short_bracket(before: str, line: str) -> bool:
    """Whether the break between the lines ``before`` and ``line`` splits a bracket of at most two Latin words: 400-05's
    "… (=" / "analytic)", 001-08's "(closed" / "form) = 29.995°" (a longer bracket may break, at a space).

    >>> splits_a_short_bracket("P13 = (0.000, 116.862) mm (=", "analytic)")
    True
    >>> splits_a_short_bracket("γ at the change point (closed", "form) = 29.995°")
    True
    >>> splits_a_short_bracket("(the links cannot", "move)"), splits_a_short_bracket("a (b)", "c)")
    (False, False)
    """
    return bool(OPENING_WORD.search(before.rstrip()) and CLOSING_WORD.match(line.strip()))


def broken_rules(line: str) -> list[str]:
    """The line-break rules ``line`` breaks (none for a good line).

    >>> broken_rules("mm (on sheet 2)"), broken_rules("%, doubtful)"), broken_rules("αmax = 82.151° (at")
    (['begins with a unit'], ['begins with closing punctuation'], ['ends in a bracket'])
    >>> broken_rules("δ ="), broken_rules("δ = 5.000°)"), broken_rules("处）；实际廓线")
    (['ends or begins with an operator or ordinal'], [], ["begins with a bracket's one-character last word"])
    """
    s = line.strip()
    out = []
    if ends_in_open_bracket(s):
        out.append("ends in a bracket")
    if UNIT.match(s):
        out.append("begins with a unit")
    if CLOSING.match(s):
        out.append("begins with closing punctuation")
    if LAST_CHAR.match(s):
        out.append("begins with a bracket's one-character last word")
    if OPERATOR.search(s):
        out.append("ends or begins with an operator or ordinal")
    return out


def sheets(path: Path) -> list[ET.Element]:
    """The SVG roots of a gallery file: the file itself, or each ``<svg>`` a player embeds."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".svg":
        return [ET.fromstring(text)]
    out, depth, start = [], 0, 0
    for m in re.finditer(r"<svg\b|</svg>", text):          # the outermost ones (a key page nests its figure's)
        if m.group() == "</svg>":
            depth -= 1
            if depth == 0:
                out.append(ET.fromstring(text[start:m.end()]))
        else:
            start, depth = (m.start() if depth == 0 else start), depth + 1
    return out


def text_lines(root: ET.Element) -> list[str]:
    """Every wrapped text line of a sheet: each ``<text>``'s characters (its subscripts' included); a
    worksheet's answer fields ("θ =", a box, "°": group ``answers``) are a form, not text, and left out."""
    out = []
    for el in root:
        if el.tag == SVG_NS + "text":
            if not (el.get("class") or "").startswith(NOT_WRAPPED):
                out.append("".join(el.itertext()))
        elif el.get("id") != "answers":
            out += text_lines(el)
    return out


def test_no_line_of_the_gallery_breaks_inside_a_bracket_or_between_a_number_and_its_unit():
    files = sorted(f for f in GALLERY.rglob("*") if f.suffix in (".svg", ".html"))
    assert len(files) > 300
    bad: dict[tuple[str, str], str] = {}
    lines = 0
    for f in files:
        for root in sheets(f):
            before = ""
            for line in text_lines(root):
                lines += 1
                for rule in broken_rules(line):
                    bad.setdefault((rule, line.strip()), str(f.relative_to(GALLERY)))
                if splits_a_short_bracket(before, line):
                    bad.setdefault(("splits a two-word bracket", f"{before.strip()} / {line.strip()}"),
                                   str(f.relative_to(GALLERY)))
                before = line
    assert lines > 20000
    assert not bad, "\n".join(f"{f}: {rule}: {line!r}" for (rule, line), f in sorted(bad.items()))


def test_the_rules_catch_the_breaks_the_reviewer_saw():
    # 000-08's warnings and 100-01's captions before the fix, and 000-04's Results line
    for line in ("αmax of the rise = 82.151° exceeds the allowance 45° (at", "(at", "mm", "%, doubtful)",
                 "undercut: rr = 5 ≥ ρmin = 1.455 of the pitch curve (at", "作位移线图 ψ–δ：δ 轴，360° 对应 450 mm（画",
                 "（即", "°)", "crank-rocker: BC in [190,"):
        assert broken_rules(line), line
    assert splits_a_short_bracket("P13 = (0.000, 116.862) mm (=", "analytic)")      # 400-05's narrow column
