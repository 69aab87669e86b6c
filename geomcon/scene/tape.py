"""Taped constructions: a recipe's planned scene recorded once with symbolic givens, then replayed on new
givens without running the recipe's Python again.

A planned solve still runs the recipe's ``construct``: its captions are formatted, its helpers called, every
kept step added. When the recipe's steps depend on the numeric givens only through arithmetic (``BC − AB``, a
pivot at ``(AD, 0)`` made by a step) the whole run can be recorded once: the float givens are handed to
``construct`` as :class:`Sym` values that remember the arithmetic done on them, and each step argument that
holds one becomes a reference to a small arithmetic step of the tape. Replaying the tape on new givens
computes that arithmetic (the same Python operations in the same order: the same bits) and hands the recorded
steps to a lean scene; nothing else of the recipe runs.

A decision the recipe's Python takes on a numeric given (a comparison, ``if x``, ``max``) is recorded as a
*guard* with its outcome: a replay first checks every guard on the new givens and leaves the tape when one
comes out differently (the planned path then runs, and may record the other path). What a tape cannot follow
raises :class:`Escape` and the recipe keeps the planned path: a given turned into a plain number
(``float()``, ``math.sin``, a ``Point`` made of it outside a step), used as a dictionary key, written into a
string that a step reads, or a construction with warnings. Every tape is also checked once, when it is made:
replayed on the givens it was recorded with, each step of the plan must give the value the planned scene
gives, bit for bit (by ``repr``), or the tape is dropped. A taped scene's captions hold the recording's
numbers, so it completes itself (a full build on its own givens) before anything reads a caption, a label or
a step object.

Examples
--------
>>> AB, BC = Sym.given("AB", 50.0), Sym.given("BC", 70.0)
>>> r = BC - AB
>>> r.v, f"{r:g}" == "20" + MARK               # marked: text a step reads must not hold a given
(20.0, True)
>>> with tracing() as guards:
...     big = r > 10.0
>>> big, len(guards)
(True, 1)
>>> try:
...     float(r)
... except Escape:
...     print("a plain number escapes the tape")
a plain number escapes the tape
"""
from __future__ import annotations

import operator
from contextlib import contextmanager
from dataclasses import dataclass, field
from ..cached import cached_property
from typing import Any, Callable, Iterator, Mapping

from ..geometry.branch import Branch
from .compiled import compile_plan, compile_values
from .step import Ref

PREFIX = "§"
"""Keys of a tape's own steps (the givens and their arithmetic) start with this; they are not the recipe's."""

MARK = "\u2063"
"""Appended to a symbolic given written as text (an invisible separator): text a step reads must not hold one."""

_GUARDS: list[list[tuple]] = []
"""The guards of the recording under way (innermost last)."""


@contextmanager
def tracing() -> Iterator[list[tuple]]:
    """Record the decisions taken on :class:`Sym` values within the block: ``(operation, arguments, outcome)``."""
    guards: list[tuple] = []
    _GUARDS.append(guards)
    try:
        yield guards
    finally:
        _GUARDS.pop()


class Escape(BaseException):
    """A numeric given left the tape: the recipe decided something on its value (a ``BaseException`` so that a
    recipe's own ``except Exception`` does not swallow it)."""


def _escape(self: Sym, *args: Any) -> Any:
    raise Escape(f"given {self.name()} used as a plain number")


def _v(x: Any) -> Any:
    return x.v if type(x) is Sym else x


class Sym:
    """A numeric given (or arithmetic on givens) during a recording: its value ``v`` and how it was made.

    Arithmetic gives new :class:`Sym`; formatting (captions) uses the value; anything that would turn it into
    a plain number or a decision raises :class:`Escape`.
    """

    __slots__ = ("v", "op", "args")

    def __init__(self, v: Any, op: Callable[..., Any] | None, args: tuple) -> None:
        self.v, self.op, self.args = v, op, args

    @classmethod
    def given(cls, name: str, value: float) -> Sym:
        """The given ``name`` with its value."""
        return cls(value, None, (name,))

    def name(self) -> str:
        """The given's name, or ``expression`` for arithmetic on givens."""
        return self.args[0] if self.op is None else "expression"

    def __format__(self, spec: str) -> str:
        return format(self.v, spec) + MARK

    def __str__(self) -> str:
        return str(self.v) + MARK

    def __repr__(self) -> str:
        return f"Sym({self.v!r})"

    def __bool__(self) -> bool:
        return _guard(operator.truth, (self,))

    __float__ = __int__ = __index__ = __complex__ = _escape
    __hash__ = __round__ = __trunc__ = __floor__ = __ceil__ = _escape


def _guard(op: Callable[..., Any], args: tuple) -> Any:
    if not _GUARDS:
        raise Escape("a decision on a given outside a recording")
    out = op(*[_v(a) for a in args])
    if type(out) is not bool:
        raise Escape("a decision on a given that is not true or false")
    _GUARDS[-1].append((op, args, out))
    return out


def _compare(op: Callable[[Any, Any], Any]) -> Callable:
    def f(a: Sym, b: Any) -> bool:
        return _guard(op, (a, b))
    return f


for _name, _op in (("lt", operator.lt), ("le", operator.le), ("gt", operator.gt), ("ge", operator.ge),
                   ("eq", operator.eq), ("ne", operator.ne)):
    setattr(Sym, f"__{_name}__", _compare(_op))


def _binary(op: Callable[[Any, Any], Any]) -> tuple[Callable, Callable]:
    def fwd(a: Sym, b: Any) -> Sym:
        return Sym(op(a.v, _v(b)), op, (a, b))

    def rev(a: Sym, b: Any) -> Sym:
        return Sym(op(_v(b), a.v), op, (b, a))
    return fwd, rev


def _unary(op: Callable[[Any], Any]) -> Callable:
    def f(a: Sym) -> Sym:
        return Sym(op(a.v), op, (a,))
    return f


for _name, _op in (("add", operator.add), ("sub", operator.sub), ("mul", operator.mul),
                   ("truediv", operator.truediv), ("floordiv", operator.floordiv), ("mod", operator.mod),
                   ("pow", operator.pow)):
    _f, _r = _binary(_op)
    setattr(Sym, f"__{_name}__", _f)
    setattr(Sym, f"__r{_name}__", _r)
for _name, _op in (("neg", operator.neg), ("pos", operator.pos), ("abs", operator.abs)):
    setattr(Sym, f"__{_name}__", _unary(_op))


def lifted(fn: Callable[..., Any], *args: Any) -> Any:
    """``fn(*args)``; during a recording, with a symbolic given among ``args``, the call is recorded on the tape
    (a :class:`Sym` of its result) so that a recipe may compute with givens through ``math`` (a rocker's end
    at ``CD·(cos a, sin a)``) and still be taped. ``fn`` must be a pure function of its arguments.

    >>> lifted(max, 2.0, 3.0)
    3.0
    >>> lifted(max, Sym.given("a", 2.0), 3.0).v
    3.0
    """
    for a in args:
        if type(a) is Sym:
            return Sym(fn(*[_v(b) for b in args]), fn, args)
    return fn(*args)


def _unset(*_: Any) -> Any:          # a tape's given: its value is put in the memo before evaluation
    raise AssertionError("a taped given was not set")


@dataclass(frozen=True)
class Tape:
    """One recipe's planned construction recorded for one shape of givens.

    ``rec`` are the scene's records with symbolic arguments turned into references to the tape's own steps;
    ``nodes`` compute those steps from the givens (key, operation, arguments: ``Ref`` of a given or an earlier
    node, or a constant); the rest rebuilds the :class:`~geomcon.recipes.Construction` around a new scene.
    """

    title: str
    rec: dict[str, tuple]
    skip: frozenset[str]
    sig: int
    keep: set[str]
    keep_len: int
    leaves: tuple[str, ...]
    nodes: tuple[tuple[str, Callable[..., Any], tuple], ...]
    guards: tuple[tuple[Callable[..., Any], tuple, bool], ...]
    answers: Mapping[str, str]
    points: Mapping[str, str]
    solutions: tuple[Mapping[str, str], ...]
    no_solution: str
    programs: dict[tuple[tuple[str, ...], Any], Callable[[Any], Any] | None] = field(default_factory=dict, compare=False,
                                                                          repr=False)

    @cached_property
    def inputs(self) -> frozenset[str]:
        """The keys of the tape's own steps (in a replayed scene's memo from the start)."""
        return frozenset([PREFIX + n for n in self.leaves] + [n[0] for n in self.nodes])

    @cached_property
    def leaf_keys(self) -> tuple[tuple[str, str], ...]:
        """``(memo key, given name)`` of each given the tape reads (the keys made once, not per replay)."""
        return tuple((PREFIX + n, n) for n in self.leaves)

    @cached_property
    def n_inputs(self) -> int:
        """How many steps the tape computes itself (a fresh replay's memo holds exactly these)."""
        return len(self.inputs)

    def program(self, keys: tuple[str, ...], *, values_only: bool = False) -> Callable[[dict], Any] | None:
        """The compiled evaluation of ``keys`` on a fresh replay (:func:`.compiled.compile_plan`), made once;
        ``values_only`` for a caller that reads ``keys`` and drops the memo (it returns nothing to settle)."""
        key = (keys, values_only)
        try:
            return self.programs[key]
        except KeyError:
            run = self.programs[key] = compile_plan(self.rec, keys, self.inputs, pending=not values_only)
            return run

    def rebuilder(self, keys: tuple[str, ...]) -> Callable[[Mapping[str, Any]], tuple | None] | None:
        """The compiled rebuild of ``keys`` from the givens (:func:`.compiled.compile_plan` with the tape as its
        ``source``), made once: ``run(given)`` computes the tape's steps, then the plan of ``keys`` on floats,
        and returns their values as a tuple (None where :meth:`values` gives None); no memo, no object but
        those the plan reads. None when a needed step is not a plain call.

        >>> from geomcon.recipes import get_recipe
        >>> from geomcon.taped import construct_taped, taped_values
        >>> r, g = get_recipe("guide_bar.extremes"), {"AB": 145.0, "AC": 290.0}
        >>> for _ in range(3):
        ...     _ = construct_taped(r, g).scene.value("theta")
        >>> tape, _ = taped_values(r, g)
        >>> [round(x, 9) for x in tape.rebuilder(("theta",))({"AB": 100.0, "AC": 200.0})]
        [60.0]
        """
        key = (keys, "given")
        try:
            return self.programs[key]
        except KeyError:
            run = self.programs[key] = compile_plan(self.rec, keys, self.inputs,
                                                    source=(self.leaf_keys, self.nodes, self.guards))
            return run

    def values(self, given: Mapping[str, Any]) -> dict[str, Any] | None:
        """The tape's own steps on ``given``: the memo a replayed scene starts from (None when the arithmetic
        fails: the planned path then raises what the recipe raises). One compiled function of the givens
        (:func:`.compiled.compile_values`), made on the first call: the givens read into the memo, each step
        computed from the ones before, each guard checked, as :meth:`values_stepwise` does step by step."""
        return self._values(given)

    @cached_property
    def _values(self) -> Callable[[Mapping[str, Any]], dict[str, Any] | None]:
        return compile_values((self.leaf_keys, self.nodes, self.guards))

    def values_stepwise(self, given: Mapping[str, Any]) -> dict[str, Any] | None:
        """:meth:`values` evaluated step by step (what the compiled function is held to in the tests)."""
        memo = {key: given[n] for key, n in self.leaf_keys}
        try:
            for key, op, args in self.nodes:
                memo[key] = op(*[memo[a[0]] if type(a) is Ref else a for a in args])
            for op, args, out in self.guards:
                if op(*[memo[a[0]] if type(a) is Ref else a for a in args]) is not out:
                    return None
        except ArithmeticError:
            return None
        return memo


def _is_str_map(m: Any) -> bool:
    return all(type(k) is str and type(v) is str for k, v in m.items())


def record(sc: Any, construction: Any, keep: set[str], guards: list[tuple]) -> Tape | None:
    """The tape of ``construction``, a recipe's construction built from :class:`Sym` givens in the planned
    scene ``sc`` following the plan ``keep``, with the ``guards`` of its recording (:func:`tracing`); None when
    a symbolic given sits where a tape cannot follow it."""
    if construction.warnings or not (_is_str_map(construction.answers) and _is_str_map(construction.points)
                                     and all(_is_str_map(m) for m in construction.solutions)):
        return None
    nodes: list[tuple[str, Callable[..., Any], tuple]] = []
    names: dict[int, str] = {}
    leaves: list[str] = []

    def node(s: Sym) -> Ref:
        key = names.get(id(s))
        if key is None:
            if s.op is None:
                key = PREFIX + s.args[0]
                leaves.append(s.args[0])
            else:
                args = tuple(node(a) if type(a) is Sym else a for a in s.args)
                key = f"{PREFIX}{len(nodes)}"
                nodes.append((key, s.op, args))
            names[id(s)] = key
        return Ref(key)

    found: list[str] = []

    def sub(x: Any) -> Any:
        t = type(x)
        if t is Sym:
            r = node(x)
            found.append(r[0])
            return r
        if t is tuple or t is list:
            y = [sub(e) for e in x]
            return tuple(y) if t is tuple else y
        if t is str and MARK in x:
            raise Escape("a step reads a given written as text")
        if isinstance(x, Branch) and any(type(r) is Sym for r in x.refs()):
            raise Escape("a branch rule holds a given")
        return x

    rec: dict[str, tuple] = {}
    try:
        for key, r in sc._rec.items():
            op, args, kwargs, mode, branch, brefs, optional, deps, meta = r
            found.clear()
            top = [type(a) is Sym for a in args]
            args2 = tuple(sub(a) for a in args)
            kwargs2 = {n: sub(v) for n, v in kwargs.items()}
            if branch is not None:
                sub(branch)
            if found:
                nested = len(found) > sum(top)
                mode = 2 if (nested or mode == 2) else 1
                deps = list(deps) + [k for k in found if k not in deps]
            rec[key] = (op, args2, kwargs2, mode, branch, brefs, optional, deps, meta)
        guarded = tuple((op, tuple(node(a) if type(a) is Sym else a for a in args), out)
                        for op, args, out in guards)
    except Escape:
        return None
    for k in [PREFIX + n for n in leaves] + [n[0] for n in nodes]:     # computed before the scene's steps
        rec[k] = (_unset, (), {}, 0, None, (), False, [], (("", ""), None, "", None, False, ""))
    sig = hash(("tape", sc.title, tuple((k, *r[7]) for k, r in rec.items())))
    return Tape(sc.title, rec, frozenset(sc._skip), sig, keep, len(keep), tuple(leaves),
                tuple(nodes), guarded, dict(construction.answers), dict(construction.points),
                tuple(dict(m) for m in construction.solutions), construction.no_solution)


def same_value(a: Any, b: Any) -> bool:
    """True when two step values are the same to the last bit (compared by type and ``repr``: floats print
    their shortest round-trip form, value objects their fields).

    >>> same_value(0.1 + 0.2, 0.3), same_value(-0.0, 0.0), same_value(1.5, 1.5)
    (False, False, True)
    """
    return type(a) is type(b) and repr(a) == repr(b)
