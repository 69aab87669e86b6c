"""A linkage as one description: fixed points, a crank, and a sequence of dyads and carried points.

:func:`solve_chain` places every element in order over an array of crank angles; :func:`check_chain` refuses a
chain that names a point or link before it is placed, or places one twice.

Examples
--------
>>> import numpy as np
>>> from .dyads import Crank, Guide, RRP
>>> m = Mechanism({"A": 0j, "G": 0j}, Crank("AB", "A", "B", 30.0, omega=10.0),
...               (RRP("C", "B", 90.0, Guide("G", 0.0), 1, "BC"),))
>>> st = solve_chain(m, np.radians([0.0, 90.0]))
>>> [round(float(x), 9) for x in st.points["C"].p.real]
[120.0, 84.852813742]
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..errors import ProblemError
from .dyads import PRP, RPR, RRP, RRR, Crank, Element, Guide, OnLink, State


@dataclass(frozen=True)
class Mechanism:
    """Fixed points (complex, mm), the crank, and the chain of elements placed in order."""

    fixed: dict[str, complex]
    crank: Crank
    chain: tuple[Element, ...]

    def unit_speed(self) -> "Mechanism":
        """The same linkage driven at ω = 1 rad/s, ε = 0: its velocities are d/dφ and its accelerations
        d²/dφ² of the positions (used to find extremes exactly)."""
        return replace(self, crank=replace(self.crank, omega=1.0, epsilon=0.0))

    def scale(self) -> float:
        """The largest length or coordinate: the linkage's size, for tolerances."""
        sizes = [abs(z) for z in self.fixed.values()] + [self.crank.length]
        for el in self.chain:
            sizes += [abs(getattr(el, k)) for k in ("l1", "l2", "length", "offset") if hasattr(el, k)]
        return max(sizes)


def _uses(el: Element) -> tuple[list[str], list[str]]:
    """(points, links) an element needs."""
    def guide(g: Guide) -> tuple[list[str], list[str]]:
        return [g.through], [g.link] if g.link else []
    if isinstance(el, RRR):
        return [el.p1, el.p2], []
    if isinstance(el, RRP):
        pts, lks = guide(el.guide)
        return [el.p, *pts], lks
    if isinstance(el, RPR):
        return [el.slider, el.pivot], []
    if isinstance(el, PRP):
        p1, l1 = guide(el.guide1)
        p2, l2 = guide(el.guide2)
        return p1 + p2, l1 + l2
    if isinstance(el, OnLink):
        return [el.base], [el.link]
    raise TypeError(el)


def _makes(el: Element) -> tuple[list[str], list[str], list[str]]:
    """(points, links, slips) an element places."""
    if isinstance(el, Crank):
        return [el.joint], [el.link], []
    if isinstance(el, RRR):
        return [el.joint or el.name], [el.link1, el.link2], []
    if isinstance(el, RRP):
        return [el.joint or el.name], [el.link], [el.slider or el.joint or el.name]
    if isinstance(el, RPR):
        return [], [el.link], [el.slip or el.name]
    if isinstance(el, PRP):
        return [el.name], [], [el.slip1, el.slip2]
    if isinstance(el, OnLink):
        return [el.name], [], []
    raise TypeError(el)


def check_chain(m: Mechanism) -> None:
    """Refuse a chain that uses a point or link before it is placed, or places a name twice.

    Examples
    --------
    >>> from .dyads import Crank, OnLink
    >>> check_chain(Mechanism({"A": 0j}, Crank("AB", "A", "B", 1.0, 1.0), (OnLink("E", "BC", "B", 1.0),)))
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: mechanism.chain[0] (E): link 'BC' is not placed before it
    """
    points, links, slips = set(m.fixed), set(), set()
    if m.crank.pivot not in m.fixed:
        raise ProblemError(f"mechanism.crank: pivot '{m.crank.pivot}' is not a fixed point")
    for k, el in enumerate((m.crank, *m.chain)):
        where = "mechanism.crank" if k == 0 else f"mechanism.chain[{k - 1}] ({el.name})"
        if k:
            need_p, need_l = _uses(el)
            for p in need_p:
                if p not in points:
                    raise ProblemError(f"{where}: point '{p}' is not placed before it")
            for lk in need_l:
                if lk not in links:
                    raise ProblemError(f"{where}: link '{lk}' is not placed before it")
        mp, ml, ms = _makes(el)
        for name, have, what in [(p, points, "point") for p in mp] + [(lk, links, "link") for lk in ml] + \
                [(s, slips, "slider") for s in ms]:
            if name in have:
                raise ProblemError(f"{where}: {what} '{name}' is placed twice")
            have.add(name)
        if isinstance(el, (RRR, RRP, RPR)) and el.branch not in (1, -1):
            raise ProblemError(f"{where}: branch must be +1 or -1, got {el.branch}")
        if isinstance(el, RRR) and el.p1 == el.p2:
            raise ProblemError(f"{where}: p1 and p2 are the same point '{el.p1}'")


def solve_chain(m: Mechanism, phi: np.ndarray, derivatives: bool = True) -> State:
    """Every point, link and slip of ``m`` at the crank angles ``phi`` (rad), vectorised (positions only when
    ``derivatives`` is False). At a dead or change point itself the velocities are unbounded (inf or nan, silently: :func:`~.cycle.assembly` reports them)."""
    st = State.start(phi, m.fixed, derivatives)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        m.crank.apply(st)
        for el in m.chain:
            el.apply(st)
    return st
