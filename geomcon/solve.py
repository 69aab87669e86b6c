"""Solving a problem: build the recipe's construction, read the answers lazily, check them against the
analytic twin, audit the published answers, and produce JSON or drawings on demand.

Only what is asked for is computed: :meth:`Solution.to_json` evaluates the answer and point steps (and
their dependencies) and no annotation; the drawing methods evaluate the rest.

Examples
--------
>>> from geomcon.problems import problem_from_dict
>>> s = solve(problem_from_dict({"recipe": "guide_bar.extremes", "given": {"AB": 145, "AC": 290},
...                              "published": {"theta": 60.5}}, name="demo"))
>>> round(s.answers["theta"], 9), s.checks[0]["ok"]
(60.0, True)
>>> s.published[0]["deviation"]
0.5
>>> s.stats["steps_evaluated"] < s.stats["steps_total"]
True
"""
from __future__ import annotations

import math
from .cached import cached_property
from typing import Any, Sequence

from .check import PUBLISHED_WARN_REL, audit_row, check_row, error_text, rounded, scale_for
from .condition import KAPPA_REFUSE, STEP, derivative, sensitivities, solution_count_stable
from .errors import NotAMechanism, ProblemError
from .tolerance import CHECK_REL
from .problems import Problem
from .recipes import Construction, Recipe, get_recipe
from .recipes.base import unit_in
from .plan import planned
from .taped import construct_taped, is_taped


def _value(unit: str, v: Any) -> Any:
    """An answer step's value in the contract's type: bool, a tuple of floats (list units) or a float."""
    if unit == "bool":
        return bool(v)
    if unit == "choice":
        return str(v)
    if unit.endswith("[]"):
        return tuple(tuple(float(y) for y in x) if isinstance(x, (tuple, list)) else float(x) for x in v)
    return float(v)


def _json(v: Any, scale: float) -> Any:
    """An answer value for JSON: numbers :func:`~geomcon.check.rounded` at ``scale``, lists element by
    element, bools and words (a choice) as they are."""
    if isinstance(v, (bool, str)):
        return v
    if isinstance(v, (tuple, list)):
        return [_json(x, scale) for x in v]
    return rounded(v, scale)


def _finite(v: Any) -> Any:
    """A number for standard JSON: NaN and ±inf (a failed check's twin value, say) become null.

    Examples
    --------
    >>> _finite(1.5), _finite(float("nan")), _finite([1.0, float("inf")]), _finite(True)
    (1.5, None, [1.0, None], True)
    """
    if isinstance(v, list):
        return [_finite(x) for x in v]
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


_UNITS: dict[str, dict[str, str]] = {}


def _answer_units(recipe: Recipe) -> dict[str, str]:
    """``{answer name: unit}`` in the recipe's declared order (made once per recipe)."""
    units = _UNITS.get(recipe.name)
    if units is None:
        units = _UNITS[recipe.name] = {q.name: q.unit for q in recipe.answers}
    return units


Table = tuple[tuple[str, ...], tuple[tuple[str | None, tuple[tuple[str, str, str], ...], tuple[tuple[str, str], ...]], ...]]
_TABLES: dict[int, tuple[Any, Table]] = {}
"""Answer tables of taped constructions, by the identity of their solution maps (a replay hands every solve
of one tape the same maps), each held with its maps so that the identity stays theirs."""
_TABLES_MAX = 1024


_PAIRS: dict[str, tuple[tuple[str, str], ...]] = {}


def _answer_pairs(recipe: Recipe) -> tuple[tuple[str, str], ...]:
    """``(name, unit)`` of each declared answer, in order (made once per recipe)."""
    pairs = _PAIRS.get(recipe.name)
    if pairs is None:
        pairs = _PAIRS[recipe.name] = tuple((q.name, q.unit) for q in recipe.answers)
    return pairs


_LENGTHS: dict[str, tuple[tuple[str, bool], ...]] = {}


def _length_givens(recipe: Recipe) -> tuple[tuple[str, bool], ...]:
    """``(name, True)`` of each given length in mm, ``(name, False)`` of each point or list of lengths, in the
    recipe's order (made once per recipe; a given whose unit depends on the others, :func:`_length_given_units`,
    is left out)."""
    out = _LENGTHS.get(recipe.name)
    if out is None:
        out = _LENGTHS[recipe.name] = tuple((q.name, q.unit == "mm") for q in recipe.givens
                                            if q.unit in ("mm", "point", "mm[]") and not q.unit_when)
    return out


def _length_given_units(recipe: Recipe) -> tuple:
    """The givens in mm whose unit depends on another given (cam.base_radius's h: degrees for an arm)."""
    return tuple(q for q in recipe.givens if q.unit == "mm" and q.unit_when)


_UNIT_SETS: dict[str, tuple[str, ...]] = {}


def _answer_unit_set(recipe: Recipe) -> tuple[str, ...]:
    """The distinct units of the recipe's answers (made once per recipe)."""
    units = _UNIT_SETS.get(recipe.name)
    if units is None:
        units = _UNIT_SETS[recipe.name] = tuple(dict.fromkeys(q.unit for q in recipe.answers))
    return units


def answer_table(units: dict[str, str], maps: tuple) -> Table:
    """How a construction's solution maps read: every step key they name (in order), and per map its
    ``_valid`` step (or None), its answers ``(name, step key, unit)`` in the recipe's declared order and any
    further named steps ``(name, step key)``.

    Examples
    --------
    >>> keys, rows = answer_table({"theta": "deg", "ok": "bool"}, ({"ok": "s2", "theta": "s1", "_valid": "v"},))
    >>> keys, rows
    (('s2', 's1', 'v'), (('v', (('theta', 's1', 'deg'), ('ok', 's2', 'bool')), ()),))
    """
    keys = tuple(k for m in maps for k in m.values())
    rows = tuple((m.get("_valid"),
                  tuple((name, m[name], unit) for name, unit in units.items() if m.get(name) is not None),
                  tuple((n, k) for n, k in m.items() if n not in units and n != "_valid")) for m in maps)
    return keys, rows


def taped_table(recipe: Recipe, solutions: tuple, answers: Any) -> Table:
    """:func:`answer_table` of a tape's solution maps, made once per tape (a replay hands every solve of one
    tape the same maps: the table is kept by their identity, with them)."""
    ident = solutions or answers
    entry = _TABLES.get(id(ident))
    if entry is None or entry[0] is not ident:
        if len(_TABLES) >= _TABLES_MAX:
            _TABLES.clear()
        entry = _TABLES[id(ident)] = (ident, answer_table(_answer_units(recipe), solutions or (answers,)))
    return entry[1]


def read_candidates(recipe: Recipe, rows: tuple, vals: dict[str, Any]) -> list[tuple[int, dict[str, Any]]]:
    """(candidate index, answers) of every candidate whose ``_valid`` step holds, from the step values
    ``vals`` read through an :func:`answer_table`'s rows, in the recipe's order of preference.

    >>> from geomcon.recipes import get_recipe
    >>> r = get_recipe("guide_bar.extremes")
    >>> read_candidates(r, answer_table({"theta": "deg"}, ({"theta": "t"},))[1], {"t": 60.0})
    [(0, {'theta': 60.0})]
    """
    out = []
    for index, (valid, named, extra) in enumerate(rows):
        if valid is not None and not vals[valid]:
            continue
        sol = {}
        for name, key, unit in named:
            v = vals[key]
            sol[name] = v if type(v) is float and unit != "bool" else _value(unit, v)
        for name, key in extra:
            sol[name] = _value("", vals[key])
        out.append((index, sol))
    if recipe.order is not None:
        order = recipe.order
        out.sort(key=lambda pair: order(pair[1]))
    return out


def _pairs(name: str, a: Any, b: Any) -> list[tuple[str, Any, Any]]:
    """Matching scalar parts of two answer values: ``("s[0]", a[0], b[0])``… for lists;
    bools compare as the numbers 1 and 0.

    Examples
    --------
    >>> _pairs("s", (1.0, 2.0), (1.0, 2.5))
    [('s[0]', 1.0, 1.0), ('s[1]', 2.0, 2.5)]
    """
    if isinstance(a, (tuple, list)):
        if not isinstance(b, (tuple, list)) or len(a) != len(b):
            raise NotAMechanism(f"answer {name}: {len(a)} values against {b!r}")
        return [p for i, (x, y) in enumerate(zip(a, b)) for p in _pairs(f"{name}[{i}]", x, y)]
    return [(name, a, b)]


def _cost(b: dict, e: dict, scales: dict[str, float], sol: Solution, bound: float = math.inf) -> float:
    """The worst relative difference of the answers ``b`` and ``e``, each at its unit's scale (``scales`` by
    answer name; a named step beyond the declared answers at ``sol.unit_scale("")``); any value above ``bound``
    once it exceeds it (:attr:`Solution.matching`). ``max`` is written as comparisons, as it makes them (the
    first of equal values kept, a NaN never taken after the first): the same floats without its calls.

    >>> _cost({"a": 1.0, "b": 2.0}, {"a": 1.5, "b": 2.0}, {"a": 1.0, "b": 1.0}, None)
    0.3333333333333333
    """
    worst = 0.0
    for k, x in b.items():
        y = e.get(k)
        if y is None:
            continue
        scale = scales.get(k)
        if scale is None:                                  # a named step beyond the declared answers
            scale = sol.unit_scale("")
        if type(x) is float and type(y) is float:          # the common case, at once
            m = abs(x)
            t = abs(y)
            if t > m:
                m = t
            if scale > m:
                m = scale
            t = abs(x - y) / m
            if t > worst:
                worst = t
        else:
            for _, p, q in _pairs(k, x, y):
                p, q = float(p), float(q)
                worst = max(worst, abs(p - q) / max(abs(p), abs(q), scale))
        if worst > bound:
            return worst
    return worst


FloatRows = tuple[list[dict[str, Any]], list[str], float, int]


def _float_rows(built: dict, exact: dict, pairs: tuple[tuple[str, str], ...], scales: dict[str, float],
                prefix: str) -> FloatRows | None:
    """The check rows of one solution against one twin solution when every answer both give is a number
    (:func:`~geomcon.check.check_row`'s rows, their arithmetic in place, not yet judged at the problem's
    condition), the answer name of each, the worst relative difference :func:`_cost` finds over the same
    answers (``err / max(|b|, |e|, scale)``: the quantities a row computes) and how many of ``built``'s answers
    are declared ones; None when an answer is not a float or both ends are infinite (the general rows handle
    those). ``scales`` by unit. The worst equals ``_cost(built, exact, …)`` when ``built`` holds only declared
    answers (the count is ``len(built)``: :meth:`Solution.matching` checks it): both skip a NaN and keep the
    largest of the rest, whatever the order.

    >>> rows, names, worst, declared = _float_rows({"a": 1.0}, {"a": 1.5}, (("a", "mm"), ("b", "mm")), {"mm": 1.0}, "")
    >>> rows[0]["ok"], names, worst, declared
    (False, ['a'], 0.3333333333333333, 1)
    """
    rows = []
    names = []
    worst = 0.0
    declared = 0
    inf = math.inf
    for name, unit in pairs:
        b = built.get(name)
        if b is None:
            continue
        declared += 1
        e = exact.get(name)
        if e is None:
            continue
        if type(b) is not float or type(e) is not float or b == e == inf:
            return None
        # max(|b|, |e|, scale) as the comparisons max makes; err < inf and err <= tol is isfinite(err) and
        # err <= tol (a NaN fails both comparisons)
        err = abs(b - e)
        m = abs(b)
        t = abs(e)
        if t > m:
            m = t
        t = scales[unit]
        if t > m:
            m = t
        t = err / m
        if t > worst:
            worst = t
        tol = CHECK_REL * m
        rows.append({"quantity": prefix + name, "construction": b, "analytic": e, "abs_error": err, "tol": tol,
                     "ok": err < inf and err <= tol, "unit": unit})
        names.append(name)
    return rows, names, worst, declared


class Solution:
    """The solved problem; every property computes only what it needs, once."""

    def __init__(self, problem: Problem, recipe: Recipe, construction: Construction, warnings: list[str]) -> None:
        self.problem = problem
        self.recipe = recipe
        self.construction = construction
        self.scene = construction.scene
        self._validation = list(warnings)
        self._built = list(construction.warnings)
        self._taped = is_taped(self.scene)      # replayed: its refusal text holds the recording's numbers

        if not self._taped:                     # a replay can complete itself already (construct_taped)
            given = problem.given
            self.scene.rebuild_with(lambda: recipe.construct(given).scene)   # a skipped step completes the scene

    def evaluate(self, keys) -> dict[str, Any]:
        """Values of the scene's steps ``keys``."""
        return self.scene.evaluate(keys)

    @cached_property
    def length_scale(self) -> float:
        """The largest given length or coordinate: the scale of relative comparisons of lengths."""
        sizes = [1e-300]
        given = self.problem.given
        for name, single in _length_givens(self.recipe):
            v = given.get(name)
            if v is None:
                continue
            if single:
                sizes.append(abs(v))
            else:
                sizes += [abs(x) for x in v]
        for q in _length_given_units(self.recipe):      # a length only when the other givens say mm
            v = given.get(q.name)
            if v is not None and unit_in(q, given) == "mm":
                sizes.append(abs(v))
        return max(sizes)

    @cached_property
    def _unbounded(self) -> frozenset[str]:
        """Answers (intervals) whose ends may be infinite: an unbounded range, written null in JSON."""
        return frozenset(q.name for q in self.recipe.answers if q.unit == "interval[]")

    @cached_property
    def solution_values(self) -> list[dict[str, float]]:
        """Every valid solution's answers, the textbook's choice first.

        A solution map may name a ``_valid`` step (a candidate of a multi-solution construction); candidates
        whose ``_valid`` is false are left out.
        """
        return [sol for _, sol in self._valid_candidates]

    @cached_property
    def _valid_candidates(self) -> list[tuple[int, dict[str, float]]]:
        """(candidate index in the construction's ``solutions``, answers) of every valid solution, in the
        order of :attr:`solution_values`."""
        c = self.construction
        if self._taped:                                   # the same maps on every replay of one tape
            keys, rows = taped_table(self.recipe, c.solutions, c.answers)
        else:
            keys, rows = answer_table(_answer_units(self.recipe), c.solutions or (c.answers,))
        out = read_candidates(self.recipe, rows, self.scene.evaluate(keys))
        if not out:
            why = self.construction.no_solution
            if self._taped:
                why = planned(self.recipe.name, self.recipe.construct, self.problem.given).no_solution
            raise NotAMechanism(why or "no candidate of the construction is a valid mechanism")
        for _, sol in out:
            for k, v in sol.items():
                if type(v) is float and v - v == 0.0 or type(v) is str:      # finite (the common case) or a word
                    continue
                flat = [x for x in (v if isinstance(v, tuple) else (v,)) for x in (x if isinstance(x, tuple) else (x,))]
                bad = [x for x in flat if not math.isfinite(x) and not (x == math.inf and k in self._unbounded)]
                if bad:
                    raise NotAMechanism(f"answer '{k}' is not a finite number ({bad[0]!r}): the givens are outside "
                                        "the range where the construction holds in double precision")
        return out

    @property
    def answers(self) -> dict[str, float]:
        """The answers of the textbook's choice of solution."""
        return self.solution_values[0]

    @cached_property
    def points(self) -> dict[str, tuple[float, float]]:
        """The named points of the chosen solution."""
        vals = self.evaluate(self.construction.points.values())
        return {name: vals[key].tuple() for name, key in self.construction.points.items()}

    @cached_property
    def analytic(self) -> list[dict[str, float]]:
        """The analytic twin's solutions."""
        return self.recipe.analytic(self.problem.given)

    def unit_scale(self, unit: str) -> float:
        """The scale of a quantity of ``unit`` (:func:`~geomcon.check.scale_for`; speeds take the given ω)."""
        scales = self._scales
        sc = scales.get(unit)
        if sc is None:
            omega = self.problem.given.get("omega")
            sc = scales[unit] = scale_for(unit.removesuffix("[]"), self.length_scale,
                                          omega if isinstance(omega, float) else 1.0)
        return sc

    @cached_property
    def _scales(self) -> dict[str, float]:
        return {}

    @cached_property
    def _unit_scales(self) -> dict[str, float]:
        """``{unit: scale}`` of the recipe's answer units (:meth:`unit_scale`)."""
        return {u: self.unit_scale(u) for u in _answer_unit_set(self.recipe)}

    @cached_property
    def matching(self) -> list[tuple[int, int]]:
        """Pairs ``(construction solution, twin solution)``: several solutions are compared as sets, each
        construction solution with the nearest twin solution (greedy on the worst relative difference)."""
        built, exact = self.solution_values, self.analytic
        if len(built) <= 1 or len(exact) <= 1:
            return [(i, i) for i in range(min(len(built), len(exact)))]
        by_unit = self._unit_scales
        units = _answer_units(self.recipe)
        scales = {k: by_unit[u] for k, u in units.items()}
        n = len(built)
        if n == len(exact):
            # the usual case: both lists in the recipe's order, each solution nearest its twin. When every other
            # pairing is worse than the worst of these, the greedy choice below takes exactly these n pairs
            # first, so the others need only be shown worse (a cost cut off once it passes that bound). The
            # diagonal's costs come with its check rows when every answer is a number (_float_rows: the same
            # differences and scales), and the rows are kept for :attr:`checks`
            pairs = _answer_pairs(self.recipe)
            shared = [_float_rows(built[i], exact[i], pairs, by_unit, f"solutions[{i}]." if i else "")
                      for i in range(n)]
            if all(r is not None and r[3] == len(built[i]) for i, r in enumerate(shared)):
                diagonal = max(r[2] for r in shared)                     # type: ignore[index]
            else:
                shared = []
                diagonal = max(_cost(built[i], exact[i], scales, self) for i in range(n))
            if all(_cost(built[i], exact[j], scales, self, diagonal) > diagonal
                   for i in range(n) for j in range(n) if i != j):
                self._diagonal_rows = shared
                return [(i, i) for i in range(n)]
        ranked = sorted((_cost(b, e, scales, self), i, j) for i, b in enumerate(built) for j, e in enumerate(exact))
        used_i: set[int] = set()
        used_j: set[int] = set()
        out = []
        for _, i, j in ranked:
            if i not in used_i and j not in used_j:
                out.append((i, j))
                used_i.add(i)
                used_j.add(j)
        return sorted(out)

    @cached_property
    def _sensitivities(self) -> list[dict[str, float]]:
        """The twin's condition sums per solution (computed only when a plain check fails)."""
        units = {q.name: q.unit for q in self.recipe.givens}
        yes_no = frozenset(q.name for q in self.recipe.answers if q.unit == "bool")
        return sensitivities(self.recipe.analytic, self.problem.given, units, self.length_scale, yes_no)

    def _conditioned(self, row: dict, j: int, flat: str, unit: str) -> dict:
        """Judge a failed answer row again at the problem's own condition (:mod:`geomcon.condition`)."""
        sens = self._sensitivities
        s = sens[j].get(flat) if j < len(sens) else None
        if s is None:
            return row
        if unit == "bool":
            return {**row, "ok": s == float("inf"), "condition": "undecidable"} if s == float("inf") else row
        magnitude = max(abs(row["analytic"]), self.unit_scale(unit))
        kappa = s / magnitude
        if kappa > KAPPA_REFUSE:
            raise NotAMechanism(f"answer '{flat}' is too ill-conditioned to check: it moves {kappa:.3g} times the "
                                f"relative change of the givens (limit {KAPPA_REFUSE:g}); the data do not determine it")
        tol = max(row["tol"], CHECK_REL * s)
        return {**row, "tol": tol, "ok": row["abs_error"] <= tol, "condition": kappa}

    def _back_conditioned(self, row: dict, name: str, i: int, given, built: dict) -> dict:
        """Judge a failed back-substitution row again at the condition of the rebuild on the solution's answers:
        ``Σ_j |∂r/∂a_j| · |a_j|`` from central differences of ``back_check``."""
        def rebuilt(answers: dict) -> float | None:
            try:
                for n, value, _, _ in planned(self.recipe.name, self.recipe.back_check, given, answers):
                    if n == name:
                        return float(value)
            except (ArithmeticError, ValueError):       # GeomconError is a ValueError: the rebuild left the domain
                return None
            return None

        total = 0.0
        for k, v in built.items():
            if isinstance(v, (bool, tuple, list)) or v == 0:
                continue
            d = derivative(lambda dv, k=k, v=v: rebuilt({**built, k: v + dv}), abs(float(v)))
            total += d or 0.0
        tol = max(row["tol"], CHECK_REL * total)
        return {**row, "tol": tol, "ok": row["abs_error"] <= tol,
                "condition": total / max(abs(row["analytic"]), 1e-300)}

    @cached_property
    def checks(self) -> list[dict[str, Any]]:
        """Construction vs analytic twin for every answer of every solution, each row judged at CHECK_REL and,
        when it fails there, at the problem's own condition."""
        rows = []
        scales = self._unit_scales
        inf = math.inf
        pairs = _answer_pairs(self.recipe)
        matching = self.matching
        shared = self.__dict__.get("_diagonal_rows")
        for i, j in matching:
            built, exact = self.solution_values[i], self.analytic[j]
            prefix = f"solutions[{i}]." if i else ""
            # every answer a number (the usual case): the rows at once, the matching's when it made them
            numbers = shared[i] if shared else _float_rows(built, exact, pairs, scales, prefix)
            if numbers is not None:
                for row, name in zip(numbers[0], numbers[1]):
                    rows.append(row if row["ok"] else self._conditioned(row, j, name, row["unit"]))
                continue
            for name, unit in pairs:
                b, e = built.get(name), exact.get(name)
                if b is None or e is None:
                    continue
                parts: Any = ([(prefix + name, b, e, name)] if type(b) is float and type(e) is float else
                              [(label, x, y, flat) for (label, x, y), (flat, _, _)
                               in zip(_pairs(prefix + name, b, e), _pairs(name, b, e))])
                scale = self.unit_scale(unit)
                for label, x, y, flat in parts:
                    if type(x) is str or type(y) is str:                 # a word (a choice): equal or not
                        rows.append({"quantity": label, "construction": x, "analytic": y, "abs_error": float(x != y),
                                     "tol": 0.0, "ok": x == y, "unit": unit})
                        continue
                    if x == y == math.inf:                               # an unbounded interval's end
                        rows.append({"quantity": label, "construction": x, "analytic": y, "abs_error": 0.0,
                                     "tol": 0.0, "ok": True, "unit": unit})
                        continue
                    row = check_row(label, x, y, scale, unit)
                    if not row["ok"]:
                        row = self._conditioned(row, j, flat, unit)
                    rows.append(row)
        back_check = self.recipe.back_check
        if back_check is not None:
            given = self.problem.given
            for i, built in enumerate(self.solution_values):
                prefix = f"solutions[{i}].back_substitution." if i else "back_substitution."
                for name, b, e, unit in planned(self.recipe.name, back_check, given, built):
                    if type(b) is float and type(e) is float:
                        # check_row's row, its arithmetic in place, as for the answers above
                        err = abs(b - e)
                        m = abs(b)
                        t = abs(e)
                        if t > m:
                            m = t
                        t = scales.get(unit)
                        if t is None:
                            t = self.unit_scale(unit)
                        if t > m:
                            m = t
                        tol = CHECK_REL * m
                        row = {"quantity": prefix + name, "construction": b, "analytic": e, "abs_error": err,
                               "tol": tol, "ok": err < inf and err <= tol, "unit": unit}
                    else:
                        row = check_row(prefix + name, b, e, self.unit_scale(unit), unit)
                    if not row["ok"]:
                        row = self._back_conditioned(row, name, i, given, built)
                    rows.append(row)
        if len(self.solution_values) != len(self.analytic):
            units = {q.name: q.unit for q in self.recipe.givens}
            borderline = solution_count_stable(self.recipe.analytic, self.problem.given, units,
                                               self.length_scale) is False
            rows.append({"quantity": "number of solutions", "construction": len(self.solution_values),
                         "analytic": len(self.analytic),
                         "abs_error": abs(len(self.solution_values) - len(self.analytic)), "tol": 0, "unit": "",
                         "ok": borderline, **({"condition": "undecidable"} if borderline else {})})
        return rows

    @property
    def ok(self) -> bool:
        """True when every check passes."""
        return all(r["ok"] for r in self.checks)

    @cached_property
    def published(self) -> list[dict[str, Any]]:
        """The audit of the printed answers against the exact ones."""
        units = {q.name: q.unit for q in self.recipe.answers}
        rows = []
        for k, v in self.problem.published.items():
            if k not in self.answers:
                raise ProblemError(f"published '{k}' is not an answer of this form of {self.recipe.name} "
                                   f"(its answers: {', '.join(self.answers)})")
            have = self.answers[k]
            if isinstance(have, tuple) and len(have) != len(v):
                raise ProblemError(f"published '{k}' has {len(v)} values; the answer has {len(have)}")
            rows += [audit_row(name, p, e, self.unit_scale(units[k])) for name, p, e in _pairs(k, v, have)]
        return rows

    @property
    def construction_warnings(self) -> list[str]:
        """The warnings of validation and construction alone (borderline geometry), without the checks and
        without the recipe's costly advice (:attr:`advice`)."""
        return self._validation + self._built

    @cached_property
    def advice(self) -> list[str]:
        """The recipe's warnings that cost a computation (:attr:`~geomcon.recipes.Recipe.advise`): made when
        the warnings are asked for, never for answers alone."""
        if self.recipe.advise is None:
            return []
        return planned(self.recipe.name, self.recipe.advise, self.problem.given)

    @property
    def warnings(self) -> list[str]:
        """Borderline geometry, failed checks and published answers that deviate beyond drawing accuracy."""
        return self.warnings_with(self.checks)

    def warnings_with(self, checks: Sequence[dict[str, Any]]) -> list[str]:
        """:attr:`warnings` with the check rows ``checks`` (a batch that found every check passing without
        making the rows passes none: such rows add no warning)."""
        from .render.results import fixed, percent

        out = self._validation + self.advice + self._built
        allow = self.problem.given.get("gamma_allow")
        for i, sol in enumerate(self.solution_values):
            if allow is not None and "gamma_min" in sol and sol["gamma_min"] < allow:
                which = f"solution {i + 1}: " if len(self.solution_values) > 1 else ""
                out.append(f"{which}γmin = {sol['gamma_min']:.4g}° is below gamma_allow = {allow:g}°")
        for r in checks:
            if not r["ok"]:
                out.append(f"check failed: {r['quantity']} construction {r['construction']!r} vs analytic {r['analytic']!r}")
            elif r.get("condition") == "undecidable":
                out.append(f"{r['quantity']}: construction {r['construction']!r}, analytic {r['analytic']!r} — the data "
                           f"lie on the boundary where it changes (it flips within a relative change of {STEP:g})")
            elif "condition" in r:
                out.append(f"{r['quantity']} is ill-conditioned: it moves {r['condition']:.3g} times the relative "
                           f"change of the givens; construction and twin agree to {r['abs_error']:.2g} "
                           f"(allowed {r['tol']:.2g})")
        for r in self.published:
            rel = r["rel_deviation"]
            if r["doubtful"]:
                how = percent(rel) if rel is not None else f"{r['deviation']:+g}"
                out.append(f"published {r['quantity']} = {r['published']:g} is doubtful: it deviates from the exact "
                           f"{fixed(r['exact'])} by {how}, beyond drafting accuracy (±{100 * PUBLISHED_WARN_REL:g} %)")
        return out

    @property
    def stats(self) -> dict[str, int]:
        """Steps in the scene and steps computed so far — by the solve that found the answers: the drawing of
        another valid solution (:meth:`as_solution`) reports the steps that evaluated every candidate, its own
        among them (its scene, built again to draw it, has computed only the choice when the text is printed)."""
        return self.__dict__.get("_answered_by", self).scene.stats

    def to_json(self) -> dict[str, Any]:
        """The public JSON object (angles in degrees, lengths in mm)."""
        units = {q.name: q.unit for q in self.recipe.answers}

        def answers_json(sol: dict) -> dict:
            return {k: _finite(_json(v, self.unit_scale(units.get(k, "")))) for k, v in sol.items()}

        def check_json(r: dict) -> dict:
            sc = self.unit_scale(r["unit"])
            if type(r["construction"]) is str:                 # a word (a choice): as it is
                return r
            magnitude = max(abs(float(r["construction"])), abs(float(r["analytic"])), sc)
            return {**r, "construction": _finite(_json(r["construction"], sc)),
                    "analytic": _finite(_json(r["analytic"], sc)),
                    "abs_error": _finite(error_text(r["abs_error"], magnitude)), "tol": _finite(float(f"{r['tol']:.2g}")),
                    **({"condition": _finite(float(f"{r['condition']:.2g}"))}
                       if isinstance(r.get("condition"), float) else {})}

        out = {
            "problem": self.problem.id,
            "recipe": self.recipe.name,
            "title": self.problem.title,
            **({"title_zh": self.problem.title_zh} if self.problem.title_zh else {}),
            "given": dict(self.problem.given),
            "answers": answers_json(self.answers),
            "points": {k: [rounded(x, self.length_scale), rounded(y, self.length_scale)]
                       for k, (x, y) in self.points.items()},
            "solutions": [answers_json(s) for s in self.solution_values],
            "checks": [check_json(r) for r in self.checks],
            "published": [{**r, "rel_deviation": None if r["rel_deviation"] is None else float(f"{r['rel_deviation']:.4g}")}
                          for r in self.published],
            "warnings": self.warnings,
        }
        out["stats"] = dict(self.stats)
        return out

    # ------------------------------------------------------------------ drawings (lazy imports: no SVG work
    # unless a drawing is asked for)
    def info_lines(self) -> list[str]:
        """Result lines printed under the protocol: answer, twin agreement, published deviation."""
        from .render.results import percent

        pub = {r["quantity"]: r for r in self.published}
        lines = []
        for q in self.recipe.answers:
            if q.name not in self.answers:
                continue
            unit = {"deg": "°", "mm": " mm", "mm/s": " mm/s", "mm/s²": " mm/s²", "rad/s": " rad/s",
                    "rad/s²": " rad/s²"}.get(q.unit.removesuffix("[]"), "")
            parts = _pairs(q.name, self.answers[q.name], self.answers[q.name])
            rows = [r for r in self.checks if any(r["quantity"] == name for name, _, _ in parts)]
            mark = "" if not rows else (" ✓ twin" if all(r["ok"] for r in rows) else " ✗ twin")
            shown = ", ".join(str(v).lower() if isinstance(v, (bool, str)) else f"{v:.4f}" for _, v, _ in parts)
            shown = f"[{shown}]{unit}" if len(parts) > 1 or q.unit.endswith("[]") else shown + ("" if isinstance(parts[0][1], (bool, str)) else unit)
            if q.unit == "interval[]":                              # [[low, high], …] mm
                shown = "[" + ", ".join(f"[{lo:.4f}, {hi:.4f}]" for lo, hi in self.answers[q.name]) + "] mm"
            line = f"{q.name} = {shown}{mark}"
            printed = [pub[name] for name, _, _ in parts if name in pub]
            if printed:
                rels = [p["rel_deviation"] for p in printed if p["rel_deviation"] is not None]
                worst = f", worst {percent(max(rels, key=abs))}" if rels and len(parts) > 1 else (
                    f", {percent(rels[0])}" if rels else "")
                values = ", ".join(f"{p['published']:g}" for p in printed)
                doubt = ", doubtful: beyond drafting accuracy" if any(p["doubtful"] for p in printed) else ""
                line += f"  (printed {values}{worst}{doubt})"
            lines.append(line)
        return lines

    def figure_lines(self, lang: str = "en", brief: bool = False) -> list[str]:
        """The result lines of a drawing, as a textbook prints them (:mod:`geomcon.render.results`): one per
        answer, in the order of :meth:`info_lines`, each saying what agreed with what and how the printed
        answer deviates. ``brief``: the lines sheet 1 prints when the full ones find no room there — no Chinese
        gloss after an English line (the symbols say it), a list's printed values counted, not listed
        (:func:`~geomcon.render.results.brief_printed`); the full lines stand on the results sheet."""
        from .render.results import brief_printed, percent, result_line, shown_printed

        pub = {r["quantity"]: r for r in self.published}
        zh = lang == "zh"
        lines = []
        for q in self.sheet_answers():
            parts = _pairs(q.name, self.answers[q.name], self.answers[q.name])
            rows = [r for r in self.checks if any(r["quantity"] == name for name, _, _ in parts)]
            printed = []
            for name, _, _ in parts:
                p = pub.get(name)
                if p is None:
                    continue
                rel = p["rel_deviation"]
                how = "" if rel is None else (percent(rel) if p["deviation"] else ("精确" if zh else "exact"))
                printed.append((shown_printed(p["published"], q.unit, lang), how, bool(p["doubtful"])))
            if brief:
                words = brief_printed(printed, lang) if printed else []
            else:
                sep = "，" if zh else ", "
                words = [pr + (f"{sep}{how}" if how else "") + ((sep + ("存疑" if zh else "doubtful")) if d else "")
                         for pr, how, d in printed]
            at = self.problem.given.get("at") if "`at`" in q.doc else None
            lines.append(result_line(q.name, self.answers[q.name], q.unit,
                                     twin=None if not rows else all(r["ok"] for r in rows), printed=words,
                                     lang=("zh" if zh else "en") if brief else lang, recipe=self.recipe.name,
                                     at=tuple(at or ()), given=self.problem.given))
        return lines

    def sheet_answers(self) -> list[Any]:
        """The answers (:class:`~geomcon.recipes.base.Quantity`) a figure prints, in the recipe's order: those
        computed, less what :func:`~geomcon.render.results.on_sheet` leaves off (a knife edge's ρa,min and
        undercut: its actual profile is the pitch curve) unless the textbook printed it. The JSON keeps them all."""
        from .render.results import on_sheet

        printed = {r["quantity"].split("[")[0] for r in self.published}
        name, given = self.recipe.name, self.problem.given
        return [q for q in self.recipe.answers
                if q.name in self.answers and on_sheet(q.name, name, given, q.name in printed)]

    def listed_at(self) -> dict[str, tuple[float, ...]]:
        """The cam angles ``at`` of each list answer given at them (as :meth:`figure_lines` prints it: ``ψ(2°, 4°)``),
        by answer: a warning names a list's entry the same way (``ψ(6°)``, not ``psi[2]``)."""
        at = tuple(self.problem.given.get("at") or ())
        return {q.name: at for q in self.recipe.answers if at and "`at`" in q.doc}

    def info_steps(self) -> list[int]:
        """The frame that produces each line of :meth:`figure_lines` (an answer's step, or, for a problem with
        several candidate solutions, the last of its candidates' steps: a result never shows early; an answer
        no drawn step produces — computed from the givens alone — shows with the last frame; an answer the
        drawing constructs later than its inputs are known shows with the first step drawn from it,
        :meth:`~geomcon.scene.Scene.drawn_from`: 200-07 showed α_max at step 2, its worst position at 17; an answer
        the recipe says is read off a later step shows with that step, :meth:`~geomcon.scene.Scene.read_off`:
        001-10 showed AB, BC at step 23, measured at 27 "AB = NM, BC = AM")."""
        sc = self.drawing_scene
        last = len(sc.frames())
        maps = self.construction.solutions or (self.construction.answers,)
        drawn = self.construction.answers
        out = []
        for q in self.sheet_answers():
            k = sc.available_at([m[q.name] for m in maps if q.name in m], default=last)
            later = sc.drawn_from(drawn[q.name]) if q.name in drawn else None
            read = sc.read_at(drawn[q.name]) if q.name in drawn else None
            out.append(max(x for x in (k, later, read) if x is not None))
        return out

    def title(self, lang: str = "en") -> str:
        """Title for drawings in ``lang`` (:func:`~geomcon.problems.title_in`: the problem's ``title_zh`` in
        Chinese, both titles on two lines for ``both``; the scene's title when the problem has none); a drawing
        of another valid solution says which on each line ("— solution 2 of 4", "——解 2（共 4 个）")."""
        shown = self.problem.title_in(lang) or self.scene.title
        note = getattr(self, "_title_note", None)
        if note is None:
            return shown
        return solution_note(shown, *note)

    def as_solution(self, n: int) -> Solution:
        """The problem drawn and reported as its valid solution ``n`` (1 = the textbook's choice, as listed
        by :attr:`solution_values`): the construction is built again with its choice step (``choice``: the
        index of the candidate the drawing shows) fixed to that candidate, so the figure, its frames and its
        results are those of solution ``n``.

        Raises
        ------
        ProblemError
            When ``n`` is not the number of a valid solution, or the recipe draws only one.
        """
        count = len(self.solution_values)
        if n == 1:
            return self
        if not 1 <= n <= count:
            raise ProblemError(f"--solution {n}: the problem has {count} valid solution{'s' if count != 1 else ''} "
                               f"(1 to {count})")
        scene = self.recipe.construct(self.problem.given).scene
        if "choice" not in scene:
            raise ProblemError(f"--solution {n}: recipe {self.recipe.name} draws one solution only")
        index, _ = self._valid_candidates[n - 1]
        scene.fix("choice", index)
        c = self.construction
        other = Solution(self.problem, self.recipe, Construction(scene, c.answers, c.points, c.solutions, c.warnings,
                                                                  c.no_solution), self._validation)
        cands = self._valid_candidates
        other.__dict__["_valid_candidates"] = [cands[n - 1]] + cands[:n - 1] + cands[n:]
        other._title_note = (n, count)
        other.__dict__["_answered_by"] = self
        other.solution_numbers = [n] + [i for i in range(1, count + 1) if i != n]
        return other

    @property
    def solution_numbers(self) -> list[int]:
        """The number of each of :attr:`solution_values` (1 = the textbook's choice): 1, 2, … unless this is
        the drawing of another solution (:meth:`as_solution`), which comes first."""
        return self.__dict__.get("_numbers") or list(range(1, len(self.solution_values) + 1))

    @solution_numbers.setter
    def solution_numbers(self, numbers: list[int]) -> None:
        self.__dict__["_numbers"] = list(numbers)

    @property
    def drawing_scene(self):
        """The full scene, annotations included (the answers' scene is lean: it skips what only a drawing needs,
        and is built once more in full, keeping its values, when a drawing asks for it)."""
        return self.scene.complete()

    def sheets(self, page=None, *, upto: int | None = None, viewbox=None) -> list[str]:
        """The printed sheets (:func:`geomcon.render.svg.render_sheets`): the drawing at a standard scale with
        results, warnings (in the page's language: :mod:`geomcon.render.warning_words`) and title block, then the
        construction protocol; ``page`` a
        :class:`~geomcon.render.page.PageSpec` (default A4 landscape, both languages)."""
        return self.fitted_sheets(page, upto=upto, viewbox=viewbox)[0]

    def fitted_sheets(self, page=None, *, upto: int | None = None, viewbox=None):
        """:meth:`sheets` and how sheet 1 holds the figure: its scale, whether it prints the results
        (:func:`geomcon.render.svg.fitted_sheets`)."""
        from .render.page import PageSpec
        from .render.svg import fitted_sheets
        page = page or PageSpec()
        info, warned, brief = self.sheet_lines(page.lang)
        return fitted_sheets(self.drawing_scene, upto=upto, viewbox=viewbox, title=self.title(page.lang),
                             info=info, warnings=warned, info_steps=self.info_steps(), brief=brief,
                             page=page, problem=self.problem.id + ".toml" if self.problem.path else self.problem.id,
                             recipe=self.recipe.name)

    def sheet_lines(self, lang: str = "both"):
        """What sheet 1 prints beside the drawing, in ``lang``: the result lines, the warning lines, and their
        brief forms (one line per result; ``{sheet}`` the number of the sheet with the full ones)."""
        from .render.results import brief_warnings
        from .render.warning_words import warning_lines
        at = self.listed_at()
        return (self.figure_lines(lang), warning_lines(self.warnings, lang, at),
                (self.figure_lines(lang, brief=True), brief_warnings(self.warnings, lang, "{sheet}", at)))

    def svg(self, *, upto: int | None = None, viewbox=None, page=None) -> str:
        """Sheet 1 of the drawing (frame ``upto`` when given)."""
        return self.sheets(page, upto=upto, viewbox=viewbox)[0]

    def html(self, page=None, sheets: list[str] | None = None) -> str:
        """The self-contained step player page (``sheets``: :meth:`sheets` already rendered)."""
        from .render import render_html
        from .render.page import PageSpec
        page = page or PageSpec()
        return render_html(self.drawing_scene, title=self.title(page.lang), svg=sheets or self.sheets(page), page=page)

    def frames(self, page=None, sheet: str | None = None) -> list[str]:
        """One SVG per numbered step: sheet 1 with later steps hidden and step k highlighted, exactly the step
        player's frame k (one rendering, one label placement: labels never jump between frames)."""
        from .render.svg import frame_of
        full = sheet or self.svg(page=page)
        return [frame_of(full, k) for k in range(1, len(self.drawing_scene.frames()) + 1)]


def solution_note(title: str, n: int, count: int) -> str:
    """``title`` with which of ``count`` valid solutions is shown said on each of its lines, in the line's
    language: the drawing of another solution (:meth:`Solution.title`) and the terminal's header.

    >>> solution_note("Jaw crusher\\n颚式破碎机", 2, 4)
    'Jaw crusher — solution 2 of 4\\n颚式破碎机——解 2（共 4 个）'
    """
    lines = title.split("\n")
    words = [f"——解 {n}（共 {count} 个）" if any("\u4e00" <= ch <= "\u9fff" for ch in line)
             else f" — solution {n} of {count}" for line in lines]
    return "\n".join(line + w for line, w in zip(lines, words))


def solve(problem: Problem) -> Solution:
    """Build the construction of a validated problem.

    Raises
    ------
    NotAMechanism
        When the givens describe no mechanism of the recipe's kind.
    """
    recipe = get_recipe(problem.recipe)
    warnings = planned(recipe.name, recipe.validate, problem.given) if recipe.validate else []
    return Solution(problem, recipe, construct_taped(recipe, problem.given), warnings)
