"""A solved cycle as text: the CSV table and the JSON summary, deterministic (every number through
:func:`geomcon.check.rounded` at its quantity's scale, keys in a fixed order).

Examples
--------
>>> from .problem import demo_problem
>>> from .result import solve_cycle
>>> p = demo_problem(step=90, columns=["C.x", "C.vx"])
>>> print(table_csv(solve_cycle(p)), end="")
phi_deg,C.x,C.vx
0,120,0
90,84.8528137424,-300
180,60,0
270,84.8528137424,300
360,120,0
"""
from __future__ import annotations

import json
import math
from typing import Callable

import numpy as np

from ..check import rounded, rounder
from .result import CycleResult, scale_of, unit_of
from .quantities import value


def table_csv(r: CycleResult) -> str:
    """The table: one row per crank angle, a column per quantity (header: the quantity names; units in
    :func:`units_line`)."""
    m = r.problem.mechanism
    # each column as floats, and its rounding's digits, once (:func:`geomcon.check.rounder`): the same text
    cols = [(value(r.cycle.state, q).tolist(), rounder(scale_of(q, m))) for q in r.problem.columns]
    at_360 = rounder(360.0)
    lines = [",".join(("phi_deg", *r.problem.columns))]
    for i, phi in enumerate(r.cycle.phi_deg.tolist()):
        lines.append(",".join([_text(phi, at_360)] + [_text(c[i], rnd) for c, rnd in cols]))
    return "\n".join(lines) + "\n"


def _text(x: float, rnd: Callable[[float], float]) -> str:
    """A number for a file: 12 significant digits at its column's scale (``rnd``, the scale's
    :func:`geomcon.check.rounder`), integers without a decimal point."""
    if not math.isfinite(x):
        return "nan"
    r = rnd(x)
    return str(int(r)) if r == int(r) and abs(r) < 1e15 else repr(r)


def units_line(r: CycleResult) -> str:
    """The columns' units, in the table's order."""
    return ", ".join(f"{q} ({unit_of(q) or '1'})" for q in r.problem.columns)


def to_json(r: CycleResult) -> dict:
    """The summary: problem, mechanism's size, answers, stationary points, change points, the ``at`` rows, the
    printed answers audited, warnings."""
    p, m = r.problem, r.problem.mechanism
    out = {"problem": p.id, "kind": "cycle", "title": p.title, "seed": p.seed,
           "positions": len(r.cycle.phi_deg), "range_deg": [float(p.phi_deg[0]), float(p.phi_deg[-1])],
           "columns": {q: unit_of(q) for q in p.columns},
           "answers": r.answers,
           "stationary": [{"quantity": s.quantity, "phi_deg": rounded(s.phi_deg, 360.0),
                           "value": rounded(s.value, scale_of(s.quantity, m)), "kind": s.kind}
                          for s in r.stationary],
           "change_points": [{"dyad": c.dyad, "phi_deg": rounded(c.phi_deg, 360.0)} for c in r.cycle.changes],
           "published": list(r.published), "warnings": list(r.warnings)}
    if r.at_state is not None:
        out["at"] = [{"phi_deg": a, **{q: rounded(float(value(r.at_state, q)[i]), scale_of(q, m))
                                      for q in p.columns}} for i, a in enumerate(p.at)]
    return out


def json_text(r: CycleResult) -> str:
    """:func:`to_json` as text (standard JSON: no NaN)."""
    def clean(o):
        if isinstance(o, float) and not math.isfinite(o):
            return None
        if isinstance(o, dict):
            return {k: clean(v) for k, v in o.items()}
        if isinstance(o, list):
            return [clean(v) for v in o]
        if isinstance(o, np.floating):
            return clean(float(o))
        return o
    return json.dumps(clean(to_json(r)), ensure_ascii=False, indent=2, allow_nan=False) + "\n"


def summary(r: CycleResult) -> str:
    """The text ``geomcon cycle`` prints."""
    p = r.problem
    lines = [f"{p.id}: whole cycle" + (f" — {p.title}" if p.title else ""),
             f"  {len(r.cycle.phi_deg)} crank positions {p.phi_deg[0]:g}°…{p.phi_deg[-1]:g}°; columns: {units_line(r)}"]
    lines += [f"  {k} = {v:.6g}" for k, v in r.answers.items()]
    lines += [f"  extreme of {s.quantity}: {s.kind} {s.value:.6g} at crank angle {s.phi_deg:.6f}°" for s in r.stationary]
    lines += [f"  printed {row['quantity']} = {row['published']:g} (exact {row['exact']:g})" for row in r.published]
    lines += [f"  warning: {w}" for w in r.warnings]
    return "\n".join(lines) + "\n"
