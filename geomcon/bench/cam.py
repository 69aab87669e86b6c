"""``geomcon bench``, cams: run time against profile error for the roller profile of problem 200-01.

Three ways to the actual profile, all measured against the exact envelope (every point of it lies at rr
from the exact pitch curve, sampled 200,000 times (100,000 quick): the error of a sampled profile is the largest
|distance to the pitch curve − rr| over its vertices and edge midpoints):

- the analytic offset along the exact normal, N equal steps of cam angle;
- the same with N chosen from ρmin for a tolerance (:func:`geomcon.cam.profile.roller_profile`);
- shapely's buffer of the pitch polygon (N points) by −rr, at several arc resolutions.

Then a fresh solve asked for its answers only against one asked for the drawing too.

Examples
--------
>>> rows = measure_cam(quick=True)
>>> any(r.method == "analytic offset, tolerance" and r.error <= 1.05e-3 for r in rows)
True
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from ..cam.profile import chord_error, roller_profile
from .clock import clock
from .report import fmt_error, fmt_seconds, format_table

PROBLEM = {"recipe": "cam.translating", "given": {
    "follower": "roller", "r0": 40, "e": 10, "rr": 10, "h": 20, "rotation": "ccw",
    "program": [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
                {"kind": "return", "angle": 90, "law": "cycloidal"}, {"kind": "dwell", "angle": 90}]}}
RR = 10.0


@dataclass(frozen=True)
class CamRow:
    """One measurement: ``method``, its parameter, the number of profile points, seconds, error (mm)."""

    method: str
    parameter: str
    points: int
    seconds: float
    error: float


def _timed(fn, repeat: int):
    best, out = math.inf, None
    for _ in range(repeat):
        t = clock()
        out = fn()
        best = min(best, clock() - t)
    return out, best


def _solution():
    from ..problems import problem_from_dict
    from ..solve import solve
    return solve(problem_from_dict(PROBLEM, name="bench-cam"))


def _offset_n(curve, n: int) -> np.ndarray:
    d = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    x, y, dx, dy = curve.eval(d)[:4]
    sp, sg = np.hypot(dx, dy), curve.orientation
    return np.column_stack([x - RR * sg * dy / sp, y + RR * sg * dx / sp])


def measure_cam(quick: bool = False) -> list[CamRow]:
    """Time and error of each way to the profile, and answers against the drawing."""
    repeat = 1 if quick else 3
    curve = _solution().scene.value("pitch")
    d = np.linspace(0.0, 2 * math.pi, 100_000 if quick else 200_000, endpoint=False)
    ref = np.column_stack(curve.eval(d)[:2])
    rows = []
    for n in ((90, 360, 1440) if quick else (90, 360, 1440, 5760, 23040)):
        xy, t = _timed(lambda: _offset_n(curve, n), repeat)
        rows.append(CamRow("analytic offset, N steps", f"N = {n}", n, t, chord_error(xy, ref, RR)))
    for tol in (1e-3, 1e-5):
        prof, t = _timed(lambda: roller_profile(curve, RR, tol), repeat)
        rows.append(CamRow("analytic offset, tolerance", f"tol = {tol:g} mm", len(prof.xy), t,
                           chord_error(prof.xy, ref, RR)))
    for n_pitch, q in ((360, 16), (1440, 16)) if quick else ((360, 16), (1440, 16), (5760, 16), (5760, 4)):
        def buffer():
            pitch = Polygon(np.column_stack(curve.eval(np.linspace(0, 2 * math.pi, n_pitch, endpoint=False))[:2]))
            return np.asarray(pitch.buffer(-RR, quad_segs=q).exterior.coords)[:-1]
        xy, t = _timed(buffer, repeat)
        rows.append(CamRow("shapely buffer of the pitch polygon", f"N = {n_pitch}, quad_segs = {q}", len(xy), t,
                           chord_error(xy, ref, RR)))
    for what in ("answers only", "answers + SVG"):
        def run():
            sol = _solution()
            sol.answers
            if what != "answers only":
                sol.svg()
            return sol
        sol, t = _timed(run, repeat)
        rows.append(CamRow(what, f"{sol.stats['steps_evaluated']} of {sol.stats['steps_total']} steps", 0, t,
                           max(c["abs_error"] for c in sol.checks)))
    return rows


def cam_table(rows: list[CamRow]) -> str:
    """The cam rows as a table (profile error in mm; for the solves, the largest |construction − twin|)."""
    body = [(r.method, r.parameter, str(r.points or ""), fmt_seconds(r.seconds), fmt_error(r.error)) for r in rows]
    return ("(e) cam.translating, roller profile of 200-01 against the exact envelope\n"
            + format_table(("method", "parameter", "points", "time", "error"), body, "llrrr"))
