"""Giving each student a variant of each exercise.

A student's variants of an exercise are tried in an order of the student's own: the distinct pool indices of
``draw(seed, exercise digest, exercise number, student id, t) mod pool`` for t = 0, 1, … (after
:data:`DRAWS` draws, the indices after the last one in turn, so that the order visits the whole pool). The first
accepted variant that no student listed earlier holds is the student's. So:

- a student's variant depends on the spec's exercise (its recipe and givens: editing a statement, points or
  the title changes no variant), the seed and the student's id, and on the students listed before them only
  when two sequences meet on the same accepted variant (rare in a large pool);
- a student added at the end of the class list changes no one else's variant, and ``--count`` N + 1 keeps
  the variants of 1 … N;
- no two students share a variant while the pool allows: a student whose :data:`TRIES` tries find accepted
  variants, all taken, goes on along their order through the rest of the pool (at most :data:`BUDGET` variants
  judged per exercise) for one nobody holds. Only when the whole pool is judged and every acceptable variant is
  taken (or the budget ends the search) does the student share, taking of the variants met the one held by the
  fewest students (the first in their order on a tie), so that the class is spread evenly. The statistics say
  so: ``shared`` students, ``exhausted`` (the whole pool was judged) and then the pool's exact number of
  acceptable variants.

The trade-off: "a variant derived from (spec, exercise, student id) alone" and "adding a student changes no one
else's" cannot both hold with "no two students share while the pool allows": uniqueness needs to know who came
first. The class order decides, and only for a student whose own order meets a taken variant first; a student
appended later never moves an earlier one.

A spec whose acceptance is too low is refused: when a student's :data:`TRIES` tries find no acceptable variant
and none is known in the whole exercise (a student who finds none while others have goes on through the pool
likewise), or an exercise has judged :data:`BUDGET` variants before every student has one, with the acceptance
rate and the rejection counts.

Examples
--------
>>> from geomcon.paper import PAPERS
>>> from geomcon.worksheet.roster import numbered
>>> from geomcon.worksheet.spec import parse_spec
>>> spec = parse_spec('''
... [[exercise]]
... recipe = "guide_bar.extremes"
... ask = ["theta"]
... [exercise.given]
... AB = {min = 100, max = 140, step = 10}
... AC = 290
... ''')
>>> a = assign(spec, numbered(3), PAPERS["A4"])
>>> [v[0].given["AB"] for v in a.variants]
[120.0, 110.0, 100.0]
>>> a.stats[0].accepted, a.stats[0].shared
(3, 0)
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Callable, Iterator, Sequence

from ..errors import ProblemError
from ..paper import Paper
from .accept import REASONS, Accepted, Rejected, judge
from .rng import below, draw
from .roster import Student
from .spec import Exercise, Spec

TRIES = 200
"""Distinct variants tried per student and exercise before the spec is refused (or the student shares)."""
DRAWS = 8 * TRIES
"""Hashed draws of a student's order before it continues in turn (a small pool is then covered whole)."""
BUDGET = 20_000
"""Most variants judged per exercise: beyond it the spec is refused as too rarely acceptable."""


@dataclass(frozen=True)
class Stats:
    """Acceptance statistics of one exercise: variants judged, accepted, rejected by reason (with one example
    line per reason), the pool's size and how many students share a variant with an earlier one."""

    n: int
    recipe: str
    pool: int
    tried: int
    accepted: int
    rejected: dict[str, int] = field(default_factory=dict)
    examples: dict[str, str] = field(default_factory=dict)
    shared: int = 0
    most: int = 1
    """The most students holding one variant."""

    @property
    def exhausted(self) -> bool:
        """Whether the whole pool was judged (then :attr:`accepted` is the pool's exact number of acceptable
        variants)."""
        return self.tried == self.pool

    @property
    def rate(self) -> float:
        """Accepted / judged."""
        return self.accepted / self.tried if self.tried else 0.0

    def line(self) -> str:
        """One line for the terminal."""
        why = ", ".join(f"{k} {v}" for k, v in self.rejected.items())
        return (f"exercise {self.n} ({self.recipe}): {self.accepted} of {self.tried} variants judged were accepted "
                f"({100 * self.rate:.0f} %) from a pool of {self.pool}" + (f"; rejected: {why}" if why else "")
                + (f"; {self.shared} students share a variant: {self.short()}" if self.shared else ""))

    def short(self) -> str:
        """Why students share a variant: the pool holds no more acceptable variants, or the budget ended the
        search."""
        if self.exhausted:
            return (f"the pool of {self.pool} variants holds only {self.accepted} acceptable ones (every variant "
                    f"judged), so at most {self.accepted} students can have a variant of their own; each variant is "
                    f"held by at most {self.most} students (widen the givens' ranges or relax [require] for more)")
        return (f"{BUDGET} variants of the pool of {self.pool} judged found only {self.accepted} acceptable ones "
                f"(the rest of the pool was not judged); each variant is held by at most {self.most} students")


@dataclass(frozen=True)
class Assignment:
    """The class's variants: ``variants[i][j]`` is student i's variant of exercise j; ``stats[j]`` exercise j's
    statistics."""

    students: tuple[Student, ...]
    variants: tuple[tuple[Accepted, ...], ...]
    stats: tuple[Stats, ...]


def order(seed: int | str | None, ex: Exercise, student: str) -> Iterator[int]:
    """The distinct pool indices a student's tries visit, in order (see the module)."""
    pool = ex.pool
    seen: set[int] = set()
    last = 0
    for t in range(DRAWS):
        last = below(draw(seed, ex.digest, ex.n, student, t), pool)
        if last not in seen:
            seen.add(last)
            yield last
            if len(seen) == pool:
                return
    for j in range(1, pool + 1):
        k = (last + j) % pool
        if k not in seen:
            seen.add(k)
            yield k


def _refusal(ex: Exercise, why: str, counts: Counter, examples: dict[str, str], tried: int, accepted: int) -> ProblemError:
    top = sorted(counts.items(), key=lambda kv: (-kv[1], REASONS.index(kv[0])))
    listed = "; ".join(f"{k} {v}" + (f" (e.g. {examples[k][:160]})" if i == 0 else "") for i, (k, v) in enumerate(top))
    rate = f"{100 * accepted / tried:.2g} %" if tried else "none"
    return ProblemError(f"exercise {ex.n} ({ex.recipe}): {why}: {accepted} of {tried} variants judged were accepted "
                        f"({rate}); rejected: {listed or 'none'}")


def assign_exercise(ex: Exercise, students: Sequence[Student], paper: Paper, seed: int | str | None = None,
                    judge_fn: Callable[[Exercise, int, Paper], Accepted | Rejected] = judge
                    ) -> tuple[list[Accepted], Stats]:
    """Each student's variant of one exercise, and its statistics; refuses (ProblemError) a spec whose variants
    are too rarely acceptable."""
    cache: dict[int, Accepted | Rejected] = {}
    counts: Counter = Counter()
    examples: dict[str, str] = {}
    holders: Counter = Counter()                  # pool index → students holding it
    out: list[Accepted] = []
    shared = 0
    for s in students:
        mine: Accepted | None = None
        met: list[Accepted] = []                   # accepted variants met, all taken
        for n, idx in enumerate(order(seed, ex, s.id), 1):
            v = cache.get(idx)
            if v is None:
                if len(cache) >= BUDGET:
                    if len(cache) > sum(counts.values()):
                        continue                   # past the budget: only variants already judged are met
                    raise _refusal(ex, f"{BUDGET} variants judged without filling the class", counts, examples,
                                   len(cache), len(cache) - sum(counts.values()))
                v = cache[idx] = judge_fn(ex, idx, paper)
                if isinstance(v, Rejected):
                    counts[v.reason] += 1
                    examples.setdefault(v.reason, v.detail)
            if isinstance(v, Accepted):
                if not holders[idx]:
                    mine = v
                    break
                met.append(v)
            if n >= TRIES and not met and len(cache) == sum(counts.values()):
                break                              # TRIES tries, and no acceptable variant known at all
        if mine is None:
            if not met:
                tried = min(TRIES, ex.pool)
                why = (f"unsatisfiable [exercise.require]: no variant among the {tried} tried for student {s.id!r} "
                       "meets it" if counts and counts.most_common(1)[0][0] == "require"
                       else f"no acceptable variant among the {tried} tried for student {s.id!r}")
                raise _refusal(ex, why, counts, examples, len(cache), len(cache) - sum(counts.values()))
            mine = min(met, key=lambda x: holders[x.index])        # the least held; the first met on a tie
            shared += 1
        holders[mine.index] += 1
        out.append(mine)
    rejected = {k: counts[k] for k in REASONS if counts[k]}
    stats = Stats(ex.n, ex.recipe, ex.pool, len(cache), len(cache) - sum(counts.values()), rejected,
                  {k: examples[k] for k in rejected}, shared, max(holders.values(), default=1))
    return out, stats


def assign(spec: Spec, students: Sequence[Student], paper: Paper, seed: int | str | None = None,
           judge_fn: Callable[[Exercise, int, Paper], Accepted | Rejected] = judge) -> Assignment:
    """Every student's variant of every exercise; ``seed`` (the command's ``--seed``) overrides the spec's."""
    used = spec.seed if seed is None else seed
    per_ex = [assign_exercise(ex, students, paper, used, judge_fn) for ex in spec.exercises]
    variants = tuple(tuple(per_ex[j][0][i] for j in range(len(per_ex))) for i in range(len(students)))
    return Assignment(tuple(students), variants, tuple(st for _, st in per_ex))


__all__ = ["Assignment", "BUDGET", "DRAWS", "Stats", "TRIES", "assign", "assign_exercise", "order"]
