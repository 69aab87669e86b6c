"""``cam.base_radius`` with a curvature limit for an oscillating (roller or knife) follower: the smallest base
circle whose pitch curve's radius of curvature is at least ρallow, as well as the pressure angle within α_allow.

The pressure angle alone gives the best centre O* (the admissible point nearest B0, :func:`.cam_base_radius.
construct_arm`). As for a translating follower, whose centre then moves along the guide at the same offset, the
centre O moves from O* along the line perpendicular to the arm A0B0 (the direction of the roller's motion at
B0), away from B0: r0 = OB0 grows strictly along it, and a = OA0 and ψ0 = ∠OA0B0 follow from the points. The
search is one-dimensional and honest about a ρmin that need not grow monotonically: the distance t moved is
doubled from r0α until the limit holds, the first sign change of ρmin(t) − ρallow on a grid of
:data:`SCAN` samples of [0, t] is taken, and it is refined by regula falsi (Illinois). At the design the
pressure-angle limits are checked again (cam.oscillating's closed form); a design the move would push past
them is refused.

Twin: the same family in closed form — O* at (a·cos ψ0, a·sin ψ0) with A0 at the origin and B0 at (L, 0), moved
to y + t — ρmin by cam.oscillating's complex route (:func:`geomcon.cam.arm_twin.arm_rho_min`) instead of the
profile machinery's, a grid of :data:`TWIN_SCAN` samples and plain bisection.
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping

from ..cam.arm_twin import arm_rho_min
from ..cam.profile import rho_min
from ..errors import NotAMechanism
from ..geometry import Point
from ..numeric import bisect_up, illinois
from .common import angle_deg

GROW_MAX = 1e3
"""Largest factor by which the curvature limit may move the centre (in units of r0α): beyond it ρallow is far
beyond the cam's size and the limit is refused."""
SCAN = 16
"""Samples of [0, t] in which the construction looks for the first sign change."""
TWIN_SCAN = 21
"""Samples of [0, t] in which the twin looks for it (a grid of its own)."""


def _first_root(f: Callable[[float], float], scale: float, scan: int, refine: str) -> float:
    """The smallest t ≥ 0 with f(t) ≥ 0: 0 when f(0) ≥ 0; else t doubled from ``scale`` until f(t) ≥ 0, the
    first sign change on ``scan`` samples of [0, t], refined by ``refine`` ("illinois" or "bisect")."""
    f0 = f(0.0)
    if f0 >= 0.0:
        return 0.0
    hi = scale
    while f(hi) < 0.0:
        if hi > GROW_MAX * scale:
            raise NotAMechanism(f"rho_allow needs the centre moved over {GROW_MAX:g}·r0α = {GROW_MAX * scale:.6g} mm: "
                                "the limit is far beyond the cam's size")
        hi *= 2.0
    ts = [hi * i / scan for i in range(scan + 1)]
    lo, flo = 0.0, f0
    for t in ts[1:]:
        ft = f(t)
        if ft >= 0.0:
            hi, fhi = t, ft
            break
        lo, flo = t, ft
    return bisect_up(f, lo, hi) if refine == "bisect" else illinois(f, lo, flo, hi, fhi)


def _check_alpha(g: Mapping[str, Any], cam, r0: float) -> None:
    """Refuse a grown design whose pressure angle exceeds a limit (the move is along the follower's motion at
    B0; with a large stroke it can leave the admissible region)."""
    tol = 1e-9 * max(1.0, g["alpha_allow"])
    parts = [("rise", g["alpha_allow"])]
    if g.get("alpha_allow_return") is not None:
        parts.append(("return", g["alpha_allow_return"]))
    for part, allow in parts:
        alpha = cam.worst_pressure(part)[0]
        if alpha > allow + tol:
            raise NotAMechanism(f"rho_allow = {g['rho_allow']:g}: the base circle grown to r0 = {r0:.6g} mm for it "
                                f"(the centre moved along the roller's motion at B0) has α_max = {alpha:.6g}° in the "
                                f"{part} > α_allow = {allow:g}°")


def grow_arm_centre(g: Mapping[str, Any], O: Point, A0: Point, B0: Point) -> Point:
    """The designed centre: O moved perpendicular to A0B0, away from B0, by the smallest distance that makes the
    pitch curve's ρmin (profile machinery) at least ρallow."""
    from .cam_base_radius import arm_cam

    n = (B0 - A0).perp().unit()
    if n.dot(O - B0) < 0.0:
        n = -n

    def cam_at(t: float):
        P = O + n * t
        return arm_cam(g, abs(P - A0), abs(P - B0), angle_deg(A0, P, B0))

    t = _first_root(lambda t: rho_min(cam_at(t).pitch_curve(scalar=True)).value - g["rho_allow"], abs(O - B0), SCAN, "illinois")
    _check_alpha(g, cam_at(t), abs(O + n * t - B0))
    return O + n * t


def grown(a: float, psi0: float, L: float, t: float) -> tuple[float, float, float]:
    """(a, r0, ψ0 in degrees) of the centre (a·cos ψ0, a·sin ψ0) moved to y + t (A0 at the origin, B0 at (L, 0))."""
    x, y = a * math.cos(math.radians(psi0)), a * math.sin(math.radians(psi0)) + t
    return math.hypot(x, y), math.hypot(x - L, y), math.degrees(math.atan2(y, x))


def twin_arm_grow(g: Mapping[str, Any], out: Mapping[str, float]) -> dict[str, float]:
    """The twin's design: ``out`` (a, r0, ψ0 of the pressure angle's best centre) moved along the same family
    until cam.oscillating's complex-route ρmin reaches ρallow."""
    from .cam_base_radius import arm_cam

    def f(t: float) -> float:
        return arm_rho_min(arm_cam(g, *grown(out["a"], out["psi0"], g["L"], t))) - g["rho_allow"]

    t = _first_root(f, out["r0"], TWIN_SCAN, "bisect")
    a, r0, psi0 = grown(out["a"], out["psi0"], g["L"], t)
    cam = arm_cam(g, a, r0, psi0)
    _check_alpha(g, cam, r0)
    return {"a": a, "r0": r0, "psi0": psi0, "r0_alpha": out["r0"], "r0_rho": r0 if t > 0.0 else out["r0"]}


def arm_margins(g: Mapping[str, Any], cam) -> float:
    """The smallest relative margin of the limits on the designed arm cam: (α_allow − α_max)/α_allow of the rise
    (and the return when limited) and (ρmin − ρallow)/ρallow by cam.oscillating's closed forms; 0 when one limit
    is active, never negative."""
    out = [(g["alpha_allow"] - cam.worst_pressure("rise")[0]) / g["alpha_allow"],
           (arm_rho_min(cam) - g["rho_allow"]) / g["rho_allow"]]
    if g.get("alpha_allow_return") is not None:
        out.append((g["alpha_allow_return"] - cam.worst_pressure("return")[0]) / g["alpha_allow_return"])
    return min(out)
