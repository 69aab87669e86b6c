"""``cam.eccentric`` with ω given: the follower's acceleration and the maxima of its speed and acceleration, by
the velocity, acceleration and jerk polygons of the equivalent linkage (高副低代).

The follower's speed at the drawn position is the construction's own (:func:`.cam_eccentric.velocity`: the
instant centre P where the normal AB meets the line through O perpendicular to the guide, v = ω·OP; for an
arm, P on the line of centres OQ, ω2 = ω·OP/QP). A disc cam's contact normal always passes through the disc's
centre A at the fixed distance Rp = R + rr from the roller centre B, so the cam and follower move as the
linkage O–A–B: a crank OA (turning at ω) with a coupler AB = Rp, B sliding on the guide (a crank-slider), or
swinging on the arm QB (a four-bar); a flat face rides on A's height (a Scotch yoke). The relative-motion
equations of the coupler, v_B = v_A + ω3·J(B − A), differentiated once and twice more (J the quarter turn,
ω constant: a_A = −ω²·A, j_A = −ω²·v_A),

    a_B = a_A − ω3²·(B − A) + α3·J(B − A),
    j_B = j_A − 3·ω3·α3·(B − A) + (α̇3 − ω3³)·J(B − A),

and the same for the arm's side (B − Q turning at ω2, α2, α̇2), are two linear equations each: the
polygons, solved exactly. The maxima over the turn: |v| at a root of a, |a| at a root of the jerk (a sign
change on a grid of :data:`GRID` cells of the disc's turn, in one array pass, refined by Brent's method on
floats, :func:`geomcon.numeric.brent_root`). The twin differentiates the exact motion by hand
(:mod:`geomcon.cam.eccentric_speeds`): a different route to the same numbers.

Examples
--------
>>> from geomcon.geometry import Point
>>> A = Point(-10.0, 0.0)                      # a flat face on a disc 10 off centre: y = R + 10·sin θ
>>> round(guide_v_max(A, Point(0.0, 0.0), 40.0, True, 40.0, 1.0, 2.0), 12)
20.0
>>> round(guide_a_max(A, Point(0.0, 0.0), 40.0, True, 40.0, 1.0, 2.0), 12)
40.0
"""
from __future__ import annotations

import math
from typing import Any, Callable

import numpy as np

from ..errors import GeomconError
from ..geometry import LeftOf, Point, RightOf, circle, circle_circle, line_line, line_through
from ..numeric import brent_root

GRID = 720
"""Cells of the turn on which a sign change of the next derivative is looked for."""
XTOL = 1e-13
"""The roots' tolerance (rad): a maximum's value is then exact to ~XTOL² relative, far below what prints."""

Triple = tuple[Any, Any, Any]


def guide_kinematics(ax: Any, ay: Any, e: float, Rp: float, flat: bool, sense: float, omega: float,
                     sqrt: Callable = math.sqrt) -> Triple:
    """(v, a, j) of a translating follower (mm/s, mm/s², mm/s³; > 0 upwards) with the disc's centre at
    (ax, ay) turning at ``omega`` in the ``sense`` (+1 ccw): floats, or arrays with ``sqrt = np.sqrt``.

    >>> v, a, j = guide_kinematics(0.0, -10.0, 0.0, 40.0, False, 1.0, 1.0)    # A below O: B lowest, at rest
    >>> v, a, j                                    # a crank-slider's inner dead centre: ω²·r·(1 − r/l)
    (0.0, 7.5, 0.0)
    """
    w = sense * omega
    w2 = omega * omega
    vax, vay = -w * ay, w * ax                     # v_A = ω × OA
    aax, aay = -w2 * ax, -w2 * ay                  # a_A = −ω²·OA
    jax, jay = -w2 * vax, -w2 * vay
    if flat:                                       # the face rides on A's height: a Scotch yoke
        return vay, aay, jay
    rx = e - ax                                    # r = B − A, B = (e, ·) the upper meeting point
    ry = sqrt((Rp - rx) * (Rp + rx))
    w3 = vax / ry                                  # x: 0 = v_Ax − ω3·ry
    al = (aax - w3 * w3 * rx) / ry                 # x: 0 = a_Ax − ω3²·rx − α3·ry
    k = (jax - 3.0 * w3 * al * rx) / ry            # x: 0 = j_Ax − 3ω3α3·rx − (α̇3 − ω3³)·ry
    return vay + w3 * rx, aay - w3 * w3 * ry + al * rx, jay - 3.0 * w3 * al * ry + k * rx


def arm_kinematics(ax: Any, ay: Any, qa: float, L: float, Rp: float, left: bool, sense: float, omega: float,
                   sqrt: Callable = math.sqrt) -> tuple[Any, Any, Any, Any]:
    """(ω2, ε2, ε̇2, x of B) of the arm QB (Q = (0, qa)) with the disc's centre at (ax, ay): the four-bar
    O–A–B–Q's polygons; B where the arm's circle (Q, L) meets the pitch circle (A, Rp), right of Q→A for an
    arm on the left. The angular rates are those of the ray Q→B, counter-clockwise positive (the caller signs
    them by the side of B: swinging out is positive).

    >>> w2, e2, j2, bx = arm_kinematics(0.0, -10.0, 100.0, 80.0, 50.0, True, 1.0, 1.0)   # A straight below Q
    >>> round(bx, 9) == round(-(80.0 ** 2 - (16000 / 220) ** 2) ** 0.5, 9)
    True
    >>> round(w2 * 110 / 10, 15)                   # the normal AB meets OQ at A: ω2 = ω·OP/QP = 10/110
    1.0
    """
    w = sense * omega
    w2 = omega * omega
    dx, dy = ax, ay - qa                           # A − Q
    dd = dx * dx + dy * dy
    d = sqrt(dd)
    along = (dd + (L - Rp) * (L + Rp)) / (2.0 * d)
    hgt = sqrt((L - along) * (L + along))
    ux, uy = dx / d, dy / d
    if left:                                       # right of Q→A: Q + along·u − hgt·J·u
        qx, qy = along * ux + hgt * uy, along * uy - hgt * ux
    else:
        qx, qy = along * ux - hgt * uy, along * uy + hgt * ux
    rx, ry = qx - dx, qy - dy                      # r = B − A
    det = qy * rx - ry * qx

    def solve(px, py):                             # ω2·J·q − ω3·J·r = p  →  (ω2, ω3)
        return (-px * rx - ry * py) / det, (-qy * py - qx * px) / det

    vax, vay = -w * ay, w * ax
    o2, o3 = solve(vax, vay)
    a2, a3 = solve(-w2 * ax - o3 * o3 * rx + o2 * o2 * qx, -w2 * ay - o3 * o3 * ry + o2 * o2 * qy)
    k2, _ = solve(-w2 * vax - 3.0 * o3 * a3 * rx + 3.0 * o2 * a2 * qx,
                  -w2 * vay - 3.0 * o3 * a3 * ry + 3.0 * o2 * a2 * qy)
    return o2, a2, k2 + o2 * o2 * o2, qx


def _turned(A: Point, sense: float, u):
    """A turned about O by the cam angle u (in the sense of rotation): floats or arrays."""
    if isinstance(u, np.ndarray):
        c, s = np.cos(sense * u), np.sin(sense * u)
    else:
        c, s = math.cos(sense * u), math.sin(sense * u)
    return A.x * c - A.y * s, A.x * s + A.y * c


def _guide(A: Point, D: Point, Rp: float, flat: bool, sense: float, omega: float) -> Callable[[Any], Triple]:
    def kin(u):
        ax, ay = _turned(A, sense, u)
        return guide_kinematics(ax, ay, D.x, Rp, flat, sense, omega, np.sqrt if isinstance(u, np.ndarray) else math.sqrt)
    return kin


def _arm(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> Callable[[Any], Triple]:
    def kin(u):
        ax, ay = _turned(A, sense, u)
        arr = isinstance(u, np.ndarray)
        o2, e2, j2, bx = arm_kinematics(ax, ay, Q.y, L, Rp, left, sense, omega, np.sqrt if arr else math.sqrt)
        out = np.where(bx > 0, 1.0, -1.0) if arr else (1.0 if bx > 0 else -1.0)   # swinging out: > 0
        return out * o2, out * e2, out * j2
    return kin


_GRID_U = np.linspace(0.0, 2.0 * math.pi, GRID + 1)
_GRID_U.flags.writeable = False
_LAST: list = [None, None]
"""The last grid evaluation (its key, its values): a speed's maximum and its acceleration's maximum are two
steps of one solve on the same linkage, whose grid is then evaluated once."""


def largest(kin: Callable[[Any], Triple], k: int, key: Any = None) -> float:
    """max |kin(u)[k]| over the turn (k = 0: the speed, 1: the acceleration): the largest value at the roots
    of the next derivative, kin(u)[k + 1]: every sign change on the grid of :data:`GRID` cells (one array
    call, kept for the next call with the same ``key``) refined by Brent's method on floats; a grid sample
    where it is 0 counts as it stands.

    >>> kin = lambda u: (np.sin(u), np.cos(u), -np.sin(u)) if isinstance(u, np.ndarray) else (math.sin(u), math.cos(u), -math.sin(u))
    >>> largest(kin, 0), round(largest(kin, 1), 15)
    (1.0, 1.0)
    """
    u = _GRID_U
    if key is not None and _LAST[0] == key:
        vals = _LAST[1]
    else:
        vals = kin(u)
        _LAST[0], _LAST[1] = key, vals
    f, slope = np.asarray(vals[k], dtype=float), np.asarray(vals[k + 1], dtype=float)
    best = float(np.max(np.abs(f[slope == 0.0]), initial=0.0))
    pos = slope > 0.0
    cells = np.nonzero((pos[:-1] != pos[1:]) & (slope[:-1] != 0.0) & (slope[1:] != 0.0))[0]

    def g(x: float) -> float:
        return kin(x)[k + 1]

    for i, lo, hi, flo, fhi in zip(cells.tolist(), u[cells].tolist(), u[cells + 1].tolist(),
                                   slope[cells].tolist(), slope[cells + 1].tolist()):
        x = brent_root(g, lo, hi, flo, fhi, xtol=XTOL)
        best = max(best, abs(kin(x)[k]))
    if not cells.size and best == 0.0:            # no root on the grid (a constant): the largest sample
        best = float(np.max(np.abs(f)))
    return best


def guide_accel(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float) -> float:
    """a at the drawn position (mm/s²): the acceleration polygon (an exact 0 unsigned, as it prints)."""
    return _guide(A, D, Rp, flat, sense, omega)(0.0)[1] + 0.0


def guide_v_max(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float) -> float:
    """Largest |v| over the turn (mm/s)."""
    return largest(_guide(A, D, Rp, flat, sense, omega), 0, ("guide", A, D, Rp, flat, sense, omega))


def guide_a_max(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float) -> float:
    """Largest |a| over the turn (mm/s²)."""
    return largest(_guide(A, D, Rp, flat, sense, omega), 1, ("guide", A, D, Rp, flat, sense, omega))


def arm_omega2(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """ω2 at the drawn position (rad/s): P where the normal AB meets OQ, ω2 = ω·OP/QP, > 0 swinging out (B
    turning away from the line QO)."""
    B = (RightOf if left else LeftOf)(Q, A).choose(circle_circle(circle(Q, L), circle(A, Rp)))
    out = 1.0 if B.x > 0 else -1.0
    try:
        P = line_line(line_through(A, B), line_through(Point(0.0, 0.0), Q))
    except GeomconError:
        P = ()
    if not P:                                       # the normal parallel to OQ: P at infinity, OP/QP = 1
        return out * sense * omega
    p, a = P[0].y, Q.y
    return out * sense * omega * p / (p - a)


def arm_epsilon2(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """ε2 at the drawn position (rad/s²): the acceleration polygon (an exact 0 unsigned, as it prints)."""
    return _arm(A, Q, L, Rp, left, sense, omega)(0.0)[1] + 0.0


def arm_omega2_max(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """Largest |ω2| over the turn (rad/s)."""
    return largest(_arm(A, Q, L, Rp, left, sense, omega), 0, ("arm", A, Q, L, Rp, left, sense, omega))


def arm_epsilon2_max(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """Largest |ε2| over the turn (rad/s²)."""
    return largest(_arm(A, Q, L, Rp, left, sense, omega), 1, ("arm", A, Q, L, Rp, left, sense, omega))

