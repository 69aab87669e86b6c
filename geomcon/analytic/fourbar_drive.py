"""Driving a designed four-bar: assemble it at a given input angle on a named branch (plain floats).

The back-substitution of the synthesis recipes uses these: the designed linkage ABCD is assembled at each
prescribed crank angle and must reach the prescribed positions. Points are ``(x, y)`` tuples in mm, angles
in degrees counter-clockwise from +x.

The **assembly branch** is the side of the directed line B→D on which C lies: ``+1`` left, ``-1`` right.
A linkage that moves without passing a dead point keeps its branch; positions reached on different
branches cannot be reached by one continuous motion (the branch or circuit defect).

Examples
--------
>>> B, C = assemble((0.0, 0.0), (90.0, 0.0), 50.0, 70.0, 80.0, 90.0, +1)
>>> [round(v, 9) for v in B + C]
[0.0, 50.0, 64.995527349, 75.991949228]
>>> branch_of(B, C, (90.0, 0.0))
1
>>> assemble((0.0, 0.0), (90.0, 0.0), 50.0, 10.0, 10.0, 90.0, +1) is None     # BD = 103 > BC + CD
True

The **movable range** of the input: a position φ can be assembled when BD(φ) lies in [|BC − CD|, BC + CD];
at either end of that interval BC and CD are collinear (a dead point of the input: the transmission angle
is 0 and the branch may change). A motion of the input from φ1 through φ2 to φ3 passes no dead point when
BD stays strictly inside the interval over the whole arc (:func:`arc_through`, :func:`bd_extremes`,
:func:`dead_point_free`).

>>> arc_through(10.0, 60.0, 100.0), arc_through(10.0, -30.0, -80.0), arc_through(10.0, 200.0, 100.0)
((10.0, 90.0), (10.0, -90.0), (10.0, -270.0))
>>> [round(v, 9) for v in bd_extremes((0.0, 0.0), (90.0, 0.0), 50.0, 10.0, 90.0)]
[41.674095346, 110.285237448]
>>> dead_point_free(41.1, 100.2, 70.0, 80.0), turns_fully(50.0, 70.0, 80.0, 90.0)
(True, True)
"""
from __future__ import annotations

import math

from ..tolerance import REL_TOL

XY = tuple[float, float]

WARN_CONDITION = 100.0
"""One policy for every three-position synthesis (the recipes and their twins): a centre of three points
(a fixed pivot, or a hinge found by inversion) whose condition R / h_min — circumradius over the smallest
altitude, the mm the centre moves per mm one point is misplaced — is at least 100 is warned."""

REFUSE_CONDITION = 1e7
"""… and at least 1e7 is refused: the centre lies some 1e7 chords away and double precision no longer
delivers it to the 1e-9 the twin check asks for (the points count as collinear)."""


def centre_condition(P1: XY, P2: XY, P3: XY) -> float:
    """R / h_min of the triangle P1P2P3 (∞ for collinear or coincident points), from the side lengths:
    R = abc / (4·area), h_min = 2·area / max side, so R / h_min = abc·max / (8·area²).

    >>> round(centre_condition((0.0, 0.0), (1.0, 1.0), (2.0, 0.0)), 12)
    1.0
    """
    a, b, c = math.dist(P2, P3), math.dist(P3, P1), math.dist(P1, P2)
    area2 = abs((P2[0] - P1[0]) * (P3[1] - P1[1]) - (P2[1] - P1[1]) * (P3[0] - P1[0]))
    return math.inf if area2 == 0.0 else (a * b * c * max(a, b, c)) / (2.0 * area2 * area2)


def _circle_circle_side(P: XY, r: float, Q: XY, s: float, side: int, nearest: bool = False) -> XY | None:
    """The meeting point of circle(P, r) and circle(Q, s) on ``side`` of the directed line P→Q
    (+1 left, −1 right); None when they do not meet (a tangency counts as meeting) — or, with ``nearest``,
    the point of circle(P, r) nearest to circle(Q, s), on the line PQ (None only when P = Q)."""
    dx, dy = Q[0] - P[0], Q[1] - P[1]
    d = math.hypot(dx, dy)
    if d == 0.0 or (not nearest and (d > r + s or d < abs(r - s))):
        return None
    x = (d * d + r * r - s * s) / (2.0 * d)                 # along P→Q
    x = min(r, max(-r, x))                                  # apart or nested: the end of P's circle nearest Q's
    h = math.sqrt(max(0.0, (r + x) * (r - x)))              # across, no cancellation in r² − x²
    ux, uy = dx / d, dy / d
    return (P[0] + x * ux - side * h * uy, P[1] + x * uy + side * h * ux)


def crank_point(A: XY, AB: float, phi: float) -> XY:
    """B at crank angle ``phi`` (deg) about A."""
    t = math.radians(phi)
    return (A[0] + AB * math.cos(t), A[1] + AB * math.sin(t))


def assemble(A: XY, D: XY, AB: float, BC: float, CD: float, phi: float, branch: int,
             nearest: bool = False) -> tuple[XY, XY] | None:
    """(B, C) of the four-bar ABCD at crank angle ``phi`` on ``branch`` (+1: C left of B→D), or None when
    the linkage cannot be assembled there (BD outside [|BC − CD|, BC + CD]).

    With ``nearest`` a position that cannot be assembled gives the dead point nearest to it instead: C on the
    line BD at CD from D, on the side nearest to the circle of radius BC about B (so a back-substitution reads
    a finite angle that misses by what the linkage misses, never NaN); None only when B falls on D.

    >>> B, C = assemble((0.0, 0.0), (90.0, 0.0), 50.0, 10.0, 10.0, 90.0, +1, nearest=True)
    >>> [round(v, 9) for v in C]
    [81.258427239, 4.856429312]
    """
    B = crank_point(A, AB, phi)
    C = _circle_circle_side(D, CD, B, BC, -branch, nearest)   # left of B→D = right of D→B
    return None if C is None else (B, C)


def branch_of(B: XY, C: XY, D: XY) -> int:
    """+1 when C lies left of the directed line B→D, −1 right, 0 on it (a dead point)."""
    cross = (D[0] - B[0]) * (C[1] - B[1]) - (D[1] - B[1]) * (C[0] - B[0])
    return (cross > 0) - (cross < 0)


def angle_of(P: XY, Q: XY) -> float:
    """Direction of P→Q in degrees, in (−180°, 180°]."""
    return math.degrees(math.atan2(Q[1] - P[1], Q[0] - P[0]))


def arc_through(phi1: float, phi2: float, phi3: float) -> tuple[float, float]:
    """The input's motion from ``phi1`` to ``phi3`` passing ``phi2``: ``(start, sweep)`` in degrees, the
    sweep positive counter-clockwise, |sweep| < 360°."""
    s2, s3 = (phi2 - phi1) % 360.0, (phi3 - phi1) % 360.0
    return (phi1, s3) if s2 < s3 else (phi1, s3 - 360.0)


def on_arc(phi: float, start: float, sweep: float) -> bool:
    """True when direction ``phi`` (deg) lies on the arc from ``start`` turning through ``sweep``."""
    t = (phi - start) % 360.0 if sweep >= 0 else (start - phi) % 360.0
    return t <= abs(sweep)


def bd_extremes(A: XY, D: XY, AB: float, start: float, sweep: float) -> tuple[float, float]:
    """Smallest and largest distance BD while the crank AB turns over the arc ``(start, sweep)``.

    BD² = AB² + AD² − 2·AB·AD·cos(φ − φ_D) is smallest at φ = φ_D (B on AD) and largest opposite; over an
    arc the extremes are those two when they lie on it, else at its ends.
    """
    AD = math.hypot(D[0] - A[0], D[1] - A[1])
    phid = angle_of(A, D)

    def bd(phi: float) -> float:
        # |AB − AD|² + 4·AB·AD·sin²((φ − φ_D)/2): no cancellation near φ_D
        s = math.sin(math.radians(phi - phid) / 2.0)
        return math.sqrt((AB - AD) ** 2 + 4.0 * AB * AD * s * s)

    ends = [bd(start), bd(start + sweep)]
    lo = abs(AD - AB) if on_arc(phid, start, sweep) else min(ends)
    hi = AD + AB if on_arc(phid + 180.0, start, sweep) else max(ends)
    return lo, hi


def dead_point_free(bd_min: float, bd_max: float, BC: float, CD: float) -> bool:
    """True when BD in [bd_min, bd_max] stays strictly inside (|BC − CD|, BC + CD): no dead point (BC and CD
    collinear) on the way; touching an end within the tolerance counts as a dead point."""
    t = REL_TOL * max(BC, CD, bd_max)
    return bd_min > abs(BC - CD) + t and bd_max < BC + CD - t


def turns_fully(AB: float, BC: float, CD: float, AD: float) -> bool:
    """True when the crank AB can turn through 360° relative to the frame AD: BD over the whole turn,
    [|AD − AB|, AD + AB], lies within [|BC − CD|, BC + CD] (touching counts: a change-point linkage)."""
    t = REL_TOL * max(AB, BC, CD, AD)
    return AD + AB <= BC + CD + t and abs(AD - AB) >= abs(BC - CD) - t
