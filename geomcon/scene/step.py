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


class Ref(tuple):
    """A reference to the value of another step of the same scene (never a bare string).

    An immutable one-field record (a tuple underneath, so that making one costs a tenth of a frozen
    dataclass: every step added returns one). It is never taken apart as a tuple: scenes test
    ``type(x) is Ref`` before looking inside containers.

    Examples
    --------
    >>> r = Ref("C1")
    >>> r.key, r, r == Ref("C1")
    ('C1', Ref(key='C1'), True)
    """

    __slots__ = ()

    def __new__(cls, key: str) -> Ref:
        return tuple.__new__(cls, (key,))

    @property
    def key(self) -> str:
        """The referenced step's key."""
        return self[0]

    def __repr__(self) -> str:
        return f"Ref(key={self[0]!r})"

    def __getnewargs__(self) -> tuple[str]:
        return (self[0],)


class Role(str, Enum):
    """What a step is for, in the textbook's sense."""

    GIVEN = "given"                 # data of the problem (fixed pivots, frame line...)
    CONSTRUCTION = "construction"   # thin, light auxiliary lines and circles
    RESULT = "result"               # the mechanism found, drawn bold
    MEASUREMENT = "measurement"     # a number read off the drawing (an answer or a checked quantity)
    ANNOTATION = "annotation"       # angle arcs, dimensions, symbols: drawing only


def collect_refs(x: Any, out: list[str]) -> None:
    """Append the keys of every :class:`Ref` inside ``x`` (tuples, lists and branch rules included) to ``out``.

    Examples
    --------
    >>> out = []
    >>> collect_refs((Ref("A"), 2.0, [Ref("B"), (Ref("C"),)]), out)
    >>> out
    ['A', 'B', 'C']
    """
    t = type(x)
    if t is Ref:
        out.append(x[0])
    elif t is tuple or t is list:
        for y in x:
            collect_refs(y, out)
    elif isinstance(x, Branch):
        collect_refs(x.refs(), out)


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
        collect_refs(self.args, out)
        collect_refs(tuple(self.kwargs.values()), out)
        if self.branch is not None:
            collect_refs(self.branch, out)
        return tuple(dict.fromkeys(out))


def constant(value: Any) -> Any:
    """The operation of a given step (:meth:`~geomcon.scene.Scene.given`): its value."""
    return value
