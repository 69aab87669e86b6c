"""The speed reference of ``geomcon bench``'s lean-core table: the same constructions as plain lazy DAGs.

Each ``*_plain`` function below builds the steps of one recipe's scene, key for key and in the same order, as a
plain dict ``key → (function, dependency keys)`` of float code — points are tuples ``(x, y)``, lines
``(px, py, ux, uy)`` with a unit direction, circles ``(cx, cy, r)``; no geomcon objects, no captions, no checks
— then culls it to what the answers need and computes those steps once each (:func:`evaluate`). The
intersections use geomcon's formulas (local frame, Heron's half-chord, the bisectors of a circumcircle) and the
recipes' branch rules (above a line, to the right of a point, farthest from a point …); drawing-only steps (bars,
marks) are in the dict but never computed. It is what the scene machinery costs at the very least; the bench
reports a solve's time as a multiple of it, and a test checks that every replica gives the recipe's answers.

Not modelled: the tolerance decisions (a tangency within 1e-13 of the scale counts as one point there; the
replicas see two, or none) and the recipes' refusals; each replica covers the problem form it says.

Examples
--------
>>> a = crank_rocker_plain({"AB": 50.0, "BC": 70.0, "CD": 80.0, "AD": 90.0})
>>> round(a["theta"], 9), round(a["gamma_min"], 9)
(12.505586093, 29.994725527)
>>> round(crank_slider_design_plain({"K": 1.5, "H": 50.0, "e": 20.0})["AB"], 9)
21.50674666
>>> round(guide_bar_plain({"AB": 145.0, "AC": 290.0})["psi"], 9)
60.0
>>> d = crank_rocker_design_plain({"K": 1.25, "CD": 290.0, "psi": 32.0, "BC": 260.0})
>>> round(d["AB"], 6), round(d["AD"], 6)
(66.98113, 261.012733)
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping, Sequence

from ..tolerance import REL_TOL

Steps = dict[str, tuple[Callable[..., Any], tuple[str, ...]]]
Pt = tuple[float, float]
Ln = tuple[float, float, float, float]
Circ = tuple[float, float, float]


def evaluate(steps: Steps, want: Sequence[str]) -> dict[str, Any]:
    """Cull ``steps`` to what ``want`` needs and compute those in insertion order, once each.

    A step one of whose dependencies is None (a missing intersection) is None itself, as an optional step of
    a scene is.

    >>> evaluate({"a": (lambda: 2.0, ()), "b": (lambda a: a * a, ("a",)), "c": (print, ("b",))}, ["b"])
    {'b': 4.0}
    """
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
            args = [memo[d] for d in deps]
            memo[k] = None if None in args else fn(*args)
    return {k: memo[k] for k in want}


def _drawn(*args: Any) -> tuple:
    """A drawing-only step (a bar, a mark, a ghost position): never computed for answers."""
    return args


# ------------------------------------------------------------------------------------------ plain geometry
def unit(x: float, y: float) -> Pt:
    """(x, y) scaled to length 1."""
    n = math.hypot(x, y)
    return x / n, y / n


def line(p: Pt, d: Pt) -> Ln:
    """The line through ``p`` with direction ``d`` (made unit)."""
    ux, uy = unit(d[0], d[1])
    return (p[0], p[1], ux, uy)


def dist(a: Pt, b: Pt) -> float:
    """|ab|."""
    return math.hypot(b[0] - a[0], b[1] - a[1])


def midpoint(a: Pt, b: Pt) -> Pt:
    """The midpoint of ab."""
    return ((a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0)


def along(o: Pt, t: Pt, d: float) -> Pt:
    """The point at signed distance ``d`` from ``o`` towards ``t``."""
    ux, uy = unit(t[0] - o[0], t[1] - o[1])
    return (o[0] + ux * d, o[1] + uy * d)


def at(ln: Ln, t: float) -> Pt:
    """The point of ``ln`` at signed distance ``t`` from its point."""
    return (ln[0] + ln[2] * t, ln[1] + ln[3] * t)


def cross(ax: float, ay: float, bx: float, by: float) -> float:
    """a × b."""
    return ax * by - ay * bx


def angle_deg(o: Pt, a: Pt, b: Pt) -> float:
    """∠aob in degrees, in [0, 180]."""
    ux, uy, vx, vy = a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]
    return math.degrees(abs(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)))


def k_ratio(theta: float) -> float:
    """K = (180° + θ)/(180° − θ)."""
    return (180.0 + theta) / (180.0 - theta)


def _sum_less(x: float, y: float, z: float) -> float:
    big, small = (x, y) if x >= y else (y, x)
    return (big - z) + small


def circle_circle(c1: Circ, c2: Circ) -> tuple[Pt, ...]:
    """The intersections of two circles, in the local frame of the first centre, Heron's half-chord (as
    geomcon's): ``()`` when they miss."""
    ox, oy, r1 = c1
    r2 = c2[2]
    vx, vy = c2[0] - ox, c2[1] - oy
    d = math.hypot(vx, vy)
    if d == 0.0 or d > r1 + r2 or abs(r1 - r2) > d:
        return ()
    ux, uy = vx / d, vy / d
    big, small = (d, r1) if d >= r1 else (r1, d)
    a = ((big - r2) * (big + r2) + small * small) / (2.0 * d)
    h = math.sqrt(_sum_less(r1, r2, d) * _sum_less(d, r2, r1) * _sum_less(d, r1, r2) * (d + r1 + r2)) / (2.0 * d)
    fx, fy, nx, ny = ux * a, uy * a, -uy * h, ux * h
    return ((ox + (fx + nx), oy + (fy + ny)), (ox + (fx - nx), oy + (fy - ny)))


def line_circle(ln: Ln, k: Circ) -> tuple[Pt, ...]:
    """The intersections of a line and a circle, ordered along the line (as geomcon's): ``()`` when they miss."""
    px, py, ux, uy = ln
    wx, wy = px - k[0], py - k[1]
    t0 = -(wx * ux + wy * uy)
    ap = abs(ux * wy - uy * wx)
    r = k[2]
    if ap > r:
        return ()
    h = math.sqrt((r - ap) * (r + ap))
    t1, t2 = t0 - h, t0 + h
    return ((px + ux * t1, py + uy * t1), (px + ux * t2, py + uy * t2))


def line_line(l1: Ln, l2: Ln) -> Pt | None:
    """The crossing of two lines (None when parallel)."""
    wx, wy = l2[0] - l1[0], l2[1] - l1[1]
    s = cross(l1[2], l1[3], l2[2], l2[3])
    if s == 0.0:
        return None
    t = cross(wx, wy, l2[2], l2[3]) / s
    return (l1[0] + l1[2] * t, l1[1] + l1[3] * t)


def circle_through3(a: Pt, b: Pt, c: Pt) -> Circ:
    """The circumcircle, as the crossing of the perpendicular bisectors of ab and bc (as geomcon's)."""
    abx, aby = b[0] - a[0], b[1] - a[1]
    cbx, cby = c[0] - b[0], c[1] - b[1]
    d1x, d1y = unit(-aby, abx)
    d2x, d2y = unit(-cby, cbx)
    m1x, m1y = (a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0
    m2x, m2y = (b[0] + c[0]) / 2.0, (b[1] + c[1]) / 2.0
    wx, wy = m2x - m1x, m2y - m1y
    t = (wx * d2y - wy * d2x) / (d1x * d2y - d1y * d2x)
    ox, oy = m1x + d1x * t, m1y + d1y * t
    return (ox, oy, math.hypot(a[0] - ox, a[1] - oy))


def thales(a: Pt, b: Pt) -> Circ:
    """The circle on ab as diameter."""
    return ((a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, math.hypot(b[0] - a[0], b[1] - a[1]) / 2.0)


def perpendicular(ln: Ln, p: Pt) -> Ln:
    """The perpendicular to ``ln`` through ``p``, directed to the line's left."""
    return line(p, (-ln[3], ln[2]))


def perpendicular_at(a: Pt, b: Pt) -> Ln:
    """The perpendicular to ab at b."""
    return line(b, (-(b[1] - a[1]), b[0] - a[0]))


def ray_from(o: Pt, t: Pt, angle_deg_: float) -> Ln:
    """The ray (as a line) from ``o`` turned by ``angle_deg_`` from ``o → t``."""
    dx, dy = unit(t[0] - o[0], t[1] - o[1])
    a = math.radians(angle_deg_)
    c, s = math.cos(a), math.sin(a)
    return line(o, (c * dx - s * dy, s * dx + c * dy))


def foot(ln: Ln, p: Pt) -> Pt:
    """The foot of the perpendicular from ``p`` to ``ln``."""
    return at(ln, (p[0] - ln[0]) * ln[2] + (p[1] - ln[1]) * ln[3])


def seeing_circle(c1: Pt, c2: Pt, beta: float, side: int) -> Circ | None:
    """The circle through c1, c2 whose arc on ``side`` sees c1c2 under ``beta`` degrees (the θ-circle's steps)."""
    if abs(beta - 90.0) < 1e-12:
        return thales(c1, c2)
    p = line_line(ray_from(c1, c2, side * (90.0 - beta)), perpendicular_at(c1, c2))
    return None if p is None else circle_through3(c1, c2, p)


# ------------------------------------------------------------------------------------------ branch rules
def choose(cands: tuple[Pt, ...], score: Callable[[Pt], float]) -> Pt | None:
    """The candidate of larger score (the only one, or None when there is none)."""
    if len(cands) < 2:
        return cands[0] if cands else None
    return cands[0] if score(cands[0]) > score(cands[1]) else cands[1]


def above(cands: tuple[Pt, ...], a: Pt, b: Pt, sign: float = 1.0) -> Pt | None:
    """The candidate above the line ab (``sign`` −1: below)."""
    dx, dy = unit(b[0] - a[0], b[1] - a[1])
    nx, ny = (-dy, dx) if dx > 0 else (dy, -dx)
    return choose(cands, lambda p: sign * (nx * (p[0] - a[0]) + ny * (p[1] - a[1])))


def right_of(cands: tuple[Pt, ...], p: Pt) -> Pt | None:
    """The candidate to the right of ``p`` (larger x)."""
    return choose(cands, lambda q: q[0] - p[0])


def left_of(cands: tuple[Pt, ...], p: Pt) -> Pt | None:
    """The candidate to the left of ``p`` (smaller x)."""
    return choose(cands, lambda q: p[0] - q[0])


def farthest(cands: tuple[Pt, ...], p: Pt) -> Pt | None:
    """The candidate farthest from ``p`` (also the rule "other than p")."""
    return choose(cands, lambda q: dist(q, p))


# ------------------------------------------------------------------------------------------ measurements
def transmission(b: Pt, c: Pt, d: Pt) -> float:
    """The acute form of ∠bcd in degrees."""
    g = angle_deg(c, b, d)
    return min(g, 180.0 - g)


def pressure(b: Pt, c: Pt, guide: Ln) -> float:
    """The acute angle between the rod c→b and the guide's direction, degrees."""
    a = angle_deg((0.0, 0.0), (b[0] - c[0], b[1] - c[1]), (guide[2], guide[3]))
    return min(a, 180.0 - a)


def largest(*values: float) -> float:
    """The largest of the values."""
    return max(values)


def pressure_from_gap(BC: float, gap: float) -> float:
    """The largest pressure angle of a crank-slider from B3's gap to the guide (as the recipe's)."""
    gap = max(0.0, gap)
    return math.degrees(math.atan2(BC - gap, math.sqrt(gap * (2.0 * BC - gap))))


# ------------------------------------------------------------------------------------------ the replicas
def crank_rocker_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``crank_rocker.extremes`` (45 steps) as a plain lazy DAG; its eight answers."""
    AB, BC, CD, AD = g["AB"], g["BC"], g["CD"], g["AD"]
    side = -1.0 if g.get("branch", "above") == "below" else 1.0
    S: Steps = {
        "A": (lambda: (0.0, 0.0), ()), "A_ground": (_drawn, ("A",)),
        "D": (lambda: (AD, 0.0), ()), "D_ground": (_drawn, ("D",)), "AD": (_drawn, ("A", "D")),
        "kD": (lambda D: (D[0], D[1], CD), ("D",)),
        "r1": (lambda: BC - AB, ()), "k1": (lambda A, r: (A[0], A[1], r), ("A", "r1")),
        "C1": (lambda k, kD, A, D: above(circle_circle(k, kD), A, D, side), ("k1", "kD", "A", "D")),
        "r2": (lambda: BC + AB, ()), "k2": (lambda A, r: (A[0], A[1], r), ("A", "r2")),
        "C2": (lambda k, kD, A, D: above(circle_circle(k, kD), A, D, side), ("k2", "kD", "A", "D")),
        "B1": (lambda A, C: along(A, C, -AB), ("A", "C1")), "B2": (lambda A, C: along(A, C, AB), ("A", "C2")),
        "AB1": (_drawn, ("A", "B1")), "B1C1": (_drawn, ("B1", "C1")), "C1D": (_drawn, ("C1", "D")),
        "AB2": (_drawn, ("A", "B2")), "B2C2": (_drawn, ("B2", "C2")), "C2D": (_drawn, ("C2", "D")),
        "AC2": (_drawn, ("A", "C2")),
        "theta": (angle_deg, ("A", "C1", "C2")), "K": (k_ratio, ("theta",)),
        "psi": (angle_deg, ("D", "C1", "C2")),
        "angle_C1AD": (angle_deg, ("A", "C1", "D")), "angle_C2AD": (angle_deg, ("A", "C2", "D")),
    }
    for i, sign in ((1, 1.0), (2, -1.0)):
        S[f"Bg{i}"] = (lambda A, D, s=sign: along(A, D, s * AB), ("A", "D"))
        S[f"kBg{i}"] = (lambda B: (B[0], B[1], BC), (f"Bg{i}",))
        S[f"Cg{i}"] = (lambda k, kD, A, D: above(circle_circle(k, kD), A, D, side), (f"kBg{i}", "kD", "A", "D"))
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


def _pressure_steps(S: Steps, AB: Any, BC: Any, gap: Any) -> None:
    """The crank-slider's pressure-angle steps (``add_pressure_angles``): B3, B4 with the crank perpendicular to
    the guide, αmax from the gap, the slow stroke's from C1 and C4. ``AB``, ``BC``, ``gap`` are numbers or step
    keys (a tuple ``(key,)``)."""
    def ref(x: Any) -> tuple[tuple[str, ...], Callable[..., float]]:
        return (x, lambda v: v) if isinstance(x, tuple) else ((), lambda: x)

    S["nA"] = (perpendicular, ("guide", "A"))
    ab_deps, ab_fn = ref(AB)
    bc_deps, bc_fn = ref(BC)
    for i, sign in ((3, 1.0), (4, -1.0)):
        if i == 3:                                # drawn only: αmax comes from the gap
            S["B3"], S["kB3"], S["C3"] = (_drawn, ("nA",) + ab_deps), (_drawn, ("B3",) + bc_deps), (_drawn, ("guide", "kB3", "B3"))
        else:
            S["B4"] = (lambda n, *ab, s=sign: at(n, s * ab_fn(*ab)), ("nA",) + ab_deps)
            S["kB4"] = (lambda B, *bc: (B[0], B[1], bc_fn(*bc)), ("B4",) + bc_deps)
            S["C4"] = (lambda gl, k, B: right_of(line_circle(gl, k), B), ("guide", "kB4", "B4"))
        S[f"AB{i}"], S[f"B{i}C{i}"] = (_drawn, ("A", f"B{i}")), (_drawn, (f"B{i}", f"C{i}"))
    gap_deps, gap_fn = ref(gap)
    S["alpha_3"] = (lambda *v: pressure_from_gap(bc_fn(*v[:len(bc_deps)]), gap_fn(*v[len(bc_deps):])),
                    bc_deps + gap_deps)
    S["alpha_4"] = (pressure, ("B4", "C4", "guide"))
    S["alpha_1"] = (pressure, ("B1", "C1", "guide"))
    S["alpha_max"] = (largest, ("alpha_3",))
    S["gamma_min"] = (lambda a: 90.0 - a, ("alpha_3",))
    S["gamma_min_fast"] = (lambda a: 90.0 - a, ("alpha_3",))
    S["alpha_slow"] = (largest, ("alpha_1", "alpha_4"))
    S["gamma_min_slow"] = (lambda a: 90.0 - a, ("alpha_slow",))
    S["mark_alpha"] = (_drawn, ("C3", "B3", "guide", "alpha_3"))


def crank_slider_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``crank_slider.extremes`` (46 steps) as a plain lazy DAG; its seven answers."""
    AB, BC, e = g["AB"], g["BC"], g["e"]
    S: Steps = {
        "A": (lambda: (0.0, 0.0), ()), "A_ground": (_drawn, ("A",)),
        "F": (lambda: (0.0, -e), ()),
        "guide": (lambda F: line(F, (1.0, 0.0)), ("F",)),
        "dim_e": (_drawn, ("F", "A")),
        "r1": (lambda: BC - AB, ()), "k1": (lambda A, r: (A[0], A[1], r), ("A", "r1")),
        "C1": (lambda gl, k, A: right_of(line_circle(gl, k), A), ("guide", "k1", "A")),
        "r2": (lambda: BC + AB, ()), "k2": (lambda A, r: (A[0], A[1], r), ("A", "r2")),
        "C2": (lambda gl, k, A: right_of(line_circle(gl, k), A), ("guide", "k2", "A")),
        "B1": (lambda A, C: along(A, C, -AB), ("A", "C1")), "B2": (lambda A, C: along(A, C, AB), ("A", "C2")),
        "AB1": (_drawn, ("A", "B1")), "B1C1": (_drawn, ("B1", "C1")), "slider1": (_drawn, ("C1",)),
        "AB2": (_drawn, ("A", "B2")), "B2C2": (_drawn, ("B2", "C2")), "slider2": (_drawn, ("C2",)),
        "guide_mark": (_drawn, ("C1", "C2", "guide")), "AC2": (_drawn, ("A", "C2")),
        "H": (dist, ("C1", "C2")),
        "theta": (angle_deg, ("A", "C1", "C2")), "K": (k_ratio, ("theta",)),
    }
    _pressure_steps(S, AB, BC, math.fsum((BC, -AB, -e)))
    S["mark_theta"] = (_drawn, ("A", "C1", "C2", "theta"))
    S["dim_H"] = (_drawn, ("C1", "C2", "H"))
    return evaluate(S, ("H", "theta", "K", "alpha_max", "gamma_min", "gamma_min_fast", "gamma_min_slow"))


def guide_bar_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``guide_bar.extremes`` (26 steps) as a plain lazy DAG; its three answers."""
    AB, AC = g["AB"], g["AC"]
    S: Steps = {
        "A": (lambda: (0.0, 0.0), ()), "A_ground": (_drawn, ("A",)),
        "C": (lambda: (0.0, -AC), ()), "C_ground": (_drawn, ("C",)), "AC": (_drawn, ("A", "C")),
        "kB": (lambda A: (A[0], A[1], AB), ("A",)),
        "kT": (thales, ("A", "C")),
        "B1": (lambda kB, kT, A: left_of(circle_circle(kB, kT), A), ("kB", "kT", "A")),
        "B2": (lambda kB, kT, A: right_of(circle_circle(kB, kT), A), ("kB", "kT", "A")),
    }
    for i in (1, 2):
        S[f"E{i}"] = (lambda C, B: along(C, B, AC + AB), ("C", f"B{i}"))
        S[f"AB{i}"], S[f"CE{i}"] = (_drawn, ("A", f"B{i}")), (_drawn, ("C", f"E{i}"))
        S[f"slider{i}"], S[f"right{i}"] = (_drawn, (f"B{i}", "C")), (_drawn, (f"B{i}", "A", "C"))
    S.update({
        "B1x": (lambda A, B: along(A, B, -AB), ("A", "B1")), "ext1": (_drawn, ("A", "B1x")),
        "psi": (angle_deg, ("C", "B1", "B2")), "theta": (angle_deg, ("A", "B1x", "B2")), "K": (k_ratio, ("theta",)),
        "mark_psi": (_drawn, ("C", "B1", "B2", "psi")), "mark_theta": (_drawn, ("A", "B1x", "B2", "theta")),
    })
    return evaluate(S, ("theta", "psi", "K"))


def _theta_circle_steps(S: Steps, side: int, prefix: str = "") -> None:
    """The θ-circle's steps (``add_theta_circle``): C2P ⊥ C1C2, ∠C2C1P = 90° − θ, the circle C1C2P."""
    if "n2" not in S:
        S["n2"] = (perpendicular_at, ("C1", "C2"))
    S[f"{prefix}compl"] = (lambda th: side * (90.0 - th), ("theta",))
    S[f"{prefix}rP"] = (ray_from, ("C1", "C2", f"{prefix}compl"))
    S[f"{prefix}P"] = (line_line, (f"{prefix}rP", "n2"))
    S[f"{prefix}kTheta"] = (circle_through3, ("C1", "C2", f"{prefix}P"))


def crank_slider_design_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``crank_slider.design_by_K`` with the offset e given and K > 1 (62 steps) as a plain lazy DAG; its nine
    answers."""
    K, H, e = g["K"], g["H"], g.get("e")
    if e is None or K == 1.0:
        raise ValueError("the plain replica of crank_slider.design_by_K covers the form with e given and K > 1")
    S: Steps = {
        "C1": (lambda: (0.0, 0.0), ()), "C2": (lambda: (H, 0.0), ()),
        "guide": (lambda C1: line(C1, (1.0, 0.0)), ("C1",)),
        "theta": (lambda: 180.0 * (K - 1.0) / (K + 1.0), ()), "K": (lambda: float(K), ()),
    }
    _theta_circle_steps(S, +1)
    S.update({
        "n1": (perpendicular, ("guide", "C1")),
        "Q": (lambda n, k, C1: farthest(line_circle(n, k), C1), ("n1", "kTheta", "C1")),
        "arc_ok": (_drawn, ("kTheta", "Q", "C1", "C2")),
        "Pe": (lambda n: at(n, e), ("n1",)),
        "le": (lambda gl, p: line(p, (gl[2], gl[3])), ("guide", "Pe")),
        "A": (lambda le, k, C1: left_of(line_circle(le, k), C1), ("le", "kTheta", "C1")),
        "AC1": (_drawn, ("A", "C1")), "AC2s": (_drawn, ("A", "C2")),
        "AC1_len": (dist, ("A", "C1")),
        "Ea": (along, ("A", "C2", "AC1_len")),
        "M": (midpoint, ("Ea", "C2")),
        "AB": (dist, ("Ea", "M")), "BC": (dist, ("A", "M")),
        "Fa": (foot, ("guide", "A")),
        "e": (dist, ("A", "Fa")), "AC1_out": (dist, ("A", "C1")), "AC2_out": (dist, ("A", "C2")),
        "minus_AB": (lambda x: -x, ("AB",)),
        "B1": (along, ("A", "C1", "minus_AB")), "B2": (along, ("A", "C2", "AB")),
        "AB1": (_drawn, ("A", "B1")), "B1C1": (_drawn, ("B1", "C1")), "slider1": (_drawn, ("C1",)),
        "AB2": (_drawn, ("A", "B2")), "B2C2": (_drawn, ("B2", "C2")), "slider2": (_drawn, ("C2",)),
        "FC1": (dist, ("Fa", "C1")),
        "gap": (lambda fc1, ac1, ee: fc1 * fc1 / (ac1 + ee), ("FC1", "AC1_len", "e")),
    })
    _pressure_steps(S, ("AB",), ("BC",), ("gap",))
    S.update({
        "A_ground": (_drawn, ("A",)), "theta_at_A": (angle_deg, ("A", "C1", "C2")),
        "mark_theta": (_drawn, ("A", "C1", "C2", "theta")), "dim_H": (_drawn, ("C1", "C2")),
    })
    out = evaluate(S, ("AB", "BC", "e", "theta", "K", "alpha_max", "gamma_min", "AC1_out", "AC2_out"))
    out["AC1"], out["AC2"] = out.pop("AC1_out"), out.pop("AC2_out")
    return out


# ---------------------------------------------------------------- crank_rocker.design_by_K: the candidates' tests
def half_difference(A: Pt, P: Pt, Q: Pt) -> float:
    """|AQ − AP| / 2: the crank."""
    return abs(dist(A, Q) - dist(A, P)) / 2.0


def half_sum(A: Pt, P: Pt, Q: Pt) -> float:
    """(AP + AQ) / 2: the coupler."""
    return (dist(A, P) + dist(A, Q)) / 2.0


def folded_flag(A: Pt, P1: Pt, P2: Pt) -> float:
    """1.0 when P1 is nearer to A (the folded position)."""
    return 1.0 if dist(A, P1) < dist(A, P2) else 0.0


def near_flag(A: Pt, C1: Pt, C2: Pt, D: Pt) -> float:
    """1.0 when A and D lie on one side of the line C1C2."""
    ux, uy = C2[0] - C1[0], C2[1] - C1[1]
    return 1.0 if cross(ux, uy, A[0] - C1[0], A[1] - C1[1]) * cross(ux, uy, D[0] - C1[0], D[1] - C1[1]) > 0 else 0.0


def rocker_valid(A: Pt, P1: Pt, P2: Pt, D: Pt, CD: float, arc_side: int) -> bool:
    """A crank-rocker (Grashof, P1 and P2 strictly on one side of AD), A on the θ-arc's side of P1P2."""
    AD = dist(A, D)
    if AD == 0.0:
        return False
    a, b = half_difference(A, P1, P2), half_sum(A, P1, P2)
    if arc_side:
        cx, cy = P2[0] - P1[0], P2[1] - P1[1]
        if arc_side * cross(cx, cy, A[0] - P1[0], A[1] - P1[1]) <= REL_TOL * math.hypot(cx, cy) * max(b, CD, AD):
            return False
    ux, uy = D[0] - A[0], D[1] - A[1]
    h1 = cross(ux, uy, P1[0] - A[0], P1[1] - A[1]) / AD
    h2 = cross(ux, uy, P2[0] - A[0], P2[1] - A[1]) / AD
    scale = max(b, CD, AD)
    if not 0.0 < a or AD <= REL_TOL * scale or h1 * h2 <= 0 or min(abs(h1), abs(h2)) <= REL_TOL * scale:
        return False
    ls = sorted([b, CD, AD])
    return a < ls[0] and a + ls[2] <= ls[0] + ls[1] + REL_TOL * ls[2]


def excess_by_foot(V: Pt, P: Pt, Q: Pt) -> float:
    """|VP| + |VQ| − |PQ| through the foot of V on PQ (as the recipe's)."""
    x, y = dist(V, P), dist(V, Q)
    pqx, pqy = Q[0] - P[0], Q[1] - P[1]
    z = math.hypot(pqx, pqy)
    if z == 0.0:
        return x + y
    wx, wy = V[0] - P[0], V[1] - P[1]
    s = (wx * pqx + wy * pqy) / z
    if not 0.0 < s < z:
        return x + y - z
    h = abs(pqx * wy - pqy * wx) / z
    return h * h / (x + s) + h * h / (y + (z - s))


def gamma_min_of(A: Pt, D: Pt, P1: Pt, P2: Pt) -> float:
    """γmin of the designed linkage from its extreme positions (as the recipe's)."""
    Cf, Ce = (P1, P2) if dist(A, P1) < dist(A, P2) else (P2, P1)
    a, b = half_difference(A, P1, P2), half_sum(A, P1, P2)
    c, d = dist(D, Cf), dist(D, A)
    out = []
    for e_b, e_c, e_bd, per in ((excess_by_foot(D, A, Ce), excess_by_foot(A, D, Cf), excess_by_foot(Ce, A, D), b + c + d - a),
                                (excess_by_foot(D, A, Cf), excess_by_foot(A, D, Ce), excess_by_foot(Cf, A, D), b + c + d + a)):
        gm = math.degrees(2.0 * math.atan2(math.sqrt(max(0.0, e_b * e_c)), math.sqrt(max(0.0, per * e_bd))))
        out.append(min(gm, 180.0 - gm))
    return min(out)


def crank_rocker_design_plain(g: Mapping[str, Any]) -> dict[str, float]:
    """``crank_rocker.design_by_K`` with the swing ψ, the rocker CD and the coupler BC given, K > 1 (79 steps) as
    a plain lazy DAG; the answers of the textbook's choice among the valid candidates (C1 folded, then A on D's
    side, then the shorter frame)."""
    K, CD, psi, BC = g["K"], g.get("CD"), g.get("psi"), g.get("BC")
    if None in (CD, psi, BC) or K == 1.0 or any(g.get(k) not in (None, False) for k in
                                                ("AB", "AC1", "frame_line", "AD", "phi", "phi1", "H_out")):
        raise ValueError("the plain replica of crank_rocker.design_by_K covers the form K > 1, CD, psi and BC")
    a1, a2 = math.radians(90.0 + psi / 2), math.radians(90.0 - psi / 2)
    c1, c2 = (CD * math.cos(a1), CD * math.sin(a1)), (CD * math.cos(a2), CD * math.sin(a2))
    near = 1 if cross(c2[0] - c1[0], c2[1] - c1[1], 0.0 - c1[0], 0.0 - c1[1]) > 0 else -1
    S: Steps = {
        "theta": (lambda: 180.0 * (K - 1.0) / (K + 1.0), ()), "K": (lambda: float(K), ()),
        "CD": (lambda: float(CD), ()),
        "D": (lambda: (0.0, 0.0), ()), "D_ground": (_drawn, ("D",)),
        "C1": (lambda: c1, ()), "C2": (lambda: c2, ()),
        "DC1": (_drawn, ("D", "C1")), "DC2": (_drawn, ("D", "C2")), "chord": (_drawn, ("C1", "C2")),
    }
    cands = []
    for n, (s, pre) in enumerate(((near, "n"), (-near, "f")), 1):
        _theta_circle_steps(S, s, pre)
        S[f"{pre}arcs_ok"] = (_drawn, (f"{pre}kTheta", "C1", "C2", "D"))
        S[f"{pre}half"] = (lambda th: 0.5 * th, ("theta",))
        S[f"{pre}kF"] = (lambda C1, C2, h, s=s: seeing_circle(C1, C2, h, s), ("C1", "C2", f"{pre}half"))
        if "kC1" not in S:
            S["kC1"] = (lambda C1: (C1[0], C1[1], 2 * BC), ("C1",))
        S[f"F_{n}"] = (lambda k, kF, C2: farthest(circle_circle(k, kF), C2), ("kC1", f"{pre}kF", "C2"))
        S[f"lF_{n}"] = (lambda C1, F: line(C1, (F[0] - C1[0], F[1] - C1[1])), ("C1", f"F_{n}"))
        S[f"A_{n}"] = (lambda l, k, C1: farthest(line_circle(l, k), C1), (f"lF_{n}", f"{pre}kTheta", "C1"))
        cands.append(s)
    for i, s in enumerate(cands, 1):
        A = f"A_{i}"
        S[f"AB_{i}"] = (half_difference, (A, "C1", "C2"))
        S[f"BC_{i}"] = (half_sum, (A, "C1", "C2"))
        S[f"AD_{i}"] = (dist, (A, "D"))
        S[f"psi_{i}"] = (angle_deg, ("D", "C1", "C2"))
        S[f"C1_folded_{i}"] = (folded_flag, (A, "C1", "C2"))
        S[f"A_near_{i}"] = (near_flag, (A, "C1", "C2", "D"))
        S[f"valid_{i}"] = (lambda A, P1, P2, D, s=s: rocker_valid(A, P1, P2, D, CD, s), (A, "C1", "C2", "D"))
        S[f"gamma_min_{i}"] = (gamma_min_of, (A, "D", "C1", "C2"))
    names = ("AB", "BC", "AD", "psi", "gamma_min", "C1_folded", "A_near")
    S["choice"] = (_drawn, tuple(f"{k}_{i}" for i in range(1, len(cands) + 1) for k in ("valid", "C1_folded", "A_near", "AD")))
    for k in ("A", "P1c", "P2c", "Cf", "Ce", "A_ground", "ACf", "ACe", "u_len", "Echoice", "Mchoice", "AB_draw",
              "AD_link", "mAB", "B1", "B2", "AB1", "B1C1", "C1D_design", "AB2", "B2C2", "C2D_design", "mark_theta"):
        S[k] = (_drawn, ("choice",))                                    # the drawing of the choice
    for k in names:
        S[f"chosen_{k}"] = (_drawn, ("choice",))
    keys = [f"{k}_{i}" for i in range(1, len(cands) + 1) for k in names + ("valid",)]
    v = evaluate(S, keys + ["CD", "theta", "K"])
    sols = [{**{k: v[f"{k}_{i}"] for k in names}, "CD": v["CD"], "theta": v["theta"], "K": v["K"]}
            for i in range(1, len(cands) + 1) if v[f"valid_{i}"]]
    if not sols:
        raise ValueError("no valid crank-rocker")
    return min(sols, key=lambda x: (-x["C1_folded"], -x["A_near"], x["AD"]))


PLAIN: dict[str, Callable[[Mapping[str, Any]], dict[str, float]]] = {
    "crank_rocker.extremes": crank_rocker_plain,
    "crank_slider.extremes": crank_slider_plain,
    "guide_bar.extremes": guide_bar_plain,
    "crank_slider.design_by_K": crank_slider_design_plain,
    "crank_rocker.design_by_K": crank_rocker_design_plain,
}
"""Recipe name → its plain-DAG replica (givens as the recipe's; the design-by-K replicas cover one form each)."""
