"""Chinese lines break between words (issue 11, review item 7: "最小传动\\n角", "滑枕行\\n程", "第\\n一固定铰链", a
protocol line ending after "曲" with "柄" on the next), and no line starts with closing punctuation or ends with
opening punctuation.

Every text the gallery wraps is recorded while every problem's sheets are rendered in Chinese and in both
languages, with the worksheet and the grading example: the protocols, the step captions, the results, the
warnings and the worksheets' statements."""
from __future__ import annotations

from pathlib import Path

import pytest

from geomcon.gallery import _classwork, gallery_page, problem_files
from geomcon.problems import load_problem
from geomcon.render import labels
from geomcon.render.protocol import _info_lines
from geomcon.render.zh_words import SINGLE, WORDS, is_ideograph, words
from geomcon.solve import solve

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"
NO_START = tuple("，。、；：？！）】》」』”’…,;:)!?%‰")
"""What a line may not begin with (closing punctuation, the ellipsis, a per cent sign), as Chinese typesetting rules."""
NO_END = tuple("（【《「『“‘(")
"""What a line may not end with (opening punctuation)."""


@pytest.fixture(scope="module")
def wrapped() -> dict[str, set[tuple[str, ...]]]:
    """Every text wrapped while the gallery's sheets are rendered in ``zh`` and ``both``: text → its line sets."""
    seen: dict[str, set[tuple[str, ...]]] = {}
    original = labels._wrap

    def record(text: str, width: float, size: float, last_reserve: float) -> tuple[str, ...]:
        out = original(text, width, size, last_reserve)
        seen.setdefault(text, set()).add(out)
        return out

    labels._wrap = record
    _info_lines.cache_clear()               # result lines wrapped by earlier tests come back through wrap()
    try:
        for path in problem_files(PROBLEMS):
            sol = solve(load_problem(path))
            for lang in ("zh", "both"):
                sol.sheets(gallery_page(lang))
        _classwork(PROBLEMS)
    finally:
        labels._wrap = original
    return seen


def _han_runs(text: str) -> list[tuple[int, str]]:
    """(start, run) of each run of Chinese ideographs in ``text``."""
    out, i = [], 0
    while i < len(text):
        if is_ideograph(text[i]):
            j = i
            while j < len(text) and is_ideograph(text[j]):
                j += 1
            out.append((i, text[i:j]))
            i = j
        else:
            i += 1
    return out


def breaks(text: str, lines: tuple[str, ...]) -> list[int]:
    """The offsets in ``text`` where ``lines`` break it without a space (a break at a space is always allowed).

    >>> breaks("以 A 为圆心作圆", ("以 A 为", "圆心作圆")), breaks("以 A 为圆心作圆", ("以 A 为圆", "心作圆"))
    ([5], [6])
    >>> breaks("作 AB 的中垂线", ("作 AB", "的中垂线"))
    []
    """
    out, pos = [], 0
    for prev, line in zip(lines, lines[1:]):
        if not prev or not line:
            continue
        start = text.index(prev, pos)
        end = start + len(prev)
        nxt = text.index(line, end)
        if nxt == end:
            out.append(end)
        pos = end
    return out


def inside_a_word(text: str, at: int) -> str | None:
    """The word of ``text`` (:func:`words` of its ideograph run) that a break at offset ``at`` cuts, or None."""
    for start, run in _han_runs(text):
        if start < at < start + len(run):
            i = start
            for w in words(run):
                if i < at < i + len(w):
                    return w
                i += len(w)
    return None


def test_the_recording_holds_the_chinese_protocols_and_results(wrapped):
    chinese = [t for t in wrapped if _han_runs(t)]
    assert len(chinese) > 2000
    assert sum(1 for t in chinese for ls in wrapped[t] if len(ls) > 1) > 500        # many are broken


def test_no_chinese_line_breaks_inside_a_word(wrapped):
    cut = {}
    for text, sets in wrapped.items():
        for lines in sets:
            for at in breaks(text, lines):
                w = inside_a_word(text, at)
                if w is not None:
                    cut.setdefault(w, " | ".join(lines))
    assert not cut, cut


def test_no_line_starts_with_closing_or_ends_with_opening_punctuation(wrapped):
    bad = []
    for text, sets in wrapped.items():
        for lines in sets:
            for a, b in zip(lines, lines[1:]):
                if a.rstrip().endswith(NO_END) or b.lstrip().startswith(NO_START):
                    bad.append((a, b))
    assert not bad, bad[:10]


def test_the_glossary_knows_every_word_of_our_chinese_texts(wrapped):
    # a character left alone by the glossary that is not a word by itself is a word the glossary is missing
    # ("连杆" missing would leave 连 alone); SINGLE lists only characters the texts use alone
    alone: dict[str, str] = {}
    used: set[str] = set()
    for text in wrapped:
        for _, run in _han_runs(text):
            for w in words(run):
                if len(w) == 1:
                    used.add(w)
                    if w not in SINGLE:
                        alone.setdefault(w, run)
    assert not alone, alone
    assert used == SINGLE, sorted(SINGLE - used)


@pytest.mark.parametrize("text, word", [("最小传动角", "传动角"), ("滑枕行程", "行程"), ("构件 3 的角速度", "角速度"),
                                        ("第一固定铰链", "第一"), ("作曲柄圆", "曲柄"), ("运动失真（根切）", "根切")])
def test_the_words_the_review_saw_cut_are_whole(text, word):
    assert any(word in words(run) for _, run in _han_runs(text))


def test_a_narrow_column_breaks_chinese_between_words_only():
    text = "以曲柄转动中心为圆心、曲柄长为半径作圆交导路于滑块铰链位置"
    for width in (6.0, 9.0, 12.0, 15.0, 20.0, 30.0):
        lines = tuple(labels.wrap(text, width, 2.4))
        assert "".join(lines) == text
        assert all(inside_a_word(text, at) is None for at in breaks(text, lines)), lines


def test_the_glossary_s_words_are_chinese_and_no_longer_than_the_segmenter_looks():
    from geomcon.render.zh_words import _LONGEST
    assert all(all(is_ideograph(c) for c in w) and 2 <= len(w) <= _LONGEST for w in WORDS)
    assert all(len(c) == 1 and is_ideograph(c) for c in SINGLE)
