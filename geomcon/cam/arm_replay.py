"""The eccentric cam's oscillating arm replayed over the cam angle, on floats and on arrays.

``cam.eccentric`` finds the largest pressure angle of an oscillating arm on the construction itself: the pivot
Q0 of the lowest position turned back about O by the cam angle δ (the inversion), the arm's arc (radius L
about it) met with the pitch circle (Rp about the disc's centre A) on the arm's side of the line from the
pivot to A, and α = |90° − ∠A B Q| measured at the roller centre B. The geometry builds points, circles and
a branch rule for every δ; :class:`ArmReplay` does the same arithmetic on plain floats, and on arrays for a
search's samples, by the operations of :func:`~geomcon.geometry.construct.rotate`,
:func:`~geomcon.geometry.intersect.circle_circle`, the rules :class:`~geomcon.geometry.branch.RightOf` /
:class:`~geomcon.geometry.branch.LeftOf` and :func:`~geomcon.geometry.measure.angle_at` in their order,
so with the same bits (``math.hypot``, which rounds differently from numpy's, taken one element at a time).

A cam angle where the geometry would take another path — a tangency, circles that do not meet, a branch rule
that cannot tell the points apart, a zero-length direction, a non-finite point — is replayed by the geometry
itself (``exact``), which returns its value or raises its error, as the construction does.

Examples
--------
>>> import math
>>> from geomcon.geometry import Point, RightOf, circle, circle_circle, rotate
>>> from geomcon.recipes.cam_eccentric import arm_pressure
>>> Q0, A = Point(-57.0, 69.0), Point(0.0, -20.0)
>>> def exact(d):
...     Qd = rotate(Q0, Point(0.0, 0.0), -1.0 * d)
...     B = RightOf(Qd, A).choose(circle_circle(circle(Qd, 70.0), circle(A, 50.0)))
...     return arm_pressure(A, B, Qd)
>>> arm = ArmReplay(Q0.x, Q0.y, 0.0, 0.0, A.x, A.y, 70.0, 50.0, True, 1.0, exact)
>>> arm.alpha1(0.7) == exact(0.7), arm.alpha(np.array([0.1, 0.7, 2.0])).tolist() == [exact(d) for d in (0.1, 0.7, 2.0)]
(True, True)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..geometry.primitives import _SAFE_NORM
from ..tolerance import REL_TOL
from .profile import numpy_is_libm


def _sum_less1(x: float, y: float, z: float) -> float:
    """:func:`~geomcon.geometry.intersect._sum_less`: x + y − z, z taken from the larger of x, y first."""
    big, small = (x, y) if x >= y else (y, x)
    return (big - z) + small


def _sum_less(x, y, z) -> np.ndarray:
    """:func:`_sum_less1` elementwise."""
    big, small = np.where(x >= y, x, y), np.where(x >= y, y, x)
    return (big - z) + small


@dataclass(frozen=True)
class ArmReplay:
    """α(δ) of the replayed inversion (see the module docstring).

    Parameters
    ----------
    q0x, q0y, ox, oy, ax, ay : float
        The pivot's lowest position Q0, the cam centre O and the disc's centre A.
    L, Rp : float
        The arm's length and the pitch circle's radius.
    left : bool
        The arm's side: the roller right of the line Q→A for a left arm, left of it otherwise.
    sense : float
        +1 for a counter-clockwise cam, −1 clockwise (the pivot turns back by −sense·δ).
    exact : callable
        α at one cam angle by the geometry itself (its values and errors where the replay steps aside).
    """

    q0x: float
    q0y: float
    ox: float
    oy: float
    ax: float
    ay: float
    L: float
    Rp: float
    left: bool
    sense: float
    exact: Callable[[float], float]

    def alpha1(self, d: float) -> float:
        """α (deg) at the cam angle ``d`` (radians), on floats."""
        ox, oy, ax, ay, r1, r2 = self.ox, self.oy, self.ax, self.ay, float(self.L), float(self.Rp)
        ang = -self.sense * d                                   # rotate(Q0, O, −sense·δ)
        c, s = math.cos(ang), math.sin(ang)
        vx, vy = self.q0x - ox, self.q0y - oy
        qx, qy = ox + c * vx - s * vy, oy + s * vx + c * vy
        wx, wy = ax - qx, ay - qy                               # circle_circle(circle(Q, L), circle(A, Rp))
        dd = math.hypot(wx, wy)
        eps = REL_TOL * abs(max(dd, r1, r2))
        outer, inner = dd - (r1 + r2), abs(r1 - r2) - dd
        if not (dd > eps and abs(outer) > eps and abs(inner) > eps and outer <= 0.0 and inner <= 0.0
                and _SAFE_NORM <= dd < math.inf and qx - qx == 0.0 and qy - qy == 0.0):
            return self.exact(d)
        ux, uy = wx / dd, wy / dd
        big, small = (dd, r1) if dd >= r1 else (r1, dd)
        a = ((big - r2) * (big + r2) + small * small) / (2.0 * dd)
        h2 = _sum_less1(r1, r2, dd) * _sum_less1(dd, r2, r1) * _sum_less1(dd, r1, r2) * (dd + r1 + r2)
        h = math.sqrt(h2) / (2.0 * dd)
        fx, fy = ux * a, uy * a
        nx, ny = -uy * h, ux * h
        p0x, p0y, p1x, p1y = qx + (fx + nx), qy + (fy + ny), qx + (fx - nx), qy + (fy - ny)
        ex, ey = wx / dd, wy / dd                               # the rule's direction Q→A (unit_xy)
        s0, s1 = ex * (p0y - qy) - ey * (p0x - qx), ex * (p1y - qy) - ey * (p1x - qx)
        if self.left:                                           # RightOf: the score negated
            s0, s1 = -s0, -s1
        scale = max(math.hypot(p0x - p1x, p0y - p1y), 1e-300)
        if abs(s0 - s1) <= REL_TOL * max(scale, abs(s0), abs(s1)) or not (p0x - p0x == 0.0 and p0y - p0y == 0.0
                                                                            and p1x - p1x == 0.0 and p1y - p1y == 0.0):
            return self.exact(d)
        bx, by = (p0x, p0y) if s0 > s1 else (p1x, p1y)
        ux2, uy2, vx2, vy2 = ax - bx, ay - by, qx - bx, qy - by  # angle_at(B, A, Q)
        if (ux2 == 0.0 and uy2 == 0.0) or (vx2 == 0.0 and vy2 == 0.0):
            return self.exact(d)
        t = math.atan2(ux2 * vy2 - uy2 * vx2, ux2 * vx2 + uy2 * vy2)
        t = math.pi if t == -math.pi else t
        return abs(90.0 - math.degrees(abs(t)))

    def alpha(self, d: np.ndarray) -> np.ndarray:
        """α (deg) at the cam angles ``d`` (radians), elementwise by :meth:`alpha1`'s operations; the angles
        where it steps aside go to ``exact`` in their order (the first error is the one the geometry raises
        first)."""
        d = np.asarray(d, dtype=float)
        ox, oy, ax, ay, r1, r2 = self.ox, self.oy, self.ax, self.ay, float(self.L), float(self.Rp)
        ang = -self.sense * d
        c, s = np.cos(ang), np.sin(ang)
        vx, vy = self.q0x - ox, self.q0y - oy
        qx, qy = ox + c * vx - s * vy, oy + s * vx + c * vy
        wx, wy = ax - qx, ay - qy
        hyp = math.hypot
        dd = np.array([hyp(x, y) for x, y in zip(wx.tolist(), wy.tolist())], dtype=float).reshape(d.shape)
        with np.errstate(all="ignore"):
            eps = REL_TOL * np.abs(np.maximum(np.maximum(dd, r1), r2))
            outer, inner = dd - (r1 + r2), abs(r1 - r2) - dd
            ok = (dd > eps) & (np.abs(outer) > eps) & (np.abs(inner) > eps) & (outer <= 0.0) & (inner <= 0.0) \
                & (_SAFE_NORM <= dd) & (dd < math.inf) & (qx - qx == 0.0) & (qy - qy == 0.0)
            ux, uy = wx / dd, wy / dd
            big, small = np.where(dd >= r1, dd, r1), np.where(dd >= r1, r1, dd)
            a = ((big - r2) * (big + r2) + small * small) / (2.0 * dd)
            h2 = _sum_less(r1, r2, dd) * _sum_less(dd, r2, r1) * _sum_less(dd, r1, r2) * (dd + r1 + r2)
            h = np.sqrt(h2) / (2.0 * dd)
            fx, fy = ux * a, uy * a
            nx, ny = -uy * h, ux * h
            p0x, p0y, p1x, p1y = qx + (fx + nx), qy + (fy + ny), qx + (fx - nx), qy + (fy - ny)
            ex, ey = wx / dd, wy / dd
            s0, s1 = ex * (p0y - qy) - ey * (p0x - qx), ex * (p1y - qy) - ey * (p1x - qx)
            if self.left:
                s0, s1 = -s0, -s1
            scale = np.maximum(np.hypot(p0x - p1x, p0y - p1y), 1e-300)
            # the tie test with twice the tolerance (numpy's hypot may differ from math's in the last bit):
            # outside it both decide alike; inside it the geometry decides
            ok &= ~(np.abs(s0 - s1) <= 2.0 * REL_TOL * np.maximum(np.maximum(scale, np.abs(s0)), np.abs(s1)))
            ok &= (p0x - p0x == 0.0) & (p0y - p0y == 0.0) & (p1x - p1x == 0.0) & (p1y - p1y == 0.0)
            first = s0 > s1
            bx, by = np.where(first, p0x, p1x), np.where(first, p0y, p1y)
            ux2, uy2, vx2, vy2 = ax - bx, ay - by, qx - bx, qy - by
            ok &= ~(((ux2 == 0.0) & (uy2 == 0.0)) | ((vx2 == 0.0) & (vy2 == 0.0)))
            y, x = ux2 * vy2 - uy2 * vx2, ux2 * vx2 + uy2 * vy2
            if numpy_is_libm("arctan2"):
                t = np.arctan2(y, x)
            else:
                t = np.array([math.atan2(p, q) for p, q in zip(y.tolist(), x.tolist())], dtype=float).reshape(d.shape)
            t = np.where(t == -math.pi, math.pi, t)
            out = np.abs(90.0 - np.degrees(np.abs(t)))
        if not ok.all():
            flat, okf = out.reshape(-1), ok.reshape(-1)
            for i, x in zip(np.nonzero(~okf)[0].tolist(), d.reshape(-1)[~okf].tolist()):
                flat[i] = self.exact(x)
        return out
