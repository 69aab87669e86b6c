"""The standard motion laws of cam followers, normalised: f(x) for x = δ/Φ in [0, 1], with f(0) = 0, f(1) = 1.

A rise of stroke h over the cam angle Φ (radians) is s(δ) = h·f(δ/Φ), so ds/dδ = h·f′(x)/Φ and
d²s/dδ² = h·f″(x)/Φ². A return is s(δ) = h·(1 − f(δ/Φ)).

=============  ===================  =====================================  =============================
name           textbook name        f(x)                                   impact at the ends (with dwells)
=============  ===================  =====================================  =============================
uniform        等速                 x                                      rigid (velocity jumps)
parabolic      等加速等减速          2x² (x < ½), 1 − 2(1 − x)² (x ≥ ½)     soft (acceleration jumps, also at ½)
cosine         余弦加速度 (简谐)     (1 − cos πx)/2                          soft
cycloidal      正弦加速度 (摆线)     x − sin(2πx)/(2π)                       none
poly345        五次多项式 (3-4-5)    10x³ − 15x⁴ + 6x⁵                       none
=============  ===================  =====================================  =============================

At x = ½ the parabolic law's f″ jumps from +4 to −4; the value returned there is the decelerating one
(each law's pieces own the half-open interval that starts at their left end).

Examples
--------
>>> law("parabolic").f(0.25), round(law("cosine").f(0.5), 15)
(0.125, 0.5)
>>> law("等速").name, law("3-4-5").name
('uniform', 'poly345')
>>> [law(n).impact for n in LAW_NAMES]
['rigid', 'soft', 'soft', 'none', 'none']
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..errors import NotAMechanism

Fn = Callable[[np.ndarray], np.ndarray]


def _uniform(x):
    return x, np.ones_like(x), np.zeros_like(x)


def _parabolic(x):
    first = x < 0.5
    y = 1.0 - x
    f = np.where(first, 2.0 * x * x, 1.0 - 2.0 * y * y)
    d1 = np.where(first, 4.0 * x, 4.0 * y)
    d2 = np.where(first, 4.0, -4.0)
    return f, d1, d2 + 0.0 * x


def _cosine(x):
    t = math.pi * x
    return np.sin(t / 2.0) ** 2, math.pi / 2.0 * np.sin(t), math.pi ** 2 / 2.0 * np.cos(t)   # sin² = (1 − cos)/2


def _cycloidal(x):
    t = 2.0 * math.pi * x
    return x - np.sin(t) / (2.0 * math.pi), 1.0 - np.cos(t), 2.0 * math.pi * np.sin(t)


def _poly345(x):
    x2 = x * x
    return x2 * x * (10.0 - 15.0 * x + 6.0 * x2), 30.0 * x2 * (1.0 - x) ** 2, 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x)


# The same formulas for one float, with math instead of numpy (the searches evaluate one angle at a time: a
# numpy call on one number costs a hundred times the arithmetic). numpy's float64 sin and cos give math's bits,
# but a float's ** 2 is the C library's pow in Python and x·x in numpy (they differ in the last bit for about
# one argument in a thousand), so squares are written as products: both paths give the same bits.
def _uniform1(x: float) -> tuple[float, float, float]:
    return x, 1.0, 0.0


def _parabolic1(x: float) -> tuple[float, float, float]:
    if x < 0.5:
        return 2.0 * x * x, 4.0 * x, 4.0
    y = 1.0 - x
    return 1.0 - 2.0 * y * y, 4.0 * y, -4.0


def _cosine1(x: float) -> tuple[float, float, float]:
    t = math.pi * x
    h = math.sin(t / 2.0)
    return h * h, math.pi / 2.0 * math.sin(t), math.pi ** 2 / 2.0 * math.cos(t)


def _cycloidal1(x: float) -> tuple[float, float, float]:
    t = 2.0 * math.pi * x
    return x - math.sin(t) / (2.0 * math.pi), 1.0 - math.cos(t), 2.0 * math.pi * math.sin(t)


def _poly345_1(x: float) -> tuple[float, float, float]:
    x2, y = x * x, 1.0 - x
    return x2 * x * (10.0 - 15.0 * x + 6.0 * x2), 30.0 * x2 * (y * y), 60.0 * x * y * (1.0 - 2.0 * x)


@dataclass(frozen=True)
class Law:
    """One normalised motion law.

    Parameters
    ----------
    name : str
        The public name (``uniform``, ``parabolic``, ``cosine``, ``cycloidal``, ``poly345``).
    zh : str
        The textbook's name.
    impact : str
        ``"rigid"``, ``"soft"`` or ``"none"``: the shock at the ends of a rise between dwells.
    fn : callable
        ``fn(x) -> (f, f′, f″)`` on arrays.
    fn1 : callable
        The same on one float, returning floats (the scalar path; the same bits as ``fn``).
    peak1 : float
        The largest |f′| on [0, 1] (exact: 1, 2, π/2, 2, 15/8), a bound for a quick test of the speeds.
    fn3 : callable or None
        ``fn3(x) -> f‴(x)`` on one float (the jerk; where the extrema of f″ are sought,
        :mod:`geomcon.cam.kinematics`).
    cuts : tuple of float
        Fractions inside (0, 1) where f‴ (or f″) jumps: the ends of the law's smooth pieces (a piece owns the
        half-open interval that starts at its left end).
    params : tuple
        The numbers a parametrised law was made from (coefficients, a table), so that two laws made from the
        same numbers are equal.
    """

    name: str
    zh: str
    impact: str
    fn: Callable
    fn1: Callable[[float], tuple[float, float, float]]
    peak1: float = math.inf
    fn3: Callable[[float], float] | None = None
    cuts: tuple[float, ...] = ()
    params: tuple = ()

    def f(self, x: float) -> float:
        """f(x) for one x in [0, 1]."""
        return self.fn1(float(x))[0]

    def derivatives(self, x) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(f, f′, f″) at ``x`` (scalar or array), each as a float array of x's shape."""
        xa = np.asarray(x, dtype=float)
        f, d1, d2 = self.fn(xa)
        return np.asarray(f, dtype=float), np.asarray(d1, dtype=float), np.asarray(d2, dtype=float)


def _zero3(x: float) -> float:
    return 0.0


def _cosine3(x: float) -> float:
    return -math.pi ** 3 / 2.0 * math.sin(math.pi * x)


def _cycloidal3(x: float) -> float:
    return 4.0 * math.pi ** 2 * math.cos(2.0 * math.pi * x)


def _poly345_3(x: float) -> float:
    return 60.0 * (1.0 - 6.0 * x + 6.0 * x * x)


LAWS: dict[str, Law] = {l.name: l for l in (
    Law("uniform", "等速运动规律", "rigid", _uniform, _uniform1, 1.0, _zero3),
    Law("parabolic", "等加速等减速运动规律", "soft", _parabolic, _parabolic1, 2.0, _zero3, (0.5,)),
    Law("cosine", "余弦加速度(简谐)运动规律", "soft", _cosine, _cosine1, math.pi / 2.0, _cosine3),
    Law("cycloidal", "正弦加速度(摆线)运动规律", "none", _cycloidal, _cycloidal1, 2.0, _cycloidal3),
    Law("poly345", "五次多项式(3-4-5)运动规律", "none", _poly345, _poly345_1, 1.875, _poly345_3),
)}
LAW_NAMES = tuple(LAWS)

ALIASES = {
    "constant_velocity": "uniform", "linear": "uniform", "等速": "uniform",
    "constant_acceleration": "parabolic", "parabola": "parabolic", "等加速等减速": "parabolic",
    "simple_harmonic": "cosine", "harmonic": "cosine", "余弦": "cosine", "余弦加速度": "cosine", "简谐": "cosine",
    "sine": "cycloidal", "cycloid": "cycloidal", "正弦": "cycloidal", "正弦加速度": "cycloidal", "摆线": "cycloidal",
    "3-4-5": "poly345", "345": "poly345", "polynomial": "poly345", "五次多项式": "poly345",
}


def law(name: str) -> Law:
    """The law called ``name`` (or one of its aliases): one of the five standard laws or of the handbook laws
    of :mod:`geomcon.cam.custom_laws` (``double_harmonic``, ``modified_trapezoid``, ``modified_sine``); an
    unknown name raises :class:`NotAMechanism` listing the known ones. The parametrised laws (``poly``,
    ``table``) are made by :func:`geomcon.cam.custom_laws.custom_law` from their numbers.

    >>> law("modified_sine").impact, law("改进梯形").name
    ('none', 'modified_trapezoid')
    """
    from .custom_laws import HANDBOOK_ALIASES, HANDBOOK_LAWS, PARAMETRISED
    key = ALIASES.get(name, HANDBOOK_ALIASES.get(name, name))
    if key in LAWS:
        return LAWS[key]
    if key in HANDBOOK_LAWS:
        return HANDBOOK_LAWS[key]
    known = ", ".join((*LAW_NAMES, *HANDBOOK_LAWS, *PARAMETRISED))
    raise NotAMechanism(f"unknown motion law '{name}' (known: {known}; aliases: {', '.join((*ALIASES, *HANDBOOK_ALIASES))})")
