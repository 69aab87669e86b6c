"""Random valid problems of ``cam.base_radius``: translating followers (knife/roller pitch curve, offset e given
or best, either sense of rotation, all five laws, a return limit or not) and oscillating arms (L, centre
distance a given or best, either arm side and sense).

What is expected is found here by brute force, independently of the construction and of the twin: the motion
laws written out again, the pressure angle's closed form evaluated on a dense grid of cam angles (no
stationary points, no refinement), and

- translating: s0(e) = max over the grid of |s′ − k·e|/tan α_allow − s, r0(e) = √(e² + s0²), minimised over
  e by golden section (r0² is convex in e);
- oscillating: at a centre distance a, the arm angles ψ0 that keep tan α = |L(1 − εψ′) − a cos φ|/(a sin φ)
  ≤ tan α_allow at every grid position form an interval; its lower end gives r0 = √((a − L)² + 4aL sin²(ψ0/2)),
  and with a free r0 is minimised over a log-spaced scan of a refined by golden section.

A grid underestimates a maximum by O(Δ²); the tolerance of each expected value is ten times the change
between the grid and one of half its spacing, plus 1e-9 of the scale, so a wrong optimum (a missed
constraint, a local minimum, the wrong end of an interval) shows while the grid's own error does not.

Near-degenerate cases: α_allow small (0.5–3°) and large (80–89°), tiny (1e-3) and huge (1e6) scales, e = 0
and e near the largest useful offset, a just above the smallest admissible centre distance, arm strokes
wider than 2α_allow (a bounded admissible region), drafted data rounded to 4 decimals.

Examples
--------
>>> import random
>>> c = GENERATORS["cam.base_radius.translating"](random.Random(1))
>>> c.problem["recipe"], sorted(c.expect)
('cam.base_radius', ['r0'])
"""
from __future__ import annotations

import math
import random
from typing import Any

import numpy as np

from .case import ValidCase

LAWS = ("uniform", "parabolic", "cosine", "cycloidal", "poly345")
N_GRID = 1601
"""Cam angles per constrained part of the brute force (and 2·N_GRID − 1 for its error estimate)."""
REL = 1e-9


def _law(name: str, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(f, f′) of a normalised law on [0, 1], written out again (independent of geomcon.cam.laws)."""
    if name == "uniform":
        return x, np.ones_like(x)
    if name == "parabolic":
        lo = x < 0.5
        return np.where(lo, 2 * x * x, 1 - 2 * (1 - x) ** 2), np.where(lo, 4 * x, 4 * (1 - x))
    if name == "cosine":
        return (1 - np.cos(np.pi * x)) / 2, np.pi / 2 * np.sin(np.pi * x)
    if name == "cycloidal":
        return x - np.sin(2 * np.pi * x) / (2 * np.pi), 1 - np.cos(2 * np.pi * x)
    return 10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5, 30 * x * x * (1 - x) ** 2


KINKS = {"parabolic": (0.5,)}
"""Interior points of a law where f′ has a corner (f″ jumps): the brute force cuts its grid there, so that
:func:`_peak` never rounds a corner into a parabola (that overshoots the true maximum by O(Δ))."""


def _pieces(name: str, n: int) -> list[np.ndarray]:
    """Grids of n points on each smooth piece of a law on [0, 1] (ends and corners included).

    >>> [(float(x[0]), float(x[-1])) for x in _pieces("parabolic", 5)]
    [(0.0, 0.5), (0.5, 1.0)]
    """
    cuts = (0.0, *KINKS.get(name, ()), 1.0)
    return [np.linspace(lo, hi, n) for lo, hi in zip(cuts[:-1], cuts[1:])]


def _program(rng: random.Random) -> list[dict[str, Any]]:
    """Rise, dwell, return, dwell (dwells sometimes absent), random laws and angles."""
    rise, ret = rng.uniform(60, 200), rng.uniform(60, 160)
    rest = 360.0 - rise - ret
    if rest < 0:
        ret += rest - 10.0
        rest = 10.0
    d1 = rng.uniform(0, rest) if rng.random() < 0.8 else 0.0
    prog = [{"kind": "rise", "angle": rise, "law": rng.choice(LAWS)}]
    if d1 > 0:
        prog.append({"kind": "dwell", "angle": d1})
    prog.append({"kind": "return", "angle": ret, "law": rng.choice(LAWS)})
    if rest - d1 > 0:
        prog.append({"kind": "dwell", "angle": rest - d1})
    else:
        prog[-1]["angle"] = 360.0 - sum(p["angle"] for p in prog[:-1])
    return prog


def _parts(program: list[dict[str, Any]], g: dict[str, Any], n: int) -> list[tuple[np.ndarray, np.ndarray, float]]:
    """(s, s′ per radian, tan α_allow) on n cam angles (ends included) of each smooth piece of each constrained
    part; s in the unit of h (mm, or radians for an arm)."""
    out, level = [], 0.0
    h = g["h"] if g.get("motion", "translating") == "translating" else math.radians(g["h"])
    for seg in program:
        if seg["kind"] != "dwell":
            allow = g["alpha_allow"] if seg["kind"] == "rise" else g.get("alpha_allow_return")
            if allow is not None and not any(p[3] == seg["kind"] for p in out):
                sign = 1.0 if seg["kind"] == "rise" else -1.0
                for x in _pieces(seg["law"], n):
                    f, f1 = _law(seg["law"], x)
                    out.append((level + sign * h * f, sign * h * f1 / math.radians(seg["angle"]),
                                math.tan(math.radians(allow)), seg["kind"]))
            level += h if seg["kind"] == "rise" else -h
    return [p[:3] for p in out]


def _peak(y: np.ndarray) -> np.ndarray:
    """The largest value along the last axis, every peak inside the grid raised to the vertex of the parabola
    through it and its neighbours (error O(Δ³) instead of O(Δ²) on a smooth peak).

    >>> x = np.linspace(0.0, 3.0, 301)
    >>> round(float(_peak(np.sin(x))), 6)
    1.0
    """
    y0, y1, y2 = y[..., :-2], y[..., 1:-1], y[..., 2:]
    curv = y0 - 2.0 * y1 + y2
    with np.errstate(divide="ignore", invalid="ignore"):
        lift = np.where((y1 >= y0) & (y1 >= y2) & (curv < 0), -(y0 - y2) ** 2 / (8.0 * curv), 0.0)
    lift = np.where(np.isfinite(lift), lift, 0.0)
    return np.maximum(np.max(y, axis=-1), np.max(y1 + lift, axis=-1))


def _golden_min(f, lo: float, hi: float, steps: int = 90) -> tuple[float, float]:
    """(min value, where) of a unimodal f on [lo, hi]."""
    inv = (math.sqrt(5) - 1) / 2
    c, d = hi - inv * (hi - lo), lo + inv * (hi - lo)
    fc, fd = f(c), f(d)
    for _ in range(steps):
        if fc <= fd:
            hi, d, fd = d, c, fc
            c = hi - inv * (hi - lo)
            fc = f(c)
        else:
            lo, c, fc = c, d, fd
            d = lo + inv * (hi - lo)
            fd = f(d)
    return (fc, c) if fc <= fd else (fd, d)


# ---------------------------------------------------------------------------- translating
def _translating_r0(g: dict[str, Any], n: int) -> float:
    """The brute-force smallest r0 (at the given e, or over e)."""
    k = 1.0 if g.get("rotation", "ccw") == "ccw" else -1.0
    parts = _parts(g["program"], g, n)

    def r0(e: float) -> float:
        s0 = max(float(_peak(np.abs(v - k * e) / t - s)) for s, v, t in parts)
        return math.hypot(e, s0) if s0 > 0 else math.inf
    if g.get("e") is not None:
        return r0(g["e"])
    span = g["h"] + max(float(np.max(np.abs(v))) for _, v, _ in parts)
    return _golden_min(r0, -span, span, 120)[0]


def translating(rng: random.Random) -> ValidCase:
    """A translating follower; expect the brute-force r0."""
    kind = "random"
    g: dict[str, Any] = {"h": rng.uniform(5, 80), "program": _program(rng), "alpha_allow": rng.uniform(12, 60),
                         "rotation": rng.choice(["ccw", "cw"])}
    if rng.random() < 0.4:
        g["alpha_allow_return"] = rng.uniform(20, 75)
    u = rng.random()
    if u < 0.08:
        g["alpha_allow"], kind = rng.uniform(0.5, 3.0), "near-degenerate: alpha_allow small"
    elif u < 0.16:
        g["alpha_allow"], kind = rng.uniform(80, 89), "near-degenerate: alpha_allow large"
    elif u < 0.24:
        f = rng.choice([1e-3, 1e6])
        g["h"], kind = g["h"] * f, f"near-degenerate: scale {f:g}"
    elif u < 0.30:
        g = {k: (round(v, 4) if isinstance(v, float) else v) for k, v in g.items()}
        kind = "near-degenerate: drafted (4 decimals)"
    if rng.random() < 0.3:
        e = rng.choice([0.0, rng.uniform(-0.4, 0.4) * g["h"], rng.uniform(-1.5, 1.5) * g["h"]])
        g["e"] = e
        if e == 0.0:
            kind = "near-degenerate: e = 0" if kind == "random" else kind
    fine, coarse = _translating_r0(g, 2 * N_GRID - 1), _translating_r0(g, N_GRID)
    tol = 10 * abs(fine - coarse) + REL * max(fine, g["h"])
    return ValidCase({"recipe": "cam.base_radius", "given": g}, {"r0": (fine, tol)}, kind)


# ---------------------------------------------------------------------------- oscillating
def _arm_arrays(g: dict[str, Any], n: int) -> list[tuple[np.ndarray, np.ndarray, float]]:
    """(ψ, c = L(1 − εψ′), α_allow in rad) on the grid of each constrained part."""
    sigma = 1 if g.get("rotation", "ccw") == "ccw" else -1
    tau = -1 if g.get("arm", "left") == "left" else 1
    return [(s, g["L"] * (1.0 - sigma * tau * v), math.atan(t)) for s, v, t in _parts(g["program"], g, n)]


def _arm_interval(parts, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The admissible arm angles ψ0 ∈ [lo, hi] at centre distances a (inverted where none)."""
    lo, hi = np.full(a.shape, -np.inf), np.full(a.shape, np.inf)
    for psi, c, al in parts:
        mu = c[None, :] * math.cos(al) / a[:, None]
        out = np.any(np.abs(mu) > 1.0, axis=1)
        b = np.arccos(np.clip(mu, -1.0, 1.0))
        lo = np.where(out, np.inf, np.maximum(lo, _peak(np.abs(b - al) - psi)))
        hi = np.minimum(hi, -_peak(psi - np.minimum(b + al, 2 * np.pi - b - al)))
    return lo, hi


def _r0(a, L, psi0):
    return np.sqrt((a - L) ** 2 + 4.0 * a * L * np.sin(psi0 / 2) ** 2)


def _arm_best(g: dict[str, Any], n: int) -> tuple[float, float, float] | None:
    """(r0, a, ψ0) by brute force; None when no scanned distance is admissible."""
    parts, L = _arm_arrays(g, n), g["L"]
    if g.get("a") is not None:
        lo, hi = _arm_interval(parts, np.array([g["a"]]))
        return (float(_r0(g["a"], L, lo[0])), g["a"], float(lo[0])) if lo[0] <= hi[0] else None
    a_min = max(float(np.max(np.abs(c))) * math.cos(al) for _, c, al in parts)
    avals = a_min * np.logspace(1e-9, 4, 400)
    lo, hi = _arm_interval(parts, avals)
    r = np.where(lo <= hi, _r0(avals, L, lo), np.inf)
    k = int(np.argmin(r))
    if not math.isfinite(r[k]):
        return None

    def f(x):
        l, h = _arm_interval(parts, np.array([x]))
        return float(_r0(x, L, l[0])) if l[0] <= h[0] else math.inf
    val, where = _golden_min(f, avals[max(k - 1, 0)], avals[min(k + 1, avals.size - 1)])
    if val > r[k]:
        val, where = float(r[k]), float(avals[k])
    l, _ = _arm_interval(parts, np.array([where]))
    return val, where, float(l[0])


def oscillating(rng: random.Random) -> ValidCase:
    """An arm follower; expect the brute-force r0 (and ψ0 at a given a)."""
    while True:
        kind = "random"
        g: dict[str, Any] = {"motion": "oscillating", "L": rng.uniform(40, 160), "h": rng.uniform(8, 35),
                             "program": _program(rng), "alpha_allow": rng.uniform(28, 50),
                             "rotation": rng.choice(["ccw", "cw"]), "arm": rng.choice(["left", "right"])}
        if rng.random() < 0.5:
            g["alpha_allow_return"] = rng.uniform(35, 70)
        u = rng.random()
        if u < 0.08:
            g["h"], kind = rng.uniform(2.2, 3.0) * g["alpha_allow"], "near-degenerate: h > 2·alpha_allow (bounded region)"
            g["h"] = min(g["h"], 150.0)
        elif u < 0.16:
            f = rng.choice([1e-3, 1e6])
            g["L"], kind = g["L"] * f, f"near-degenerate: scale {f:g}"
        elif u < 0.22:
            g["alpha_allow"], kind = rng.uniform(60, 85), "near-degenerate: alpha_allow large"
        elif u < 0.28:
            g = {k: (round(v, 4) if isinstance(v, float) else v) for k, v in g.items()}
            kind = "near-degenerate: drafted (4 decimals)"
        free = _arm_best(g, N_GRID)
        if free is None or math.degrees(free[2]) + g["h"] >= 179.0:
            continue
        if rng.random() < 0.5:
            near = rng.random() < 0.15
            parts = _arm_arrays(g, N_GRID)
            avals = free[1] * np.logspace(-1.0, 1.0, 401)
            lo, hi = _arm_interval(parts, avals)
            ok = avals[(lo + 1e-6 < hi) & (avals <= 1e9)]
            if ok.size == 0:
                continue
            if near:
                g["a"], kind = float(ok[0]) * 1.001, "near-degenerate: a just above the nearest admissible distance"
            else:
                g["a"] = float(ok[rng.randrange(ok.size)])
        fine, coarse = _arm_best(g, 2 * N_GRID - 1), _arm_best(g, N_GRID)
        if fine is None or coarse is None:
            continue
        scale = max(g["L"], fine[1])
        expect = {"r0": (fine[0], 10 * abs(fine[0] - coarse[0]) + REL * scale)}
        if g.get("a") is not None:
            expect["psi0"] = (math.degrees(fine[2]), 10 * math.degrees(abs(fine[2] - coarse[2])) + REL * 360)
        return ValidCase({"recipe": "cam.base_radius", "given": g}, expect, kind)


GENERATORS = {"cam.base_radius.translating": translating, "cam.base_radius.oscillating": oscillating}
