"""The brute-force baseline: turn the crank through N equal steps and look for the extreme positions.

At each of N crank angles φ the linkage is assembled with vectorised numpy (one circle–circle or
line–circle intersection per angle, on the recipe's assembly branch); the extreme positions of the output
link are the arg-max and arg-min over the samples. θ follows from the two crank angles found, ψ (or the
stroke H) from the output values there. Each crank angle found is off by about half a step h = 360°/N
at most, so the error of θ is at most about h (O(1/N)); the output is flat at its extremes, so ψ and H err
by O(1/N²).

The samples start ``PHASE`` = (√5 − 1)/2 ≈ 0.618 of a step past 0, not at 0 itself: a
sweep from 0 samples every multiple of 1° (for N = 360·10^k) exactly, and textbook problems put their
extreme positions at round angles — the guide-bar 145/290 has them at exactly 210° and 330° — so a sweep
from 0 would report accidental exactness instead of the error a sweep makes in general. (θ itself can
still come out exact when it is a multiple of the step, as the guide-bar's θ = 60° is for N divisible by 6.)

All functions take the normalised givens of the recipe (``{"AB": 50.0, ...}``) and return answers keyed
by the recipe's answer names, in degrees and mm.

Examples
--------
>>> r = sweep_guide_bar({"AB": 145.0, "AC": 290.0}, 3600)
>>> abs(r["theta"] - 60.0) <= 360 / 3600, abs(r["psi"] - 60.0) < 1e-3
(True, True)
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping

import numpy as np

Sweep = Callable[..., dict[str, float]]
"""``sweep(given, n, phase=PHASE) -> {answer: value}``."""

PHASE: float = (math.sqrt(5.0) - 1.0) / 2.0
"""Where the first sample lies, as a fraction of a step: the golden fraction, far from every simple ratio."""


def crank_angles(n: int, phase: float = PHASE) -> np.ndarray:
    """The ``n`` crank angles (k + phase)·2π/n, k = 0 … n − 1, in radians.

    Examples
    --------
    >>> crank_angles(4, phase=0.0) / np.pi
    array([0. , 0.5, 1. , 1.5])
    """
    return (np.arange(n) + phase) * (2.0 * math.pi / n)


def circle_circle_side(bx: np.ndarray, by: np.ndarray, r1: float, cx: float, cy: float, r2: float,
                       side: float) -> tuple[np.ndarray, np.ndarray]:
    """Intersect the circles about (bx, by) of radius r1 and about (cx, cy) of radius r2, elementwise.

    Parameters
    ----------
    bx, by : ndarray
        Centres of the first circles (one per crank angle).
    r1 : float
        Their radius.
    cx, cy, r2 : float
        Centre and radius of the fixed second circle.
    side : float
        ``+1`` for the intersection on the left of the directed line b → c, ``-1`` for the right.

    Returns
    -------
    x, y : ndarray
        The chosen intersection points. Where the circles miss by rounding only, the tangent point.

    Examples
    --------
    >>> x, y = circle_circle_side(np.array([0.0]), np.array([0.0]), 5.0, 8.0, 0.0, 5.0, +1)
    >>> float(x[0]), float(y[0])
    (4.0, 3.0)
    """
    dx, dy = cx - bx, cy - by
    d = np.hypot(dx, dy)
    ux, uy = dx / d, dy / d
    a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d)
    h = np.sqrt(np.maximum(r1 * r1 - a * a, 0.0))
    return bx + a * ux - side * h * uy, by + a * uy + side * h * ux


def theta_between(phi_a: float, phi_b: float) -> float:
    """The angle θ (degrees) between two crank positions that are 180° ± θ apart.

    Examples
    --------
    >>> round(theta_between(0.0, math.radians(192.5)), 9), round(theta_between(math.radians(192.5), 0.0), 9)
    (12.5, 12.5)
    """
    delta = (phi_a - phi_b) % (2.0 * math.pi)
    return math.degrees(abs(delta - math.pi))


def _extremes(phi: np.ndarray, out: np.ndarray) -> tuple[float, float, float]:
    """Crank angles at the arg-max and arg-min of the output and the output's range there."""
    i_max, i_min = int(np.argmax(out)), int(np.argmin(out))
    return float(phi[i_max]), float(phi[i_min]), float(out[i_max] - out[i_min])


def sweep_crank_rocker(g: Mapping[str, Any], n: int, phase: float = PHASE) -> dict[str, float]:
    """θ and ψ of a crank-rocker from ``n`` assembled positions.

    A at the origin, D = (AD, 0); C is the intersection of the coupler circle about B with the rocker circle
    about D on the left of B → D when the linkage is drawn above the frame (the right when below): the
    assembly branch of the construction, which a crank-rocker keeps all round the cycle. The rocker angle is
    measured from DA, so it does not wrap while the rocker stays out of the extension of AD beyond D.
    """
    AB, BC, CD, AD = g["AB"], g["BC"], g["CD"], g["AD"]
    side = -1.0 if g.get("branch", "above") == "below" else 1.0
    phi = crank_angles(n, phase)
    bx, by = AB * np.cos(phi), AB * np.sin(phi)
    cx, cy = circle_circle_side(bx, by, BC, AD, 0.0, CD, side)
    rocker = np.arctan2(-cy, AD - cx)  # signed angle from D→A to D→C
    phi_max, phi_min, swing = _extremes(phi, rocker)
    return {"theta": theta_between(phi_max, phi_min), "psi": math.degrees(abs(swing))}


def sweep_crank_slider(g: Mapping[str, Any], n: int, phase: float = PHASE) -> dict[str, float]:
    """θ and the stroke H of an offset crank-slider from ``n`` assembled positions.

    A at the origin, the guide the line y = −e; C is the intersection of the rod circle about B with the
    guide to the right of B (the construction's branch; the rod never turns past vertical when AB + e < BC).
    """
    AB, BC, e = g["AB"], g["BC"], g["e"]
    phi = crank_angles(n, phase)
    bx, by = AB * np.cos(phi), AB * np.sin(phi)
    x = bx + np.sqrt(np.maximum(BC * BC - (by + e) ** 2, 0.0))
    phi_max, phi_min, stroke = _extremes(phi, x)
    return {"theta": theta_between(phi_max, phi_min), "H": abs(stroke)}


def sweep_guide_bar(g: Mapping[str, Any], n: int, phase: float = PHASE) -> dict[str, float]:
    """θ and ψ of an oscillating guide-bar from ``n`` positions of the crank.

    A at the origin, C = (0, −AC); the guide bar is the line C → B, its angle measured from CA (it stays
    within ±90° of CA because AB < AC).
    """
    AB, AC = g["AB"], g["AC"]
    phi = crank_angles(n, phase)
    bx, by = AB * np.cos(phi), AB * np.sin(phi)
    bar = np.arctan2(bx, by + AC)
    phi_max, phi_min, swing = _extremes(phi, bar)
    return {"theta": theta_between(phi_max, phi_min), "psi": math.degrees(abs(swing))}


SWEEPS: dict[str, Sweep] = {
    "crank_rocker.extremes": sweep_crank_rocker,
    "crank_slider.extremes": sweep_crank_slider,
    "guide_bar.extremes": sweep_guide_bar,
}
"""The sweep of each benchmarked recipe, by recipe name."""
