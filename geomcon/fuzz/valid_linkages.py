"""Random valid problems of the linkage family: extreme positions and design by the time-ratio coefficient K.

Every design case is stated from a linkage generated first (its K, stroke or swing computed exactly), and
``expect`` holds that linkage's own dimensions, so a design that comes back with a different linkage is a
wrong answer whatever its twin says. Extreme-position cases expect values computed at 40 digits (mpmath)
by coordinates — circles intersected, angles by ``atan2`` — a route neither the construction nor the twin
takes. Expectations are absolute tolerances of :data:`EXPECT_REL` times the value (at least 1 mm·scale or
1°); answers that the case leaves ill-determined (γ at a dead point reached to 1e-12) are not expected.

Near-degenerate kinds: Grashof boundary, folded or flat positions, K → 1 (θ at its documented minimum), θ
near its documented maximum, e → 0 and e → its largest value, tiny cranks, scales 1e-3 and 1e6, data drafted
to 4 decimals.

Examples
--------
>>> import random
>>> case = GENERATORS["guide_bar.extremes"](random.Random(1))
>>> case.problem["recipe"], sorted(case.expect)
('guide_bar.extremes', ['K', 'psi', 'theta'])
>>> sorted(GENERATORS)[:3]
['crank_rocker.design_by_K', 'crank_rocker.extremes', 'crank_slider.best_by_K']
"""
from __future__ import annotations

import math
import random
from typing import Any, Callable

from .case import Generator, ValidCase


class _FloatMath:
    """The few functions of mpmath the generators use, in double precision: the stand-in when mpmath (a test
    extra) is not installed. Problems are then stated as well as floats allow and expect nothing."""

    mpf = float
    sqrt = staticmethod(math.sqrt)
    atan2 = staticmethod(math.atan2)
    asin = staticmethod(math.asin)
    sin = staticmethod(math.sin)
    cos = staticmethod(math.cos)
    degrees = staticmethod(math.degrees)
    radians = staticmethod(math.radians)


_BACKEND: Any = None


def _m() -> Any:
    """mpmath, imported on first use (it is only a test extra), or :class:`_FloatMath` when it is missing.

    >>> _m().sqrt(_m().mpf(4)) == 2
    True
    """
    global _BACKEND
    if _BACKEND is None:
        try:
            import mpmath
            _BACKEND = mpmath
        except ImportError:
            _BACKEND = _FloatMath
    return _BACKEND


def exact() -> bool:
    """Whether the generators compute at 40 digits (mpmath installed): only then do cases carry ``expect``."""
    return _m() is not _FloatMath

EXPECT_REL = 1e-7
"""Relative agreement required with the generating linkage (the twins are held to 1e-9)."""

THETA_MIN = math.degrees(1e-3)
"""θ below this (K < 1.00064) is refused by every θ-circle design (documented limit): generated θ stay above.
Crank-slider designs also keep θ ≤ 90° − THETA_MIN, crank-rocker and slotter designs θ ≤ 180° − THETA_MIN
(the documented maxima of K)."""


# ----------------------------------------------------------------------------------------------- helpers
def _scale(rng: random.Random) -> tuple[float, str]:
    """A length scale and the kind it makes: mostly moderate, sometimes 1e-3 or 1e6 (near-degenerate)."""
    r = rng.random()
    if r < 0.08:
        return 1e-3 * rng.uniform(1, 3), "near-degenerate: scale 1e-3"
    if r < 0.16:
        return 1e6 * rng.uniform(1, 3), "near-degenerate: scale 1e6"
    return 10 ** rng.uniform(0, 3), "random"


def _drafted(rng: random.Random, given: dict[str, Any], kind: str) -> tuple[dict[str, Any], str]:
    """Sometimes keep the data as a draughtsman prints them: 4 decimals (extremes cases only: their
    expectations are computed from the givens as they are)."""
    if kind == "random" and rng.random() < 0.15:
        return {k: (round(v, 4) if isinstance(v, float) and abs(v) > 1 else v) for k, v in given.items()}, \
            "near-degenerate: drafted to 4 decimals"
    return given, kind


def _tol(value: float, unit_scale: float, rel: float = EXPECT_REL) -> float:
    return rel * max(abs(value), unit_scale)


def _expect(values: dict[str, float], units: dict[str, float], rel: float = EXPECT_REL) -> dict[str, tuple[float, float]]:
    """``name -> (value, tolerance)`` with the unit scale of each name (length scale for mm, 1 otherwise)."""
    return {k: (float(v), _tol(float(v), units.get(k, 1.0), rel)) for k, v in values.items()}


def _mp_intersect(c1, r1, c2, r2, upper: bool = True):
    """The intersection of two circles at 40 digits, the one left (upper=True) of c1 → c2."""
    dx, dy = c2[0] - c1[0], c2[1] - c1[1]
    d = _m().sqrt(dx * dx + dy * dy)
    a = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    h = _m().sqrt(max(_m().mpf(0), r1 * r1 - a * a))
    ux, uy = dx / d, dy / d
    s = 1 if upper else -1
    return (c1[0] + a * ux - s * h * uy, c1[1] + a * uy + s * h * ux)


def _mp_angle(v, p, q):
    """Unsigned angle at vertex ``v`` between p and q, degrees, at 40 digits."""
    ax, ay, bx, by = p[0] - v[0], p[1] - v[1], q[0] - v[0], q[1] - v[1]
    return _m().degrees(abs(_m().atan2(ax * by - ay * bx, ax * bx + ay * by)))


def _k(theta):
    return (180 + theta) / (180 - theta)


def _acute(g):
    return min(g, 180 - g)


# ----------------------------------------------------------------------------------------- crank-rocker
def _rocker_links(rng: random.Random, S: float) -> tuple[tuple[float, float, float, float], str]:
    """A Grashof crank-rocker (AB strictly shortest, s + l < p + q), or one at or near the boundary."""
    while True:
        kind = "random"
        a = S * rng.uniform(0.05, 0.5)
        if rng.random() < 0.1:
            a = S * 10 ** rng.uniform(-6, -2)
            kind = "near-degenerate: tiny crank"
        b, c, d = (S * rng.uniform(0.3, 1.5) for _ in range(3))
        if min(b, c, d) <= a * 1.01:
            continue
        ls = sorted([b, c, d])
        margin = ls[0] + ls[1] - ls[2] - a
        if margin <= 0:
            continue
        r = rng.random()
        if r < 0.12:
            # move the longest link so that s + l = p + q (1 − δ): Grashof boundary or just inside
            delta = 0.0 if r < 0.03 else 10 ** rng.uniform(-12, -5)
            longest = max(range(3), key=lambda i: (b, c, d)[i])
            vals = [b, c, d]
            others = sum(vals) - vals[longest]
            vals[longest] = (others - a) * (1 - delta) + 0.0
            b, c, d = vals
            if min(b, c, d) <= a * 1.01 or max(b, c, d) < sorted([b, c, d])[1]:
                continue
            kind = "near-degenerate: Grashof boundary" if delta == 0 else "near-degenerate: near the Grashof boundary"
        ls = sorted([b, c, d])
        if a + ls[2] > ls[0] + ls[1]:
            continue
        return (a, b, c, d), kind


def _mp_rocker(a: float, b: float, c: float, d: float) -> dict[str, Any]:
    """Extreme positions and transmission angles of a crank-rocker (A origin, D on +x, linkage above)."""
    A, D = (_m().mpf(0), _m().mpf(0)), (_m().mpf(d), _m().mpf(0))
    a, b, c, d = (_m().mpf(x) for x in (a, b, c, d))
    C1 = _mp_intersect(A, b - a, D, c)
    C2 = _mp_intersect(A, b + a, D, c)
    th, psi = _mp_angle(A, C1, C2), _mp_angle(D, C1, C2)
    gam = []
    for sign in (1, -1):
        B = (sign * a, _m().mpf(0))
        C = _mp_intersect(B, b, D, c)
        gam.append(_acute(_mp_angle(C, B, D)))
    return {"theta": th, "psi": psi, "K": _k(th), "gamma_1": gam[0], "gamma_2": gam[1], "gamma_min": min(gam),
            "angle_C1AD": _mp_angle(A, C1, D), "angle_C2AD": _mp_angle(A, C2, D), "C1": C1, "C2": C2}


def crank_rocker_extremes(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    (a, b, c, d), k2 = _rocker_links(rng, S)
    kind = k2 if k2 != "random" else kind
    given = {"AB": a, "BC": b, "CD": c, "AD": d}
    given, kind = _drafted(rng, given, kind)
    if rng.random() < 0.2:
        given["branch"] = "below"
    r = _mp_rocker(given["AB"], given["BC"], given["CD"], given["AD"])
    names = ["theta", "psi", "K", "gamma_min", "gamma_1", "gamma_2", "angle_C1AD", "angle_C2AD"]
    rel = EXPECT_REL
    if "Grashof" in kind:                    # a dead point (γ = 0, C2 on the frame) reached to rounding only
        names, rel = ["theta", "psi", "K"], 1e-5
    return ValidCase({"recipe": "crank_rocker.extremes", "given": given},
                     _expect({n: r[n] for n in names}, {}, rel), kind)


# ----------------------------------------------------------------------------------------- crank-slider
def _slider_links(rng: random.Random, S: float) -> tuple[tuple[float, float, float], str]:
    a = S * rng.uniform(0.1, 1.0)
    b = a * (1 + 10 ** rng.uniform(-1, 1))
    kind = "random"
    r = rng.random()
    if r < 0.08:
        e = 0.0
        kind = "near-degenerate: e = 0"
    elif r < 0.16:
        e = (b - a) * 10 ** rng.uniform(-9, -3)
        kind = "near-degenerate: e → 0"
    elif r < 0.26:
        e = (b - a) * (1 - 10 ** rng.uniform(-12, -4))
        kind = "near-degenerate: e → BC − AB"
    elif r < 0.3:
        a = b * 10 ** rng.uniform(-9, -4)
        e = (b - a) * rng.uniform(0.0, 0.9)
        kind = "near-degenerate: tiny crank"
    else:
        e = (b - a) * rng.uniform(0.0, 0.95)
    return (a, b, e), kind


def _mp_slider(a: float, b: float, e: float) -> dict[str, Any]:
    """Extreme positions and pressure angles of an offset crank-slider, at 40 digits (guide y = −e)."""
    a, b, e = (_m().mpf(x) for x in (a, b, e))
    x1 = _m().sqrt(max(_m().mpf(0), (b - a) ** 2 - e * e))
    x2 = _m().sqrt((b + a) ** 2 - e * e)
    A = (_m().mpf(0), _m().mpf(0))
    th = _mp_angle(A, (x1, -e), (x2, -e))
    a3 = _m().degrees(_m().asin(min(_m().mpf(1), (a + e) / b)))
    a4 = _m().degrees(_m().asin(abs(a - e) / b))
    a1 = _m().degrees(_m().atan2(e, x1))
    return {"H": x2 - x1, "theta": th, "K": _k(th), "alpha_max": a3, "gamma_min": 90 - a3, "gamma_min_fast": 90 - a3,
            "gamma_min_slow": 90 - max(a1, a4)}


def crank_slider_extremes(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    (a, b, e), k2 = _slider_links(rng, S)
    kind = k2 if k2 != "random" else kind
    given, kind = _drafted(rng, {"AB": a, "BC": b, "e": e}, kind)
    if given["AB"] + given["e"] > given["BC"]:
        given["e"] = given["BC"] - given["AB"]
    r = _mp_slider(given["AB"], given["BC"], given["e"])
    return ValidCase({"recipe": "crank_slider.extremes", "given": given},
                     _expect(r, {"H": given["BC"] + given["AB"]}), kind)


# ----------------------------------------------------------------------------------------- guide bar
def guide_bar_extremes(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    r = rng.random()
    if r < 0.1:
        ratio = 10 ** rng.uniform(-9.9, -4)
        kind = "near-degenerate: tiny crank"
    elif r < 0.2:
        ratio = 1 - 10 ** rng.uniform(-12, -4)
        kind = "near-degenerate: nearly a rotating guide bar"
    else:
        ratio = rng.uniform(0.01, 0.99)
    AC = S
    AB = AC * ratio
    if not 1e-6 <= AB:
        AB, AC = 1e-6, 1e-6 / ratio
    given, kind = _drafted(rng, {"AB": AB, "AC": AC}, kind)
    if given["AB"] >= given["AC"]:
        given = {"AB": AB, "AC": AC}
    psi = 2 * _m().degrees(_m().asin(_m().mpf(given["AB"]) / _m().mpf(given["AC"])))
    return ValidCase({"recipe": "guide_bar.extremes", "given": given},
                     _expect({"theta": psi, "psi": psi, "K": _k(psi)}, {}), kind)


# ----------------------------------------------------------------------------------------- design by K
def _theta_ok(theta: float, upper: float) -> bool:
    return THETA_MIN * 1.001 < theta < upper


def crank_slider_design(rng: random.Random) -> ValidCase:
    """Stated from a generated offset crank-slider: K and H of that linkage plus one of its e, AB, BC."""
    while True:
        S, kind = _scale(rng)
        (a, b, e), k2 = _slider_links(rng, S)
        kind = k2 if k2 != "random" else kind
        if e == 0.0:
            given = {"K": 1.0, "H": 2 * a, "BC": b}
            return ValidCase({"recipe": "crank_slider.design_by_K", "given": given},
                             _expect({"AB": a, "BC": b, "e": 0.0}, {"AB": b, "BC": b, "e": b}), "near-degenerate: K = 1")
        r = _mp_slider(a, b, e)
        th = float(r["theta"])
        if not _theta_ok(th, 90.0 - THETA_MIN):
            continue
        K, H = float(_k(r["theta"])), float(r["H"])
        which = rng.choice(["e", "AB", "BC"])
        given = {"K": K, "H": H, which: {"e": e, "AB": a, "BC": b}[which]}
        exp = {"AB": a, "BC": b, "e": e}
        rel = EXPECT_REL
        if "e → BC − AB" in kind:
            rel = 1e-5                           # A at Q: the closing condition crosses the circle at a small angle
        return ValidCase({"recipe": "crank_slider.design_by_K", "given": given},
                         _expect(exp, {n: H for n in exp}, rel), kind)


def crank_slider_best(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    r = rng.random()
    if r < 0.1:
        th = THETA_MIN * rng.uniform(1.01, 2)
        kind = "near-degenerate: K → 1"
    elif r < 0.2:
        th = (90 - THETA_MIN) * (1 - 10 ** rng.uniform(-9, -3))
        kind = "near-degenerate: θ → its largest value"
    else:
        th = rng.uniform(1, 85)
    K = float(_k(_m().mpf(th)))
    given: dict[str, Any] = {"K": K, "H": S}
    e_hi = S / math.tan(math.radians(th))
    if rng.random() < 0.3:
        lo = e_hi * rng.uniform(0, 0.5)
        given["e_min"] = lo
        if rng.random() < 0.5:
            given["e_max"] = lo + (e_hi - lo) * rng.uniform(0.05, 0.9)
    return ValidCase({"recipe": "crank_slider.best_by_K", "given": given},
                     _expect({"K": K, "theta": th}, {}), kind)


def _rocker_case_geometry(rng: random.Random):
    """A generated crank-rocker with θ within the documented limits and its extreme positions."""
    while True:
        S, kind = _scale(rng)
        (a, b, c, d), k2 = _rocker_links(rng, S)
        kind = k2 if k2 != "random" else kind
        r = _mp_rocker(a, b, c, d)
        if _theta_ok(float(r["theta"]), 180 - THETA_MIN * 1.001):
            return (a, b, c, d), r, kind


def crank_rocker_design(rng: random.Random) -> ValidCase:
    """Every form: positions (psi or phi1/phi2) with BC, AB, AC1 or frame_line; K = 1 with AD or frame_line;
    the frame form (AD, phi); the links form (AB, BC, psi); sometimes H_out."""
    form = rng.choice(["BC", "AB", "AC1", "frame_line", "K1", "phi", "links"])
    if form == "K1":
        return _rocker_k1(rng)
    (a, b, c, d), r, kind = _rocker_case_geometry(rng)
    K, th = float(r["K"]), float(r["theta"])
    exp = {"AB": a, "BC": b, "CD": c, "AD": d}
    units = {n: max(b, c, d) for n in exp}
    D = (_m().mpf(d), _m().mpf(0))
    C1, C2 = r["C1"], r["C2"]
    phi1 = float(_m().degrees(_m().atan2(C1[1] - D[1], C1[0] - D[0])))
    phi2 = float(_m().degrees(_m().atan2(C2[1] - D[1], C2[0] - D[0])))
    psi = float(r["psi"])
    rel = EXPECT_REL if "Grashof" not in kind else 1e-5
    if form == "links":
        given = {"K": K, "AB": a, "BC": b, "psi": psi}
    elif form == "phi":
        phi = float(_mp_angle(D, (_m().mpf(0), _m().mpf(0)), C1))
        given = {"K": K, "CD": c, "AD": d, "phi": phi}
    else:
        given = {"K": K, "CD": c}
        if form == "frame_line" or rng.random() < 0.5:
            given.update(phi1=phi1, phi2=phi2)
        else:
            given["psi"] = psi
        given.update({"BC": {"BC": b}, "AB": {"AB": a}, "AC1": {"AC1": b - a},
                      "frame_line": {"frame_line": True}}[form])
        if "psi" in given and rng.random() < 0.2:
            H_out = c * rng.uniform(0.5, 2)
            given["H_out"] = H_out
            exp["DE"] = H_out / (2 * math.sin(math.radians(psi) / 2))
            units["DE"] = H_out
    if kind == "near-degenerate: Grashof boundary":
        # the generating linkage has an extreme position on its frame line (a dead point): by the validity rule
        # it is not a design (the positions must lie strictly on one side of AD), and the problem may have no
        # other solution or one too ill-conditioned to check; a clean refusal is acceptable
        return ValidCase({"recipe": "crank_rocker.design_by_K", "given": given}, {}, kind, may_refuse=True)
    # near the boundary (δ down to 1e-12) γmin ∝ √δ moves ~1/δ times the relative change of the givens: the
    # solver's documented condition limit (KAPPA_REFUSE = 1e7) may refuse it, cleanly
    return ValidCase({"recipe": "crank_rocker.design_by_K", "given": given}, _expect(exp, units, rel), kind,
                     may_refuse="near the Grashof boundary" in kind)


def _rocker_k1(rng: random.Random) -> ValidCase:
    """K = 1: A on the line C1C2 beyond C1 (the folded end), with AD or the frame line through D."""
    while True:
        S, kind = _scale(rng)
        c = S
        f1 = rng.uniform(20, 160)
        f2 = f1 - rng.uniform(10, 120) * rng.choice([1, -1])
        C1 = (c * math.cos(math.radians(f1)), c * math.sin(math.radians(f1)))
        C2 = (c * math.cos(math.radians(f2)), c * math.sin(math.radians(f2)))
        L = math.dist(C1, C2)
        use_frame = rng.random() < 0.5
        ux, uy = (C1[0] - C2[0]) / L, (C1[1] - C2[1]) / L
        if use_frame:
            if abs(uy) < 0.05:
                continue
            t = -C1[1] / uy                  # A = C1 + t·u on the horizontal through D
            if t <= 0:
                continue
        else:
            t = L * rng.uniform(0.05, 3)
        A = (C1[0] + t * ux, C1[1] + t * uy)
        a, b, d = L / 2, t + L / 2, math.hypot(*A)
        ls = sorted([b, c, d])
        if not (a < ls[0] * 0.999 and a + ls[2] < (ls[0] + ls[1]) * 0.999):
            continue
        s1 = (0 - A[0]) * (C1[1] - A[1]) - (0 - A[1]) * (C1[0] - A[0])
        s2 = (0 - A[0]) * (C2[1] - A[1]) - (0 - A[1]) * (C2[0] - A[0])
        if s1 * s2 <= 0 or min(abs(s1), abs(s2)) < 1e-3 * d * c:
            continue
        given: dict[str, Any] = {"K": 1.0, "CD": c, "phi1": f1, "phi2": f2}
        given.update({"frame_line": True} if use_frame else {"AD": d})
        exp = {"AB": a, "BC": b, "AD": d}
        return ValidCase({"recipe": "crank_rocker.design_by_K", "given": given},
                         _expect(exp, {n: max(b, c, d) for n in exp}), "near-degenerate: K = 1" if kind == "random" else kind)


def _guide_theta(rng: random.Random) -> tuple[float, str]:
    r = rng.random()
    if r < 0.1:
        return THETA_MIN * rng.uniform(1.01, 2), "near-degenerate: K → 1"
    if r < 0.2:
        return 90 * (1 - 10 ** rng.uniform(-9, -3)), "near-degenerate: θ → 90°"
    return rng.uniform(1, 89), "random"


def guide_bar_design(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    th, k2 = _guide_theta(rng)
    kind = k2 if k2 != "random" else kind
    AC = S
    AB = float(AC * _m().sin(_m().radians(_m().mpf(th) / 2)))
    psi = float(2 * _m().degrees(_m().asin(_m().mpf(AB) / AC)))
    K = float(_k(_m().mpf(psi)))
    which = rng.choice(["AB", "AC"])
    given = {"K": K, which: {"AB": AB, "AC": AC}[which]}
    return ValidCase({"recipe": "guide_bar.design_by_K", "given": given},
                     _expect({"AB": AB, "AC": AC, "psi": psi}, {"AB": AC, "AC": AC}), kind)


def shaper_design(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    th, k2 = _guide_theta(rng)
    kind = k2 if k2 != "random" else kind
    AC = S
    AB = float(AC * _m().sin(_m().radians(_m().mpf(th) / 2)))
    psi = 2 * _m().degrees(_m().asin(_m().mpf(AB) / AC))
    K = float(_k(psi))
    CD = S * rng.uniform(1, 5)
    half = _m().radians(psi / 2)
    H = float(2 * CD * _m().sin(half))
    which = rng.choice(["AB", "AC"])
    given: dict[str, Any] = {"K": K, "H": H, which: {"AB": AB, "AC": AC}[which]}
    dev = CD * (1 - _m().cos(half)) / 2
    exp = {"AB": AB, "AC": AC, "psi": float(psi), "CD": CD, "h": CD * (1 + _m().cos(half)) / 2, "deviation": dev}
    r = rng.random()
    if r < 0.3:
        al = rng.uniform(1, 89)
        given["alpha_allow"] = al
        exp["DE"] = dev / _m().sin(_m().radians(al))
        exp["alpha_max"] = al
    elif r < 0.5:
        DE = float(dev) * rng.uniform(1.01, 20)
        given["DE"] = DE
        exp["DE"] = DE
        exp["alpha_max"] = _m().degrees(_m().asin(dev / DE))
    units = {n: CD for n in ("AB", "AC", "CD", "h", "deviation", "DE")}
    units["deviation"] = units["DE"] = float(dev) if dev > 0 else CD
    return ValidCase({"recipe": "shaper.design_by_K", "given": given}, _expect(exp, units), kind)


def slotter_design(rng: random.Random) -> ValidCase:
    """Stated from a rotating guide bar (AB > AC): K from the crank angle between B's crossings of ee."""
    S, kind = _scale(rng)
    AB = S
    r = rng.random()
    if r < 0.1:
        ratio = 10 ** rng.uniform(-6, -2)          # AC ≪ AB: K → 1
        kind = "near-degenerate: K → 1"
    elif r < 0.2:                                  # near the documented K ≤ 6282: 180° − θ → 0.057°
        fast = math.radians(THETA_MIN) * rng.uniform(1.01, 3)  # the fast stroke's crank angle
        ratio = math.cos(fast / 2)
        kind = "near-degenerate: K near its maximum"
    else:
        ratio = rng.uniform(0.05, 0.95)
    AC = AB * ratio
    half = _m().sqrt((_m().mpf(AB) - AC) * (_m().mpf(AB) + AC))
    crank = 2 * _m().degrees(_m().atan2(half, AC))      # the crank angle of the fast stroke
    K = float((360 - crank) / crank)
    th = 180 * (K - 1) / (K + 1)
    if not THETA_MIN * 1.001 < th < 180 - THETA_MIN * 1.001:
        return slotter_design(rng)
    CD = S * rng.uniform(0.2, 2)
    given: dict[str, Any] = {"K": K, "H": 2 * CD, "B1B2": float(2 * half)}
    exp: dict[str, Any] = {"AB": AB, "AC": AC, "CD": CD}
    if rng.random() < 0.4:
        al = rng.uniform(1, 89)
        given["alpha_allow"] = al
        exp["DE"] = CD / math.sin(math.radians(al))
    return ValidCase({"recipe": "slotter.design_by_K", "given": given},
                     _expect(exp, {n: AB for n in exp}), kind)


def in_ranges(case: ValidCase) -> bool:
    """Whether every given length lies in the global range (0 or 1e-6 … 1e9 mm, no two nonzero lengths more
    than 1e10 apart): the generators draw again otherwise, since the problem would be refused up front.

    >>> in_ranges(ValidCase({"recipe": "guide_bar.extremes", "given": {"AB": 1e-7, "AC": 1.0}}))
    False
    """
    from ..recipes import get_recipe
    units = {q.name: q.unit for q in get_recipe(case.problem["recipe"]).givens}
    lengths = [abs(v) for k, v in case.problem["given"].items() if units[k] == "mm" and v != 0]
    return all(1e-6 <= x <= 1e9 for x in lengths) and max(lengths) <= 1e10 * min(lengths)


def _ranged(gen: Callable[[random.Random], ValidCase]) -> Generator:
    """The generator drawn again until its case lies in the global ranges, run at 40 digits when mpmath is
    installed (a local precision: the process's own mpmath setting is left alone), otherwise in floats and
    with no ``expect`` (floats are not ground truth near the degenerate cases)."""
    def draw(rng: random.Random) -> ValidCase:
        while True:
            if exact():
                with _m().workdps(40):
                    case = gen(rng)
            else:
                case = gen(rng)
                case = ValidCase(case.problem, {}, case.kind, case.may_refuse)
            if in_ranges(case):
                return case
    draw.__doc__ = gen.__doc__
    draw.__name__ = gen.__name__
    return draw


GENERATORS: dict[str, Generator] = {name: _ranged(gen) for name, gen in (
    ("crank_rocker.extremes", crank_rocker_extremes),
    ("crank_slider.extremes", crank_slider_extremes),
    ("guide_bar.extremes", guide_bar_extremes),
    ("crank_slider.design_by_K", crank_slider_design),
    ("crank_rocker.design_by_K", crank_rocker_design),
    ("crank_slider.best_by_K", crank_slider_best),
    ("guide_bar.design_by_K", guide_bar_design),
    ("slotter.design_by_K", slotter_design),
    ("shaper.design_by_K", shaper_design),
)}

__all__ = ["EXPECT_REL", "GENERATORS"]
