"""What a recipe is: one textbook construction with its named givens and answers and its analytic twin.

Examples
--------
>>> q = Quantity("AB", "mm", "crank length")
>>> q.name, q.unit, q.required
('AB', 'mm', True)
"""
from __future__ import annotations

from typing import Any, Callable, Mapping

from ..scene import Scene
from ..values import Frozen, store


class Quantity(Frozen):
    """A named given or answer.

    Parameters
    ----------
    name : str
        The public name (part of the contract: problem files and JSON use it).
    unit : str
        ``"mm"``, ``"deg"``, ``""`` (a ratio), ``"count"`` (a whole number), ``"rad/s"`` … (see
        :data:`geomcon.problems.RANGES`), ``"choice"`` (one of ``choices``), ``"bool"``,
        ``"point"`` (``[x, y]`` in mm), ``"mm[]"`` / ``"deg[]"`` / ``"[]"`` (a list of numbers; answers of
        these units are tuples, checked element by element) or ``"table[]"`` (givens only: a list of
        tables, e.g. a cam's motion program, whose contents the recipe validates).
    doc : str
        One line saying what it is.
    required : bool
        Givens only: must the problem file give it.
    default : Any
        Givens only: the value when not given.
    minimum : float
        Givens only: smallest admissible value.
    inclusive : bool
        Givens only: whether ``minimum`` itself is admissible (e ≥ 0) or not (AB > 0).
    maximum : float or None
        Givens only: largest admissible value (inclusive), on top of the unit's global range
        (:data:`geomcon.problems.RANGES`); for lists, of every element.
    choices : tuple of str
        Givens of unit "choice": the admissible words.
    unit_when : tuple of (str, str, str)
        Givens only: (given, word, unit) — the unit is ``unit`` when the choice ``given`` is ``word``
        (cam.base_radius's h: mm, or degrees when motion = "oscillating"; :func:`unit_in`).
    """

    _FIELDS = ("name", "unit", "doc", "required", "default", "minimum", "inclusive", "maximum", "choices",
               "unit_when")
    name: str
    unit: str
    doc: str
    required: bool
    default: Any
    minimum: float | None
    inclusive: bool
    maximum: float | None
    choices: tuple[str, ...]
    unit_when: tuple[tuple[str, str, str], ...]

    def __init__(self, name: str, unit: str, doc: str, required: bool = True, default: Any = None,
                 minimum: float | None = 0.0, inclusive: bool = False, maximum: float | None = None,
                 choices: tuple[str, ...] = (), unit_when: tuple[tuple[str, str, str], ...] = ()) -> None:
        for field, value in zip(self._FIELDS, (name, unit, doc, required, default, minimum, inclusive, maximum,
                                               choices, unit_when)):
            store(self, field, value)


def unit_in(q: Quantity, given: Mapping[str, Any]) -> str:
    """The unit of given ``q`` in a problem's ``given`` (:attr:`Quantity.unit_when`).

    >>> h = Quantity("h", "mm", "stroke", unit_when=(("motion", "oscillating", "deg"),))
    >>> unit_in(h, {"motion": "oscillating"}), unit_in(h, {"motion": "translating"}), unit_in(h, {})
    ('deg', 'mm', 'mm')
    """
    for name, word, unit in q.unit_when:
        if given.get(name) == word:
            return unit
    return q.unit


class Construction(Frozen):
    """A built scene plus the map from public names to its step keys.

    ``solutions`` lists, for problems with several solutions, the answer→step-key map of each candidate in
    the textbook's order of preference; a map may name a boolean ``_valid`` step, and the first valid
    candidate is the textbook's choice. ``no_solution`` is the refusal when no candidate is valid.
    """

    _FIELDS = ("scene", "answers", "points", "solutions", "warnings", "no_solution")
    scene: Scene
    answers: Mapping[str, str]
    points: Mapping[str, str]
    solutions: tuple[Mapping[str, str], ...]
    warnings: tuple[str, ...]
    no_solution: str

    def __init__(self, scene: Scene, answers: Mapping[str, str], points: Mapping[str, str],
                 solutions: tuple[Mapping[str, str], ...] = (), warnings: tuple[str, ...] = (),
                 no_solution: str = "") -> None:
        for field, value in zip(self._FIELDS, (scene, answers, points, solutions, warnings, no_solution)):
            store(self, field, value)


class Recipe(Frozen):
    """One textbook construction.

    Parameters
    ----------
    name : str
        Public recipe name, e.g. ``"crank_rocker.extremes"``.
    title : str
        One-line description.
    givens, answers : tuple of Quantity
        The contract: names, units, meaning.
    points : tuple of str
        Names of the points reported in the JSON.
    construct : callable
        ``construct(given) -> Construction``: adds the ruler-and-compass steps.
    analytic : callable
        ``analytic(given) -> [ {answer: value}, ... ]``: the independent closed form, one dict per solution in
        the order of ``Construction.solutions``.
    validate : callable or None
        ``validate(given) -> list[str]`` raises :class:`~geomcon.errors.NotAMechanism` for givens that
        describe no such mechanism, and returns warnings for borderline ones.
    back_check : callable or None
        ``back_check(given, answers) -> [(quantity, rebuilt, required, unit), ...]``: a design recipe rebuilds
        the designed linkage with the core's ``*.extremes`` construction and returns what it reproduces
        (K, H, ψ, the closing condition) next to what the problem required.
    order : callable or None
        Sort key of a solution's answers: the textbook's order of preference among several solutions (the
        construction's valid candidates are sorted by it; the twin returns its solutions in that order).
    advise : callable or None
        ``advise(given) -> [str, ...]``: the warnings that cost a computation of their own (a cam's ρmin and
        largest pressure angle against the allowance), made only when the warnings are asked for, never for
        answers alone; they are listed right after ``validate``'s.
    rigid : tuple of tuple of (str, str)
        Rigid links among the point givens, in groups: a link ``(anchor, point)`` draws ``point`` at the
        link's length from ``anchor``, and the links of one group are one link in its several positions (their
        lengths equal, as ``validate`` requires within its drafting limit): ``(("B1", "C1"), ("B2", "C2"),
        ("B3", "C3"))`` for a coupler BC given in three positions. A worksheet's drafting error moves such a
        point only as its link lets it (:mod:`geomcon.worksheet.drafting`). Each point has at most one anchor.
    """

    _FIELDS = ("name", "title", "givens", "answers", "points", "construct", "analytic", "validate", "back_check",
               "order", "advise", "rigid")
    name: str
    title: str
    givens: tuple[Quantity, ...]
    answers: tuple[Quantity, ...]
    points: tuple[str, ...]
    construct: Callable[[Mapping[str, Any]], Construction]
    analytic: Callable[[Mapping[str, Any]], list[dict[str, float]]]
    validate: Callable[[Mapping[str, Any]], list[str]] | None
    back_check: Callable[[Mapping[str, Any], Mapping[str, float]], list[tuple[str, float, float, str]]] | None
    order: Callable[[Mapping[str, float]], Any] | None
    advise: Callable[[Mapping[str, Any]], list[str]] | None
    rigid: tuple[tuple[tuple[str, str], ...], ...]

    def __init__(self, name: str, title: str, givens: tuple[Quantity, ...], answers: tuple[Quantity, ...],
                 points: tuple[str, ...], construct: Callable[[Mapping[str, Any]], Construction],
                 analytic: Callable[[Mapping[str, Any]], list[dict[str, float]]],
                 validate: Callable[[Mapping[str, Any]], list[str]] | None = None,
                 back_check: Callable[[Mapping[str, Any], Mapping[str, float]],
                                      list[tuple[str, float, float, str]]] | None = None,
                 order: Callable[[Mapping[str, float]], Any] | None = None,
                 advise: Callable[[Mapping[str, Any]], list[str]] | None = None,
                 rigid: tuple[tuple[tuple[str, str], ...], ...] = ()) -> None:
        for field, value in zip(self._FIELDS, (name, title, givens, answers, points, construct, analytic, validate,
                                               back_check, order, advise, rigid)):
            store(self, field, value)

    def given_names(self) -> tuple[str, ...]:
        """Names of all givens, required first."""
        return tuple(q.name for q in self.givens)

    def answer(self, name: str) -> Quantity:
        """The answer quantity called ``name``."""
        for q in self.answers:
            if q.name == name:
                return q
        raise KeyError(name)
