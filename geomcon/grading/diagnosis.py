"""Mistake diagnosis: for each asked answer of a variant, the values the plausible wrong constructions give,
computed once per variant (:func:`prepare`); a student's wrong value is then matched against them.

Where the alternatives come from, in order of preference when two match equally well:

1. the teacher's expressions (``[exercise.diagnose]`` in the spec, :mod:`.expr`), of the other answers'
   exact values and the givens;
2. the recipe's declared mistakes (:mod:`.mistakes`), each a replay of the scene;
3. the recipe's other candidate solutions (``C1_C2``, ``far_theta_circle``, … by the flag that differs;
   ``other_branch`` when none is declared);
4. ``other_branch``: every named branch rule the asked answers depend on, flipped one at a time (the step is
   named in the feedback);
5. ``swapped`` (another asked answer of the exercise, same unit), ``degrees_radians`` (an angle given in
   radians, or radians taken for degrees), ``turn`` (an angle counted through another turn, ± 360°: 100-06's
   β = 188.439° counter-clockwise from DE written as −171.561°), ``scale`` (a length off by a drawing-scale factor 2, 2.5, 5, 10 or its
   inverse: μl misread), ``sign``.

A value matches an alternative within the answer's tolerance (scaled with it for ``scale`` and
``degrees_radians``: the drafting error is scaled too); of several matches the nearest (in tolerances) wins.
An alternative that lies within tolerance of the right value is dropped (a drawing cannot tell them apart).
``rounding`` is decided on the student's own digits (:func:`rounding`): the right value rounded to fewer
significant digits than the tolerance needs.

Examples
--------
>>> from geomcon.grading.keyfile import key_from_json
>>> import json
>>> key = key_from_json(json.dumps({"students": [{"id": "1", "exercises": [{"n": 1, "recipe": "crank_rocker.extremes",
...     "given": {"AB": 25, "BC": 85, "CD": 70, "AD": 70},
...     "answers": {"theta": {"value": 26.4098557731, "tol": 0.88, "points": 2},
...                 "K": {"value": 1.34390039681, "tol": 0.01, "points": 1}}}]}]}))
>>> p = prepare(key.students["1"].exercises[0])
>>> [(a.code, round(a.value, 4)) for a in p.alts["1.K"]][:2]
[('K_inverted', 0.7441), ('other_branch', 3.6654)]
>>> match(p.alts["1.K"], 0.744).code
'K_inverted'
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Mapping

from ..errors import GeomconError
from .expr import parse
from .keyfile import Answer, ExerciseKey
from .mistakes import mistakes_of
from .replay import Variant

if TYPE_CHECKING:
    from ..solve import Solution

SCALES = (2.0, 2.5, 5.0, 10.0)
SHARED = ("other_branch", "swapped", "degrees_radians", "turn", "scale", "sign", "rounding")
"""The codes every recipe shares (plus ``follow_through`` for credit carried from an earlier answer)."""
WORDS: dict[str, tuple[str, str]] = {
    "other_branch": ("the other intersection taken at a step", "某一步取了另一个交点"),
    "swapped": ("two answers exchanged", "两个答案填反了"),
    "degrees_radians": ("degrees and radians confused", "角度与弧度混淆"),
    "turn": ("the same direction counted through another turn (± 360°)", "方向相同，但多转或少转了一周(± 360°)"),
    "scale": ("off by a drawing-scale factor (μl misread)", "比例尺 μl 换算错误"),
    "sign": ("the sign is wrong", "符号错误"),
    "rounding": ("right, but rounded to fewer digits than asked", "数值正确但有效数字不足"),
    "follow_through": ("right from your own earlier answer", "由你前面的答案推得正确"),
}
"""One sentence per shared code (English, Chinese)."""


@dataclass(frozen=True)
class Alt:
    """A plausible wrong value of an answer: its code, value, the tolerance it is recognised within, and what
    the student did, in words (English, Chinese)."""

    code: str
    value: Any
    tol: float
    en: str
    zh: str


@dataclass
class Prepared:
    """One exercise of one variant, ready to grade: the alternatives of each answer (by column), the earlier
    answers each answer's construction uses (for follow-through), and the replayable variant."""

    ex: ExerciseKey
    alts: dict[str, tuple[Alt, ...]]
    uses: dict[str, tuple[str, ...]]
    variant: Variant | None
    steps: dict[str, str]
    problem: str = ""
    _follow: dict = field(default_factory=dict)

    def follow(self, base: Answer, value: float, target: Answer) -> float | None:
        """``target``'s value in a replay where ``base``'s step holds the student's ``value`` (None when it
        cannot be replayed)."""
        key = (base.column, value, target.column)
        if key not in self._follow:
            out = None
            try:
                got = self.variant.values([self.steps[target.column]], constant={self.steps[base.column]: value})
                out = _element(got[self.steps[target.column]], target)
            except (GeomconError, ArithmeticError, ValueError, TypeError, KeyError):
                out = None
            if len(self._follow) > 10_000:
                self._follow.clear()
            self._follow[key] = out
        return self._follow[key]


def _element(v: Any, a: Answer) -> Any:
    if a.ref.index is not None:
        v = v[a.ref.index] if isinstance(v, (tuple, list)) and a.ref.index < len(v) else None
    if isinstance(v, bool) or v is None:
        return None
    if a.unit == "point":
        if hasattr(v, "x"):
            return float(v.x), float(v.y)
        return (float(v[0]), float(v[1])) if isinstance(v, (tuple, list)) and len(v) == 2 else None
    return float(v) if isinstance(v, (int, float)) and math.isfinite(v) else None


def distance(a: Any, b: Any) -> float:
    """|a − b| for numbers, the distance for points."""
    if isinstance(a, tuple):
        return math.hypot(a[0] - b[0], a[1] - b[1])
    return abs(a - b)


def _shared(ex: ExerciseKey, a: Answer) -> list[Alt]:
    out = []
    for b in ex.answers:
        if b is not a and b.unit == a.unit:
            out.append(Alt("swapped", b.expected, b.tol, f"the value of {b.ref.text} given for {a.ref.text}",
                           f"把 {b.ref.text} 的值填在了 {a.ref.text} 处"))
    if a.unit == "deg":
        r = math.pi / 180.0
        out.append(Alt("degrees_radians", a.expected * r, a.tol * r, "the angle given in radians", "角度以弧度给出"))
        out.append(Alt("degrees_radians", a.expected / r, a.tol / r, "radians read as degrees", "把弧度当成了度"))
        for k in (-360.0, 360.0):
            out.append(Alt("turn", a.expected + k, a.tol, *WORDS["turn"]))
    if a.unit == "mm":
        for f in SCALES:
            for k in (f, 1.0 / f):
                out.append(Alt("scale", a.expected * k, a.tol * k, f"the length off by a factor {k:g} (drawing scale "
                               "misread)", f"长度差了 {k:g} 倍(比例尺换算错误)"))
    if a.unit != "point" and a.expected != 0:
        out.append(Alt("sign", -a.expected, a.tol, "the sign is wrong", "符号错误"))
    return out


def prepare(ex: ExerciseKey, solved: Solution | None = None) -> Prepared:
    """The alternatives of every answer of one exercise of one variant (see the module). A variant the recipe
    no longer solves is graded without diagnoses (``problem`` says why). ``solved``: the variant's solution
    when it is at hand (the worksheet judged it: :meth:`.replay.Variant.of` uses it instead of solving again)."""
    found: dict[str, list[Alt]] = {a.column: [] for a in ex.answers}
    try:
        var = Variant.of(ex.recipe, ex.given, solved)
    except GeomconError as exc:
        shared = {a.column: tuple(_keep(a, _shared(ex, a))) for a in ex.answers}
        return Prepared(ex, shared, {}, None, {}, f"variant not solved again: {exc}")
    steps = {a.column: var.answers[a.ref.name] for a in ex.answers if a.ref.name in var.answers}

    def add(code: str, values: Mapping[str, Any], en: str, zh: str, only: str = "") -> None:
        for a in ex.answers:
            if (only and a.ref.name != only) or a.column not in steps:
                continue
            v = _element(values.get(steps[a.column]), a)
            if v is not None:
                found[a.column].append(Alt(code, v, a.tol, en, zh))

    keys = list(steps.values())
    # 1. the teacher's expressions
    names = {a.ref.text: a.expected for a in ex.answers if a.unit != "point"}
    names.update({k: float(v) for k, v in ex.given.items() if isinstance(v, (int, float)) and not isinstance(v, bool)})
    for a in ex.answers:
        for rule in ex.diagnose.get(a.ref.text, ()):
            try:
                v = parse(rule["expr"])(names)
            except (ValueError, KeyError):
                continue
            found[a.column].append(Alt(rule["code"], v, a.tol, rule.get("en") or rule["expr"], rule.get("zh") or rule["expr"]))
    # 2. the recipe's declared mistakes
    candidates_flagged = []
    for m in mistakes_of(ex.recipe):
        try:
            if m.kind == "read":
                if m.answer not in var.answers:
                    continue
                src = var.answers.get(m.step, m.step)
                got = var.values([src])
                add(m.code, {var.answers[m.answer]: got[src]}, m.en, m.zh, only=m.answer)
            elif m.kind == "op":
                ks = [steps[a.column] for a in ex.answers if a.column in steps and a.ref.name == m.answer] \
                    if m.answer else keys
                if ks:
                    add(m.code, var.values(ks, op=tuple((s, m.op) for s in m.where())), m.en, m.zh, only=m.answer)
            elif m.kind == "rewire":
                add(m.code, var.values(keys, rewire=(m.step, m.old, m.new)), m.en, m.zh, only=m.answer)
            elif m.kind == "given":
                g = dict(ex.given)
                for name, fn in m.given.items():
                    g[name] = fn(g.get(name))
                other = Variant.of(ex.recipe, g)
                okeys = {a.column: other.answers[a.ref.name] for a in ex.answers if a.ref.name in other.answers}
                got = other.values(okeys.values())
                for a in ex.answers:
                    if a.column in okeys and (not m.answer or a.ref.name == m.answer):
                        v = _element(got[okeys[a.column]], a)
                        if v is not None:
                            found[a.column].append(Alt(m.code, v, a.tol, m.en, m.zh))
            else:
                candidates_flagged.append(m)
        except (GeomconError, KeyError, ArithmeticError, ValueError, TypeError):
            continue
    # 3. the other candidate solutions
    chosen = dict(var.answers)
    for cand in var.candidates:
        if all(cand.get(n) == chosen.get(n) for n in cand if n != "_valid"):
            continue
        try:
            flags = [m for m in candidates_flagged
                     if var.values([cand[m.flag]])[cand[m.flag]] != var.values([chosen[m.flag]])[chosen[m.flag]]]
            cvals = var.values([cand[a.ref.name] for a in ex.answers if a.ref.name in cand])
        except (GeomconError, KeyError):
            continue
        m = flags[0] if flags else None
        for a in ex.answers:
            if a.ref.name in cand:
                v = _element(cvals[cand[a.ref.name]], a)
                if v is not None:
                    found[a.column].append(Alt(m.code, v, a.tol, m.en, m.zh) if m else
                                           Alt("other_branch", v, a.tol, "another solution of the construction",
                                               "作图的另一组解"))
    # 4. every branch rule flipped
    for k in var.branched(keys):
        try:
            got = var.values(keys, flip=k)
        except (GeomconError, ArithmeticError, ValueError):
            continue
        en, zh = var.caption(k)
        add("other_branch", got, f"the other intersection taken at step '{k}' ({en})", f"第 '{k}' 步取了另一个交点({zh})")
    # 5. the shared transforms
    for a in ex.answers:
        found[a.column] += _shared(ex, a)
    uses = {}
    for j, b in enumerate(ex.answers):
        if b.column in steps and b.ref.index is None:
            need = set(var.closure([steps[b.column]]))
            uses[b.column] = tuple(a.column for a in ex.answers[:j]
                                   if a.column in steps and a.ref.index is None and a.unit != "point"
                                   and steps[a.column] != steps[b.column] and steps[a.column] in need)
    return Prepared(ex, {a.column: tuple(_keep(a, found[a.column])) for a in ex.answers}, uses, var, steps)


def _keep(a: Answer, alts: list[Alt]) -> list[Alt]:
    """Drop alternatives a drawing cannot tell from the right value, and repeats of an earlier value."""
    out: list[Alt] = []
    for alt in alts:
        if not _finite(alt.value) or distance(alt.value, a.expected) <= a.tol:
            continue
        if any(distance(alt.value, o.value) <= 1e-9 * max(1.0, abs(a.tol)) and o.code == alt.code for o in out):
            continue
        out.append(alt)
    return out


def _finite(v: Any) -> bool:
    return all(math.isfinite(x) for x in v) if isinstance(v, tuple) else math.isfinite(v)


def match(alts: tuple[Alt, ...], value: Any) -> Alt | None:
    """The alternative ``value`` matches best (the nearest, in its tolerances; the earlier on a tie), or None."""
    best, best_r = None, math.inf
    for alt in alts:
        d = distance(value, alt.value)
        if d <= alt.tol:
            r = d / alt.tol if alt.tol > 0 else 0.0
            if r < best_r:
                best, best_r = alt, r
    return best


def significant(text: str) -> int:
    """How many significant digits a number as written has (an integer's trailing zeros do not count).

    >>> significant("30"), significant("0.0450"), significant("1.3e2"), significant("-23.15")
    (1, 3, 2, 4)
    """
    mant = text.lstrip("+-").split("e")[0].split("E")[0]
    digits = mant.replace(".", "").lstrip("0")
    if "." not in mant:
        digits = digits.rstrip("0")
    return max(len(digits), 1)


def rounding(text: str, value: float, expected: float) -> bool:
    """Whether ``value`` (written as ``text``) is ``expected`` rounded to the significant digits ``text``
    has — right, but to fewer digits than the tolerance needs (the caller has found it outside tolerance).

    >>> rounding("1.3", 1.3, 1.30498), rounding("30", 30.0, 31.736), rounding("40", 40.0, 31.736)
    (True, True, False)
    """
    s = significant(text)
    if s >= 15 or expected == 0 or not math.isfinite(value):
        return False
    r = float(f"{expected:.{s}g}")
    return abs(value - r) <= 1e-9 * max(abs(r), 1e-300)


__all__ = ["Alt", "Prepared", "SCALES", "SHARED", "WORDS", "distance", "match", "prepare", "rounding", "significant"]
