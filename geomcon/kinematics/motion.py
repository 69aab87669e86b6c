"""Value objects of a solved linkage: the motion of a point (complex position, velocity, acceleration) and of a
link (angle, angular velocity, angular acceleration), each an array over the crank angles.

Points are complex numbers x + iy (mm), velocities mm/s, accelerations mm/s²; angles in radians,
counter-clockwise positive, ω in rad/s and ε in rad/s².

Examples
--------
>>> import numpy as np
>>> x, y = solve_real_pair(np.array([1j]), np.array([1 + 0j]), np.array([2 + 3j]))
>>> float(x[0]), float(y[0])
(3.0, 2.0)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PointMotion:
    """Position ``p`` (mm), velocity ``v`` (mm/s) and acceleration ``a`` (mm/s²) of a point, complex arrays
    (``v`` and ``a`` None when only positions were asked for)."""

    p: np.ndarray
    v: np.ndarray
    a: np.ndarray


@dataclass(frozen=True)
class LinkMotion:
    """Angle ``theta`` (rad, continuous along the cycle where the link turns fully), ``omega`` (rad/s) and
    ``epsilon`` (rad/s²) of a link, real arrays."""

    theta: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray


@dataclass(frozen=True)
class SlipMotion:
    """A slider's position ``s`` along its guide (mm), measured from the guide's reference point, and its
    relative velocity ``v`` and acceleration ``a`` along the guide."""

    s: np.ndarray
    v: np.ndarray
    a: np.ndarray


def cross(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """The 2-D cross product Im(p̄ q) of complex arrays (x₁y₂ − y₁x₂)."""
    return p.real * q.imag - p.imag * q.real


def solve_real_pair(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real ``x, y`` with ``x·a + y·b = c`` for complex ``a, b, c`` (two real equations, Cramer's rule).

    The determinant Im(ā b) is zero where ``a`` and ``b`` are parallel: the linkage's dead or change point,
    where the velocities are unbounded (the callers report such angles before they get here).
    """
    det = cross(a, b)
    return cross(c, b) / det, cross(a, c) / det
