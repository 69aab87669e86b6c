"""``four_bar.link_ranges``: three links and the frame given, the ranges of the fourth for each type.

Construction (the textbook's case analysis, seed 001-02): with the known lengths a ≤ b ≤ c and the unknown
x, Grashof's condition s + l ≤ p + q reads x + c ≤ a + b when x is the shortest, a + c ≤ x + b when x lies
between a and c, a + x ≤ b + c when x is the longest; the chain cannot move when x ≥ a + b + c or
x ≤ c − a − b. These lengths and a, c cut the axis of x into pieces; each piece (and each cut) is classified
by Grashof's rule: the joints of the shortest link turn fully, a neighbour of the frame at such a joint is
a crank. Neighbouring pieces of one type are joined; a cut takes the type of its own chain (a change-point
keeps its crank, so 190 ≤ BC ≤ 290 is closed). The drawing is the axis of x with one row per type.
"""
from __future__ import annotations

import math
from typing import Any, Callable, Iterable, Mapping

from ..analytic.four_bar_analysis import LINKS, LOOPS, link_name
from ..analytic.link_ranges import link_ranges
from ..errors import NotAMechanism, ProblemError
from ..geometry import Point, segment
from ..scene import Role, Scene
from ..tolerance import REL_TOL
from ..render.results import name_of
from .base import Construction, Quantity, Recipe

KIND_NAMES = {"crank_rocker": ("crank-rocker", "曲柄摇杆"), "double_crank": ("double-crank", "双曲柄"),
              "double_rocker": ("double-rocker", "双摇杆"), "immovable": ("not a mechanism", "不能运动")}
GIVENS = tuple(Quantity(n, "mm", f"link {n} (leave out the unknown one)", required=False) for n in LINKS) + (
    Quantity("frame", "choice", "the fixed link", required=False, default="AD", minimum=None, choices=LINKS),
)
ANSWERS = (
    Quantity("crank_rocker", "interval[]", "lengths of the unknown link giving a crank-rocker, [[low, high], …]"),
    Quantity("double_crank", "interval[]", "lengths giving a double-crank"),
    Quantity("double_rocker", "interval[]", "lengths giving a double-rocker"),
    Quantity("immovable", "interval[]", "lengths for which the chain cannot move (high = inf: unbounded)"),
    Quantity("grashof_ranges", "interval[]", "lengths for which Grashof's condition s + l ≤ p + q holds"),
    Quantity("boundaries", "mm[]", "the lengths where the type changes (each a change-point or a flat chain)"),
)


def _unknown(g: Mapping[str, Any]) -> str:
    missing = [n for n in LINKS if g.get(n) is None]
    if len(missing) != 1:
        raise ProblemError(f"give exactly three of AB, BC, CD, AD (the fourth is the unknown); missing: "
                           f"{', '.join(missing) or 'none'}")
    return missing[0]


def _validate(g: Mapping[str, Any]) -> list[str]:
    _unknown(g)
    return []


def _kind(L: Mapping[str, Any], frame: str, x: str = "") -> tuple[str, bool]:
    """Grashof's rule on a chain (lengths by name): its type and whether s + l ≤ p + q (``x``, the unknown
    link, is not needed by the rule; a student's rule (:mod:`geomcon.grading.mistakes`) may look at it)."""
    order = sorted(LINKS, key=lambda n: L[n])
    s, p, q, l_ = (L[n] for n in order)
    if l_ >= s + p + q - REL_TOL * l_:
        return "immovable", False
    if s + l_ > p + q + REL_TOL * l_:
        return "double_rocker", False
    return by_shortest(L, frame), True


def by_shortest(L: Mapping[str, Any], frame: str) -> str:
    """The type of a chain that satisfies Grashof's condition: the joints of the shortest link turn fully, a
    neighbour of the frame at such a joint is a crank."""
    s, l_ = min(L.values()), max(L.values())
    shortest = [n for n in LINKS if L[n] <= s + REL_TOL * l_]
    j = LOOPS[frame]
    a = any(j[0] in n for n in shortest)
    b = any(j[3] in n for n in shortest)
    return "double_crank" if a and b else "crank_rocker" if a or b else "double_rocker"


grashof_kind = _kind
"""The textbook's rule (public: :mod:`geomcon.grading.mistakes` replays a student's rule beside it)."""

Kind = Callable[[Mapping[str, Any], str, str], tuple[str, bool]]


def pieces_of(known: Mapping[str, float], x: str, frame: str, cuts: Iterable[float], kind: Kind = _kind
              ) -> tuple[list[float], dict[str, list[list[float]]]]:
    """The axis of the unknown ``x`` cut at the positive ``cuts``: the cuts in order, and the runs of each
    type (and of Grashof's condition), each piece and each cut classified by ``kind``."""
    edges: list[float] = []
    for v in sorted(v for v in cuts if v > 0):         # decisions on the givens: guards of a tape
        if not edges or v > edges[-1]:
            edges.append(v)
    pieces: list[tuple[Any, Any, str, bool]] = []
    lo = 0.0
    c = max(known.values())
    for e in edges + [None]:
        mid = (lo + e) / 2.0 if e is not None else lo + c
        k, gr = kind({**known, x: mid}, frame, x)
        pieces.append((lo, e if e is not None else math.inf, k, gr))
        if e is not None:
            k, gr = kind({**known, x: e}, frame, x)
            pieces.append((e, e, k, gr))
            lo = e
    runs: dict[str, list[list[Any]]] = {k: [] for k in list(KIND_NAMES) + ["grashof_ranges"]}
    for lo_, hi_, k, gr in pieces:
        for name in (k, "grashof_ranges") if gr else (k,):
            r = runs[name]
            if r and r[-1][1] == lo_:
                r[-1][1] = hi_
            else:
                r.append([lo_, hi_])
    return edges, runs


def ends_of(edges: list[float], runs: Mapping[str, list[list[float]]]) -> list[float]:
    """The cuts where the type changes: the ends of the types' runs."""
    return [e for e in edges if any(e in (iv[0], iv[1]) for name in KIND_NAMES for iv in runs[name])]


def boundaries_of(frame: str, x: str, na: str, a: float, nb: str, b: float, nc: str, c: float, *cases: float,
                  kind: Kind = _kind) -> tuple[float, ...]:
    """The ``boundaries`` step: the lengths of ``x`` where the type changes, from the case analysis's lengths
    ``cases`` (and a, c, where the unknown changes rank), each piece classified by ``kind``.

    >>> boundaries_of("AD", "BC", "AB", 160, "AD", 210, "CD", 240, 130, 190, 290, 610)
    (190, 290, 610)
    """
    known = {na: a, nb: b, nc: c}
    return tuple(ends_of(*pieces_of(known, x, frame, list(cases) + [a, c], kind)))


def interval_text(lo: float, hi: float) -> str:
    """A range of lengths as a caption prints it: closed, or open towards an unbounded end (as the Results block
    prints it), never Python's ``inf``.

    >>> interval_text(190, 290), interval_text(610, math.inf)
    ('[190, 290]', '[610, ∞)')
    """
    return f"[{lo:g}, ∞)" if hi == math.inf else f"[{lo:g}, {hi:g}]"


def _intervals(*flat: float) -> tuple[tuple[float, float], ...]:
    """Pairs ((low, high), …) from the flat list low1, high1, low2, high2 …"""
    return tuple((flat[i], flat[i + 1]) for i in range(0, len(flat), 2))


def construct(g: Mapping[str, Any]) -> Construction:
    """Cut the axis of the unknown at the Grashof and assembly lengths; classify and join the pieces."""
    x = _unknown(g)
    frame = g.get("frame") or "AD"
    known = {n: g[n] for n in LINKS if n != x}
    (na, a), (nb, b), (nc, c) = sorted(known.items(), key=lambda kv: kv[1])
    sc = Scene(f"Four-bar: the types as {x} varies")
    row = 0.08 * (a + b + c)
    cases = [("x_short", (a, b, -c), (f"{x} shortest: {x} + {nc} ≤ {na} + {nb}, {x} ≤ {na} + {nb} − {nc}",
                                       f"{x} 为最短杆:{x} + {nc} ≤ {na} + {nb}")),
             ("x_between", (a, c, -b), (f"{x} between: {na} + {nc} ≤ {x} + {nb}, {x} ≥ {na} + {nc} − {nb}",
                                        f"{x} 居中:{na} + {nc} ≤ {x} + {nb}")),
             ("x_long", (b, c, -a), (f"{x} longest: {na} + {x} ≤ {nb} + {nc}, {x} ≤ {nb} + {nc} − {na}",
                                     f"{x} 为最长杆:{na} + {x} ≤ {nb} + {nc}")),
             ("x_flat", (a, b, c), (f"The chain is flat at {x} = {na} + {nb} + {nc}",
                                    f"{x} = {na} + {nb} + {nc} 时四杆共线"))]
    if c - a - b > 0:
        cases.append(("x_flat_short", (c, -a, -b), (f"and at {x} = {nc} − {na} − {nb}", f"及 {x} = {nc} − {na} − {nb}")))
    cut_values, case_refs = [], []
    for key, terms, caption in cases:
        case_refs.append(sc.add(key, _plus, *terms, role=Role.MEASUREMENT, unit="mm", caption=caption))
        cut_values.append(terms[0] + terms[1] + terms[2])
    edges, runs = pieces_of(known, x, frame, cut_values + [a, c])
    answers = {}
    top = 1.15 * edges[-1]
    for i, (name, (en, zh)) in enumerate(list(KIND_NAMES.items()) + [("grashof_ranges", ("Grashof", "满足杆长条件"))]):
        flat = [v for iv in runs[name] for v in iv]
        sc.add(name, _intervals, *flat, role=Role.MEASUREMENT, unit="interval[]",
               caption=(f"{en}: {x} in " + (", ".join(interval_text(*iv) for iv in runs[name]) or "no range"),
                        f"{zh}:" + (f"{x} 取 " + "、".join(interval_text(*iv) for iv in runs[name]) if runs[name]
                                    else f"{x} 无取值范围")))         # not "BC 取 无" (BC takes: none)
        answers[name] = name
        y = -row * i
        if sc.drawing:
            # named as the Results name it, in both languages (001-02 printed "not a mechanism" beside
            # "immovable 不能运动的杆长范围", English only on a bilingual sheet)
            sc.add(f"row{i}", segment, sc.add(f"row{i}_0", Point, 0.0, y, label=f"{name_of(name).symbol} {zh}",
                                              style="row-start",
                                              role=Role.ANNOTATION), sc.add(f"row{i}_1", Point, top, y, visible=False),
                   style="given", role=Role.ANNOTATION)     # a number line, not a fixed link: drawn dash-dot
            # ("frame"), the green range bars along it were cut away as construction over a frame line
            for k, (lo_, hi_) in enumerate(runs[name]):
                hi_d = top if hi_ == math.inf else hi_
                p = sc.add(f"{name}_{k}_lo", Point, lo_, y, style="tick", role=Role.RESULT, label=f"{lo_:g}")
                q = sc.add(f"{name}_{k}_hi", Point, hi_d, y, style="tick", role=Role.RESULT,
                           label="∞" if hi_ == math.inf else f"{hi_:g}")
                sc.add(f"{name}_{k}", segment, p, q, style="admissible", role=Role.RESULT)
    if sc.drawing:                           # the number lines' quantity, at the top row's end
        sc.add("axis_name", Point, top, 0.0, label=f"{x} (mm) 杆长", style="row-end", role=Role.ANNOTATION)
    ends = ends_of(edges, runs)
    named = [(e, _kind({**known, x: e}, frame)[0]) for e in ends]
    sc.add("boundaries", boundaries_of, frame, x, na, a, nb, b, nc, c, *case_refs, role=Role.MEASUREMENT, unit="mm",
           caption=("The type changes at " + "; ".join(
               f"{x} = {v:g} ({'flat: the links cannot move' if k == 'immovable' else 'change-point s + l = p + q, still a ' + KIND_NAMES[k][0]})"
               for v, k in named),
               "类型在 " + ";".join(f"{x} = {v:g}({'四杆共线,不能运动' if k == 'immovable' else '变点机构 s + l = p + q,仍为' + KIND_NAMES[k][1] + '机构'})"
                                   for v, k in named) + " 处改变"))
    answers["boundaries"] = "boundaries"
    return Construction(sc, answers, {})


def _plus(x: float, y: float, z: float) -> float:
    return x + y + z


def analytic(g: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The twin: cuts at every ±a ± b ± c, each piece classified by the joints' diagonals."""
    x = _unknown(g)
    r = link_ranges({n: g[n] for n in LINKS if n != x}, g.get("frame") or "AD")
    out: dict[str, Any] = {k: tuple(tuple(iv) for iv in v) for k, v in r.items() if k != "boundaries"}
    out["boundaries"] = tuple(r["boundaries"])
    return [out]


RECIPE = Recipe(
    name="four_bar.link_ranges",
    title="Four-bar: the lengths of one link for which the chain is a crank-rocker, double-crank, double-rocker",
    givens=GIVENS,
    answers=ANSWERS,
    points=(),
    construct=construct,
    analytic=analytic,
    validate=_validate,
)
del NotAMechanism, link_name
