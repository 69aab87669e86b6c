"""The students' sheets: one SVG page per student and exercise (``sheets/<page>.svg``) and ``sheets.html``, every
student's pages in class order, print-ready.

A page (:func:`student_svg`) holds the title, the student's name and id, the variant code (with the spec,
enough to regenerate the variant), the exercise's statement with its numbers (English, Chinese or both), an
answer box per asked answer with its unit, and the givens drawn to true scale at the variant's scale
(:mod:`.givens_figure`) where the whole construction fits (:mod:`.pages`), with a cam's s–δ axes beside. A
student's page holds no answer: nothing of the solution but the givens is read, and every coordinate is an
integer in hundredths of a millimetre.

Page names (:func:`page_name`) keep issue 12's contract, ``sheets/<id>.svg`` and ``key/<id>.svg``: a student's
first page (exercise 1) is ``<id>``, the page of exercise n ``<id>-<n>`` (``-2``, ``-3`` …, as the print sheets of
``geomcon solve`` continue with ``out-2.svg``), and the key page of a sheet has the sheet's name. A cam whose figure
leaves its s–δ axes no room on the page gets a second page named after its exercise's page, ``<page>-sd``
(``<id>-sd``, ``<id>-3-sd``); the key has no such page. An id is written as it is when it is made of lower-case
letters, digits, ``_`` and ``-`` only and does not end in what a further page appends (``-2`` … ``-20``,
``-sd``), so that no id's first page is another id's further page; any other id (upper case, a path separator,
CJK, ``2023-15`` …) is written as its safe characters lower-cased (or ``id`` when none is left), a dot (which no
plain id holds) and 8 hexadecimal digits of its SHA-256: a name depends on the id alone (adding a student renames
no one's file) and cannot leave the output folder or clash by case.

Examples
--------
>>> page_name("2023001", 1), page_name("2023001", 2), page_name("../Ann", 2), page_name("2023-001", 1)
('2023001', '2023001-2', 'ann.eb825571-2', '2023-001')
"""
from __future__ import annotations

import functools
import hashlib
import html
import math
import re
from dataclasses import dataclass, replace
from typing import Any, Sequence

import svgwrite

from ..geometry.primitives import Point
from ..render.labels import label_runs, rich_runs, text_width
from ..render.view import TAU, clip_arc
from ..render.serial import svg_string
from ..errors import ProblemError
from ..solve import Solution
from .accept import Accepted
from .assign import Assignment
from .givens_figure import DOT, LABEL_SIZE, Item, Placed, given_items, has_diagram, place_labels
from .key import statement, variant_code
from .key_extent import figure_box
from .pages import ANSWER_FONT, ANSWER_H, BOX_W, HEADER_H, LINE, Layout, Rect, U, layout, u
from .roster import Student
from .solving import solve_given
from .spec import AnswerRef, Exercise, Spec
from .statements import number

FONT = "Noto Sans CJK SC, Noto Sans, DejaVu Sans, sans-serif"
INK = "#000"
_SAFE = re.compile(r"[a-z0-9_-]{1,64}")
_SUFFIX = re.compile(r"-([2-9]|1[0-9]|20)(-sd)?$|-sd$")
"""What a further page appends to a student's page name (exercises 2 … 20, a cam's s–δ page): an id that
ends so is written in the hashed form, or its first page could be another student's further page."""

SYMBOLS = {"theta": "θ", "psi": "ψ", "gamma_min": "γmin", "phi": "φ", "alpha": "α", "alpha_max_rise": "αmax (rise)",
           "alpha_max_return": "αmax (return)", "rho_min_pitch": "ρmin", "rho_min_actual": "ρa,min", "K": "K"}
"""How an answer box names an answer (others by their name)."""
UNITS = {"mm": "mm", "deg": "°", "": ""}
SD_PAGE_H = 90.0
"""Height (paper mm) of the s–δ axes on a page of their own."""


def page_name(student_id: str, n: int) -> str:
    """The file name (without ``.svg``) of a student's page of exercise ``n`` (see the module): ``<id>`` for
    exercise 1, ``<id>-<n>`` for the others."""
    if _SAFE.fullmatch(student_id) and not _SUFFIX.search(student_id):
        base = student_id
    else:
        safe = re.sub(r"[^a-z0-9_-]+", "", student_id.lower())[:40]
        digest = hashlib.sha256(student_id.encode("utf-8")).hexdigest()[:8]
        base = f"{safe or 'id'}.{digest}"
    return base if n == 1 else f"{base}-{n}"


@dataclass(frozen=True)
class Page:
    """One student's page of one exercise: who, what, the solved variant and where everything goes."""

    name: str
    student: Student
    code: str
    ex: Exercise
    count: int
    variant: Accepted
    sol: Solution
    items: tuple[Item, ...]
    labels: tuple[Placed, ...]
    statement: tuple[str, ...]
    lay: Layout
    title: str
    part: str = ""
    lang: str = "both"
    """The page's language: ``en``, ``zh`` or ``both`` (statement and header)."""


def answer_name(ref: AnswerRef, given: dict[str, Any]) -> str:
    """How an answer box names ``ref``: ``AB``, ``θ``, ``s(δ = 60°)``.

    >>> answer_name(AnswerRef("s[0]", "s", 0, "mm"), {"at": [60]}), answer_name(AnswerRef("psi", "psi", None, "deg"), {})
    ('s(δ = 60°)', 'ψ')
    """
    base = SYMBOLS.get(ref.name, ref.name)
    if ref.index is None:
        return base
    at = given.get("at") or ()
    return f"{base}(δ = {number(at[ref.index])}°)" if ref.index < len(at) else ref.text


def slot_labels(ex: Exercise, v: Accepted, lang: str = "both") -> list[str]:
    """Each asked answer's box label and unit, joined by a tab (:func:`~.pages.answer_slots`); under ``zh`` the
    part a name adds is Chinese (``αmax（推程）``)."""
    out = []
    for r in ex.ask:
        name = answer_name(r, dict(v.given))
        if lang == "zh":
            name = name.replace(" (rise)", "（推程）").replace(" (return)", "（回程）")
        out.append(f"{name} =\t{UNITS.get(r.unit, r.unit)}")
    return out


def langs(lang: str) -> tuple[str, ...]:
    """The statement's languages in page order."""
    return ("en", "zh") if lang == "both" else (lang,)


def make_pages(spec: Spec, a: Assignment, lang: str) -> list[Page]:
    """Every page of the class, student by student, exercise by exercise.

    Raises
    ------
    ProblemError
        When an exercise's statement and answer boxes leave its figure no room even in the smallest font.
    """
    out = []
    for s, variants in zip(a.students, a.variants):
        code = variant_code([v.index for v in variants])
        for ex, v in zip(spec.exercises, variants):
            if v.solved is not None:                            # judged here: its solution, box and givens
                sol, box, items = v.solved.sol, v.solved.box, v.solved.items
            else:
                sol = solve_given(ex.recipe, v.given)
                box = figure_box(sol, [r.name for r in ex.ask], v.scale.factor)
                items = tuple(given_items(sol))
            paragraphs = tuple(statement(ex, v, lg) for lg in langs(lang))
            try:
                lay = layout(v.sheet, v.scale, box, paragraphs, slot_labels(ex, v, lang), diagram=has_diagram(sol))
            except ValueError as exc:
                raise ProblemError(f"exercise {ex.n} ({ex.recipe}), student {s.id!r}: {exc} at {v.scale}; "
                                   "shorten the statement or ask fewer answers") from None
            placed, _ = place_labels(items, lay.to_paper)
            page = Page(page_name(s.id, ex.n), s, code, ex, len(spec.exercises), v, sol, items, tuple(placed),
                        paragraphs, lay, spec.title_in(lang), lang=lang)
            out.append(page)
            if has_diagram(sol) and lay.diagram is None:        # no free strip at the figure's scale
                x0, y0, x1, _ = lay.frame
                sd = replace(lay, lines=(), diagram=(x0, y0 + HEADER_H + 4, x1, y0 + HEADER_H + 4 + SD_PAGE_H))
                out.append(replace(page, name=page.name + "-sd", lay=sd, part="sd"))
    return out


# ------------------------------------------------------------------------------------------------ drawing
def page_drawing(p: Page, units: int) -> svgwrite.Drawing:
    w, h = p.lay.sheet.width, p.lay.sheet.height
    dwg = svgwrite.Drawing(size=(f"{w:g}mm", f"{h:g}mm"), viewBox=f"0 0 {round(w * units)} {round(h * units)}",
                           profile="full", debug=False)
    dwg.attribs["font-family"] = FONT
    return dwg


def svg_text(dwg: svgwrite.Drawing, s: str, x: float, y: float, size: float, *, anchor: str = "start",
             bold: bool = False, rich: bool = False) -> Any:
    """A text: a short label as a point label (C1: C with subscript 1), a statement or an answer box's label
    (``rich``) with its symbols typeset as the Results block types them (γmin, DC1, r0: :func:`rich_runs`),
    anything else as it is. A subscript is lowered and the text after it raised back."""
    attrs: dict[str, Any] = {"font_size": u(size), "fill": INK}
    if anchor != "start":
        attrs["text_anchor"] = anchor
    if bold:
        attrs["font_weight"] = "bold"
    el = dwg.text("", insert=(u(x), u(y)), **attrs)
    runs = rich_runs(s) if rich else label_runs(s) if len(s) <= 8 else ((s, False),)
    down = False
    for run, sub in runs:
        if sub:
            el.add(dwg.tspan(run, font_size=u(size * 0.72), dy=[u(size * 0.25)]) if not down else
                   dwg.tspan(run, font_size=u(size * 0.72)))
        else:
            el.add(dwg.tspan(run, dy=[u(-size * 0.25)]) if down else dwg.tspan(run))
        down = sub
    el.attribs["xml:space"] = "preserve"
    return el


HEADER_WORDS: dict[str, tuple[str, str]] = {
    "key": ("KEY", "答案"), "exercise": ("Exercise", "题"), "continued": ("continued", "续"),
    "scale": ("scale", "比例"), "name": ("Name", "姓名"), "id": ("ID", "学号"), "variant": ("Variant", "变体")}
"""The words of a page's header, English and Chinese."""


def header_word(word: str, lang: str) -> str:
    """A header word in the page's language: ``en``, ``zh``, or both (English then Chinese).

    >>> header_word("name", "zh"), header_word("name", "en"), header_word("name", "both")
    ('姓名', 'Name', 'Name 姓名')
    """
    en, zh = HEADER_WORDS[word]
    return zh if lang == "zh" else en if lang == "en" else f"{en} {zh}"


def header_lines(p: Page, key: bool = False) -> tuple[str, str, str]:
    """The header's title, its exercise line (right) and its name line, in the page's language (:func:`header_word`;
    a colon full-width in Chinese, the paper named as a title block names it).

    >>> from types import SimpleNamespace as NS
    >>> p = NS(lang="zh", title="T", part="sd", ex=NS(n=2), count=3, variant=NS(scale="1:2"),
    ...        lay=NS(sheet="A4 portrait"), student=NS(name="", id="7"), code="AB")
    >>> header_lines(p, key=True)[1:]
    ('题 2/3（续：s–δ） · 比例 1:2 · A4 纵向', '姓名：________________    学号：7    变体：AB')
    """
    lg = p.lang
    w = functools.partial(header_word, lang=lg)
    colon = "：" if lg == "zh" else ": "
    title = (f"{w('key')} — " if key else "") + p.title
    cont = ((f"（{w('continued')}：s–δ）" if lg == "zh" else f" ({w('continued')}: s–δ)")
            if p.part == "sd" else "")
    paper = str(p.lay.sheet)
    if lg == "zh":
        paper = paper.replace(" landscape", " 横向").replace(" portrait", " 纵向")
    exercise = f"{w('exercise')} {p.ex.n}/{p.count}{cont} · {w('scale')} {p.variant.scale} · {paper}"
    name = p.student.name or "_" * 16
    who = f"{w('name')}{colon}{name}    {w('id')}{colon}{p.student.id}    {w('variant')}{colon}{p.code}"
    return title, exercise, who


TITLE_SIZE = 4.5
"""The header's title text size (mm); a long title is set smaller, down to 2.5 mm, then cut with …"""


def title_fit(title: str, width: float) -> tuple[str, float]:
    """The header's title and its size so that it fits ``width`` mm left of the exercise line (bold: 1.12 times
    the regular estimate): :data:`TITLE_SIZE`, smaller down to 2.5 mm, then cut (a title in both languages ran
    into "Exercise 题 1/3 · scale …").

    >>> title_fit("Guide bar", 100.0)
    ('Guide bar', 4.5)
    >>> t, size = title_fit("Linkages and cams — worksheet 3  连杆机构与凸轮机构——练习 3", 95.0); size < 4.5
    True
    """
    from ..render.page import fit_size, fitted
    title = fitted(title, width, TITLE_SIZE, 1.12)
    return title, fit_size(title, width / 1.12, TITLE_SIZE)


def header(dwg: svgwrite.Drawing, p: Page, key: bool = False) -> Any:
    """Title, exercise, scale, name, id and variant code (in the page's language: :func:`header_lines`), and the
    statement."""
    x0, y0, x1, _ = p.lay.frame
    g = dwg.g(id="header")
    title, exercise, who = header_lines(p, key)
    room = (x1 - 3) - text_width(exercise, 3.0) - 4.0 - (x0 + 3)       # the title ends 4 mm before the exercise line
    title, size = title_fit(title, room)
    g.add(svg_text(dwg, title, x0 + 3, y0 + 6.5, size, bold=True))
    g.add(svg_text(dwg, exercise, x1 - 3, y0 + 6.5, 3.0, anchor="end"))
    g.add(svg_text(dwg, who, x0 + 3, y0 + 12.5, 3.2))
    g.add(dwg.line((u(x0), u(y0 + HEADER_H - 1.5)), (u(x1), u(y0 + HEADER_H - 1.5)), stroke=INK,
                   stroke_width=u(0.25)))
    size, y = p.lay.size, p.lay.text_top + p.lay.size * 1.2
    for lines in p.lay.lines:
        for line in lines:
            g.add(svg_text(dwg, line, x0 + 3, y, size, rich=True))
            y += size * LINE
        y += 2.0
    return g


def answer_boxes(dwg: svgwrite.Drawing, p: Page, values: Sequence[str] | None = None) -> Any:
    """One box per asked answer with its name and unit (``values`` written beside them: the key)."""
    x0 = p.lay.frame[0] + 3
    g = dwg.g(id="answers")
    for i, (lab, (row, dx)) in enumerate(zip(slot_labels(p.ex, p.variant, p.lang), p.lay.slots)):
        name, _, unit = lab.partition("\t")
        x, y = x0 + dx, p.lay.answers_top + row * ANSWER_H
        g.add(svg_text(dwg, name, x, y + 6.5, ANSWER_FONT, rich=True))
        bx = x + text_width(name, ANSWER_FONT) + 1.5
        g.add(dwg.rect((u(bx), u(y + 1)), (u(BOX_W), u(8.5)), fill="none", stroke=INK, stroke_width=u(0.35)))
        g.add(svg_text(dwg, unit, bx + BOX_W + 1.5, y + 6.5, ANSWER_FONT))
        if values is not None:
            g.add(svg_text(dwg, values[i], bx + 1.0, y + 6.3, 3.0))
    return g


def _path(points: Sequence[tuple[float, float]]) -> str:
    return "M" + "L".join(f"{u(x)} {u(y)}" for x, y in points)


def circle_room(p: Page) -> Rect:
    """Where a given circle may run (paper mm): the drawing frame below the statement and the answer boxes
    (the figure area's top), left of (or above) a cam's s–δ strip beside the figure. A circle leaving it through
    the frame ends on the frame line: it runs on beyond the sheet."""
    fx0, _, fx1, fy1 = p.lay.frame
    x0, y0, x1, y1 = fx0, p.lay.fig[1], fx1, fy1
    d = p.lay.diagram
    if d is not None and p.part != "sd":
        if d[0] >= p.lay.fig[2] - 1e-9:
            x1 = min(x1, d[0])
        elif d[1] >= p.lay.fig[3] - 1e-9:
            y1 = min(y1, d[1])
    return (x0, y0, x1, y1)


def circle_path(c: tuple[float, float], r: float, room: Rect) -> str:
    """SVG path data (in the page's user units, :func:`~.pages.u`) of the circle (paper mm, centre ``c``, radius
    ``r``) drawn whole when it lies in ``room``, else as the arcs of it inside ``room`` (each one explicit, ending
    where the circle leaves the room).

    >>> circle_path((0.0, 0.0), 1.0, (-2.0, -2.0, 2.0, 2.0))
    'M100 0A100 100 0 1 1 -100 0A100 100 0 1 1 100 0'
    >>> circle_path((0.0, 0.0), 1.0, (0.0, -2.0, 2.0, 2.0))
    'M0 -100A100 100 0 0 1 0 100'
    """
    parts = clip_arc(Point(*c), r, room)
    out = []
    for start, sweep in parts:
        if sweep >= TAU - 1e-12:
            return (f"M{u(c[0] + r)} {u(c[1])}A{u(r)} {u(r)} 0 1 1 {u(c[0] - r)} {u(c[1])}"
                    f"A{u(r)} {u(r)} 0 1 1 {u(c[0] + r)} {u(c[1])}")
        a, b = start, start + sweep          # paper angles (y down): increasing = clockwise as seen
        out.append(f"M{u(c[0] + r * math.cos(a))} {u(c[1] + r * math.sin(a))}A{u(r)} {u(r)} 0 "
                   f"{int(sweep > math.pi)} 1 {u(c[0] + r * math.cos(b))} {u(c[1] + r * math.sin(b))}")
    return "".join(out)


def givens_group(dwg: svgwrite.Drawing, p: Page) -> Any:
    """The givens at true scale, with their labels: segments and curves clipped to the figure area (a clip path
    of the page's own id, so the pages inlined in one HTML document each clip to their own area), given circles
    whole or as explicit arcs inside the frame (:func:`circle_path`)."""
    x0, y0, x1, y1 = p.lay.fig
    area = f"figure-area-{p.name.replace('/', '-')}"
    clip = dwg.defs.add(dwg.clipPath(id=area))
    clip.add(dwg.rect((u(x0), u(y0)), (u(x1 - x0), u(y1 - y0))))
    g = dwg.g(id="givens", fill="none", stroke=INK)
    lines = dwg.g(clip_path=f"url(#{area})")
    g.add(lines)
    tp = p.lay.to_paper
    room = circle_room(p)
    for it in p.items:
        if it.kind in ("segment", "polyline"):
            lines.add(dwg.path(d=_path([tp(*q) for q in it.pts]), stroke_width=u(0.5), stroke_linecap="round"))
        elif it.kind == "circle":
            d = circle_path(tp(*it.pts[0]), it.r * p.lay.scale.factor, room)
            if d:
                g.add(dwg.path(d=d, stroke_width=u(0.25), class_="given-circle"))
    for it in p.items:
        if it.kind == "point":
            c = tp(*it.pts[0])
            g.add(dwg.circle((u(c[0]), u(c[1])), u(DOT), fill="#fff", stroke_width=u(0.35)))
    for lab in p.labels:
        t = svg_text(dwg, lab.label, lab.x, lab.y, LABEL_SIZE)
        t.attribs["stroke"] = "none"
        g.add(t)
    x, y = p.lay.fig[0] + 2, p.lay.fig[3] - 2
    note = svg_text(dwg, f"{p.variant.scale}", x, y, 3.0)
    note.attribs["stroke"] = "none"
    g.add(note)
    return g


def diagram_axes(dwg: svgwrite.Drawing, p: Page) -> Any | None:
    """A cam's s–δ axes in the page's free strip: δ from 0 to 360° with a tick at each boundary of the motion
    program, s upward at the figure's scale up to h."""
    if p.lay.diagram is None:
        return None
    x0, y0, x1, y1 = p.lay.diagram
    if p.part != "sd":                     # in the strip beside the figure: keep clear of it
        y0 = max(y0, p.lay.fig[3] if x0 < p.lay.fig[2] - 1e-9 else y0)
    g = dwg.g(id="sd-axes", fill="none", stroke=INK)
    given = p.sol.problem.given
    unit = "°" if p.sol.recipe.name == "cam.oscillating" else "mm"
    h = 30.0 if unit == "°" else float(given["h"]) * p.lay.scale.factor
    h = min(h, y1 - y0 - 18)
    ox, oy = x0 + 12, min(y1 - 9, (y0 + y1) / 2 + (h + 6) / 2)      # centred in the strip
    length = min(x1 - 12 - ox, 180.0)
    g.add(dwg.path(d=_path([(ox, oy), (ox + length + 4, oy)]), stroke_width=u(0.35)))
    g.add(dwg.path(d=_path([(ox, oy), (ox, oy - h - 6)]), stroke_width=u(0.35)))
    total = 0.0
    ticks = [0.0]
    for row in given["program"]:
        total += float(row["angle"])
        ticks.append(total)
    for t in ticks:
        x = ox + length * t / 360.0
        g.add(dwg.path(d=_path([(x, oy - 1.2), (x, oy + 1.2)]), stroke_width=u(0.3)))
        label = svg_text(dwg, f"{number(t)}°", x, oy + 5, 2.6, anchor="middle")
        label.attribs["stroke"] = "none"
        g.add(label)
    g.add(dwg.path(d=_path([(ox - 1.2, oy - h), (ox + 1.2, oy - h)]), stroke_width=u(0.3)))
    for s, x, y, anchor in (("δ", ox + length + 5, oy + 1, "start"), ("s", ox - 2, oy - h - 4, "end"),
                            (f"h = {number(given['h'])} {unit}", ox + 2, oy - h - 1.5, "start")):
        t = svg_text(dwg, s, x, y, 3.2, anchor=anchor)
        t.attribs["stroke"] = "none"
        g.add(t)
    return g


def frame(dwg: svgwrite.Drawing, p: Page) -> Any:
    """The white paper and the ISO 5457 frame."""
    x0, y0, x1, y1 = p.lay.frame
    g = dwg.g(id="frame")
    g.add(dwg.rect((0, 0), (u(p.lay.sheet.width), u(p.lay.sheet.height)), fill="#fff"))
    g.add(dwg.rect((u(x0), u(y0)), (u(x1 - x0), u(y1 - y0)), fill="none", stroke=INK, stroke_width=u(0.5)))
    return g


def student_svg(p: Page) -> str:
    """The student's page (see the module); ``part == "sd"``: the s–δ axes of a cam whose figure leaves them
    no room, on a page of their own."""
    dwg = page_drawing(p, U)
    dwg.add(frame(dwg, p))
    dwg.add(header(dwg, p))
    if p.part == "sd":
        dwg.add(diagram_axes(dwg, p))
        return svg_string(dwg) + "\n"
    dwg.add(answer_boxes(dwg, p))
    dwg.add(givens_group(dwg, p))
    axes = diagram_axes(dwg, p)
    if axes is not None:
        dwg.add(axes)
    return svg_string(dwg) + "\n"


# ------------------------------------------------------------------------------------------------ html
def pages_html(title: str, pages: Sequence[tuple[Page, str]], lang: str) -> str:
    """A print-ready HTML document of SVG pages (each ``(page, svg text)``): CSS ``@page`` of each page's paper
    and orientation (named pages), no margins, one sheet of paper per page, the pages of one student in one
    ``<article>`` that starts on a new sheet."""
    sizes = sorted({(p.lay.sheet.paper, p.lay.sheet.orientation) for p, _ in pages})
    css = ["html, body { margin: 0; padding: 0; }", "@page { margin: 0; }"]
    for paper, orient in sizes:
        css.append(f"@page {paper}-{orient} {{ size: {paper} {orient}; margin: 0; }}")
        w, h = _paper_mm(pages, paper, orient)
        css.append(f".sheet.{paper}-{orient} {{ page: {paper}-{orient}; width: {w:g}mm; height: {h:g}mm; }}")
    css.append(".sheet { overflow: hidden; break-after: page; page-break-after: always; }")
    css.append(".sheet > svg { display: block; }")
    body = []
    current = None
    for p, svg in pages:
        if p.student.id != current:
            if current is not None:
                body.append("</article>")
            body.append(f'<article class="student" data-id="{html.escape(p.student.id)}">')
            current = p.student.id
        kind = f"{p.lay.sheet.paper}-{p.lay.sheet.orientation}"
        body.append(f'<section class="sheet {kind}" id="{html.escape(p.name)}">{svg[svg.index("<svg"):].rstrip()}</section>')
    if current is not None:
        body.append("</article>")
    html_lang = "zh" if lang == "zh" else "en"
    return "\n".join([
        "<!DOCTYPE html>", f'<html lang="{html_lang}">', "<head>", '<meta charset="utf-8">',
        f"<title>{html.escape(title)}</title>", "<style>", *css, "</style>", "</head>", "<body>", *body,
        "</body>", "</html>", ""])


def _paper_mm(pages: Sequence[tuple[Page, str]], paper: str, orient: str) -> tuple[float, float]:
    for p, _ in pages:
        if p.lay.sheet.paper == paper and p.lay.sheet.orientation == orient:
            return p.lay.sheet.width, p.lay.sheet.height
    raise KeyError(paper)                   # pragma: no cover - sizes come from the pages


def sheet_files(pages: Sequence[Page], title: str, lang: str) -> dict[str, str]:
    """``sheets/<page>.svg`` for every page and ``sheets.html``."""
    svgs = [(p, student_svg(p)) for p in pages]
    files = {f"sheets/{p.name}.svg": s for p, s in svgs}
    files["sheets.html"] = pages_html(title, svgs, lang)
    return files


__all__ = ["Page", "SYMBOLS", "answer_boxes", "answer_name", "diagram_axes", "frame", "givens_group",
           "header", "langs", "make_pages", "slot_labels", "page_drawing", "page_name", "pages_html", "svg_text", "sheet_files", "student_svg"]
