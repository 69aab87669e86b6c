"""Replays of a variant's scene done the wrong way: a branch rule flipped, a step's operation replaced, a
step's reference rewired to another step, or a step's value replaced by a student's number.

A replay shares the built scene's steps and every value that does not depend on the changed step (the
scene's insertion order is a topological order, so what depends on a step is found in one pass); only the
steps downstream are computed again. This module is the one place grading reads a scene's step records.

Examples
--------
>>> r = Variant.of("crank_rocker.extremes", {"AB": 25, "BC": 85, "CD": 70, "AD": 70})
>>> round(r.values(["theta"])["theta"], 6), sorted(r.branched(["theta"]))
(26.409856, ['C1', 'C2'])
>>> round(r.values(["theta"], flip="C1")["theta"], 6)        # C1 taken below the frame line
102.836277
>>> round(r.values(["K"], constant={"theta": 30.0})["K"], 6)  # K from a student's θ
1.4
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Iterable, Mapping

from ..scene.scene import Scene
from ..scene.step import Ref
from ..solve import Solution
from ..worksheet.solving import chosen_map, same_given, solve_given


class _Other:
    """A branch rule flipped: the candidate the textbook's rule does not choose (the same one at tangency)."""

    __slots__ = ("branch",)

    def __init__(self, branch: Any) -> None:
        self.branch = branch

    def rule(self, cands: tuple, *points: Any) -> Any:
        chosen = self.branch.rule(cands, *points)
        if len(cands) == 2:
            return cands[1] if chosen is cands[0] else cands[0]
        return chosen


@dataclass
class Variant:
    """One variant's solution with its scene built in full, ready for replays.

    ``answers`` maps answer names to the step keys of the textbook's choice of solution; ``candidates`` are the
    answer maps of every candidate solution (empty for a recipe with one solution)."""

    solution: Solution
    scene: Scene
    answers: Mapping[str, str]
    candidates: tuple[Mapping[str, str], ...]

    @classmethod
    def of(cls, recipe: str, given: Mapping[str, Any], solved: Solution | None = None) -> Variant:
        """Solve ``given`` (validated as a problem file's givens) and complete its scene. ``solved``: a solution
        of the same recipe already at hand (the worksheet's judged variant); it is used, not solved again, when
        its givens are ``given`` validated (:func:`~geomcon.worksheet.solving.same_given`)."""
        sol = solved if solved is not None and same_given(solved, recipe, given) else solve_given(recipe, given)
        chosen = dict(chosen_map(sol))
        sc = sol.construction.scene.complete()
        return cls(sol, sc, chosen, tuple(sol.construction.solutions))

    def closure(self, keys: Iterable[str]) -> list[str]:
        """The steps needed for ``keys``, in evaluation order."""
        return self.scene.closure(keys)

    def branched(self, keys: Iterable[str]) -> list[str]:
        """The two-point intersections with a named branch rule among the steps ``keys`` need."""
        rec = self.scene._rec
        return [k for k in self.closure(keys) if rec[k][4] is not None]

    def caption(self, key: str) -> tuple[str, str]:
        """A step's caption (English, Chinese), its branch rule included."""
        return self.scene.caption(key)

    def values(self, keys: Iterable[str], *, flip: str | None = None, op: tuple[str, Callable] | tuple[tuple[str, Callable], ...] | None = None,
               rewire: tuple[str, str, str] | None = None, constant: Mapping[str, Any] | None = None) -> dict[str, Any]:
        """The values of ``keys`` in a replay with one change (or none): ``flip`` a step's branch rule, replace
        a step's operation (``op = (key, fn)``, the same arguments; or a tuple of such pairs: one mistake made at
        each of several steps, e.g. both θ-circles drawn the same wrong way), ``rewire = (key, old, new)`` a step's
        reference to ``old`` made to ``new``, or ``constant`` step values (a student's numbers).

        Raises
        ------
        GeomconError
            When the replay cannot be built (the flipped intersection does not exist, …).
        """
        keys = tuple(keys)
        sc = self.scene
        rec = sc._rec
        changed: dict[str, tuple] = {}
        if flip is not None:
            r = rec[flip]
            changed[flip] = r[:4] + (_Other(r[4]),) + r[5:]
        if op is not None:
            for key, fn in ((op,) if isinstance(op[0], str) else op):
                changed[key] = (fn,) + rec[key][1:]
        if rewire is not None:
            key, old, new = rewire
            r = rec[key]
            new_ref = tuple.__new__(Ref, (new,))
            args = tuple(new_ref if type(a) is Ref and a[0] == old else a for a in r[1])
            deps = [new if d == old else d for d in r[7]]
            changed[key] = (r[0], args) + r[2:7] + (deps,) + r[8:]
        fixed = dict(constant or {})
        tainted = set(changed) | set(fixed)
        if not tainted:
            return sc.evaluate(keys)
        for k, r in rec.items():
            if k not in tainted and any(d in tainted for d in r[7]):
                tainted.add(k)
        sc.settle()                  # a compiled replay's other steps in its memo before it is copied
        other = Scene.__new__(Scene)
        other.__dict__.update(sc.__dict__)
        other._rec = {**rec, **changed} if changed else rec
        other._memo = {k: v for k, v in sc._memo.items() if k not in tainted}
        other._memo.update(fixed)
        other._step, other._learn, other._keep, other._rebuild = {}, None, None, None
        other._sig = hash((sc._sig, "replay", tuple(sorted(changed)), tuple(sorted(fixed))))
        if rewire is not None:
            other._sig = hash((other._sig, rewire))
        return other.evaluate(keys)


__all__ = ["Variant"]
