"""(c) Design by K: the engine's construction against the same construction in sympy.geometry (exact
arithmetic, then evaluated to 30 digits), run time and error against the closed-form twin side by side.

sympy is an optional dependency of the benchmark only (it is in the ``test`` extra); without it this part
is reported as not measured.
"""
from __future__ import annotations

import statistics
from dataclasses import dataclass
from typing import Any, Mapping

from ..analytic.design_by_k import crank_slider_design
from ..problems import validate_given
from ..recipes import get_recipe
from ..taped import construct_taped
from .clock import clock

CASES = ({"K": 1.5, "H": 50, "e": 20}, {"K": 1.25, "H": 101.737391, "e": 20}, {"K": 2, "H": 300, "e": 60})


@dataclass(frozen=True)
class ExactRow:
    """One design by both routes: seconds and |error| of AB and BC against the twin."""

    given: Mapping[str, Any]
    method: str
    seconds: float
    err_AB: float
    err_BC: float


def sympy_crank_slider(K: float, H: float, e: float) -> tuple[float, float]:
    """AB, BC by the θ-circle construction in sympy.geometry (C2P ⊥ C1C2, ∠C2C1P = 90° − θ, circle C1C2P,
    the parallel at distance e, the intersection left of C1, then AB = (AC2 − AC1)/2, BC = (AC2 + AC1)/2)."""
    import sympy as sp
    from sympy.geometry import Circle, Line, Point

    Kq, Hq, eq = sp.nsimplify(K), sp.nsimplify(H), sp.nsimplify(e)
    th = sp.pi * (Kq - 1) / (Kq + 1)
    C1, C2 = Point(0, 0), Point(Hq, 0)
    P = Line(C2, Point(Hq, 1)).intersection(Line(C1, Point(sp.cos(sp.pi / 2 - th), sp.sin(sp.pi / 2 - th))))[0]
    k = Circle(C1, C2, P)
    A = min(k.intersection(Line(Point(0, eq), Point(1, eq))), key=lambda p: float(p.x))
    u, v = A.distance(C1), A.distance(C2)
    return float(sp.N((v - u) / 2, 30)), float(sp.N((v + u) / 2, 30))


def engine_givens(K: float, H: float, e: float) -> dict[str, Any]:
    """The givens of ``crank_slider.design_by_K`` validated as a problem file's (numbers made floats)."""
    return validate_given(get_recipe("crank_slider.design_by_K"), {"K": K, "H": H, "e": e})


def engine_design(given: Mapping[str, Any]) -> tuple[float, float]:
    """AB, BC by geomcon's ``crank_slider.design_by_K`` construction (answers only) on validated givens (what a
    repeated solve runs: the recipe's tape replayed, the compiled plan of its answers; the imports are made
    with the module's, not in every timed call).

    >>> ab, bc = engine_design(engine_givens(1.5, 50, 20))
    >>> round(ab, 9), round(bc, 9)
    (21.50674666, 46.517112642)
    """
    vals = construct_taped(get_recipe("crank_slider.design_by_K"), given).scene.evaluate(("AB", "BC"))
    return vals["AB"], vals["BC"]


def engine_crank_slider(K: float, H: float, e: float) -> tuple[float, float]:
    """AB, BC by geomcon's ``crank_slider.design_by_K`` construction (answers only)."""
    return engine_design(engine_givens(K, H, e))


ENGINE_CALLS = 20
"""Engine calls per timed sample: one call (~15 µs) is not much longer than reading the CPU clock twice (~1 µs on
the development machine, a syscall), which a sample of one call would count as the engine's."""


def measure_exact(repeat: int = 3) -> list[ExactRow] | None:
    """Both routes on every case, median times; None when sympy is not installed. sympy is warmed up once on
    another design (its lazy imports) and its cache cleared before every timed run, so that no run reuses the
    results of the one before. The engine is timed on givens validated once (as a loaded problem's: the
    lean-core rows time ``solve(problem)`` the same way), ``repeat × 20`` samples of :data:`ENGINE_CALLS` calls
    each, the median of their mean (sympy's runs take ~10⁴ times longer: one run a sample); sympy's timed run
    includes turning the numbers into exact ones (``nsimplify``), which is part of its method."""
    try:
        from sympy.core.cache import clear_cache
    except ImportError:
        return None
    sympy_crank_slider(2.0, 100.0, 10.0)                  # θ = 60°: quick (θ = 3π/23 takes sympy minutes)
    rows = []
    for g in CASES:
        exact = crank_slider_design(g["K"], g["H"], e=g["e"])
        given = engine_givens(g["K"], g["H"], g["e"])      # a problem's givens are validated when it is loaded,
        for method, n in (("geomcon", repeat * 20), ("sympy.geometry", repeat)):   # as in the lean-core rows
            times = []
            for _ in range(n):
                if method == "geomcon":
                    t0 = clock()
                    for _ in range(ENGINE_CALLS):
                        ab, bc = engine_design(given)
                    times.append((clock() - t0) / ENGINE_CALLS)
                else:
                    clear_cache()
                    t0 = clock()
                    ab, bc = sympy_crank_slider(g["K"], g["H"], g["e"])
                    times.append(clock() - t0)
            rows.append(ExactRow(g, method, statistics.median(times), abs(ab - exact["AB"]), abs(bc - exact["BC"])))
    return rows


def exact_table(rows: list[ExactRow] | None) -> str:
    """The printed table of part (c)."""
    if rows is None:
        return "(c) design by K vs sympy.geometry: not measured (sympy is not installed: pip install sympy)"
    lines = ["(c) crank_slider.design_by_K (K, H, e): the engine vs the same construction in sympy.geometry", "",
             f"{'given':<28}  {'method':<15}  {'time (median)':>13}  {'|ΔAB| mm':>9}  {'|ΔBC| mm':>9}",
             f"{'-' * 28}  {'-' * 15}  {'-' * 13}  {'-' * 9}  {'-' * 9}"]
    for r in rows:
        g = ", ".join(f"{k}={v:g}" for k, v in r.given.items())
        t = f"{r.seconds * 1e3:.3g} ms" if r.seconds < 1 else f"{r.seconds:.3g} s"
        lines.append(f"{g:<28}  {r.method:<15}  {t:>13}  {r.err_AB:>9.1e}  {r.err_BC:>9.1e}")
    return "\n".join(lines)
