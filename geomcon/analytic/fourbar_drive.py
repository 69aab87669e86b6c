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
"""
from __future__ import annotations

import math

XY = tuple[float, float]


def _circle_circle_side(P: XY, r: float, Q: XY, s: float, side: int) -> XY | None:
    """The meeting point of circle(P, r) and circle(Q, s) on ``side`` of the directed line P→Q
    (+1 left, −1 right); None when they do not meet (a tangency counts as meeting)."""
    dx, dy = Q[0] - P[0], Q[1] - P[1]
    d = math.hypot(dx, dy)
    if d == 0.0 or d > r + s or d < abs(r - s):
        return None
    x = (d * d + r * r - s * s) / (2.0 * d)                 # along P→Q
    h = math.sqrt(max(0.0, (r + x) * (r - x)))              # across, no cancellation in r² − x²
    ux, uy = dx / d, dy / d
    return (P[0] + x * ux - side * h * uy, P[1] + x * uy + side * h * ux)


def crank_point(A: XY, AB: float, phi: float) -> XY:
    """B at crank angle ``phi`` (deg) about A."""
    t = math.radians(phi)
    return (A[0] + AB * math.cos(t), A[1] + AB * math.sin(t))


def assemble(A: XY, D: XY, AB: float, BC: float, CD: float, phi: float, branch: int) -> tuple[XY, XY] | None:
    """(B, C) of the four-bar ABCD at crank angle ``phi`` on ``branch`` (+1: C left of B→D), or None when
    the linkage cannot be assembled there (BD outside [|BC − CD|, BC + CD])."""
    B = crank_point(A, AB, phi)
    C = _circle_circle_side(D, CD, B, BC, -branch)          # left of B→D = right of D→B
    return None if C is None else (B, C)


def branch_of(B: XY, C: XY, D: XY) -> int:
    """+1 when C lies left of the directed line B→D, −1 right, 0 on it (a dead point)."""
    cross = (D[0] - B[0]) * (C[1] - B[1]) - (D[1] - B[1]) * (C[0] - B[0])
    return (cross > 0) - (cross < 0)


def angle_of(P: XY, Q: XY) -> float:
    """Direction of P→Q in degrees, in (−180°, 180°]."""
    return math.degrees(math.atan2(Q[1] - P[1], Q[0] - P[0]))
