"""A worksheet spec: TOML, untrusted; parsed into small frozen value objects, or refused in one line.

A spec holds a title (and optionally ``title_zh``, the Chinese title of zh pages), an optional seed and one
``[[exercise]]`` table per exercise (recipe, ``ask``, optional ``points``, ``statement``, ``[exercise.given]``,
``[exercise.require]``). Each given is

- a **value** (fixed): ``psi = 40``, ``follower = "roller"``, ``program = [{kind = "rise", …}, …]``;
- a **list** (one of): ``K = [1.2, 1.25, 1.4]``, ``follower = ["knife", "roller"]``; for a given that is itself a
  list (a point, ``at``, a motion program) a list of such values;
- a **range** on a grid: ``CD = {min = 60, max = 120, step = 5}``: every ``min + k·step ≤ max``, computed in
  decimal, so 1.2 + 3 × 0.05 is the number 1.35, exactly as a teacher wrote it.

Inside a motion program (a list of tables) each row's fields take the same three forms
(``angle = [120, 150]``, ``law = ["cosine", "cycloidal"]``): the program's segments still have to add up to
360°, and combinations that do not are rejected as invalid variants (counted in the statistics).

The variant pool of an exercise is the product of its choices (each a *slot*); a variant is one index into it
(mixed radix, slots in the order of the spec). ``together = [["B2", "C2"], …]`` chooses the listed givens by one
index (their lists are as long as one another): the k-th B2 goes with the k-th C2, as the two points of one
position of a rigid coupler must (a product of their lists would mostly pull the coupler apart).

Examples
--------
>>> spec = parse_spec('''
... title = "demo"
... [[exercise]]
... recipe = "guide_bar.extremes"
... ask = ["theta"]
... [exercise.given]
... AB = {min = 100, max = 140, step = 10}
... AC = [290, 300]
... ''', name="demo.toml")
>>> ex = spec.exercises[0]
>>> ex.pool, [s.count for s in ex.slots]
(10, [5, 2])
>>> ex.given_of(7)
{'AB': 130.0, 'AC': 300}
"""
from __future__ import annotations

import hashlib
import json
import math
import re
import unicodedata
from dataclasses import dataclass, field
from decimal import Decimal
from pathlib import Path
from typing import Any, Mapping

from ..errors import ProblemError
from ..paper import STANDARD, Scale
from ..problems import parse_toml, read_limited, title_in, title_zh
from ..recipes import Quantity, Recipe, get_recipe

LIMITS = {
    "file_bytes": 1 << 20,       # the spec file
    "exercises": 20,             # exercises per spec
    "list_items": 1000,          # choices of one given (a list)
    "grid_points": 100_000,      # values of one range {min, max, step}
    "program_rows": 64,          # rows of a motion program
    "ask": 20,                   # answers asked per exercise
    "title_chars": 500,          # the title
    "text_chars": 4000,          # a statement (a paragraph; it is copied into every student's key)
    "points": 1000.0,            # points of one answer
}
"""Size limits of a worksheet spec, checked before anything is solved."""

TOP_KEYS = ("title", "title_zh", "seed", "exercise")
EXERCISE_KEYS = ("recipe", "ask", "points", "statement", "given", "require", "tol", "scale", "max_tol_rel", "diagnose",
                 "together")
LANGS = ("en", "zh")
MAX_TOL_REL = 0.05
"""A variant whose drafting tolerance of an asked answer exceeds this fraction of the answer is rejected
(issue 12: a careful drawing cannot determine it); ``max_tol_rel`` in an exercise narrows or widens it."""

_SCALAR = ("mm", "deg", "", "count", "mm/s", "mm/s²", "rad/s", "rad/s²")
"""Units of a number a variant gives or a student answers (the rest: points, lists, choices, programs)."""
_ANSWER_REF = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d{1,4})\])?$")
_PLACEHOLDER = re.compile(r"\{([^{}]*)\}")
_WORDS = {"choice": (lambda v: isinstance(v, str), "words"), "bool": (lambda v: isinstance(v, bool), "true/false")}
"""Givens of these units: what a value must be, and what a list of them is called in a refusal."""


# ---------------------------------------------------------------------------------------------- value objects
@dataclass(frozen=True)
class Grid:
    """``count`` values ``start + k·step`` computed in decimal (each the float nearest the decimal number).

    >>> g = Grid(Decimal("1.2"), Decimal("0.05"), 5)
    >>> [g.value(k) for k in range(5)]
    [1.2, 1.25, 1.3, 1.35, 1.4]
    """

    start: Decimal
    step: Decimal
    count: int

    def value(self, k: int) -> float:
        """The ``k``-th value."""
        return float(self.start + k * self.step)


@dataclass(frozen=True)
class Slot:
    """One choice of an exercise: where it goes in the givens and what it may take.

    ``path`` is ``(given,)`` or ``(given, row, field)`` for a field of a table given (a motion program);
    ``choices`` holds the values of a list, ``grid`` those of a range (exactly one of them is set); ``parts``,
    the slots of givens chosen ``together`` (then ``path`` is the first one's and ``value`` a tuple of theirs).
    """

    path: tuple
    choices: tuple = ()
    grid: Grid | None = None
    parts: tuple["Slot", ...] = ()

    @property
    def count(self) -> int:
        """How many values the slot may take."""
        if self.parts:
            return self.parts[0].count
        return self.grid.count if self.grid is not None else len(self.choices)

    def value(self, k: int) -> Any:
        """The slot's ``k``-th value (a float for numbers; a string, bool, list or table as written)."""
        if self.parts:
            return tuple(s.value(k) for s in self.parts)
        return self.grid.value(k) if self.grid is not None else self.choices[k]

    def put(self, given: dict[str, Any], k: int) -> None:
        """Write the slot's ``k``-th value into ``given`` (each part's, for givens chosen together)."""
        if self.parts:
            for s in self.parts:
                s.put(given, k)
        elif len(self.path) == 1:
            given[self.path[0]] = _copy(self.value(k))
        else:
            name, row, field = self.path
            given[name][row][field] = self.value(k)

    @property
    def name(self) -> str:
        """The slot as a spec names it: ``CD``, ``program[0].angle``, ``B2+C2`` (chosen together)."""
        if self.parts:
            return "+".join(s.name for s in self.parts)
        return self.path[0] if len(self.path) == 1 else f"{self.path[0]}[{self.path[1]}].{self.path[2]}"


@dataclass(frozen=True)
class AnswerRef:
    """An answer named by ``ask`` or ``[require]``: ``AB``, or an element of a list answer, ``s[2]``."""

    text: str
    name: str
    index: int | None
    unit: str

    def of(self, answers: Mapping[str, Any]) -> float | None:
        """The referred number in a solution's answers (None when the variant has no such answer)."""
        v = answers.get(self.name)
        if v is None:
            return None
        if self.index is not None:
            if not isinstance(v, (tuple, list)) or self.index >= len(v):
                return None
            v = v[self.index]
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            return None
        return float(v)


@dataclass(frozen=True)
class Bound:
    """A ``[require]`` bound: ``lo ≤ answer ≤ hi`` (either may be None)."""

    answer: AnswerRef
    lo: float | None
    hi: float | None

    def holds(self, x: float) -> bool:
        """Whether ``x`` lies within the bound (inclusive)."""
        return (self.lo is None or x >= self.lo) and (self.hi is None or x <= self.hi)

    def text(self) -> str:
        """The bound as a line says it: ``gamma_min ≥ 40``."""
        parts = []
        if self.lo is not None:
            parts.append(f"≥ {self.lo:g}")
        if self.hi is not None:
            parts.append(f"≤ {self.hi:g}")
        return f"{self.answer.text} " + " and ".join(parts)


@dataclass(frozen=True)
class TolRule:
    """A teacher's tolerance of one answer instead of the drafting one: ``abs`` (in the answer's unit),
    ``rel`` (a fraction of the answer) or ``sig`` (significant figures: half a unit of the last one).

    >>> TolRule("sig", 3).of(21.07), TolRule("rel", 0.02).of(50.0), TolRule("abs", 0.5).of(7.0)
    (0.05, 1.0, 0.5)
    """

    kind: str
    value: float

    def of(self, x: float) -> float:
        """The absolute tolerance for the answer ``x``."""
        if self.kind == "abs":
            return self.value
        if self.kind == "rel":
            return self.value * abs(x)
        if x == 0:
            return 0.0
        exponent = math.floor(math.log10(abs(x))) - int(self.value) + 1
        return float(Decimal(5).scaleb(exponent - 1))


@dataclass(frozen=True)
class Exercise:
    """One exercise of a spec, validated; ``given`` holds the fixed values (as written) and ``slots`` the
    choices, in the spec's order."""

    n: int
    recipe: str
    given: Mapping[str, Any]
    slots: tuple[Slot, ...]
    ask: tuple[AnswerRef, ...]
    points: tuple[float, ...]
    statement: Mapping[str, str] | None
    require: tuple[Bound, ...]
    tol: Mapping[str, TolRule]
    scale: Scale | None
    max_tol_rel: float
    digest: str
    diagnose: Mapping[str, tuple[Mapping[str, str], ...]] = field(default_factory=dict)

    @property
    def pool(self) -> int:
        """How many variants the choices make (the product of the slots' counts)."""
        out = 1
        for s in self.slots:
            out *= s.count
        return out

    def digits(self, index: int) -> tuple[int, ...]:
        """The slots' choices of variant ``index`` (mixed radix, the first slot most significant)."""
        out = []
        for s in reversed(self.slots):
            index, k = divmod(index, s.count)
            out.append(k)
        return tuple(reversed(out))

    def given_of(self, index: int) -> dict[str, Any]:
        """The raw givens of variant ``index`` (fixed values and the slots' choices), as a problem file's
        ``[given]`` table would hold them."""
        out = {k: _copy(v) for k, v in self.given.items()}
        for s, k in zip(self.slots, self.digits(index)):
            s.put(out, k)
        return out


@dataclass(frozen=True)
class Spec:
    """A parsed worksheet spec."""

    name: str
    title: str
    seed: int | str | None
    exercises: tuple[Exercise, ...]
    sha256: str
    title_zh: str = ""
    """The Chinese title (as a problem file's ``title_zh``): the header of a zh page prints it, of a page in
    both languages after the English one."""

    def title_in(self, lang: str) -> str:
        """The title in the page's language, on one line (``both``: English, two spaces, Chinese).

        >>> Spec("s", "Guide bar", None, (), "", "导杆机构").title_in("both")
        'Guide bar  导杆机构'
        """
        return title_in(self.title, self.title_zh, lang).replace("\n", "  ")


def _copy(v: Any) -> Any:
    if isinstance(v, list):
        return [_copy(x) for x in v]
    if isinstance(v, dict):
        return {k: _copy(x) for k, x in v.items()}
    return v


# ---------------------------------------------------------------------------------------------- parsing
def load_spec(path: str | Path) -> Spec:
    """Read and parse a spec file (a regular UTF-8 file of at most ``LIMITS['file_bytes']``).

    Raises
    ------
    ProblemError
        One line naming the exercise, the key and the numbers.
    """
    p = Path(path)
    text = read_limited(p, LIMITS["file_bytes"])
    return parse_spec(text, name=p.name)


def parse_spec(text: str, *, name: str = "spec.toml") -> Spec:
    """Parse spec text (see the module's documentation); ``sha256`` is the digest of the UTF-8 text."""
    data = parse_toml(text)
    extra = [k for k in data if k not in TOP_KEYS]
    if extra:
        raise ProblemError(f"unknown key {_quote(extra[0])} (a worksheet spec takes {', '.join(TOP_KEYS)})")
    title = _text(data.get("title", ""), "title", LIMITS["title_chars"])
    seed = data.get("seed")
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, str))
                             or (isinstance(seed, int) and abs(seed) >= 2 ** 63)):
        raise ProblemError(f"'seed' must be an integer below 2**63 in size or a string, got {_short(seed)}")
    if isinstance(seed, str):
        seed = _text(seed, "seed", 200)
    exercises = data.get("exercise")
    if not isinstance(exercises, list) or not exercises or not all(isinstance(e, dict) for e in exercises):
        raise ProblemError("a worksheet spec needs at least one [[exercise]] table")
    if len(exercises) > LIMITS["exercises"]:
        raise ProblemError(f"{len(exercises)} exercises; at most {LIMITS['exercises']}")
    parsed = tuple(_exercise(e, i + 1) for i, e in enumerate(exercises))
    return Spec(name, title, seed, parsed, hashlib.sha256(text.encode("utf-8")).hexdigest(),
                title_zh(data.get("title_zh", "")))


def _exercise(data: Mapping[str, Any], n: int) -> Exercise:
    where = f"exercise {n}"
    extra = [k for k in data if k not in EXERCISE_KEYS]
    if extra:
        raise ProblemError(f"{where}: unknown key {_quote(extra[0])} (an exercise takes {', '.join(EXERCISE_KEYS)})")
    if "recipe" not in data:
        raise ProblemError(f"{where}: missing key 'recipe'")
    if not isinstance(data["recipe"], str):
        raise ProblemError(f"{where}: 'recipe' must be a string, got {_short(data['recipe'])}")
    try:
        recipe = get_recipe(data["recipe"])
    except ProblemError as exc:
        raise ProblemError(f"{where}: {exc}") from None
    given_in = data.get("given", {})
    if not isinstance(given_in, dict):
        raise ProblemError(f"{where}: [exercise.given] must be a table of name = value, list or range")
    names = recipe.given_names()
    units = {q.name: q for q in recipe.givens}
    fixed: dict[str, Any] = {}
    slots: list[Slot] = []
    together = data.get("together")
    joint = {n for g in together for n in g if isinstance(n, str)} if isinstance(together, list) and all(
        isinstance(g, list) for g in together) else set()
    for key, value in given_in.items():
        if key not in units:
            raise ProblemError(f"{where}: unknown given {_quote(key)} for recipe {recipe.name} "
                               f"(it takes {', '.join(names)})")
        _given(units[key], value, f"{where}: given '{key}'", fixed, slots, key in joint)
    ask = _ask(recipe, data.get("ask"), where)
    points = _points(data.get("points"), len(ask), where)
    require = _require(recipe, data.get("require", {}), where)
    tol = _tol_rules(recipe, data.get("tol", {}), ask, where)
    scale = _scale(data.get("scale"), where)
    max_rel = data.get("max_tol_rel", MAX_TOL_REL)
    if isinstance(max_rel, bool) or not isinstance(max_rel, (int, float)) or not 0 < max_rel <= 1:
        raise ProblemError(f"{where}: 'max_tol_rel' must be a number in (0, 1], got {_short(max_rel)}")
    statement = _statement(data.get("statement"), where, set(given_in))
    slots = _together(together, slots, where)
    drawn = {"recipe": recipe.name, "given": given_in} | ({"together": data["together"]} if "together" in data else {})
    digest = hashlib.sha256(json.dumps(drawn, sort_keys=True, ensure_ascii=True,
                                       separators=(",", ":")).encode()).hexdigest()
    diagnose = _diagnoses(recipe, data.get("diagnose", {}), ask, where)
    return Exercise(n, recipe.name, fixed, tuple(slots), ask, points, statement, require, tol, scale,
                    float(max_rel), digest, diagnose)


def _given(q: Quantity, value: Any, where: str, fixed: dict[str, Any], slots: list[Slot], joint: bool = False) -> None:
    """Sort one given into a fixed value or a slot (list or range), refusing any other form; a ``joint`` given
    (chosen ``together`` with others) may repeat a value: its group's combinations must differ instead."""
    form = (f"{where} must be {_forms(q)}, got {_short(value)}")
    fixed[q.name] = None                   # its place in the spec's order; a slot fills it in each variant
    if isinstance(value, dict):
        if q.unit not in _SCALAR:
            raise ProblemError(form)
        slots.append(Slot((q.name,), grid=_grid(value, where)))
        return
    if q.unit in _SCALAR:
        if isinstance(value, list):
            slots.append(Slot((q.name,), choices=_choices(value, where, _is_number, "numbers", repeats=joint)))
            return
        if not _is_number(value):
            raise ProblemError(form)
        fixed[q.name] = value
        return
    if q.unit in _WORDS:
        ok, words = _WORDS[q.unit]
        if isinstance(value, list):
            slots.append(Slot((q.name,), choices=_choices(value, where, ok, words, repeats=joint)))
        elif ok(value):
            fixed[q.name] = value
        else:
            raise ProblemError(form)
        return
    if q.unit == "table[]":
        if isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            fixed[q.name] = _program(q.name, value, where, slots)
        elif isinstance(value, list) and value and all(isinstance(v, list) for v in value):
            for i, v in enumerate(value):
                if not v or not all(isinstance(r, dict) for r in v):
                    raise ProblemError(f"{where}[{i}] must be a list of tables, got {_short(v)}")
                _check_rows(v, f"{where}[{i}]")
                for j, row in enumerate(v):
                    for field, x in row.items():
                        if not (_is_number(x) or isinstance(x, str)):
                            raise ProblemError(f"{where}[{i}][{j}].{field} must be a number or a word, got {_short(x)}")
            slots.append(Slot((q.name,), choices=_choices(value, where, lambda v: True, "programs", repeats=joint)))
        else:
            raise ProblemError(form)
        return
    # a list given: a point [x, y] or a list of numbers; one of several: a list of them
    if isinstance(value, list) and value and all(isinstance(v, list) for v in value):
        for i, v in enumerate(value):
            if not v or not all(_is_number(x) for x in v) or len(v) > LIMITS["list_items"]:
                raise ProblemError(f"{where}[{i}] must be a non-empty list of numbers, got {_short(v)}")
        slots.append(Slot((q.name,), choices=_choices(value, where, lambda v: True, "lists", repeats=joint)))
    elif isinstance(value, list) and value and all(_is_number(x) for x in value):
        fixed[q.name] = value
    else:
        raise ProblemError(form)


def _together(value: Any, slots: list[Slot], where: str) -> list[Slot]:
    """The slots with each group of ``together`` (a list of lists of given names) merged into one slot, at the
    place of the group's first given; the groups' givens must be lists or ranges of one length."""
    if value is None:
        return slots
    if not isinstance(value, list) or not all(isinstance(g, list) and len(g) >= 2 and all(isinstance(n, str) for n in g)
                                              for g in value):
        raise ProblemError(f"{where}: 'together' must be a list of lists of two or more given names, e.g. "
                           f"[[\"B2\", \"C2\"]], got {_short(value)}")
    by_name = {s.path[0]: s for s in slots if len(s.path) == 1}
    merged: dict[str, Slot] = {}
    gone: set[str] = set()
    for i, group in enumerate(value):
        for n in group:
            if n not in by_name:
                raise ProblemError(f"{where}: together[{i}] names {_quote(n)}, not a given of this exercise with "
                                   "choices (a list or a range)")
            if n in gone:
                raise ProblemError(f"{where}: together[{i}] names {_quote(n)} again (a given goes in one group)")
            gone.add(n)
        counts = [by_name[n].count for n in group]
        if len(set(counts)) > 1:
            listed = ", ".join(f"{n} {c}" for n, c in zip(group, counts))
            raise ProblemError(f"{where}: together[{i}]: givens chosen together need as many choices each, got {listed}")
        slot = Slot(by_name[group[0]].path, parts=tuple(by_name[n] for n in group))
        seen: set[str] = set()
        for k in range(slot.count):
            v = json.dumps(slot.value(k), sort_keys=True)
            if v in seen:
                raise ProblemError(f"{where}: together[{i}]: choice {k} of {', '.join(group)} repeats an earlier one, "
                                   f"{_short(list(slot.value(k)))}")
            seen.add(v)
        merged[group[0]] = slot
    return [merged.get(s.path[0], s) if len(s.path) == 1 else s for s in slots
            if len(s.path) != 1 or s.path[0] in merged or s.path[0] not in gone]


def _forms(q: Quantity) -> str:
    if q.unit in _SCALAR:
        return "a number, a list of numbers (one of them) or a range {min, max, step}"
    if q.unit == "choice":
        return f"one of {', '.join(q.choices)} or a list of them"
    if q.unit == "bool":
        return "true, false or a list of them"
    if q.unit == "table[]":
        return "a list of tables (rows may hold lists and ranges) or a list of such lists (one of them)"
    return "a list of numbers or a list of such lists (one of them)"


LAW_NUMBERS = ("coefficients", "points")
"""Program fields that are lists by nature (a ``poly`` law's coefficients, a ``table`` law's points): kept as
given (checked by the program's parser), never read as a list of choices."""


def _program(name: str, rows: list, where: str, slots: list[Slot]) -> list[dict[str, Any]]:
    """A motion program whose fields may hold lists and ranges (slots ``(name, row, field)``)."""
    _check_rows(rows, where)
    out = []
    for i, row in enumerate(rows):
        kept = {}
        for field, v in row.items():
            at = f"{where}[{i}].{field}"
            if isinstance(v, dict):
                slots.append(Slot((name, i, field), grid=_grid(v, at)))
                kept[field] = None
            elif field in LAW_NUMBERS and isinstance(v, list):   # a law's own numbers: one fixed value, not choices
                kept[field] = v
            elif isinstance(v, list):
                slots.append(Slot((name, i, field), choices=_choices(
                    v, at, lambda x: _is_number(x) or isinstance(x, str), "numbers or words")))
                kept[field] = None
            elif _is_number(v) or isinstance(v, str):
                kept[field] = v
            else:
                raise ProblemError(f"{at} must be a number, a word, a list of them or a range {{min, max, step}}, "
                                   f"got {_short(v)}")
        out.append(kept)
    return out


def _check_rows(rows: list, where: str) -> None:
    if len(rows) > LIMITS["program_rows"]:
        raise ProblemError(f"{where} has {len(rows)} rows; at most {LIMITS['program_rows']}")


def _is_number(v: Any) -> bool:
    return (not isinstance(v, bool) and isinstance(v, (int, float))
            and (math.isfinite(v) if isinstance(v, float) else abs(v) <= 10 ** 300))


def _choices(values: list, where: str, ok, what: str, repeats: bool = False) -> tuple:
    if not values:
        raise ProblemError(f"{where} is an empty list: give at least one value")
    if len(values) > LIMITS["list_items"]:
        raise ProblemError(f"{where} has {len(values)} choices; at most {LIMITS['list_items']}")
    seen: set[str] = set()
    for i, v in enumerate(values):
        if not ok(v):
            raise ProblemError(f"{where}[{i}] must be one of the {what} to choose from, got {_short(v)}")
        k = json.dumps(v, sort_keys=True)
        if k in seen and not repeats:
            raise ProblemError(f"{where} lists {_short(v)} twice")
        seen.add(k)
    return tuple(values)


def _grid(value: Mapping[str, Any], where: str) -> Grid:
    """A range {min, max, step}: every min + k·step ≤ max, in decimal."""
    keys = set(value)
    if keys != {"min", "max", "step"}:
        missing = sorted({"min", "max", "step"} - keys)
        what = f"lacks {', '.join(missing)}" if missing else f"has unknown key {_quote(sorted(keys - {'min', 'max', 'step'})[0])}"
        raise ProblemError(f"{where}: a range is {{min, max, step}}; this one {what}")
    dec = {}
    for k in ("min", "max", "step"):
        v = value[k]
        if not _is_number(v) or (isinstance(v, int) and abs(v) > 1e15):
            raise ProblemError(f"{where}.{k} must be a number, got {_short(v)}")
        dec[k] = Decimal(repr(float(v))) if isinstance(v, float) else Decimal(v)
    lo, hi, step = dec["min"], dec["max"], dec["step"]
    if step <= 0:
        raise ProblemError(f"{where}: step = {_g(value['step'])} must be > 0")
    if hi < lo:
        raise ProblemError(f"{where}: empty range: max = {_g(value['max'])} < min = {_g(value['min'])}")
    span = (hi - lo) / step
    if span >= LIMITS["grid_points"]:
        shown = str(int(span) + 1) if span < 10 ** 15 else f"about {span:.3g}"
        raise ProblemError(f"{where}: the range has {shown} values ((max − min)/step + 1); at most "
                           f"{LIMITS['grid_points']}")
    count = int((hi - lo) / step) + 1
    return Grid(lo, step, count)


def _ask(recipe: Recipe, value: Any, where: str) -> tuple[AnswerRef, ...]:
    if value is None:
        raise ProblemError(f"{where}: missing key 'ask' (the answers the student gives, e.g. ask = [\"AB\"])")
    if not isinstance(value, list) or not value:
        raise ProblemError(f"{where}: 'ask' must be a non-empty list of answer names, got {_short(value)}")
    if len(value) > LIMITS["ask"]:
        raise ProblemError(f"{where}: 'ask' names {len(value)} answers; at most {LIMITS['ask']}")
    out = [_answer_ref(recipe, v, f"{where}: ask[{i}]") for i, v in enumerate(value)]
    texts = [a.text for a in out]
    dup = next((t for t in texts if texts.count(t) > 1), None)
    if dup is not None:
        raise ProblemError(f"{where}: 'ask' names {_quote(dup)} twice")
    return tuple(out)


def _answer_ref(recipe: Recipe, value: Any, where: str) -> AnswerRef:
    answers = {q.name: q for q in recipe.answers}
    m = _ANSWER_REF.match(value) if isinstance(value, str) else None
    if m is None or m.group(1) not in answers:
        raise ProblemError(f"{where}: {_short(value)} is not an answer of {recipe.name} "
                           f"(its answers: {', '.join(answers)})")
    q = answers[m.group(1)]
    index = None if m.group(2) is None else int(m.group(2))
    if q.unit == "bool":
        raise ProblemError(f"{where}: {value!r} is a yes/no answer; ask for numbers")
    if q.unit in ("choice", "interval[]"):
        lists = [f"'{a.name}[0]'" for a in recipe.answers if a.unit.endswith("[]") and a.unit != "interval[]"]
        raise ProblemError(f"{where}: {value!r} is {'a word' if q.unit == 'choice' else 'a list of intervals [low, high]'}"
                           f", not a number; ask for numbers" + (f" (e.g. {lists[0]})" if lists else ""))
    if q.unit.endswith("[]") and index is None:
        raise ProblemError(f"{where}: {value!r} is a list answer; name one element, e.g. '{q.name}[0]'")
    if not q.unit.endswith("[]") and index is not None:
        raise ProblemError(f"{where}: {value!r}: answer '{q.name}' is a number, not a list")
    return AnswerRef(value, q.name, index, q.unit.removesuffix("[]"))


def _points(value: Any, n: int, where: str) -> tuple[float, ...]:
    if value is None:
        return (1.0,) * n
    if not isinstance(value, list) or len(value) != n:
        raise ProblemError(f"{where}: 'points' must list one number per asked answer ({n}), got {_short(value)}")
    for i, v in enumerate(value):
        if not _is_number(v) or not 0 < v <= LIMITS["points"]:
            raise ProblemError(f"{where}: points[{i}] must be a number in (0, {LIMITS['points']:g}], got {_short(v)}")
    return tuple(float(v) for v in value)


def _require(recipe: Recipe, value: Any, where: str) -> tuple[Bound, ...]:
    if not isinstance(value, dict):
        raise ProblemError(f"{where}: [exercise.require] must be a table of answer = {{min, max}}")
    out = []
    for key, b in value.items():
        at = f"{where}: require '{key}'"
        ref = _answer_ref(recipe, key, f"{where}: require")
        if not isinstance(b, dict) or not b or set(b) - {"min", "max"}:
            raise ProblemError(f"{at} must be {{min = …}}, {{max = …}} or both, got {_short(b)}")
        for k, v in b.items():
            if not _is_number(v):
                raise ProblemError(f"{at}.{k} must be a number, got {_short(v)}")
        lo = float(b["min"]) if "min" in b else None
        hi = float(b["max"]) if "max" in b else None
        if lo is not None and hi is not None and lo > hi:
            raise ProblemError(f"{at}: unsatisfiable: min = {_g(lo)} > max = {_g(hi)}")
        out.append(Bound(ref, lo, hi))
    return tuple(out)


def _tol_rules(recipe: Recipe, value: Any, ask: tuple[AnswerRef, ...], where: str) -> dict[str, TolRule]:
    if not isinstance(value, dict):
        raise ProblemError(f"{where}: [exercise.tol] must be a table of answer = {{abs | rel | sig = …}}")
    asked = {a.text for a in ask}
    out = {}
    for key, rule in value.items():
        at = f"{where}: tol '{key}'"
        if key not in asked:
            raise ProblemError(f"{at}: not an asked answer (ask: {', '.join(sorted(asked))})")
        if not isinstance(rule, dict) or len(rule) != 1 or next(iter(rule)) not in ("abs", "rel", "sig"):
            raise ProblemError(f"{at} must be {{abs = x}}, {{rel = x}} or {{sig = n}}, got {_short(rule)}")
        kind, v = next(iter(rule.items()))
        if not _is_number(v) or v <= 0 or (kind == "sig" and (not isinstance(v, int) or v > 15)) \
                or (kind == "rel" and v > 1):
            raise ProblemError(f"{at}: {kind} = {_short(v)} must be positive"
                               + (", an integer ≤ 15" if kind == "sig" else ", at most 1" if kind == "rel" else ""))
        out[key] = TolRule(kind, float(v))
    return out


def _diagnoses(recipe: Recipe, value: Any, ask: tuple[AnswerRef, ...], where: str
               ) -> dict[str, tuple[dict[str, str], ...]]:
    """``[exercise.diagnose]``: asked answer = {code, expr, en, zh} or a list of them (at most 20); ``expr`` is
    parsed by :func:`geomcon.grading.expr.parse` over the exercise's asked answers and givens."""
    from ..grading.expr import parse

    if not isinstance(value, dict):
        raise ProblemError(f"{where}: [exercise.diagnose] must be a table of answer = {{code, expr, en, zh}}")
    asked = {a.text for a in ask}
    names = asked | set(recipe.given_names())
    out = {}
    for key, rules in value.items():
        at = f"{where}: diagnose '{key}'"
        if key not in asked:
            raise ProblemError(f"{at}: not an asked answer (ask: {', '.join(sorted(asked))})")
        rules = rules if isinstance(rules, list) else [rules]
        if len(rules) > 20:
            raise ProblemError(f"{at}: at most 20 diagnoses per answer")
        rows = []
        for r in rules:
            if not isinstance(r, dict) or set(r) - {"code", "expr", "en", "zh"} or not {"code", "expr"} <= set(r) \
                    or not all(isinstance(x, str) for x in r.values()):
                raise ProblemError(f"{at} must be {{code = \"…\", expr = \"…\", en = \"…\", zh = \"…\"}} (texts), "
                                   f"got {_short(r)}")
            if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,39}", r["code"]):
                raise ProblemError(f"{at}: code {_short(r['code'])} must be a word of letters, digits and _")
            try:
                parse(r["expr"], names - {key})
            except ValueError as exc:
                raise ProblemError(f"{at}: {exc}") from None
            rows.append({k: _text(r.get(k, ""), k, 400) if k in ("en", "zh") else r[k]
                         for k in ("code", "expr", "en", "zh")})
        out[key] = tuple(rows)
    return out


def _scale(value: Any, where: str) -> Scale | None:
    if value is None:
        return None
    names = {str(s): s for s in STANDARD}
    if not isinstance(value, str) or value.replace(" ", "") not in names:
        raise ProblemError(f"{where}: 'scale' must be a standard scale such as \"1:2\" "
                           f"({', '.join(str(s) for s in STANDARD if 0.01 <= s.factor <= 10)}), got {_short(value)}")
    return names[value.replace(" ", "")]


def _statement(value: Any, where: str, givens: set[str]) -> dict[str, str] | None:
    """A custom statement: one text for every language, or a table {en, zh}; its placeholders must name
    givens of the exercise or ``choice`` (never an answer: a student sheet holds none)."""
    if value is None:
        return None
    if isinstance(value, str):
        texts = {lang: value for lang in LANGS}
    elif isinstance(value, dict) and value and set(value) <= set(LANGS):
        texts = dict(value)
    else:
        raise ProblemError(f"{where}: 'statement' must be a text or a table {{en = …, zh = …}}, got {_short(value)}")
    allowed = givens | {"choice"}
    for lang, t in texts.items():
        t = _text(t, f"{where}: statement", LIMITS["text_chars"])
        bare = t.replace("{{", "").replace("}}", "")
        for m in _PLACEHOLDER.finditer(bare):
            if m.group(1) not in allowed:
                raise ProblemError(f"{where}: statement ({lang}) names {{{_short(m.group(1), 40)[1:-1]}}}: "
                                   f"a placeholder is a given ({', '.join(sorted(givens))}) or {{choice}}")
        if "{" in _PLACEHOLDER.sub("", bare) or "}" in _PLACEHOLDER.sub("", bare):
            raise ProblemError(f"{where}: statement ({lang}) has an unmatched brace (write {{{{ or }}}} for a brace)")
    return texts


# ---------------------------------------------------------------------------------------------- small helpers
def _text(value: Any, key: str, limit: int) -> str:
    if not isinstance(value, str):
        raise ProblemError(f"{_quote(key) if ':' not in key else key} must be a string, got {_short(value)}")
    if len(value) > limit:
        raise ProblemError(f"{key} has {len(value)} characters; at most {limit}")
    for i, ch in enumerate(value):
        if ch not in "\t\n" and (unicodedata.category(ch) in ("Cc", "Cs") or ch in "\ufffe\uffff"):
            raise ProblemError(f"{key} holds the control character U+{ord(ch):04X} at position {i}")
    return value


def _quote(key: Any) -> str:
    return repr(str(key)[:60])


def _g(x: float) -> str:
    return f"{float(x):g}"


def _short(value: Any, limit: int = 60) -> str:
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 10 ** 30:
        return f"an integer of {len(str(abs(value)))} digits"
    if isinstance(value, dict):
        text = "{" + ", ".join(f"{k} = {_short(v, 20)}" for k, v in value.items()) + "}"
    elif isinstance(value, bool):
        text = "true" if value else "false"
    elif isinstance(value, float):
        text = _g(value)
    else:
        text = repr(value)
    return text if len(text) <= limit else text[:limit - 1] + "…"


__all__ = ["AnswerRef", "Bound", "Exercise", "Grid", "LIMITS", "MAX_TOL_REL", "Slot", "Spec", "TolRule",
           "load_spec", "parse_spec"]
