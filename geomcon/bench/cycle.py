"""``geomcon bench``, whole cycles: four-bar positions per second over a crank turn, geomcon's vectorised chain
(:mod:`geomcon.kinematics`) beside pylinkage (numba-compiled ``step_fast``) where it is installed.

The four-bar 50/70/80/90 (crank-rocker, open branch) is swept through N crank angles: geomcon positions only,
and positions + velocities + accelerations; pylinkage ``step_fast`` (positions) and
``step_fast_with_kinematics`` after a warm-up call (numba's compilation is not counted). Each row also gives
the largest distance of its C from the closed-form twin (:func:`geomcon.analytic.kinematics.four_bar`) over
1000 of its positions, relative to the linkage's size. Times are CPU seconds, best of ``repeat``.

Examples
--------
>>> rows = measure_cycle(n=20_000, repeat=1, pylinkage=False)
>>> [r.method for r in rows]
['geomcon positions', 'geomcon positions + velocities + accelerations']
>>> all(r.rel_error < 1e-12 for r in rows)
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..analytic.kinematics import four_bar
from ..kinematics.chain import Mechanism, solve_chain
from ..kinematics.dyads import RRR, Crank
from .cam import _timed
from .report import format_table

AB, BC, CD, AD = 50.0, 70.0, 80.0, 90.0


@dataclass(frozen=True)
class CycleRow:
    """One measurement: ``method``, N positions, best CPU seconds, positions per second, worst error of C
    relative to the linkage's size."""

    method: str
    n: int
    seconds: float
    rate: float
    rel_error: float


def _error(phi_deg: np.ndarray, C: np.ndarray) -> float:
    idx = np.linspace(0, len(phi_deg) - 1, 1000).round().astype(int)
    worst = 0.0
    for i in idx:
        ref = four_bar(AB, BC, CD, AD, float(phi_deg[i]), 1.0, branch="above")
        worst = max(worst, abs(complex(C[i]) - complex(ref["Cx"], ref["Cy"])))
    return worst / AD


def measure_cycle(n: int = 1_000_000, repeat: int = 3, pylinkage: bool = True) -> list[CycleRow]:
    """The rows of the table (pylinkage's only when it imports and ``pylinkage`` is True)."""
    m = Mechanism({"A": 0j, "D": complex(AD)}, Crank("AB", "A", "B", AB, 10.0),
                  (RRR("C", "B", "D", BC, CD, 1, "BC", "DC"),))
    phi_deg = np.arange(n) * (360.0 / n)
    phi = np.radians(phi_deg)
    rows = []
    for label, der in (("geomcon positions", False), ("geomcon positions + velocities + accelerations", True)):
        st, t = _timed(lambda der=der: solve_chain(m, phi, der), repeat)
        rows.append(CycleRow(label, n, t, n / max(t, 1e-9), _error(phi_deg, st.points["C"].p)))
    if pylinkage:
        rows += _pylinkage_rows(n, repeat, phi_deg)
    return rows


def _pylinkage_rows(n: int, repeat: int, phi_deg: np.ndarray) -> list[CycleRow]:
    try:
        import pylinkage as pl
    except ImportError:
        return []
    A, D = pl.Ground(0.0, 0.0, name="A"), pl.Ground(AD, 0.0, name="D")
    crank = pl.Crank(anchor=A, radius=AB, angular_velocity=math.radians(360.0 / n), initial_angle=0.0)
    # the open branch: pylinkage follows the intersection nearest C's previous position
    C0 = four_bar(AB, BC, CD, AD, 0.0, 1.0, branch="above")
    rocker = pl.RRRDyad(crank.output, D, distance1=BC, distance2=CD, x=C0["Cx"], y=C0["Cy"])
    link = pl.Linkage([A, D, crank, rocker])
    start = link.get_coords()
    rows = []
    link.step_fast(iterations=16)                      # numba compiles here, not in the timed calls
    link.set_coords(start)

    def run():
        link.set_coords(start)
        return link.step_fast(iterations=n, dt=1.0)
    tr, t = _timed(run, repeat)
    # step k holds the crank advanced k + 1 steps
    C = tr[:, 3, 0] + 1j * tr[:, 3, 1]
    phi_pl = (np.arange(1, n + 1) * (360.0 / n)) % 360.0
    rows.append(CycleRow("pylinkage step_fast (numba)" if _numba() else "pylinkage step_fast", n, t, n / max(t, 1e-9),
                         _error(phi_pl, C)))
    try:
        link.set_input_velocity(crank, omega=10.0, alpha=0.0)
        link.set_coords(start)
        link.step_fast_with_kinematics(iterations=16)

        def run_k():
            link.set_coords(start)
            return link.step_fast_with_kinematics(iterations=n, dt=1.0)
        (pos, _, _), tk = _timed(run_k, repeat)
        Ck = pos[:, 3, 0] + 1j * pos[:, 3, 1]
        rows.append(CycleRow("pylinkage step_fast_with_kinematics", n, tk, n / max(tk, 1e-9), _error(phi_pl, Ck)))
    except Exception:   # an older pylinkage without kinematics: positions only
        pass
    return rows


def _numba() -> bool:
    try:
        import numba  # noqa: F401
        return True
    except ImportError:
        return False


def cycle_table(rows: list[CycleRow]) -> str:
    """The rows as the bench prints them, with each rate's ratio to pylinkage's positions."""
    ref = next((r.rate for r in rows if r.method.startswith("pylinkage step_fast") and "kinematics" not in r.method),
               None)
    body = [[r.method, f"{r.n:,}", f"{r.seconds:.3g}", f"{r.rate / 1e6:.2f}",
             f"{r.rate / ref:.2f}×" if ref else "—", f"{r.rel_error:.1e}"] for r in rows]
    note = "" if ref else "\npylinkage was not measured (not installed: pip install -e '.[test]' brings it)."
    return ("Whole cycle: four-bar 50/70/80/90 swept through N crank angles (CPU time, best of repeats)\n"
            + format_table(["method", "N", "s", "M positions/s", "vs pylinkage", "max |C − twin|/AD"], body,
                           "lrrrrr") + note)
