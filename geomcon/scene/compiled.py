"""A taped scene's evaluation plan as one Python function: the steps a request needs, in order, each a call on
local variables, no dictionary lookups or argument resolution per step.

The source is generated from the recorded steps' shapes alone: local names ``v0_0, o3, …`` and the operations,
constants and branch rules bound by name in the function's namespace (``k3``, ``f3``, ``c3_1``, ``b3``); no key,
label or value of a problem ever becomes source text (keys are read and written through a tuple of them). A
request whose steps are not all plain calls (nested references such as a tuple of points) gets no function and
is evaluated step by step as before.

A step whose operation has a float kernel (:mod:`geomcon.geometry.kernels`) is computed on floats: a point is
two locals, a line four, a circle three, and a branch rule with a kernel chooses among flat candidates; the
step's object (a :class:`~geomcon.geometry.Point`, a ``Line`` …) is made only where something reads it: an
operation without a kernel, an answer asked for, or the scene's memo when it is read further (``run`` returns
``(fill, tol)`` for that, ``fill`` computing them again from the same inputs under the tolerance ``tol``
of the run; :meth:`~geomcon.scene.Scene.settle`). The kernels are the operations' own
arithmetic, so every value is the same to the last bit. The branches of one intersection (two steps calling
the same operation on the same arguments, each with its own rule) share one call: each rule chooses from the
same candidates, as two separate calls would give them (the operations are pure). An optional step (a
candidate that may not exist) is None when a step it refers to is None or, for an intersection, when nothing
meets, as the scene's own evaluation decides.

Examples
--------
>>> from geomcon.scene.step import Ref
>>> rec = {"a": (float, (2,), {}, 0, None, (), False, [], None),
...        "b": (pow, (Ref("a"), 3.0), {}, 1, None, (), False, ["a"], None)}
>>> run = compile_plan(rec, ("b",), frozenset())
>>> memo = {}
>>> fill, tol = run(memo)                    # "a" was computed too: stored when the memo is read further
>>> memo
{'b': 8.0}
>>> fill(memo, tol)
>>> memo
{'a': 2.0, 'b': 8.0}
"""
from __future__ import annotations

from typing import Any, Callable, Iterable

from .. import tolerance as _tolerance
from ..errors import NoIntersection
from ..geometry.kernels import FIELDS, KERNELS, MAKERS, PURE, RULES, SIZES, SPLIT, TYPES, Fallback
from ..geometry.primitives import Point
from .step import Ref, constant as _constant

_PLAIN, _TOP = 0, 1


def order_of(rec: dict[str, tuple], keys: Iterable[str]) -> list[str]:
    """The keys needed for ``keys`` (themselves included), in insertion order.

    Raises
    ------
    KeyError
        Naming the first needed key that is not recorded.
    """
    need: set[str] = set()
    todo = list(keys)
    while todo:
        k = todo.pop()
        if k in need:
            continue
        need.add(k)
        todo.extend(rec[k][7])
    return [k for k in rec if k in need]


def compile_plan(rec: dict[str, tuple], keys: tuple[str, ...], inputs: frozenset[str], *,
                 pending: bool = True, source: Source | None = None) -> Callable[[Any], Any] | None:
    """A function ``run(memo)`` that computes the steps ``keys`` need and stores ``keys`` in ``memo``, the
    steps named in ``inputs`` being read from ``memo``; None when a needed step is not a plain call.

    ``run`` returns None, or ``(fill, tol)`` when it computed steps besides ``keys``: ``fill(memo, tol)``
    stores those too (computed again from the same inputs under the run's tolerance ``tol``: the same values;
    their objects made then, in the plan's order), for a scene that is read further
    (without ``pending``, for a caller that only reads ``keys``, it always returns None).

    With ``source`` — a tape's givens, its own steps and its guards (:class:`~geomcon.scene.tape.Tape`) — the
    function is ``run(given)`` instead: it computes the tape's steps from the givens itself, as
    :meth:`~geomcon.scene.tape.Tape.values` does (None when their arithmetic fails or a guard does not hold),
    then the plan, and returns the values of ``keys`` as a tuple, in their order: a rebuild that only reads
    numbers, with no memo.

    A step that fails raises (the caller evaluates step by step again to report it); a branch step whose
    intersection is empty raises :class:`~geomcon.errors.NoIntersection`."""
    try:
        order = order_of(rec, keys)
    except KeyError:
        return None
    order = [k for k in order if k in inputs] + [k for k in order if k not in inputs]
    ns: dict[str, Any] = {"_NoIntersection": NoIntersection, "_Fallback": Fallback}
    g = _Gen(ns)
    loaded: list[str] = []
    computed: list[str] = []
    tape_vars = _source_lines(g, source) if source is not None else {}
    for i, k in enumerate(order):
        op, args, kwargs, mode, branch, brefs, optional, _, _ = rec[k]
        if k in inputs:
            g.kind[k] = "x"
            g.opt[k] = False
            if source is not None:                   # the tape's own step, computed above
                g.obj[k] = tape_vars[k]
                continue
            g.obj[k] = f"o{i}"
            g.body.append(f"    o{i} = memo[_IN[{len(loaded)}]]")
            loaded.append(k)
            continue
        if mode not in (_PLAIN, _TOP):
            return None
        computed.append(k)
        if op is _constant and len(args) == 1 and not kwargs and branch is None:
            g.alias(k, i, args[0])
            continue
        if not g.kernel_step(k, i, op, args, kwargs, branch, brefs, optional):
            g.object_step(k, i, op, args, kwargs, branch, brefs, optional)
    if source is not None:                      # the values of keys, in their order: nothing stored
        values = ", ".join(g.value(k) for k in keys)
        g.body.append(f"    return ({values}{',' if len(keys) == 1 else ''})")
        exec(compile("def run(given):\n" + "\n".join(g.body) + "\n", "<geomcon taped rebuild>", "exec"), ns)
        return ns["run"]
    wanted = set(keys)
    req = [k for k in computed if k in wanted]
    rest = [k for k in computed if k not in wanted]
    ns["_IN"], ns["_REQ"], ns["_ALL"] = tuple(loaded), tuple(req), tuple(computed)
    body = g.body
    calc = list(body)
    if req:
        body.append(f"    memo.update(zip(_REQ, ({', '.join(g.value(k) for k in req)},)))")
    if rest and pending:
        # the other steps are computed again when the memo is read further (seldom: a drawing, stats, a later
        # evaluation), from the same inputs with the same kernels and the tolerance of this run (pure float
        # code: the same bits), rather than every run handing over all its locals for it
        at = {k: j for j, k in enumerate(req)}
        fill = (["def fill(memo, tol):", "    if tol is not _tol.REL_TOL and tol != _tol.REL_TOL:",
                 "        return _pinned(fill, memo, tol)"] + calc
                + ["    req = [memo.pop(k) for k in _REQ]",
                   f"    memo.update(zip(_ALL, ({', '.join(f'req[{at[k]}]' if k in at else g.value(k) for k in computed)},)))"])
        ns["_tol"], ns["_pinned"] = _tolerance, _pinned
        exec(compile("\n".join(fill) + "\n", "<geomcon taped plan: fill>", "exec"), ns)
        ns["_FILL"] = ns["fill"]
        body.append("    return _FILL, _tol.REL_TOL")
    source = "def run(memo):\n" + "\n".join(body or ["    pass"]) + "\n"       # an empty request: nothing
    exec(compile(source, "<geomcon taped plan>", "exec"), ns)
    return ns["run"]


def _pinned(fill: Callable[[dict, float], None], memo: dict, tol: float) -> None:
    """``fill(memo, tol)`` with ``geomcon.tolerance.REL_TOL`` set back to ``tol``, the tolerance of the run whose
    steps it computes again, while it runs (it was changed at run time in between)."""
    now = _tolerance.REL_TOL
    _tolerance.REL_TOL = tol
    try:
        fill(memo, tol)
    finally:
        _tolerance.REL_TOL = now


Source = tuple[tuple[tuple[str, str], ...], tuple[tuple[str, Callable[..., Any], tuple], ...],
               tuple[tuple[Callable[..., Any], tuple, bool], ...]]
"""A tape's ``(memo key, given name)`` of each given it reads, its own steps ``(key, operation, arguments)``
and its guards ``(operation, arguments, outcome)`` (:class:`~geomcon.scene.tape.Tape`)."""


def _source_lines(g: _Gen, source: Source) -> dict[str, str]:
    """The lines that compute a tape's own steps from ``given`` (as :meth:`~geomcon.scene.tape.Tape.values`:
    every given read first, then the steps and the guards, None returned when their arithmetic fails or a guard
    does not hold); the local variable of each step's key."""
    leaves, nodes, guards = source
    names: dict[str, str] = {}
    for j, (key, name) in enumerate(leaves):
        names[key] = f"t{j}"
        g.body.append(f"    t{j} = given[{g.const(f'_L{j}', name)}]")

    def arg(a: Any, where: str) -> str:
        return names[a[0]] if type(a) is Ref else g.const(where, a)

    lines = []
    for j, (key, op, args) in enumerate(nodes):
        var = names[key] = f"t{len(leaves) + j}"
        parts = ", ".join(arg(a, f"_N{j}_{m}") for m, a in enumerate(args))
        lines.append(f"        {var} = {g.const(f'_N{j}', op)}({parts})")
    for j, (op, args, out) in enumerate(guards):
        parts = ", ".join(arg(a, f"_G{j}_{m}") for m, a in enumerate(args))
        lines.append(f"        if {g.const(f'_G{j}', op)}({parts}) is not {g.const(f'_GO{j}', out)}: return None")
    if lines:
        g.body += ["    try:"] + lines + ["    except ArithmeticError:", "        return None"]
    return names


def compile_values(source: Source) -> Callable[[Any], dict[str, Any] | None]:
    """``values(given)``: a tape's own steps computed from ``given`` as one function — the memo a replay
    starts from, exactly as :meth:`~geomcon.scene.tape.Tape.values` made it step by step (every given read
    first, a missing one raising ``KeyError``; then the steps and the guards, None when their arithmetic fails
    or a guard does not hold; the keys in the same order).

    >>> import operator
    >>> from geomcon.scene.step import Ref
    >>> values = compile_values(((("§a", "a"),), (("§0", operator.sub, (Ref("§a"), 1.0)),),
    ...                          ((operator.gt, (Ref("§0"), 0.0), True),)))
    >>> values({"a": 3.0}), values({"a": 0.5})
    ({'§a': 3.0, '§0': 2.0}, None)
    """
    ns: dict[str, Any] = {}
    g = _Gen(ns)
    names = _source_lines(g, source)
    items = ", ".join(f"{g.const(f'_K{j}', key)}: {var}" for j, (key, var) in enumerate(names.items()))
    g.body.append(f"    return {{{items}}}")
    exec(compile("def values(given):\n" + "\n".join(g.body) + "\n", "<geomcon tape values>", "exec"), ns)
    return ns["values"]


def _natural(name: str) -> tuple:
    return (len(name), name)


class _Gen:
    """The source of one compiled plan as it is generated: each step's value held as the floats of its kind
    (:data:`~geomcon.geometry.kernels.SIZES`), as an object, or both."""

    def __init__(self, ns: dict[str, Any]) -> None:
        self.ns = ns
        self.body: list[str] = []
        self.kind: dict[str, str] = {}
        self.flat: dict[str, list[str]] = {}
        self.obj: dict[str, str] = {}
        self.opt: dict[str, bool] = {}
        self.shared: dict[tuple, str] = {}     # (operation, argument names) → the variable of its candidates

    # ---------------------------------------------------------------------------------- values
    def const(self, name: str, value: Any) -> str:
        self.ns[name] = value
        return name

    def alias(self, k: str, i: int, a: Any) -> None:
        """A step that is its argument (a given's ``_constant``): the same variables."""
        if type(a) is Ref:
            src = a[0]
            self.kind[k], self.opt[k] = self.kind[src], self.opt[src]
            if src in self.flat:
                self.flat[k] = self.flat[src]
            if src in self.obj:
                self.obj[k] = self.obj[src]
            return
        self.opt[k] = False
        self.obj[k] = self.const(f"c{i}_0", a)
        if type(a) is Point:
            self.kind[k] = "P"
            self.flat[k] = [self.const(f"c{i}_0x", a.x), self.const(f"c{i}_0y", a.y)]
        else:
            self.kind[k] = "x"

    def as_flat(self, k: str, want: str) -> list[str] | None:
        """The floats of step ``k`` as kind ``want`` (read off its object, its type checked, when it has no
        floats yet); None when it is of another kind."""
        have = self.kind[k]
        if have == want:
            return self.flat[k]
        if have != "x" or want not in TYPES:
            return None
        if k not in self.flat:
            o = self.obj[k]
            names = [f"{o}_{j}" for j in range(SIZES[want])]
            t = self.const(f"_T{want}", TYPES[want])
            read = ", ".join(f"{o}{f}" for f in FIELDS[want])
            if self.opt[k]:
                self.body.append(f"    if {o} is None:")
                self.body.append(f"        {' = '.join(names)} = None")
                self.body.append(f"    elif type({o}) is not {t}: raise _Fallback()")
                self.body.append(f"    else: {', '.join(names)} = {read}")
            else:
                self.body.append(f"    if type({o}) is not {t}: raise _Fallback()")
                self.body.append(f"    {', '.join(names)} = {read}")
            self.flat[k] = names
            self.kind[k] = want
        return self.flat[k]

    def as_obj(self, k: str) -> str:
        """The variable holding step ``k``'s object (made of its floats here, once)."""
        o = self.obj.get(k)
        if o is None:
            made = self.value(k)
            o = self.obj[k] = "o_" + self.flat[k][0]
            self.body.append(f"    {o} = {made}")
        return o

    def value(self, k: str) -> str:
        """An expression of step ``k``'s object."""
        o = self.obj.get(k)
        if o is not None:
            return o
        f = self.flat[k]
        mk = self.const(f"_MK{self.kind[k]}", MAKERS[self.kind[k]])
        if self.opt[k]:
            return f"(None if {f[0]} is None else {mk}({', '.join(f)}))"
        return f"{mk}({', '.join(f)})"

    def reads(self, k: str) -> list[str]:
        """The local variables :meth:`value` reads."""
        o = self.obj.get(k)
        if o is not None:
            return [] if o.startswith("c") else [o]
        return [f for f in self.flat[k] if not f.startswith("c")]

    def _guard(self, refs: list[str]) -> str:
        """The ``if … is None`` line of an optional step (a candidate of a missing candidate is missing),
        '' when none of its references may be missing."""
        used = [a for a in refs if self.opt.get(a)]
        if not used:
            return ""
        return " or ".join(f"{(self.flat[a][0] if a in self.flat else self.obj[a])} is None" for a in used)

    # ---------------------------------------------------------------------------------- steps
    def kernel_step(self, k: str, i: int, op: Any, args: tuple, kwargs: dict, branch: Any, brefs: tuple,
                    optional: bool) -> bool:
        """Emit step ``k`` as a kernel call on floats; False (nothing emitted) when it has none."""
        if kwargs:
            return False
        try:
            kernels = KERNELS.get(op)
        except TypeError:                       # an unhashable operation
            return False
        if not kernels:
            return False
        rule = None
        if branch is not None:
            rule = RULES.get(branch.rule)
            if rule is None or len(rule[0]) != len(brefs):
                return False
        kinds = []
        for a in args:
            if type(a) is Ref:
                kinds.append(self.kind[a[0]])
            else:
                kinds.append("P" if type(a) is Point else "x")
        for want, out, fn in kernels:
            if len(want) != len(args) or (branch is None) == (out == "T"):
                continue
            if all(w == h or (h == "x" and w in TYPES) for w, h in zip(want, kinds)):
                break
        else:
            return False
        if rule is not None and not all(type(r) is Point or (type(r) is Ref and (self.kind[r[0]] == "P" or self.kind[r[0]] == "x"))
                                        for r in brefs):
            return False
        parts: list[str] = []
        refs: list[str] = []
        for j, (a, w) in enumerate(zip(args, want)):
            if type(a) is Ref:
                refs.append(a[0])
                if w == "x":
                    parts.append(self.as_obj(a[0]))
                else:
                    parts.extend(self.as_flat(a[0], w))
            elif w == "x":
                parts.append(self.const(f"c{i}_{j}", a))
            else:
                parts.extend([self.const(f"c{i}_{j}x", a.x), self.const(f"c{i}_{j}y", a.y)])
        rparts: list[str] = []
        if rule is not None:
            for j, r in enumerate(brefs):
                if type(r) is Ref:
                    rparts.extend(self.as_flat(r[0], "P"))
                else:
                    rparts.extend([self.const(f"r{i}_{j}x", r.x), self.const(f"r{i}_{j}y", r.y)])
        if rule is None and not optional and fn in PURE and all(p in self.ns for p in parts) \
                and self.fold(k, i, fn, out, parts):
            return True
        f = self.const(f"k{i}", fn)
        guard = self._guard(refs) if optional else ""
        size = SIZES["P" if rule is not None else out]
        names = [f"v{i}_{j}" for j in range(size)] if (rule is not None or out != "x") else []
        target = ", ".join(names) if names else f"o{i}"
        pad = "    "
        if guard:
            self.body.append(f"    if {guard}:")
            self.body.append(f"        {' = '.join(names or [f'o{i}'])} = None")
            self.body.append("    else:")
            pad = "        "
        call = f"{f}({', '.join(parts)})"
        if rule is None:
            self.body.append(f"{pad}{target} = {call}")
        else:
            b = self.const(f"b{i}", rule[1])
            if optional:
                self.body.append(f"{pad}u{i} = {call}")
                self.body.append(f"{pad}if u{i}: {target} = {b}({', '.join([f'u{i}'] + rparts)})")
                self.body.append(f"{pad}else: {' = '.join(names)} = None")
            else:
                raw = self.shared.get((op, tuple(parts)))
                if raw is None:
                    raw = self.shared[(op, tuple(parts))] = f"u{i}"
                    self.body.append(f"{pad}{raw} = {call}")
                    self.body.append(f"{pad}if not {raw}: raise _NoIntersection('')")
                split = SPLIT.get(branch.rule)
                if split is None:
                    self.body.append(f"{pad}{target} = {b}({', '.join([raw] + rparts)})")
                else:
                    # the rule's set-up on its points (above/below a line: the line's upward normal) made once
                    # for every step that chooses by the same rule and points, where the first one reads it
                    prep, choose, keep = split
                    made = self.shared.get((prep, tuple(rparts)))
                    if made is None:
                        made = self.shared[(prep, tuple(rparts))] = [f"n{i}_0", f"n{i}_1"]
                        self.body.append(f"{pad}{', '.join(made)} = {self.const(f'p{i}', prep)}({', '.join(rparts)})")
                    c = self.const(f"b{i}", choose)
                    self.body.append(f"{pad}{target} = {c}({', '.join([raw] + rparts[:keep] + made)})")
        self.opt[k] = optional
        if names:
            self.kind[k] = "P" if rule is not None else out
            self.flat[k] = names
        else:
            self.kind[k] = "x"
            self.obj[k] = f"o{i}"
        return True

    def fold(self, k: str, i: int, fn: Any, out: str, parts: list[str]) -> bool:
        """Step ``k``, a pure kernel (:data:`~geomcon.geometry.kernels.PURE`) of constants only (a fixed pivot,
        the horizontal guide through it, its normal), computed now, once: its floats become constants of the
        plan (the same call on the same floats gives the same bits at every replay). False (nothing done)
        when the call raises: each replay then raises as it would."""
        try:
            got = fn(*[self.ns[p] for p in parts])
        except Exception:
            return False
        if out == "x":
            self.kind[k], self.obj[k], self.opt[k] = "x", self.const(f"c{i}_v", got), False
            return True
        if type(got) is not tuple or len(got) != SIZES[out]:
            return False
        self.kind[k], self.opt[k] = out, False
        self.flat[k] = [self.const(f"c{i}_v{j}", v) for j, v in enumerate(got)]
        return True

    def object_step(self, k: str, i: int, op: Any, args: tuple, kwargs: dict, branch: Any, brefs: tuple,
                    optional: bool) -> None:
        """Emit step ``k`` as a call of its operation on objects (the arguments' objects made once)."""
        parts, used = [], []
        for j, a in enumerate(args):
            if type(a) is Ref:
                parts.append(self.as_obj(a[0]))
                used.append(a[0])
            else:
                parts.append(self.const(f"c{i}_{j}", a))
        if kwargs:
            parts.append(f"**{self.const(f'kw{i}', kwargs)}")
        refs = []
        for j, r in enumerate(brefs if branch is not None else ()):
            refs.append(self.as_obj(r[0]) if type(r) is Ref else self.const(f"r{i}_{j}", r))
        f = self.const(f"f{i}", op)
        v = f"o{i}"
        pad = "    "
        guard = self._guard(used) if optional else ""
        if guard:
            self.body.append(f"    if {guard}:")
            self.body.append(f"        {v} = None")
            self.body.append("    else:")
            pad = "        "
        if branch is None:
            self.body.append(f"{pad}{v} = {f}({', '.join(parts)})")
        else:
            b = self.const(f"b{i}", branch.rule)
            if optional:
                self.body.append(f"{pad}{v} = {f}({', '.join(parts)})")
                self.body.append(f"{pad}{v} = {b}({', '.join([v] + refs)}) if {v} else None")
            else:
                # the two branches of one intersection (B1 left of A, B2 right of A) call it on the same
                # arguments: it is computed once and each rule chooses from the same candidates
                raw = self.shared.get((op, tuple(parts)))
                if raw is None:
                    raw = self.shared[(op, tuple(parts))] = f"u{i}"
                    self.body.append(f"{pad}{raw} = {f}({', '.join(parts)})")
                    self.body.append(f"{pad}if not {raw}: raise _NoIntersection('')")
                self.body.append(f"{pad}{v} = {b}({', '.join([raw] + refs)})")
        self.kind[k], self.obj[k], self.opt[k] = "x", v, optional
