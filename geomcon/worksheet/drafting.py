"""The drafting tolerance of an answer: how far a careful drawing at the sheet's scale may land from the
exact value.

Model. A student lays off every given with a drafting error: a length with ±0.5 mm **on paper** (0.5 mm
divided by the scale factor in real mm: 1 mm at 1:2), an angle with ±0.5° (a protractor's reading), the
time-ratio coefficient K through its angle θ = 180°(K − 1)/(K + 1) with ±0.5° (θ is what is drawn), a point
with ±0.5 mm on paper in x and in y, each boundary between two segments of a cam's motion program with ±0.5°
(the segment before it grows, the one after shrinks: the program still spans 360°). Then the answer is read
off the drawing with ±0.5 mm on paper (a length) or ±0.5° (an angle); K is read through θ. A given that is
not drawn is not perturbed: a length of 0 (a centric follower's offset, nothing to lay off), K = 1 (θ = 0), a
choice, a count, and the sampling ``tolerance`` of a cam profile.

Rigid bodies. Points given as one body in several positions (:attr:`~geomcon.recipes.base.Recipe.rigid`: a
coupler B_iC_i in three positions, an input link AB_i and the coupler's point K_i) are drafted as bodies, not
point by point: the data must stay one rigid body (the recipe refuses links that differ by more than 1 %, and
one point moved 0.5 mm on paper at 1:2 made a 50 mm coupler differ by 2 %). A free point (B_i, A, D) is drafted
in x and in y and carries what rides on it (C_i rides on B_i, B_i and K_i on A): the whole position moves; a
link's point is turned about its anchor so that it moves ±0.5 mm on paper across the link ("C1 ⊥ B1C1"), what
rides on it moving with it; and each group's common length is drafted once, ±0.5 mm on paper along every link
("BC (length)"). That is one drafted quantity per degree of freedom of the data (three coupler positions: 10),
and every drafted end is as rigid as the givens. A point's error along its own link in one position alone
would make the body not rigid; below the recipe's limit the recipe fits it away (each point slid to the mean
length), so it does not move the answer.

Propagation. For each drafted quantity i the answer's shift is the central difference of the solve over
the drafting interval itself, d_i = (a(g_i + δ_i) − a(g_i − δ_i)) / 2: the secant over the interval the
student can actually land in, so a strongly curved answer is not judged by a derivative at one point, and
no step size has to be chosen. The errors of separate operations are independent and of either sign, so
they combine as the root-sum-square (the GUM's law of propagation for uncorrelated inputs),
tol = √(Σ d_i² + r²), r the reading error. A worst-case sum Σ|d_i| would grade a drawing with six givens as
if every error had conspired; a single largest term would ignore that they add up. Intermediate
constructed points (an intersection placed with its own ±0.5 mm) are not propagated separately: their
sensitivities are not exposed by the scene yet; the reading error of the answer stands in for the last one.

A drafting interval that leaves the recipe's domain (the mechanism ceases to exist within the drawing's
accuracy) makes the variant undeterminable: :class:`Undeterminable` names the given.

Examples
--------
>>> from geomcon.worksheet.spec import AnswerRef
>>> ab = AnswerRef("AB", "AB", None, "mm")
>>> g = {"K": 1.5, "CD": 75, "AD": 100, "phi": 45}
>>> far, near = {"AB": 49.3117990843}, {"AB": 22.5119573574}   # the two designs of issue 12's worked check
>>> round(shifts("crank_rocker.design_by_K", g, (ab,), far, 1.0)["K (θ)"]["AB"], 2)
0.22
>>> round(shifts("crank_rocker.design_by_K", g, (ab,), near, 1.0)["K (θ)"]["AB"], 2)
0.03
>>> round(tolerances("crank_rocker.design_by_K", g, (ab,), far, 0.5)["AB"], 3)
1.149
>>> pos = {"B1": [0, 0], "C1": [0, 50], "B2": [-20, 35], "C2": [10, 75], "B3": [-20, 85], "C3": [30, 85]}
>>> [d.name for d in drafted("four_bar.three_positions", pos, 0.5)][4:]
['B3.x', 'B3.y', 'C1 ⊥ B1C1', 'C2 ⊥ B2C2', 'C3 ⊥ B3C3', 'BC (length)']
>>> {k: v for k, v in drafted("four_bar.three_positions", pos, 0.5)[1].plus.items() if v != pos[k]}
{'B1': [0.0, 1.0], 'C1': [0.0, 51.0]}
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Mapping, Sequence

from ..errors import GeomconError
from ..recipes import get_recipe
from ..recipes.base import unit_in
from .bodies import Bodies, is_point, point_drafts
from .solving import read, solve_given
from .spec import AnswerRef

PAPER_MM = 0.5
"""Drafting error of a length laid off or read on paper (mm)."""
DEGREES = 0.5
"""Drafting error of an angle laid off or read (degrees)."""
NOT_DRAWN = frozenset({"tolerance"})
"""Givens of unit mm or deg that a student never draws."""


class Undeterminable(GeomconError):
    """A drafting interval of a given leaves the recipe's domain: the drawing cannot determine the answer."""


@dataclass(frozen=True)
class Drafted:
    """One drafted quantity: its name as a report says it, and the givens at its two ends."""

    name: str
    plus: Mapping[str, Any]
    minus: Mapping[str, Any]


def theta_of_k(k: float) -> float:
    """θ = 180°(K − 1)/(K + 1).

    >>> theta_of_k(1.5)
    36.0
    """
    return 180.0 * (k - 1.0) / (k + 1.0)


def k_of_theta(theta: float) -> float:
    """K = (180° + θ)/(180° − θ)."""
    return (180.0 + theta) / (180.0 - theta)


def drafted(recipe: str, given: Mapping[str, Any], factor: float) -> list[Drafted]:
    """Every drafted quantity of a variant with raw givens ``given`` drawn at scale ``factor`` (paper mm per
    real mm), in the recipe's order of givens.

    >>> [d.name for d in drafted("crank_rocker.design_by_K", {"K": 1.25, "CD": 90, "psi": 40, "BC": 95}, 0.5)]
    ['K (θ)', 'CD', 'psi', 'BC']
    >>> d = drafted("crank_rocker.design_by_K", {"K": 1.25, "CD": 90, "psi": 40, "BC": 95}, 0.5)[1]
    >>> d.plus["CD"], d.minus["CD"]
    (91.0, 89.0)
    """
    rec = get_recipe(recipe)
    length = PAPER_MM / factor
    bodies = Bodies.of(rec.rigid, given)
    out: list[Drafted] = []

    def with_value(name: str, value: Any) -> dict[str, Any]:
        g = dict(given)
        g[name] = value
        return g

    for q in rec.givens:
        v = given.get(q.name)
        if v is None or q.name in NOT_DRAWN:
            continue
        unit = unit_in(q, given)                # cam.base_radius's h: degrees for an arm
        if unit in ("mm", "deg") and _num(v):
            if unit == "mm" and float(v) == 0.0:
                continue
            d = length if unit == "mm" else DEGREES
            out.append(Drafted(q.name, with_value(q.name, float(v) + d), with_value(q.name, float(v) - d)))
        elif q.unit == "" and q.name == "K" and _num(v) and float(v) != 1.0:
            th = theta_of_k(float(v))
            out.append(Drafted("K (θ)", with_value("K", k_of_theta(th + DEGREES)),
                               with_value("K", k_of_theta(th - DEGREES))))
        elif q.unit == "point" and is_point(v):
            out.extend(Drafted(*d) for d in point_drafts(bodies, q.name, given, length))
        elif q.unit in ("mm[]", "deg[]") and isinstance(v, (list, tuple)):
            d = length if q.unit == "mm[]" else DEGREES
            for i, x in enumerate(v):
                if not _num(x) or (q.unit == "mm[]" and float(x) == 0.0):
                    continue
                p, m = list(v), list(v)
                p[i], m[i] = float(x) + d, float(x) - d
                out.append(Drafted(f"{q.name}[{i}]", with_value(q.name, p), with_value(q.name, m)))
        elif q.unit == "table[]" and isinstance(v, (list, tuple)):
            for i in range(len(v) - 1):
                a, b = v[i].get("angle"), v[i + 1].get("angle")
                if not (_num(a) and _num(b)):
                    continue
                plus = [dict(r) for r in v]
                minus = [dict(r) for r in v]
                plus[i]["angle"], plus[i + 1]["angle"] = float(a) + DEGREES, float(b) - DEGREES
                minus[i]["angle"], minus[i + 1]["angle"] = float(a) - DEGREES, float(b) + DEGREES
                out.append(Drafted(f"{q.name} boundary {i + 1}|{i + 2}", with_value(q.name, plus),
                                   with_value(q.name, minus)))
    return out


def _num(v: Any) -> bool:
    return not isinstance(v, bool) and isinstance(v, (int, float))


def reading(ref: AnswerRef, value: float, factor: float) -> float:
    """The error of reading an answer off the drawing: ±0.5 mm on paper, ±0.5°, K through θ; 0 for other
    ratios (computed, not read).

    >>> from geomcon.worksheet.spec import AnswerRef
    >>> reading(AnswerRef("AB", "AB", None, "mm"), 20.0, 0.5), reading(AnswerRef("K", "K", None, ""), 1.5, 1.0)
    (1.0, 0.008680555555555556)
    """
    if ref.unit == "mm":
        return PAPER_MM / factor
    if ref.unit == "deg":
        return DEGREES
    if ref.name == "K" and value >= 1.0:
        th = theta_of_k(value)
        return 360.0 / (180.0 - th) ** 2 * DEGREES
    return 0.0


def nearest(candidates: Sequence[Mapping[str, float | None]], nominal: Mapping[str, float]) -> Mapping[str, float] | None:
    """The candidate solution closest to ``nominal`` (worst relative difference over its answers), among those
    holding every answer; None when none does."""
    best, best_cost = None, math.inf
    for c in candidates:
        if any(c.get(k) is None for k in nominal):
            continue
        cost = max((abs(c[k] - v) / max(abs(v), 1e-300) for k, v in nominal.items()), default=0.0)
        if cost < best_cost:
            best, best_cost = c, cost
    return best


def shift_rows(recipe: str, given: Mapping[str, Any], refs: Sequence[AnswerRef], nominal: Mapping[str, float],
               factor: float, *, solve: Callable[[str, Mapping[str, Any]], Any] = solve_given,
               keep: dict[str, tuple[Any, Any]] | None = None) -> Iterator[tuple[str, dict[str, float]]]:
    """(drafted quantity, {asked answer: its shift}) one drafted quantity at a time: each shift is
    d_i = (a(g_i + δ_i) − a(g_i − δ_i)) / 2 in the solution nearest the chosen one (``nominal``: the asked
    answers' values there) at both ends. With ``keep``, each drafted quantity's two solutions (``g + δ``,
    ``g − δ``) are stored there under its name, for the key's overlay (:mod:`.overlay`) to read its points
    from without solving again.

    Raises
    ------
    Undeterminable
        When a drafting interval leaves the recipe's domain or loses the answer.
    """
    for d in drafted(recipe, given, factor):
        ends = []
        sols = []
        for g in (d.plus, d.minus):
            try:
                sol = solve(recipe, g)
                sols.append(sol)
                cands = read(sol, refs)
            except GeomconError as exc:
                raise Undeterminable(f"{d.name} ± its drafting error leaves the domain: {exc}") from None
            best = nearest(cands, nominal)
            if best is None:
                raise Undeterminable(f"{d.name} ± its drafting error loses an asked answer")
            ends.append(best)
        if keep is not None:
            keep[d.name] = (sols[0], sols[1])
        yield d.name, {r.text: (ends[0][r.text] - ends[1][r.text]) / 2.0 for r in refs}


def shifts(recipe: str, given: Mapping[str, Any], refs: Sequence[AnswerRef], nominal: Mapping[str, float],
           factor: float, *, solve: Callable[[str, Mapping[str, Any]], Any] = solve_given) -> dict[str, dict[str, float]]:
    """Every drafted quantity's shifts of the asked answers (:func:`shift_rows`)."""
    return dict(shift_rows(recipe, given, refs, nominal, factor, solve=solve))


def tolerances(recipe: str, given: Mapping[str, Any], refs: Sequence[AnswerRef], nominal: Mapping[str, float],
               factor: float, *, limits: Mapping[str, float] | None = None,
               solve: Callable[[str, Mapping[str, Any]], Any] = solve_given,
               keep: dict[str, tuple[Any, Any]] | None = None) -> dict[str, float]:
    """The drafting tolerance of each asked answer (``refs``, whose values in the chosen solution are
    ``nominal``) of a variant drawn at ``factor`` paper mm per real mm: √(Σ d_i² + r²) (:func:`shift_rows`,
    :func:`reading`).

    With ``limits`` (answer → largest tolerance accepted) the sum stops as soon as one answer's partial sum
    exceeds its limit, and the partial sums are returned: each is then a lower bound of the full tolerance, so
    a variant rejected on it is rejected exactly as on the full sum, without the remaining solves. ``keep``:
    see :func:`shift_rows`.

    Raises
    ------
    Undeterminable
        When a drafting interval leaves the recipe's domain or loses the answer.
    """
    sums = {r.text: reading(r, nominal[r.text], factor) ** 2 for r in refs}
    caps = {k: v * v for k, v in (limits or {}).items()}

    def over() -> bool:
        return any(sums[k] > c for k, c in caps.items())

    if not over():
        for _, by_ref in shift_rows(recipe, given, refs, nominal, factor, solve=solve, keep=keep):
            for k, d in by_ref.items():
                sums[k] += d * d
            if over():
                break
    return {k: math.sqrt(s) for k, s in sums.items()}


__all__ = ["DEGREES", "Drafted", "NOT_DRAWN", "PAPER_MM", "Undeterminable", "drafted", "k_of_theta", "nearest",
           "reading", "shift_rows", "shifts", "theta_of_k", "tolerances"]
