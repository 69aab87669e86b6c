"""A construction step: one operation with explicit references to earlier steps.

Examples
--------
>>> from geomcon.geometry import midpoint
>>> s = Step("M", midpoint, (Ref("A"), Ref("B")), caption=("Bisect AB at M", "取 AB 中点 M"))
>>> sorted(s.deps())
['A', 'B']
"""
from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Any, Callable, Mapping

from ..geometry.branch import Branch


@dataclass(frozen=True, slots=True)
class Ref:
    """A reference to the value of another step of the same scene (never a bare string)."""

    key: str


class Role(str, Enum):
    """What a step is for, in the textbook's sense."""

    GIVEN = "given"                 # data of the problem (fixed pivots, frame line...)
    CONSTRUCTION = "construction"   # thin, light auxiliary lines and circles
    RESULT = "result"               # the mechanism found, drawn bold
    MEASUREMENT = "measurement"     # a number read off the drawing (an answer or a checked quantity)
    ANNOTATION = "annotation"       # angle arcs, dimensions, symbols: drawing only


def _collect(x: Any, out: list[str]) -> None:
    if isinstance(x, Ref):
        out.append(x.key)
    elif isinstance(x, (tuple, list)):
        for y in x:
            _collect(y, out)
    elif isinstance(x, Branch):
        _collect(x.refs(), out)


@dataclass(frozen=True, slots=True)
class Step:
    """One step of a scene.

    Parameters
    ----------
    key : str
        Stable key, unique in the scene; also the SVG group id (``step-<key>``).
    op : callable
        The operation; called with the resolved ``args`` and ``kwargs``.
    args : tuple
        Positional arguments; :class:`Ref` anywhere inside (also in tuples) is replaced by its value.
    kwargs : mapping
        Keyword arguments, resolved the same way.
    caption : (str, str)
        The sentence a textbook prints for this step, in English and Chinese.
    role : Role
        Given, construction, result, measurement or annotation.
    style : str
        Drawing style name (see :mod:`geomcon.render.style`).
    label : str or None
        The point's label as printed ("C1", "B2'"); None for no label.
    branch : Branch or None
        The named rule choosing one point of a two-point intersection.
    visible : bool
        False for helper values (a radius, an intermediate number) that are neither drawn nor numbered.
    unit : str
        "mm", "deg" or "" for measurements.
    optional : bool
        A candidate of a multi-solution construction: an empty intersection gives ``None`` instead of an
        error, and so does any step whose arguments include ``None``.
    """

    key: str
    op: Callable[..., Any]
    args: tuple[Any, ...] = ()
    kwargs: Mapping[str, Any] = field(default_factory=dict)
    caption: tuple[str, str] = ("", "")
    role: Role = Role.CONSTRUCTION
    style: str = ""
    label: str | None = None
    branch: Branch | None = None
    visible: bool = True
    unit: str = ""
    optional: bool = False

    def deps(self) -> tuple[str, ...]:
        """Keys of the steps this step refers to, in order of appearance, without repeats."""
        out: list[str] = []
        _collect(self.args, out)
        _collect(tuple(self.kwargs.values()), out)
        if self.branch is not None:
            _collect(self.branch, out)
        return tuple(dict.fromkeys(out))
