"""The speed reference of ``geomcon bench``'s lean-core table: the same constructions as a plain lazy DAG.

Each function below builds the steps of one recipe's scene, key for key and in the same order, as a plain
dict ``key → (function, dependency keys)`` of float code (points are tuples, circles ``(cx, cy, r)``, lines
``(px, py, dx, dy)``; no geomcon objects, no captions, no checks), culls it to what the answers need and
computes those steps once. It is what the scene machinery costs at the very least; the bench reports a
solve's time as a multiple of it. A test checks that it gives the recipe's answers.

Examples
--------
>>> a = crank_rocker_plain({"AB": 50.0, "BC": 70.0, "CD": 80.0, "AD": 90.0})
>>> round(a["theta"], 9), round(a["gamma_min"], 9)
(12.505586093, 29.994725527)
>>> round(crank_slider_design_plain({"K": 1.5, "H": 50.0, "e": 20.0})["AB"], 9)
21.50674666
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping

Steps = dict[str, tuple[Callable[..., Any], tuple[str, ...]]]


def evaluate(steps: Steps, want: tuple[str, ...]) -> dict[str, Any]:
    """Cull ``steps`` to what ``want`` needs, compute those in insertion order, once each."""
    need: set[str] = set()
    todo = list(want)
    while todo:
        k = todo.pop()
        if k not in need:
            need.add(k)
            todo.extend(steps[k][1])
    memo: dict[str, Any] = {}
    for k, (fn, deps) in steps.items():
        if k in need:
            memo[k] = fn(*[memo[d] for d in deps])
    return {k: memo[k] for k in want}


def _drawn(*args: Any) -> tuple:
    """A drawing-only step (a bar, a mark): never computed for answers."""
    return args


def _sum_less(x: float, y: float, z: float) -> float:
    big, small = (x, y) if x >= y else (y, x)
    return (big - z) + small


def circle_circle_above(c1: tuple, c2: tuple, up: bool) -> tuple[float, float]:
    """The intersection of two circles on the upper (or lower) side, Heron's half-chord as geomcon's."""
    (x1, y1, r1), (x2, y2, r2) = c1, c2
    vx, vy = x2 - x1, y2 - y1
    d = math.hypot(vx, vy)
    big, small = (d, r1) if d >= r1 else (r1, d)
    a = ((big - r2) * (big + r2) + small * small) / (2.0 * d)
    h = math.sqrt(_sum_less(r1, r2, d) * _sum_less(d, r2, r1) * _sum_less(d, r1, r2) * (d + r1 + r2)) / (2.0 * d)
    ux, uy = vx / d, vy / d
    p = (x1 + ux * a - uy * h, y1 + uy * a + ux * h)
    q = (x1 + ux * a + uy * h, y1 + uy * a - ux * h)
    return (p if p[1] > q[1] else q) if up else (p if p[1] < q[1] else q)


def angle_deg(o: tuple, a: tuple, b: tuple) -> float:
    """∠aob in degrees."""
    ux, uy, vx, vy = a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]
    return math.degrees(abs(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)))


def along(o: tuple, t: tuple, dist: float) -> tuple[float, float]:
    """The point at ``dist`` from ``o`` towards ``t``."""
    dx, dy = t[0] - o[0], t[1] - o[1]
    n = math.hypot(dx, dy)
    return (o[0] + dx / n * dist, o[1] + dy / n * dist)


def transmission(b: tuple, c: tuple, d: tuple) -> float:
    """The acute form of ∠bcd in degrees."""
    g = angle_deg(c, b, d)
    return min(g, 180.0 - g)


def crank_rocker_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``crank_rocker.extremes`` (45 steps) as a plain lazy DAG; returns its eight answers."""
    AB, BC, CD, AD = g["AB"], g["BC"], g["CD"], g["AD"]
    up = g.get("branch", "above") != "below"
    S: Steps = {
        "A": (lambda: (0.0, 0.0), ()), "A_ground": (_drawn, ("A",)),
        "D": (lambda: (AD, 0.0), ()), "D_ground": (_drawn, ("D",)), "AD": (_drawn, ("A", "D")),
        "kD": (lambda D: (D[0], D[1], CD), ("D",)),
        "r1": (lambda: BC - AB, ()), "k1": (lambda A, r: (A[0], A[1], r), ("A", "r1")),
        "C1": (lambda k, kD: circle_circle_above(k, kD, up), ("k1", "kD")),
        "r2": (lambda: BC + AB, ()), "k2": (lambda A, r: (A[0], A[1], r), ("A", "r2")),
        "C2": (lambda k, kD: circle_circle_above(k, kD, up), ("k2", "kD")),
        "B1": (lambda A, C: along(A, C, -AB), ("A", "C1")), "B2": (lambda A, C: along(A, C, AB), ("A", "C2")),
        "AB1": (_drawn, ("A", "B1")), "B1C1": (_drawn, ("B1", "C1")), "C1D": (_drawn, ("C1", "D")),
        "AB2": (_drawn, ("A", "B2")), "B2C2": (_drawn, ("B2", "C2")), "C2D": (_drawn, ("C2", "D")),
        "AC2": (_drawn, ("A", "C2")),
        "theta": (angle_deg, ("A", "C1", "C2")),
        "K": (lambda t: (180.0 + t) / (180.0 - t), ("theta",)),
        "psi": (angle_deg, ("D", "C1", "C2")),
        "angle_C1AD": (angle_deg, ("A", "C1", "D")), "angle_C2AD": (angle_deg, ("A", "C2", "D")),
    }
    for i, sign in ((1, 1.0), (2, -1.0)):
        S[f"Bg{i}"] = (lambda A, D, s=sign: along(A, D, s * AB), ("A", "D"))
        S[f"kBg{i}"] = (lambda B: (B[0], B[1], BC), (f"Bg{i}",))
        S[f"Cg{i}"] = (lambda k, kD: circle_circle_above(k, kD, up), (f"kBg{i}", "kD"))
        S[f"g{i}_AB"] = (_drawn, ("A", f"Bg{i}"))
        S[f"g{i}_BC"] = (_drawn, (f"Bg{i}", f"Cg{i}"))
        S[f"g{i}_CD"] = (_drawn, (f"Cg{i}", "D"))
        S[f"gamma_{i}"] = (transmission, (f"Bg{i}", f"Cg{i}", "D"))
    S["gamma_min"] = (min, ("gamma_1", "gamma_2"))
    S["mark_theta"] = (_drawn, ("A", "C1", "C2", "theta"))
    S["mark_psi"] = (_drawn, ("D", "C1", "C2", "psi"))
    S["mark_gamma_1"] = (_drawn, ("Cg1", "Bg1", "D", "gamma_1"))
    S["mark_gamma_2"] = (_drawn, ("Cg2", "Bg2", "D", "gamma_2"))
    return evaluate(S, ("theta", "psi", "K", "gamma_min", "gamma_1", "gamma_2", "angle_C1AD", "angle_C2AD"))


def _circumcircle(a: tuple, b: tuple, c: tuple) -> tuple[float, float, float]:
    bx, by, cx, cy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
    d = 2.0 * (bx * cy - by * cx)
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    ox, oy = (cy * b2 - by * c2) / d, (bx * c2 - cx * b2) / d
    return (a[0] + ox, a[1] + oy, math.hypot(ox, oy))


def _left_on_level(k: tuple, y: float) -> tuple[float, float]:
    """The left intersection of the circle ``k`` with the horizontal line at height ``y``."""
    cx, cy, r = k
    return (cx - math.sqrt((r - (y - cy)) * (r + (y - cy))), y)


def _pressure_from_gap(BC: float, gap: float) -> float:
    gap = max(0.0, gap)
    return math.degrees(math.atan2(BC - gap, math.sqrt(gap * (2.0 * BC - gap))))


def crank_slider_design_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``crank_slider.design_by_K`` with the offset e given (62 steps) as a plain lazy DAG; its nine answers."""
    K, H, e = g["K"], g["H"], g["e"]
    dist = math.dist
    S: Steps = {
        "C1": (lambda: (0.0, 0.0), ()), "C2": (lambda: (H, 0.0), ()),
        "guide": (lambda C1: (C1[0], C1[1], 1.0, 0.0), ("C1",)),
        "theta": (lambda: 180.0 * (K - 1.0) / (K + 1.0), ()), "K": (lambda: float(K), ()),
        "n2": (lambda C1, C2: (C2[0], C2[1], 0.0, 1.0), ("C1", "C2")),
        "compl": (lambda t: 90.0 - t, ("theta",)),
        "rP": (lambda C1, C2, a: (C1[0], C1[1], math.cos(math.radians(a)), math.sin(math.radians(a))),
               ("C1", "C2", "compl")),
        "P": (lambda r, n: (n[0], r[1] + r[3] / r[2] * (n[0] - r[0])), ("rP", "n2")),
        "kTheta": (_circumcircle, ("C1", "C2", "P")),
        "n1": (lambda gl, C1: (C1[0], C1[1], 0.0, 1.0), ("guide", "C1")),
        "Q": (lambda n, k, C1: (C1[0], 2.0 * k[1]), ("n1", "kTheta", "C1")),
        "arc_ok": (_drawn, ("kTheta", "Q", "C1", "C2")),
        "Pe": (lambda n: (n[0], n[1] + e), ("n1",)),
        "le": (lambda gl, p: (p[0], p[1], 1.0, 0.0), ("guide", "Pe")),
        "A": (lambda le, k, C1: _left_on_level(k, le[1]), ("le", "kTheta", "C1")),
        "AC1": (_drawn, ("A", "C1")), "AC2s": (_drawn, ("A", "C2")),
        "AC1_len": (dist, ("A", "C1")),
        "Ea": (along, ("A", "C2", "AC1_len")),
        "M": (lambda E, C2: ((E[0] + C2[0]) / 2.0, (E[1] + C2[1]) / 2.0), ("Ea", "C2")),
        "AB": (dist, ("Ea", "M")), "BC": (dist, ("A", "M")),
        "Fa": (lambda gl, A: (A[0], gl[1]), ("guide", "A")),
        "e": (dist, ("A", "Fa")), "AC1_out": (dist, ("A", "C1")), "AC2_out": (dist, ("A", "C2")),
        "minus_AB": (lambda x: -x, ("AB",)),
        "B1": (along, ("A", "C1", "minus_AB")), "B2": (along, ("A", "C2", "AB")),
        "AB1": (_drawn, ("A", "B1")), "B1C1": (_drawn, ("B1", "C1")), "slider1": (_drawn, ("C1",)),
        "AB2": (_drawn, ("A", "B2")), "B2C2": (_drawn, ("B2", "C2")), "slider2": (_drawn, ("C2",)),
        "FC1": (dist, ("Fa", "C1")),
        "gap": (lambda fc1, ac1, ee: fc1 * fc1 / (ac1 + ee), ("FC1", "AC1_len", "e")),
        "nA": (_drawn, ("guide", "A")),
    }
    for i, sign in ((3, 1.0), (4, -1.0)):
        S[f"B{i}"] = (_drawn, ("nA", "AB"))
        S[f"kB{i}"] = (_drawn, (f"B{i}", "BC"))
        S[f"C{i}"] = (_drawn, ("guide", f"kB{i}", f"B{i}"))
        S[f"AB{i}"] = (_drawn, ("A", f"B{i}"))
        S[f"B{i}C{i}"] = (_drawn, (f"B{i}", f"C{i}"))
    S.update({
        "alpha_3": (_pressure_from_gap, ("BC", "gap")),
        "alpha_4": (_drawn, ("B4", "C4", "guide")), "alpha_1": (_drawn, ("B1", "C1", "guide")),
        "alpha_max": (lambda a: a, ("alpha_3",)), "gamma_min": (lambda a: 90.0 - a, ("alpha_3",)),
        "gamma_min_fast": (lambda a: 90.0 - a, ("alpha_3",)),
        "alpha_slow": (_drawn, ("alpha_1", "alpha_4")), "gamma_min_slow": (_drawn, ("alpha_slow",)),
        "mark_alpha": (_drawn, ("C3", "B3", "guide", "alpha_3")), "A_ground": (_drawn, ("A",)),
        "theta_at_A": (angle_deg, ("A", "C1", "C2")), "mark_theta": (_drawn, ("A", "C1", "C2", "theta")),
        "dim_H": (_drawn, ("C1", "C2")),
    })
    out = evaluate(S, ("AB", "BC", "e", "theta", "K", "alpha_max", "gamma_min", "AC1_out", "AC2_out"))
    out["AC1"], out["AC2"] = out.pop("AC1_out"), out.pop("AC2_out")
    return out


PLAIN: dict[str, Callable[[Mapping[str, Any]], dict[str, float]]] = {
    "crank_rocker.extremes": crank_rocker_plain,
    "crank_slider.design_by_K": crank_slider_design_plain,
}
"""Recipe name → its plain-DAG replica (givens as the recipe's; for design by K, the offset form)."""
