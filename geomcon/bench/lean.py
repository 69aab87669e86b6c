"""``geomcon bench``, first table: the lean core's targets (issue 10), each measured as a ratio in one run.

Every row times one thing and sets it beside a reference measured in the same run, so that the ratio, not the
machine, is what counts:

- answers only (``solve(problem).answers`` on a loaded problem) against the same construction written as a
  plain lazy DAG of float code (:mod:`.plain`);
- answers and twin checks, against the answers alone;
- cam answers (every bundled translating, oscillating and eccentric problem), against the same answers by plain scalar
  code (:mod:`.cam_plain`; the analytic twin for the flat faces it does not cover);
- ``cam.base_radius`` with checks;
- a whole ``geomcon solve`` process, against ``python -c pass``;
- the construction against the same construction in sympy.geometry, and against a crank sweep with N chosen
  for a relative error of 1e-9 in ψ or H (N from the order of convergence the sweep shows at its two largest
  sizes, its time scaled linearly from the largest N measured);
- the batch API's cost per variant, against one solve at a time.

Each row's thing and its reference are timed *interleaved* (:func:`interleaved`): round after round, each runs
``number`` times in turn, the garbage collector off while timing (as :mod:`timeit` does) and a collection between
rounds, and each keeps its shortest round. Timed one after the other, a row's two sides saw different moments of
a shared machine (a burst of another job's work, a full collection of what an earlier table left): the first
row of a run once measured 2.9× where the same code measures 1.4×. Tests check the arithmetic of the rows,
never a time.

Examples
--------
>>> r = LeanRow("answers", "x", 40e-6, "plain DAG", 30e-6, "≤ 50 µs, ≤ 1.5×", 50e-6, 1.5)
>>> round(r.ratio, 12), r.met
(1.333333333333, True)
>>> LeanRow("vs sympy", "x", 1e-4, "sympy", 2.0, "≥ 10⁴×", None, None, speedup=1e4).met
True
"""
from __future__ import annotations

import gc
import math
import os
import random
import statistics
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

from ..batch import solve_batch
from ..problems import load_problem, problem_from_dict
from ..recipes import get_recipe
from ..solve import solve
from .clock import child_seconds, clock
from .cam_plain import CAM_PLAIN, covered
from .plain import PLAIN
from .report import fmt_seconds, format_table

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
"""The bundled problems (the bench runs from a checkout)."""

LINKAGES: tuple[tuple[str, str, dict[str, Any]], ...] = (
    ("001-08", "crank_rocker.extremes", {"AB": 50, "BC": 70, "CD": 80, "AD": 90}),
    ("001-06", "crank_slider.extremes", {"AB": 120, "BC": 250, "e": 60}),
    ("001-05", "guide_bar.extremes", {"AB": 145, "AC": 290}),
    ("001-18", "crank_slider.design_by_K", {"K": 1.5, "H": 50, "e": 20}),
    ("001-10", "crank_rocker.design_by_K", {"K": 1.25, "CD": 290, "psi": 32, "BC": 260}),
)
"""The linkage and design-by-K problems timed (givens as in the bundled files)."""

CAM_RECIPES = ("cam.translating", "cam.oscillating", "cam.eccentric")
BASE_RADIUS = "200-12_oscillating_base_radius"
WHOLE = "001-08_crank_rocker"
SWEEP_TARGET = 1e-9


@dataclass(frozen=True)
class LeanRow:
    """One target: what was timed, its time, the reference and its time, the target and whether it is met.

    ``limit`` (seconds) and ``max_ratio`` bound a time and its ratio to the reference; ``speedup`` is instead a
    smallest reference/time factor (the construction against sympy or a sweep).
    """

    what: str
    case: str
    seconds: float
    reference: str
    ref_seconds: float | None
    target: str
    limit: float | None
    max_ratio: float | None
    speedup: float | None = None
    note: str = ""

    @property
    def ratio(self) -> float | None:
        """Time over the reference's time (None without a reference)."""
        return None if not self.ref_seconds else self.seconds / self.ref_seconds

    @property
    def met(self) -> bool:
        """Whether every bound of the target holds."""
        if self.speedup is not None:
            return self.ratio is not None and 1.0 / self.ratio >= self.speedup
        ok = self.limit is None or self.seconds <= self.limit
        if self.max_ratio is not None:
            ok = ok and self.ratio is not None and self.ratio <= self.max_ratio
        return ok


def interleaved(fns: Sequence[Callable[[], Any]], *, number: int, rounds: int, warm: int = 3) -> list[float]:
    """The time of one call (seconds) of each of ``fns``, timed interleaved: after ``warm`` calls of each
    (imports, the recipe's evaluation plan, its tape), ``rounds`` rounds in which each function runs ``number``
    times in turn; each keeps its shortest round (divided by ``number``). The garbage collector is off while
    timing, as :mod:`timeit` has it, and collects between rounds, so that no round pays for what an earlier one
    (or an earlier table) left behind.

    >>> a, b = interleaved([lambda: sum(range(50)), lambda: sum(range(5000))], number=20, rounds=3)
    >>> 0 < a < b
    True
    """
    for fn in fns:
        for _ in range(warm):
            fn()
    best = [math.inf] * len(fns)
    was_enabled = gc.isenabled()
    try:
        for _ in range(rounds):
            gc.collect()
            gc.disable()
            for i, fn in enumerate(fns):
                t0 = clock()
                for _ in range(number):
                    fn()
                best[i] = min(best[i], (clock() - t0) / number)
            if was_enabled:
                gc.enable()
    finally:
        if was_enabled:
            gc.enable()
    return best


def median_time(fn: Callable[[], Any], *, number: int, repeat: int) -> float:
    """The median over ``repeat`` runs of the mean time of ``number`` calls of ``fn`` (seconds): for the cam
    rows, whose single calls take milliseconds."""
    for _ in range(3):                            # warm: imports, the recipe's evaluation plan, its tape
        fn()
    runs = []
    for _ in range(repeat):
        t0 = clock()
        for _ in range(number):
            fn()
        runs.append((clock() - t0) / number)
    return statistics.median(runs)


def _problem(recipe: str, given: Mapping[str, Any]):
    return problem_from_dict({"recipe": recipe, "given": dict(given)}, name="bench")


def linkage_rows(quick: bool) -> list[LeanRow]:
    """Answers only against the plain DAG (where written), and answers with checks, per linkage problem: the
    three timed interleaved (:func:`interleaved`)."""
    number, rounds = (100, 5) if quick else (200, 25)
    rows = []
    for pid, recipe, given in LINKAGES:
        p = _problem(recipe, given)
        plain = PLAIN.get(recipe)
        g = p.given
        fns = [lambda: solve(p).answers, lambda: solve(p).checks] + ([lambda: plain(g)] if plain else [])
        t, tc, *ref = interleaved(fns, number=number, rounds=rounds)
        if ref:
            rows.append(LeanRow("answers only", f"{pid} {recipe}", t, "plain DAG", ref[0], "≤ 50 µs, ≤ 1.5×", 50e-6,
                                1.5))
        else:
            rows.append(LeanRow("answers only", f"{pid} {recipe}", t, "—", None, "≤ 50 µs", 50e-6, None,
                                note="no plain replica"))
        rows.append(LeanRow("answers + twin checks", f"{pid} {recipe}", tc, "answers only", t, "≤ 100 µs",
                            100e-6, None))
    return rows


def _cam_problems() -> list[Path]:
    """The bundled cam.translating, cam.oscillating and cam.eccentric problems (every one: the target is for
    each; issue 10 names the first two, the eccentric cams are held to the same bound)."""
    return [path for path in sorted(PROBLEMS.glob("*.toml")) if load_problem(path).recipe in CAM_RECIPES]


def cam_rows(quick: bool) -> list[LeanRow]:
    """Cam answers of every bundled translating, oscillating and eccentric problem against the scalar reference
    (:mod:`.cam_plain`; the analytic twin for a flat face and for the eccentric cams, which it does not cover);
    the base-radius design with its checks."""
    rows = []
    n, repeat = (1, 3) if quick else (3, 5)
    for path in _cam_problems():
        p = load_problem(path)
        t = median_time(lambda: solve(p).answers, number=n, repeat=repeat)
        if covered(p.recipe, p.given):
            ref_fn, ref = CAM_PLAIN[p.recipe], "scalar reference"
        else:
            ref_fn, ref = get_recipe(p.recipe).analytic, "its analytic twin"
        g = p.given
        tr = median_time(lambda: ref_fn(g), number=n, repeat=repeat)
        sense = " cw" if g.get("rotation") == "cw" else ""          # 001-29 is bundled turning both ways
        case = f"{path.stem.split('_')[0]} {p.recipe}{sense} {g.get('follower', '')}".strip()
        rows.append(LeanRow("cam answers only", case,
                            t, ref, tr, "≤ 2 ms", 2e-3, None))
    path = PROBLEMS / f"{BASE_RADIUS}.toml"
    if path.exists():
        p = load_problem(path)
        t = median_time(lambda: solve(p).checks, number=1, repeat=1 if quick else 3)
        rows.append(LeanRow("base radius + checks", f"{BASE_RADIUS[:6]} {p.recipe}", t, "—", None, "≤ 50 ms",
                            50e-3, None))
    return rows


def process_rows(quick: bool) -> list[LeanRow]:
    """A whole ``geomcon solve`` process against ``python -c pass``."""
    path = PROBLEMS / f"{WHOLE}.toml"
    if not path.exists():
        return []
    repeat = 3 if quick else 9
    # as installed: pip byte-compiles a package when it installs it, so a process reads cached byte-code; a shell
    # with PYTHONDONTWRITEBYTECODE (some tools set it) would compile every module on every start instead
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}

    argvs = ([sys.executable, "-c", "pass"], [sys.executable, "-m", "geomcon", "solve", str(path)])
    for argv in argvs:
        child_seconds(argv, env)                                 # writes the byte-code caches if missing
    runs: tuple[list[float], list[float]] = ([], [])
    for _ in range(repeat):                                      # interleaved, as the in-process rows
        for argv, out in zip(argvs, runs):
            out.append(child_seconds(argv, env))
    base, t = (statistics.median(r) for r in runs)
    return [LeanRow("whole process", f"geomcon solve {WHOLE[:6]}", t, "python -c pass", base, "≤ 120 ms", 0.120, None,
                    note="byte-code cached, as installed")]


def sympy_rows(exact_rows: Sequence[Any] | None) -> list[LeanRow]:
    """The construction against the same θ-circle design in sympy.geometry (the bench's part (c) rows)."""
    if not exact_rows:
        return []
    out = []
    by_given: dict[str, dict[str, float]] = {}
    for r in exact_rows:
        by_given.setdefault(", ".join(f"{k}={v:g}" for k, v in r.given.items()), {})[r.method] = r.seconds
    for label, t in by_given.items():
        if "geomcon" in t and "sympy.geometry" in t:
            out.append(LeanRow("vs sympy.geometry", f"design by K {label}", t["geomcon"], "sympy.geometry",
                               t["sympy.geometry"], "≥ 10⁴×", None, None, speedup=1e4))
    return out


def sweep_n_for(rows: Sequence[Any], quantity: str, target: float = SWEEP_TARGET) -> tuple[float, float, float] | None:
    """The sweep size N at which ``quantity``'s relative error reaches ``target``, that sweep's time (s) and the
    order p of convergence used, from part (a)'s sweep rows of one problem. When a measured N reaches the target,
    N is interpolated between it and the size before with the error fitted as C/N^p through both; otherwise the
    fit goes through the two largest sizes and N is extrapolated (p = 2 when the fit is not a convergence: one
    size, or errors at the sweep's rounding floor). The time is scaled linearly in N from the nearest measured
    size. None without a usable row.

    >>> class R:   # a sweep row: n, seconds, values, errors
    ...     def __init__(self, n, s, e): self.n, self.seconds, self.values, self.errors = n, s, {"psi": 1.0}, {"psi": e}
    >>> [round(x, 6) for x in sweep_n_for([R(100, 1e-4, 1e-5), R(1000, 1e-3, 1e-7)], "psi")]   # extrapolated
    [10000.0, 0.01, 2.0]
    >>> [round(x, 6) for x in sweep_n_for([R(100, 1e-4, 1e-6), R(1000, 1e-3, 1e-10)], "psi")]  # interpolated
    [562.341325, 0.000562, 4.0]
    """
    usable = sorted((r for r in rows if r.n and abs(r.values[quantity]) > 0), key=lambda x: x.n)
    if not usable:
        return None

    def rel(r: Any) -> float:
        return r.errors[quantity] / abs(r.values[quantity])

    def order(a: Any, b: Any) -> float:
        if rel(b) > 0 and rel(a) > rel(b):
            p = math.log(rel(a) / rel(b)) / math.log(b.n / a.n)
            if p >= 0.5:
                return p
        return 2.0

    reached = [i for i, r in enumerate(usable) if rel(r) <= target]
    if reached:
        i = reached[0]
        if i == 0:
            return float(usable[0].n), usable[0].seconds, 2.0
        a, b = usable[i - 1], usable[i]
        p = order(a, b)
        n_star = a.n * (rel(a) / target) ** (1.0 / p)
        return n_star, b.seconds * n_star / b.n, p
    fit = [r for r in usable if rel(r) > 1e-13]
    if not fit:
        return None
    last = fit[-1]
    p = order(fit[-2], last) if len(fit) >= 2 else 2.0
    n_star = last.n * (rel(last) / target) ** (1.0 / p)
    return n_star, usable[-1].seconds * n_star / usable[-1].n, p


def sweep_rows(extremes: Sequence[Any]) -> list[LeanRow]:
    """The construction against the sweep that reaches the same 1e-9 relative error in ψ or H."""
    out = []
    cases = {r.case.label: r.case for r in extremes}
    for label, case in cases.items():
        mine = [r for r in extremes if r.case.label == label]
        built = next(r for r in mine if r.n is None)
        q = case.quantities[1]
        found = sweep_n_for([r for r in mine if r.n is not None], q)
        if found is None:
            continue
        n_star, t_star, order = found
        out.append(LeanRow(f"vs crank sweep ({q}, 1e-9)", label, built.seconds,
                           f"sweep N ≈ {n_star:.2g} (error ∝ N^-{order:.2g})", t_star,
                           "≥ 10⁴×", None, None, speedup=1e4,
                           note="N and time extrapolated" if n_star > max(r.n for r in mine if r.n) else
                           "N interpolated between measured sizes"))
    return out


def _variants(recipe: str, n: int) -> list[dict[str, float]]:
    rng = random.Random(2026)
    if recipe == "crank_rocker.extremes":
        return [{"AB": rng.uniform(20, 40), "BC": rng.uniform(60, 80), "CD": rng.uniform(60, 80),
                 "AD": rng.uniform(70, 90)} for _ in range(n)]
    return [{"K": rng.uniform(1.1, 1.8), "H": rng.uniform(30, 80), "e": rng.uniform(0, 25)} for _ in range(n)]


def _checked(sol: Any) -> tuple:
    """What a checked batch gives of one variant: its answers, whether the twin agreed, its warnings."""
    return sol.answers, sol.ok, sol.warnings


def batch_rows(quick: bool) -> list[LeanRow]:
    """The batch API's cost per variant, with and without checks, against one solve at a time of the same
    variants asked for what the batch gives (answers; or answers, ``ok`` and warnings) as loaded problems (validated beforehand, outside the timing: the batch validates each variant
    within it); the four timed interleaved."""
    n = 200 if quick else 1000
    out = []
    for recipe in ("crank_rocker.extremes", "crank_slider.design_by_K"):
        drawn = _variants(recipe, n)
        rows = [g for g, err in zip(drawn, solve_batch(recipe, drawn, checks=False).errors) if err is None]
        problems = [_problem(recipe, g) for g in rows]
        count = len(rows)                     # the valid variants (a random draw may fail Grashof)
        single, batch, single_checks, batch_checks = (t / count for t in interleaved(
            [lambda: [solve(p).answers for p in problems], lambda: solve_batch(recipe, rows, checks=False),
             lambda: [_checked(solve(p)) for p in problems], lambda: solve_batch(recipe, rows, checks=True)],
            number=1, rounds=2 if quick else 5, warm=1))
        out.append(LeanRow("batch per variant", f"{count} × {recipe}", batch, "one solve at a time (answers)",
                           single, "≤ 1×", None, 1.0))
        out.append(LeanRow("batch per variant + checks", f"{count} × {recipe}", batch_checks,
                           "one solve at a time (answers, ok, warnings)", single_checks, "≤ 1×", None, 1.0))
    return out


def measure_lean(quick: bool, extremes: Sequence[Any], exact_rows: Sequence[Any] | None) -> list[LeanRow]:
    """Every row of the lean-core table (``extremes`` and ``exact_rows`` are parts (a) and (c) of the run)."""
    return (linkage_rows(quick) + cam_rows(quick) + process_rows(quick) + sympy_rows(exact_rows)
            + sweep_rows(extremes) + batch_rows(quick))


def _ratio(r: LeanRow) -> str:
    if r.ratio is None:
        return "—"
    return f"{1 / r.ratio:,.3g}× faster" if r.speedup is not None else f"{r.ratio:.3g}×"


def baseline_line(rows: Sequence[LeanRow]) -> str:
    """The machine's speed in one line: ``python -c pass`` as the whole-process row measured it."""
    base = next((r.ref_seconds for r in rows if r.reference == "python -c pass" and r.ref_seconds), None)
    if base is None:
        return "python -c pass: not measured"
    return f"python -c pass: {fmt_seconds(base)} on this machine (median), the whole-process row's reference"


def lean_table(rows: Sequence[LeanRow]) -> str:
    """The printed table: what, case, time, reference, ratio, target, met; the baseline line above it."""
    body = [(r.what, r.case, fmt_seconds(r.seconds), f"{r.reference} {fmt_seconds(r.ref_seconds) if r.ref_seconds else ''}".strip(),
             _ratio(r), r.target, ("" if r.target == "reported" else ("met" if r.met else "SHORT"))
             + (f" ({r.note})" if r.note else "")) for r in rows]
    met = sum(r.met for r in rows if r.target != "reported")
    total = sum(1 for r in rows if r.target != "reported")
    return ("(0) lean core: each target as a ratio to a reference timed in the same run, interleaved\n"
            + baseline_line(rows) + "\n\n"
            + format_table(("measured", "case", "time", "reference", "ratio", "target", ""), body, "llrlrll")
            + f"\n\n{met} of {total} targets met on this run. Ratios are time / reference (\"× faster\": reference"
            " / time). Linkage and batch rows: the shortest of interleaved rounds, gc off while timing; the whole process and cams: medians; the sweep rows: part (a)'s best-of times on both sides.")
