"""Steps and checks shared by the three-position syntheses of a four-bar.

- :func:`add_bisector_centre`: the textbook's centre of three positions — chords P1P2 and P2P3, their
  perpendicular bisectors with right-angle marks, and their meeting point.
- :func:`add_positions` and :func:`add_report`: the designed linkage drawn in its three positions in
  graded tones, and the numbers read off it (lengths, Grashof class, transmission angles, defects).
- :func:`require_distinct_noncollinear`, :func:`require_equal`: refusals and warnings for near-degenerate
  input, with the condition number :func:`condition` = R / h_min.
- :func:`fit_rigid`: drafted data (lengths of one link differing within :data:`DRAFT_REFUSE_REL`) fitted
  to a rigid link by a documented rule, the same in the construction and the twin.
- :func:`positions_back_check`: the designed linkage driven through the prescribed input angles.

Conventions. The **assembly branch** of a position is the side of the directed line B→D on which C lies
(:mod:`geomcon.analytic.fourbar_drive`). ``gamma_min`` is the smallest transmission angle over the motion
the linkage makes: the full turn when AB is a crank, else the working arc (B1 through B2 to B3; 0 when
the arc meets a dead point).

Examples
--------
>>> from geomcon.geometry import Point
>>> round(condition(Point(0, 0), Point(1, 1), Point(2, 0)), 12)      # R = 1, smallest altitude 1
1.0
>>> round(condition(Point(-10, 0), Point(0, 0.1), Point(10, 0)), 1)  # nearly collinear: ill-conditioned
5000.5
"""
from __future__ import annotations

import math
from typing import Any, Mapping, Sequence

from ..analytic.fourbar_drive import REFUSE_CONDITION, WARN_CONDITION, angle_of, assemble, branch_of
from ..errors import NotAMechanism
from ..geometry import (LeftOf, Line, Point, RightOf, circle, circle_circle, line_line, midpoint, perpendicular_bisector,
                        point_along, segment)
from ..geometry.measure import _signed_angle_xy
from ..scene import Ref, Role, Scene, marks
from ..tolerance import CHECK_REL, REL_TOL, tol
from .common import add_bar, length, transmission_deg

DRAFT = 0.1
"""The drafting error the sensitivities are quoted for, mm."""

POSITION_STYLES = ("pos1", "pos2", "pos3")
"""Graded tones of the three positions (dark, medium, light)."""


# ----------------------------------------------------------------------------------------- conditioning
def altitudes(P1: Point, P2: Point, P3: Point) -> tuple[float, float, float]:
    """Distance of each point from the line through the other two."""
    out = []
    for p, q, r in ((P1, P2, P3), (P2, P3, P1), (P3, P1, P2)):
        ux, uy = r.x - q.x, r.y - q.y                      # abs((r − q) × (p − q)) / abs(r − q), on floats
        out.append(abs(ux * (p.y - q.y) - uy * (p.x - q.x)) / math.hypot(ux, uy))
    return tuple(out)


def condition(P1: Point, P2: Point, P3: Point) -> float:
    """R / h_min: the circumradius over the smallest altitude of the triangle P1P2P3 — how many mm the
    centre moves per mm a point is misplaced, at worst (∞ for collinear points)."""
    # on floats, in the order of the vector formulas (abs(P2 − P3) is hypot(P2.x − P3.x, P2.y − P3.y))
    a = math.hypot(P2.x - P3.x, P2.y - P3.y) * math.hypot(P3.x - P1.x, P3.y - P1.y) * math.hypot(P1.x - P2.x, P1.y - P2.y)
    area2 = abs((P2.x - P1.x) * (P3.y - P1.y) - (P2.y - P1.y) * (P3.x - P1.x))
    h = min(altitudes(P1, P2, P3)) if area2 > 0 else 0.0
    return math.inf if h == 0.0 else a / (2.0 * area2) / h


def require_distinct_noncollinear(names: Sequence[str], pts: Sequence[Point], what: str) -> list[str]:
    """Refuse coincident or collinear positions (NotAMechanism, one line with the numbers); warn when the
    centre of the three is ill-conditioned (R/h_min ≥ :data:`WARN_CONDITION`)."""
    span = max(math.hypot(p.x - q.x, p.y - q.y) for p in pts for q in pts)       # abs(p − q)
    for i in range(3):
        for j in range(i + 1, 3):
            if math.hypot(pts[i].x - pts[j].x, pts[i].y - pts[j].y) <= tol(span, 1e-300):
                raise NotAMechanism(f"{names[i]} = {names[j]} = ({pts[i].x:.6g}, {pts[i].y:.6g}): two coincident "
                                    f"positions, {what} is not determined")
    k = condition(*pts)
    if k < WARN_CONDITION:
        return []
    seq = ", ".join(f"{n} = ({p.x:.6g}, {p.y:.6g})" for n, p in zip(names, pts))
    if k >= REFUSE_CONDITION:
        raise NotAMechanism(f"{seq} are (nearly) collinear (R/h_min = {k:.3g} ≥ {REFUSE_CONDITION:g}): the perpendicular "
                            f"bisectors are parallel, {what} lies at infinity")
    if k >= WARN_CONDITION:
        return [f"{seq} are nearly collinear: R/h_min = {k:.4g} ≥ {WARN_CONDITION:g}, {what} moves up to "
                f"{DRAFT * k:.4g} mm per {DRAFT:g} mm of drafting error"]
    return []


def spread_decimals(spread: float) -> int:
    """Decimals that print lengths ``spread`` mm apart alike and show that they differ: two significant digits of
    the spread, at least 3 (the sheet's). 100-03 printed B1K1 = 24.9977319, B2K2 = 24.999784, B3K3 = 25.000244
    (``:.10g``, each its own length); now 24.9977, 24.9998, 25.0002.

    >>> spread_decimals(0.00251), spread_decimals(0.01), spread_decimals(1e-5), spread_decimals(2.0)
    (4, 3, 6, 3)
    """
    return max(3, 1 - math.floor(math.log10(spread))) if spread > 0 else 3


def require_equal(what: str, named: Mapping[str, float], *, refuse_rel: float = CHECK_REL, why: str = "") -> list[str]:
    """Refuse when the lengths differ by more than ``refuse_rel`` relative; warn (``why`` says what is used
    instead) when they differ by more than 1e-9 relative (the twin-check tolerance)."""
    vals = list(named.values())
    spread = max(vals) - min(vals)
    if spread <= CHECK_REL * max(vals):
        return []
    seq = ", ".join(f"{k} = {v:.{spread_decimals(spread)}f}" for k, v in named.items())
    if spread > refuse_rel * max(vals):
        raise NotAMechanism(f"{what}: {seq} differ by {spread:.3g} mm (more than {refuse_rel:g} = "
                            f"{100 * refuse_rel:g} % of the longest, the limit of drafting error)")
    return [f"{what}: {seq} differ by {spread:.3g} mm{why}"]


DRAFT_REFUSE_REL = 0.01
"""Lengths of one rigid link drawn in three positions that differ by more than 1 % of the longest are not
one link (refused); up to that they are drafted data (coordinates rounded as a textbook prints them, warned)
and fitted by :func:`fit_rigid`."""


def fit_rigid(anchors: Sequence[Point], pts: Sequence[Point]) -> tuple[float, tuple[Point, ...]]:
    """The documented fit of drafted data to a rigid link drawn as anchor_i → point_i in three positions:
    the link's length is the mean of the drawn lengths, and each point slides along its own line from its
    anchor to that length (the link's direction is kept). Exact data come back unchanged up to rounding.

    >>> r, fitted = fit_rigid([Point(0, 0)] * 3, [Point(3, 4), Point(0, 5.003), Point(-5.003, 0)])
    >>> round(r, 12), fitted[1]
    (5.002, Point(x=0.0, y=5.002))
    """
    lens = [abs(p - a) for a, p in zip(anchors, pts)]
    r = sum(lens) / len(lens)
    return r, tuple(p if d == r or d == 0.0 else a + (p - a) * (r / d) for a, p, d in zip(anchors, pts, lens))


# ----------------------------------------------------------------------------------------- step operations
def meet(l1: Line, l2: Line) -> Point:
    """The crossing of two bisectors (validation has refused parallel ones)."""
    pts = line_line(l1, l2)
    if not pts:
        raise NotAMechanism("the perpendicular bisectors are parallel: the three positions are collinear")
    return pts[0]


def bisector_foot(a: Point, b: Point) -> Point:
    """A point on the perpendicular bisector of ab, half a chord from its midpoint (for the right-angle mark)."""
    return midpoint(a, b) + (b - a).perp() * 0.5


def centre_sensitivity(O: Point, P1: Point, P2: Point, P3: Point) -> float:
    """How far the centre O of P1P2P3 moves, at worst, when one of them is misplaced by :data:`DRAFT` mm:
    moving P_k by δ moves O along the bisector of the other two by (O − P_k)·δ / h_k, so the worst case is
    DRAFT · R / min h_k."""
    return DRAFT * abs(O - P1) / min(altitudes(P1, P2, P3))


def side_of(B: Point, C: Point, D: Point) -> int:
    """The assembly branch: +1 when C lies left of the directed line B→D, −1 right."""
    c = (D - B).cross(C - B)
    return (c > 0) - (c < 0)


def same_branch(*triples: Point) -> bool:
    """True when every (B, C, D) triple has C on the same (non-zero) side of B→D."""
    sides = {side_of(*triples[i:i + 3]) for i in range(0, len(triples), 3)}
    return len(sides) == 1 and 0 not in sides


def grashof_margin(AB: float, BC: float, CD: float, AD: float) -> float:
    """(p + q) − (s + l): positive when the shortest and longest links together are shorter than the others."""
    ls = sorted((AB, BC, CD, AD))
    return (ls[1] + ls[2]) - (ls[0] + ls[3])


def is_grashof(AB: float, BC: float, CD: float, AD: float) -> bool:
    """s + l ≤ p + q (equality, a change-point linkage, counts)."""
    return grashof_margin(AB, BC, CD, AD) >= -tol(AB, BC, CD, AD)


def fully_turning(a: float, b: float, c: float, d: float) -> bool:
    """Link ``a`` (next to the frame ``d``, ``b`` the coupler, ``c`` the other side link) turns fully
    relative to the frame: Grashof, and the shortest link is ``a`` or the frame."""
    return is_grashof(a, b, c, d) and min(a, d) <= min(b, c) + tol(a, b, c, d)


def on_working_arc(A: Point, B1: Point, B2: Point, B3: Point, P: Point) -> bool:
    """True when P (seen from A) lies on the arc the crank turns through from B1 via B2 to B3."""
    ax, ay = A.x, A.y
    ux, uy = B1.x - ax, B1.y - ay

    def turn(Q: Point) -> float:                     # signed_angle(B1 − A, Q − A) mod 2π, on floats
        return _signed_angle_xy(ux, uy, Q.x - ax, Q.y - ay) % (2 * math.pi)

    t2, t3, tp = turn(B2), turn(B3), turn(P)
    if t2 < t3:                      # counter-clockwise from B1
        return tp <= t3
    return tp == 0.0 or tp >= t3     # clockwise: from 2π down to t3


def working_motion(A: Point, D: Point, B1: Point, B2: Point, B3: Point, C1: Point, C3: Point, Bn: Point, Cn: Point | None,
                   Bf: Point, Cf: Point | None, BC: float, CD: float) -> tuple[bool, float]:
    """(no dead point on the working arc, γmin over it) measured on the drawing: the working arc runs from B1
    through B2 to B3; BD is extreme at its ends or at B′ (B on AD, BD smallest) and B″ (opposite, largest)
    when they lie on it; the linkage meets a dead point when BD reaches |BC − CD| or BC + CD there."""
    cands = [(B1, C1), (B3, C3)]
    for Bx, Cx in ((Bn, Cn), (Bf, Cf)):
        if on_working_arc(A, B1, B2, B3, Bx):
            if Cx is None:
                return False, 0.0
            cands.append((Bx, Cx))
    bds = [math.hypot(D.x - B.x, D.y - B.y) for B, _ in cands]                  # abs(D − B)
    t = REL_TOL * max(BC, CD, max(bds))
    if min(bds) <= abs(BC - CD) + t or max(bds) >= BC + CD - t:
        return False, 0.0
    return True, min(transmission_deg(B, C, D) for B, C in cands)


def shown_if_used(crank: bool, A: Point, B1: Point, B2: Point, B3: Point, Bx: Point, value: Point | None = None) -> Point | None:
    """``value`` (default ``Bx``) when the crank-along-frame position Bx matters for γmin: AB is a crank, or Bx
    lies on the working arc; else None (not drawn)."""
    used = crank or on_working_arc(A, B1, B2, B3, Bx)
    return (Bx if value is None else value) if used else None


def pick_flag(flags: tuple[bool, float]) -> bool:
    """The first part of :func:`working_motion`."""
    return flags[0]


def pick_gamma(flags: tuple[bool, float]) -> float:
    """The second part of :func:`working_motion`."""
    return flags[1]


def full_turn_gamma(crank: bool, Bn: Point, Cn: Point | None, Bf: Point, Cf: Point | None, D: Point,
                    work: float) -> float:
    """γmin over the full turn when AB is a crank (the crank along the frame, both ways), else over the
    working arc."""
    if not crank:
        return work
    return min(transmission_deg(Bn, Cn, D), transmission_deg(Bf, Cf, D))


def order_flag(crank: bool, work_ok: bool) -> bool:
    """No dead point between the positions: a crank never meets one; else the working arc must be clear."""
    return crank or work_ok


def xy(p: Point) -> tuple[float, float]:
    """A point as the answer pair (x, y)."""
    return p.tuple()


def directions(A: Point, *Bs: Point) -> tuple[float, ...]:
    """Directions of A→B_i in degrees, in (−180°, 180°]."""
    return tuple(math.degrees(math.atan2(B.y - A.y, B.x - A.x)) for B in Bs)


# ----------------------------------------------------------------------------------------- scene helpers
def add_bisector_centre(sc: Scene, key: str, pts: Sequence[Ref], names: Sequence[str], label: str,
                        caption: tuple[str, str], *, style: str = "pivot", keys: Sequence[str] | None = None,
                        ground: bool = True) -> Ref:
    """Chords P1P2, P2P3, their perpendicular bisectors (with right-angle marks) and their meeting point
    (a fixed pivot with its ground symbol unless ``ground`` is false). ``keys`` spell the names in step keys
    (ASCII, e.g. ``D2p`` for D2′)."""
    keys = names if keys is None else keys
    drawing = sc.drawing                     # the chords and right-angle marks only a drawing needs
    lines = []
    for a, b in ((0, 1), (1, 2)):
        n, m = names[a], names[b]
        k = f"{key}_{keys[a]}{keys[b]}"
        p, q = pts[a], pts[b]
        if drawing:
            sc.add(f"{k}_chord", segment, p, q, style="construction", caption=(f"Join {n}{m}", f"连接 {n}{m}"))
        ln = sc.add(f"{k}_bis", perpendicular_bisector, p, q, style="construction",
                    caption=(f"Draw the perpendicular bisector of {n}{m}", f"作 {n}{m} 的中垂线"))
        if drawing:
            M = sc.add(f"{k}_mid", midpoint, p, q, visible=False)
            F = sc.add(f"{k}_foot", bisector_foot, p, q, visible=False)
            sc.add(f"{k}_right", marks.right_angle, M, q, F, role=Role.ANNOTATION, style="right-angle")
        lines.append(ln)
    ref = sc.add(key, meet, *lines, role=Role.RESULT, style=style, label=label, caption=caption)
    if ground and drawing:
        sc.add(f"{key}_ground", marks.ground, ref, -math.pi / 2, role=Role.ANNOTATION, style="ground")
    return ref


def add_positions(sc: Scene, A: Ref, D: Ref, Bs: Sequence[Ref], Cs: Sequence[Ref], *, role: Role = Role.RESULT) -> None:
    """The frame AD and the designed linkage in its three positions AB_iC_iD, in graded tones (a drawing's
    steps only: nothing is added to a scene that is not drawn)."""
    if not sc.drawing:
        return
    sc.add("AD", segment, A, D, style="frame", role=Role.RESULT, caption=("Draw the frame AD", "连接机架 AD"))
    for i, (B, C, st) in enumerate(zip(Bs, Cs, POSITION_STYLES), 1):
        add_bar(sc, f"AB{i}", A, B, (f"Draw position {i} of the linkage, AB{i}C{i}D", f"画出机构的第 {i} 位置 AB{i}C{i}D"),
                style=st, role=role)
        add_bar(sc, f"B{i}C{i}", B, C, style=st, role=role)
        add_bar(sc, f"C{i}D", C, D, style=st, role=role)


def add_report(sc: Scene, A: Ref, D: Ref, Bs: Sequence[Ref], Cs: Sequence[Ref]) -> dict[str, str]:
    """Measure the designed linkage: lengths, Grashof, crank, transmission angles, branch and order.

    Returns the answer-name → step-key map of these answers.
    """
    AB = sc.add("AB", length, A, Bs[0], role=Role.MEASUREMENT, unit="mm", caption=("Measure AB = AB1", "量得 AB = AB1"))
    BC = sc.add("BC", length, Bs[0], Cs[0], role=Role.MEASUREMENT, unit="mm", caption=("Measure BC = B1C1", "量得 BC = B1C1"))
    CD = sc.add("CD", length, Cs[0], D, role=Role.MEASUREMENT, unit="mm", caption=("Measure CD = C1D", "量得 CD = C1D"))
    AD = sc.add("ADlen", length, A, D, role=Role.MEASUREMENT, unit="mm", caption=("Measure the frame AD", "量得机架 AD"))
    sc.add("grashof_margin", grashof_margin, AB, BC, CD, AD, role=Role.MEASUREMENT, unit="mm",
           caption=("Grashof: (p + q) − (s + l), shortest s, longest l", "杆长条件:(p + q) − (s + l)"))
    sc.add("grashof", is_grashof, AB, BC, CD, AD, visible=False)
    sc.add("output_crank", fully_turning, CD, BC, AB, AD, visible=False)
    # the crank along the frame: BD smallest at B′ (on AD), largest at B″ (on DA extended beyond A)
    side = sc.value(sc.add("side1", side_of, Bs[0], Cs[0], D, visible=False).key)
    where = ("left", "左") if side > 0 else ("right", "右")
    drawing = sc.drawing                     # the shown positions B′, B″ and their ghost links, the γ mark
    mAB = sc.add("mAB", _negative, AB, visible=False)
    crank = sc.add("crank", fully_turning, AB, BC, CD, AD, role=Role.MEASUREMENT,
                   caption=("AB turns fully when Grashof holds and AB or AD is the shortest link",
                            "满足杆长条件且最短杆为 AB 或 AD 时 AB 为曲柄"))
    ext = []
    for k, r, lab, en, zh in (("n", AB, "B′", "towards D", "指向 D"), ("f", mAB, "B″", "away from D", "背离 D")):
        Bx = sc.add(f"B{k}", point_along, A, D, r, visible=False)
        kB = sc.add(f"kB{k}", circle, Bx, BC, visible=False)
        kD = sc.add(f"kD{k}", circle, D, CD, visible=False)
        rule = LeftOf(Bx, D) if side > 0 else RightOf(Bx, D)
        Cx = sc.add(f"C{k}", circle_circle, kB, kD, branch=rule, optional=True, visible=False)
        # drawn only where it matters: always for a crank, else when it lies on the working arc
        if drawing:
            cx = lab.replace("B", "C")
            Bs_ = sc.add(f"B{k}_shown", shown_if_used, crank, A, *Bs, Bx, style="point", label=lab,
                         caption=(f"Crank along the frame {en}: {lab} with A{lab} = AB (if AB is a crank or {lab} "
                                  "lies on the working arc)", f"曲柄与机架共线({zh}):A{lab} = AB"))
            Cs_ = sc.add(f"C{k}_shown", shown_if_used, crank, A, *Bs, Bx, Cx, style="point", label=cx, optional=True,
                         caption=(f"Assemble {cx} on the branch of position 1 (C1 lies {where[0]} of B1→D, so {cx} "
                                  f"{where[0]} of {lab}→D)", f"按位置 1 的装配分支作出 {cx}(C1 在 B1→D 的{where[1]}侧)"))
            sc.add(f"g{k}_B", segment, Bs_, Cs_, style="ghost", optional=True)
            sc.add(f"g{k}_C", segment, Cs_, D, style="ghost", optional=True)
        ext.append((Bx, Cx))
    (Bn, Cn), (Bf, Cf) = ext
    wm = sc.add("work", working_motion, A, D, *Bs, Cs[0], Cs[2], Bn, Cn, Bf, Cf, BC, CD, visible=False)
    work_ok = sc.add("work_ok", pick_flag, wm, visible=False)
    gw = sc.add("gamma_min_work", pick_gamma, wm, role=Role.MEASUREMENT, unit="deg",
                caption=("γmin over the working arc B1 → B2 → B3 (at its ends, at B′ and B″ when on it)",
                         "工作行程 B1 → B2 → B3 内的最小传动角"))
    gm = sc.add("gamma_min", full_turn_gamma, crank, Bn, Cn, Bf, Cf, D, gw, role=Role.MEASUREMENT, unit="deg",
                caption=("γmin: over the full turn for a crank (at B′ and B″), else over the working arc",
                         "最小传动角:曲柄取整周(B′、B″ 处),否则取工作行程"))
    sc.add("order_ok", order_flag, crank, work_ok, role=Role.MEASUREMENT,
           caption=("Order: no dead point while the input turns from B1 through B2 to B3", "顺序:输入件由 B1 经 B2 到 B3 不经过死点"))
    sc.add("branch_ok", same_branch, *(x for B, C in zip(Bs, Cs) for x in (B, C, D)), role=Role.MEASUREMENT,
           caption=("Branch: C1, C2, C3 on the same side of B→D", "分支:C1、C2、C3 位于 B→D 的同一侧"))
    sc.add("phi", directions, A, *Bs, visible=False)
    if drawing:
        sc.add("mark_gamma", _gamma_mark, crank, Bn, Cn, Bf, Cf, D, gm, role=Role.ANNOTATION, style="angle",
               optional=True)
    return {n: n for n in ("AB", "BC", "CD", "grashof", "grashof_margin", "crank", "output_crank", "gamma_min",
                           "gamma_min_work", "branch_ok", "order_ok", "phi")} | {"AD": "ADlen"}


def _negative(x: float) -> float:
    return -x


def _gamma_mark(crank: bool, Bn: Point, Cn: Point, Bf: Point, Cf: Point, D: Point, g: float):
    """The γmin arc at the crank-along-frame position that has it (crank only)."""
    from .common import transmission_mark
    if not crank:
        return None
    B, C = (Bn, Cn) if transmission_deg(Bn, Cn, D) <= transmission_deg(Bf, Cf, D) else (Bf, Cf)
    return transmission_mark(C, B, D, "γmin", g)


# ----------------------------------------------------------------------------------------- back-substitution
def _wrapped(rebuilt: float, required: float) -> float:
    """``rebuilt`` moved by whole turns next to ``required`` (so 179.9° and −179.9° compare as 0.2° apart)."""
    return required + (rebuilt - required + 180.0) % 360.0 - 180.0


def positions_back_check(A: Point, D: Point, AB: float, BC: float, CD: float, Bs: Sequence[Point], Cs: Sequence[Point],
                         Ks: Sequence[Point] | None = None) -> list[tuple[str, float, float, str]]:
    """Drive the designed linkage A, D, AB, BC, CD (floats, :func:`~geomcon.analytic.fourbar_drive.assemble`)
    to each prescribed input angle on the branch of position 1 and compare what it reaches with the
    prescribed positions: |AB_i| = AB (the crank passes B_i), |DC_i| = CD, the direction of DC_i and, with
    coupler points K_i, the direction of B_iK_i (the coupler's angle). A position on the other branch is
    assembled on its own branch and named so (the branch defect is reported separately). A position the
    linkage cannot be assembled at reads the nearest dead point (``assemble(..., nearest=True)``): a finite
    direction that misses by what the linkage misses, never NaN."""
    a, d = A.tuple(), D.tuple()
    b1 = branch_of(Bs[0].tuple(), Cs[0].tuple(), d)
    rows = []
    for i, (B, C) in enumerate(zip(Bs, Cs), 1):
        br = branch_of(B.tuple(), C.tuple(), d)
        tag = "" if br == b1 else " (other branch)"
        got = assemble(a, d, AB, BC, CD, angle_of(a, B.tuple()), br or b1, nearest=True)
        rows.append((f"|AB{i}|", abs(B - A), AB, "mm"))
        rows.append((f"|DC{i}|", abs(C - D), CD, "mm"))
        if got is None:
            raise NotAMechanism(f"the designed crank pin B{i} falls on D: the rocker's direction is undefined")
        Bg, Cg = got
        rows.append((f"C{i} direction from D{tag}", _wrapped(angle_of(d, Cg), angle_of(d, C.tuple())),
                     angle_of(d, C.tuple()), "deg"))
        if Ks is not None:
            # the coupler's angle: BK turned from BC by the fixed angle of position 1
            off = angle_of(Bs[0].tuple(), Ks[0].tuple()) - angle_of(Bs[0].tuple(), Cs[0].tuple())
            want = angle_of(B.tuple(), Ks[i - 1].tuple())
            rows.append((f"K{i}: direction of B{i}K{i}{tag}", _wrapped(angle_of(Bg, Cg) + off, want), want, "deg"))
    return rows


def defect_warnings(v: Mapping[str, Any]) -> list[str]:
    """Warnings for the branch and order defects and for a change-point linkage, from the evaluated flags."""
    out = []
    if not v["branch_ok"]:
        where = {1: "left", -1: "right", 0: "on it"}          # C_i's side of B_i→D, as a student says it
        out.append("branch defect: the three positions are not on one assembly branch (C on different sides of B→D: "
                   f"{', '.join(f'C{i} {where[s]}' for i, s in enumerate(v['sides'], 1))}); no continuous motion of "
                   "the linkage passes all three")
    if not v["order_ok"]:
        out.append(f"order defect: the input meets a dead point turning from B1 through B2 to B3 (crank angles "
                   f"{', '.join(f'{p:.4g}°' for p in v['phi'])}; AB is not a crank), so the positions are not "
                   "reached in the given order by one motion")
    if abs(v["grashof_margin"]) <= tol(v["AB"], v["BC"], v["CD"], v["AD"]):
        out.append("Grashof equality s + l = p + q: a change-point linkage (all links can be collinear)")
    return out


def evaluate_defects(sc: Scene, Bs: Sequence[Ref], Cs: Sequence[Ref], D: Ref) -> list[str]:
    """Evaluate the flags of :func:`add_report` and turn the defects into warnings."""
    keys = ["branch_ok", "order_ok", "phi", "grashof_margin", "AB", "BC", "CD", "ADlen"]
    v = sc.evaluate(keys + [r.key for r in (*Bs, *Cs, D)])
    v["AD"] = v["ADlen"]
    v["sides"] = [side_of(v[B.key], v[C.key], v[D.key]) for B, C in zip(Bs, Cs)]
    return defect_warnings(v)
