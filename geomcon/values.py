"""Small frozen values written out, for the classes every ``geomcon solve`` imports.

:func:`dataclasses.dataclass` compiles each class's methods (``__init__``, ``__repr__``, ``__eq__``,
``__hash__``, ``__setattr__``, ``__delattr__``) from source when its module is imported: about 1 ms a class on
this machine, and a solve imports dozens. A class deriving from :class:`Frozen` names its fields in ``_FIELDS``
(in order) and writes its ``__init__`` (storing through :data:`store`); it is then equal, hashed, shown,
pickled and frozen as a frozen dataclass with those fields would be, though :func:`dataclasses.replace` and
:func:`dataclasses.fields` do not know it.

Examples
--------
>>> class Pair(Frozen):
...     _FIELDS = ("a", "b")
...     def __init__(self, a, b=0):
...         store(self, "a", a)
...         store(self, "b", b)
>>> p = Pair(1)
>>> p, p == Pair(1, 0), p == Pair(1, 2), hash(p) == hash((1, 0))
(Pair(a=1, b=0), True, False, True)
>>> p.a = 2
Traceback (most recent call last):
...
dataclasses.FrozenInstanceError: cannot assign to field 'a'
"""
from __future__ import annotations

from typing import Any

store = object.__setattr__
"""Set a field of a frozen value (in its ``__init__``)."""


class Frozen:
    """Base of a small frozen value whose fields are ``_FIELDS``; subclasses may add ``__slots__``."""

    __slots__ = ()
    _FIELDS: tuple[str, ...] = ()

    def _values(self) -> tuple[Any, ...]:
        """The fields' values, in order."""
        return tuple([getattr(self, name) for name in self._FIELDS])

    def __eq__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return self._values() == other._values()  # type: ignore[attr-defined]
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self._values())

    def __repr__(self) -> str:
        shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._FIELDS)
        return f"{type(self).__qualname__}({shown})"

    def __setattr__(self, name: str, value: Any) -> None:
        from dataclasses import FrozenInstanceError        # the error a frozen dataclass raises (here: seldom)
        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name: str) -> None:
        from dataclasses import FrozenInstanceError
        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __getstate__(self) -> list[Any]:
        return [getattr(self, name) for name in self._FIELDS]

    def __setstate__(self, state: list[Any]) -> None:
        for name, value in zip(self._FIELDS, state):
            store(self, name, value)
