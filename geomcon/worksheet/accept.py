"""Whether a variant may go on a sheet, and its key if so.

A variant is judged by these checks, cheapest first; the first that fails is its rejection reason
(:data:`REASONS`, the codes the statistics count):

``invalid``            its givens are refused as a problem file's would be (a range, a form of the recipe);
``no_mechanism``       the recipe does not solve it (no crank, circles that do not meet …);
``missing_answer``     an asked or required answer does not exist in this form;
``several_solutions``  several valid solutions, and the statement does not name the textbook's choice (the
                       default statements do, for every recipe with a sentence in :data:`~.statements.CHOICE`;
                       a spec's own statement must hold ``{choice}``);
``require``            a ``[require]`` bound fails;
``borderline``         the construction warns (Grashof equality, a rod perpendicular to its guide …);
``fit``                the key's whole construction does not fit the sheet at a standard scale (or at the spec's
                       ``scale``): :func:`fit_construction`;
``crossing``           an intersection the student constructs crosses at less than 20°;
``crowded``            two labelled points (of the construction, or of the givens the sheet draws) lie closer
                       than 4 mm on paper;
``labels``             a label of the student's sheet can only be placed over another label or a point
                       (:func:`~.givens_figure.place_labels`);
``undeterminable``     a drafting interval leaves the recipe's domain;
``tolerance``          an asked answer's drafting tolerance exceeds 5 % of it (``max_tol_rel``);
``twin``               the construction disagrees with the analytic twin (last: it never happens on a sound
                       recipe, and a cam's twin costs more than the rest).

The figure of each exercise is drawn at the largest standard scale at which its extent (what the student draws
and everything the key draws of the solution: θ-circle, construction lines, compass arcs), with
:data:`FIGURE_MARGIN` around it, fits the sheet (either orientation) below a band of :data:`TEXT_BAND` mm for
the statement and the answer boxes. A cam's s–δ axes take a free strip of :data:`DIAGRAM_MIN` beside or below
its figure when there is one (:func:`diagram_strip`), else a page of their own: they never lower the scale.

Examples
--------
>>> from geomcon.paper import PAPERS
>>> from geomcon.worksheet.spec import parse_spec
>>> ex = parse_spec('''
... [[exercise]]
... recipe = "crank_rocker.design_by_K"
... ask = ["AB", "AD"]
... [exercise.given]
... K = 1.25
... CD = 90
... psi = 40
... BC = [95, 300]
... ''').exercises[0]
>>> ok = judge(ex, 0, PAPERS["A4"])
>>> str(ok.scale), [(a.ref.text, round(a.value, 3), round(a.tol, 2)) for a in ok.answers], ok.several
('1:2', [('AB', 26.389, 1.2), ('AD', 90.0, 1.93)], True)
>>> judge(ex, 1, PAPERS["A4"]).reason
'no_mechanism'
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

from ..errors import GeomconError, ProblemError
from ..paper import STANDARD, Paper, Scale, Sheet, choose_scale
from ..solve import Solution
from .drafting import Undeterminable, tolerances
from .key_extent import drawn_box, figure_box, key_content
from .givens_figure import Item, given_gap, given_items, place_labels
from .overlay import position_tolerances
from .readability import MIN_CROSSING, MIN_POINT_GAP, closest_points, crossings, extent
from .solving import read, solve_given
from .spec import AnswerRef, Exercise
from .statements import CHOICE

REASONS = ("invalid", "no_mechanism", "missing_answer", "several_solutions", "require", "borderline", "fit",
           "crossing", "crowded", "labels", "undeterminable", "tolerance", "twin")
"""Rejection codes, in the order the checks run."""

TEXT_BAND = 60.0
"""Paper mm of a sheet's height kept for an exercise's statement and answer boxes."""
DIAGRAM_MIN = (90.0, 32.0)
"""Smallest free strip (paper mm, width and height) beside or below a cam's figure for its s–δ axes."""
FIGURE_MARGIN = 8.0
"""Paper mm kept free around a figure (labels, dimension lines)."""


@dataclass(frozen=True)
class AnswerKey:
    """One asked answer of an accepted variant: its exact value, its unit, the tolerance it is graded at (the
    spec's rule, else the drafting one), the drafting tolerance, and the scale its value is written at."""

    ref: AnswerRef
    value: float
    tol: float
    drafting_tol: float
    scale: float


@dataclass(frozen=True)
class Solved:
    """What judging an accepted variant computed that its pages draw: its solution (the full scene, with the
    values the checks evaluated), the model box of its figure (:func:`~.readability.extent`), the givens its
    sheet draws (:func:`~.givens_figure.given_items`) and the radius (paper mm) of the key overlay's tolerance
    circle around each point the student constructs (:func:`~.overlay.position_tolerances`, from the solutions
    at the ends of each drafting interval that the answers' tolerances solved)."""

    sol: Solution
    box: tuple[float, float, float, float]
    items: tuple[Item, ...]
    radii: Mapping[str, float]


@dataclass(frozen=True)
class Accepted:
    """An accepted variant: pool index, raw givens, the sheet and scale its figure is drawn at, its answers;
    ``several`` when it has several valid solutions (its statement names the textbook's choice); ``solved``
    what judging it solved (:class:`Solved`; None for a variant made otherwise, which the pages solve again).
    """

    index: int
    given: Mapping[str, Any]
    scale: Scale
    sheet: Sheet
    answers: tuple[AnswerKey, ...]
    several: bool
    solved: Solved | None = field(default=None, compare=False, repr=False)

    reason = None


@dataclass(frozen=True)
class Rejected:
    """A rejected variant: pool index, reason code (:data:`REASONS`) and a line saying why with the numbers."""

    index: int
    reason: str
    detail: str


def _refs(ex: Exercise) -> tuple[AnswerRef, ...]:
    """The asked answers, then the required ones not asked."""
    asked = {a.text for a in ex.ask}
    return ex.ask + tuple({b.answer.text: b.answer for b in ex.require if b.answer.text not in asked}.values())


def names_choice(ex: Exercise) -> bool:
    """Whether the exercise's statement names the textbook's choice among several solutions."""
    if ex.recipe not in CHOICE:
        return False
    if ex.statement is None:
        return True
    return all("{choice}" in t.replace("{{", "").replace("}}", "") for t in ex.statement.values())


def diagram_strip(area: tuple[float, float], fig: tuple[float, float]) -> str | None:
    """Where a cam's s–δ axes go beside a figure of paper size ``fig`` (margins included) in ``area`` (paper
    width and height below the text): ``"right"`` or ``"below"`` (the larger free strip of at least
    :data:`DIAGRAM_MIN`), None when neither is free.

    >>> diagram_strip((180.0, 217.0), (176.0, 176.0)), diagram_strip((267.0, 130.0), (120.0, 120.0))
    ('below', 'right')
    """
    (aw, ah), (fw, fh) = area, fig
    right = (aw - fw) * ah if aw - fw >= DIAGRAM_MIN[0] and ah >= DIAGRAM_MIN[1] else 0.0
    below = aw * (ah - fh) if ah - fh >= DIAGRAM_MIN[1] and aw >= DIAGRAM_MIN[0] else 0.0
    if right == below == 0.0:
        return None
    return "right" if right > below else "below"


def sheet_at(size: tuple[float, float], scale: Scale, paper: Paper) -> Sheet | None:
    """The first orientation of ``paper``, portrait first, on which a figure of model ``size`` fits at ``scale``
    below the :data:`TEXT_BAND` with :data:`FIGURE_MARGIN` around it; None when it fits neither."""
    for orientation in ("portrait", "landscape"):
        sheet = paper.sheet(orientation)
        aw, ah = sheet.area
        try:
            choose_scale(size, (aw, ah - TEXT_BAND), margin=FIGURE_MARGIN, series=(scale,))
            return sheet
        except ValueError:
            continue
    return None


def fit_construction(ex: Exercise, sol: Solution, names: list[str], paper: Paper
                     ) -> tuple[Scale, Sheet, tuple[float, float, float, float]]:
    """The scale, sheet and model box of a variant's figure: the box holds what the student draws
    (:func:`~.readability.extent`) and the key's whole construction at that scale (its
    content and compass arcs: :func:`~.key_extent.figure_box`), so that the sheet leaves room for every part of the solution. The
    largest standard scale (or the spec's ``scale``) at which that box fits the sheet, either orientation,
    portrait first. ValueError when it fits at none: the variant is ill-posed (``fit``), never cut."""
    content = key_content(sol)
    drawn = drawn_box(sol, names, content)
    series = STANDARD if ex.scale is None else (ex.scale,)

    def size(b: tuple[float, float, float, float]) -> tuple[float, float]:
        return (b[2] - b[0], b[3] - b[1])

    box = drawn
    for scale in reversed(series):
        if sheet_at(size(drawn), scale, paper) is None:   # the compass arcs only add to it: no need to sample them
            continue
        box = figure_box(sol, names, scale.factor, content, drawn)
        sheet = sheet_at(size(box), scale, paper)
        if sheet is not None:
            return scale, sheet, box
    w, h = size(box)
    raise ValueError(f"the key's construction of {w:.4g} × {h:.4g} mm does not fit {paper.name} "
                     f"even at {series[0]}")


def judge(ex: Exercise, index: int, paper: Paper) -> Accepted | Rejected:
    """Judge variant ``index`` of exercise ``ex`` on ``paper`` (see the module for the checks)."""
    given = ex.given_of(index)
    refs = _refs(ex)
    try:
        sol = solve_given(ex.recipe, given)
        cands = read(sol, refs)
    except ProblemError as exc:
        return Rejected(index, "invalid", str(exc))
    except GeomconError as exc:
        return Rejected(index, "no_mechanism", str(exc))
    chosen = cands[0]
    gone = [r.text for r in refs if chosen[r.text] is None]
    if gone:
        return Rejected(index, "missing_answer", f"answer '{gone[0]}' does not exist for these givens")
    several = len(cands) > 1
    if several and not names_choice(ex):
        return Rejected(index, "several_solutions", f"{len(cands)} valid solutions and the statement does not name "
                                                    "the textbook's choice")
    for b in ex.require:
        x = chosen[b.answer.text]
        if not b.holds(x):
            return Rejected(index, "require", f"{b.answer.text} = {x:.6g}, required {b.text()}")
    try:
        warned = sol.construction_warnings
        if warned:
            return Rejected(index, "borderline", warned[0])
        names = [r.name for r in ex.ask]
        try:
            scale, sheet, box = fit_construction(ex, sol, names, paper)
        except ValueError as exc:
            return Rejected(index, "fit", str(exc))
        flat = [(k, cap, a) for k, cap, a in crossings(sol, names) if a < MIN_CROSSING - 1e-9]
        if flat:
            k, cap, a = min(flat, key=lambda t: t[2])
            return Rejected(index, "crossing", f"step '{k}' ({cap}) crosses at {a:.3g}° < {MIN_CROSSING:g}°")
        close = closest_points(sol)
        if close is not None and scale.to_paper(close[2]) < MIN_POINT_GAP:
            return Rejected(index, "crowded", f"points {close[0]} and {close[1]} lie {scale.to_paper(close[2]):.3g} mm "
                                              f"apart on paper at {scale} (at least {MIN_POINT_GAP:g} mm)")
        items = given_items(sol)
        gap = given_gap(items)
        if gap is not None and scale.to_paper(gap[2]) < MIN_POINT_GAP:
            return Rejected(index, "crowded", f"given points {gap[0]} and {gap[1]} lie {scale.to_paper(gap[2]):.3g} mm "
                                              f"apart on paper at {scale} (at least {MIN_POINT_GAP:g} mm)")
        f = scale.factor
        _, bad = place_labels(items, lambda x, y: (x * f, -y * f))
        if bad:
            return Rejected(index, "labels", f"the label {bad[0]} of the sheet's givens overlaps another label or a "
                                             f"point at {scale}")
        nominal = {r.text: chosen[r.text] for r in ex.ask}
        try:
            limits = {r.text: ex.max_tol_rel * abs(nominal[r.text]) for r in ex.ask}
            ends: dict[str, tuple[Solution, Solution]] = {}
            tols = tolerances(ex.recipe, given, ex.ask, nominal, scale.factor, limits=limits, keep=ends)
        except Undeterminable as exc:
            return Rejected(index, "undeterminable", str(exc))
        for r in ex.ask:
            v, t = nominal[r.text], tols[r.text]
            if t > limits[r.text]:
                return Rejected(index, "tolerance", f"{r.text} = {v:.6g} is determined by a drawing at {scale} only "
                                                    f"to ±{t:.3g} or worse ({100 * t / abs(v) if v else float('inf'):.3g} %, "
                                                    f"at most {100 * ex.max_tol_rel:g} %)")
        if not sol.ok:                  # the twin last: it never fails on a sound recipe, and a cam's twin is costly
            bad = next(r for r in sol.checks if not r["ok"])
            return Rejected(index, "twin", f"{bad['quantity']}: construction {bad['construction']!r} vs analytic "
                                           f"{bad['analytic']!r}")
    except GeomconError as exc:
        return Rejected(index, "no_mechanism", str(exc))
    out = []
    for r in ex.ask:
        v, t = nominal[r.text], tols[r.text]
        rule = ex.tol.get(r.text)
        graded = rule.of(v) if rule is not None else t
        out.append(AnswerKey(r, v, graded, t, sol.unit_scale(r.unit)))
    radii = position_tolerances(sol, given, scale.factor, ends)
    return Accepted(index, given, scale, sheet, tuple(out), several, Solved(sol, box, tuple(items), radii))


__all__ = ["Accepted", "AnswerKey", "DIAGRAM_MIN", "FIGURE_MARGIN", "REASONS", "Rejected", "Solved", "TEXT_BAND",
           "diagram_strip", "fit_construction", "judge", "names_choice", "sheet_at"]
