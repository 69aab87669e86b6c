"""The printed sheet: paper size, drawing frame (ISO 5457 margins), title block (ISO 7200-like) and the
regions of a figure sheet and of the protocol sheets that follow it.

Every sheet is an SVG whose ``width``/``height`` are the paper's in mm and whose user unit is 1 mm of
paper, so a sheet printed at 100 % puts every length where the drawing scale says: the drawing is drawn at
a standard scale (:mod:`geomcon.paper`), stated in the title block as ``1:2`` and as μl (model mm per paper
mm), and both are true on paper.

Sheet 1 holds the drawing, its scale bar, the results and warnings, and the title block; the numbered
construction protocol flows onto sheets 2, 3 … (``geomcon solve --svg out.svg`` writes ``out.svg``,
``out-2.svg`` …; the HTML player shows every sheet and prints one per page).

Examples
--------
>>> spec = PageSpec("A4", "landscape")
>>> spec.sheet.width, spec.sheet.height, frame_box(spec.sheet)
(297.0, 210.0, (20.0, 10.0, 287.0, 200.0))
>>> PageSpec("A3", "portrait").sheet.area
(267.0, 400.0)
>>> text("Results", "结果", "zh"), text("Results", "结果", "both")
('结果', 'Results  结果')
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import Any, Literal

import svgwrite

from ..paper import PAPERS, Orientation, Scale, Sheet
from .labels import rich_runs, text_width, wrap
from .serial import Element
from .shapes import add_runs
from .style import FONT_FAMILY, INK
from .view import Box, fmt

Lang = Literal["en", "zh", "both"]
LANGS: tuple[str, ...] = ("en", "zh", "both")

TB_W = 180.0            # title block width (ISO 7200: at most 180 mm)
TB_ROWS = 4
TB_H = 28.0             # title block height: the title field and three rows of data
TB_TITLE_H = 11.0       # the title field: one title of 5 mm, or two lines of 3.5 mm (both languages, a long title)
TB_ROW = (TB_H - TB_TITLE_H) / (TB_ROWS - 1)    # height of each data row (5.67 mm for 3.5 mm text)
TB_TEXT = 3.5           # title block text size (ISO 3098 series 2.5, 3.5, 5, 7)
TB_TITLE = 5.0          # a title that fits one line
TB_TITLE_BOTH = 3.5     # each line of two: the English and the Chinese title, or a long title wrapped
TB_PITCH = 5.0          # baseline to baseline of two title lines
FRAME_WIDTH = 0.7       # the drawing frame's line
INSET = 4.0             # free paper between the frame and what is drawn inside it
MIN_TEXT = 2.5          # the smallest text on paper (ISO 3098), mm


@dataclass(frozen=True)
class PageSpec:
    """The paper a figure is printed on (:data:`geomcon.paper.PAPERS` name and orientation) and the language
    of its texts (``en``, ``zh`` or ``both``).

    >>> PageSpec().sheet
    Sheet(paper='A4', orientation='landscape', width=297.0, height=210.0, margin_left=20.0, margin_right=10.0, margin_top=10.0, margin_bottom=10.0)
    """

    paper: str = "A4"
    orientation: Orientation = "landscape"
    lang: Lang = "both"

    def __post_init__(self) -> None:
        if self.paper not in PAPERS:
            raise ValueError(f"paper is one of {', '.join(PAPERS)}, got {self.paper!r}")
        if self.lang not in LANGS:
            raise ValueError(f"lang is one of {', '.join(LANGS)}, got {self.lang!r}")

    @property
    def sheet(self) -> Sheet:
        """The paper turned as asked, with its margins."""
        return PAPERS[self.paper].sheet(self.orientation)


def text(en: str, zh: str, lang: str) -> str:
    """A heading in the language asked for (both: English, two spaces, Chinese)."""
    return en if lang == "en" or not zh else zh if lang == "zh" else f"{en}  {zh}"


from .zh import _cjk, zh_punct  # noqa: E402  (re-exported: Chinese punctuation lives in a module of its own)


def frame_box(sheet: Sheet) -> Box:
    """The drawing frame on paper: (x0, y0, x1, y1), y down."""
    return (sheet.margin_left, sheet.margin_top, sheet.width - sheet.margin_right, sheet.height - sheet.margin_bottom)


def title_block_box(sheet: Sheet) -> Box:
    """The title block: the frame's bottom-right corner, :data:`TB_W` wide (the frame's width when narrower)."""
    x0, y0, x1, y1 = frame_box(sheet)
    return (max(x0, x1 - TB_W), y1 - TB_H, x1, y1)


def document(sheet: Sheet) -> svgwrite.Drawing:
    """An empty sheet: the SVG document (width and height in mm, 1 user unit = 1 mm), the white paper and
    the drawing frame."""
    w, h = fmt(sheet.width), fmt(sheet.height)
    dwg = svgwrite.Drawing(size=(f"{w}mm", f"{h}mm"), viewBox=f"0 0 {w} {h}", profile="full", debug=False)
    dwg.attribs["font-family"] = FONT_FAMILY
    dwg.add(Element("rect", x="0", y="0", width=w, height=h, fill="#ffffff", id="paper"))
    x0, y0, x1, y1 = frame_box(sheet)
    dwg.add(Element("rect", x=fmt(x0), y=fmt(y0), width=fmt(x1 - x0), height=fmt(y1 - y0), fill="none", stroke=INK,
                    stroke_width=fmt(FRAME_WIDTH), id="frame"))
    return dwg


@cache
def version() -> str:
    """geomcon's version as installed (printed in the title block)."""
    try:
        from importlib.metadata import version as _v
        return _v("geomcon")
    except Exception:       # pragma: no cover - a source tree that is not installed
        return "unknown"


@dataclass(frozen=True)
class TitleBlock:
    """What the title block states: the title (a title of both languages is two lines, English then Chinese,
    joined by a newline: :func:`geomcon.problems.title_in`), the problem file, the recipe, the scale (None on a
    sheet without a drawing), the paper, the sheet number and count. No date: outputs are byte-identical."""

    title: str
    problem: str
    recipe: str
    scale: Scale | None
    paper: str
    sheet: int
    sheets: int
    lang: str = "both"


def _paper_words(paper: str, lang: str) -> str:
    """The paper as the title block names it: ``A4 landscape``, in Chinese ``A4 横向`` / ``A4 纵向``.

    >>> _paper_words("A3 portrait", "zh"), _paper_words("A4 landscape", "both")
    ('A3 纵向', 'A4 landscape')
    """
    if lang != "zh":
        return paper
    return paper.replace(" landscape", " 横向").replace(" portrait", " 纵向")


def printable(text_: str) -> str:
    r"""``text_`` with every character that XML cannot hold or a reader cannot see written as its escape (a
    problem file's name is chosen by whoever saved it: ``a\x01b.toml`` would make the sheet ill-formed XML).

    >>> printable("001-08_crank_rocker"), printable("a\x01b\nc")
    ('001-08_crank_rocker', 'a\\x01b\\nc')
    """
    if text_.isprintable():                 # every character as it is (a space is printable)
        return text_
    return "".join(ch if ch.isprintable() or ch == " " else ch.encode("unicode_escape").decode("ascii")
                   for ch in text_)


def title_lines(title: str, width: float) -> tuple[tuple[str, ...], float]:
    """The lines of the title field (at most two) and their size: a title of one language on one line of
    :data:`TB_TITLE` (5 mm) when it fits ``width``, else wrapped to two of :data:`TB_TITLE_BOTH` (3.5 mm); two
    titles (English above Chinese: both languages) one line each of 3.5 mm. A line still too wide is set smaller
    by :func:`title_block` (never under :data:`MIN_TEXT`) — not, as before, both titles at 2.8 mm in a 7 mm row
    and a long title shrunk towards 2.5 mm in one line (88 of the 186 titles are wider than 177 mm at 5 mm).

    >>> title_lines("Crank-rocker", 177.0)
    (('Crank-rocker',), 5.0)
    >>> title_lines("Crank-rocker\\n曲柄摇杆机构", 177.0)
    (('Crank-rocker', '曲柄摇杆机构'), 3.5)
    >>> lines, size = title_lines("Eccentric-circle cam, offset roller follower, turning cw: rise and return angles", 100)
    >>> lines
    ('Eccentric-circle cam, offset roller ', 'follower, turning cw: rise and return angles')
    """
    parts = [t for t in title.split("\n") if t] or [""]
    if len(parts) > 1:
        return tuple(parts[:2]), TB_TITLE_BOTH
    one = parts[0]
    if text_width(rich_runs(one), TB_TITLE) * TITLE_WEIGHT <= width:
        return (one,), TB_TITLE
    limit = width / TITLE_WEIGHT
    room = min(limit, text_width(rich_runs(one), TB_TITLE_BOTH) / 2)      # two lines of about equal length
    lines = wrap(one, room, TB_TITLE_BOTH)
    while len(lines) > 2 and room < limit:
        room = min(limit, room + 2.0)
        lines = wrap(one, room, TB_TITLE_BOTH)
    cut = len(lines[0])                 # the rest on the second line (set smaller should it need a third)
    while cut < len(one) and one[cut] == " ":
        cut += 1                        # the break's space ends the first line: the two lines read as the title
    return ((one[:cut], one[cut:]) if one[cut:] else (one,)), TB_TITLE_BOTH


TITLE_WEIGHT = 1.12
"""How much wider the bold title is than the regular estimate of :func:`~geomcon.render.labels.text_width`."""


def title_block(dwg: svgwrite.Drawing, sheet: Sheet, tb: TitleBlock) -> Any:
    """The title block group: the title field (:func:`title_lines`: one line of 5 mm, or two of 3.5 mm — both
    languages, a long title wrapped), then three rows: problem file and recipe; scale, μl and paper; geomcon's
    version and the sheet number."""
    x0, y0, x1, y1 = title_block_box(sheet)
    g = dwg.g(id="title-block", stroke=INK, fill="none")
    g.add(Element("rect", x=fmt(x0), y=fmt(y0), width=fmt(x1 - x0), height=fmt(y1 - y0), stroke_width="0.5"))
    tops = [y0] + [y0 + TB_TITLE_H + r * TB_ROW for r in range(TB_ROWS - 1)]
    for y in tops[1:]:
        g.add(Element("line", x1=fmt(x0), y1=fmt(y), x2=fmt(x1), y2=fmt(y), stroke_width="0.25"))
    w = x1 - x0
    lang = tb.lang
    if tb.scale is not None:
        mu = tb.scale.real / tb.scale.paper
        scale = [f"{text('Scale', '比例', lang)} {tb.scale}", f"μl = {mu:g} mm/mm"]
    else:
        scale = [text("Scale", "比例", lang) + " —", ""]
    titles, title_size = title_lines("\n".join(printable(t) for t in tb.title.split("\n")), w - 3.0)
    rows = [[""],
            [f"{text('Problem', '题目', lang)} {printable(tb.problem)}", f"{text('Recipe', '作图法', lang)} {tb.recipe}"],
            scale + [f"{text('Paper', '图幅', lang)} {_paper_words(tb.paper, lang)}"],
            [f"geomcon {version()}", f"{text('Sheet', '第', lang)} {tb.sheet}/{tb.sheets}"
             + ("" if lang == "en" else " 张")]]
    mid = y0 + TB_TITLE_H / 2
    for i, cell in enumerate(titles):   # one line centred in the field, or two TB_PITCH apart about its middle
        cell = fitted(cell, w - 3.0, title_size, TITLE_WEIGHT)
        size = fit_size(cell, (w - 3.0) / TITLE_WEIGHT, title_size)
        base = mid + 0.36 * size + (TB_PITCH * (i - 0.5) if len(titles) == 2 else 0.0)
        zh = len(titles) == 2 and i == 1 and "\n" in tb.title
        t = Element("text", class_="tb tb-0-0" + (" tb-title-zh" if zh else ""), fill=INK, font_size=fmt(size),
                    stroke="none", x=fmt(x0 + 1.5), y=fmt(base))
        add_runs(t, rich_runs(cell), size, least=MIN_TEXT)
        t.attribs["xml:space"] = "preserve"
        t.attribs["font-weight"] = "bold"
        g.add(t)
    for r, cells in enumerate(rows):
        cw = w / len(cells)
        for c, cell in enumerate(cells):
            if not cell:
                continue
            if c:
                x = fmt(x0 + c * cw)
                g.add(Element("line", x1=x, y1=fmt(tops[r]), x2=x, y2=fmt(tops[r] + TB_ROW), stroke_width="0.25"))
            size = TB_TEXT
            cell = fitted(cell, cw - 3.0, size)
            size = fit_size(cell, cw - 3.0, size)
            at = (fmt(x0 + c * cw + 1.5), fmt(tops[r] + TB_ROW / 2 + 0.36 * size))
            if cell.startswith("μl"):                     # μl: its subscript as the textbook prints it
                t = Element("text", class_=f"tb tb-{r}-{c}", fill=INK, font_size=fmt(size), stroke="none",
                            x=at[0], y=at[1])
                add_runs(t, rich_runs(cell), size, least=MIN_TEXT)
                t.attribs["xml:space"] = "preserve"
            else:
                t = Element("text", cell, x=at[0], y=at[1], font_size=fmt(size), fill=INK, stroke="none",
                            class_=f"tb tb-{r}-{c}")
            g.add(t)
    return g


def fit_size(s: str, width: float, size: float) -> float:
    """``size``, or smaller down to :data:`MIN_TEXT`, so that ``s`` fits ``width`` paper mm.

    >>> fit_size("short", 100.0, 5.0), fit_size("a much longer text than fits", 30.0, 5.0)
    (5.0, 2.5)
    """
    need = text_width(s, size)
    if need <= width:
        return size
    return max(MIN_TEXT, round(size * width / need, 2))


def fitted(s: str, width: float, size: float, weight: float = 1.0, least: float = MIN_TEXT) -> str:
    """``s``, cut short with … when even at ``least`` (the smallest size it may be set at: :data:`MIN_TEXT` for
    a text that :func:`fit_size` shrinks, its own ``size`` for one set at that size) it is wider than ``width``
    (``weight``: how much wider the font is than the regular estimate, e.g. bold).

    >>> fitted("abc", 100.0, 5.0), fitted("x" * 200, 50.0, 5.0).endswith("…")
    ('abc', True)
    >>> fitted("x" * 30, 50.0, 3.5), fitted("x" * 30, 50.0, 3.5, least=3.5).endswith("…")
    ('xxxxxxxxxxxxxxxxxxxxxxxxxxxxxx', True)
    >>> fitted("最大的点 A*（在弧上）", 26.0, 3.5, least=3.5)        # not "… A*（…"
    '最大的点 A*…'
    """
    if text_width(s, least) * weight <= width:
        return s
    while s and text_width(s + "…", least) * weight > width:
        s = s[:-1]
    return s.rstrip().rstrip("([（［【「『《“‘").rstrip() + "…"      # no opening mark left before the cut


def sheet_names(path: str, n: int) -> list[str]:
    """The file names of ``n`` sheets written for ``path``: the path itself, then ``<stem>-2<suffix>`` …

    >>> sheet_names("out/fig.svg", 3)
    ['out/fig.svg', 'out/fig-2.svg', 'out/fig-3.svg']
    """
    from pathlib import PurePath
    p = PurePath(path)
    return [str(p)] + [str(p.with_name(f"{p.stem}-{i}{p.suffix}")) for i in range(2, n + 1)]


def print_css(spec: PageSpec) -> str:
    """CSS that prints every sheet (``svg.sheet``) on a page of its own at 100 %: ``@page`` of the sheet's
    size, no printer margins (the sheet carries its own). A sheet's box is cut 1 mm short (blank paper below
    the frame), so that a browser's page, rounded to whole points, never spills a sliver onto a blank page."""
    sh = spec.sheet
    return (f"@page {{ size: {spec.paper} {spec.orientation}; margin: 0; }}\n"
            "@media print {\n"
            "  body { margin: 0; background: #fff; }\n"
            "  #bar { display: none; }\n"
            "  #drawing { border: 0; overflow: visible; }\n"
            f"  #drawing svg.sheet {{ width: {fmt(sh.width)}mm; height: {fmt(sh.height)}mm; max-height: none; "
            "margin: 0; }\n"
            f"  .page {{ height: {fmt(sh.height - 1.0)}mm; overflow: hidden; border: 0 !important; "
            "break-after: page; page-break-after: always; break-inside: avoid; page-break-inside: avoid; }\n"
            "  .page:last-child { break-after: auto; page-break-after: auto; }\n"
            "}\n")


def centred(size: tuple[float, float], area: Box) -> tuple[float, float]:
    """Top-left corner of a box of ``size`` centred in ``area``."""
    return (area[0] + (area[2] - area[0] - size[0]) / 2, area[1] + (area[3] - area[1] - size[1]) / 2)


__all__ = ["LANGS", "Lang", "MIN_TEXT", "PageSpec", "TitleBlock", "centred", "document", "fit_size", "frame_box",
           "print_css", "sheet_names", "text", "title_block", "title_block_box", "version", "zh_punct"]
