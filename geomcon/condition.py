"""The problem's own condition: how far an exact answer moves when the givens move.

A construction and its twin are compared to ``CHECK_REL`` (1e-9) of the answer's scale. That is fair when the
answer is well conditioned; when the data are nearly degenerate (a folded position flat to 1e-9, three nearly
collinear points) even an exact method's answer moves by far more than 1e-9 when a given moves by one rounding
step, and a disagreement at 1e-9 says nothing about either route. For such a check the solver measures the
condition from the twin and judges the row again at

    tol = CHECK_REL × max(scale, Σ_i |∂a/∂g_i| · u_i),

where ``u_i`` is the size of given ``i`` (a length or ratio: its magnitude; a point coordinate: the problem's
length scale; an angle: one radian, whatever turn it is written in), and the partial derivatives are central differences of the twin at relative
steps of :data:`STEP`. For a well-conditioned answer the sum is about ``|a|`` and nothing changes; when it is
κ times larger the answer is allowed κ times the error, exactly as forward error ≤ condition × backward error.
An answer whose condition exceeds :data:`KAPPA_REFUSE` is not worth checking: the problem is refused with the
number.

The condition is measured only for rows that fail the plain check, so a well-posed problem pays nothing.

Examples
--------
>>> def twin(g):                      # a = x² − y², ill-conditioned where x ≈ y
...     return [{"a": g["x"] ** 2 - g["y"] ** 2}]
>>> s = sensitivities(twin, {"x": 1.0, "y": 1.0 - 1e-9}, {"x": "", "y": ""}, 1.0)
>>> round(s[0]["a"], 6)               # |2x|·|x| + |2y|·|y| ≈ 4 while a itself is 2e-9
4.0
"""
from __future__ import annotations

import math
from typing import Any, Callable, Mapping, Sequence

from .errors import GeomconError

STEPS = (1e-6, 1e-9, 1e-12)
"""Relative steps of the differences, tried in turn where a side leaves the domain (truncation O(h²),
rounding O(ε/h) ≤ 2e-4 of the derivative even at the smallest)."""

STEP = STEPS[0]

KAPPA_REFUSE = 1e7
"""An answer more than this many times as sensitive as its own size (relative condition) is refused: the
data determine it to worse than CHECK_REL × 1e7 = 1 %."""

DEGREE_SIZE = 180.0 / math.pi
"""The size of every angle given: one radian (−295° and 65° are the same direction, equally well known)."""

Twin = Callable[[Mapping[str, Any]], Sequence[Mapping[str, Any]]]


def _magnitude(unit: str, value: float, length_scale: float) -> float:
    """The size ``u`` of one given number: what a relative perturbation is taken of."""
    if unit == "point":
        return length_scale
    if unit.removesuffix("[]") == "deg":
        return DEGREE_SIZE
    return abs(value)


def _variations(given: Mapping[str, Any], units: Mapping[str, str], length_scale: float):
    """Yield ``(u, moved)`` for every number in the givens: its size and ``moved(d)``, the givens with that
    number moved by ``d`` (numbers of size 0 are exact and skipped)."""
    for name, unit in units.items():
        value = given.get(name)
        if value is None or unit in ("bool", "choice", "table[]") or isinstance(value, (bool, str)):
            continue
        if isinstance(value, (tuple, list)):
            for i, x in enumerate(value):
                u = _magnitude(unit, float(x), length_scale)
                if u > 0:
                    yield u, (lambda d, name=name, i=i, value=value:
                              {**given, name: tuple(v + d if j == i else v for j, v in enumerate(value))})
        else:
            u = _magnitude(unit, float(value), length_scale)
            if u > 0:
                yield u, (lambda d, name=name, value=value: {**given, name: value + d})


def derivative(f: Callable[[float], float | None], u: float) -> float | None:
    """``|f′(0)|·u`` by central differences at the first of the relative steps :data:`STEPS` at which both
    sides evaluate (near the edge of the domain a smaller step stays inside), else one-sided at the largest
    step with one side; None when nothing evaluates.

    Examples
    --------
    >>> derivative(lambda d: 3.0 * d, 2.0)
    6.0
    >>> round(derivative(lambda d: (1e-7 - d) ** 0.5 if d < 1e-7 else None, 1.0))   # the 1e-6 step leaves it
    1581
    """
    def g(d: float) -> float | None:
        v = f(d)
        return v if v is not None and math.isfinite(v) else None      # a NaN or inf is outside the domain too

    one_sided: tuple[float, float] | None = None
    for h in STEPS:
        p, m = g(h * u), g(-h * u)
        if p is not None and m is not None:
            return abs(p - m) / (2 * h)
        if one_sided is None and (p is not None or m is not None):
            one_sided = (h, p if p is not None else m)
    if one_sided is None:
        return None
    f0 = g(0.0)
    return None if f0 is None else abs(one_sided[1] - f0) / one_sided[0]


def _scalars(sol: Mapping[str, Any]) -> dict[str, float]:
    """A solution's numeric answers flattened: ``{"theta": …, "s[0]": …}`` (bools as 0/1)."""
    out: dict[str, float] = {}
    for k, v in sol.items():
        if isinstance(v, (tuple, list)):
            out.update({f"{k}[{i}]": float(x) for i, x in enumerate(v)})
        else:
            out[k] = float(v)
    return out


def _safe(twin: Twin, given: Mapping[str, Any]) -> list[dict[str, float]] | None:
    try:
        return [_scalars(s) for s in twin(given)]
    except (GeomconError, ArithmeticError):
        return None


def _nearest(target: Mapping[str, float], candidates: Sequence[Mapping[str, float]]) -> Mapping[str, float]:
    """The candidate solution closest to ``target`` (solutions may come in another order once perturbed)."""
    def cost(c: Mapping[str, float]) -> float:
        return max((abs(c[k] - v) / max(abs(v), 1e-300) for k, v in target.items()
                    if k in c and type(v) is not str), default=0.0)
    return min(candidates, key=cost)


def sensitivities(twin: Twin, given: Mapping[str, Any], units: Mapping[str, str],
                  length_scale: float, yes_no: frozenset[str] = frozenset()) -> list[dict[str, float]]:
    """``Σ_i |∂a/∂g_i| · u_i`` for every scalar answer ``a`` (list answers element by element, ``"s[0]"``) of
    every twin solution, from central differences (one-sided where one side leaves the domain).

    Parameters
    ----------
    twin : callable
        ``twin(given) -> [solution, …]``, each solution ``{answer: value}``.
    given : mapping
        The normalised givens.
    units : mapping
        Unit of each given (``"mm"``, ``"deg"``, ``""``, ``"point"``, ``"mm[]"`` …).
    length_scale : float
        The problem's length scale (size of point coordinates).
    yes_no : frozenset of str
        Names of the yes/no answers: one that flips within the step gets ``inf`` (undecidable at the data's
        precision), one that does not flip gets 0.

    Returns
    -------
    list of dict
        One dict per twin solution (a given whose both variations leave the domain contributes nothing).
    """
    base = _safe(twin, given) or []
    sums = [dict.fromkeys(s, 0.0) for s in base]
    for u, moved in _variations(given, units, length_scale):
        cache: dict[float, list[dict[str, float]] | None] = {0.0: base}

        def at(d: float) -> list[dict[str, float]] | None:
            if d not in cache:
                cache[d] = _safe(twin, moved(d))
            return cache[d]

        for i, b in enumerate(base):
            for k in b:
                if type(b[k]) is str:                    # a word (a choice) has no derivative
                    continue

                def f(d: float, b=b, k=k) -> float | None:
                    sols = at(d)
                    if not sols:
                        return None
                    near = _nearest(b, sols)
                    return near.get(k)
                dk = derivative(f, u)
                if dk is None:
                    continue
                if k in yes_no and dk > 0:
                    sums[i][k] = math.inf          # a yes/no that flips within the step: undecidable here
                else:
                    sums[i][k] += dk
    return sums


def solution_count_stable(twin: Twin, given: Mapping[str, Any], units: Mapping[str, str],
                          length_scale: float) -> bool:
    """True when the twin finds the same number of solutions for every variation of the givens (a count that
    changes within the step means a candidate lies on the boundary of validity)."""
    base = _safe(twin, given)
    n = len(base) if base is not None else -1
    for u, moved in _variations(given, units, length_scale):
        for d in (STEP * u, -STEP * u):
            h = _safe(twin, moved(d))
            if h is not None and len(h) != n:
                return False
    return True
