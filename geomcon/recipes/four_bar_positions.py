"""``four_bar.three_positions``: a four-bar whose coupler BC passes three given positions (moving pivots given).

B and C move on circles about the fixed pivots, so A is the centre of the circle through B1, B2, B3 — the
meeting point of the perpendicular bisectors of the chords B1B2 and B2B3 — and D likewise the centre of
C1, C2, C3. The designed linkage is drawn in its three positions and measured (see
:mod:`.synthesis_common` for γmin, the branch and the order), and each fixed pivot's sensitivity to the
drafting of the positions is reported: how far it moves, at worst, when one given point is misplaced by
0.1 mm (DRAFT · R / h_min, h_min the smallest altitude of the triangle of the three positions).

Drafted data. Coordinates copied from a drawing or a textbook are rounded, so |B1C1|, |B2C2|, |B3C3| differ a
little. Up to 1 % of the longest (:data:`~.synthesis_common.DRAFT_REFUSE_REL`) they are accepted with a
warning and fitted to a rigid coupler by one documented rule (:func:`~.synthesis_common.fit_rigid`): the
B_i are kept and each C_i slides along B_iC_i to the mean length BC; D is the centre of the fitted C_i, and
the back-substitution drives the linkage through the fitted positions. The twin fits the same way. Beyond
1 % the coupler is refused as not rigid.

Examples
--------
>>> from geomcon.problems import problem_from_dict
>>> from geomcon.solve import solve
>>> s = solve(problem_from_dict({"recipe": "four_bar.three_positions", "given": {
...     "B1": [10, 17.320508075689], "B2": [-3.472963553339, 19.696155060244], "B3": [-15.320888862380, 12.855752193731],
...     "C1": [47.671051703496, 41.935378856429], "C2": [36.757733714529, 39.857776952869],
...     "C3": [24.665115845391, 33.498412572427]}}, name="demo"))
>>> [round(s.answers[k], 6) for k in ("AB", "BC", "CD", "AD")]
[20.0, 45.0, 42.0, 50.0]
>>> s.answers["crank"], s.answers["branch_ok"], s.answers["order_ok"], s.ok
(True, True, True, True)
"""
from __future__ import annotations

from typing import Any, Mapping

from ..analytic.synthesis import three_positions as twin
from ..errors import NotAMechanism
from ..geometry import Point, circle, perpendicular_bisector, segment
from ..scene import Role, Scene
from ..tolerance import tol
from .base import Construction, Quantity, Recipe
from .common import length
from .synthesis_common import (DRAFT_REFUSE_REL, add_bisector_centre, add_positions, add_report, centre_sensitivity,
                               evaluate_defects, fit_rigid, meet, positions_back_check, require_distinct_noncollinear,
                               require_equal, xy)

NAMES = ("B1", "B2", "B3", "C1", "C2", "C3")
GIVENS = tuple(Quantity(n, "point", f"position {n[1]} of the moving pivot {n[0]} [x, y]", minimum=None) for n in NAMES)
REPORT = (
    Quantity("AB", "mm", "input link (crank or rocker) AB"),
    Quantity("BC", "mm", "coupler BC"),
    Quantity("CD", "mm", "output link CD"),
    Quantity("AD", "mm", "frame AD"),
    Quantity("grashof", "bool", "Grashof's condition s + l ≤ p + q holds"),
    Quantity("grashof_margin", "mm", "(p + q) − (s + l): > 0 Grashof, 0 change point, < 0 no link turns fully"),
    Quantity("crank", "bool", "AB turns fully relative to the frame (crank-rocker or double crank)"),
    Quantity("output_crank", "bool", "CD turns fully relative to the frame (double crank or rocker-crank)"),
    Quantity("gamma_min", "deg", "smallest transmission angle: over the full turn when AB is a crank, else over the working arc"),
    Quantity("gamma_min_work", "deg", "smallest transmission angle while AB turns from B1 through B2 to B3 (0 at a dead point)"),
    Quantity("branch_ok", "bool", "the three positions lie on one assembly branch (no branch defect)"),
    Quantity("order_ok", "bool", "AB turns from B1 through B2 to B3 without meeting a dead point (no order defect)"),
    Quantity("phi", "deg[]", "directions of AB1, AB2, AB3 (deg, counter-clockwise from +x)"),
)
ANSWERS = (
    Quantity("A", "mm[]", "fixed pivot of the input link [x, y]: the centre of B1, B2, B3"),
    Quantity("D", "mm[]", "fixed pivot of the output link [x, y]: the centre of C1, C2, C3 (fitted, for drafted data)"),
) + REPORT + (
    Quantity("sens_A", "mm", "worst shift of A when one of B1, B2, B3 is misplaced by 0.1 mm (mm per 0.1 mm)"),
    Quantity("sens_D", "mm", "worst shift of D when one of C1, C2, C3 is misplaced by 0.1 mm (mm per 0.1 mm)"),
)


def _points(g: Mapping[str, Any]) -> dict[str, Point]:
    """The given points, each C_i fitted onto the rigid coupler (slid along B_iC_i to the mean BC)."""
    p = {n: Point(*g[n]) for n in NAMES}
    _, fitted = fit_rigid([p[f"B{i}"] for i in (1, 2, 3)], [p[f"C{i}"] for i in (1, 2, 3)])
    p.update({f"C{i}": C for i, C in enumerate(fitted, 1)})
    return p


def _validate(g: Mapping[str, Any]) -> list[str]:
    raw = {n: Point(*g[n]) for n in NAMES}
    for i in (1, 2, 3):
        if raw[f"B{i}"] == raw[f"C{i}"]:
            raise NotAMechanism(f"B{i} = C{i} = ({raw[f'B{i}'].x:g}, {raw[f'B{i}'].y:g}): the coupler has no length")
    lens = {f"B{i}C{i}": abs(raw[f"C{i}"] - raw[f"B{i}"]) for i in (1, 2, 3)}
    warn = require_equal("the coupler is not rigid", lens, refuse_rel=DRAFT_REFUSE_REL,
                         why=f" (drafted data?): each C_i is slid along B_iC_i to the mean BC = {sum(lens.values()) / 3:.10g} mm")
    p = _points(g)
    warn += require_distinct_noncollinear(NAMES[:3], [p[n] for n in NAMES[:3]], "the fixed pivot A")
    warn += require_distinct_noncollinear(NAMES[3:], [p[n] for n in NAMES[3:]], "the fixed pivot D")
    A, D = (meet(perpendicular_bisector(p[f"{X}1"], p[f"{X}2"]), perpendicular_bisector(p[f"{X}2"], p[f"{X}3"]))
            for X in "BC")
    if abs(A - D) <= tol(*(abs(q) for q in p.values()), abs(A)):
        raise NotAMechanism(f"A = D = ({A.x:.6g}, {A.y:.6g}): the three positions are turns of the coupler about one "
                            "point, the frame AD has no length")
    return warn


def construct(g: Mapping[str, Any]) -> Construction:
    """Perpendicular bisectors of B1B2, B2B3 meet at A; of C1C2, C2C3 at D."""
    p = _points(g)
    sc = Scene("Four-bar through three coupler positions")
    drawing = sc.drawing                     # the given bars and the paths only a drawing needs
    Bs, Cs = [], []
    for i in (1, 2, 3):
        Bs.append(sc.given(f"B{i}", p[f"B{i}"], style="joint",
                           caption=(f"Coupler position {i}: B{i}C{i}", f"连杆第 {i} 位置 B{i}C{i}")))
        Cs.append(sc.given(f"C{i}", p[f"C{i}"], style="joint"))
        if drawing:
            sc.add(f"given_B{i}C{i}", segment, Bs[-1], Cs[-1], role=Role.GIVEN, style=f"pos{i}")
    A = add_bisector_centre(sc, "A", Bs, NAMES[:3], "A", ("The bisectors meet at the fixed pivot A", "两中垂线交于固定铰链 A"))
    D = add_bisector_centre(sc, "D", Cs, NAMES[3:], "D", ("The bisectors meet at the fixed pivot D", "两中垂线交于固定铰链 D"))
    if drawing:
        sc.add("kA", circle, A, sc.add("rA", length, A, Bs[0], visible=False), style="path",
               caption=("The path of B: the circle about A through B1, B2, B3", "B 点轨迹:以 A 为圆心过 B1、B2、B3 的圆"))
        sc.add("kD", circle, D, sc.add("rD", length, D, Cs[0], visible=False), style="path",
               caption=("The path of C: the circle about D through C1, C2, C3", "C 点轨迹:以 D 为圆心过 C1、C2、C3 的圆"))
    add_positions(sc, A, D, Bs, Cs)
    answers = add_report(sc, A, D, Bs, Cs)
    sc.add("sens_A", centre_sensitivity, A, *Bs, role=Role.MEASUREMENT, unit="mm",
           caption=("Sensitivity of A: 0.1 mm · R / smallest altitude of B1B2B3", "A 的敏感度:0.1 mm · R / B1B2B3 最小高"))
    sc.add("sens_D", centre_sensitivity, D, *Cs, role=Role.MEASUREMENT, unit="mm",
           caption=("Sensitivity of D: 0.1 mm · R / smallest altitude of C1C2C3", "D 的敏感度:0.1 mm · R / C1C2C3 最小高"))
    sc.add("A_xy", xy, A, visible=False)
    sc.add("D_xy", xy, D, visible=False)
    answers |= {"sens_A": "sens_A", "sens_D": "sens_D", "A": "A_xy", "D": "D_xy"}
    return Construction(sc, answers, {n: n for n in ("A", "D") + NAMES}, warnings=tuple(evaluate_defects(sc, Bs, Cs, D)))


def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The circumcentres by Cramer's rule (:func:`geomcon.analytic.synthesis.three_positions`)."""
    r = twin(*(g[n] for n in NAMES))
    return [{q.name: r[q.name] for q in ANSWERS}]


def back_check(g: Mapping[str, Any], ans: Mapping[str, Any]) -> list[tuple[str, float, float, str]]:
    """Drive the designed linkage to the input angles of B1, B2, B3 on the branch of position 1: it must
    reach C1, C2, C3."""
    p = _points(g)
    Bs, Cs = [p[f"B{i}"] for i in (1, 2, 3)], [p[f"C{i}"] for i in (1, 2, 3)]
    # A and D by the construction's own steps (add_bisector_centre: the bisectors of P1P2 and P2P3 met), the
    # same values as its scene's "A" and "D" without building the rest of it
    A, D = (meet(perpendicular_bisector(P[0], P[1]), perpendicular_bisector(P[1], P[2])) for P in (Bs, Cs))
    return positions_back_check(A, D, ans["AB"], ans["BC"], ans["CD"], Bs, Cs)


RECIPE = Recipe(
    name="four_bar.three_positions",
    title="Four-bar through three given coupler positions B1C1, B2C2, B3C3 (fixed pivots by bisectors)",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "D") + NAMES,
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
    rigid=(tuple((f"B{i}", f"C{i}") for i in (1, 2, 3)),),        # the coupler BC in its three positions
)
