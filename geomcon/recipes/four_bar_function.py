"""``four_bar.function_generation``: a four-bar whose rocker's three positions correspond to three crank angles.

Givens and conventions: A at the origin, D = (AD, 0) on +x. The crank AB makes the angle φ with the frame
line A→D, counter-clockwise. The rocker carries a marked line DE (the line the problem prescribes, e.g. a
pointer); ψ is the direction of DE measured, as the crank's, counter-clockwise from the direction A→D —
i.e. from AD extended beyond D (the interior angle ∠ADE is 180° − ψ). This is the textbook convention of
Freudenstein's equation (both angles from the frame line, counter-clockwise). Only ψ1 − ψi enter the
construction; the hinge C found lies at the angle β from DE (β = 0 when C happens to lie on DE).

Construction (the inversion method, 刚化反转法): hold the rocker in position 1 and turn the whole linkage
about D so that the rocker's position i falls on position 1: the crank pin Bi goes to Bi′, turned about D
through ψ1 − ψi (△DEiBi ≅ △DE1Bi′). In that frame B moves on a circle about the hinge C1, so C1 is the centre
of the circle through B1, B2′, B3′: the perpendicular bisectors of B1B2′ and B2′B3′ meet at C1. Then
BC = B1C1, CD = DC1, and C2, C3 are C1 carried by the rocker (turned about D through ψi − ψ1).

Checks: the twin is Freudenstein's equation as a linear 3×3 system
(:mod:`geomcon.analytic.function_generation`). The back-substitution assembles the designed linkage at each
φi with :func:`geomcon.analytic.fourbar_drive.assemble` on the branch of position 1 and reads the rocker's
angle. ``branch_ok`` says whether the three designed positions lie on one assembly branch (C on the same side
of BD); ``order_ok`` whether the crank, turning from φ1 through φ2 to φ3, meets no dead point (coupler and
rocker collinear; always true when AB turns fully). ``sens_C1`` is how far C1 moves per 0.1° of error in
any one given angle and ``sens_C1_mm`` per 0.1 mm of AD or AB: first order, by sliding the centre along the
fixed bisector when one of the three points moves.

Refusals: two equal angle pairs, inverted points that coincide or lie on a line (the
triangle B1B2′B3′ with R/h_min ≥ 1e7, warned from 100 — the policy of every three-position synthesis), a hinge
falling on D.
"""
from __future__ import annotations

import math
from typing import Any, Mapping, Sequence

from ..analytic.fourbar_drive import angle_of, assemble, branch_of, crank_point
from ..analytic.function_generation import check_inverted, function_generation, hinge_distance, inverted_pins
from ..errors import NotAMechanism
from ..numeric import deg360
from ..geometry import (Arc, LeftOf, Point, RightOf, circle, circle_circle, midpoint,
                        perpendicular_bisector, polar_angle, rotate, segment)
from ..geometry.primitives import unit_xy
from ..scene import Ref, Role, Scene, marks
from ..tolerance import REL_TOL
from .base import Construction, Quantity, Recipe
from .common import add_pivot, length, transmission_deg, transmission_mark
from .theta_circle import meet_lines

GIVENS = (
    Quantity("AD", "mm", "frame: A at the origin, D on +x"),
    Quantity("AB", "mm", "crank"),
    Quantity("phi", "deg[]", "three crank angles φ1, φ2, φ3: direction of AB, counter-clockwise from the frame line A→D",
             minimum=None),
    Quantity("psi", "deg[]", "the three corresponding rocker angles ψ1, ψ2, ψ3: direction of the rocker's marked line "
             "DE, counter-clockwise from A→D (AD extended beyond D)", minimum=None),
)
ANSWERS = (
    Quantity("C1", "mm[]", "hinge of coupler and rocker in position 1, [x, y]"),
    Quantity("BC", "mm", "coupler"),
    Quantity("CD", "mm", "rocker"),
    Quantity("beta", "deg", "angle of DC from the marked line DE, counter-clockwise, 0° ≤ β < 360°"),
    Quantity("gamma_min", "deg", "smallest transmission angle over the motion (whole turn when AB is a crank, else "
             "from φ1 through φ2 to φ3)"),
    Quantity("grashof", "bool", "shortest + longest ≤ sum of the other two"),
    Quantity("crank", "bool", "AB turns fully"),
    Quantity("branch_ok", "bool", "the three positions lie on one assembly branch"),
    Quantity("order_ok", "bool", "the crank reaches φ1, φ2, φ3 in this order without passing a dead point"),
    Quantity("sens_C1", "mm", "how far C1 moves per 0.1° of error in any one given angle (the largest)"),
    Quantity("sens_C1_mm", "mm", "how far C1 moves per 0.1 mm of error in AD or AB (the largest)"),
)
DRAFT_DEG = math.radians(0.1)
DRAFT_MM = 0.1


# ----------------------------------------------------------------------------------------- validation
def same_pairs(angles: Sequence[Sequence[float]], names: str) -> None:
    """Refuse two positions whose given angles are all equal (mod 360°)."""
    n = len(angles[0])
    for i in range(n):
        for j in range(i + 1, n):
            if all(abs((a[i] - a[j] + 180.0) % 360.0 - 180.0) <= 1e-9 for a in angles):
                vals = ", ".join(f"{a[i]:g}°" for a in angles)
                raise NotAMechanism(f"positions {i + 1} and {j + 1} are the same ({names} = {vals}): "
                                    "three distinct positions are needed")


def count(g: Mapping[str, Any], names: Sequence[str], n: int) -> None:
    """Refuse angle lists that do not hold ``n`` values."""
    for k in names:
        if len(g[k]) != n:
            raise NotAMechanism(f"{k} must hold {n} angles, got {len(g[k])}")


def _validate(g: Mapping[str, Any]) -> list[str]:
    count(g, ("phi", "psi"), 3)
    same_pairs((g["phi"], g["psi"]), "φ, ψ")
    warnings = check_inverted(inverted_pins(g["AD"], g["AB"], g["phi"], g["psi"]), "C1", "B1, B2′, B3′")
    cd = hinge_distance(g["AD"], g["AB"], g["phi"], g["psi"])
    if cd <= 1e-9 * max(g["AD"], g["AB"]):
        raise NotAMechanism(f"the hinge C1 falls on D (CD = {cd:.3g}): no rocker")
    return warnings


# ----------------------------------------------------------------------------------------- step operations
def polar_point(center: Point, r: float, deg: float) -> Point:
    """The point at distance r from center in the direction ``deg`` (counter-clockwise from +x)."""
    t = math.radians(deg)
    return Point(center.x + r * math.cos(t), center.y + r * math.sin(t))


def turn(p: Point, center: Point, deg: float) -> Point:
    """``p`` turned about ``center`` through ``deg`` degrees."""
    return rotate(p, center, math.radians(deg))


def turn_arc(center: Point, p: Point, deg: float) -> Arc:
    """The arc a point ``p`` describes when turned about ``center`` through ``deg`` degrees."""
    start = polar_angle(center, p)
    sweep = math.radians(deg)
    return Arc(center, abs(p - center), start if sweep >= 0 else start + sweep, abs(sweep))


def bisector_mark(p: Point, q: Point) -> marks.RightAngleMark:
    """Right-angle mark where the perpendicular bisector of pq crosses it."""
    m = midpoint(p, q)
    return marks.RightAngleMark(m, q, m + (q - p).perp())


def centre_shift(O: Point, P: Sequence[Point], dP: Sequence[Point]) -> Point:
    """First-order movement of the centre O of the circle through P1, P2, P3 when they move by dP.

    Moving only Pk keeps O on the bisector of the other two points (direction t ⊥ PjPl) and keeps
    |O − Pk| = |O − Pj|; hence dO = ((O − Pk)·dPk) / (t·(Pj − Pk)) · t. The moves superpose.

    >>> P = (Point(1, 0), Point(0, 1), Point(-1, 0))
    >>> centre_shift(Point(0, 0), P, (Point(0.1, 0), Point(0, 0), Point(0, 0)))
    Point(x=0.05, y=-0.05)
    """
    x, y = _shift_xy(O, P, _bisectors(P), dP)
    return Point(x, y)


def _bisectors(P: Sequence[Point]) -> tuple[tuple[float, float, float, float, float], ...]:
    """Per point P_k: (P_k, the unit direction t ⊥ P_jP_l, t·(P_j − P_k)) as floats, the same numbers as
    (P[l] − P[j]).perp().unit() and t.dot(P[j] − P[k])."""
    out = []
    for k in range(3):
        pj, pk, pl = P[(k + 1) % 3], P[k], P[(k + 2) % 3]
        tx, ty = unit_xy(-(pl.y - pj.y), pl.x - pj.x)
        out.append((pk.x, pk.y, tx, ty, tx * (pj.x - pk.x) + ty * (pj.y - pk.y)))
    return tuple(out)


def _shift_xy(O: Point, P: Sequence[Point], bis: tuple, dP: Sequence[Point]) -> tuple[float, float]:
    """:func:`centre_shift` on floats, in the order of its vector formula: out + t·((O − P_k)·dP_k / den)."""
    ox, oy = O.x, O.y
    x = y = 0.0
    for (px, py, tx, ty, den), d in zip(bis, dP):
        f = ((ox - px) * d.x + (oy - py) * d.y) / den
        x, y = x + tx * f, y + ty * f
    if x - x != 0.0 or y - y != 0.0:                   # not finite: the points of the vector formula refuse it
        out = Point(0.0, 0.0)
        for k in range(3):
            j, l = (k + 1) % 3, (k + 2) % 3
            t = (P[l] - P[j]).perp().unit()
            out = out + t * ((O - P[k]).dot(dP[k]) / t.dot(P[j] - P[k]))
    return x, y


def largest_shift(O: Point, P: Sequence[Point], moves: Sequence[Sequence[Point]], per: float) -> float:
    """The largest |dO| over the given sets of first-order point moves, times ``per``.

    >>> P = (Point(1, 0), Point(0, 1), Point(-1, 0))
    >>> z = Point(0, 0)
    >>> largest_shift(Point(0, 0), P, [(Point(0.1, 0), z, z), (z, Point(0, 0.3), z)], 10.0) == 3.0
    True
    """
    bis = _bisectors(P)
    return max(math.hypot(*_shift_xy(O, P, bis, m)) for m in moves) * per


def inverse_turn(v: Point, deg: float) -> Point:
    """Vector ``v`` turned through ``deg`` degrees (a move carried into the inverted frame)."""
    return rotate(v, Point(0.0, 0.0), math.radians(deg))


def fg_sensitivity(A: Point, D: Point, B: Sequence[Point], P: Sequence[Point], C1: Point,
                   phi: Sequence[float], psi: Sequence[float]) -> tuple[float, float]:
    """(mm per 0.1° of any given angle, mm per 0.1 mm of AD or AB) for C1, from :func:`centre_shift`.

    The inverted points are P1 = B1, Pi = Bi turned about D through ψ1 − ψi. Per radian: φi moves Bi along
    the crank circle (perpendicular to ABi); ψ1 turns P2, P3 about D, ψi (i > 1) turns Pi back; AB moves
    each Bi along ABi; AD moves D (and with it the centre of the turns) along the frame.
    """
    zero = Point(0.0, 0.0)
    rot = [psi[0] - p for p in psi]
    angle_moves = []
    for i in range(3):                                       # φi
        m = [zero] * 3
        m[i] = inverse_turn((B[i] - A).perp(), rot[i])
        angle_moves.append(m)
    angle_moves.append([zero] + [(P[i] - D).perp() for i in (1, 2)])      # ψ1
    for i in (1, 2):                                         # ψ2, ψ3
        m = [zero] * 3
        m[i] = -(P[i] - D).perp()
        angle_moves.append(m)
    ab = [inverse_turn((B[i] - A).unit(), rot[i]) for i in range(3)]
    ad = [zero] + [Point(1.0, 0.0) - inverse_turn(Point(1.0, 0.0), rot[i]) for i in (1, 2)]
    return (largest_shift(C1, P, angle_moves, DRAFT_DEG), largest_shift(C1, P, (ab, ad), DRAFT_MM))


def first(x: tuple) -> Any:
    """The first element of a pair (a step that splits a tuple)."""
    return x[0]


def second(x: tuple) -> Any:
    """The second element of a tuple."""
    return x[1]


def third(x: tuple) -> Any:
    """The third element of a tuple."""
    return x[2]


def side_of(B: Point, C: Point, D: Point) -> int:
    """+1 when C lies left of the directed line B→D, −1 right, 0 on it (the assembly branch)."""
    s = (D - B).cross(C - B)
    scale = abs(D - B) * abs(C - B)
    return 0 if abs(s) <= REL_TOL * scale else (1 if s > 0 else -1)


def same_branch(*sides: int) -> bool:
    """True when every position has the same, non-zero branch."""
    return len(set(sides)) == 1 and 0 not in sides


def dead_pins(A: Point, AB: float, D: Point, BC: float, CD: float) -> tuple[tuple[Point, ...], bool]:
    """(pins, crank): the crank pins where coupler and rocker are collinear — the crank circle meets the
    circles about D of radii BC + CD and |BC − CD| — and whether AB turns fully (no circle crosses it;
    touching is a change point, the crank still turns)."""
    kA = circle(A, AB)
    pins, crank = [], True
    for r in (BC + CD, abs(BC - CD)):
        if r <= REL_TOL * (BC + CD):
            continue
        pts = circle_circle(kA, circle(D, r))
        pins += pts
        crank = crank and len(pts) < 2
    return tuple(pins), crank


def on_turn(A: Point, X: Point, B1: Point, B2: Point, B3: Point) -> bool:
    """True when the pin X lies on the crank's turn from B1 through B2 to B3 (ends included)."""
    a1, a2, a3, ax = (math.degrees(polar_angle(A, p)) for p in (B1, B2, B3, X))
    ccw = (a2 - a1) % 360.0 < (a3 - a1) % 360.0
    span = (a3 - a1) % 360.0 if ccw else (a1 - a3) % 360.0
    t = (ax - a1) % 360.0 if ccw else (a1 - ax) % 360.0
    return t <= span or t >= 360.0 - 1e-9


def order_free(A: Point, B1: Point, B2: Point, B3: Point, dead: tuple) -> bool:
    """True when the crank turns fully or no dead pin lies on its turn from B1 through B2 to B3."""
    pins, crank = dead
    return crank or not any(on_turn(A, X, B1, B2, B3) for X in pins)


def farther_by(P: Point, Q: Point, R: Point) -> float:
    """|PQ| − |PR| as (Q − R)·((Q − P) + (R − P)) / (|PQ| + |PR|): from the difference of the nearby points Q, R,
    not of two long distances (each holds only ε of itself).

    >>> farther_by(Point(0, 0), Point(3, 4), Point(0, 4))
    1.0
    """
    return _farther_by_xy(P.x, P.y, Q.x, Q.y, R.x, R.y)


def _farther_by_xy(px: float, py: float, qx: float, qy: float, rx: float, ry: float) -> float:
    """:func:`farther_by` on floats, in the order of its vector formula (the same bits)."""
    ax, ay, bx, by = qx - px, qy - py, rx - px, ry - py              # Q − P, R − P
    return ((qx - rx) * (ax + bx) + (qy - ry) * (ay + by)) / (math.hypot(ax, ay) + math.hypot(bx, by))


def design_transmission(B: Point, D: Point, B1: Point, C1: Point, DC1: Point | None = None) -> float:
    """The acute transmission angle (deg) of the designed linkage (BC = |B1C1|, CD = |DC1|) with its crank pin
    at B: the triangle B C D's angle at C from Kahan's factors, each a side plus or minus a difference of
    sides read from nearby points (:func:`farther_by`). Re-intersecting the circles about B and D put C off by
    the last bit of BC over sin γ: with AD = 1e9 and CD = 150, BC (1e9) holds only 1e-7 mm, and a 0.4° γmin
    came out 1.3e-6° off. ``DC1`` is the rocker C1 − D as found from D (:func:`hinge_from`; default the
    difference of the points): with CD = 5e-6 and AD = 80, C1 − D read from C1 holds only 1e-8 of CD.

    >>> round(design_transmission(Point(50, 0), Point(90, 0), Point(0, 50), Point(64.995527349, 75.991949228)), 6)
    29.994726
    """
    # on floats, in the order of the vector formulas in the comments (the same bits)
    bx, by, dx, dy, b1x, b1y, c1x, c1y = B.x, B.y, D.x, D.y, B1.x, B1.y, C1.x, C1.y
    ux, uy = (c1x - dx, c1y - dy) if DC1 is None else (DC1.x, DC1.y)  # u = C1 − D
    x, y, z = math.hypot(c1x - b1x, c1y - b1y), math.hypot(ux, uy), math.hypot(dx - bx, dy - by)   # BC, CD, BD
    d_xy = _farther_by_xy(c1x, c1y, b1x, b1y, dx, dy)                 # BC − CD
    d_bc = (ux * ((c1x - b1x) + (dx - b1x)) + uy * ((c1y - b1y) + (dy - b1y))) / (x + math.hypot(dx - b1x, dy - b1y))
    d_xz = d_bc + _farther_by_xy(dx, dy, b1x, b1y, bx, by)            # BC − BD
    d_yz = _farther_by_xy(dx, dy, c1x, c1y, b1x, b1y) + _farther_by_xy(dx, dy, b1x, b1y, bx, by)   # CD − BD
    f1 = y - d_xz if y <= z else z - d_xy                             # y + z − x
    f2 = x - d_yz if x <= z else z + d_xy                             # x + z − y
    f3 = x + d_yz if x <= y else y + d_xz                             # x + y − z
    g = math.degrees(2.0 * math.atan2(math.sqrt(max(0.0, f1 * f2)), math.sqrt(max(0.0, (x + y + z) * f3))))
    return min(g, 180.0 - g)


def hinge_from(D: Point, X: Sequence[Point], P: Sequence[Point]) -> Point:
    """The centre of the circle through the inverted points P1 = X1, P2′, P3′ (Pi = Xi turned about D), as the
    vector from D: the meet of the two perpendicular bisectors written from D, o·(Pi − P1) = (|Pi − D|² −
    |P1 − D|²)/2, whose right sides are (Xi − X1)·((Xi − D) + (X1 − D))/2 (the turn keeps |Pi − D| = |Xi − D|):
    a product with the difference of the nearby points Xi, X1, never the difference of two squares.

    The bisectors met in the drawing's coordinates hold the hinge only to the last bit of |D| (1e-14 mm at
    AD = 80): with AB = 1e-6 the hinge is 5e-6 mm from D and β came out 5.8e-7° off.

    >>> X = (Point(1, 0), Point(3, 0), Point(2, 1))                     # no turn: Pi = Xi
    >>> hinge_from(Point(0, 0), X, X)
    Point(x=2.0, y=0.0)
    """
    rows, rhs = [], []
    for i in (1, 2):
        rows.append(P[i] - P[0])
        rhs.append((X[i] - X[0]).dot((X[i] - D) + (X[0] - D)) / 2.0)
    det = rows[0].cross(rows[1])
    if det == 0.0:
        raise NotAMechanism("the inverted points lie on a line: the hinge would lie at infinity")
    return Point((rhs[0] * rows[1].y - rhs[1] * rows[0].y) / det, (rows[0].x * rhs[1] - rows[1].x * rhs[0]) / det)


def from_D(D: Point, u: Point) -> Point:
    """The point D + u."""
    return D + u


def ccw_deg_of(D: Point, E: Point, u: Point) -> float:
    """The angle from DE to the vector u, counter-clockwise, degrees in [0°, 360°) as a textbook states an angle
    measured one way round (100-06 printed β = −171.561° for 188.439°)."""
    return deg360(math.degrees(math.atan2(u.y, u.x) - polar_angle(D, E)))


def worst_transmission(A: Point, D: Point, AB: float, BC: float, CD: float, B1: Point, B2: Point, B3: Point,
                       side: int, dead: tuple, C1: Point, DC1: Point | None = None) -> tuple[float, Point, Point]:
    """(γmin, B, C) over the motion: the transmission angle is extreme where BD is, i.e. with the crank along
    the frame line (both ways for a crank; those on the turn otherwise) or at the ends of the turn; a dead
    point on the turn gives 0. γ is measured by :func:`design_transmission` (C drawn by the circles)."""
    pins, crank = dead
    if not crank:
        on = [X for X in pins if on_turn(A, X, B1, B2, B3)]
        if on:
            X = on[0]
            Cs = [D + (X - D).unit() * (k * CD) for k in (1.0, -1.0)]
            return 0.0, X, min(Cs, key=lambda C: abs(abs(C - X) - BC))
    along = [polar_point(A, AB, 0.0), polar_point(A, AB, 180.0)]
    cands = along if crank else [B1, B3] + [X for X in along if on_turn(A, X, B1, B2, B3)]
    rule = LeftOf if side >= 0 else RightOf
    best = None
    for B in cands:
        C = rule(B, D).choose(circle_circle(circle(B, BC), circle(D, CD)))
        g = design_transmission(B, D, B1, C1, DC1)
        if best is None or g < best[0]:
            best = (g, B, C)
    return best


def signed_deg(D: Point, E: Point, C: Point) -> float:
    """The angle from DE to DC, counter-clockwise, degrees in (−180°, 180°]."""
    a = math.degrees(polar_angle(D, C) - polar_angle(D, E))
    return (a + 180.0) % 360.0 - 180.0 if (a + 180.0) % 360.0 != 0.0 else 180.0


def as_xy(p: Point) -> tuple[float, float]:
    """A point as the answer pair (x, y)."""
    return p.tuple()


def defect_warnings(sc: Scene, keys: Mapping[str, str], labels: Sequence[str], what: str,
                    sides_words: tuple[str, str, str] = ("left", "right", "on it")) -> tuple[str, ...]:
    """Warnings for a branch or an order defect, with the numbers (evaluates the flag steps); ``sides_words``
    says a side +1, −1, 0 as ``what`` measures it (a point left or right of a line; a pin ahead or behind)."""
    v = sc.evaluate(list(keys.values()))
    out = []
    sides = [v[keys[f"side{i}"]] for i in range(1, len(labels) + 1)]
    if not v[keys["branch_ok"]]:
        names = dict(zip((1, -1, 0), sides_words))
        where = ", ".join(f"{lab}: {names[s]}" for lab, s in zip(labels, sides))
        out.append(f"branch defect: the designed positions lie on different assembly branches ({what}: {where}); "
                   "they cannot all be reached without taking the linkage apart")
    if not v[keys["order_ok"]]:
        out.append(f"order defect: the input's motion from position 1 through 2 to 3 passes a dead point "
                   f"(γ = 0 at {v[keys['dead_at']]}); the positions are not reached in the given order")
    return tuple(out)


def dead_text(A: Point, pins: tuple) -> str:
    """The crank angles of the dead points, for a warning."""
    return ", ".join(f"φ = {math.degrees(polar_angle(A, X)):.4g}°" for X in pins[0]) or "none"


def add_turned(sc: Scene, D: Ref, X: Ref, deg: float, name: str, caption: tuple[str, str]) -> Ref:
    """Turn the point X (labelled ``name``) about D through ``deg``: the radius DX, the arc and the turned
    point X′ (key ``<name>p``) with its radius, in light construction lines."""
    drawing = sc.drawing                     # the radii and the arc only a drawing needs
    if drawing:
        sc.add(f"D{name}", segment, D, X, style="construction", caption=caption)
        sc.add(f"arc{name}", turn_arc, D, X, deg, style="construction")
    Xp = sc.add(f"{name}p", turn, X, D, deg, style="point", label=f"{name}′",
                caption=(f"{name} comes to {name}′", f"{name} 转到 {name}′"))
    if drawing:
        sc.add(f"D{name}p", segment, D, Xp, style="construction")
    return Xp


def add_circumcentre(sc: Scene, key: str, P: Sequence[Ref], names: Sequence[str], caption: tuple[str, str],
                     centre: Ref | None = None) -> Ref:
    """The centre of the circle through P1, P2, P3 by the textbook's two perpendicular bisectors (chords
    P1P2 and P2P3, each bisector with its right-angle mark); the result step is ``key``: the bisectors' meet,
    or with ``centre`` (a step holding the same point found more exactly) that point."""
    bis = []
    drawing = sc.drawing                     # the chords and right-angle marks only a drawing needs
    for k, (p, q, n) in enumerate(((P[0], P[1], names[0] + names[1]), (P[1], P[2], names[1] + names[2])), 1):
        if drawing:
            sc.add(f"chord{k}", segment, p, q, style="construction", caption=(f"Join {n}", f"连接 {n}"))
        bis.append(sc.add(f"bis{k}", perpendicular_bisector, p, q, style="construction",
                          caption=(f"Draw the perpendicular bisector of {n}", f"作 {n} 的中垂线")))
        if drawing:
            sc.add(f"bis{k}_mark", bisector_mark, p, q, role=Role.ANNOTATION, style="right-angle")
    if centre is None:
        return sc.add(key, meet_lines, bis[0], bis[1], role=Role.RESULT, style="joint", label=key, caption=caption)
    return sc.add(key, _same, centre, role=Role.RESULT, style="joint", label=key, caption=caption)


def _same(x: Any) -> Any:
    """The value itself (a result step that shows a point computed by an earlier step)."""
    return x


def add_inversion(sc: Scene, D: Ref, X: Sequence[Ref], K1: Ref, psi: Sequence[float], letters: tuple[str, str, str],
                  words: tuple[tuple[str, str], ...]) -> tuple[list[Ref], list[Ref]]:
    """The inversion about D shared by both recipes: the points X2, X3 (letter ``x``) turned through ψ1 − ψi
    onto the rocker's position 1 (marked line D``k``1), the hinge ``h``1 as the centre of X1X2′X3′, the rod
    ``x``1``h``1 and the arm D``h``1 measured (step keys of ``words[1][0]``, ``words[2][0]``), the angle
    ``beta`` from the marked line, and ``h``2, ``h``3 carried by the rocker. Returns (hinges, inverted points)."""
    x, k, h = letters
    (what_en, what_zh), (rod, rod_zh), (arm, arm_zh) = words
    P = [X[0]]
    for i in (2, 3):
        rot = psi[0] - psi[i - 1]
        P.append(add_turned(sc, D, X[i - 1], rot, f"{x}{i}",
                            (f"Hold the rocker at D{k}1 and turn △D{k}{i}{x}{i} about D through ψ1 − ψ{i} = {rot:g}°",
                             f"刚化反转:将 △D{k}{i}{x}{i} 绕 D 转过 ψ1 − ψ{i} = {rot:g}°,使 D{k}{i} 与 D{k}1 重合")))
    u = sc.add(f"{h}1_from_D", hinge_from, D, tuple(X), tuple(P), visible=False)
    H1 = add_circumcentre(sc, f"{h}1", P, (f"{x}1", f"{x}2′", f"{x}3′"),
                          (f"The bisectors meet at {h}1, {what_en} (centre of the circle {x}1{x}2′{x}3′)",
                           f"两中垂线交于 {h}1,即{what_zh}(△{x}1{x}2′{x}3′ 外接圆圆心)"),
                          centre=sc.add(f"{h}1_at", from_D, D, u, visible=False))
    r = sc.add(rod, length, X[0], H1, role=Role.MEASUREMENT, unit="mm",
               caption=(f"Measure {rod} = {x}1{h}1", f"量得{rod_zh} {rod} = {x}1{h}1"))
    if sc.drawing:
        sc.add("k_inv", circle, H1, r, style="construction")
    sc.add(arm, abs, u, role=Role.MEASUREMENT, unit="mm", caption=(f"Measure {arm} = D{h}1", f"量得{arm_zh} {arm} = D{h}1"))
    sc.add("beta", ccw_deg_of, D, K1, u, role=Role.MEASUREMENT, unit="deg", visible=False)
    sc.add(f"{h}1_xy", as_xy, H1, visible=False)
    H = [H1] + [sc.add(f"{h}{i}", turn, H1, D, psi[i - 1] - psi[0], role=Role.RESULT, style="joint", label=f"{h}{i}",
                       caption=(f"The rocker carries {h}1 to {h}{i} (through ψ{i} − ψ1)", f"摇杆带 {h}1 转到 {h}{i}"))
                for i in (2, 3)]
    return H, P


# ----------------------------------------------------------------------------------------- construction
def construct(g: Mapping[str, Any]) -> Construction:
    """Build the inversion construction of the function generator."""
    AD, AB, phi, psi = g["AD"], g["AB"], g["phi"], g["psi"]
    sc = Scene("Four-bar function generator: inversion about D")
    A = add_pivot(sc, "A", Point(0.0, 0.0), ("Fixed pivot A at the origin", "取固定铰链 A 为原点"))
    D = add_pivot(sc, "D", (AD, 0.0), (f"Fixed pivot D on the frame line, AD = {AD:g}",
                                              f"在机架线上取 D,使 AD = {AD:g}"))
    drawing = sc.drawing                     # the given bars, the linkage's positions and the γ ghost only a drawing needs
    if drawing:
        sc.add("AD", segment, A, D, role=Role.GIVEN, style="frame", caption=("Draw the frame AD", "作机架 AD"))
    B = []
    for i, f in enumerate(phi, 1):
        B.append(sc.add(f"B{i}", polar_point, A, AB, f, role=Role.GIVEN, style="joint", label=f"B{i}",
                        caption=(f"Crank position AB{i} at φ{i} = {f:g}° from AD", f"作曲柄位置 AB{i},φ{i} = {f:g}°")))
        if drawing:
            sc.add(f"AB{i}_given", segment, A, B[-1], role=Role.GIVEN, style="given")
    rE = 0.45 * max(AD, AB)
    E = []
    for i, p in enumerate(psi, 1):
        E.append(sc.add(f"E{i}", polar_point, D, rE, p, role=Role.GIVEN, style="point", label=f"E{i}",
                        caption=(f"Rocker line DE{i} at ψ{i} = {p:g}°", f"作摇杆标线 DE{i},ψ{i} = {p:g}°")))
        if drawing:
            sc.add(f"DE{i}", segment, D, E[-1], role=Role.GIVEN, style="given")
    C, P = add_inversion(sc, D, B, E[0], psi, ("B", "E", "C"),
                         (("the hinge on the rocker", "连杆与摇杆的铰链"), ("BC", "连杆"), ("CD", "摇杆")))
    for i in range(1, 4) if drawing else ():
        style = ("link", "link-2", "link-3")[i - 1]
        sc.add(f"AB{i}", segment, A, B[i - 1], role=Role.RESULT, style=style,
               caption=(f"The designed linkage in position {i}: AB{i}C{i}D", f"所设计机构的第 {i} 位置 AB{i}C{i}D"))
        sc.add(f"B{i}C{i}", segment, B[i - 1], C[i - 1], role=Role.RESULT, style=style)
        sc.add(f"C{i}D", segment, C[i - 1], D, role=Role.RESULT, style=style)
    BC, CD = Ref("BC"), Ref("CD")
    sides = [sc.add(f"side{i}", side_of, B[i - 1], C[i - 1], D, visible=False) for i in range(1, 4)]
    sc.add("branch_ok", same_branch, *sides, role=Role.MEASUREMENT, visible=False)
    dead = sc.add("dead", dead_pins, A, AB, D, BC, CD, visible=False)
    sc.add("crank", second, dead, role=Role.MEASUREMENT, visible=False)
    sc.add("grashof", grashof_of, AB, BC, CD, AD, visible=False)
    sc.add("order_ok", order_free, A, B[0], B[1], B[2], dead, role=Role.MEASUREMENT, visible=False)
    sc.add("dead_at", dead_text, A, dead, visible=False)
    worst = sc.add("worst", worst_transmission, A, D, AB, BC, CD, B[0], B[1], B[2], sides[0], dead, C[0],
                   Ref("C1_from_D"), visible=False)
    gm = sc.add("gamma_min", first, worst, role=Role.MEASUREMENT, unit="deg",
                caption=("γmin: crank along the frame line (and at the ends of the motion unless AB is a crank)",
                         "最小传动角:曲柄与机架共线位置(非曲柄时另比较运动两端位置)"))
    if drawing:
        Bw = sc.add("Bw", second, worst, visible=False)
        Cw = sc.add("Cw", third, worst, visible=False)
        sc.add("w_AB", segment, A, Bw, style="ghost")
        sc.add("w_BC", segment, Bw, Cw, style="ghost")
        sc.add("w_CD", segment, Cw, D, style="ghost")
        sc.add("mark_gamma", transmission_mark, Cw, Bw, D, "γmin", gm, role=Role.ANNOTATION, style="angle")
    sc.add("sens", fg_sensitivity, A, D, tuple(B), tuple(P), C[0], tuple(phi), tuple(psi), visible=False)
    sc.add("sens_C1", first, Ref("sens"), unit="mm", visible=False)
    sc.add("sens_C1_mm", second, Ref("sens"), unit="mm", visible=False)
    answers = {q.name: q.name for q in ANSWERS}
    answers["C1"] = "C1_xy"
    points = {"A": "A", "D": "D", "B1": "B1", "B2": "B2", "B3": "B3", "B2'": "B2p", "B3'": "B3p",
              "C1": "C1", "C2": "C2", "C3": "C3", "E1": "E1"}
    warns = defect_warnings(sc, {"side1": "side1", "side2": "side2", "side3": "side3", "branch_ok": "branch_ok",
                                 "order_ok": "order_ok", "dead_at": "dead_at"},
                            ("position 1", "position 2", "position 3"), "side of C from B→D")
    return Construction(sc, answers, points, warnings=warns)


def grashof_of(a: float, b: float, c: float, d: float) -> bool:
    """Shortest + longest ≤ sum of the other two (within the tolerance)."""
    ls = sorted((a, b, c, d))
    return ls[0] + ls[3] <= ls[1] + ls[2] + REL_TOL * ls[3]


# ----------------------------------------------------------------------------------------- twin, back-check
def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """Freudenstein's equation as a linear system (:func:`geomcon.analytic.function_generation.function_generation`)."""
    return [function_generation(g["AD"], g["AB"], g["phi"], g["psi"])]


def near(value: float, target: float) -> float:
    """An angle taken to the turn nearest ``target`` (degrees)."""
    return target + ((value - target + 180.0) % 360.0 - 180.0)


def back_check(g: Mapping[str, Any], ans: Mapping[str, Any]) -> list[tuple[str, float, float, str]]:
    """Drive the designed linkage to each φi on the branch of position 1 and read the marked line's angle
    (the rocker's direction minus β); a position designed on the other branch is driven on its own branch
    and reported as ``psi[i].own_branch`` (the branch defect is in ``branch_ok`` and the warnings). A position
    the linkage cannot be assembled at reads the nearest dead point (``assemble(..., nearest=True)``): a finite
    angle that misses by what the linkage misses — the rebuild at perturbed answers (the solver's condition of
    a back-substitution row) leaves the assembly range at AD = 1e9, where BC moved by 1e-6 of itself is 1000 mm."""
    A, D = (0.0, 0.0), (g["AD"], 0.0)
    a, b, c, beta = g["AB"], ans["BC"], ans["CD"], ans["beta"]
    sides = []
    for f, p in zip(g["phi"], g["psi"]):
        B = crank_point(A, a, f)
        t = math.radians(p + beta)
        sides.append(branch_of(B, (D[0] + c * math.cos(t), D[1] + c * math.sin(t)), D))
    rows = []
    for i, (f, p) in enumerate(zip(g["phi"], g["psi"])):
        side = sides[0] if sides[i] == sides[0] else sides[i]
        BCpos = assemble(A, D, a, b, c, f, side, nearest=True)
        if BCpos is None:
            raise NotAMechanism(f"the designed crank pin falls on D at φ = {f:g}°: the rocker's angle is undefined")
        name = f"psi[{i}]" if side == sides[0] else f"psi[{i}].own_branch"
        got = near(angle_of(D, BCpos[1]) - beta, p)
        rows.append((name, got, p, "deg"))
    return rows


RECIPE = Recipe(
    name="four_bar.function_generation",
    title="Four-bar function generator: three crank angles and rocker angles, by inversion about D",
    givens=GIVENS,
    answers=ANSWERS,
    points=("A", "D", "B1", "B2", "B3", "B2'", "B3'", "C1", "C2", "C3", "E1"),
    construct=construct,
    analytic=analytic,
    validate=_validate,
    back_check=back_check,
)
