"""Closed forms for the analysis of any hinged four-bar chain: its class, which joints turn fully, θ/ψ/K, γ.

The twin of ``four_bar.analysis``. It does not use Grashof's shortest-link rule (the construction does):
a joint between links x and y turns fully exactly when the diagonal opposite it can take both its extreme
lengths |x − y| and x + y, i.e. when the other two links z, w satisfy x + y ≤ z + w and |x − y| ≥ |z − w|.
The chain's type follows from which of the frame's two joints turn fully.

Examples
--------
>>> r = four_bar_analysis(50, 70, 80, 90)
>>> r["type"], r["A_full"], r["D_full"], round(r["theta"], 4), round(r["gamma_min"], 4)
('crank-rocker', True, False, 12.5056, 29.9947)
>>> four_bar_analysis(28, 52, 50, 72, frame="AB")["type"]
'double-crank'
>>> four_bar_analysis(50, 50, 30, 90)["type"]
'double-rocker'
"""
from __future__ import annotations

import math

from ..tolerance import REL_TOL
from .linkages import _tri_angle, k_from_theta

LINKS = ("AB", "BC", "CD", "AD")
"""The links of the loop A–B–C–D–A."""
LOOPS = {"AD": "ABCD", "AB": "BCDA", "BC": "CDAB", "CD": "DABC"}
"""Frame → the loop's joints (j0, j1, j2, j3): the frame is j3j0, the input link j0j1 (at the origin), the
coupler j1j2, the output link j2j3 (its pivot j3 on +x)."""


def link(lengths: dict[str, float], p: str, q: str) -> float:
    """The length of the link joining joints ``p`` and ``q``.

    >>> link({"AB": 1.0, "BC": 2.0, "CD": 3.0, "AD": 4.0}, "D", "A")
    4.0
    """
    return lengths[p + q] if p + q in lengths else lengths[q + p]


def joint_turns_fully(x: float, y: float, z: float, w: float) -> bool:
    """The joint between links x and y turns fully (the chain's other links z, w): both |x − y| and x + y
    are lengths the diagonal opposite the joint can take (equality, a change-point, counts as reached).

    >>> joint_turns_fully(50, 90, 70, 80), joint_turns_fully(70, 80, 50, 90)
    (True, False)
    """
    tol = REL_TOL * max(x, y, z, w)
    return x + y <= z + w + tol and abs(x - y) >= abs(z - w) - tol


def acute(g: float) -> float:
    """The acute form min(g, 180° − g) of an angle in degrees."""
    return min(g, 180.0 - g)


def four_bar_analysis(AB: float, BC: float, CD: float, AD: float, *, frame: str = "AD", driver: str | None = None,
                      phi: float | None = None) -> dict[str, object]:
    """The class of the chain with ``frame`` fixed, its fully turning joints, θ/ψ/K when one frame link is a
    crank, γmin over the driver's motion and, at the driver's angle ``phi``, γ and the pressure angle α.

    ``driver`` is one of the two links at the frame (default: the input link j0j1 of :data:`LOOPS`); ``phi``
    its direction, counter-clockwise from the frame line j0→j3 (degrees), γ the transmission angle at the
    driven link's moving joint (acute form) and α = 90° − γ. γ does not depend on the assembly branch.
    """
    L = {"AB": AB, "BC": BC, "CD": CD, "AD": AD}
    j = LOOPS[frame]
    s = sorted(L.values())
    out: dict[str, object] = {}
    if s[3] >= s[0] + s[1] + s[2] - REL_TOL * s[3]:
        out.update(type="immovable", grashof=False, input_crank=False, output_crank=False)
        out.update({f"{p}_full": False for p in "ABCD"})
        return out
    full = {}
    for i, p in enumerate(j):
        prev, nxt = j[i - 1], j[(i + 1) % 4]
        opp = j[(i + 2) % 4]
        full[p] = joint_turns_fully(link(L, prev, p), link(L, p, nxt), link(L, nxt, opp), link(L, opp, prev))
    out.update({f"{p}_full": full[p] for p in "ABCD"})
    margin = (s[1] + s[2]) - (s[0] + s[3])
    out["grashof"] = margin >= -REL_TOL * s[3]
    change = abs(margin) <= REL_TOL * s[3]
    in_crank, out_crank = full[j[0]], full[j[3]]     # a link at the frame turns fully about its pivot
    if change:
        kind = "change-point"
    elif in_crank and out_crank:
        kind = "double-crank"
    elif in_crank or out_crank:
        kind = "crank-rocker"
    else:
        kind = "double-rocker"
    out["type"] = kind
    out["input_crank"], out["output_crank"] = in_crank, out_crank
    F, X, Z, Y = link(L, j[3], j[0]), link(L, j[0], j[1]), link(L, j[1], j[2]), link(L, j[2], j[3])
    if in_crank != out_crank:                       # one crank, one rocker: extreme positions exist
        a, b, c = (X, Z, Y) if in_crank else (Y, Z, X)
        if b != a:
            f, x = b - a, b + a
            theta = abs(_tri_angle(f, F, c) - _tri_angle(x, F, c))
            out.update(theta=theta, psi=abs(_tri_angle(F, c, x) - _tri_angle(F, c, f)), K=k_from_theta(theta))
    drives_input = driver is None or driver == link_name(j[0], j[1])
    d, e = (X, Y) if drives_input else (Y, X)      # driver, driven
    d_full = in_crank if drives_input else out_crank
    if d_full:
        out["gamma_min"] = min(acute(_tri_angle(Z, e, abs(F - d))), acute(_tri_angle(Z, e, F + d)))
    else:
        out["gamma_min"] = 0.0
    out["dead_points"] = change or not d_full
    if phi is not None:
        # the driven side: diagonal from the driver's moving end to the driven pivot
        diag = math.sqrt(max(0.0, d * d + F * F - 2.0 * d * F * math.cos(math.radians(phi if drives_input else 180.0 - phi))))
        g = acute(_tri_angle(Z, e, diag))
        out["gamma"], out["alpha"] = g, 90.0 - g
    return out


def link_name(p: str, q: str) -> str:
    """The public name of the link joining joints ``p`` and ``q``.

    >>> link_name("D", "A"), link_name("C", "B")
    ('AD', 'BC')
    """
    return p + q if p + q in LINKS else q + p
