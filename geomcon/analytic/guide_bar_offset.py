"""Closed forms of the offset oscillating guide-bar and of the rotating guide-bar (Whitworth).

Offset guide-bar: the guide bar turns about C and its guide line runs at the distance e from C; the block
at the crank pin B slides on it. At an extreme position the guide line touches the crank circle as well:
with d = AC, a = AB and β the angle between the guide and the line AC (seen from C), the guide line's
distance from A is |d·cos β − e| = a, so cos β = (e ± a)/d. Then ψ = acos((e − a)/d) − acos((e + a)/d); the crank is perpendicular to the guide at
both extremes, so θ = ψ. With the lever CD = L, a slider at D moves H = 2·L·sin(ψ/2).

Rotating guide-bar (AB > AC, the crank AB about A, the guide bar about C): the bar turns fully; a ram driven
from the bar's arm CD = R by a coupler DE, its guide through C perpendicular to the frame, has its extreme
positions when the arm is along the ram's guide: S = 2R; the crank turns through 2·acos(AC/AB) while the
arm goes from one extreme to the other the short way: K = (360° − φ)/φ with φ = 2·acos(AC/AB).

Examples
--------
>>> r = guide_bar_offset_extremes(40, 60, 10)
>>> round(r["psi"], 6) == round(r["theta"], 6)
True
>>> round(guide_bar_offset_extremes(100, 200, 0, L=400)["H"], 9)
400.0
>>> round(rotating_guide_bar_extremes(75, 50)["K"], 3)
2.735
"""
from __future__ import annotations

import math

from .linkages import k_from_theta


def guide_bar_offset_extremes(AB: float, AC: float, e: float, L: float | None = None) -> dict[str, float]:
    """θ, ψ, K (and H with the lever L) of the guide-bar with its guide line offset e from the pivot C."""
    psi = math.degrees(math.acos((e - AB) / AC) - math.acos((e + AB) / AC))
    out = {"theta": psi, "psi": psi, "K": k_from_theta(psi)}
    if L is not None:
        out["H"] = 2.0 * L * math.sin(math.radians(psi) / 2.0)
    return out


def rotating_guide_bar_extremes(AB: float, AC: float, R: float | None = None) -> dict[str, float]:
    """The rotating guide-bar: the crank angle of the ram's slow and quick strokes, K and the stroke 2R.

    The ram's guide passes through C perpendicular to AC: the ram is at an extreme when the bar lies along
    it, i.e. when B is on that line, at cos ∠(AB, AC) = AC/AB: the quick stroke takes the crank through
    φ = 2·acos(AC/AB), the slow one through 360° − φ; the stroke with the arm CD = R is 2R.
    """
    quick = 2.0 * math.degrees(math.acos(AC / AB))
    slow = 360.0 - quick
    out = {"phi_slow": slow, "phi_quick": quick, "theta": 180.0 - quick, "K": slow / quick}
    if R is not None:
        out["S"] = 2.0 * R
    return out

