"""A scene: the lazy construction DAG of one textbook construction.

Steps are added in drawing order and may only refer to steps added before them, so insertion order is a
topological order. Evaluation culls to the dependencies of what is asked for, walks them in that order and
computes each step once (memoised). ``stats`` tells how many steps exist and how many were computed, so
laziness is observable: asking for the answers computes no annotation, asking for frame k computes no
step after k.

Examples
--------
>>> from geomcon.geometry import Point, circle, circle_circle, LeftOf
>>> sc = Scene("demo")
>>> A = sc.given("A", Point(0, 0))
>>> D = sc.given("D", Point(8, 0))
>>> cA = sc.add("cA", circle, A, 5.0, caption=("Circle about A, r = 5", "以 A 为圆心、5 为半径作圆"))
>>> cD = sc.add("cD", circle, D, 5.0, caption=("Circle about D, r = 5", "以 D 为圆心、5 为半径作圆"))
>>> C = sc.add("C", circle_circle, cA, cD, branch=LeftOf(A, D), caption=("They meet at C", "两圆交于 C"))
>>> sc.value("C")
Point(x=4.0, y=3.0)
>>> sc.stats
{'steps_total': 5, 'steps_evaluated': 5}
>>> sc.caption("C")[0]
'They meet at C (left of the directed line A→D)'
"""
from __future__ import annotations

from typing import Any, Callable, Iterable

from ..errors import GeomconError, NoIntersection, Unbuildable
from ..geometry.branch import Branch
from ..geometry.primitives import Circle, Line, Point
from .step import Ref, Role, Step


def _resolve(x: Any, memo: dict[str, Any]) -> Any:
    if isinstance(x, Ref):
        return memo[x.key]
    if isinstance(x, tuple):
        return tuple(_resolve(y, memo) for y in x)
    if isinstance(x, list):
        return [_resolve(y, memo) for y in x]
    if isinstance(x, Branch):
        return x.with_points(tuple(_resolve(y, memo) for y in x.refs()))
    return x


def _describe(obj: Any) -> str:
    if isinstance(obj, Circle):
        return f"circle(({obj.center.x:.6g}, {obj.center.y:.6g}), r={obj.r:.6g})"
    if isinstance(obj, Line):
        return f"line through ({obj.point.x:.6g}, {obj.point.y:.6g}) dir ({obj.direction.x:.4g}, {obj.direction.y:.4g})"
    return repr(obj)


def _no_meet_message(a: Any, b: Any) -> str:
    if isinstance(a, Circle) and isinstance(b, Circle):
        d = abs(b.center - a.center)
        if d > a.r + b.r:
            why = f"distance of centres {d:.6g} > r1 + r2 = {a.r + b.r:.6g}"
        else:
            why = f"distance of centres {d:.6g} < |r1 - r2| = {abs(a.r - b.r):.6g}"
        return f"{_describe(a)} and {_describe(b)} do not meet: {why}"
    if isinstance(a, Line) and isinstance(b, Circle):
        dist = abs(a.direction.cross(b.center - a.point))
        return f"{_describe(a)} misses {_describe(b)}: distance {dist:.6g} > r = {b.r:.6g}"
    return f"{_describe(a)} and {_describe(b)} do not meet"


class Scene:
    """An ordered mapping key → :class:`Step` with lazy, memoised evaluation.

    Parameters
    ----------
    title : str
        Title of the construction (used by the drawing).
    """

    def __init__(self, title: str = "") -> None:
        self.title = title
        self._steps: dict[str, Step] = {}
        self._memo: dict[str, Any] = {}

    # ------------------------------------------------------------------ building
    def add(self, key: str, op: Callable[..., Any], *args: Any, caption: tuple[str, str] = ("", ""),
            role: Role = Role.CONSTRUCTION, style: str = "", label: str | None = None,
            branch: Branch | None = None, visible: bool = True, unit: str = "", optional: bool = False,
            **kwargs: Any) -> Ref:
        """Add a step and return a :class:`Ref` to it.

        Raises
        ------
        KeyError
            When ``key`` exists already or a reference names a step not yet added.
        """
        if key in self._steps:
            raise KeyError(f"step '{key}' defined twice")
        step = Step(key, op, tuple(args), dict(kwargs), caption, role, style, label, branch, visible, unit, optional)
        missing = [d for d in step.deps() if d not in self._steps]
        if missing:
            raise KeyError(f"step '{key}' refers to unknown step(s) {missing}")
        self._steps[key] = step
        return Ref(key)

    def given(self, key: str, value: Any, *, caption: tuple[str, str] = ("", ""), style: str = "given",
              label: str | None = None, visible: bool = True, unit: str = "") -> Ref:
        """Add a given value (a step whose operation returns ``value``)."""
        return self.add(key, _constant, value, caption=caption, role=Role.GIVEN, style=style,
                        label=label if label is not None else (key if isinstance(value, Point) else None),
                        visible=visible, unit=unit)

    # ------------------------------------------------------------------ reading
    def __contains__(self, key: str) -> bool:
        return key in self._steps

    def __len__(self) -> int:
        return len(self._steps)

    def __getitem__(self, key: str) -> Step:
        return self._steps[key]

    @property
    def steps(self) -> tuple[Step, ...]:
        """All steps in insertion (drawing) order."""
        return tuple(self._steps.values())

    def visible_steps(self) -> tuple[Step, ...]:
        """The steps that are drawn and numbered in the protocol, in order."""
        return tuple(s for s in self._steps.values() if s.visible)

    def frames(self) -> list[list[Step]]:
        """The visible steps grouped by protocol number: a step with an empty caption is drawn with the
        numbered step before it (a link drawn with its position, a ground symbol with its pivot)."""
        out: list[list[Step]] = []
        for s in self.visible_steps():
            if s.caption[0] or s.branch is not None or not out:
                out.append([s])
            else:
                out[-1].append(s)
        return out

    def number(self, key: str) -> int:
        """1-based protocol number of a visible step (the number of the frame it is drawn in)."""
        for i, group in enumerate(self.frames(), 1):
            if any(s.key == key for s in group):
                return i
        raise KeyError(f"step '{key}' is not a visible step")

    def label_of(self, x: Any) -> str:
        """The printed label of a referenced point (its step label, else its key)."""
        key = x.key if isinstance(x, Ref) else str(x)
        step = self._steps.get(key)
        return (step.label or key) if step else key

    def caption(self, key: str) -> tuple[str, str]:
        """The step's caption with its branch rule appended, in English and Chinese."""
        s = self._steps[key]
        en, zh = s.caption
        if s.branch is not None:
            ben, bzh = s.branch.describe(self.label_of)
            en = f"{en} ({ben})" if en else ben
            zh = f"{zh}({bzh})" if zh else bzh
        return en, zh

    def closure(self, keys: Iterable[str]) -> list[str]:
        """The keys needed to compute ``keys`` (themselves included), in evaluation order."""
        need: set[str] = set()
        todo = list(keys)
        while todo:
            k = todo.pop()
            if k in need:
                continue
            if k not in self._steps:
                raise KeyError(f"no step '{k}'")
            need.add(k)
            todo.extend(self._steps[k].deps())
        return [k for k in self._steps if k in need]

    # ------------------------------------------------------------------ evaluating
    def value(self, key: str) -> Any:
        """The value of one step, computing what it needs (once)."""
        return self.evaluate([key])[key]

    def evaluate(self, keys: Iterable[str]) -> dict[str, Any]:
        """Compute the requested steps and their dependencies; return ``{key: value}`` for ``keys``.

        Raises
        ------
        Unbuildable
            When a step fails; the message names the step, its caption and the numbers.
        """
        keys = list(keys)
        for k in self.closure(keys):
            if k not in self._memo:
                self._memo[k] = self._compute(self._steps[k])
        return {k: self._memo[k] for k in keys}

    def _compute(self, step: Step) -> Any:
        try:
            args = _resolve(step.args, self._memo)
            kwargs = {n: _resolve(v, self._memo) for n, v in step.kwargs.items()}
            if step.optional and _missing(step, args, kwargs):
                return None
            out = step.op(*args, **kwargs)
            if step.branch is not None:
                if not out and step.optional:
                    return None
                if not out:
                    raise NoIntersection(_no_meet_message(*args[:2]))
                out = _resolve(step.branch, self._memo).choose(out)
            return out
        except GeomconError as exc:
            raise Unbuildable(step.key, self.caption(step.key)[0], exc) from None

    def is_evaluated(self, key: str) -> bool:
        """True when the step's value has been computed already."""
        return key in self._memo

    @property
    def stats(self) -> dict[str, int]:
        """``steps_total`` (all steps) and ``steps_evaluated`` (computed so far)."""
        return {"steps_total": len(self._steps), "steps_evaluated": len(self._memo)}


def _constant(value: Any) -> Any:
    return value


def _missing(step: Step, args: tuple, kwargs: dict) -> bool:
    """True when a referenced value an optional step needs is None (a candidate that does not exist);
    a literal None argument (e.g. "default radius") does not count."""
    refs = [v for a, v in zip(step.args, args) if isinstance(a, Ref)]
    refs += [kwargs[n] for n, a in step.kwargs.items() if isinstance(a, Ref)]
    return any(v is None for v in refs)
