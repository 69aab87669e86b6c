"""A taped scene's evaluation plan as one Python function: the steps a request needs, in order, each a call on
local variables, no dictionary lookups or argument resolution per step.

The source is generated from the recorded steps' shapes alone: local names ``v0, v1, …`` and the operations,
constants and branch rules bound by name in the function's namespace (``f3``, ``c3_1``, ``b3``); no key, label
or value of a problem ever becomes source text (keys are read and written through a tuple of them). A request
whose steps are not all plain calls (nested references such as a tuple of points) gets no function and is
evaluated step by step as before. The branches of one intersection (two steps calling the same operation on
the same arguments, each with its own rule) share one call: each rule chooses from the same candidates, as
two separate calls would give them (the operations are pure). An optional step (a candidate that may not exist) is None when a step it
refers to is None or, for an intersection, when nothing meets, as the scene's own evaluation decides.

Examples
--------
>>> from geomcon.scene.step import Ref
>>> rec = {"a": (float, (2,), {}, 0, None, (), False, [], None),
...        "b": (pow, (Ref("a"), 3.0), {}, 1, None, (), False, ["a"], None)}
>>> run = compile_plan(rec, ("b",), frozenset())
>>> memo = {}
>>> run(memo)
>>> memo
{'a': 2.0, 'b': 8.0}
"""
from __future__ import annotations

from typing import Any, Callable, Iterable

from ..errors import NoIntersection
from .step import Ref

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


def compile_plan(rec: dict[str, tuple], keys: tuple[str, ...], inputs: frozenset[str]) -> Callable[[dict], None] | None:
    """A function ``run(memo)`` that computes the steps ``keys`` need and stores them in ``memo``, the steps
    named in ``inputs`` being read from ``memo``; None when a needed step is not a plain call.

    A step that fails raises (the caller evaluates step by step again to report it); a branch step whose
    intersection is empty raises :class:`~geomcon.errors.NoIntersection`."""
    try:
        order = order_of(rec, keys)
    except KeyError:
        return None
    order = [k for k in order if k in inputs] + [k for k in order if k not in inputs]
    ns: dict[str, Any] = {"_NoIntersection": NoIntersection}
    names: dict[str, str] = {}
    body: list[str] = []
    loaded: list[str] = []
    computed: list[str] = []
    shared: dict[tuple, str] = {}            # (operation, argument names) → the variable of its candidates
    for i, k in enumerate(order):
        op, args, kwargs, mode, branch, brefs, optional, _, _ = rec[k]
        v = names[k] = f"v{i}"
        if k in inputs:
            body.append(f"    {v} = memo[_IN[{len(loaded)}]]")
            loaded.append(k)
            continue
        if mode not in (_PLAIN, _TOP):
            return None
        parts, used = [], []
        for j, a in enumerate(args):
            if type(a) is Ref:
                parts.append(names[a[0]])
                used.append(names[a[0]])
            else:
                ns[f"c{i}_{j}"] = a
                parts.append(f"c{i}_{j}")
        if kwargs:
            ns[f"k{i}"] = kwargs
            parts.append(f"**k{i}")
        ns[f"f{i}"] = op
        pad = "    "
        if optional and used:                    # a candidate of a missing candidate is missing
            body.append(f"    if {' is None or '.join(used)} is None:")
            body.append(f"        {v} = None")
            body.append("    else:")
            pad = "        "
        if branch is None:
            body.append(f"{pad}{v} = f{i}({', '.join(parts)})")
            computed.append(k)
            continue
        refs = []
        for j, b in enumerate(brefs):
            if type(b) is Ref:
                refs.append(names[b[0]])
            else:
                ns[f"r{i}_{j}"] = b
                refs.append(f"r{i}_{j}")
        ns[f"b{i}"] = branch.rule
        if optional:
            body.append(f"{pad}{v} = f{i}({', '.join(parts)})")
            body.append(f"{pad}{v} = b{i}({', '.join([v] + refs)}) if {v} else None")
        else:
            # the two branches of one intersection (B1 left of A, B2 right of A) call it on the same
            # arguments: it is computed once and each rule chooses from the same candidates
            raw = shared.get((op, tuple(parts)))
            if raw is None:
                raw = shared[(op, tuple(parts))] = f"u{i}"
                body.append(f"{pad}{raw} = f{i}({', '.join(parts)})")
                body.append(f"{pad}if not {raw}: raise _NoIntersection('')")
            body.append(f"{pad}{v} = b{i}({', '.join([raw] + refs)})")
        computed.append(k)
    ns["_IN"], ns["_OUT"] = tuple(loaded), tuple(computed)
    outs = ", ".join(names[k] for k in computed)
    body.append(f"    memo.update(zip(_OUT, ({outs}{',' if len(computed) == 1 else ''})))")
    source = "def run(memo):\n" + "\n".join(body) + "\n"
    exec(compile(source, "<geomcon taped plan>", "exec"), ns)
    return ns["run"]
