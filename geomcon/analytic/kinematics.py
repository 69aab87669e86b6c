"""Closed-form kinematics of the basic linkages at one crank position: the vector loop in complex numbers,
differentiated exactly (the analytic twins of the velocity and acceleration polygons, issue 15).

Conventions (shared with the linkage recipes):

- angles in degrees in and out of the public functions, counter-clockwise positive; angular velocities in rad/s,
  angular accelerations in rad/s², lengths in mm, speeds in mm/s, accelerations in mm/s²;
- links numbered as the textbooks do for the polygons: 1 the crank (``omega``, ``epsilon``), 2 the coupler, 3 the
  rocker, slider or guide, 4 the frame;
- four-bar: A at the origin, D at (AD, 0); ``phi`` is the crank angle from A→D; ``branch = "above"`` puts C to the
  left of the directed line B→D (the open assembly: above the frame when B lies on AD), ``"below"`` to its right;
- crank-slider: A at the origin, the guide the line y = −e, the slider to the right of B (as in
  ``crank_slider.extremes``); ``phi`` from +x; the slider's velocity and acceleration are signed along +x;
- guide-bar: A at the origin, the guide's pivot C at (0, −AC); ``phi`` from +x; the slip of the block along the
  guide is signed along C→B and the Coriolis component along C→B turned +90°;
- slotter (the six-bar of seed 000: crank, guide bar, coupler and ram): A at the origin, the guide bar's pivot C at
  (−AC, 0), its arm CD on the far side of C from the block B, the ram E on the vertical path x = −(AC + CF), above
  D (``branch = "above"``) or below; the ram's velocity and acceleration are signed along +y, the coupler DE is
  link 4.

Examples
--------
>>> r = four_bar(AB=50, BC=70, CD=80, AD=90, phi=60, omega=10)
>>> round(r["omega2"], 9), round(r["omega3"], 9)
(-4.484900843, 3.372439984)
>>> s = crank_slider(AB=100, BC=300, e=0, phi=90, omega=1)
>>> round(s["vC"], 9), abs(s["omega2"]) < 1e-15
(-100.0, True)
>>> round(guide_bar(AB=100, AC=200, phi=90, omega=1)["v_slip"], 12)
0.0
"""
from __future__ import annotations

import cmath
import math
from typing import Literal

from ..errors import NotAMechanism
from .linkages import _tri_angle

Branch = Literal["above", "below"]


def _unit(deg: float) -> complex:
    return cmath.exp(1j * math.radians(deg))


def _pair(b: float, t2: complex, c: float, t3: complex, rhs: complex) -> tuple[float, float]:
    """Real x, y with ``b·x·t2 − c·y·t3 = rhs`` (t2, t3 unit vectors): the polygon closing on two known directions.

    >>> x, y = _pair(1.0, 1.0, 1.0, 1j, 2 - 3j)
    >>> round(x, 12), round(y, 12)
    (2.0, 3.0)
    """
    s = (t2 * t3.conjugate()).imag                   # sin(θ2 − θ3)
    if s == 0.0:
        raise NotAMechanism("the coupler and the rocker are collinear: a dead point, the velocities are not determined")
    x = (rhs * t3.conjugate()).imag / (b * s)
    y = (rhs * t2.conjugate()).imag / (c * s)
    return x, y


def four_bar(AB: float, BC: float, CD: float, AD: float, phi: float, omega: float, epsilon: float = 0.0,
             branch: Branch = "above", BE: float | None = None, angle_CBE: float = 0.0) -> dict[str, float]:
    """Velocities and accelerations of a four-bar at the crank angle ``phi``.

    ``BE`` and ``angle_CBE`` place a coupler point E: BE long, at ``angle_CBE`` counter-clockwise from B→C.

    Returns
    -------
    dict
        ``theta2``, ``theta3`` (deg: the coupler B→C and the rocker D→C), ``omega2``, ``omega3``, ``epsilon2``,
        ``epsilon3``, ``vC``, ``aC`` (magnitudes) and ``vCx``… components, with ``vE``, ``aE``… when E is given.

    Examples
    --------
    >>> r = four_bar(AB=50, BC=70, CD=80, AD=90, phi=0, omega=10)
    >>> abs(abs(r["omega3"]) * 80 - r["vC"]) < 1e-12
    True
    """
    B = AB * _unit(phi)
    z = AD - B
    d = abs(z)
    if not (abs(BC - CD) <= d <= BC + CD) or d == 0.0:
        raise NotAMechanism(f"at phi = {phi:g}° the dyad BCD does not close: BD = {d:.6g} outside "
                            f"[|BC − CD|, BC + CD] = [{abs(BC - CD):.6g}, {BC + CD:.6g}]")
    sign = 1.0 if branch == "above" else -1.0
    t2 = z / d * _unit(sign * _tri_angle(BC, d, CD))      # the coupler's direction B→C
    C = B + BC * t2
    t3 = (C - AD) / CD                                    # the rocker's direction D→C
    t1 = _unit(phi)
    vB = 1j * AB * omega * t1
    # vB + i·ω2·BC·t2 = i·ω3·CD·t3  ⇔  BC·ω2·t2 − CD·ω3·t3 = −vB / i
    w2, w3 = _pair(BC, t2, CD, t3, -vB / 1j)
    aB = AB * (1j * epsilon - omega * omega) * t1
    # aB + (i·ε2 − ω2²)·BC·t2 = (i·ε3 − ω3²)·CD·t3
    rest = aB - w2 * w2 * BC * t2 + w3 * w3 * CD * t3
    e2, e3 = _pair(BC, t2, CD, t3, -rest / 1j)
    vC = 1j * w3 * CD * t3
    aC = (1j * e3 - w3 * w3) * CD * t3
    out = {"theta2": math.degrees(cmath.phase(t2)), "theta3": math.degrees(cmath.phase(t3)),
           "omega2": w2, "omega3": w3, "epsilon2": e2, "epsilon3": e3,
           "vC": abs(vC), "aC": abs(aC), "vCx": vC.real, "vCy": vC.imag, "aCx": aC.real, "aCy": aC.imag,
           "vB": abs(vB), "aB": abs(aB), "Cx": C.real, "Cy": C.imag}
    if BE is not None:
        r = BE * t2 * _unit(angle_CBE)
        vE = vB + 1j * w2 * r
        aE = aB + (1j * e2 - w2 * w2) * r
        E = B + r
        out.update(vE=abs(vE), aE=abs(aE), vEx=vE.real, vEy=vE.imag, aEx=aE.real, aEy=aE.imag, Ex=E.real, Ey=E.imag)
    return out


def crank_slider(AB: float, BC: float, e: float, phi: float, omega: float, epsilon: float = 0.0) -> dict[str, float]:
    """Velocities and accelerations of the offset crank-slider at ``phi`` (slider to the right of B, guide y = −e).

    Examples
    --------
    >>> r = crank_slider(AB=120, BC=250, e=60, phi=30, omega=2)
    >>> round(r["vC"], 6), round(r["aC"], 6)
    (-233.723595, -540.320202)
    """
    t1 = _unit(phi)
    B = AB * t1
    h = B.imag + e                                        # height of B over the guide
    if abs(h) > BC:
        raise NotAMechanism(f"at phi = {phi:g}° B is {abs(h):.6g} from the guide, more than BC = {BC:g}")
    dx = math.sqrt((BC - h) * (BC + h))                   # C to the right of B
    t2 = complex(dx, -h) / BC                             # the coupler's direction B→C
    vB = 1j * AB * omega * t1
    # vB + i·ω2·BC·t2 = vC (real): the imaginary part fixes ω2
    if t2.real == 0.0:
        raise NotAMechanism("the coupler is perpendicular to the guide: a dead point")
    w2 = -vB.imag / (BC * t2.real)
    vC = vB.real - w2 * BC * t2.imag
    aB = AB * (1j * epsilon - omega * omega) * t1
    rest = aB - w2 * w2 * BC * t2                         # aB − ω2²·BC·t2 + i·ε2·BC·t2 = aC (real)
    e2 = -rest.imag / (BC * t2.real)
    aC = rest.real - e2 * BC * t2.imag
    return {"theta2": math.degrees(cmath.phase(t2)), "omega2": w2, "epsilon2": e2, "vC": vC, "aC": aC,
            "xC": B.real + dx}


def guide_bar(AB: float, AC: float, phi: float, omega: float, epsilon: float = 0.0) -> dict[str, float]:
    """The oscillating guide-bar (block at B slides on the guide through C) at ``phi``.

    Examples
    --------
    >>> r = guide_bar(AB=100, AC=200, phi=0, omega=1)
    >>> round(r["omega3"], 12), round(r["v_slip"], 7)
    (0.2, 89.4427191)
    """
    t1 = _unit(phi)
    r = AB * t1 + 1j * AC                                 # C→B
    s = abs(r)
    if s == 0.0:
        raise NotAMechanism("B coincides with C: the guide's direction is undefined")
    t3 = r / s
    q = t1 * t3.conjugate()                               # e^{i(φ − θ3)}
    v = 1j * AB * omega * q                               # vB in the guide's frame: slip + i·s·ω3
    slip, w3 = v.real, v.imag / s
    a = AB * (1j * epsilon - omega * omega) * q           # aB in the guide's frame
    a_slip = a.real + s * w3 * w3
    cor = 2.0 * w3 * slip
    e3 = (a.imag - cor) / s
    return {"theta3": math.degrees(cmath.phase(t3)), "omega3": w3, "epsilon3": e3, "v_slip": slip,
            "a_slip": a_slip, "a_coriolis": cor, "CB": s}


def slotter(AB: float, AC: float, CD: float, DE: float, CF: float, phi: float, omega: float, epsilon: float = 0.0,
            branch: Branch = "above") -> dict[str, float]:
    """The slotter's six-bar (crank AB, guide bar through the block B turning about C, arm CD, coupler DE, ram E on
    the vertical path x = −(AC + CF)) at ``phi``: the loop A→B = A→C + C→B in the guide's frame, then the ram's
    loop C→D→E, both differentiated exactly.

    Returns
    -------
    dict
        ``omega3``, ``epsilon3`` (the guide bar), ``v_slip``, ``a_slip``, ``a_coriolis`` (the block B2 relative to
        the guide, as :func:`guide_bar`), ``vB3`` (speed of the guide's point at B), ``vD``, ``aD`` (magnitudes),
        ``omega4``, ``epsilon4`` (the coupler DE), ``vE``, ``aE`` (the ram, signed along +y), ``yE``, and D's
        components ``vDx``, ``vDy``, ``aDx``, ``aDy``.

    Examples
    --------
    >>> r = slotter(AB=70, AC=161, CD=115, DE=46, CF=115.4, phi=180, omega=4.8147)
    >>> round(r["omega3"], 9), round(r["vE"], 6), abs(r["v_slip"]) < 1e-12
    (-3.703615385, 425.915769, True)
    """
    t1 = _unit(phi)
    r = AB * t1 + AC                                      # C→B, C at −AC
    s = abs(r)
    if s <= 1e-12 * (AB + AC):
        raise NotAMechanism("B coincides with C: the guide's direction is undefined")
    u = r / s
    q = t1 * u.conjugate()                                # the crank's direction in the guide's frame
    vB = 1j * AB * omega * q                              # = slip + i·s·ω3
    slip, w3 = vB.real, vB.imag / s
    aB = AB * (1j * epsilon - omega * omega) * q          # = (a_slip − s·ω3²) + i·(s·ε3 + 2·ω3·slip)
    a_slip = aB.real + s * w3 * w3
    cor = 2.0 * w3 * slip
    e3 = (aB.imag - cor) / s
    D = -AC - CD * u                                      # the arm's end, beyond C
    rD = D + AC
    vD = 1j * w3 * rD
    aD = (1j * e3 - w3 * w3) * rD
    h = -(AC + CF) - D.real                               # from D across to the path
    if abs(h) >= DE:
        raise NotAMechanism(f"at phi = {phi:g}° D is {abs(h):.6g} from the ram's path, not less than DE = {DE:g}"
                            + (" (the coupler perpendicular to the path: a dead point)" if abs(h) == DE else ""))
    dy = math.sqrt((DE - h) * (DE + h)) * (1.0 if branch == "above" else -1.0)
    t4 = complex(h, dy) / DE                              # the coupler's direction D→E
    # vD + i·ω4·DE·t4 is vertical: its real part is 0
    w4 = vD.real / (DE * t4.imag)
    vE = vD.imag + w4 * DE * t4.real
    rest = aD - w4 * w4 * DE * t4                         # + i·ε4·DE·t4, vertical
    e4 = rest.real / (DE * t4.imag)
    aE = rest.imag + e4 * DE * t4.real
    return {"theta3": math.degrees(cmath.phase(u)), "omega3": w3, "epsilon3": e3, "v_slip": slip, "a_slip": a_slip,
            "a_coriolis": cor, "CB": s, "vB3": abs(w3) * s, "vD": abs(vD), "aD": abs(aD),
            "theta4": math.degrees(cmath.phase(t4)), "omega4": w4, "epsilon4": e4, "vE": vE, "aE": aE,
            "yE": D.imag + dy, "vDx": vD.real, "vDy": vD.imag, "aDx": aD.real, "aDy": aD.imag}


def four_bar_instant_centres(AB: float, BC: float, CD: float, AD: float, phi: float,
                             branch: Branch = "above") -> dict[str, complex | None]:
    """The six instant centres of a four-bar (1 crank, 2 coupler, 3 rocker, 4 frame) and ω3/ω1, ω2/ω1.

    P13 (crank–rocker) is where BC meets AD; P24 (coupler–frame) where AB meets CD (Kennedy's theorem); a centre at
    infinity (parallel lines) is None.

    Examples
    --------
    >>> ic = four_bar_instant_centres(50, 70, 80, 90, 60)
    >>> r = four_bar(50, 70, 80, 90, 60, 1.0)
    >>> abs(ic["w3_w1"] - r["omega3"]) < 1e-12, abs(ic["w2_w1"] - r["omega2"]) < 1e-12
    (True, True)
    """
    B = AB * _unit(phi)
    at = four_bar(AB, BC, CD, AD, phi, 0.0, branch=branch)
    C = complex(at["Cx"], at["Cy"])
    A, D = 0j, complex(AD, 0.0)

    def meet(p: complex, q: complex, r: complex, s: complex) -> complex | None:
        u, w = q - p, s - r
        den = (u.conjugate() * w).imag
        if den == 0.0:
            return None
        t = ((r - p).conjugate() * w).imag / den
        return p + t * u

    P13 = meet(B, C, A, D)
    P24 = meet(A, B, D, C)
    out: dict[str, complex | None] = {"P14": A, "P12": B, "P23": C, "P34": D, "P13": P13, "P24": P24}
    # ω3/ω1 = P14P13 / P34P13 (signed along AD); at infinity (BC ∥ AD) the rocker turns as the crank does
    out["w3_w1"] = (P13 - A).real / (P13 - D).real if P13 is not None else 1.0
    # ω2/ω1 = P14P12 / P24P12 along AB (the coupler turns about P24)
    out["w2_w1"] = ((B - A) / (B - P24)).real if P24 is not None else 0.0
    return out


__all__ = ["crank_slider", "four_bar", "four_bar_instant_centres", "guide_bar", "slotter"]
