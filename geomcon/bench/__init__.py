"""``geomcon bench``: how fast and how exact is the construction, against the obvious numerical baseline?

(0) The lean core's targets, each a ratio to a reference timed in the same run (:mod:`.lean`).

(a) For three textbook problems — the crank-rocker 50/70/80/90, the offset crank-slider 120/250/60 and the
guide-bar 145/290 — the construction (the recipe's scene built and evaluated for its answers) is timed and
checked against the analytic twin, and so is sweeping the crank through N = 360 … 10⁶ steps with
vectorised numpy and taking the extremes of the output by arg-max/arg-min (:mod:`.sweep`). (b) A fresh
solve asked for its answers only is compared with one asked for the SVG drawing too: time and steps
evaluated, which shows the scene's laziness.

(i) The gallery (issue 11): the whole ``geomcon gallery --check`` in wall and CPU seconds, and sheet 1 of the
costliest figures (:mod:`.gallery`).

(g) Grading a class of 100 000 rows × 6 answers with diagnosis (:mod:`.grading`).
(h) Whole cycles: four-bar positions per second over a crank turn, geomcon's vectorised chain (the compiled fast
path and the reference path) beside pylinkage (numba) where installed, each also as a ratio to numpy's cos + sin
of the same angles timed in the same run (:mod:`.cycle`).

The table is printed and the time–error plot written (atomically) as SVG.
"""
from __future__ import annotations

from importlib import import_module
from pathlib import Path
from typing import Any

_LAZY = {"CASES": "measure", "FULL": "measure", "QUICK": "measure", "Case": "measure", "Config": "measure",
         "DrawRow": "measure", "ErrorRow": "measure", "measure_drawing": "measure", "measure_extremes": "measure",
         "render_plot": "plot"}
"""The package's exports and the module each lives in: imported when first asked for (PEP 562), so that
``geomcon gallery``, which needs only :mod:`.cycle_record`, does not import (and, without a byte-code cache,
compile) every benchmark."""


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def run_bench(*, quick: bool = False, out: Path = Path("bench.svg"), cycle_record: Path | None = None) -> int:
    """Measure, print the tables, write the plot to ``out``; return the exit code (0).

    Parameters
    ----------
    quick : bool
        Fewer repetitions and sweeps of N ≤ 36,000 only (seconds instead of about a minute).
    out : Path
        Where the SVG plot goes.
    cycle_record : Path or None
        Where to write the whole-cycle rows as the JSON record the gallery draws
        (``problems/cycles/bench_record.json``); None writes none.
    """
    from ..fileio import write_all
    from .cam import cam_table, measure_cam
    from .cycle import cycle_table, measure_cycle
    from .exact import exact_table, measure_exact
    from .gallery import gallery_table, measure_all_figures, measure_figures, measure_gallery
    from .grading import grading_table, measure_grading
    from .lean import lean_table, measure_lean
    from .measure import FULL, QUICK, measure_drawing, measure_extremes
    from .plot import render_plot
    from .report import report
    from .synthesis import measure_synthesis, synthesis_table

    config = QUICK if quick else FULL
    extremes = measure_extremes(config)
    drawing = measure_drawing(config)
    exact = measure_exact(1 if quick else 3)
    lean = lean_table(measure_lean(quick, extremes, exact))
    text = lean + "\n\n" + report(extremes, drawing, quick=quick) + "\n\n" + exact_table(exact)
    text += "\n\n" + synthesis_table(measure_synthesis(1 if quick else 3))
    text += "\n\n" + cam_table(measure_cam(quick))
    text += "\n\n" + grading_table(measure_grading(rows=10_000 if quick else 100_000))
    cycle = measure_cycle(200_000 if quick else 1_000_000, 1 if quick else 3)
    text += "\n\n" + cycle_table(cycle)
    text += "\n\n" + gallery_table(measure_gallery(1 if quick else 3), measure_figures(5 if quick else 15),
                                   measure_all_figures(1 if quick else 2))
    files = {out: render_plot(extremes, quick=quick)}
    if cycle_record is not None:
        import time
        from .cycle_record import record_of, record_text
        stamp = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
        files[cycle_record] = record_text(record_of(cycle, f"{stamp}, geomcon bench{' --quick' if quick else ''}"))
    write_all(files)
    print(text + f"\nplot written to {out}")
    return 0


__all__ = ["CASES", "FULL", "QUICK", "Case", "Config", "DrawRow", "ErrorRow", "measure_drawing",
           "measure_extremes", "render_plot", "run_bench"]
