"""Whole-cycle problems: a TOML file describing a linkage and what to tabulate over the crank turn.

The format (``problems/cycles/*.toml``; lengths in mm, angles in degrees, ω in rad/s, ε in rad/s²)::

    kind = "cycle"
    seed = "000-09"                 # optional provenance: seed, title, statement, source, notes
    title = "Slotting machine: cutter motion over a crank turn"
    [mechanism]
    fixed = { O2 = [0, 0], O4 = [-161, 0], G = [-276.4, 0] }
    crank = { link = "O2A", pivot = "O2", joint = "A", length = 70, omega = 4.8147 }   # [epsilon = 0]
    [[mechanism.chain]]             # in order; each uses only names placed before it
    type = "RPR"                    # RRR | RRP | RPR | PRP | point (see below)
    name = "guide"
    slider = "A"
    pivot = "O4"
    link = "O4B"
    [cycle]
    step = 2                        # [start = 0, stop = 360]: crank angles start, start + step, …, stop
    columns = ["O4B.omega", "BC.omega", "C.y", "C.vy", "C.ay"]
    extremes = ["C.y"]              # stationary points, found exactly
    strokes = ["C.y"]               # stroke, crank angles of the two motions, K, θ (full turn only)
    trace = ["C"]                   # points whose paths the animation draws
    at = [231.65]                   # crank angles tabulated besides the grid (the columns, in the JSON)
    [published]                     # printed answers, audited: "stroke(C.y)", "K(C.y)", "min(C.y)", …

Elements of the chain (optional keys in brackets):

- ``RRR``: ``name p1 p2 l1 l2 branch link1 link2 [joint]`` — the joint (default ``name``) at l1 from p1 and l2
  from p2, left of p1→p2 for branch = 1, right for −1;
- ``RRP``: ``name p length guide branch link [joint slider]`` — a link from p to a pin sliding on ``guide``
  (``{through, angle [, link]}``: through a point at ``angle``, fixed or carried by ``link``); branch 1: the
  pin ahead of the foot of the perpendicular from p along the guide;
- ``RPR``: ``name slider pivot link [branch offset slip]`` — the guide link about ``pivot`` through the slider
  block pinned at ``slider``;
- ``PRP``: ``name guide1 guide2 slip1 slip2`` — a revolute where two guides cross;
- ``point``: ``name link base length [angle]`` — a point carried by ``link``, ``length`` from its point
  ``base`` at ``angle`` from the link's direction.

Untrusted input: nothing is evaluated; the file is at most 1 MiB (:func:`~geomcon.problems.read_limited`),
nesting at most 32 levels, at most :data:`LIMITS` of each kind; names are identifiers of at most 32
characters; every number is checked for type, finiteness and range.

Examples
--------
>>> p = cycle_from_dict({"kind": "cycle", "mechanism": {"fixed": {"A": [0, 0], "G": [0, 0]},
...     "crank": {"link": "AB", "pivot": "A", "joint": "B", "length": 30, "omega": 10},
...     "chain": [{"type": "RRP", "name": "C", "p": "B", "length": 90, "guide": {"through": "G", "angle": 0},
...                "branch": 1, "link": "BC"}]}, "cycle": {"step": 90, "columns": ["C.x"]}}, name="demo")
>>> p.phi_deg.tolist(), p.columns
([0.0, 90.0, 180.0, 270.0, 360.0], ('C.x',))
>>> cycle_from_dict({"kind": "cycle", "mechanism": {}}, name="demo")
Traceback (most recent call last):
...
geomcon.errors.ProblemError: mechanism: missing key 'chain'
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from ..errors import ProblemError
from ..problems import _text, check_number, parse_toml, read_limited, title_zh
from .chain import Mechanism, _makes, check_chain
from .dyads import PRP, RPR, RRP, RRR, Crank, Element, Guide, OnLink
from .quantities import check_name

LIMITS = {"fixed_points": 64, "chain": 64, "columns": 64, "names": 64, "positions": 100_001}
"""Most fixed points, chain elements, columns, listed names and crank positions a cycle problem may hold."""

MIN_STEP = 1e-3
"""The smallest crank step (deg)."""

TOP = ("kind", "seed", "title", "title_zh", "statement", "source", "notes", "mechanism", "cycle", "published")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}$")
_KEYS = {
    "RRR": ({"name", "p1", "p2", "l1", "l2", "branch", "link1", "link2"}, {"joint"}),
    "RRP": ({"name", "p", "length", "guide", "branch", "link"}, {"joint", "slider"}),
    "RPR": ({"name", "slider", "pivot", "link"}, {"branch", "offset", "slip"}),
    "PRP": ({"name", "guide1", "guide2", "slip1", "slip2"}, set()),
    "point": ({"name", "link", "base", "length"}, {"angle"}),
}


@dataclass(frozen=True)
class CycleProblem:
    """A validated cycle problem."""

    id: str
    mechanism: Mechanism
    phi_deg: np.ndarray
    columns: tuple[str, ...]
    extremes: tuple[str, ...] = ()
    strokes: tuple[str, ...] = ()
    trace: tuple[str, ...] = ()
    at: tuple[float, ...] = ()
    published: Mapping[str, float] = field(default_factory=dict)
    title: str = ""
    seed: str = ""
    statement: str = ""
    source: str = ""
    notes: str = ""
    title_zh: str = ""
    """The Chinese title (:func:`geomcon.problems.title_zh`): the plot sheets, printed in both languages, set it
    under the English one."""


def _table(data: Any, where: str) -> Mapping[str, Any]:
    if not isinstance(data, Mapping):
        raise ProblemError(f"{where} must be a table")
    return data


def _keys(data: Mapping[str, Any], need: set[str], may: set[str], where: str) -> None:
    for k in sorted(need):
        if k not in data:
            raise ProblemError(f"{where}: missing key '{k}'")
    for k in data:
        if k not in need | may:
            raise ProblemError(f"{where}: unknown key '{str(k)[:40]}'")


def _name(value: Any, where: str) -> str:
    if not isinstance(value, str) or not _NAME.match(value):
        raise ProblemError(f"{where} must be a name (a letter, then letters, digits or _; at most 32), "
                           f"got {str(value)[:40]!r}")
    return value


def _length(value: Any, where: str, zero: bool = False) -> float:
    x = check_number("mm", value, where)
    if x < 0 or (x == 0 and not zero) or (0 < x < 1e-6):
        raise ProblemError(f"{where} must be a length > 0 (at least 1e-6 mm), got {value}")
    return x


def _signed(value: Any, unit: str, where: str) -> float:
    return check_number(unit, value, where)


def _branch(value: Any, where: str) -> int:
    if isinstance(value, bool) or value not in (1, -1):
        raise ProblemError(f"{where} must be 1 or -1, got {str(value)[:40]}")
    return int(value)


def _guide(data: Any, where: str) -> Guide:
    data = _table(data, where)
    _keys(data, {"through", "angle"}, {"link"}, where)
    link = _name(data["link"], f"{where}.link") if "link" in data else None
    return Guide(_name(data["through"], f"{where}.through"), math.radians(_signed(data["angle"], "deg",
                                                                                   f"{where}.angle")), link)


def _element(data: Any, where: str) -> Element:
    data = _table(data, where)
    kind = data.get("type")
    if kind not in _KEYS:
        raise ProblemError(f"{where}.type must be one of {', '.join(_KEYS)}, got {str(kind)[:40]!r}")
    need, may = _KEYS[kind]
    _keys({k: v for k, v in data.items() if k != "type"}, need, may, where)
    n = {k: _name(data[k], f"{where}.{k}") for k in ("name", "p1", "p2", "p", "link", "link1", "link2", "slider",
                                                    "pivot", "joint", "slip", "slip1", "slip2", "base")
         if k in data}
    if kind == "RRR":
        return RRR(n["name"], n["p1"], n["p2"], _length(data["l1"], f"{where}.l1"),
                   _length(data["l2"], f"{where}.l2"), _branch(data["branch"], f"{where}.branch"),
                   n["link1"], n["link2"], n.get("joint", ""))
    if kind == "RRP":
        return RRP(n["name"], n["p"], _length(data["length"], f"{where}.length"),
                   _guide(data["guide"], f"{where}.guide"), _branch(data["branch"], f"{where}.branch"),
                   n["link"], n.get("slider", ""), n.get("joint", ""))
    if kind == "RPR":
        return RPR(n["name"], n["slider"], n["pivot"], n["link"], _branch(data.get("branch", 1), f"{where}.branch"),
                   _signed(data.get("offset", 0), "mm", f"{where}.offset"), n.get("slip", ""))
    if kind == "PRP":
        return PRP(n["name"], _guide(data["guide1"], f"{where}.guide1"), _guide(data["guide2"], f"{where}.guide2"),
                   n["slip1"], n["slip2"])
    return OnLink(n["name"], n["link"], n["base"], _length(data["length"], f"{where}.length"),
                  math.radians(_signed(data.get("angle", 0), "deg", f"{where}.angle")))


def _names(data: Any, where: str, limit: int) -> tuple[str, ...]:
    if not isinstance(data, list):
        raise ProblemError(f"{where} must be a list of names")
    if len(data) > limit:
        raise ProblemError(f"{where} has {len(data)} items; at most {limit}")
    out = []
    for i, v in enumerate(data):
        if not isinstance(v, str) or len(v) > 80:
            raise ProblemError(f"{where}[{i}] must be a quantity name of at most 80 characters")
        out.append(v)
    return tuple(out)


def _mechanism(data: Any) -> Mechanism:
    data = _table(data, "mechanism")
    _keys(data, {"fixed", "crank", "chain"}, set(), "mechanism")
    fixed_in = _table(data["fixed"], "mechanism.fixed")
    if len(fixed_in) > LIMITS["fixed_points"]:
        raise ProblemError(f"mechanism.fixed has {len(fixed_in)} points; at most {LIMITS['fixed_points']}")
    fixed = {}
    for k, v in fixed_in.items():
        where = f"mechanism.fixed.{str(k)[:40]}"
        _name(k, where)
        if not isinstance(v, list) or len(v) != 2:
            raise ProblemError(f"{where} must be a point [x, y]")
        fixed[k] = complex(check_number("point", v[0], where), check_number("point", v[1], where))
    c = _table(data["crank"], "mechanism.crank")
    _keys(c, {"link", "pivot", "joint", "length", "omega"}, {"epsilon"}, "mechanism.crank")
    omega = _signed(c["omega"], "", "mechanism.crank.omega")
    if omega == 0:
        raise ProblemError("mechanism.crank.omega must not be 0 (the crank drives the linkage)")
    crank = Crank(_name(c["link"], "mechanism.crank.link"), _name(c["pivot"], "mechanism.crank.pivot"),
                  _name(c["joint"], "mechanism.crank.joint"), _length(c["length"], "mechanism.crank.length"),
                  omega, _signed(c.get("epsilon", 0), "", "mechanism.crank.epsilon"))
    chain_in = data["chain"]
    if not isinstance(chain_in, list):
        raise ProblemError("mechanism.chain must be a list of tables ([[mechanism.chain]])")
    if len(chain_in) > LIMITS["chain"]:
        raise ProblemError(f"mechanism.chain has {len(chain_in)} elements; at most {LIMITS['chain']}")
    m = Mechanism(fixed, crank, tuple(_element(e, f"mechanism.chain[{i}]") for i, e in enumerate(chain_in)))
    check_chain(m)
    return m


def _grid(data: Mapping[str, Any]) -> np.ndarray:
    start = _signed(data.get("start", 0), "deg", "cycle.start")
    stop = _signed(data.get("stop", start + 360), "deg", "cycle.stop")
    step = _signed(data["step"], "deg", "cycle.step")
    if not stop > start or stop - start > 360:
        raise ProblemError(f"cycle: need start < stop ≤ start + 360°, got start = {start:g}, stop = {stop:g}")
    if step < MIN_STEP:
        raise ProblemError(f"cycle.step = {step:g}° is below the smallest step {MIN_STEP:g}°")
    n = (stop - start) / step
    if abs(n - round(n)) > 1e-9 * max(n, 1):
        raise ProblemError(f"cycle.step = {step:g}° does not divide stop − start = {stop - start:g}°")
    if round(n) + 1 > LIMITS["positions"]:
        raise ProblemError(f"cycle: {round(n) + 1} crank positions; at most {LIMITS['positions']}")
    return start + step * np.arange(round(n) + 1)


def cycle_from_dict(data: Mapping[str, Any], *, name: str, path: str | None = None) -> CycleProblem:
    """Validate a parsed cycle problem."""
    data = _table(data, "the file")
    for k in data:
        if k not in TOP:
            raise ProblemError(f"unknown key '{str(k)[:40]}' (a cycle problem has {', '.join(TOP)})")
    if data.get("kind") != "cycle":
        raise ProblemError(f"kind must be \"cycle\", got {str(data.get('kind'))[:40]!r}")
    if "mechanism" not in data:
        raise ProblemError("missing table [mechanism]")
    m = _mechanism(data["mechanism"])
    cyc = _table(data.get("cycle", {}), "cycle")
    _keys(cyc, {"step"}, {"start", "stop", "columns", "extremes", "strokes", "trace", "at"}, "cycle")
    phi = _grid(cyc)
    points, links, slips = set(m.fixed), set(), set()
    for el in (m.crank, *m.chain):
        p, lk, s = _makes(el)
        points.update(p), links.update(lk), slips.update(s)
    lists = {}
    for key in ("columns", "extremes", "strokes"):
        lists[key] = _names(cyc.get(key, []), f"cycle.{key}", LIMITS["columns"])
        for i, q in enumerate(lists[key]):
            check_name(q, points, links, slips, f"cycle.{key}[{i}]")
    trace = _names(cyc.get("trace", []), "cycle.trace", LIMITS["names"])
    for i, p in enumerate(trace):
        if p not in points:
            raise ProblemError(f"cycle.trace[{i}]: no point '{p[:40]}'")
    at_in = cyc.get("at", [])
    if not isinstance(at_in, list) or len(at_in) > LIMITS["names"]:
        raise ProblemError(f"cycle.at must be a list of at most {LIMITS['names']} crank angles")
    at = tuple(_signed(x, "deg", f"cycle.at[{i}]") for i, x in enumerate(at_in))
    full = abs(float(phi[-1] - phi[0]) - 360.0) < 1e-9
    if lists["strokes"] and not full:
        raise ProblemError("cycle.strokes need a full crank turn (stop = start + 360)")
    pub_in = _table(data.get("published", {}), "published")
    if len(pub_in) > LIMITS["names"]:
        raise ProblemError(f"published has {len(pub_in)} entries; at most {LIMITS['names']}")
    published = {}
    for k, v in pub_in.items():
        if not isinstance(k, str) or len(k) > 100:
            raise ProblemError("published: a key must be an answer name of at most 100 characters")
        published[k] = check_number("", v, f"published.{k}") if not k.startswith(("stroke", "min", "max")) \
            else _signed(v, "point", f"published.{k}")
    return CycleProblem(name, m, phi, lists["columns"], lists["extremes"], lists["strokes"], trace, at, published,
                        **{k: _text(data[k], k) if k in data else "" for k in
                           ("title", "seed", "statement", "source", "notes")},
                        title_zh=title_zh(data.get("title_zh", "")))


def demo_problem(**cycle: Any) -> CycleProblem:
    """A small problem for examples: the centric crank-slider 30/90 at ω = 10 rad/s, ``cycle`` its [cycle] table.

    >>> demo_problem(step=180, columns=["C.x"]).phi_deg.tolist()
    [0.0, 180.0, 360.0]
    """
    return cycle_from_dict({"kind": "cycle", "mechanism": {"fixed": {"A": [0, 0], "G": [0, 0]},
                            "crank": {"link": "AB", "pivot": "A", "joint": "B", "length": 30, "omega": 10},
                            "chain": [{"type": "RRP", "name": "C", "p": "B", "length": 90,
                                       "guide": {"through": "G", "angle": 0}, "branch": 1, "link": "BC"}]},
                            "cycle": cycle}, name="demo")


def load_cycle(path: str | Path) -> CycleProblem:
    """Read and validate a cycle problem file (untrusted: see the module's notes)."""
    path = Path(path)
    return cycle_from_dict(parse_toml(read_limited(path)), name=path.stem, path=str(path))
