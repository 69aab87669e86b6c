"""The scalar reference of ``geomcon bench``'s cam rows: a cam's answers by plain float code.

For a translating or an oscillating knife-edge or roller follower, the quantities a cam solve answers — the
largest pressure angle of the rise and of the return and where it occurs, the smallest radius of curvature of
the pitch curve (and of the roller's profile, undercut), ψ0, and the displacement, pressure angle and pitch
point at the listed angles — computed as one would by hand: the motion laws' closed forms on one float with
:mod:`math`, each smooth piece of the program (a segment; the parabolic law's halves) sampled at
:data:`GRID` angles, the best sample refined by bisection on the sign of α's exact derivative (its place)
or by golden-section search (ρmin: the value only) to :data:`XTOL` rad. No numpy, no geomcon
objects: what a cam answer costs at the least by the obvious route. The flat-faced followers and the roller's
actual profile points are not covered (their rows take the twin as the reference). A test checks the covered
answers against the recipes'.

Conventions are those of :mod:`geomcon.cam.translating` and :mod:`geomcon.cam.oscillating` (stated there).

Examples
--------
>>> prog = [{"kind": "rise", "angle": 120, "law": "cosine"}, {"kind": "dwell", "angle": 60},
...         {"kind": "return", "angle": 90, "law": "uniform"}, {"kind": "dwell", "angle": 90}]
>>> a = translating_plain({"follower": "knife", "r0": 30.0, "e": 0.0, "h": 16.0, "rotation": "ccw", "program": prog})
>>> round(a["alpha_max_rise"], 6), round(a["delta_alpha_max_rise"], 6), round(a["rho_min_pitch"], 6)
(17.901969, 51.897868, 28.714034)
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping, Sequence

GRID = 240
"""Samples per smooth piece of the program."""

XTOL = 1e-12
"""Golden-section search stops when its bracket is this narrow (rad)."""

TIE = 1e-12
"""Maxima within this relative difference tie; the smaller cam angle wins."""

_PI2 = math.pi * math.pi
_INV = (math.sqrt(5.0) - 1.0) / 2.0

Law = Callable[[float], tuple[float, float, float]]


def _uniform(x: float) -> tuple[float, float, float]:
    return x, 1.0, 0.0


def _parabolic(x: float) -> tuple[float, float, float]:
    if x <= 0.5:
        return 2.0 * x * x, 4.0 * x, 4.0
    y = 1.0 - x
    return 1.0 - 2.0 * y * y, 4.0 * y, -4.0


def _cosine(x: float) -> tuple[float, float, float]:
    return (1.0 - math.cos(math.pi * x)) / 2.0, math.pi / 2.0 * math.sin(math.pi * x), _PI2 / 2.0 * math.cos(math.pi * x)


def _cycloidal(x: float) -> tuple[float, float, float]:
    t = 2.0 * math.pi * x
    return x - math.sin(t) / (2.0 * math.pi), 1.0 - math.cos(t), 2.0 * math.pi * math.sin(t)


def _poly345(x: float) -> tuple[float, float, float]:
    x2 = x * x
    return x2 * x * (10.0 - 15.0 * x + 6.0 * x2), 30.0 * x2 * (1.0 - x) * (1.0 - x), 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x)


LAWS: dict[str, Law] = {"uniform": _uniform, "parabolic": _parabolic, "cosine": _cosine, "cycloidal": _cycloidal,
                        "poly345": _poly345}
"""The normalised laws f(x), f′(x), f″(x) on 0 ≤ x ≤ 1."""

Piece = tuple[str, float, float, Callable[[float], tuple[float, float, float]]]


def pieces(program: Sequence[Mapping[str, Any]], h: float) -> list[Piece]:
    """The program's smooth pieces ``(kind, start, end, motion)`` in radians; ``motion(δ)`` gives (s, s′, s″)
    per radian by the piece's own segment (its ends included), h in the follower's unit."""
    out: list[Piece] = []
    start, level = 0.0, 0.0
    for seg in program:
        kind, beta = seg["kind"], math.radians(seg["angle"])
        if kind == "dwell":
            out.append((kind, start, start + beta, lambda d, s=level * h: (s, 0.0, 0.0)))
        else:
            f, sign = LAWS[seg["law"]], (1.0 if kind == "rise" else -1.0)

            def motion(d: float, f=f, sign=sign, s0=level * h, a=start, b=beta) -> tuple[float, float, float]:
                y, y1, y2 = f(min(1.0, max(0.0, (d - a) / b)))
                return s0 + sign * h * y, sign * h * y1 / b, sign * h * y2 / (b * b)

            ends = (start, start + beta / 2, start + beta) if seg["law"] == "parabolic" else (start, start + beta)
            out += [(kind, x, y, motion) for x, y in zip(ends, ends[1:])]
            level += sign
        start += beta
    return out


def motion_at(ps: Sequence[Piece], d: float) -> tuple[float, float, float]:
    """(s, s′, s″) at cam angle ``d`` (rad): the segment that starts there (the last one at the turn's end)."""
    for _, a, b, m in ps:
        if a <= d < b:
            return m(d)
    return ps[-1][3](d)


def golden_max(f: Callable[[float], float], a: float, b: float) -> float:
    """The maximiser of ``f`` on [a, b] by golden-section search to :data:`XTOL`."""
    c, d = b - _INV * (b - a), a + _INV * (b - a)
    fc, fd = f(c), f(d)
    while b - a > XTOL:
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - _INV * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + _INV * (b - a)
            fd = f(d)
    return (a + b) / 2


def bisect_down(df: Callable[[float], float], lo: float, hi: float) -> float:
    """Where ``df`` turns from positive (at ``lo``) to not positive (at ``hi``), by bisection to :data:`XTOL`."""
    while hi - lo > XTOL:
        mid = (lo + hi) / 2
        if df(mid) > 0:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def piece_max(f: Callable[[float], float], a: float, b: float,
              df: Callable[[float], float] | None = None) -> tuple[float, float]:
    """(max f, where) on [a, b]: the best of :data:`GRID` + 1 samples, refined between its neighbours — where
    the derivative ``df`` changes sign when it is given (the place to :data:`XTOL`), else by golden section (the
    value only: the place of a smooth maximum is known to √ε) — or the sample itself when it stays the best."""
    xs = [a + (b - a) * i / GRID for i in range(GRID + 1)]
    vs = [f(x) for x in xs]
    i = max(range(GRID + 1), key=vs.__getitem__)
    if df is None:
        found = [golden_max(f, xs[max(0, i - 1)], xs[min(GRID, i + 1)])]
    else:
        found = [bisect_down(df, xs[j], xs[j + 1]) for j in (i - 1, i)
                 if 0 <= j < GRID and df(xs[j]) > 0 >= df(xs[j + 1])]
    return best_of([(vs[i], xs[i])] + [(f(x), x) for x in found])


def best_of(found: Sequence[tuple[float, float]]) -> tuple[float, float]:
    """The largest of several (value, angle), ties to :data:`TIE` going to the smaller angle."""
    best = None
    for v, x in sorted(found, key=lambda t: t[1]):
        if best is None or v > best[0] + TIE * max(abs(v), abs(best[0])):
            best = (v, x)
    assert best is not None
    return best


def _extremes(ps: Sequence[Piece], alpha: Callable, dalpha: Callable, curvature: Callable) -> dict[str, float]:
    """α max per stroke with its angle (deg; ``dalpha`` has the sign of its slope), and ρmin of the pitch
    curve from the largest convex curvature."""
    out: dict[str, float] = {}
    for kind, part in (("rise", "rise"), ("return", "return")):
        found = [piece_max(lambda d, m=m: alpha(*m(d)), a, b, lambda d, m=m: dalpha(*m(d)))
                 for k, a, b, m in ps if k == kind]
        v, x = best_of(found) if found else (0.0, 0.0)
        d = math.degrees(x) % 360.0                 # [0°, 360°): a return's end is 0°, as the recipes say
        out[f"alpha_max_{part}"], out[f"delta_alpha_max_{part}"] = v, 0.0 if 360.0 - d < 1e-9 else d
    top = max(piece_max(lambda d, m=m: curvature(*m(d), d), a, b)[0] for _, a, b, m in ps)
    out["rho_min_pitch"] = 1.0 / top if top > 0 else math.inf
    return out


def _roller(out: dict[str, Any], g: Mapping[str, Any]) -> None:
    rr = g.get("rr") or 0.0
    roller = g["follower"] == "roller"
    out["rho_min_actual"] = out["rho_min_pitch"] - (rr if roller else 0.0)
    out["undercut"] = roller and rr >= out["rho_min_pitch"]


COVERS = "the scalar reference covers knife and roller followers with the five standard laws, without omega"


def _plain_form(g: Mapping[str, Any]) -> bool:
    """A knife or roller follower, every law one of :data:`LAWS`, no ω (the follower's speeds and the handbook
    and parametrised laws are the twin's to check)."""
    rows = g.get("program") or ()
    return (g.get("follower") in ("knife", "roller") and g.get("omega") is None
            and all(r.get("kind") == "dwell" or r.get("law") in LAWS for r in rows))


def translating_plain(g: Mapping[str, Any]) -> dict[str, Any]:
    """``cam.translating`` with a knife or roller follower: the answers above, by scalar code."""
    if not _plain_form(g):
        raise ValueError(COVERS)
    h, r0, e = g["h"], g["r0"], g.get("e") or 0.0
    k = 1.0 if g.get("rotation", "ccw") == "ccw" else -1.0
    s0 = math.sqrt((r0 - e) * (r0 + e))
    ps = pieces(g["program"], h)

    def alpha(s: float, v: float, _a: float) -> float:
        return math.degrees(math.atan2(abs(v - k * e), s0 + s))

    def dalpha(s: float, v: float, acc: float) -> float:     # the sign of d/dδ |E|/S
        E = v - k * e
        return math.copysign(1.0, E) * (acc * (s0 + s) - E * v)

    def curvature(s: float, v: float, acc: float, _d: float) -> float:
        S, E = s0 + s, v - k * e
        return (S * S + E * (E + v) - S * acc) / (S * S + E * E) ** 1.5

    out: dict[str, Any] = {"h": h, **_extremes(ps, alpha, dalpha, curvature)}
    _roller(out, g)
    at = [math.radians(x) for x in g.get("at") or ()]
    if at:
        ms = [motion_at(ps, d) for d in at]
        out["s"] = tuple(m[0] for m in ms)
        out["alpha"] = tuple(alpha(*m) for m in ms)
    return out


def oscillating_plain(g: Mapping[str, Any]) -> dict[str, Any]:
    """``cam.oscillating`` with a knife or roller follower: the answers above (and ψ0), by scalar code."""
    if not _plain_form(g):
        raise ValueError(COVERS)
    a, L, r0, h = g["a"], g["L"], g["r0"], g["h"]
    sg = 1 if g.get("rotation", "ccw") == "ccw" else -1
    tu = -1 if g.get("arm", "left") == "left" else 1
    eps = sg * tu
    p, q = (r0 - a + L) * (r0 + a - L), (a + L + r0) * (a + L - r0)
    psi0 = 2.0 * math.atan2(math.sqrt(p), math.sqrt(q))
    ps = pieces(g["program"], math.radians(h))

    def alpha(psi: float, d1: float, _d2: float) -> float:
        phi = psi0 + psi
        return math.degrees(math.atan2(abs(L * (1.0 - eps * d1) - a * math.cos(phi)), a * math.sin(phi)))

    def dalpha(psi: float, d1: float, d2: float) -> float:   # the sign of d/dδ |N|/D
        phi = psi0 + psi
        c, s = math.cos(phi), math.sin(phi)
        n, den = L * (1.0 - eps * d1) - a * c, a * s
        return math.copysign(1.0, n) * ((-eps * L * d2 + a * s * d1) * den - n * a * c * d1)

    def pitch(psi: float, d1: float, d2: float, d: float) -> tuple[float, ...]:
        ta = math.pi / 2 - sg * d
        t2 = ta + tu * (psi0 + psi)
        w2 = -sg + tu * d1
        ca, sa, c2, s2 = math.cos(ta), math.sin(ta), math.cos(t2), math.sin(t2)
        dx, dy = sg * a * sa + L * w2 * s2, -sg * a * ca - L * w2 * c2
        ddx = -a * ca + L * tu * d2 * s2 + L * w2 * w2 * c2
        ddy = -a * sa - L * tu * d2 * c2 + L * w2 * w2 * s2
        return a * ca - L * c2, a * sa - L * s2, dx, dy, ddx, ddy

    def curvature(psi: float, d1: float, d2: float, d: float) -> float:
        _, _, dx, dy, ddx, ddy = pitch(psi, d1, d2, d)
        return -sg * (dx * ddy - dy * ddx) / math.hypot(dx, dy) ** 3

    out: dict[str, Any] = {"psi_max": h, "psi0": math.degrees(psi0), **_extremes(ps, alpha, dalpha, curvature)}
    _roller(out, g)
    at = [math.radians(x) for x in g.get("at") or ()]
    if at:
        ms = [(motion_at(ps, d), d) for d in at]
        out["psi"] = tuple(math.degrees(m[0]) for m, _ in ms)
        out["alpha"] = tuple(alpha(*m) for m, _ in ms)
        pts = [pitch(*m, d) for m, d in ms]
        out["pitch_x"], out["pitch_y"] = tuple(p[0] for p in pts), tuple(p[1] for p in pts)
    return out


CAM_PLAIN: dict[str, Callable[[Mapping[str, Any]], dict[str, Any]]] = {
    "cam.translating": translating_plain,
    "cam.oscillating": oscillating_plain,
}
"""Recipe name → its scalar reference (knife and roller followers)."""


def covered(recipe: str, given: Mapping[str, Any]) -> bool:
    """Whether :data:`CAM_PLAIN` has a reference for this problem."""
    return recipe in CAM_PLAIN and _plain_form(given)
