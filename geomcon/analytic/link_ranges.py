"""The ranges of one unknown link length for which a hinged four-bar is each type (twin of
``four_bar.link_ranges``).

The twin does not reason about which link is shortest: it takes every length at which one of the joints'
conditions (:func:`geomcon.analytic.four_bar_analysis.joint_turns_fully`) or the assembly condition changes —
the positive values of ±a ± b ± c — and classifies the chain at each of them and between them by the joint
rule. A boundary length belongs to the type its chain has there (a change-point keeps its crank: seed 001-02's
crank-rocker range 190 ≤ BC ≤ 290 is closed).

Examples
--------
>>> r = link_ranges({"AB": 160, "CD": 240, "AD": 210}, "AD")
>>> r["crank_rocker"], r["double_crank"], r["double_rocker"], r["immovable"]
([[190.0, 290.0]], [], [[0.0, 190.0], [290.0, 610.0]], [[610.0, inf]])
>>> r["grashof_ranges"], r["boundaries"]
([[0.0, 130.0], [190.0, 290.0]], [190.0, 290.0, 610.0])
"""
from __future__ import annotations

import itertools
import math

from ..tolerance import REL_TOL
from .four_bar_analysis import LINKS, LOOPS, joint_turns_fully, link

KINDS = ("crank_rocker", "double_crank", "double_rocker", "immovable")


def base_kind(L: dict[str, float], frame: str) -> str:
    """The chain's type by which of the frame's neighbours turn fully (a change-point counts as turning).

    >>> base_kind({"AB": 160, "BC": 190, "CD": 240, "AD": 210}, "AD")
    'crank_rocker'
    """
    s = sorted(L.values())
    if s[3] >= s[0] + s[1] + s[2] - REL_TOL * s[3]:
        return "immovable"
    j = LOOPS[frame]

    def turns(i: int) -> bool:
        p, prev, nxt, opp = j[i], j[i - 1], j[(i + 1) % 4], j[(i + 2) % 4]
        return joint_turns_fully(link(L, prev, p), link(L, p, nxt), link(L, nxt, opp), link(L, opp, prev))

    a, b = turns(0), turns(3)
    return "double_crank" if a and b else "crank_rocker" if a or b else "double_rocker"


def link_ranges(known: dict[str, float], frame: str = "AD") -> dict[str, list[list[float]]]:
    """For the one link missing from ``known`` (three of AB, BC, CD, AD), the intervals ``[low, high]`` of its
    length for each type (``high`` = inf for the unbounded one), and the boundaries."""
    (unknown,) = [n for n in LINKS if n not in known]
    vals = list(known.values())
    cuts = sorted({abs(sa * vals[0] + sb * vals[1] + sc * vals[2])
                   for sa, sb, sc in itertools.product((1.0, -1.0), repeat=3)} - {0.0})
    scale = max(vals)

    def kind(x: float) -> str:
        return base_kind({**known, unknown: x}, frame)

    pieces: list[tuple[float, float, str]] = []
    edges = [0.0] + cuts
    for i, lo in enumerate(edges):
        hi = edges[i + 1] if i + 1 < len(edges) else math.inf
        mid = (lo + hi) / 2.0 if hi != math.inf else lo + scale
        pieces.append((lo, hi, kind(mid)))
        if hi != math.inf:
            pieces.append((hi, hi, kind(hi)))
    out: dict[str, list[list[float]]] = {k: [] for k in KINDS + ("grashof_ranges",)}
    for lo, hi, k in pieces:
        for name in (k, "grashof_ranges") if _grashof({**known, unknown: (lo + hi) / 2.0 if hi != math.inf else lo + scale}
                                               if hi != lo else {**known, unknown: lo}) else (k,):
            run = out[name]
            if run and run[-1][1] >= lo:
                run[-1][1] = max(run[-1][1], hi)
            else:
                run.append([lo, hi])
    ends = {x for k in KINDS for iv in out[k] for x in iv}
    out["boundaries"] = sorted(ends - {0.0, math.inf})                   # type: ignore[assignment]
    return out


def _grashof(L: dict[str, float]) -> bool:
    """s + l ≤ p + q (within rounding), the chain's lengths in any order."""
    s = sorted(L.values())
    return s[0] + s[3] <= s[1] + s[2] + REL_TOL * s[3]
