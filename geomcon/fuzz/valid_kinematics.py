"""Random valid problems of the kinematics family: velocity and acceleration polygons and instant centres at one
crank position.

Ground truth takes a route neither the polygons nor the twins take: positions written with the law of cosines
at 40 digits (mpmath) and differentiated in time by mpmath's high-precision numerical differentiation along the
crank's motion φ(t) = φ0 + ωt + ½εt². Expectations are :data:`~geomcon.fuzz.valid_linkages.EXPECT_REL` of each
answer's scale (the answer, or the crank's own speed or acceleration for one near 0).

Near-degenerate kinds: a position close to a dead point (the polygon's two direction lines at a small angle),
tiny and huge scales (1e-3, 1e6), a slow and a fast crank.

Examples
--------
>>> import random
>>> case = GENERATORS["four_bar.kinematics"](random.Random(1))
>>> case.problem["recipe"], "omega2" in case.expect or not case.expect
('four_bar.kinematics', True)
"""
from __future__ import annotations

import math
import random
from typing import Any, Callable

from .case import Generator, ValidCase
from .valid_linkages import EXPECT_REL, _ranged


def _m() -> Any:
    import mpmath
    return mpmath


def _scale(rng: random.Random) -> tuple[float, str]:
    r = rng.random()
    if r < 0.1:
        return 1e-3, "near-degenerate: scale 1e-3"
    if r < 0.2:
        return 1e6, "near-degenerate: scale 1e6"
    return 1.0, "random"


def _motion(rng: random.Random) -> tuple[float, float]:
    w = rng.choice((-1, 1)) * (10 ** rng.uniform(-1, 2))
    return w, (rng.uniform(-3, 3) * w * w if rng.random() < 0.6 else 0.0)


def _expect(values: dict[str, Any], scales: dict[str, float]) -> dict[str, tuple[Any, float]]:
    out = {}
    for k, v in values.items():
        s = scales.get(k, 0.0)
        if isinstance(v, tuple):
            out[k] = (tuple(float(x) for x in v), EXPECT_REL * max(max(abs(float(x)) for x in v), s))
        else:
            out[k] = (float(v), EXPECT_REL * max(abs(float(v)), s))
    return out


def _d(f: Callable[[Any], Any], n: int) -> Any:
    return _m().diff(f, 0, n)


def _crank(phi0: float, w: float, e: float) -> Callable[[Any], Any]:
    m = _m()
    p0 = m.radians(m.mpf(phi0))
    return lambda t: p0 + w * t + e * t * t / 2


def _fourbar_angles(AB, BC, CD, AD, p, sign):
    m = _m()
    bx, by = AB * m.cos(p), AB * m.sin(p)
    d = m.sqrt((AD - bx) ** 2 + by ** 2)
    beta = m.acos((BC * BC + d * d - CD * CD) / (2 * BC * d))
    t2 = m.atan2(-by, AD - bx) + sign * beta
    cx, cy = bx + BC * m.cos(t2), by + BC * m.sin(t2)
    return t2, m.atan2(cy, cx - AD)


def _fourbar_links(rng: random.Random, S: float) -> tuple[dict[str, float], str]:
    kind = "random"
    while True:
        AB, BC, CD, AD = (rng.uniform(10, 200) * S for _ in range(4))
        phi = rng.uniform(-180, 360)
        bx, by = AB * math.cos(math.radians(phi)), AB * math.sin(math.radians(phi))
        d = math.hypot(AD - bx, by)
        lo, hi = abs(BC - CD), BC + CD
        if lo < d < hi:
            margin = min(d - lo, hi - d) / d
            if margin > 0.05:
                break
            if margin > 1e-3:
                kind = "near-degenerate: near a dead point"
                break
    return {"AB": AB, "BC": BC, "CD": CD, "AD": AD, "phi": phi}, kind


def four_bar_kinematics(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    g, k2 = _fourbar_links(rng, S)
    kind = k2 if k2 != "random" else kind
    w, e = _motion(rng)
    branch = rng.choice(("above", "below"))
    g.update(omega=w, epsilon=e, branch=branch)
    if rng.random() < 0.5:
        g["BE"], g["angle_CBE"] = rng.uniform(5, 150) * S, rng.uniform(-180, 180)
    m = _m()
    sign = 1 if branch == "above" else -1
    ph = _crank(g["phi"], w, e)
    th = lambda t, i: _fourbar_angles(g["AB"], g["BC"], g["CD"], g["AD"], ph(t), sign)[i]
    w2, w3 = _d(lambda t: th(t, 0), 1), _d(lambda t: th(t, 1), 1)
    e2, e3 = _d(lambda t: th(t, 0), 2), _d(lambda t: th(t, 1), 2)
    vals = {"omega2": w2, "omega3": w3, "epsilon2": e2, "epsilon3": e3, "vC": abs(w3) * g["CD"],
            "aC": g["CD"] * m.sqrt(e3 ** 2 + w3 ** 4)}
    wsc, asc = abs(w), w * w + abs(e)
    scales = {"omega2": wsc, "omega3": wsc, "epsilon2": asc, "epsilon3": asc, "vC": wsc * g["AB"], "aC": asc * g["AB"]}
    if "BE" in g:
        a = m.radians(g["angle_CBE"])
        ex = lambda t: g["AB"] * m.cos(ph(t)) + g["BE"] * m.cos(th(t, 0) + a)
        ey = lambda t: g["AB"] * m.sin(ph(t)) + g["BE"] * m.sin(th(t, 0) + a)
        vals["vE"] = m.hypot(_d(ex, 1), _d(ey, 1))
        vals["aE"] = m.hypot(_d(ex, 2), _d(ey, 2))
        scales.update(vE=wsc * g["AB"], aE=asc * g["AB"])
    rel = 1e3 if "dead point" in kind else 1.0
    exp = {k: (v, t * rel) for k, (v, t) in _expect(vals, scales).items()}
    return ValidCase({"recipe": "four_bar.kinematics", "given": g}, exp, kind)


def _slider_case(rng: random.Random) -> tuple[dict[str, float], str]:
    S, kind = _scale(rng)
    while True:
        AB, BC, e = rng.uniform(10, 100) * S, rng.uniform(50, 300) * S, rng.uniform(-40, 40) * S
        phi = rng.uniform(-180, 360)
        if abs(AB * math.sin(math.radians(phi)) + e) < 0.9 * BC:
            return {"AB": AB, "BC": BC, "e": e, "phi": phi}, kind


def _slider_x(g, p):
    m = _m()
    h = g["AB"] * m.sin(p) + g["e"]
    return g["AB"] * m.cos(p) + m.sqrt(g["BC"] ** 2 - h * h), m.asin(-h / g["BC"])


def crank_slider_kinematics(rng: random.Random) -> ValidCase:
    g, kind = _slider_case(rng)
    w, e = _motion(rng)
    g.update(omega=w, epsilon=e)
    ph = _crank(g["phi"], w, e)
    x = lambda t: _slider_x(g, ph(t))[0]
    th = lambda t: _slider_x(g, ph(t))[1]
    wsc, asc = abs(w), w * w + abs(e)
    vals = {"omega2": _d(th, 1), "epsilon2": _d(th, 2), "vC": _d(x, 1), "aC": _d(x, 2)}
    scales = {"omega2": wsc, "epsilon2": asc, "vC": wsc * g["AB"], "aC": asc * g["AB"]}
    return ValidCase({"recipe": "crank_slider.kinematics", "given": g}, _expect(vals, scales), kind)


def guide_bar_kinematics(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    AB, AC = rng.uniform(10, 200) * S, rng.uniform(10, 200) * S
    if abs(AB - AC) < 5 * S:
        AC += 10 * S
    w, e = _motion(rng)
    g = {"AB": AB, "AC": AC, "phi": rng.uniform(-180, 360), "omega": w, "epsilon": e}
    m = _m()
    ph = _crank(g["phi"], w, e)
    s = lambda t: m.hypot(AB * m.cos(ph(t)), AB * m.sin(ph(t)) + AC)
    a = lambda t: m.atan2(AB * m.sin(ph(t)) + AC, AB * m.cos(ph(t)))
    w3, v = _d(a, 1), _d(s, 1)
    lever = 1 + AB / abs(AB - AC)
    wsc, asc = abs(w) * lever, (w * w + abs(e)) * lever * lever
    vals = {"omega3": w3, "epsilon3": _d(a, 2), "v_slip": v, "a_slip": _d(s, 2), "a_coriolis": 2 * w3 * v}
    scales = {"omega3": wsc, "epsilon3": asc, "v_slip": wsc * AB, "a_slip": asc * AB, "a_coriolis": asc * AB}
    return ValidCase({"recipe": "guide_bar.kinematics", "given": g}, _expect(vals, scales), kind)


def _slotter_at(g: dict[str, Any], p: Any) -> tuple[Any, Any, Any, Any, Any]:
    """The slotter at the crank angle ``p`` (rad) by atan2 and Pythagoras only: the guide bar's angle, CB, D's
    coordinates, the coupler's angle and the ram's height."""
    m = _m()
    bx, by = g["AB"] * m.cos(p) + g["AC"], g["AB"] * m.sin(p)
    th3 = m.atan2(by, bx)
    dx, dy = -g["AC"] - g["CD"] * m.cos(th3), -g["CD"] * m.sin(th3)
    h = -(g["AC"] + g["CF"]) - dx
    up = m.sqrt(g["DE"] ** 2 - h * h) * (1 if g["branch"] == "above" else -1)
    return th3, m.hypot(bx, by), (dx, dy), m.atan2(up, h), dy + up


def slotter_kinematics(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    while True:
        AB, AC, CD, DE = (rng.uniform(10, 200) * S for _ in range(4))
        phi = rng.uniform(-180, 360)
        a = math.radians(phi)
        bx, by = AB * math.cos(a) + AC, AB * math.sin(a)
        if math.hypot(bx, by) > 0.1 * AC:
            break
    reach = 0.9 if rng.random() < 0.9 else 0.999
    if reach > 0.9:
        kind = "near-degenerate: the coupler nearly perpendicular to the ram's path"
    CF = CD * bx / math.hypot(bx, by) + rng.choice((-1, 1)) * rng.uniform(0, reach) * DE
    w, e = _motion(rng)
    g = {"AB": AB, "AC": AC, "CD": CD, "DE": DE, "CF": CF, "phi": phi, "omega": w, "epsilon": e,
         "branch": rng.choice(("above", "below"))}
    m = _m()
    ph = _crank(phi, w, e)
    at = lambda i: (lambda t: _slotter_at(g, ph(t))[i])
    dx = lambda t: _slotter_at(g, ph(t))[2][0]
    dy = lambda t: _slotter_at(g, ph(t))[2][1]
    w3, s1 = _d(at(0), 1), _d(at(1), 1)
    vals = {"omega3": w3, "epsilon3": _d(at(0), 2), "v_slip": s1, "a_slip": _d(at(1), 2), "a_coriolis": 2 * w3 * s1,
            "vB3": abs(w3) * _slotter_at(g, ph(0))[1], "vD": m.hypot(_d(dx, 1), _d(dy, 1)),
            "aD": m.hypot(_d(dx, 2), _d(dy, 2)), "omega4": _d(at(3), 1), "epsilon4": _d(at(3), 2),
            "vE": _d(at(4), 1), "aE": _d(at(4), 2)}
    lever = 1 + AB / math.hypot(bx, by)
    steep = 1 / math.sqrt(1 - reach ** 2)
    wsc, asc = abs(w) * lever, (w * w + abs(e)) * lever * lever
    L = AB + CD
    scales = {"omega3": wsc, "epsilon3": asc, "v_slip": wsc * L, "a_slip": asc * L, "a_coriolis": asc * L,
              "vB3": wsc * L, "vD": wsc * L, "aD": asc * L, "omega4": wsc * steep * L / DE,
              "epsilon4": asc * steep ** 3 * L / DE, "vE": wsc * steep * L, "aE": asc * steep ** 3 * L}
    return ValidCase({"recipe": "slotter.kinematics", "given": g}, _expect(vals, scales), kind)


def four_bar_instant_centres(rng: random.Random) -> ValidCase:
    S, kind = _scale(rng)
    g, k2 = _fourbar_links(rng, S)
    kind = k2 if k2 != "random" else kind
    branch = rng.choice(("above", "below"))
    g["branch"] = branch
    m = _m()
    sign = 1 if branch == "above" else -1
    p0 = m.radians(m.mpf(g["phi"]))
    th = lambda t, i: _fourbar_angles(g["AB"], g["BC"], g["CD"], g["AD"], p0 + t, sign)[i]
    w2, w3 = _d(lambda t: th(t, 0), 1), _d(lambda t: th(t, 1), 1)
    if abs(w3) < 1e-3 or abs(w2) < 1e-3 or abs(w3 - 1) < 1e-3:      # a centre near infinity: not stated
        return four_bar_instant_centres(rng)
    bx, by = g["AB"] * m.cos(p0), g["AB"] * m.sin(p0)
    vals = {"w3_w1": w3, "w2_w1": w2, "i13": 1 / w3, "P13": (w3 * g["AD"] / (w3 - 1), 0),
            "P24": (bx - bx / w2, by - by / w2)}
    far = max(abs(w3 * g["AD"] / (w3 - 1)), m.hypot(bx / w2, by / w2), g["AD"])
    scales = {"w3_w1": 1.0, "w2_w1": 1.0, "i13": 1.0, "P13": far * far / g["AD"], "P24": far * far / g["AD"]}
    rel = 1e3 if "dead point" in kind else 1.0
    exp = {k: (v, t * rel) for k, (v, t) in _expect(vals, scales).items()}
    return ValidCase({"recipe": "four_bar.instant_centres", "given": g}, exp, kind)


def crank_slider_instant_centres(rng: random.Random) -> ValidCase:
    g, kind = _slider_case(rng)
    m = _m()
    p0 = m.radians(m.mpf(g["phi"]))
    v = _d(lambda t: _slider_x(g, p0 + t)[0], 1)
    w2 = _d(lambda t: _slider_x(g, p0 + t)[1], 1)
    if abs(w2) < 1e-3:                                   # P24 near infinity: not stated
        return crank_slider_instant_centres(rng)
    bx, by = g["AB"] * m.cos(p0), g["AB"] * m.sin(p0)
    vals = {"vC_w1": v, "w2_w1": w2, "P13": (0, -v), "P24": (bx - bx / w2, by - by / w2)}
    far = max(m.hypot(bx / w2, by / w2), g["BC"])
    scales = {"vC_w1": g["AB"], "w2_w1": 1.0, "P13": g["AB"], "P24": far * far / g["BC"]}
    return ValidCase({"recipe": "crank_slider.instant_centres", "given": g}, _expect(vals, scales), kind)


GENERATORS: dict[str, Generator] = {name: _ranged(gen) for name, gen in (
    ("four_bar.kinematics", four_bar_kinematics),
    ("crank_slider.kinematics", crank_slider_kinematics),
    ("guide_bar.kinematics", guide_bar_kinematics),
    ("slotter.kinematics", slotter_kinematics),
    ("four_bar.instant_centres", four_bar_instant_centres),
    ("crank_slider.instant_centres", crank_slider_instant_centres),
)}

__all__ = ["GENERATORS"]
