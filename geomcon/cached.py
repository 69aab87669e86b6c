"""``cached_property`` as Python 3.12 has it: computed on first access and stored in the instance's
``__dict__``, without the lock of Python 3.11's, which costs about 0.7 µs on every first access (a solve
reads three or four cached properties for its answers; the lock was removed in 3.12 as useless).

Examples
--------
>>> class Demo:
...     calls = 0
...     @cached_property
...     def x(self) -> int:
...         "Computed once."
...         Demo.calls += 1
...         return 42
>>> d = Demo()
>>> d.x, d.x, Demo.calls, Demo.x.__doc__
(42, 42, 1, 'Computed once.')
"""
from __future__ import annotations

import sys
from typing import Any, Callable, Generic, TypeVar

T = TypeVar("T")

if sys.version_info >= (3, 12):
    from functools import cached_property
else:
    class cached_property(Generic[T]):      # noqa: N801 - the standard library's name
        """A lock-free :func:`functools.cached_property` (a non-data descriptor: the stored value shadows it)."""

        def __init__(self, func: Callable[[Any], T]) -> None:
            self.func = func
            self.attrname: str | None = None
            self.__doc__ = func.__doc__

        def __set_name__(self, owner: type, name: str) -> None:
            self.attrname = name

        def __get__(self, instance: Any, owner: type | None = None) -> Any:
            if instance is None:
                return self
            value = instance.__dict__[self.attrname] = self.func(instance)
            return value

__all__ = ["cached_property"]
