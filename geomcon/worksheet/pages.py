"""The layout of a worksheet page, shared by the student's sheet and its key so that a key printed on film lays
exactly over the sheet: the text band at the top, the figure at true scale below it, a cam's s–δ axes beside.

A page is one exercise of one student on the sheet the variant was accepted on (``Accepted.sheet``: A4 or A3,
portrait or landscape), inside the ISO 5457 frame (20 mm left, 10 mm elsewhere). The top of the frame holds
the header (title, name, id, variant code) and the statement; the answer boxes follow the statement. The
figure — the construction's model box (:func:`~.readability.extent`) at the variant's scale with
:data:`~.accept.FIGURE_MARGIN` around it — sits below, centred in the space left; a cam's figure is pushed to one
side so that the s–δ diagram's axes get the larger free strip. The statement is set at 3.2 mm, or smaller (down
to 2.5 mm) when the figure leaves it too little room.

Student pages are written in hundredths of a millimetre (:data:`U` user units per mm, integers only), so no
coordinate of a sheet can spell an answer's decimals.

Examples
--------
>>> from geomcon.paper import PAPERS, Scale
>>> lay = layout(PAPERS["A4"].sheet("portrait"), Scale(1, 2), (0.0, 0.0, 200.0, 100.0), ["x"] * 3, ["AB =\tmm"])
>>> lay.to_paper(0.0, 100.0)[0] >= 20.0, round(lay.to_paper(200.0, 0.0)[0] - lay.to_paper(0.0, 0.0)[0], 9)
(True, 100.0)
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from ..paper import Scale, Sheet
from ..render.labels import wrap
from ..render.labels import text_width
from .accept import FIGURE_MARGIN, diagram_strip

U = 100
"""User units per paper mm in a student's page."""
HEADER_H = 16.0
"""Paper mm of the header (title line, name/id/variant line, rule)."""
ANSWER_H = 13.0
"""Paper mm of a row of answer boxes (box and a gap)."""
ANSWER_FONT = 3.5
"""Font size of an answer box's name and unit (paper mm)."""
BOX_W = 26.0
"""Width of an answer box (paper mm)."""
GAP = 8.0
"""Paper mm between two answer slots."""
FONT_SIZES = (3.2, 2.9, 2.6)
"""Statement font sizes tried, largest first (paper mm)."""
LINE = 1.45
"""Line height of the statement, in font sizes."""

Rect = tuple[float, float, float, float]


@dataclass(frozen=True)
class Layout:
    """Where everything of a page goes (paper mm, y down)."""

    sheet: Sheet
    scale: Scale
    box: tuple[float, float, float, float]
    fig: Rect
    size: float
    lines: tuple[tuple[str, ...], ...]
    text_top: float
    answers_top: float
    slots: tuple[tuple[int, float], ...]
    diagram: Rect | None

    def to_paper(self, x: float, y: float) -> tuple[float, float]:
        """Paper mm of the model point (x, y): the model box's lower-left corner at the figure's, y flipped."""
        f = self.scale.factor
        return (self.fig[0] + FIGURE_MARGIN + (x - self.box[0]) * f, self.fig[3] - FIGURE_MARGIN - (y - self.box[1]) * f)

    @property
    def frame(self) -> Rect:
        """The drawing frame (ISO 5457 margins)."""
        s = self.sheet
        return (s.margin_left, s.margin_top, s.width - s.margin_right, s.height - s.margin_bottom)


def answer_slots(labels: Sequence[str], width: float) -> list[tuple[int, float]]:
    """(row, x offset) of each answer box, its label (``"AB ="``) and its unit (``labels[i]`` is the label and
    the unit joined by a tab) flowed across ``width`` paper mm.

    >>> [(r, round(x)) for r, x in answer_slots(["AB =\tmm", "AD =\tmm", "αmax (rise) =\t°", "ψ =\t°"], 150.0)]
    [(0, 0), (0, 53), (1, 0), (1, 66)]
    """
    out: list[tuple[int, float]] = []
    row, x = 0, 0.0
    for lab in labels:
        w = slot_width(lab)
        if x > 0 and x + w > width:
            row, x = row + 1, 0.0
        out.append((row, x))
        x += w
    return out


def slot_width(label: str) -> float:
    """Paper mm of one answer slot: label, box, unit and a gap."""
    name, _, unit = label.partition("\t")
    return text_width(name, ANSWER_FONT) + 1.5 + BOX_W + 1.5 + text_width(unit or " ", ANSWER_FONT) + GAP


def layout(sheet: Sheet, scale: Scale, box: tuple[float, float, float, float], paragraphs: Sequence[str],
           answers: Sequence[str], diagram: bool = False) -> Layout:
    """The layout of a page: ``paragraphs`` (the statement in each language) wrapped to the frame's width, then
    the ``answers`` boxes (labels as :func:`answer_slots` takes them), then the figure of model ``box`` at
    ``scale``; with ``diagram`` a free strip beside or below it for a cam's s–δ axes (:func:`~.accept.diagram_strip`).

    Raises
    ------
    ValueError
        When the figure and the text cannot share the sheet even at the smallest statement font.
    """
    x0, y0 = sheet.margin_left, sheet.margin_top
    x1, y1 = sheet.width - sheet.margin_right, sheet.height - sheet.margin_bottom
    f = scale.factor
    fw = (box[2] - box[0]) * f + 2 * FIGURE_MARGIN
    fh = (box[3] - box[1]) * f + 2 * FIGURE_MARGIN
    text_w = x1 - x0 - 6.0
    slots = answer_slots(answers, text_w)
    rows = 1 + max((r for r, _ in slots), default=0)
    bottom = y1
    for size in FONT_SIZES:
        lines = tuple(tuple(wrap(p, text_w, size)) for p in paragraphs)
        n = sum(len(ls) for ls in lines)
        text_h = n * size * LINE + 2.0 * (len(lines) - 1)
        top = y0 + HEADER_H + text_h + 2.0 + ANSWER_H * rows
        if bottom - top >= fh - 1e-9:
            break
    else:
        raise ValueError(f"a figure {fh:.0f} mm high and {n} lines of statement do not fit {sheet}")
    where = diagram_strip((x1 - x0, y1 - top), (fw, fh)) if diagram else None
    if where == "right":
        fx, fy = x0, top + (y1 - top - fh) / 2
        diag: Rect | None = (x0 + fw, top, x1, y1)
    elif where == "below":
        fx, fy = x0 + (x1 - x0 - fw) / 2, top
        diag = (x0, top + fh, x1, y1)
    else:
        fx, fy = x0 + (x1 - x0 - fw) / 2, top + (y1 - top - fh) / 2
        diag = None
    return Layout(sheet, scale, box, (fx, fy, fx + fw, fy + fh), size, lines, y0 + HEADER_H,
                  y0 + HEADER_H + text_h + 2.0, tuple(slots), diag)


def u(x: float) -> str:
    """A paper length in user units (hundredths of a mm) as an integer.

    >>> u(12.346), u(-0.004)
    ('1235', '0')
    """
    n = round(x * U)
    return str(n if n != 0 else 0)


__all__ = ["ANSWER_FONT", "ANSWER_H", "BOX_W", "GAP", "answer_slots", "slot_width", "FONT_SIZES", "HEADER_H", "LINE", "Layout", "U", "layout", "u"]
