"""Given points that are one rigid body in several positions, drafted as a body (:mod:`.drafting`).

A recipe names its rigid links (:attr:`~geomcon.recipes.base.Recipe.rigid`): a link ``(anchor, point)`` draws
the point at the link's length from the anchor, and a group of links is one link in its positions (a coupler
B_iC_i in three positions). A drafting error must keep the body rigid, as the recipe requires within 1 %: a free
point moves in x and in y and carries what rides on it; a link's point turns about its anchor, ±0.5 mm on paper
across the link; a group's common length grows and shrinks by 0.5 mm on paper along every link of it.

Examples
--------
>>> g = {"B1": [0, 0], "C1": [0, 50], "B2": [10, 0], "C2": [40, 40]}        # a coupler BC of 50 in two positions
>>> for name, plus, minus in point_drafts(Bodies.of(((("B1", "C1"), ("B2", "C2")),), g), "C2", g, 5.0):
...     print(name, {k: [round(x, 3) for x in v] for k, v in plus.items() if v != g[k]})
C2 ⊥ B2C2 {'C2': [35.857, 42.795]}
BC (length) {'C1': [0.0, 55.0], 'C2': [43.0, 44.0]}
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Sequence


def _num(v: Any) -> bool:
    return not isinstance(v, bool) and isinstance(v, (int, float))


def is_point(v: Any) -> bool:
    """Whether ``v`` is a point given ``[x, y]`` of two numbers."""
    return isinstance(v, (list, tuple)) and len(v) == 2 and all(_num(x) for x in v)


@dataclass(frozen=True)
class Bodies:
    """The rigid links of a variant's point givens (:attr:`~geomcon.recipes.base.Recipe.rigid`) that both
    ends of are given: ``anchor`` maps a link's point to its anchor, ``groups`` lists each group's points (in
    the recipe's order) under the name of its link (``BC``: the links' names without their position digits,
    when they agree)."""

    anchor: Mapping[str, str]
    groups: tuple[tuple[str, tuple[str, ...]], ...]

    @staticmethod
    def of(rigid: Sequence[Sequence[tuple[str, str]]], given: Mapping[str, Any]) -> "Bodies":
        """The links of ``rigid`` whose anchor and point are both points of ``given``.

        >>> b = Bodies.of(((("A", "B1"), ("A", "B2")), (("B1", "K1"), ("B2", "K2"))), {"A": [0, 0], "B1": [1, 0],
        ...               "B2": [0, 1], "K1": None, "K2": None})
        >>> dict(b.anchor), b.groups
        ({'B1': 'A', 'B2': 'A'}, (('AB', ('B1', 'B2')),))
        """
        anchor: dict[str, str] = {}
        groups = []
        for group in rigid:
            links = [(a, p) for a, p in group if is_point(given.get(a)) and is_point(given.get(p))]
            if not links:
                continue
            anchor.update({p: a for a, p in links})
            names = {a.rstrip("0123456789") + p.rstrip("0123456789") for a, p in links}
            groups.append((names.pop() if len(names) == 1 else links[0][0] + links[0][1],
                           tuple(p for _, p in links)))
        return Bodies(anchor, tuple(groups))

    def carried(self, name: str) -> list[str]:
        """``name`` and every point that rides on it (its links' points, theirs, …), in a fixed order."""
        out = [name]
        for p in out:
            out.extend(q for q, a in self.anchor.items() if a == p and q not in out)
        return out


def _shifted(given: Mapping[str, Any], names: Sequence[str], dx: float, dy: float) -> dict[str, Any]:
    """``given`` with the points ``names`` moved by (dx, dy)."""
    g = dict(given)
    for n in names:
        g[n] = [float(given[n][0]) + dx, float(given[n][1]) + dy]
    return g


def point_drafts(bodies: Bodies, name: str, given: Mapping[str, Any], length: float) -> list[tuple[str, dict[str, Any], dict[str, Any]]]:
    """The drafted quantities of the point given ``name`` (see the module): a free point's x and y; a link's
    point turned about its anchor by ``length`` across the link; after the last point of a group, the group's
    common length ± ``length`` (each point slid along its link). What rides on a point moves with it."""
    out = []
    ride = bodies.carried(name)
    a = bodies.anchor.get(name)
    if a is None:
        for xy, (dx, dy) in (("x", (length, 0.0)), ("y", (0.0, length))):
            out.append((f"{name}.{xy}", _shifted(given, ride, dx, dy), _shifted(given, ride, -dx, -dy)))
        return out
    ax, ay = (float(c) for c in given[a])
    px, py = (float(c) for c in given[name])
    arm = math.hypot(px - ax, py - ay)
    if arm > 0.0:
        ends = []
        for t in (length / arm, -length / arm):
            c, s = math.cos(t), math.sin(t)
            ends.append(_shifted(given, ride, ax + c * (px - ax) - s * (py - ay) - px,
                                 ay + s * (px - ax) + c * (py - ay) - py))
        out.append((f"{name} ⊥ {a}{name}", ends[0], ends[1]))
    for link, points in bodies.groups:
        if points[-1] == name:
            out.append((f"{link} (length)", _slid(bodies, given, points, length),
                        _slid(bodies, given, points, -length)))
    return out


def _slid(bodies: Bodies, given: Mapping[str, Any], points: Sequence[str], by: float) -> dict[str, Any]:
    """Each of ``points`` (and what rides on it) moved ``by`` along its link, away from its anchor."""
    g = dict(given)
    for p in points:
        ax, ay = (float(c) for c in given[bodies.anchor[p]])
        px, py = (float(c) for c in given[p])
        arm = math.hypot(px - ax, py - ay)
        if arm > 0.0:
            g = _shifted(g, bodies.carried(p), by * (px - ax) / arm, by * (py - ay) / arm)
    return g


__all__ = ["Bodies", "is_point", "point_drafts"]
