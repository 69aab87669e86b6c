"""``four_bar.analysis``: what a hinged four-bar chain is, with any of its links as the frame.

Construction (the textbook's way): Grashof's sums s + l and p + q of the shortest and longest link against
the other two; the joints at the ends of the shortest link turn fully (周转副) when s + l ≤ p + q, every
other joint oscillates (摆转副); the frame's neighbours that turn fully about their pivots are cranks, and
the type follows. Drawn with the frame's first pivot at the origin and the second on +x: when one link at
the frame is a crank, its extreme positions (the rocker circle met by circles of radius coupler ∓ crank
about the crank's pivot) give θ, ψ and K; γmin is read where the driver lies along the frame line and, when
the driver cannot turn fully, at its dead points (coupler and driven link collinear: γ = 0); at a given
driver angle ``phi`` the linkage is assembled and γ and the pressure angle α = 90° − γ measured.

The links are named by the loop A–B–C–D–A whatever the frame: ``frame = "AB"`` fixes AB, and the joints keep
their names (seed 001-03's inversions).
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.four_bar_analysis import LINKS, LOOPS, four_bar_analysis, link, link_name
from ..errors import NotAMechanism
from ..geometry import Above, Below, LeftOf, Point, RightOf, circle, circle_circle, point_along, point_on_ray, segment
from ..geometry import ray_at_angle
from ..scene import Role, Scene, marks
from ..tolerance import REL_TOL
from .base import Construction, Quantity, Recipe
from .common import (add_angle_mark, add_bar, add_pivot, angle_deg, complement_deg, difference, k_ratio, smallest,
                     total, transmission_deg, transmission_mark, velocity_end)

TYPES = ("crank-rocker", "double-crank", "double-rocker", "change-point", "immovable")
GIVENS = (
    Quantity("AB", "mm", "link AB"),
    Quantity("BC", "mm", "link BC"),
    Quantity("CD", "mm", "link CD"),
    Quantity("AD", "mm", "link AD (the frame unless `frame` says otherwise)"),
    Quantity("frame", "choice", "the fixed link", required=False, default="AD", minimum=None, choices=LINKS),
    Quantity("driver", "choice", "the driving link, one of the two at the frame (default: the one at the "
             "frame's first pivot: AB for frame AD)", required=False, minimum=None, choices=LINKS),
    Quantity("phi", "deg", "direction of the driver, counter-clockwise from the frame line (first pivot → "
             "second): the position where γ and α are asked", required=False, minimum=None),
    Quantity("branch", "choice", "side of the frame the linkage is drawn on", required=False, default="above",
             minimum=None, choices=("above", "below")),
)
ANSWERS = (
    Quantity("type", "choice", "the chain's type with this frame", choices=TYPES),
    Quantity("grashof", "bool", "Grashof's condition s + l ≤ p + q holds"),
    Quantity("A_full", "bool", "joint A turns fully (周转副); false: it oscillates (摆转副)"),
    Quantity("B_full", "bool", "joint B turns fully"),
    Quantity("C_full", "bool", "joint C turns fully"),
    Quantity("D_full", "bool", "joint D turns fully"),
    Quantity("input_crank", "bool", "the link at the frame's first pivot turns fully (AB for frame AD)"),
    Quantity("output_crank", "bool", "the link at the frame's second pivot turns fully (CD for frame AD)"),
    Quantity("theta", "deg", "crank angle between the extreme positions (one crank, one rocker)"),
    Quantity("psi", "deg", "the rocker's swing (one crank, one rocker)"),
    Quantity("K", "", "time-ratio coefficient (one crank, one rocker)"),
    Quantity("gamma_min", "deg", "smallest transmission angle over the driver's motion (0 at a dead point)"),
    Quantity("dead_points", "bool", "the driven link meets a dead point (γ = 0) in the driver's motion"),
    Quantity("gamma", "deg", "transmission angle at `phi` (at the driven link's moving joint, acute form)"),
    Quantity("alpha", "deg", "pressure angle on the driven link at `phi`, 90° − γ"),
)


def _setup(g: Mapping[str, Any]) -> tuple[str, dict[str, Any], bool]:
    """The loop's joints (j0 j1 j2 j3), the lengths by name and whether the driver is the input link."""
    frame = g.get("frame") or "AD"
    j = LOOPS[frame]
    driver = g.get("driver")
    if driver is not None and driver not in (link_name(j[0], j[1]), link_name(j[2], j[3])):
        raise NotAMechanism(f"driver = {driver} is not a link at the frame {frame} (those are "
                            f"{link_name(j[0], j[1])} and {link_name(j[2], j[3])})")
    return j, {n: g[n] for n in LINKS}, driver is None or driver == link_name(j[0], j[1])


def _validate(g: Mapping[str, Any]) -> list[str]:
    j, L, drives_input = _setup(g)
    s = sorted(L.values())
    if s[3] >= s[0] + s[1] + s[2] - REL_TOL * s[3]:
        if g.get("phi") is not None:
            raise NotAMechanism(f"the links cannot be assembled (longest {s[3]:g} ≥ sum of the other three "
                                f"{s[0] + s[1] + s[2]:g}): there is no position at phi")
        return [f"the longest link {s[3]:g} ≥ the sum of the other three {s[0] + s[1] + s[2]:g}: the chain "
                "cannot move (immovable)"]
    warn = []
    if abs((s[0] + s[3]) - (s[1] + s[2])) <= REL_TOL * s[3]:
        warn.append(f"Grashof equality s + l = p + q = {s[1] + s[2]:g}: a change-point chain (the links can "
                    "all be collinear, γ = 0 there)")
    phi = g.get("phi")
    if phi is not None:
        F, X, Z, Y = (link(L, j[3], j[0]), link(L, j[0], j[1]), link(L, j[1], j[2]), link(L, j[2], j[3]))
        d, e = (X, Y) if drives_input else (Y, X)
        c = math.cos(math.radians(phi)) * (1.0 if drives_input else -1.0)
        diag = math.sqrt(max(0.0, d * d + F * F - 2.0 * d * F * c))
        lo, hi = abs(Z - e), Z + e
        tol = REL_TOL * max(L.values())
        if diag < lo - tol or diag > hi + tol:
            who = link_name(j[0], j[1]) if drives_input else link_name(j[2], j[3])
            raise NotAMechanism(f"at phi = {phi:g}° the driver {who} cannot be assembled: the diagonal "
                                f"{diag:.6g} lies outside [{lo:g}, {hi:g}]")
    return warn


def _is_grashof(sl: float, pq: float, scale: float) -> bool:
    return sl <= pq + REL_TOL * scale


def _is_equal(sl: float, pq: float, scale: float) -> bool:
    return abs(sl - pq) <= REL_TOL * scale


def _all_of(*flags: bool) -> bool:
    return all(flags)


def _kind(change: bool, immovable: bool, in_crank: bool, out_crank: bool) -> str:
    if immovable:
        return "immovable"
    if change:
        return "change-point"
    if in_crank and out_crank:
        return "double-crank"
    if in_crank or out_crank:
        return "crank-rocker"
    return "double-rocker"


def _no(*_: Any) -> bool:
    return False


def _not_or(a: bool, b: bool) -> bool:
    """b or not a: the driven link meets a dead point unless the driver turns fully (a) off a change-point (b)."""
    return b or not a


def _ray_deg(origin: Point, toward: Point, phi: float, turn: float) -> Any:
    """The ray from ``origin`` at ``phi`` degrees counter-clockwise from +x, the frame line being
    origin → toward rotated by ``turn`` degrees."""
    return ray_at_angle(origin, toward, math.radians(phi - turn))


def construct(g: Mapping[str, Any]) -> Construction:
    """Classify by Grashof's sums; extreme positions, γmin positions, dead points and the position at phi."""
    j, L, drives_input = _setup(g)
    below = g.get("branch", "above") == "below"
    ground = math.pi / 2 if below else -math.pi / 2
    F, X, Z, Y = link(L, j[3], j[0]), link(L, j[0], j[1]), link(L, j[1], j[2]), link(L, j[2], j[3])
    fname = link_name(j[3], j[0])
    sc = Scene("Four-bar chain: type, turning joints, θ, ψ, K, γ")
    P0 = add_pivot(sc, j[0], Point(0.0, 0.0), (f"Fixed pivot {j[0]} at the origin", f"取固定铰链 {j[0]} 为原点"),
                   ground_angle=ground)
    P3 = add_pivot(sc, j[3], (F, 0.0), (f"Fixed pivot {j[3]} on the frame line, {fname} = {F:g}",
                                        f"在机架线上取 {j[3]},使 {fname} = {F:g}"), ground_angle=ground)
    drawing = sc.drawing
    if drawing:
        sc.add("frame", segment, P0, P3, role=Role.GIVEN, style="frame", caption=(f"Draw the frame {fname}",
                                                                                  f"作机架 {fname}"))
    order = sorted(LINKS, key=lambda n: L[n])
    s, p, q, l_ = order
    scale = L[l_]
    sl = sc.add("s_plus_l", total, L[s], L[l_], role=Role.MEASUREMENT, unit="mm",
                caption=(f"Shortest + longest: s + l = {s} + {l_}", f"最短杆与最长杆之和 s + l = {s} + {l_}"))
    pq = sc.add("p_plus_q", total, L[p], L[q], role=Role.MEASUREMENT, unit="mm",
                caption=(f"The other two: p + q = {p} + {q}", f"其余两杆之和 p + q = {p} + {q}"))
    gr = sc.add("grashof", _is_grashof, sl, pq, scale, role=Role.MEASUREMENT,
                caption=("Grashof: s + l ≤ p + q?", "杆长条件:s + l ≤ p + q?"))
    ch = sc.add("change", _is_equal, sl, pq, scale, visible=False)
    three = sc.add("three", total, pq, L[s], visible=False, unit="mm")
    immovable = L[l_] >= L[s] + L[p] + L[q] - REL_TOL * scale      # a decision: a guard of the tape
    imm = sc.add("immovable", _is_grashof if immovable else _no, three, L[l_], scale, visible=False)
    # the joints at the ends of the shortest link(s) turn fully when Grashof holds
    shortest = [n for n in LINKS if L[n] <= L[s] + REL_TOL * scale]
    full = {}
    for p_ in "ABCD":
        at_short = any(p_ in n for n in shortest) and not immovable
        full[p_] = sc.add(f"{p_}_full", _all_of if at_short else _no, gr, role=Role.MEASUREMENT,
                          caption=((f"{p_} is a joint of the shortest link {s}: it turns fully when s + l ≤ p + q",
                                    f"{p_} 为最短杆 {s} 的转动副:满足杆长条件时为周转副") if at_short else
                                   (f"{p_} oscillates", f"{p_} 为摆转副")))
    kind = sc.add("type", _kind, ch, imm, full[j[0]], full[j[3]], role=Role.MEASUREMENT,
                  caption=(f"The type with {fname} as the frame", f"以 {fname} 为机架的机构类型"))
    answers = {q.name: q.name for q in ANSWERS[:6]}
    answers |= {"input_crank": f"{j[0]}_full", "output_crank": f"{j[3]}_full", "type": "type"}
    points = {j[0]: j[0], j[3]: j[3]}
    if immovable:
        return Construction(sc, answers, points)
    in_crank = any(j[0] in n for n in shortest) and L[s] + L[l_] <= L[p] + L[q] + REL_TOL * scale
    out_crank = any(j[3] in n for n in shortest) and L[s] + L[l_] <= L[p] + L[q] + REL_TOL * scale
    side = Below(P0, P3) if below else Above(P0, P3)
    if in_crank != out_crank:
        _extremes(sc, (P0, j[0], X, j[1]) if in_crank else (P3, j[3], Y, j[2]),
                  (P3, j[3], Y, j[2]) if in_crank else (P0, j[0], X, j[1]), Z, F, side, drawing)
        if Z != (X if in_crank else Y):
            answers |= {"theta": "theta", "psi": "psi", "K": "K"}
    # the driver and the driven link
    Pd, jd, d, jd1 = (P0, j[0], X, j[1]) if drives_input else (P3, j[3], Y, j[2])
    Pe, je, e, je1 = (P3, j[3], Y, j[2]) if drives_input else (P0, j[0], X, j[1])
    d_full = in_crank if drives_input else out_crank
    gammas = []
    # no extreme and no given position: a γ position is the linkage drawn solid, the one with the driver turned
    # away from the frame where it exists — along it, the driver lies on the frame (001-03b's crank BC′ over BA)
    reach = [i for i, diag in enumerate((abs(F - d), F + d), 1)
             if abs(Z - e) - REL_TOL * scale <= diag <= Z + e + REL_TOL * scale]
    solid_at = reach[-1] if in_crank == out_crank and g.get("phi") is None and reach else None
    for i, sign in enumerate((1.0, -1.0), 1):
        if i not in reach:
            continue
        solid = i == solid_at
        mark = "′" * i
        Bg = sc.add(f"Bg{i}", point_along, Pd, Pe, sign * d, style="point", label=f"{jd1}{mark}",
                    caption=(f"Driver {link_name(jd, jd1)} along the frame line: {jd1}{mark}",
                             f"主动件 {link_name(jd, jd1)} 与机架共线:{jd1}{mark}"))
        Cg = sc.add(f"Cg{i}", circle_circle, sc.add(f"kBg{i}", circle, Bg, Z), sc.add(f"kCg{i}", circle, Pe, e),
                    branch=side, style="point", label=f"{je1}{mark}",
                    caption=(f"Circles of radius {Z:g} about {jd1}{mark} and {e:g} about {je} meet at {je1}{mark}",
                             f"以 {jd1}{mark} 为圆心、{Z:g} 为半径与以 {je} 为圆心、{e:g} 为半径的圆交于 {je1}{mark}"))
        for a, b, nm in ((Pd, Bg, "d"), (Bg, Cg, "c"), (Cg, Pe, "e")) if drawing else ():
            add_bar(sc, f"g{i}_{nm}", a, b, **(dict(style="link", role=Role.RESULT) if solid else
                                               dict(style="ghost", role=Role.CONSTRUCTION)))
        gk = sc.add(f"gamma_{i}", transmission_deg, Bg, Cg, Pe, role=Role.MEASUREMENT, unit="deg",
                    caption=(f"Transmission angle γ{i} = ∠{jd1}{mark}{je1}{mark}{je} (acute form)",
                             f"传动角 γ{i} = ∠{jd1}{mark}{je1}{mark}{je}(取锐角)"))
        gammas.append(gk)
        # γ{i} marked only where γmin is read from it: a driver that cannot turn fully meets dead points, γmin = 0
        # is marked there, and a γ1 = 73.74° printed at B′ was in no Results row (300-01, hlook11m's review)
        if drawing and d_full:
            sc.add(f"mark_gamma_{i}", transmission_mark, Cg, Bg, Pe, f"γ{i}", gk, role=Role.ANNOTATION, style="angle")
    if not d_full:
        zname, ename = link_name(jd1, je1), link_name(je, je1)      # the coupler and the driven link, by name
        for i, (r, over) in enumerate(((Z + e, False), (abs(Z - e), Z > e)), 1):
            if r == 0 or not abs(F - d) - REL_TOL * scale <= r <= F + d + REL_TOL * scale:
                continue
            # the radius named by the links it adds (001-03c, 300-01 printed "radius Z + e", the code's names)
            rname = f"{zname} + {ename}" if i == 1 else (f"{zname} − {ename}" if Z > e else f"{ename} − {zname}")
            kr = sc.add(f"kdead{i}", circle, Pe, sc.add(f"rdead{i}", total if i == 1 else _abs_diff, Z, e,
                                                         visible=False, unit="mm"),
                        caption=(f"Circle about {je} with radius {rname} = {r:g}: coupler {zname} and {ename} "
                                 "collinear",
                                 f"以 {je} 为圆心、{rname} = {r:g} 为半径作圆(连杆 {zname} 与 {ename} 共线)"))
            Bd = sc.add(f"Bdead{i}", circle_circle, sc.add(f"kd{i}", circle, Pd, d, visible=False), kr, branch=side,
                        style="joint", label=f"{jd1}d{i}",
                        caption=(f"It meets the path of {jd1} at the dead point {jd1}d{i}",
                                 f"交 {jd1} 点轨迹于死点位置 {jd1}d{i}"))
            # the coupler's other joint at the dead point, drawn and named: hidden, the links in line read as one
            # link {jd1}d{i}–{je} and "γ = 0° (collinear)" pointed at the middle of a line (001-03c, 300-01)
            if i == 1:                                          # folded out: between the two
                where = (f"on {jd1}d{i}{je}", f"在 {jd1}d{i}{je} 上")
            elif over:                                          # the coupler reaches past the pivot
                where = (f"on {jd1}d{i}{je} extended beyond {je}", f"在 {jd1}d{i}{je} 的延长线上({je} 之外)")
            else:                                               # the driven link reaches past the dead point
                where = (f"on {je}{jd1}d{i} extended beyond {jd1}d{i}", f"在 {je}{jd1}d{i} 的延长线上({jd1}d{i} 之外)")
            cap = (f"{je1}d{i} {where[0]}, {zname} = {Z:g} from {jd1}d{i}",
                   f"{where[1]}取 {je1}d{i},使 {zname} = {Z:g}")
            Cd = (sc.add(f"Cdead{i}", point_along, Bd, Pe, Z, style="joint", label=f"{je1}d{i}", caption=cap)
                  if over else
                  sc.add(f"Cdead{i}", point_along, Pe, Bd, e, style="joint", label=f"{je1}d{i}", caption=cap))
            for a, b, nm in ((Pd, Bd, "d"), (Bd, Cd, "c"), (Cd, Pe, "e")) if drawing else ():
                add_bar(sc, f"dead{i}_{nm}", a, b, style="link-alt", role=Role.CONSTRUCTION)
            gammas.append(sc.add(f"gamma_dead{i}", transmission_deg, Bd, Cd, Pe, role=Role.MEASUREMENT, unit="deg",
                                 caption=(f"γ = 0 at the dead point {jd1}d{i}", f"死点位置 {jd1}d{i} 处 γ = 0")))
            if drawing:                    # γmin = 0 is read here: the note says so where the links line up
                sc.add(f"mark_gamma_dead{i}", transmission_mark, Cd, Bd, Pe, "γ", gammas[-1],
                       role=Role.ANNOTATION, style="angle")
    sc.add("gamma_min", smallest, *gammas, role=Role.MEASUREMENT, unit="deg",
           caption=("γmin over the driver's motion", "主动件运动范围内的最小传动角 γmin"))
    sc.add("dead_points", _not_or, full[jd], ch, role=Role.MEASUREMENT,
           caption=("Dead points: the driver cannot turn fully, or the chain is a change-point",
                    "死点:主动件不能整周转动或为变点机构时存在"))
    answers |= {"gamma_min": "gamma_min", "dead_points": "dead_points"}
    if g.get("phi") is not None:
        ray = sc.add("ray_phi", _ray_deg, Pd, Pe, g["phi"], 0.0 if drives_input else 180.0, visible=False)
        Bp = sc.add("Bphi", point_on_ray, ray, d, role=Role.RESULT, style="joint", label=jd1,
                    caption=(f"Driver {link_name(jd, jd1)} at φ = {g['phi']:g}°: {jd1}",
                             f"主动件 {link_name(jd, jd1)} 位于 φ = {g['phi']:g}°:{jd1}"))
        rule = (LeftOf if drives_input != below else RightOf)(Bp, Pe)
        Cp = sc.add("Cphi", circle_circle, sc.add("kBphi", circle, Bp, Z), sc.add("kCphi", circle, Pe, e),
                    branch=rule, role=Role.RESULT, style="joint", label=je1,
                    caption=(f"Circles about {jd1} (radius {Z:g}) and {je} (radius {e:g}) meet at {je1}",
                             f"以 {jd1}、{je} 为圆心分别以 {Z:g}、{e:g} 为半径作圆交于 {je1}"))
        for a, b, nm in ((Pd, Bp, "d"), (Bp, Cp, "c"), (Cp, Pe, "e")) if drawing else ():
            add_bar(sc, f"phi_{nm}", a, b)
        gp = sc.add("gamma", transmission_deg, Bp, Cp, Pe, role=Role.MEASUREMENT, unit="deg",
                    caption=(f"γ = ∠{jd1}{je1}{je} at φ (acute form)", f"φ 位置的传动角 γ = ∠{jd1}{je1}{je}(取锐角)"))
        al = sc.add("alpha", complement_deg, gp, role=Role.MEASUREMENT, unit="deg",
               caption=("Pressure angle α = 90° − γ", "压力角 α = 90° − γ"))
        if drawing:
            sc.add("mark_gamma", transmission_mark, Cp, Bp, Pe, "γ", gp, role=Role.ANNOTATION, style="angle")
            # the pressure angle on the driven link: between the force along the coupler and the velocity
            # of its joint (⊥ to the driven link), drawn at the joint as the question asks for it
            V = sc.add("v_end", velocity_end, Cp, Pe, Bp, 0.3 * min(Z, e), style="point", label=f"v{je1}",
                       role=Role.CONSTRUCTION)
            sc.add("v_line", marks.vector, Cp, V, role=Role.CONSTRUCTION, style="vector",
                   caption=(f"The velocity v{je1} of {je1} is perpendicular to {link_name(je, je1)}; the force on "
                            f"{je1} runs along the coupler {link_name(jd1, je1)}: α is the angle between them",
                            f"{je1} 点速度 v{je1} 垂直于 {link_name(je, je1)},所受力沿连杆 {link_name(jd1, je1)},"
                            "二者之夹角为压力角 α"))
            add_angle_mark(sc, "mark_alpha", Cp, Bp, V, "α", al)
        answers |= {"gamma": "gamma", "alpha": "alpha"}
        points |= {jd1: "Bphi", je1: "Cphi"}
    return Construction(sc, answers, points)


def _abs_diff(a: float, b: float) -> float:
    return abs(a - b)


def _extremes(sc: Scene, crank: tuple, rocker: tuple, Z: float, F: float, side: Any, drawing: bool) -> None:
    """The extreme positions of the crank (pivot, name, length, moving joint) driving the rocker."""
    Pa, ja, a, ja1 = crank
    Pr, jr, c, jr1 = rocker
    kR = sc.add("kR", circle, Pr, c, caption=(f"Circle about {jr} with radius {c:g}, the path of {jr1}",
                                              f"以 {jr} 为圆心、{c:g} 为半径作圆({jr1} 点轨迹)"))
    Es = []
    for i, (op, how) in enumerate(((difference, ("folded", "重叠")), (total, ("extended", "拉直"))), 1):
        r = sc.add(f"rE{i}", op, Z, a, visible=False, unit="mm")
        sign = "−" if i == 1 else "+"
        k = sc.add(f"kE{i}", circle, Pa, r, caption=(f"Circle about {ja} with radius coupler {sign} crank",
                                                     f"以 {ja} 为圆心、连杆{sign}曲柄为半径作圆"))
        E = sc.add(f"E{i}", circle_circle, k, kR, branch=side, role=Role.RESULT, style="joint", label=f"{jr1}{i}",
                   caption=(f"It meets the rocker circle at {jr1}{i}: crank and coupler {how[0]}",
                            f"交摇杆圆于 {jr1}{i}(曲柄与连杆{how[1]}共线)"))
        Bx = sc.add(f"X{i}", point_along, Pa, E, -a if i == 1 else a, role=Role.RESULT, style="joint",
                    label=f"{ja1}{i}", caption=(f"{ja1}{i} on the line {ja}{jr1}{i}, at the crank's length from {ja}",
                                                f"在直线 {ja}{jr1}{i} 上截取曲柄长得 {ja1}{i}"))
        for a_, b_, nm in ((Pa, Bx, "a"), (Bx, E, "b"), (E, Pr, "c")) if drawing else ():
            add_bar(sc, f"ext{i}_{nm}", a_, b_, style="link" if i == 1 else "link-alt")
        Es.append(E)
    th = sc.add("theta", angle_deg, Pa, Es[0], Es[1], role=Role.MEASUREMENT, unit="deg",
                caption=(f"Measure θ = ∠{jr1}1{ja}{jr1}2", f"量得极位夹角 θ = ∠{jr1}1{ja}{jr1}2"))
    ps = sc.add("psi", angle_deg, Pr, Es[0], Es[1], role=Role.MEASUREMENT, unit="deg",
                caption=(f"Measure the swing ψ = ∠{jr1}1{jr}{jr1}2", f"量得摇杆摆角 ψ = ∠{jr1}1{jr}{jr1}2"))
    sc.add("K", k_ratio, th, role=Role.MEASUREMENT, caption=("K = (180° + θ)/(180° − θ)", "K = (180° + θ)/(180° − θ)"))
    if drawing:
        add_angle_mark(sc, "mark_theta", Pa, Es[0], Es[1], "θ", th)
        add_angle_mark(sc, "mark_psi", Pr, Es[0], Es[1], "ψ", ps)


def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The twin: each joint by its diagonal's range (:func:`geomcon.analytic.four_bar_analysis.four_bar_analysis`)."""
    r = four_bar_analysis(g["AB"], g["BC"], g["CD"], g["AD"], frame=g.get("frame") or "AD", driver=g.get("driver"),
                          phi=g.get("phi"))
    return [r]


RECIPE = Recipe(
    name="four_bar.analysis",
    title="Four-bar chain: type, fully turning joints, θ, ψ, K, γmin, dead points, γ and α at a position",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "B", "C", "D"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
