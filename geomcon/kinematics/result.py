"""A cycle problem solved: the table, the exact extremes and strokes, the printed answers audited.

Answers are named ``min(q)``, ``max(q)`` (for each ``extremes`` quantity q), and ``stroke(q)``, ``at_max(q)``,
``at_min(q)`` and, with one maximum and one minimum per turn, ``increasing(q)``, ``decreasing(q)`` (crank
angles of the two motions, deg), ``K(q)``, ``theta(q)`` (for each ``strokes`` quantity).

Examples
--------
>>> from .problem import demo_problem
>>> p = demo_problem(step=90, strokes=["C.x"])
>>> r = solve_cycle(p)
>>> r.answers["stroke(C.x)"], r.answers["K(C.x)"]
(60.0, 1.0)
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..check import audit_row, rounded
from ..errors import ProblemError
from .chain import solve_chain
from .cycle import Cycle, Stationary, run_cycle, stationary_points, stroke
from .dyads import State
from .problem import CycleProblem
from .quantities import UNITS, derivatives, parse_name, position_name, value


@dataclass(frozen=True)
class CycleResult:
    """The solved problem: the cycle, its answers (rounded), stationary points, audit rows and warnings."""

    problem: CycleProblem
    cycle: Cycle
    answers: dict[str, float]
    stationary: tuple[Stationary, ...]
    published: tuple[dict, ...]
    warnings: tuple[str, ...]
    at_state: State | None = None

    def column(self, name: str) -> np.ndarray:
        """The quantity ``name`` at every crank angle of the table."""
        return value(self.cycle.state, name)


def unit_of(name: str) -> str:
    """The unit of a quantity or of an answer about it."""
    if name.startswith(("K(", "theta(", "increasing(", "decreasing(", "at_max(", "at_min(")):
        return "" if name.startswith("K(") else "deg"
    inner = name[name.index("(") + 1:-1] if name.startswith(("min(", "max(", "stroke(")) else name
    return UNITS[parse_name(inner)[1] if parse_name(inner)[0] != "gamma" else "gamma"]


def scale_of(name: str, m) -> float:
    """The scale at which a value of ``name`` is rounded: lengths at the linkage's size, speeds at size·|ω|,
    accelerations at size·(ω² + |ε|), angles and ratios at 1, angular speeds at |ω|, angular accelerations at
    ω² + |ε|."""
    unit = unit_of(name)
    w, e = abs(m.crank.omega), abs(m.crank.epsilon)
    return {"mm": m.scale(), "mm/s": m.scale() * w, "mm/s²": m.scale() * (w * w + e), "rad/s": w,
            "rad/s²": w * w + e}.get(unit, 1.0)


def solve_cycle(p: CycleProblem) -> CycleResult:
    """Solve the problem: assembly over the range (dead points refused), the table, extremes, strokes, audit."""
    m = p.mechanism
    cyc = run_cycle(m, p.phi_deg)
    answers: dict[str, float] = {}
    found: list[Stationary] = []
    warnings = [f"change point of dyad '{c.dyad}' at crank angle {c.phi_deg:.6f}°: its links fall collinear; "
                f"the named branch is kept through it" for c in cyc.changes]
    lo, hi = math.radians(float(p.phi_deg[0])), math.radians(float(p.phi_deg[-1]))
    known: dict[tuple[str, float, float], list[Stationary]] = {}

    def points(q: str, start: float = 0.0, stop: float = 2 * math.pi) -> list[Stationary]:
        """stationary_points of ``m``, each (output, range) searched once per problem (an output listed in
        extremes and strokes, a stroke's warning: the same search, the same points)."""
        k = (q, start, stop)
        if k not in known:
            known[k] = stationary_points(m, q, start, stop)
        return known[k]

    for q in p.extremes:
        base = position_name(q)
        if base != q:
            raise ProblemError(f"cycle.extremes: '{q}' is not a position (extremes of {base} are found as the roots "
                               f"of its velocity; list '{base}')")
        pts = points(q, lo, hi)
        found += pts
        vals = [s.value for s in pts]
        ends = [float(x) for x in value(cyc.state, q)[[0, -1]]]
        answers[f"min({q})"] = min(vals + ends)
        if base.startswith("gamma("):       # γ peaks at 90° where μ crosses it, not where μ is stationary
            mu = np.degrees(derivatives(cyc.state, q)[0]) % 180.0
            answers[f"max({q})"] = 90.0 if np.any(np.diff(np.sign(mu - 90.0)) != 0) else max(vals + ends)
        else:
            answers[f"max({q})"] = max(vals + ends)
    for q in p.strokes:
        s = stroke(m, q, points(q))
        answers[f"stroke({q})"] = s.stroke
        answers[f"at_max({q})"], answers[f"at_min({q})"] = s.at_max, s.at_min
        if s.K is not None:
            answers[f"increasing({q})"], answers[f"decreasing({q})"] = s.increasing, s.decreasing
            answers[f"K({q})"], answers[f"theta({q})"] = s.K, s.theta
        else:
            warnings.append(f"'{q}' has {sum(1 for x in points(q) if x.kind != 'flat')} extremes per "
                            "turn: K is not defined (stroke = largest maximum − smallest minimum)")
    answers = {k: rounded(v, scale_of(k, m)) for k, v in answers.items()}
    audit = []
    for k, v in p.published.items():
        if k not in answers:
            raise ProblemError(f"published.{k}: not an answer of this problem (answers: {', '.join(answers)})")
        row = audit_row(k, v, answers[k], scale_of(k, m))
        audit.append(row)
        if row["doubtful"]:
            warnings.append(f"printed {k} = {v:g} is off the exact {answers[k]:g}")
    at_state = None
    if p.at:
        at_state = solve_chain(m, np.radians(np.array(p.at)))
        for name, margin in at_state.margins.items():
            bad = [a for a, x in zip(p.at, margin) if not x > 0]
            if bad:
                raise ProblemError(f"cycle.at: dyad '{name}' cannot be assembled (or is at a dead point) at crank "
                                   f"angle {bad[0]:g}°")
    return CycleResult(p, cyc, answers, tuple(found), tuple(audit), tuple(warnings), at_state)
