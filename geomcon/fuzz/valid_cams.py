"""Random valid problems of the cam recipes: ``cam.translating``, ``cam.oscillating`` and ``cam.eccentric``.

Each generator draws a cam that the recipe must solve (exit 0) and states what is known of its answers
independently of both the construction and the twin: the motion laws' closed forms written out here again
(s, ψ at the ``at`` angles), the stroke, ψ0 from the triangle O A0 B0, the pitch point from the textbook's
formula, tan α of a translating follower, the eccentric cam's triangle formulas. Near-degenerate cases:
α close to 90° (|e| → r0), rr close to r0, e = 0, huge (1e6) and tiny (1e-3) scales, many dwells, a face
that nearly stops turning relative to the cam, drafted data rounded to 4 decimals.

Examples
--------
>>> import random
>>> c = GENERATORS["cam.translating"](random.Random(3))
>>> c.problem["recipe"], "h" in c.expect
('cam.translating', True)
"""
from __future__ import annotations

import math
import random
from typing import Any

from .case import ValidCase

LAWS = ("uniform", "parabolic", "cosine", "cycloidal", "poly345")
REL = 1e-9


def _f(law: str, x: float) -> tuple[float, float]:
    """(f, f′) of a normalised law at x in [0, 1], written out again (independent of geomcon.cam.laws)."""
    if law == "uniform":
        return x, 1.0
    if law == "parabolic":
        return (2 * x * x, 4 * x) if x < 0.5 else (1 - 2 * (1 - x) ** 2, 4 * (1 - x))
    if law == "cosine":
        return (1 - math.cos(math.pi * x)) / 2, math.pi / 2 * math.sin(math.pi * x)
    if law == "cycloidal":
        return x - math.sin(2 * math.pi * x) / (2 * math.pi), 1 - math.cos(2 * math.pi * x)
    return 10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5, 30 * x * x * (1 - x) ** 2


F1_MAX = {"uniform": 1.0, "parabolic": 2.0, "cosine": math.pi / 2, "cycloidal": 2.0, "poly345": 1.875}


def _program(rng: random.Random, *, many: bool = False) -> list[dict[str, Any]]:
    """A random program: dwell? rise, dwell? return, dwell? over 360° (``many``: up to 40 short dwells)."""
    kinds = ["rise", "return"]
    slots = [0, 1, 2]                                           # dwells before, between, after
    dwells = {s: rng.randint(0, 12 if many else 1) for s in slots}
    parts: list[str] = ["dwell"] * dwells[0] + ["rise"] + ["dwell"] * dwells[1] + ["return"] + ["dwell"] * dwells[2]
    weights = [rng.uniform(0.3, 1.0) * (3.0 if k != "dwell" else 1.0) for k in parts]
    total = sum(weights)
    angles = [round(360.0 * w / total, 3) for w in weights]
    angles[-1] = round(360.0 - sum(angles[:-1]), 9)
    if min(angles) <= 0.5:
        return _program(rng, many=many)
    return [{"kind": k, "angle": a, **({"law": rng.choice(LAWS)} if k in kinds else {})} for k, a in zip(parts, angles)]


def _motion(program: list[dict[str, Any]], h: float, delta: float) -> tuple[float, float]:
    """(s, ds/dδ per radian) at δ (deg, in [0, 360)); segments own [start, end)."""
    start, level = 0.0, 0.0
    for i, seg in enumerate(program):
        end = start + seg["angle"]
        if delta < end or i == len(program) - 1:
            if seg["kind"] == "dwell":
                return level, 0.0
            x = min(max((delta - start) / seg["angle"], 0.0), 1.0)
            f, f1 = _f(seg["law"], x)
            sign = 1.0 if seg["kind"] == "rise" else -1.0
            return level + sign * h * f, sign * h * f1 / math.radians(seg["angle"])
        level += {"rise": h, "return": -h}.get(seg["kind"], 0.0)
        start = end
    raise AssertionError


def _at(rng: random.Random, program: list[dict[str, Any]], n: int) -> list[float]:
    """Cam angles away from the segment ends (where a one-sided s′ would be ambiguous)."""
    ends, start = [0.0], 0.0
    for seg in program:
        start += seg["angle"]
        ends.append(start)
    out = []
    while len(out) < n:
        d = round(rng.uniform(0.0, 359.9), 4)
        if min(abs(d - e) for e in ends) > 0.05:
            out.append(d)
    return out


def _scale(rng: random.Random) -> tuple[float, str]:
    r = rng.random()
    if r < 0.1:
        return 1e6 * rng.uniform(0.5, 2.0), "near-degenerate: huge scale"
    if r < 0.2:
        return 1e-3 * rng.uniform(0.5, 2.0), "near-degenerate: tiny scale"
    return rng.uniform(0.5, 3.0), "random"


def translating(rng: random.Random) -> ValidCase:
    """cam.translating: knife, roller or flat, any law, offset, rotation, dwells, ``at``."""
    k, kind = _scale(rng)
    follower = rng.choice(("knife", "roller", "flat"))
    many = rng.random() < 0.1
    program = _program(rng, many=many)
    r0 = round(rng.uniform(20.0, 60.0), 4) * k
    h = round(rng.uniform(0.1, 1.0) * r0, 4)
    rot = rng.choice(("ccw", "cw"))
    u = rng.random()
    if u < 0.15:
        e, kind = 0.0, kind if kind != "random" else "near-degenerate: e = 0"
    elif u < 0.25 and follower != "flat":
        e, kind = rng.choice((-1, 1)) * r0 * (1 - 10 ** rng.uniform(-9, -3)), "near-degenerate: |e| → r0 (α → 90°)"
    else:
        e = round(rng.uniform(-0.6, 0.6) * r0, 4)
    given: dict[str, Any] = {"follower": follower, "r0": r0, "h": h, "program": program, "rotation": rot}
    if e:
        given["e"] = e
    if follower == "roller":
        if rng.random() < 0.15:
            given["rr"], kind = r0 * (1 - 10 ** rng.uniform(-9, -4)), "near-degenerate: rr → r0"
        else:
            given["rr"] = round(rng.uniform(0.05, 0.5) * r0, 4)
    if many:
        kind = "near-degenerate: many dwells"
    at = _at(rng, program, rng.randint(1, 6))
    given["at"] = at
    expect: dict[str, tuple[Any, float]] = {"h": (h, REL * h)}
    sk = 1.0 if rot == "ccw" else -1.0
    s_at, a_at = [], []
    for d in at:
        s, v = _motion(program, h, d)
        s_at.append(s)
        if follower == "flat":
            a_at.append(0.0)
        else:
            s0 = math.sqrt((r0 - e) * (r0 + e))
            a_at.append(math.degrees(math.atan2(abs(v - sk * e), s0 + s)))
    expect["s"] = (tuple(s_at), 1e-8 * h)
    expect["alpha"] = (tuple(a_at), 1e-6)
    if follower == "flat":
        ks = [sk * h * F1_MAX[seg["law"]] / math.radians(seg["angle"]) * (1 if seg["kind"] == "rise" else -1)
              for seg in program if seg["kind"] != "dwell"] + [0.0]
        expect["face_width_right"] = (max(0.0, max(ks) - e), 1e-8 * (r0 + h))
        expect["face_width_left"] = (max(0.0, e - min(ks)), 1e-8 * (r0 + h))
        expect["alpha_max_rise"] = (0.0, 0.0)
    return ValidCase({"recipe": "cam.translating", "given": given}, expect, kind)


def _psi0(a: float, L: float, r0: float) -> float:
    return math.degrees(math.acos((a * a + L * L - r0 * r0) / (2 * a * L)))


def oscillating(rng: random.Random) -> ValidCase:
    """cam.oscillating: knife, roller or flat-faced arm, both arm sides, both senses."""
    k, kind = _scale(rng)
    follower = rng.choice(("knife", "roller", "flat"))
    program = _program(rng, many=rng.random() < 0.1)
    rot, arm = rng.choice(("ccw", "cw")), rng.choice(("left", "right"))
    a = round(rng.uniform(80.0, 200.0), 4) * k
    given: dict[str, Any] = {"follower": follower, "a": a, "program": program, "rotation": rot, "arm": arm}
    sigma = 1 if rot == "ccw" else -1
    tau = -1 if arm == "left" else 1
    eps = sigma * tau
    if follower == "flat":
        f = round(rng.uniform(-0.1, 0.15) * a, 4) if rng.random() < 0.5 else 0.0
        r0 = round(rng.uniform(0.2, 0.5) * a, 4)
        psi0 = math.degrees(math.asin((r0 + f) / a))
        room = 89.0 - psi0
        # the face must keep turning relative to the cam: 1 − εψ′ > 0 (ψ′max = h·f′max/Φ in rad/rad)
        fastest = min(seg["angle"] / F1_MAX[seg["law"]] for seg in program if seg["kind"] != "dwell")
        h = round(min(room, rng.uniform(0.2, 0.9) * fastest) * rng.uniform(0.3, 1.0), 4)
        if h <= 0.01:
            return oscillating(rng)
        given.update(r0=r0, h=h)
        if f:
            given["face_offset"] = f
    else:
        r0 = round(rng.uniform(0.2, 0.6) * a, 4)
        L = round(rng.uniform(max(a - r0, 0.0) + 0.02 * r0, min(a + r0, a + 0.9 * r0)), 4)
        if not abs(a - L) < r0 < a:
            return oscillating(rng)
        psi0 = _psi0(a, L, r0)
        h = round(rng.uniform(5.0, min(40.0, 170.0 - psi0)), 4)
        given.update(L=L, r0=r0, h=h)
        if follower == "roller":
            given["rr"] = round(rng.uniform(0.05, 0.6) * r0, 4)
    at = _at(rng, program, rng.randint(1, 5))
    given["at"] = at
    expect: dict[str, tuple[Any, float]] = {"psi_max": (h, REL * h), "psi0": (psi0, 1e-7)}
    psis, extra = [], {"pitch_x": [], "pitch_y": [], "face_contact": []}
    for d in at:
        s, v = _motion(program, h, d)
        psis.append(s)
        phi = math.radians(psi0 + s)
        if follower == "flat":
            extra["face_contact"].append(a * math.cos(phi) / (1 - eps * math.radians(v)))
        else:
            ta = math.pi / 2 - sigma * math.radians(d)
            extra["pitch_x"].append(a * math.cos(ta) - L * math.cos(ta + tau * phi))
            extra["pitch_y"].append(a * math.sin(ta) - L * math.sin(ta + tau * phi))
    expect["psi"] = (tuple(psis), 1e-8 * h)
    for name, vals in extra.items():
        if vals:
            expect[name] = (tuple(vals), 1e-8 * a)
    return ValidCase({"recipe": "cam.oscillating", "given": given}, expect, kind)


def eccentric(rng: random.Random) -> ValidCase:
    """cam.eccentric: knife, roller, flat, oscillating roller, each state."""
    k, kind = _scale(rng)
    R = round(rng.uniform(20.0, 60.0), 4) * k
    OA = round(rng.uniform(0.05, 0.9) * R, 4)
    if rng.random() < 0.1:
        OA, kind = R * (1 - 10 ** rng.uniform(-8, -4)), "near-degenerate: OA → R"
    rot = rng.choice(("ccw", "cw"))
    given: dict[str, Any] = {"R": R, "OA": OA, "rotation": rot}
    expect: dict[str, tuple[Any, float]] = {"r0_actual": (R - OA, 1e-9 * R)}
    if rng.random() < 0.25:                                      # oscillating roller
        rr = round(rng.uniform(0.0, 0.4) * R, 4)
        Rp, r0 = R + rr, R + rr - OA
        top = Rp + OA
        a = round(top * rng.uniform(1.1, 2.5), 4)
        lo, hi = max(a - r0, top - a) * 1.01, a + r0 * 0.99
        if not lo < hi:
            return eccentric(rng)
        L = round(rng.uniform(lo, hi), 4)
        if not (abs(a - L) < r0 and top < a + L):
            return eccentric(rng)
        given.update(follower="roller", rr=rr, a=a, L=L, arm=rng.choice(("left", "right")))
        if rr == 0:
            given["follower"] = "knife"
            del given["rr"]
        p0 = _psi0(a, L, r0)
        expect.update(r0=(r0, 1e-9 * R), psi0=(p0, 1e-7), psi_max=(_psi0(a, L, top) - p0, 1e-7))
        return ValidCase({"recipe": "cam.eccentric", "given": given}, expect, kind)
    follower = rng.choice(("knife", "roller", "flat"))
    given["follower"] = follower
    rr = round(rng.uniform(0.05, 0.5) * R, 4) if follower == "roller" else 0.0
    if rr:
        given["rr"] = rr
    Rp = R + rr
    r0 = Rp - OA
    e = 0.0
    if follower != "flat" and rng.random() < 0.6:
        x = rng.uniform(-0.9, 0.9) * r0
        e = round(x, 4) if abs(round(x, 4)) < 0.95 * r0 else x          # r0 → 0 when OA → R: no rounding
        given["e"] = e
    if rng.random() < 0.3:
        given["omega"] = round(rng.uniform(0.1, 100.0), 4)
    state = rng.choice((None, "delta", "A_angle", "contact_angle"))
    if state:
        given[state] = round(rng.uniform(-360.0, 360.0), 4)
    if rng.random() < 0.2:
        given["turn"] = round(rng.uniform(-180.0, 180.0), 4)
    if follower == "flat":
        expect.update(r0=(R - OA, 1e-9 * R), h=(2 * OA, 1e-9 * R), rise_angle=(180.0, 1e-9 * R / (R - OA)),
                      alpha=(0.0, 0.0))
    else:
        hi_, lo_ = math.sqrt((Rp + OA) ** 2 - e * e), math.sqrt((Rp - OA) ** 2 - e * e)
        expect.update(r0=(r0, 1e-9 * R), h=(hi_ - lo_, 1e-8 * R))
        if state == "delta" and "turn" not in given:
            sense = 1.0 if rot == "ccw" else -1.0
            phi = math.atan2(-lo_, -e) + sense * math.radians(given["delta"])
            u = e - OA * math.cos(phi)
            y = OA * math.sin(phi) + math.sqrt(Rp * Rp - u * u)
            expect["s"] = (y - lo_, 1e-8 * R)
            expect["alpha"] = (math.degrees(math.asin(min(1.0, abs(u) / Rp))), 1e-6)
    return ValidCase({"recipe": "cam.eccentric", "given": given}, expect, kind)


GENERATORS = {"cam.translating": translating, "cam.oscillating": oscillating, "cam.eccentric": eccentric}
