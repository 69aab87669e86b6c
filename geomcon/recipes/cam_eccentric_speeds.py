"""``cam.eccentric`` with ω given: the follower's acceleration and the maxima of its speed and acceleration, by
replaying the construction.

The follower's speed at a position is the construction's own (:func:`.cam_eccentric.velocity`: the instant
centre P where the normal AB meets the line through O perpendicular to the guide, v = ω·OP; for an arm, P on
the line of centres OQ, ω2 = ω·OP/QP). Turning the disc's centre A about O by a cam angle u and building B
and P again gives v(u); the acceleration is ω·dv/du by central differences combined by Richardson's rule
(:func:`geomcon.numeric.derivative`, steps 1e-2, 5e-3, 2.5e-3 rad), and the maxima over the turn are searched
on the replayed functions (720 samples, peaks refined by Brent's method). The twin differentiates the exact
motion by hand (:mod:`geomcon.cam.eccentric_speeds`).
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from ..cam.profile import maximise
from ..errors import GeomconError
from ..geometry import Ahead, LeftOf, Line, Point, RightOf, circle, circle_circle, line_circle, line_line, line_through, rotate
from ..numeric import derivative

UP = Point(0.0, 1.0)
O = Point(0.0, 0.0)
H = 1e-2
"""The largest step (rad) of the central differences."""


def _guide_speed(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float
                 ) -> Callable[[float], float]:
    """v(u) of a translating follower with the disc turned by u (rad) in the sense of rotation from A."""
    from .cam_eccentric import velocity

    def v(u: float) -> float:
        Au = rotate(A, O, sense * u)
        if flat:                                   # the contact: the disc's radius parallel to the guide
            B = Ahead(Au, Au + UP).choose(line_circle(Line(Au, UP), circle(Au, R)))
        else:
            B = Ahead(D, D + UP).choose(line_circle(Line(D, UP), circle(Au, Rp)))
        return velocity(Au, B, sense, omega, -1.0, 0.0)
    return v


def _arm_speed(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float
               ) -> Callable[[float], float]:
    """ω2(u) of the arm with the disc turned by u (rad): P where the normal AB meets OQ, ω2 = ω·OP/QP, > 0
    swinging out (B turning away from the line QO)."""
    side = RightOf if left else LeftOf
    axis = line_through(O, Q)

    def w(u: float) -> float:
        Au = rotate(A, O, sense * u)
        B = side(Q, Au).choose(circle_circle(circle(Q, L), circle(Au, Rp)))
        out = 1.0 if B.x > 0 else -1.0
        try:
            P = line_line(line_through(Au, B), axis)
        except GeomconError:
            P = ()
        if not P:                                   # the normal parallel to OQ: P at infinity, OP/QP = 1
            return out * sense * omega
        p, a = P[0].y, Q.y
        return out * sense * omega * p / (p - a)
    return w


def _accel(f: Callable[[float], float], omega: float) -> Callable[[float], float]:
    return lambda u: omega * derivative(f, u, H)


def _peak(f: Callable[[float], float]) -> float:
    g1 = lambda u: abs(f(u))                       # noqa: E731
    return maximise(np.vectorize(g1, otypes=[float]), [(0.0, 2.0 * math.pi)], dense=720, g1=g1).value


def guide_accel(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float) -> float:
    """a at the drawn position (mm/s²)."""
    return _accel(_guide_speed(A, D, Rp, flat, R, sense, omega), omega)(0.0)


def guide_v_max(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float) -> float:
    """Largest |v| over the turn (mm/s)."""
    return _peak(_guide_speed(A, D, Rp, flat, R, sense, omega))


def guide_a_max(A: Point, D: Point, Rp: float, flat: bool, R: float, sense: float, omega: float) -> float:
    """Largest |a| over the turn (mm/s²)."""
    return _peak(_accel(_guide_speed(A, D, Rp, flat, R, sense, omega), omega))


def arm_omega2(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """ω2 at the drawn position (rad/s)."""
    return _arm_speed(A, Q, L, Rp, left, sense, omega)(0.0)


def arm_epsilon2(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """ε2 at the drawn position (rad/s²)."""
    return _accel(_arm_speed(A, Q, L, Rp, left, sense, omega), omega)(0.0)


def arm_omega2_max(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """Largest |ω2| over the turn (rad/s)."""
    return _peak(_arm_speed(A, Q, L, Rp, left, sense, omega))


def arm_epsilon2_max(A: Point, Q: Point, L: float, Rp: float, left: bool, sense: float, omega: float) -> float:
    """Largest |ε2| over the turn (rad/s²)."""
    return _peak(_accel(_arm_speed(A, Q, L, Rp, left, sense, omega), omega))
