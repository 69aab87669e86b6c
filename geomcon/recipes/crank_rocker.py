"""``crank_rocker.extremes``: the extreme positions of a crank-rocker (crank and coupler collinear).

Construction (A at the origin, D on +x, the linkage above the frame unless ``branch = "below"``): the
rocker circle about D meets the circle about A of radius BC − AB at C1 (folded position) and the circle of
radius BC + AB at C2 (extended position); θ = ∠C1AC2, ψ = ∠C1DC2. γmin is read at the two positions where
the crank lies along the frame.
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.linkages import crank_rocker_extremes
from ..errors import NotAMechanism
from ..geometry import Above, Below, Point, circle, circle_circle, point_along, segment
from ..scene import Role, Scene
from .. import tolerance as _tolerance
from .base import Construction, Quantity, Recipe
from .common import (add_angle_mark, add_bar, add_collinear_extremes, add_pivot, add_theta_and_K, angle_deg, smallest,
                     transmission_deg, transmission_mark)

GIVENS = (
    Quantity("AB", "mm", "crank"),
    Quantity("BC", "mm", "coupler"),
    Quantity("CD", "mm", "rocker"),
    Quantity("AD", "mm", "frame"),
    Quantity("branch", "choice", "side of the frame the linkage is drawn on", required=False, default="above",
             minimum=None, choices=("above", "below")),
)
ANSWERS = (
    Quantity("theta", "deg", "crank angle between the extreme positions, ∠C1AC2"),
    Quantity("psi", "deg", "rocker swing, ∠C1DC2"),
    Quantity("K", "", "time-ratio coefficient (180°+θ)/(180°−θ)"),
    Quantity("gamma_min", "deg", "smallest transmission angle over the cycle"),
    Quantity("gamma_1", "deg", "transmission angle with the crank along AD (B between A and D)"),
    Quantity("gamma_2", "deg", "transmission angle with the crank along DA extended (A between B and D)"),
    Quantity("angle_C1AD", "deg", "∠C1AD, folded extreme position"),
    Quantity("angle_C2AD", "deg", "∠C2AD, extended extreme position"),
)


def grashof(AB: float, BC: float, CD: float, AD: float) -> list[str]:
    """Refuse lengths for which AB is not a crank of a crank-rocker on frame AD; warn at the boundary.

    Examples
    --------
    >>> grashof(50, 70, 80, 90)
    []
    >>> grashof(15, 50, 35, 30)[0][:30]
    'Grashof equality AB + BC = CD '
    >>> grashof(50, 50, 30, 90)
    Traceback (most recent call last):
    ...
    geomcon.errors.NotAMechanism: AB is not a crank (Grashof): CD + AD > AB + BC (30 + 90 > 50 + 50, 120 > 100): no link turns fully
    """
    # every solve validates its givens: the dictionary, the key functions and the comprehensions this check
    # was written with cost ~4 µs of a ~45 µs solve, so it is written on the four numbers by position (the same
    # comparisons in the same order: max()'s first largest, sorted()'s stable order, min(); the same sum())
    vals = (AB, BC, CD, AD)
    li, big = 0, AB                                            # max(lengths, key=…): the first of the largest
    if BC > big:
        li, big = 1, BC
    if CD > big:
        li, big = 2, CD
    if AD > big:
        li, big = 3, AD
    rest = sum(vals) - big
    if big >= rest:
        raise NotAMechanism(f"the links cannot be assembled: {_LINKS[li]} = {big:g} ≥ sum of the "
                            f"other three = {rest:g}")
    order = sorted(range(4), key=vals.__getitem__)            # s, p, q, l (ties in the links' order)
    s, p, q, l_ = [vals[i] for i in order]
    if s + l_ > p + q and not abs(s + l_ - (p + q)) <= _tolerance.REL_TOL * abs(p + q):      # is_zero in place
        sn, pn, qn, ln = [_LINKS[i] for i in order]
        raise NotAMechanism(
            f"AB is not a crank (Grashof): {sn} + {ln} > {pn} + {qn} ({s:g} + {l_:g} > "
            f"{p:g} + {q:g}, {s + l_:g} > {p + q:g}): no link turns fully")
    least = BC                                                 # min(BC, CD, AD)
    if CD < least:
        least = CD
    if AD < least:
        least = AD
    if AB > least or AB == AD:
        raise NotAMechanism(
            f"AB = {AB:g} is not the strictly shortest link adjacent to the frame (BC = {BC:g}, CD = {CD:g}, "
            f"AD = {AD:g}): no crank-rocker with crank AB")
    if li == 0:
        li = 1
    o1, o2 = [i for i in (1, 2, 3) if i != li]
    s_l = AB + vals[li]
    p_q = vals[o1] + vals[o2]
    if AB == BC:
        raise NotAMechanism(f"BC = AB = {AB:g}: the folded position puts C1 on A, θ is undefined")
    if abs(s_l - p_q) <= _tolerance.REL_TOL * abs(p_q):                             # is_zero(s_l − p_q, p_q)
        return [f"Grashof equality AB + {_LINKS[li]} = {_LINKS[o1]} + {_LINKS[o2]} = {p_q:g}: a change-point "
                "linkage (links can all be collinear, γmin = 0)"]
    return []


_LINKS = ("AB", "BC", "CD", "AD")


def _validate(g: Mapping[str, Any]) -> list[str]:
    return grashof(g["AB"], g["BC"], g["CD"], g["AD"])


def construct(g: Mapping[str, Any]) -> Construction:
    """Build the extreme-position construction."""
    AB, BC, CD, AD = g["AB"], g["BC"], g["CD"], g["AD"]
    below = g.get("branch", "above") == "below"
    side_en, side_zh = ("below", "下方") if below else ("above", "上方")
    ground = math.pi / 2 if below else -math.pi / 2
    sc = Scene("Crank-rocker: extreme positions")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Fixed pivot A at the origin", "取固定铰链 A 为原点"), ground_angle=ground)
    D = add_pivot(sc, "D", (AD, 0.0), (f"Fixed pivot D on the frame line, AD = {AD:g}",
                                              f"在机架线上取 D,使 AD = {AD:g}"), ground_angle=ground)
    side = Below(A, D) if below else Above(A, D)
    drawing = sc.drawing                     # the links, ghost positions and marks only a drawing needs
    if drawing:
        sc.add("AD", segment, A, D, role=Role.GIVEN, style="frame", caption=("Draw the frame AD", "作机架 AD"))
    kD = sc.add("kD", circle, D, CD, caption=(f"Circle about D with radius CD = {CD:g}, the path of C",
                                               f"以 D 为圆心、CD = {CD:g} 为半径作圆(C 点轨迹)"))
    B1, C1, B2, C2 = add_collinear_extremes(sc, A, kD, AB, BC, side, circle_circle, ("the rocker circle", "摇杆圆"))
    for i, (B, C) in enumerate(((B1, C1), (B2, C2)), 1) if drawing else ():
        style = "link" if i == 1 else "link-alt"
        how = ("folded", "重叠") if i == 1 else ("extended", "拉直")
        add_bar(sc, f"AB{i}", A, B, (f"Draw the {how[0]} position AB{i}C{i}D", f"画出{how[1]}共线位置 AB{i}C{i}D"), style=style)
        add_bar(sc, f"B{i}C{i}", B, C, style=style)
        add_bar(sc, f"C{i}D", C, D, style=style)
    if drawing:
        sc.add("AC2", segment, A, C2, style="construction", caption=("Join AC2", "连接 AC2"))
    th = add_theta_and_K(sc, A, C1, C2)
    ps = sc.add("psi", angle_deg, D, C1, C2, role=Role.MEASUREMENT, unit="deg",
                caption=("Measure the swing ψ = ∠C1DC2", "量得摇杆摆角 ψ = ∠C1DC2"))
    sc.add("angle_C1AD", angle_deg, A, C1, D, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add("angle_C2AD", angle_deg, A, C2, D, role=Role.MEASUREMENT, unit="deg", visible=False)
    # transmission angle: crank along the frame, towards D (B') and away from D (B'')
    gammas = []
    for i, (sign, en, zh) in enumerate(((1.0, "along AD", "与 AD 重叠"), (-1.0, "along DA extended", "在 DA 延长线上")), 1):
        p = "′" * i
        Bg = sc.add(f"Bg{i}", point_along, A, D, sign * AB, style="point", label=f"B{p}",
                    caption=(f"Crank {en}: B{p} with AB{p} = AB", f"曲柄{zh}:取 AB{p} = AB 得 B{p}"))
        kB = sc.add(f"kBg{i}", circle, Bg, BC, caption=(f"Circle about B{p} with radius BC = {BC:g}",
                                                        f"以 B{p} 为圆心、BC 为半径作圆"))
        Cg = sc.add(f"Cg{i}", circle_circle, kB, kD, branch=side, style="point", label=f"C{p}",
                    caption=(f"It meets the rocker circle at C{p}", f"交摇杆圆于 C{p}"))
        for a, b, nm in ((A, Bg, f"AB{p}"), (Bg, Cg, f"B{p}C{p}"), (Cg, D, f"C{p}D")) if drawing else ():
            add_bar(sc, f"g{i}_{nm}", a, b, style="ghost", role=Role.CONSTRUCTION)
        gk = sc.add(f"gamma_{i}", transmission_deg, Bg, Cg, D, role=Role.MEASUREMENT, unit="deg",
                    caption=(f"Transmission angle γ{i} = ∠B{p}C{p}D (acute form)", f"传动角 γ{i} = ∠B{p}C{p}D(取锐角)"))
        gammas.append((gk, Bg, Cg))
    sc.add("gamma_min", smallest, gammas[0][0], gammas[1][0], role=Role.MEASUREMENT, unit="deg",
                caption=("γmin = min(γ1, γ2)", "最小传动角 γmin = min(γ1, γ2)"))
    if drawing:
        add_angle_mark(sc, "mark_theta", A, C1, C2, "θ", th)
        add_angle_mark(sc, "mark_psi", D, C1, C2, "ψ", ps)
        for i, (gk, Bg, Cg) in enumerate(gammas, 1):
            sc.add(f"mark_gamma_{i}", transmission_mark, Cg, Bg, D, f"γ{i}", gk, role=Role.ANNOTATION, style="angle")
    answers = {q.name: q.name for q in ANSWERS}
    points = {n: n for n in ("A", "D", "B1", "C1", "B2", "C2")}
    return Construction(sc, answers, points)


def analytic(g: Mapping[str, Any]) -> list[dict[str, float]]:
    """The law-of-cosines twin (branch does not change the answers)."""
    return [crank_rocker_extremes(g["AB"], g["BC"], g["CD"], g["AD"])]


RECIPE = Recipe(
    name="crank_rocker.extremes",
    title="Crank-rocker: extreme positions, θ, ψ, K, γmin",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "D", "B1", "C1", "B2", "C2"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
