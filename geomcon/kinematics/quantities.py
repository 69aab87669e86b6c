"""Named outputs of a solved linkage and their exact derivatives with respect to the crank angle.

A quantity is named ``<point>.<x|y|vx|vy|ax|ay>`` (mm, mm/s, mm/s²), ``<link>.<angle|omega|epsilon>`` (deg in
(−180°, 180°], rad/s, rad/s²), ``<slider>.<s|v|a>`` (mm, mm/s, mm/s²) or ``gamma(<link>,<link>)``, the transmission angle
between two links (deg, folded into [0°, 90°]).

Examples
--------
>>> parse_name("C.vy"), parse_name("gamma(BC, CD)")
(('C', 'vy'), ('gamma', 'BC,CD'))
"""
from __future__ import annotations

import re

import numpy as np

from ..errors import ProblemError
from .dyads import State

POINT_FIELDS = ("x", "y", "vx", "vy", "ax", "ay")
LINK_FIELDS = ("angle", "omega", "epsilon")
SLIP_FIELDS = ("s", "v", "a")
UNITS = {"x": "mm", "y": "mm", "vx": "mm/s", "vy": "mm/s", "ax": "mm/s²", "ay": "mm/s²", "angle": "deg",
         "omega": "rad/s", "epsilon": "rad/s²", "s": "mm", "v": "mm/s", "a": "mm/s²", "gamma": "deg"}
"""The unit of each field."""

_GAMMA = re.compile(r"gamma\(\s*([A-Za-z0-9_]+)\s*,\s*([A-Za-z0-9_]+)\s*\)$")
_DOTTED = re.compile(r"([A-Za-z0-9_]+)\.([a-z]+)$")


def parse_name(name: str) -> tuple[str, str]:
    """``(object, field)`` of a quantity name (for a transmission angle: ``("gamma", "L1,L2")``)."""
    m = _GAMMA.match(name)
    if m:
        return "gamma", f"{m.group(1)},{m.group(2)}"
    m = _DOTTED.match(name)
    if not m:
        raise ProblemError(f"quantity '{name[:60]}' is not of the form NAME.FIELD or gamma(LINK,LINK)")
    return m.group(1), m.group(2)


def check_name(name: str, points: set[str], links: set[str], slips: set[str], where: str) -> None:
    """Refuse a quantity naming nothing the linkage places."""
    obj, fld = parse_name(name)
    if obj == "gamma":
        for lk in fld.split(","):
            if lk not in links:
                raise ProblemError(f"{where}: '{name}': no link '{lk}'")
        return
    for have, fields, what in ((points, POINT_FIELDS, "point"), (links, LINK_FIELDS, "link"),
                               (slips, SLIP_FIELDS, "slider")):
        if obj in have:
            if fld not in fields:
                raise ProblemError(f"{where}: '{name}': a {what} has the fields {', '.join(fields)}")
            return
    raise ProblemError(f"{where}: '{name}': no point, link or slider '{obj}'")


def _position_triple(st: State, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(value, first, second time derivative) of the position-level quantity behind ``name``: for an angle in
    radians, unwrapped nowhere (the caller folds)."""
    obj, fld = parse_name(name)
    if obj == "gamma":
        a, b = (st.links[k] for k in fld.split(","))
        return b.theta - a.theta, b.omega - a.omega, b.epsilon - a.epsilon
    if obj in st.points:
        pm = st.points[obj]
        part = (lambda z: z.real) if fld.endswith("x") else (lambda z: z.imag)
        return part(pm.p), part(pm.v), part(pm.a)
    if obj in st.links:
        lk = st.links[obj]
        return lk.theta, lk.omega, lk.epsilon
    sl = st.slips[obj]
    return sl.s, sl.v, sl.a


def principal_deg(theta: np.ndarray) -> np.ndarray:
    """An angle (rad) in degrees in (−180°, 180°].

    >>> principal_deg(np.radians([180.0, -180.0, 350.0])).round(9).tolist()
    [180.0, 180.0, -10.0]
    """
    d = 180.0 - np.mod(180.0 - np.degrees(theta), 360.0)
    return d + 0.0


def fold_gamma(mu: np.ndarray) -> np.ndarray:
    """The transmission angle (deg, in [0, 90]) of the angle ``mu`` (rad) between two links."""
    m = np.mod(np.degrees(mu), 180.0)
    return np.minimum(m, 180.0 - m)


def value(st: State, name: str) -> np.ndarray:
    """The quantity ``name`` over the crank angles (angles in degrees in [0, 360), γ in [0, 90])."""
    obj, fld = parse_name(name)
    if obj == "gamma":
        return fold_gamma(_position_triple(st, name)[0])
    if obj in st.points:
        pm = st.points[obj]
        z = {"x": pm.p, "y": pm.p, "vx": pm.v, "vy": pm.v, "ax": pm.a, "ay": pm.a}[fld]
        return z.real if fld.endswith("x") else z.imag
    if obj in st.links:
        lk = st.links[obj]
        if fld == "angle":
            return principal_deg(lk.theta)
        return lk.omega if fld == "omega" else lk.epsilon
    sl = st.slips[obj]
    return {"s": sl.s, "v": sl.v, "a": sl.a}[fld]


def position_name(name: str) -> str:
    """The position-level quantity whose derivatives ``name`` is (``C.vy`` → ``C.y``), for extremes."""
    obj, fld = parse_name(name)
    if obj == "gamma":
        return name
    base = {"vx": "x", "ax": "x", "vy": "y", "ay": "y", "omega": "angle", "epsilon": "angle", "v": "s",
            "a": "s"}.get(fld, fld)
    return f"{obj}.{base}"


def derivatives(st_unit: State, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(q, dq/dφ, d²q/dφ²) of the position-level quantity ``name`` from a state solved at ω = 1, ε = 0
    (angles in radians)."""
    return _position_triple(st_unit, name)
