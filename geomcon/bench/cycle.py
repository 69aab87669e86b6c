"""``geomcon bench``, whole cycles: four-bar positions per second over a crank turn, geomcon's vectorised chain
(:mod:`geomcon.kinematics`) beside pylinkage (numba-compiled ``step_fast``) where it is installed.

The four-bar 50/70/80/90 (crank-rocker, open branch) is swept through the same N crank angles by every row, in
float64: geomcon's compiled plan (:mod:`geomcon.kinematics.plan`, the fast path) for the joints' positions
(what pylinkage's ``step_fast`` returns), for positions + velocities + accelerations (what
``step_fast_with_kinematics`` returns; the links' ω and ε come with them), and for everything with the links'
angles too; the reference path (:func:`~geomcon.kinematics.chain.solve_chain`, complex arrays) for the same
two; pylinkage after a warm-up call (numba's compilation is not counted). Times are CPU seconds, best of
``repeat``.

Each rate is given as a ratio to pylinkage's positions and, so that a figure carries over between runs on a
machine whose speed drifts, as the row's time over the time numpy takes for one cosine and one sine of each
of the N angles (the first row, timed in the same run: a position cannot cost less than that). Each row also
gives the largest distance of its C from the closed-form twin (:func:`geomcon.analytic.kinematics.four_bar`)
over 1000 of its positions, relative to the linkage's size.

Examples
--------
>>> rows = measure_cycle(n=20_000, repeat=1, pylinkage=False)
>>> [r.method for r in rows][:3]
['numpy cos + sin of the N angles', 'geomcon positions', 'geomcon positions + velocities + accelerations']
>>> all(r.rel_error < 1e-12 for r in rows[1:])
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..analytic.kinematics import four_bar
from ..kinematics.chain import Mechanism, solve_chain
from ..kinematics.dyads import RRR, Crank
from ..kinematics.plan import compile_chain
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


NUMPY = "numpy cos + sin of the N angles"
"""The first row: the stable yardstick of a run."""


def _cos_sin(phi: np.ndarray) -> np.ndarray:
    out = np.empty((2, phi.shape[0]))
    np.cos(phi, out=out[0])
    np.sin(phi, out=out[1])
    return out


def measure_cycle(n: int = 1_000_000, repeat: int = 3, pylinkage: bool = True) -> list[CycleRow]:
    """The rows of the table (pylinkage's only when it imports and ``pylinkage`` is True)."""
    m = Mechanism({"A": 0j, "D": complex(AD)}, Crank("AB", "A", "B", AB, 10.0),
                  (RRR("C", "B", "D", BC, CD, 1, "BC", "DC"),))
    plan = compile_chain(m)
    phi_deg = np.arange(n) * (360.0 / n)
    phi = np.radians(phi_deg)
    _, t = _timed(lambda: _cos_sin(phi), repeat)
    rows = [CycleRow(NUMPY, n, t, n / max(t, 1e-9), math.nan)]
    runs = (("geomcon positions", lambda: plan.solve(phi, False, False)),
            ("geomcon positions + velocities + accelerations", lambda: plan.solve(phi, True, False)),
            ("geomcon all, with the links' angles", lambda: plan.solve(phi, True, True)),
            ("geomcon reference path, positions", lambda: solve_chain(m, phi, False)),
            ("geomcon reference path, all", lambda: solve_chain(m, phi, True)))
    for label, run in runs:
        st, t = _timed(run, repeat)
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
    """The rows as the bench prints them, with each rate's ratio to pylinkage's positions and each time's
    ratio to numpy's cos + sin of the same angles."""
    ref = next((r.rate for r in rows if r.method.startswith("pylinkage step_fast") and "kinematics" not in r.method),
               None)
    base = next((r.seconds for r in rows if r.method == NUMPY), None)
    body = [[r.method, f"{r.n:,}", f"{r.seconds:.3g}", f"{r.rate / 1e6:.2f}",
             f"{r.rate / ref:.2f}×" if ref else "—", f"{r.seconds / base:.2f}" if base else "—",
             "—" if math.isnan(r.rel_error) else f"{r.rel_error:.1e}"] for r in rows]
    note = "" if ref else "\npylinkage was not measured (not installed: pip install -e '.[test]' brings it)."
    return ("Whole cycle: four-bar 50/70/80/90 swept through the same N crank angles, float64 (CPU time, best of "
            "repeats;\n'× cos+sin': the row's time over numpy's cos + sin of the N angles in this run)\n"
            + format_table(["method", "N", "s", "M positions/s", "vs pylinkage", "× cos+sin", "max |C − twin|/AD"],
                           body, "lrrrrrr") + note)
