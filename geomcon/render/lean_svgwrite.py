"""svgwrite imported without the two modules geomcon never runs: about a sixth of the gallery's serial preload.

``import svgwrite`` also imports ``urllib.request`` (for ``urlopen``, which svgwrite calls only to embed a font
from a URL; it pulls in ``http.client``, ``email``, ``ssl`` …) and ``svgwrite.data.svgparser`` (regular
expressions for transform lists, path data and animation timing, compiled at import, which svgwrite's
validator calls only for a drawing made with ``debug=True``; geomcon's documents are all ``debug=False``).
Together they were ~40 % of svgwrite's import, 30–60 ms of the parent's serial time before the gallery's
workers are forked. :func:`import_svgwrite` imports svgwrite with stand-ins for those few names that import
the real module on their first call, and leaves ``sys.modules`` as it found it: a later ``import urllib.request``
gets the real module, and a debug drawing is validated by the real parser (the module's example). Nothing
svgwrite writes changes.

Examples
--------
>>> svgwrite = import_svgwrite()
>>> d = svgwrite.Drawing(debug=True)          # the validator calls the parser's functions: the real ones
>>> _ = d.add(d.g(transform="rotate(10)"))
>>> try:
...     d.g(transform="spin(10)")
... except TypeError:
...     print("refused")
refused
"""
from __future__ import annotations

import importlib
import sys
import types
from typing import Any, Callable

DEFERRED = {"urllib.request": ("urlopen",),
            "svgwrite.data.svgparser": ("is_valid_transferlist", "is_valid_pathdata", "is_valid_animation_timing")}
"""The modules svgwrite imports for calls geomcon never makes, and the names svgwrite takes from each."""


def _deferred(module: str, name: str) -> Callable[..., Any]:
    """``module.name`` imported on its first call."""
    def call(*args: Any, **kwargs: Any) -> Any:
        return getattr(importlib.import_module(module), name)(*args, **kwargs)
    call.__name__ = call.__qualname__ = name
    return call


def import_svgwrite() -> types.ModuleType:
    """The ``svgwrite`` module, imported (if it is not yet) with :data:`DEFERRED`'s modules left unimported
    (see the module); ``sys.modules`` holds no stand-in afterwards."""
    if "svgwrite" in sys.modules:
        return sys.modules["svgwrite"]
    stand_ins = {}
    for module, names in DEFERRED.items():
        if module not in sys.modules:
            stub = types.ModuleType(module)
            for name in names:
                setattr(stub, name, _deferred(module, name))
            stand_ins[module] = sys.modules[module] = stub
    try:
        import svgwrite
    finally:
        for module, stub in stand_ins.items():
            if sys.modules.get(module) is stub:
                del sys.modules[module]
    return svgwrite


__all__ = ["DEFERRED", "import_svgwrite"]
