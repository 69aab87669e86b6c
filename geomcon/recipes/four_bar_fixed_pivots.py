"""``four_bar.three_positions_fixed_pivots``: the coupler–rocker hinge C from the fixed pivots A, D, three
positions of the input link AB and three positions of the coupler, by inversion (刚化反转法).

Seen from the coupler, the frame moves and D describes a circle about the hinge C. So the frame is made rigid
with the coupler in positions 2 and 3 and carried onto position 1: the triangle B2K2D is copied onto B1K1
(at B1 the angle ∠K2B2D is laid off from B1K1 and B1D2′ = B2D marked on it — the compass arc about B1 met
square-on by a ray from its centre, exact also for a flat triangle, where two arcs about B1 and K1 would meet
at a grazing angle), likewise D3′; C1 is the centre of the circle through D, D2′, D3′ (perpendicular bisectors).
C2 and C3 follow by carrying C1 with the coupler (the triangle B1K1C1 copied onto B2K2, B3K3).

The coupler's positions are given by a point K of it (``K1, K2, K3``) or by the angle of the coupler line
(``coupler_angles``, deg); with angles, K_i is marked on the coupler line at the distance B1D/2 from B_i
(any point of the line serves).

Drafted data: coordinates rounded as a textbook prints them leave |AB1|, |AB2|, |AB3| (and |B_iK_i|) a little
unequal. Up to 1 % of the longest (:data:`~.synthesis_common.DRAFT_REFUSE_REL`) this is accepted with a
warning and fitted by one documented rule (:func:`~.synthesis_common.fit_rigid`): each B_i slides along AB_i
to the mean length AB, and K_i moves with it (the coupler's drawn direction B_iK_i is kept); only the
directions B_iK_i are used. The twin fits the same way; beyond 1 % the data are refused. The sensitivity ``sens_C`` is the worst shift of C1 when one given point
(D, a B_i or a K_i) is misplaced by 0.1 mm, from the Jacobian of the construction: each point of the
circle moves the centre along the bisector of the other two, and D2′, D3′ move rigidly with D, B_i, K_i.

Examples
--------
>>> from geomcon.problems import problem_from_dict
>>> from geomcon.solve import solve
>>> s = solve(problem_from_dict({"recipe": "four_bar.three_positions_fixed_pivots", "given": {
...     "A": [0, 0], "D": [50, 0], "B1": [10, 17.320508075689], "B2": [-3.472963553339, 19.696155060244],
...     "B3": [-15.320888862380, 12.855752193731], "coupler_angles": [33.161246337, 26.6177481, 27.304915336]}}, name="demo"))
>>> round(s.answers["CD"], 6), round(s.answers["BC"], 6), s.ok
(42.0, 45.0, True)
"""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..analytic.synthesis import three_positions_fixed_pivots as twin
from ..errors import NotAMechanism
from ..geometry import Point, circle, perpendicular_bisector, point_on_ray, ray_at_angle, segment, signed_angle
from ..geometry.primitives import unit_xy
from ..scene import Ref, Role, Scene
from .base import Construction, Quantity, Recipe
from .common import add_bar, add_pivot, length
from .four_bar_positions import REPORT
from .synthesis_common import (DRAFT, DRAFT_REFUSE_REL, add_bisector_centre, add_positions, add_report,
                               evaluate_defects, fit_rigid, meet, positions_back_check, require_distinct_noncollinear,
                               require_equal, xy)

GIVENS = (
    Quantity("A", "point", "fixed pivot of the input link [x, y]", minimum=None),
    Quantity("D", "point", "fixed pivot of the output link [x, y]", minimum=None),
    *(Quantity(f"B{i}", "point", f"position {i} of the input link's moving end B [x, y]", minimum=None) for i in (1, 2, 3)),
    *(Quantity(f"K{i}", "point", f"position {i} of a point K of the coupler [x, y] (or give coupler_angles)",
               required=False, minimum=None) for i in (1, 2, 3)),
    Quantity("coupler_angles", "deg[]", "directions of the coupler line BK in the three positions (or give K1..K3)",
             required=False, minimum=None),
)
ANSWERS = (Quantity("C1", "mm[]", "hinge of coupler and output link in position 1 [x, y]"),) + REPORT + (
    Quantity("sens_C", "mm", "worst shift of C1 when one of D, B1..B3, K1..K3 is misplaced by 0.1 mm (mm per 0.1 mm)"),
)
K_REFUSE_REL = DRAFT_REFUSE_REL
"""K1, K2, K3 whose distances from B differ by more than 1 % are not one point of a rigid coupler (refused);
below that the difference is drafting error (warned): the construction and the twin use only the directions
of B_iK_i."""
POINTS = ("A", "D", "B1", "B2", "B3", "K1", "K2", "K3", "C1", "C2", "C3")


# ----------------------------------------------------------------------------------------- input
def _coupler_points(g: Mapping[str, Any]) -> tuple[list[Point], list[Point], bool]:
    """(B_i, K_i, K given), drafted B_i fitted onto the circle about A (:func:`fit_rigid`, K_i moved with B_i);
    with angles, K_i at B1D/2 from B_i along the coupler line."""
    raw = [Point(*g[f"B{i}"]) for i in (1, 2, 3)]
    _, Bs = fit_rigid([Point(*g["A"])] * 3, raw)
    if g.get("K1") is not None:
        return list(Bs), [Point(*g[f"K{i}"]) + (B - R) for i, B, R in zip((1, 2, 3), Bs, raw)], True
    L = abs(Point(*g["D"]) - Bs[0]) / 2.0
    return Bs, [B + Point(math.cos(math.radians(a)), math.sin(math.radians(a))) * L
                for B, a in zip(Bs, g["coupler_angles"])], False


def _validate(g: Mapping[str, Any]) -> list[str]:
    ks = [g.get(f"K{i}") is not None for i in (1, 2, 3)]
    angles = g.get("coupler_angles")
    if any(ks) and not all(ks):
        raise NotAMechanism("give all three coupler points K1, K2, K3 (or coupler_angles instead)")
    if all(ks) == (angles is not None):
        raise NotAMechanism("give the coupler's positions either as K1, K2, K3 or as coupler_angles, not both or neither")
    if angles is not None and len(angles) != 3:
        raise NotAMechanism(f"coupler_angles needs three angles, got {len(angles)}")
    A, D = Point(*g["A"]), Point(*g["D"])
    if A == D:
        raise NotAMechanism(f"A = D = ({A.x:g}, {A.y:g}): the frame has no length")
    raw = [Point(*g[f"B{i}"]) for i in (1, 2, 3)]
    for i, B in enumerate(raw, 1):
        if B == A:
            raise NotAMechanism(f"B{i} = A = ({A.x:g}, {A.y:g}): the input link has no length")
    lens = {f"AB{i}": abs(B - A) for i, B in enumerate(raw, 1)}
    warn_ab = require_equal("the input link does not keep its length", lens, refuse_rel=DRAFT_REFUSE_REL,
                            why=f" (drafted data?): each B_i is slid along AB_i to the mean AB = "
                                f"{sum(lens.values()) / 3:.10g} mm, K_i with it")
    Bs, Ks, given_k = _coupler_points(g)
    if given_k:
        for i, B in enumerate(raw, 1):
            if B == Point(*g[f"K{i}"]):
                raise NotAMechanism(f"K{i} = B{i} = ({B.x:g}, {B.y:g}): the coupler line B{i}K{i} is undefined")
        warn = require_equal("K is not one point of a rigid coupler",
                             {f"B{i}K{i}": abs(K - B) for i, (B, K) in enumerate(zip(Bs, Ks), 1)}, refuse_rel=K_REFUSE_REL,
                             why=" (drafting error?): only the directions B_iK_i, the coupler's angles, are used")
    else:
        warn = []
    warn = warn_ab + warn
    for i in range(3):
        for j in range(i + 1, 3):
            if Bs[i] == Bs[j]:
                raise NotAMechanism(f"B{i + 1} = B{j + 1} = ({Bs[i].x:g}, {Bs[i].y:g}): two input positions coincide")
    return warn


# ----------------------------------------------------------------------------------------- step operations
def copied_angle(Bi: Point, Ki: Point, P: Point) -> float:
    """The signed angle (rad) turning B_i→K_i into B_i→P: the angle of the triangle B_iK_iP at B_i."""
    return signed_angle(Ki - Bi, P - Bi)


# 2×2 matrices as 4-tuples (m00, m01, m10, m11), their products and sums on floats: the Jacobian blocks of
# hinge_sensitivity are a few dozen multiplications, which tuples of tuples built by generators made 150 µs
def _outer(ux: float, uy: float, vx: float, vy: float) -> tuple[float, float, float, float]:
    return (ux * vx, ux * vy, uy * vx, uy * vy)


def _mul(M, N) -> tuple[float, float, float, float]:
    a, b, c, d = M
    e, f, g, h = N
    return (a * e + b * g, a * f + b * h, c * e + d * g, c * f + d * h)


def _add(M, N) -> tuple[float, float, float, float]:
    return (M[0] + N[0], M[1] + N[1], M[2] + N[2], M[3] + N[3])


def _neg(M) -> tuple[float, float, float, float]:
    return (-M[0], -M[1], -M[2], -M[3])


def spectral_norm(M) -> float:
    """Largest singular value of a 2×2 matrix (rows, or the 4-tuple m00, m01, m10, m11):
    √((F + √(F² − 4·det²)) / 2), F the squared Frobenius norm.

    >>> spectral_norm(((3.0, 0.0), (0.0, -4.0))), spectral_norm((3.0, 0.0, 0.0, -4.0))
    (4.0, 4.0)
    """
    a, b, c, d = M if len(M) == 4 else (*M[0], *M[1])
    F = sum((a * a, b * b, c * c, d * d))                 # sum(): the running Python's float summation, as before
    det = a * d - b * c
    return math.sqrt((F + math.sqrt(max(0.0, (F - 2 * abs(det)) * (F + 2 * abs(det))))) / 2.0)


def hinge_sensitivity(C: Point, D: Point, D2: Point, D3: Point, B1: Point, B2: Point, B3: Point, K1: Point, K2: Point,
                      K3: Point, with_k: bool) -> float:
    """Worst shift of C1 (centre of D, D2′, D3′) per :data:`DRAFT` mm of error in one of D, B_i (and K_i).

    Moving a point P_k of the circle by δ moves the centre along the bisector of the other two by
    n·((C − P_k)·δ)/(n·(P_j − P_k)); D_i′ = B1 + R_i(D − B_i), R_i the turn from B_iK_i to B1K1, moves with D
    through R_i, with B1 and B_i by translation, and turns about B1 with the directions of B1K1 and B_iK_i
    (dα = (K − B)⊥·(dK − dB)/|K − B|²)."""
    # the vector formulas' operations in their order, on floats (the signs of zeros aside, which the norms'
    # squares and |det| do not see): the same result
    P = (D, D2, D3)
    J = []
    for k in range(3):
        pj, pk, pl = P[(k + 1) % 3], P[k], P[(k + 2) % 3]
        nx, ny = unit_xy(-(pl.y - pj.y), pl.x - pj.x)                       # n = (P_l − P_j)⊥, unit
        s = 1.0 / (nx * (pj.x - pk.x) + ny * (pj.y - pk.y))                 # 1 / n·(P_j − P_k)
        o = _outer(nx, ny, C.x - pk.x, C.y - pk.y)                          # n ⊗ (C − P_k)
        J.append((s * o[0], s * o[1], s * o[2], s * o[3]))
    eye = (1.0, 0.0, 0.0, 1.0)
    u1x, u1y = unit_xy(K1.x - B1.x, K1.y - B1.y)
    rot, p, grad = {}, {}, {}
    for i, (B, K, Dp) in ((2, (B2, K2, D2)), (3, (B3, K3, D3))):
        ux, uy = unit_xy(K.x - B.x, K.y - B.y)
        c, s = ux * u1x + uy * u1y, ux * u1y - uy * u1x
        rot[i] = (c, -s, s, c)
        p[i] = (-(Dp.y - B1.y), Dp.x - B1.x)                                # (D_i′ − B1)⊥
    for i, (B, K) in enumerate(((B1, K1), (B2, K2), (B3, K3)), 1):
        vx, vy = K.x - B.x, K.y - B.y
        vv = vx * vx + vy * vy
        grad[i] = (-vy / vv, vx / vv) if with_k else (0.0, 0.0)            # v⊥ / v·v
    m2, m3 = _mul(J[1], rot[2]), _mul(J[2], rot[3])
    blocks = [tuple(sum(t) for t in zip(J[0], m2, m3))]                                               # D
    blocks.append(_add(*(_mul(J[i - 1], _add(eye, _neg(_outer(*p[i], *grad[1])))) for i in (2, 3))))   # B1
    for i in (2, 3):                                                                                  # B2, B3
        blocks.append(_mul(J[i - 1], _add(_neg(rot[i]), _outer(*p[i], *grad[i]))))
    if with_k:
        blocks.append(_add(*(_mul(J[i - 1], _outer(*p[i], *grad[1])) for i in (2, 3))))               # K1
        for i in (2, 3):                                                                              # K2, K3
            blocks.append(_mul(J[i - 1], _neg(_outer(*p[i], *grad[i]))))
    return DRAFT * max(spectral_norm(M) for M in blocks)


def _copy_triangle(sc: Scene, key: str, P: Ref, src: tuple[Ref, Ref, str], dst: tuple[Ref, Ref, str], label: str,
                   words: tuple[str, str, str], *, style: str = "point") -> Ref:
    """Copy the triangle (B_i, K_i, P) onto (B_j, K_j): lay off the angle ∠K_iB_iP at B_j from B_jK_j and mark
    B_jP′ = B_iP on that side (angle and side copied, so the copy is congruent and equally oriented; a ray
    from the centre meets the compass arc square-on, also when the triangle is flat)."""
    (Bi, Ki, i), (Bj, Kj, j) = src, dst
    n = words[0]
    ang = sc.add(f"{key}_ang", copied_angle, Bi, Ki, P, visible=False)
    ray = sc.add(f"{key}_ray", ray_at_angle, Bj, Kj, ang, style="construction",
                 caption=(f"At B{j} lay off ∠K{i}B{i}{n} from B{j}K{j}", f"在 B{j} 处以 B{j}K{j} 为边作角等于 ∠K{i}B{i}{n}"))
    r = sc.add(f"{key}_r", length, Bi, P, visible=False, unit="mm")
    out = sc.add(key, point_on_ray, ray, r, style=style, label=label,
                 caption=(f"Mark B{j}{label} = B{i}{n} on it: {words[1]}", f"在其上截取 B{j}{label} = B{i}{n}:{words[2]}"))
    if sc.drawing:
        sc.add(f"{key}_arc", circle, Bj, r, style="construction")
    return out


def construct(g: Mapping[str, Any]) -> Construction:
    """The inversion: D carried with the coupler onto position 1, C1 the centre of D, D2′, D3′."""
    Bp, Kp, given_k = _coupler_points(g)
    sc = Scene("Four-bar from the fixed pivots and three coupler positions (inversion)")
    A = add_pivot(sc, "A", Point(*g["A"]), ("Fixed pivots A and D", "固定铰链 A、D"))
    D = add_pivot(sc, "D", Point(*g["D"]), ("", ""))
    drawing = sc.drawing                     # the given bars, joins, copied triangles and circles only a drawing needs
    if drawing:
        sc.add("frame", segment, A, D, role=Role.GIVEN, style="frame")
    Bs, Ks = [], []
    for i, (B, K) in enumerate(zip(Bp, Kp), 1):
        Bs.append(sc.given(f"B{i}", B, style="joint", caption=(
            f"Input link position AB{i}" + (f" and coupler point K{i}" if given_k else ""),
            f"输入杆位置 AB{i}" + (f"、连杆上点 K{i}" if given_k else ""))))
        if drawing:
            add_bar(sc, f"given_AB{i}", A, Bs[-1], style=f"pos{i}", role=Role.GIVEN)
        if given_k:
            Ks.append(sc.given(f"K{i}", K, style="point"))
        else:
            a = g["coupler_angles"][i - 1]
            Ks.append(sc.given(f"K{i}", K, style="point", caption=(
                f"Coupler line of position {i} at {a:g}°: mark K{i} on it, B{i}K{i} = B1D/2",
                f"作第 {i} 位置连杆线(方向角 {a:g}°),取 B{i}K{i} = B1D/2 得 K{i}")))
        if drawing:
            add_bar(sc, f"given_B{i}K{i}", Bs[-1], Ks[-1], style=f"pos{i}", role=Role.GIVEN)
    # invert: carry D with the coupler from positions 2 and 3 onto position 1
    Dp = []
    for i in (2, 3):
        B, K = Bs[i - 1], Ks[i - 1]
        if drawing:
            sc.add(f"tri{i}_B", segment, B, D, style="construction",
                   caption=(f"Join B{i}D and K{i}D: the triangle B{i}K{i}D", f"连接 B{i}D、K{i}D 得 △B{i}K{i}D"))
            sc.add(f"tri{i}_K", segment, K, D, style="construction")
        Di = _copy_triangle(sc, f"D{i}p", D, (B, K, str(i)), (Bs[0], Ks[0], "1"), f"D{i}′",
                            ("D", f"△B1K1D{i}′ ≅ △B{i}K{i}D, D carried rigidly onto position 1",
                             f"△B1K1D{i}′ ≌ △B{i}K{i}D,把 D 刚化反转到位置 1"))
        if drawing:
            sc.add(f"copy{i}_B", segment, Bs[0], Di, style="ghost",
                   caption=(f"The copied triangle B1K1D{i}′", f"复制的 △B1K1D{i}′"))
            sc.add(f"copy{i}_K", segment, Ks[0], Di, style="ghost")
        Dp.append(Di)
    pts = [D, *Dp]
    C1 = add_bisector_centre(sc, "C1", pts, ("D", "D2′", "D3′"), "C1",
                             ("The bisectors meet at the hinge C1", "两中垂线交于活动铰链 C1"), style="joint",
                             keys=("D", "D2p", "D3p"), ground=False)
    v = sc.evaluate(["D", "D2p", "D3p"])
    warnings = require_distinct_noncollinear(("D", "D2′", "D3′"), [v["D"], v["D2p"], v["D3p"]], "the hinge C1")
    if drawing:
        sc.add("kC", circle, C1, sc.add("rC", length, C1, D, visible=False), style="construction",
               caption=("The circle about C1 through D, D2′, D3′", "以 C1 为圆心过 D、D2′、D3′ 的圆"))
    # carry C1 back with the coupler to positions 2 and 3
    Cs = [C1]
    for i in (2, 3):
        Cs.append(_copy_triangle(sc, f"C{i}", C1, (Bs[0], Ks[0], "1"), (Bs[i - 1], Ks[i - 1], str(i)), f"C{i}",
                                 ("C1", f"the hinge in position {i}", f"第 {i} 位置的铰链"), style="joint"))
    if drawing:
        sc.add("kDC", circle, D, sc.add("rDC", length, D, C1, visible=False), style="path",
               caption=("The path of C: the circle about D through C1, C2, C3", "C 点轨迹:以 D 为圆心过 C1、C2、C3 的圆"))
    add_positions(sc, A, D, Bs, Cs)
    answers = add_report(sc, A, D, Bs, Cs)
    sc.add("sens_C", hinge_sensitivity, C1, D, *Dp, *Bs, *Ks, given_k, role=Role.MEASUREMENT, unit="mm",
           caption=("Sensitivity of C1 per 0.1 mm of drafting error (Jacobian of the construction)",
                    "C1 对 0.1 mm 作图误差的敏感度"))
    answers["sens_C"] = "sens_C"
    sc.add("C1_xy", xy, C1, visible=False)
    answers["C1"] = "C1_xy"
    warnings += evaluate_defects(sc, Bs, Cs, D)
    return Construction(sc, answers, {n: n for n in POINTS}, warnings=tuple(warnings))


def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """C1 by the coupler-frame linear solve (:func:`geomcon.analytic.synthesis.three_positions_fixed_pivots`)."""
    Ks = [g[f"K{i}"] for i in (1, 2, 3)] if g.get("K1") is not None else None
    r = twin(g["A"], g["D"], [g[f"B{i}"] for i in (1, 2, 3)], Ks=Ks, angles=g.get("coupler_angles"))
    return [{q.name: r[q.name] for q in ANSWERS}]


def back_check(g: Mapping[str, Any], ans: Mapping[str, Any]) -> list[tuple[str, float, float, str]]:
    """Drive the designed linkage to the input angles of B1, B2, B3 on the branch of position 1: it must
    reach C1, C2, C3 and turn the coupler line to B_iK_i."""
    # C1, C2, C3 by the construction's own steps (the triangles copied by _copy_triangle, the bisectors of
    # add_bisector_centre met): the same values as its scene's, without building the rest of it
    Bs, Ks, _ = _coupler_points(g)
    D = Point(*g["D"])
    Dp = [_copied(D, Bs[i - 1], Ks[i - 1], Bs[0], Ks[0]) for i in (2, 3)]
    C1 = meet(perpendicular_bisector(D, Dp[0]), perpendicular_bisector(Dp[0], Dp[1]))
    Cs = [C1] + [_copied(C1, Bs[0], Ks[0], Bs[i - 1], Ks[i - 1]) for i in (2, 3)]
    return positions_back_check(Point(*g["A"]), D, ans["AB"], ans["BC"], ans["CD"], Bs, Cs, list(Ks))


def _copied(P: Point, Bi: Point, Ki: Point, Bj: Point, Kj: Point) -> Point:
    """P carried from (B_i, K_i) onto (B_j, K_j): the values of :func:`_copy_triangle`'s steps."""
    return point_on_ray(ray_at_angle(Bj, Kj, copied_angle(Bi, Ki, P)), length(Bi, P))


RECIPE = Recipe(
    name="four_bar.three_positions_fixed_pivots",
    title="Four-bar from the fixed pivots A, D, three input positions and three coupler positions (inversion)",
    givens=GIVENS,
    answers=ANSWERS,
    points=POINTS,
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
    rigid=(tuple(("A", f"B{i}") for i in (1, 2, 3)),                # the input link AB in its three positions
           tuple((f"B{i}", f"K{i}") for i in (1, 2, 3))),           # the coupler's point K, carried by B
)
