"""How the gallery's text lines break (review items 7 and 47): a result's Chinese gloss is not broken when it
fits a line; no line ends with an opening bracket or an operator set between spaces ("K =\\n1.2", "运动失真（\\n根切）"),
and none starts with a closing bracket or such an operator ("(K +\\n1)")."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

GALLERY = Path(__file__).resolve().parents[1] / "gallery"
SVGS = sorted(GALLERY.glob("*.svg"))
CJK = re.compile(r"[\u2e80-\u9fff\uff00-\uffef]")
OPERATORS = ("=", "+", "−", "×", "≤", "≥", "≈")


def _lines(svg: str, classes: tuple[str, ...]) -> list[tuple[str, str]]:
    """(class, text) of each text line of those classes, in document order, tags stripped."""
    out = []
    for m in re.finditer(r'<text([^>]*)>(.*?)</text>', svg, re.S):
        cls = re.search(r'class="([^"]*)"', m.group(1))
        if cls and cls.group(1) in classes:
            out.append((cls.group(1), re.sub(r"<[^>]+>", "", m.group(2))))
    return out


def test_the_gallery_has_chinese_result_lines():
    assert sum(1 for p in SVGS for c, t in _lines(p.read_text(), ("info",)) if CJK.search(t)) > 100


@pytest.mark.parametrize("path", SVGS, ids=lambda p: p.stem)
def test_a_result_s_chinese_gloss_is_one_line(path):
    lines = [t for _, t in _lines(path.read_text(), ("info",))]
    for before, after in zip(lines, lines[1:]):
        split = CJK.match(after.strip()[:1] or " ") and CJK.search(before.strip()[-1:] or " ")
        assert not split, (path.name, before, after)


@pytest.mark.parametrize("path", SVGS, ids=lambda p: p.stem)
def test_no_line_breaks_at_an_operator_or_inside_brackets(path):
    for cls, t in _lines(path.read_text(), ("info", "warning", "en", "zh")):
        s = t.strip()
        if not s:
            continue
        assert not s.endswith(("（", "(")), (path.name, cls, t)
        assert not s.startswith(("）", ")")), (path.name, cls, t)
        assert not any(s.endswith(" " + op) for op in OPERATORS), (path.name, cls, t)
        assert not any(s.startswith(op + " ") for op in OPERATORS), (path.name, cls, t)
