"""``geomcon bench``'s gallery rows (issue 11's speed targets): the whole ``geomcon gallery --check`` ≤ 3 s of
wall time, one figure ≤ 40 ms.

- The gallery: ``python -m geomcon gallery --check`` run as a child process from the checkout (every core, as a
  user runs it), timed in wall seconds and in the CPU seconds of the process and its workers; the fastest of
  the runs. The byte-code is cached, as installed (pip byte-compiles a package it installs; a shell with
  ``PYTHONDONTWRITEBYTECODE`` compiles every module on every start instead, about 0.4 s more before the workers
  start). Wall time is what the target names, so the machine's load average is printed beside it: a shared
  machine's other jobs take cores the gallery would use.
- One figure: a problem's sheets as the gallery draws them (``Solution.sheets`` on the gallery's page: sheet 1's
  drawing with its labels placed, results and title block, a cam's s–δ sheet, the protocol's sheets), on a
  solution whose answers and checks are computed already, and of it sheet 1's figure alone (its
  :func:`~geomcon.render.figure.build_figure`: the drawing steps drawn, the labels placed); CPU seconds of this
  process, the shortest of ``samples`` fresh solutions each, the problems interleaved sample by sample.
  :data:`FIGURES` are the gallery's costliest figures (the cams with 45 labels) and the textbook's
  crank-rocker.

- Every figure: sheet 1's :func:`~geomcon.render.figure.build_figure` of every bundled problem, drawn again
  from the arguments the gallery's sheets gave it (each problem solved and its sheets drawn once, then the
  figures alone, interleaved, the shortest of ``samples``): how many exceed :data:`FIGURE_TARGET`, the slowest
  and the median (:class:`SpreadRow`).

Tests check the rows' arithmetic, never a time.

Examples
--------
>>> r = FigureRow("001-08", "crank_rocker.extremes", 0.031, 0.012)
>>> r.met
True
>>> GalleryRow(2.5, 4.6, 1.2, 1).met
True
>>> r = SpreadRow.of({"001-08": 0.012, "001-24": 0.052, "200-16": 0.047})
>>> r.over, r.slowest, r.median, r.met
(2, '001-24', 0.047, False)
"""
from __future__ import annotations

import gc
import os
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from .clock import clock
from .report import fmt_seconds, format_table

ROOT = Path(__file__).resolve().parents[2]
"""The checkout (``problems/`` and ``gallery/`` beside ``geomcon/``)."""
FIGURES = ("001-24", "200-16", "001-08")
"""The problems whose sheet 1 is timed (ids: the start of the file name)."""
GALLERY_TARGET = 3.0
FIGURE_TARGET = 0.040


@dataclass(frozen=True)
class GalleryRow:
    """The whole gallery: the fastest run's wall and CPU seconds (the process and its workers), the load
    average when the runs began, and the number of runs."""

    wall: float
    cpu: float
    load: float
    runs: int

    @property
    def met(self) -> bool:
        """Within :data:`GALLERY_TARGET` of wall time."""
        return self.wall <= GALLERY_TARGET


@dataclass(frozen=True)
class FigureRow:
    """One problem: its id, recipe and the shortest CPU seconds of its sheets and of sheet 1's figure."""

    problem: str
    recipe: str
    seconds: float
    figure: float

    @property
    def met(self) -> bool:
        """Sheet 1's figure within :data:`FIGURE_TARGET`."""
        return self.figure <= FIGURE_TARGET


@dataclass(frozen=True)
class SpreadRow:
    """Sheet 1's figure of every problem: how many were timed, how many exceed :data:`FIGURE_TARGET`, the
    slowest one's id and CPU seconds, and the median."""

    count: int
    over: int
    slowest: str
    worst: float
    median: float

    @staticmethod
    def of(seconds: dict[str, float]) -> SpreadRow:
        """The row of ``seconds`` (problem id → CPU seconds of its figure; at least one)."""
        ranked = sorted(seconds.values())
        n = len(ranked)
        median = ranked[n // 2] if n % 2 else (ranked[n // 2 - 1] + ranked[n // 2]) / 2
        slowest = max(seconds, key=seconds.__getitem__)
        return SpreadRow(n, sum(t > FIGURE_TARGET for t in ranked), slowest, seconds[slowest], median)

    @property
    def met(self) -> bool:
        """Every figure within :data:`FIGURE_TARGET`."""
        return self.over == 0


def _child_run(argv: list[str], env: dict[str, str]) -> tuple[float, float]:
    """Wall and CPU seconds (user + system of the child and its own children) of one run of ``argv``."""
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(argv, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False, env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def measure_gallery(runs: int = 3) -> GalleryRow | None:
    """The fastest of ``runs`` runs of ``geomcon gallery --check`` (see the module); None without a checkout."""
    if not (ROOT / "problems").is_dir() or not (ROOT / "gallery").is_dir():
        return None
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    argv = [sys.executable, "-m", "geomcon", "gallery", "--check"]
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "geomcon")], env=env,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)    # the byte-code caches
    load = os.getloadavg()[0]
    walls, cpus = zip(*(_child_run(argv, env) for _ in range(runs)))
    return GalleryRow(min(walls), min(cpus), load, runs)


def _problem_file(pid: str) -> Path | None:
    return next(iter(sorted((ROOT / "problems").glob(f"{pid}_*.toml"))), None)


def measure_figures(samples: int = 15, figures: tuple[str, ...] = FIGURES) -> list[FigureRow]:
    """The shortest CPU time of sheet 1 of each of ``figures`` over ``samples`` fresh solutions (see the
    module); a problem not bundled is left out."""
    from ..gallery import problem_page
    from ..problems import load_problem
    from ..solve import solve

    from ..render import svg as render_svg

    problems = [(pid, load_problem(p)) for pid in figures if (p := _problem_file(pid)) is not None]
    pages = {pid: problem_page(problem.id) for pid, problem in problems}              # the gallery's paper
    best = {pid: float("inf") for pid, _ in problems}
    first = {pid: float("inf") for pid, _ in problems}
    recipe = {}
    build = render_svg.build_figure
    spent: list[float] = []

    def timed_build(*args, **kwargs):               # each figure's CPU, read from inside render_sheets
        t0 = clock()
        fig = build(*args, **kwargs)
        spent.append(clock() - t0)
        return fig

    was = gc.isenabled()
    render_svg.build_figure = timed_build
    try:
        for _ in range(samples):
            for pid, problem in problems:
                sol = solve(problem)
                sol.ok                                   # answers and checks: not the figure's work
                recipe[pid] = sol.recipe.name
                spent.clear()
                gc.collect()
                gc.disable()
                t0 = clock()
                sol.sheets(pages[pid])
                t = clock() - t0
                gc.enable()
                best[pid] = min(best[pid], t)
                first[pid] = min(first[pid], spent[0])
    finally:
        render_svg.build_figure = build
        if was:
            gc.enable()
        else:
            gc.disable()
    return [FigureRow(pid, recipe[pid], best[pid], first[pid]) for pid, _ in problems]


def measure_all_figures(samples: int = 1, only: tuple[str, ...] | None = None) -> SpreadRow | None:
    """Sheet 1's figure of every bundled problem (of ``only``'s ids when given), the shortest CPU time of
    ``samples`` (see the module); None without problems."""
    from ..gallery import problem_files, problem_page
    from ..problems import load_problem
    from ..render import svg as render_svg
    from ..solve import solve

    build = render_svg.build_figure
    calls: list[tuple[tuple, dict]] = []

    def first_call(*args, **kwargs):                # sheet 1's figure: the first one drawn
        calls.append((args, kwargs))
        return build(*args, **kwargs)

    figures: dict[str, tuple[tuple, dict]] = {}
    render_svg.build_figure = first_call
    try:
        for path in problem_files(ROOT / "problems"):
            pid = path.stem.split("_")[0]
            if only is not None and pid not in only:
                continue
            calls.clear()
            solve(load_problem(path)).sheets(problem_page(path.stem))      # on the gallery's paper
            if calls:
                figures[path.stem] = calls[0]
    finally:
        render_svg.build_figure = build
    if not figures:
        return None
    best = {name: float("inf") for name in figures}
    was = gc.isenabled()
    try:
        for _ in range(samples):
            for name, (args, kwargs) in figures.items():
                gc.collect()
                gc.disable()
                t0 = clock()
                build(*args, **kwargs)
                best[name] = min(best[name], clock() - t0)
                gc.enable()
    finally:
        if was:
            gc.enable()
        else:
            gc.disable()
    return SpreadRow.of(best)


def gallery_table(gallery: GalleryRow | None, figures: list[FigureRow], spread: SpreadRow | None = None) -> str:
    """The printed table of the gallery rows."""
    head = ("gallery (issue 11)", "case", "time", "CPU", "target")
    rows = []
    if gallery is not None:
        rows.append(("geomcon gallery --check", f"every core, load {gallery.load:.1f}, best of {gallery.runs}",
                     f"{gallery.wall:.2f} s wall", f"{gallery.cpu:.2f} s",
                     f"≤ {GALLERY_TARGET:g} s ({'met' if gallery.met else 'SHORT'})"))
    for r in figures:
        rows.append(("one figure (sheet 1)", f"{r.problem} {r.recipe}", "", fmt_seconds(r.figure),
                     f"≤ {FIGURE_TARGET * 1e3:g} ms ({'met' if r.met else 'SHORT'})"))
        rows.append(("  its sheets (SVG)", f"{r.problem}", "", fmt_seconds(r.seconds), ""))
    if spread is not None:
        rows.append(("every figure (sheet 1)", f"{spread.count} problems: median; slowest {spread.slowest}",
                     "", f"{fmt_seconds(spread.median)}; {fmt_seconds(spread.worst)}",
                     f"{spread.over} over {FIGURE_TARGET * 1e3:g} ms ({'met' if spread.met else 'SHORT'})"))
    return format_table(head, rows, "llrrl") + ("\nthe gallery's byte-code cached, as installed; wall time depends on "
                                                "the machine's load" if gallery is not None else "")


__all__ = ["FIGURES", "FIGURE_TARGET", "FigureRow", "GALLERY_TARGET", "GalleryRow", "SpreadRow", "gallery_table",
           "measure_all_figures", "measure_figures", "measure_gallery"]
