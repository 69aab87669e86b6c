"""What ``geomcon bench`` measures: time, peak memory and error of each method on each benchmarked problem.

(a) The construction (the recipe's scene built and evaluated for its answers) against the crank sweep at N
samples, both checked against the analytic twin. (b) A fresh solve asked for its answers only
(``Solution.to_json``) against one asked for the full drawing as well (``to_json`` + ``svg``).

Timings are the best of ``repeat`` runs with the garbage collector off (as :mod:`timeit` does); peak
memory is a separate run under :mod:`tracemalloc`, which slows the code it traces.

Examples
--------
>>> best_time(lambda: sum(range(100)), repeat=3)[1]
4950
>>> relative_error(12.5, 12.5055860934) < 5e-4
True
"""
from __future__ import annotations

import gc
import math
import tracemalloc
from dataclasses import dataclass
from functools import partial
from typing import Any, Callable, Mapping, TypeVar

from ..problems import problem_from_dict, validate_given
from ..recipes import get_recipe
from ..solve import solve
from ..taped import construct_taped
from .clock import clock
from .sweep import SWEEPS

T = TypeVar("T")


@dataclass(frozen=True)
class Case:
    """One benchmarked problem: a recipe, its givens and the answers both methods find.

    Parameters
    ----------
    recipe : str
        Recipe name, e.g. ``"crank_rocker.extremes"``.
    label : str
        Short label for the table and the plot's legend.
    given : dict
        The givens (normalised by the recipe when used).
    quantities : tuple of str
        The answers compared: θ and ψ, or θ and H.
    """

    recipe: str
    label: str
    given: Mapping[str, Any]
    quantities: tuple[str, ...]

    def givens(self) -> dict[str, Any]:
        """The givens normalised as a problem file's would be (floats, defaults filled in)."""
        return validate_given(get_recipe(self.recipe), self.given)


CASES: tuple[Case, ...] = (
    Case("crank_rocker.extremes", "crank-rocker 50/70/80/90", {"AB": 50, "BC": 70, "CD": 80, "AD": 90},
         ("theta", "psi")),
    Case("crank_slider.extremes", "crank-slider 120/250/60", {"AB": 120, "BC": 250, "e": 60}, ("theta", "H")),
    Case("guide_bar.extremes", "guide-bar 145/290", {"AB": 145, "AC": 290}, ("theta", "psi")),
)


@dataclass(frozen=True)
class Config:
    """How much to measure: the sweep sizes and the number of timed repetitions of each run."""

    sizes: tuple[int, ...]
    repeat: int
    repeat_drawing: int


FULL = Config(sizes=(360, 3_600, 36_000, 360_000, 1_000_000), repeat=7, repeat_drawing=5)
QUICK = Config(sizes=(360, 3_600, 36_000), repeat=2, repeat_drawing=1)


@dataclass(frozen=True)
class ErrorRow:
    """One method on one problem: time, peak memory and error against the twin.

    ``n`` is the number of crank positions of a sweep, None for the construction; ``errors`` maps each
    compared answer to its absolute error (degrees or mm); ``rel_error`` is the largest relative error.
    """

    case: Case
    method: str
    n: int | None
    seconds: float
    peak_bytes: int
    values: Mapping[str, float]
    errors: Mapping[str, float]
    rel_error: float


@dataclass(frozen=True)
class DrawRow:
    """A fresh solve asked for answers only, or for answers and drawing: time and steps evaluated.

    ``seconds`` and ``steps_evaluated`` are None when the output could not be produced (``note`` says why).
    """

    case: Case
    output: str
    seconds: float | None
    steps_evaluated: int | None
    steps_total: int
    note: str = ""


def best_time(fn: Callable[[], T], repeat: int) -> tuple[float, T]:
    """The shortest wall time (s) of ``repeat`` calls of ``fn``, and the last call's result."""
    best, result = math.inf, None
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(max(1, repeat)):
            t0 = clock()
            result = fn()
            best = min(best, clock() - t0)
    finally:
        if was_enabled:
            gc.enable()
    return best, result  # type: ignore[return-value]


def peak_memory(fn: Callable[[], Any]) -> int:
    """Peak bytes allocated (per :mod:`tracemalloc`, numpy included) during one call of ``fn``."""
    started = not tracemalloc.is_tracing()
    if started:
        tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        fn()
        return max(0, tracemalloc.get_traced_memory()[1] - base)
    finally:
        if started:
            tracemalloc.stop()


def relative_error(value: float, exact: float) -> float:
    """|value − exact| / |exact| (the absolute error when exact is 0)."""
    err = abs(value - exact)
    return err / abs(exact) if exact != 0 else err


def _row(case: Case, method: str, n: int | None, seconds: float, peak: int, values: Mapping[str, float],
         exact: Mapping[str, float]) -> ErrorRow:
    errors = {q: abs(values[q] - exact[q]) for q in case.quantities}
    rel = max(relative_error(values[q], exact[q]) for q in case.quantities)
    return ErrorRow(case, method, n, seconds, peak, {q: values[q] for q in case.quantities}, errors, rel)


def construct_answers(recipe: str, given: Mapping[str, Any]) -> dict[str, float]:
    """Build the recipe's scene and evaluate it for its answers (what the construction method times), lean,
    following the recipe's evaluation plan and replayed from its tape when it has one, as a solve does."""
    r = get_recipe(recipe)
    con = construct_taped(r, given)
    vals = con.scene.evaluate(con.answers.values())
    return {name: float(vals[key]) for name, key in con.answers.items()}


def measure_case(case: Case, config: Config) -> list[ErrorRow]:
    """The construction row and one sweep row per size of ``config`` for one problem."""
    given = case.givens()
    exact = get_recipe(case.recipe).analytic(given)[0]
    build = partial(construct_answers, case.recipe, given)
    seconds, values = best_time(build, max(config.repeat, 5))  # cheap: a few more runs steady the minimum
    rows = [_row(case, "construction", None, seconds, peak_memory(build), values, exact)]
    sweep = SWEEPS[case.recipe]
    for n in config.sizes:
        run = partial(sweep, given, n)
        seconds, values = best_time(run, config.repeat)
        rows.append(_row(case, "sweep", n, seconds, peak_memory(run), values, exact))
    return rows


def measure_extremes(config: Config, cases: tuple[Case, ...] = CASES) -> list[ErrorRow]:
    """Part (a): time, memory and error of the construction and of every sweep, for every case."""
    return [row for case in cases for row in measure_case(case, config)]


def _solve_fresh(case: Case, *, drawing: bool) -> dict[str, int]:
    sol = solve(problem_from_dict({"recipe": case.recipe, "given": dict(case.given)}, name="bench"))
    sol.to_json()
    if drawing:
        sol.svg()
    return dict(sol.stats)


def measure_drawing(config: Config, cases: tuple[Case, ...] = CASES) -> list[DrawRow]:
    """Part (b): a fresh solve for answers only vs with the full SVG: best time and steps evaluated."""
    rows = []
    for case in cases:
        for output, drawing in (("answers (to_json)", False), ("answers + svg", True)):
            try:
                seconds, stats = best_time(partial(_solve_fresh, case, drawing=drawing), config.repeat_drawing)
            except ImportError:  # the renderer is not installed (yet)
                total = _solve_fresh(case, drawing=False)["steps_total"]
                rows.append(DrawRow(case, output, None, None, total, "renderer not available (ImportError)"))
                continue
            rows.append(DrawRow(case, output, seconds, stats["steps_evaluated"], stats["steps_total"]))
    return rows
