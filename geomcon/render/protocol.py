"""The numbered construction protocol beside the figure: English caption, Chinese caption (smaller, grey),
measured values appended, wrapped and set in balanced columns; the result lines under it.

The layout depends on the captions only, never on values, so every frame of a replay has the same page
size and frame k needs no value of a later step (a measured value gets a fixed reserve at the end of its
caption's last line).

Examples
--------
>>> from geomcon.scene import Scene
>>> sc = Scene("demo")
>>> _ = sc.given("A", 1.0, caption=("Take A", "取 A"), unit="mm")
>>> lay = layout(sc, fig_height=50.0)
>>> [(e.number, e.en, e.zh) for e in lay.entries]
[(1, ['Take A'], ['取 A'])]
>>> format_value(12.50559, "deg"), format_value(101.7374, "mm"), format_value(1.149325, "")
(' = 12.506°', ' = 101.737 mm', ' = 1.149')
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import svgwrite

from ..scene import Role, Scene
from .labels import rich_runs, text_width, wrap
from .page import text, zh_punct
from .results import unit_text
from .serial import Element
from .shapes import add_runs
from .zh import en_remark, zh_remark
from .style import GREY_TEXT, HIGHLIGHT, INFO_SIZE, INK, PROTO_SIZE, PROTO_ZH_SIZE
from .view import fmt

COL_W = 82.0          # column width, paper mm (two fit an A4 portrait frame: 2 × 82 + 6 ≤ 172)
COL_GAP = 6.0
NUM_W = 7.0           # hanging indent of the caption after its number
EN_LH = PROTO_SIZE * 1.28
ZH_LH = PROTO_ZH_SIZE * 1.3
ENTRY_GAP = 0.9
HEAD_SIZE = 3.5       # headings (ISO 3098 series)
HEAD_H = 6.0          # the heading line above the columns
MIN_FIRST = 6          # fewer protocol entries than this under the results: the protocol starts on a new sheet
BLOCK_GAP = 7.0       # paper mm added above the protocol's heading under the results: as far below them as Warnings'
MIN_LIMIT = 185.0     # a protocol may grow this tall beside a smaller figure before taking another column
VALUE_RESERVE = text_width(" = -000.000 mm", PROTO_SIZE)


def format_value(value: Any, unit: str) -> str:
    """A measured value as appended to its caption, with its unit as the Results print it (`` = 12.506°``,
    `` = 269.795 mm/s``; a ratio, unit "", none); "" for anything but a number.

    >>> format_value(269.7951, "mm/s"), format_value(-4.4852, "rad/s"), format_value(True, "")
    (' = 269.795 mm/s', ' = -4.485 rad/s', '')
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return ""
    return f" = {value:.3f}{unit_text(unit)}"


def prints_value(unit: str) -> bool:
    """Whether a measured step of ``unit`` has its value appended (:func:`format_value`: a number): not a list, an
    interval, a point, a yes/no or a word — 001-02's "crank-rocker: BC in [190, 290]" kept room for a value it
    never printed and broke as "BC in" / "[190, 290]".

    >>> prints_value("mm"), prints_value(""), prints_value("interval[]"), prints_value("deg[]"), prints_value("bool")
    (True, True, False, False, False)
    """
    return not unit.endswith("[]") and unit not in ("bool", "choice", "point", "table")


@functools.lru_cache(maxsize=64)
def value_reserve(unit: str) -> float:
    """The room kept at the end of a measured step's last line for its value: :data:`VALUE_RESERVE` (a length
    or an angle of up to three digits), wider for a unit longer than " mm", with room for four digits
    (`` = -2026.255 mm/s²``, 000-03)."""
    if unit in ("", "mm", "deg"):
        return VALUE_RESERVE
    return max(VALUE_RESERVE, text_width(f" = -0000.000{unit_text(unit)}", PROTO_SIZE))


@dataclass(frozen=True)
class Entry:
    """One numbered protocol entry: the frame number, its first step (whose caption and value it shows),
    its wrapped lines, and its position."""

    number: int
    key: str
    unit: str
    measured: bool
    en: list[str]
    zh: list[str]
    column: int
    y: float

    @property
    def height(self) -> float:
        """Height on paper."""
        return entry_height(self.en, self.zh)


def entry_height(en: Sequence[str], zh: Sequence[str]) -> float:
    """Height of an entry with these lines."""
    return len(en) * EN_LH + len(zh) * ZH_LH + ENTRY_GAP


@dataclass(frozen=True)
class Layout:
    """The protocol's entries, its number of columns, and its size on paper (info lines excluded)."""

    entries: list[Entry]
    columns: int
    width: float
    height: float


def _raw(scene: Scene, lang: str, notes: Mapping[str, tuple[str, str]] | None = None
         ) -> list[tuple[int, str, str, bool, list[str], list[str]]]:
    """Every numbered step's wrapped lines: (number, key, unit, measured, first lines, second lines). The
    first lines are English (``en``, ``both``) or Chinese (``zh``; English where a step has no Chinese), the
    second Chinese under English (``both``) or none. ``notes`` (a step's key: English and Chinese words) are
    appended to a caption: where the sheets put what it draws (a cam's s–δ diagram on sheet 2)."""
    raw = []
    for i, group in enumerate(scene.frames(), 1):
        s = group[0]
        en, zh = scene.caption(s.key)
        if notes and s.key in notes:
            note_en, note_zh = (n.strip().strip("()（）") for n in notes[s.key])   # one bracket each side
            en, zh = en_remark(en, note_en), zh_remark(zh, note_zh) if zh else zh
        zh = zh_punct(zh) if zh else zh
        measured = s.role == Role.MEASUREMENT or s.unit in ("mm", "deg")
        first = (zh or en or s.key) if lang == "zh" else (en or s.key)
        reserve = value_reserve(s.unit) if measured and prints_value(s.unit) else 0.0
        first_lines = wrap(first, COL_W - NUM_W, PROTO_SIZE, last_reserve=reserve)
        if measured and len(first_lines) > 1 and not first_lines[-1]:
            first_lines[-1] = _lhs(first_lines[-2])
        zh_lines = wrap(zh, COL_W - NUM_W, PROTO_ZH_SIZE) if zh and lang == "both" else []
        raw.append((i, s.key, s.unit, measured, first_lines, zh_lines))
    return raw


def _lhs(formula: str) -> str:
    """What a formula line equates (``ε_3`` of ``ε_3 = a^t_B3/CB = n_3b_3′⋅μ_a/CB``), to start the line its value
    goes on when the formula leaves no room for it: "ε3 = 14.993 rad/s²", not a line that begins with "=" (000-03's
    ε3 and ε4, 400-01's ε2). "" when the line is no formula.

    >>> _lhs("ε_3 = a^t_B3/CB = n_3b_3′⋅μ_a/CB"), _lhs("Measure the angle")
    ('ε_3', '')
    """
    head, eq, _ = formula.partition(" = ")
    return head if eq and " " not in head.strip() else ""


def layout(scene: Scene, fig_height: float, lang: str = "both") -> Layout:
    """Wrap every numbered step's caption and set the entries in the fewest columns (at most three) whose
    height stays within that of the figure (or :data:`MIN_LIMIT` when the figure is smaller)."""
    raw = _raw(scene, lang)
    heights = [entry_height(r[4], r[5]) for r in raw]
    limit = max(fig_height, MIN_LIMIT)
    for cols in (1, 2, 3):
        starts = _split(heights, cols)
        col_h = _column_heights(heights, starts)
        if max(col_h) <= limit or cols == 3:
            break
    return _placed(raw, heights, starts)


def _placed(raw: Sequence[tuple], heights: Sequence[float], starts: Sequence[int]) -> Layout:
    """The entries ``raw`` set in columns beginning at the indices ``starts``."""
    entries, y, col = [], 0.0, 0
    for j, r in enumerate(raw):
        if col + 1 < len(starts) and j == starts[col + 1]:
            col, y = col + 1, 0.0
        entries.append(Entry(r[0], r[1], r[2], r[3], r[4], r[5], col, y))
        y += heights[j]
    ncols = len(starts)
    col_h = _column_heights(heights, starts)
    return Layout(entries, ncols, ncols * COL_W + (ncols - 1) * COL_GAP, HEAD_H + max(col_h, default=0.0))


def paginate(scene: Scene, width: float, height: float, lang: str = "both", first_skip: float = 0.0,
             notes: Mapping[str, tuple[str, str]] | None = None) -> list[Layout]:
    """The protocol set on sheets of ``width`` × ``height`` paper mm (heading included): in the fewest
    balanced columns that fit one sheet, else column after column, sheet after sheet (an entry is never
    split). Every sheet holds at least one entry, but the first: its columns are ``first_skip`` shorter (the
    results stand above them), and when fewer than :data:`MIN_FIRST` entries would fit under the results, it
    holds none (an empty layout: the protocol starts on the next sheet, as a textbook starts a section).

    Examples
    --------
    >>> from geomcon.recipes.crank_rocker import construct
    >>> sc = construct({"AB": 50, "BC": 70, "CD": 80, "AD": 90}).scene
    >>> [len(p.entries) > 0 for p in paginate(sc, 267.0, 150.0)]
    [True]
    >>> pages = paginate(sc, 90.0, 40.0)
    >>> len(pages) > 1 and sum(len(p.entries) for p in pages) == len(sc.frames())
    True
    >>> [len(p.entries) for p in paginate(sc, 90.0, 100.0, first_skip=80.0)][:2]      # < 6 fit under the results
    [0, 7]
    """
    raw = _raw(scene, lang, notes)
    heights = [entry_height(r[4], r[5]) for r in raw]
    max_cols = max(1, int((width + COL_GAP) // (COL_W + COL_GAP)))
    limit = height - HEAD_H
    for cols in range(1, max_cols + 1):
        starts = _split(heights, cols)
        if max(_column_heights(heights, starts), default=0.0) <= limit - first_skip:
            return [_placed(raw, heights, starts)]
    pages: list[Layout] = []
    j = 0
    while j < len(raw):
        first, starts, acc = j, [j], 0.0
        room = limit - (first_skip if not pages else 0.0)
        while j < len(raw):
            if acc > 0 and acc + heights[j] > room:
                if len(starts) == max_cols:
                    break
                starts.append(j)
                acc = 0.0
            acc += heights[j]
            j += 1
        pages.append(_placed(raw[first:j], heights[first:j], [s - first for s in starts]))
        if len(pages) == 1 and first_skip > 0.0 and j < min(MIN_FIRST, len(raw)):
            return [Layout([], 0, 0.0, 0.0)] + paginate(scene, width, height, lang, notes=notes)
    return pages


def _split(heights: Sequence[float], cols: int) -> list[int]:
    """Start indices of ``cols`` balanced columns (greedy against the mean height)."""
    target = sum(heights) / cols
    starts, acc = [0], 0.0
    for j, h in enumerate(heights):
        if acc > 0 and acc + h / 2 > target and len(starts) < cols:
            starts.append(j)
            acc = 0.0
        acc += h
    return starts


def _column_heights(heights: Sequence[float], starts: Sequence[int]) -> list[float]:
    bounds = list(starts) + [len(heights)]
    return [sum(heights[a:b]) for a, b in zip(bounds, bounds[1:])]


def _line(dwg: svgwrite.Drawing, text: str, x: float, y: float, size: float, fill: str, cls: str) -> Element:
    """A line of text with its subscript runs (``dwg``, the document it goes into, is not needed to make it)."""
    el = Element.named("text", {"x": fmt(x), "y": fmt(y), "font-size": fmt(size), "fill": fill, "class": cls,
                                "xml:space": "preserve"})            # keep the spaces around subscript runs
    add_runs(el, rich_runs(text), size)
    return el


def _value_run(line: Element, value: str) -> Element:
    """The measured value's bold run at the end of ``line``, on the line's baseline: a line ending in a subscript
    (``Measure θ = ∠C1AC2``) left the next run 0.77 mm low, and 001-08's "= 12.506°" printed on the subscript's
    baseline.

    >>> el = _line(None, "θ = ∠C_1AC_2", 0.0, 0.0, 3.5, "#000", "en")
    >>> _value_run(el, " = 12.5°").attribs["dy"], "dy" in _value_run(_line(None, "K", 0.0, 0.0, 3.5, "#000", "en"), "1").attribs
    ('-0.77', False)
    """
    shift = sum(float(t.attribs.get("dy") or 0.0) for t in line.elements)
    run = Element("tspan", value, class_="value", font_weight="bold")
    if abs(shift) > 1e-9:
        run.attribs["dy"] = fmt(-shift)
    return run


def render_protocol(dwg: svgwrite.Drawing, lay: Layout, x: float, y: float, values: Mapping[str, Any],
                    shown: int, current: int | None, lang: str = "both") -> Any:
    """The protocol group: entries 1…``shown`` (each ``<g class="proto" data-step="n">``), entry
    ``current`` highlighted; values taken from ``values`` (measured steps only)."""
    root = dwg.g(id="protocol")
    root.add(_line(dwg, text("Construction protocol", "作图步骤", lang), x, y + HEAD_SIZE, HEAD_SIZE, INK, "proto-head"))
    root.elements[-1].attribs["font-weight"] = "bold"
    top = y + HEAD_H
    for e in lay.entries:
        if e.number > shown:
            break
        is_cur = e.number == current
        ink, grey = (HIGHLIGHT, HIGHLIGHT) if is_cur else (INK, GREY_TEXT)
        g = Element("g", id=f"proto-{e.key}", class_="proto current" if is_cur else "proto")
        g.attribs["data-step"] = str(e.number)
        x0 = x + e.column * (COL_W + COL_GAP)
        yy = top + e.y + PROTO_SIZE
        num = _line(dwg, f"{e.number}.", x0, yy, PROTO_SIZE, ink, "num")
        num.attribs["font-weight"] = "bold"
        g.add(num)
        value = format_value(values.get(e.key), e.unit) if e.measured else ""
        for j, ln in enumerate(e.en):
            el = _line(dwg, ln, x0 + NUM_W, yy, PROTO_SIZE, ink, "en")
            if value and j == len(e.en) - 1:
                el.add(_value_run(el, value if ln else value.lstrip()))     # on a line of its own: "= 14.993 …"
            g.add(el)
            yy += EN_LH
        yy += ZH_LH - EN_LH
        for ln in e.zh:
            g.add(_line(dwg, ln, x0 + NUM_W, yy, PROTO_ZH_SIZE, grey, "zh"))
            yy += ZH_LH
        root.add(g)
    return root


def info_wrap(s: str, width: float, size: float = INFO_SIZE) -> list[str]:
    """A result line wrapped to ``width``: whole when it fits; else its English part and its Chinese gloss (after
    two spaces) each wrapped apart, so that a gloss fitting one line is never broken inside a word (the 400-03
    result "… 构件 3（摇杆或导杆）的角速\n度" reads "…\n构件 3（摇杆或导杆）的角速度").

    >>> info_wrap("ω3 = 1.429 rad/s (= analytic)  构件 3（摇杆或导杆）的角速度", 90.0)
    ['ω3 = 1.429 rad/s (= analytic)', '构件 3（摇杆或导杆）的角速度']
    >>> info_wrap("h = 30.000 mm (= analytic)  行程", 90.0)
    ['h = 30.000 mm (= analytic)  行程']
    """
    return list(_info_lines(s, width, size))


@functools.lru_cache(maxsize=8192)
def _info_lines(s: str, width: float, size: float) -> tuple[str, ...]:
    """:func:`info_wrap`, remembered: a sheet's layout measures the same result lines at every width and in
    every box it tries (:func:`info_height`), then sets them."""
    lines = wrap(s, width, size)
    head, sep, gloss = s.rpartition("  ")
    if len(lines) == 1 or not sep or not head.strip() or not any(ord(c) >= 0x2E80 for c in gloss):
        return tuple(lines)
    return tuple(wrap(head, width, size) + wrap(gloss, width, size))


def info_height(info: Sequence[str], width: float, warnings: Sequence[str] = ()) -> float:
    """Height of the result lines (with their heading) and of the warnings (with theirs) under the protocol."""
    h = 0.0
    for block in (info, warnings):
        if block:
            n = sum(len(_info_lines(s, width, INFO_SIZE)) for s in block)
            h += 4.0 + INFO_SIZE * 1.6 + n * INFO_SIZE * 1.3
    return h


def render_info(dwg: svgwrite.Drawing, info: Sequence[str], x: float, y: float, width: float,
                warnings: Sequence[str] = (), steps: Sequence[int] | None = None, upto: int | None = None,
                lang: str = "both", last: int | None = None, id_: str = "info",
                part: tuple[int, int] | None = None, see: int | None = None) -> Any:
    """The result lines (answers, checks) under the protocol, then the warnings (a printed answer that is
    doubtful, α beyond its allowance, a branch defect, an undercut …) under their own heading.

    ``steps`` (one per result line) is the frame that produces each result, ``last`` the frame of the warnings
    (the last one: they concern the whole answer): a line carries its frame as ``data-step`` (the player shows
    it from that step on), and so does each heading (its block's first frame). The results are set in the
    order of their frames, so the lines shown at any frame are the first ones, packed under their heading; frame
    ``upto`` leaves out the lines of later steps, keeping their room so that every frame has the same page.
    ``id_`` names the group (``warnings`` for the warnings set apart from the results on sheet 1, ``info-2`` for
    results continued in a second box); ``part`` = (k, n) numbers the heading "Results (k/n)" when the results
    are split over n boxes. ``see``: the sheet whose results carry the Chinese words that brief lines leave off
    (sheet 1's brief results in both languages, :meth:`geomcon.solve.Solution.figure_lines`): the Chinese heading
    says so, "结果（释义见第 3 张）" (000-05, 100-07 printed English lines under "结果" with no word of where their
    meanings were).

    Examples
    --------
    >>> import svgwrite, re
    >>> g = render_info(svgwrite.Drawing(), ["a = 1", "b = 2"], 0.0, 0.0, 90.0, ["beware"], steps=[5, 2], last=7)
    >>> [(m[1], m[2]) for m in re.findall(r'class="(info|warning)[^"]*" data-step="(\\d+)"[^>]*>(?:<tspan>)?([^<]*)', g.tostring())]
    [('2', 'Results  结果'), ('2', 'b = 2'), ('5', 'a = 1'), ('7', 'Warnings  警告'), ('7', 'beware')]
    """
    g = dwg.g(id=id_)
    rows = list(zip(info, steps)) if steps is not None else [(s, None) for s in info]
    rows.sort(key=lambda r: r[1] or 0)
    where = "" if see is None else f"释义见第 {see} 张"
    head = text("Results", f"结果（{where}）" if where else "结果", lang) if part is None else text(
        f"Results ({part[0]}/{part[1]})", f"结果（{part[0]}/{part[1]}{'；' + where if where else ''}）", lang)
    blocks = ((rows, head, INK, "info"),
              ([(s, last) for s in warnings], text("Warnings", "警告", lang), HIGHLIGHT, "warning"))
    for block, heading, colour, cls in blocks:
        if not block:
            continue
        y += 4.0 + INFO_SIZE
        head = _line(dwg, heading, x, y, HEAD_SIZE, colour, f"{cls}-head")
        head.attribs["font-weight"] = "bold"
        first = min((step for _, step in block if step is not None), default=None)
        if first is not None and len([step for _, step in block if step is not None]) == len(block):
            head.attribs["data-step"] = str(first)
        if first is None or upto is None or first <= upto:
            g.add(head)
        y += INFO_SIZE * 1.6
        for s, step in block:
            for ln in info_wrap(s, width):
                if step is None or upto is None or step <= upto:
                    el = _line(dwg, ln, x, y, INFO_SIZE, colour, cls)
                    if step is not None:
                        el.attribs["data-step"] = str(step)
                    g.add(el)
                y += INFO_SIZE * 1.3
    return g
