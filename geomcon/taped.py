"""Constructions replayed from tapes (:mod:`geomcon.scene.tape`): the recipe's Python runs once per shape of
givens, later solves of the same shape only compute the steps.

:func:`construct_taped` is what :func:`geomcon.solve.solve` calls. The first solves of a recipe build planned
scenes (:func:`~geomcon.plan.planned`) and learn its evaluation plan; once a solve follows a plan, the recipe is
recorded with symbolic givens, the tape is checked against that planned scene step by step, and later solves
with givens of the same shape (the same names, the same non-numeric values) replay it. A recipe the tape
cannot follow, or a plan that grows, falls back to the planned path, which is always right.

Examples
--------
>>> from geomcon.recipes import get_recipe
>>> r = get_recipe("crank_rocker.extremes")
>>> g = {"AB": 50.0, "BC": 70.0, "CD": 80.0, "AD": 90.0}
>>> for _ in range(3):
...     c = construct_taped(r, g)
...     theta = c.scene.value("theta")             # the first solve learns the plan, the second records
>>> is_taped(c.scene), round(theta, 9)
(True, 12.505586093)
"""
from __future__ import annotations

from typing import Any, Iterator, Mapping

from .plan import planned
from .recipes import Construction, Recipe
from .scene import LeanScenes
from .scene.scene import _KEEP, Scene
from .scene.tape import Escape, Sym, Tape, record, same_value, tracing

Entry = tuple[Tape | None, set[str], int]
_TAPES: dict[tuple, list[Entry]] = {}
"""(recipe, shape of the givens) → entries (the tape of one path through the recipe's decisions, or None when
the recipe cannot be taped for that shape; the plan it was made for; the plan's size then). An entry is
current while its plan is the one in use and has not grown."""
_TAPES_MAX = 1024
_PATHS_MAX = 4
"""Tapes kept per shape (paths through the recipe's decisions on the givens)."""


def shape_of(recipe: str, given: Mapping[str, Any]) -> tuple | None:
    """What a tape is made for: the recipe, the givens' names, and the value of each given that is not a
    float (a branch name, a count, a list of coordinates); None when such a value cannot be a key.

    >>> shape_of("r", {"AB": 1.0, "branch": "above"})
    ('r', 'AB', ('branch', 'above'))
    >>> shape_of("r", {"AB": 1.0, "BC": None, "L": [1.0, 2.0]})
    ('r', 'AB', ('BC', None), ('L', (1.0, 2.0)))
    >>> shape_of("r", {"AB": 1.0, "table": [{"a": 1.0}]}) is None
    True
    """
    parts: list[Any] = [recipe]
    other = False                                # a value that may not hash (a list is made a tuple)
    for n, v in given.items():
        t = type(v)
        if t is float:
            parts.append(n)
        elif v is None or t is str or t is bool:  # the usual others (a default left out, a branch): hashable
            parts.append((n, v))
        else:
            parts.append((n, tuple(v) if isinstance(v, list) else v))
            other = True
    key = tuple(parts)
    if other:
        try:
            hash(key)
        except TypeError:
            return None
    return key


def _current(entry: Entry, plan: str, title: str) -> bool:
    keep = entry[1]
    return _KEEP.get((plan, title)) is keep and len(keep) == entry[2]


def replay(tape: Tape, given: Mapping[str, Any]) -> Construction | None:
    """The construction of ``given`` from ``tape`` (None when the tape's arithmetic fails on these givens)."""
    memo = tape.values(given)
    if memo is None:
        return None
    sc = Scene.replayed(tape, memo)
    return Construction(sc, tape.answers, tape.points, tape.solutions, (), tape.no_solution)


_new = object.__new__


def replayed_construction(sc: Scene, tape: Tape) -> Construction:
    """``Construction(sc, tape.answers, tape.points, tape.solutions, (), tape.no_solution)``, its fields set
    in place (the frozen dataclass's ``__init__`` sets each through ``object.__setattr__``: a few µs of a
    replay that takes twenty).

    >>> from geomcon.recipes import get_recipe
    >>> r = get_recipe("guide_bar.extremes")
    >>> for _ in range(3):
    ...     c = construct_taped(r, {"AB": 145.0, "AC": 290.0})
    >>> c == Construction(c.scene, c.answers, c.points, c.solutions, (), c.no_solution)
    True
    """
    c = _new(Construction)
    c.__dict__.update(scene=sc, answers=tape.answers, points=tape.points, solutions=tape.solutions, warnings=(),
                      no_solution=tape.no_solution)
    return c


def is_taped(scene: Scene) -> bool:
    """True for a scene replayed from a tape that has not completed itself."""
    return scene._stale


def taped_values(recipe: Recipe, given: Mapping[str, Any]) -> tuple[Tape, dict[str, Any]] | None:
    """The current tape of ``recipe`` for the shape of ``given`` whose guards hold on it, and the memo a replay
    starts from (the tape's own steps computed: :meth:`~geomcon.scene.tape.Tape.values`); None when there is
    none (not yet recorded, not tapeable, another path through the recipe's decisions). :func:`_current_tapes`
    written out (a generator costs a replay more than its loop)."""
    key = shape_of(recipe.name, given)
    entries = _TAPES.get(key) if key is not None else None
    if entries:
        first = entries[0]
        for tape, _, _ in entries:
            if tape is not None and _current(first, recipe.name, tape.title):
                memo = tape._values(given)
                if memo is not None:
                    return tape, memo
    return None


def _current_tapes(recipe: Recipe, given: Mapping[str, Any]) -> Iterator[Tape]:
    """The tapes recorded for the shape of ``given`` that are still current for ``recipe``, in their order."""
    key = shape_of(recipe.name, given)
    entries = _TAPES.get(key) if key is not None else None
    for tape, _, _ in entries or ():
        if tape is not None and _current(entries[0], recipe.name, tape.title):
            yield tape


def taped_rebuild(recipe: Recipe, given: Mapping[str, Any], keys: tuple[str, ...]) -> tuple | None:
    """The values of the steps ``keys`` of ``recipe`` on ``given``, in their order, from the current tape
    whose guards hold on it (:func:`taped_values`'s choice), by its compiled rebuild
    (:meth:`~geomcon.scene.tape.Tape.rebuilder`: no scene, no memo); None when there is no such tape or its
    plan of ``keys`` is not compiled (the caller then builds the scene). A step that fails raises.

    >>> from geomcon.recipes import get_recipe
    >>> r, g = get_recipe("guide_bar.extremes"), {"AB": 145.0, "AC": 290.0}
    >>> for _ in range(3):
    ...     _ = construct_taped(r, g).scene.value("theta")
    >>> [round(x, 9) for x in taped_rebuild(r, {"AB": 100.0, "AC": 200.0}, ("theta",))]
    [60.0]
    """
    for tape in _current_tapes(recipe, given):
        run = tape.rebuilder(keys)
        if run is None:                               # as taped_values then the program: this tape if it holds
            if tape.values(given) is None:
                continue
            return None
        values = run(given)
        if values is not None:
            return values
    return None


def construct_taped(recipe: Recipe, given: Mapping[str, Any]) -> Construction:
    """``recipe.construct(given)`` in a lean scene: replayed from a tape when a current one exists, else
    planned (and, when that solve followed a plan, taped for the next solves of this shape)."""
    found = taped_values(recipe, given)
    if found is not None:
        tape, memo = found
        sc = Scene.replayed(tape, memo)
        sc.rebuild_with(lambda: recipe.construct(given).scene)    # its captions are the recording's
        return replayed_construction(sc, tape)
    key = shape_of(recipe.name, given)
    entries = _TAPES.get(key) if key is not None else None
    c = planned(recipe.name, recipe.construct, given)
    if key is None or c.scene.unplanned():
        return c
    title = c.scene.title
    if entries and not _current(entries[0], recipe.name, title):
        entries = None                                   # the plan grew: every path is recorded again
    if not entries:
        if len(_TAPES) >= _TAPES_MAX:
            _TAPES.clear()
        entries = _TAPES[key] = []
    if len(entries) < _PATHS_MAX and all(tape is not None for tape, _, _ in entries):
        entries.append(learn(recipe, given, title))
    return c


def learn(recipe: Recipe, given: Mapping[str, Any], title: str) -> tuple[Tape | None, set[str], int]:
    """Record ``recipe`` on ``given`` with symbolic givens and check the tape against a planned scene: every
    step of the plan that the planned scene computes without error must replay to the same value, bit for
    bit. Returns the entry of :data:`_TAPES` (its tape None when the recipe cannot be taped)."""
    keep = _KEEP.get((recipe.name, title), set())
    fail = (None, keep, len(keep))
    syms = {n: Sym.given(n, v) for n, v in given.items() if type(v) is float}
    try:
        with LeanScenes(recipe.name), tracing() as guards:
            traced = recipe.construct({**given, **syms})
        sc = traced.scene
        if sc.unplanned() or sc._keep is not keep or sc.title != title:
            return fail
        tape = record(sc, traced, keep, guards)
        if tape is None:
            return fail
        reference = planned(recipe.name, recipe.construct, given).scene
        if reference._keep is not keep:
            return fail
        want: dict[str, Any] = {}
        for k in list(reference._rec):
            try:
                want[k] = reference.value(k)
            except Exception:           # a step that fails on these givens fails alike on the tape
                continue
        c = replay(tape, given)
        if c is None:
            return fail
        got = c.scene.evaluate(tuple(want))
        if c.scene._stale and all(same_value(want[k], got[k]) for k in want):
            return tape, keep, len(keep)
    except (Escape, Exception):
        pass
    return fail
