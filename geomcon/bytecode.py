"""A byte-code cache outside the checkout for a command that imports most of geomcon.

A shell with ``PYTHONDONTWRITEBYTECODE`` (some tools and this project's VM set it) makes Python compile every
module it imports on every start: ``geomcon gallery`` then spends about 0.4 s compiling geomcon's modules in
the parent before its workers are forked, and the worker that runs the graded example compiles the worksheet
and grading modules again. :func:`bytecode_cached` lets such a command write and read its byte-code under the
user's cache folder (Python's own ``sys.pycache_prefix`` mechanism: the cache mirrors each source's absolute
path), so the checkout stays exactly as it was — no ``__pycache__`` is written into the tree — and the next
run reads the compiled modules instead of compiling them. A cache that cannot be written is skipped by Python
silently (the command then compiles, as before). When Python writes byte-code anyway (no
``PYTHONDONTWRITEBYTECODE``), or ``PYTHONPYCACHEPREFIX`` names a cache, nothing is changed but the permission
to write there.

Examples
--------
>>> import sys
>>> before = (sys.pycache_prefix, sys.dont_write_bytecode)
>>> with bytecode_cached(Path("/tmp/geomcon-doctest-cache")):
...     sys.dont_write_bytecode
False
>>> (sys.pycache_prefix, sys.dont_write_bytecode) == before
True
"""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator


def cache_folder() -> Path:
    """Where :func:`bytecode_cached` keeps byte-code by default: ``$XDG_CACHE_HOME/geomcon/pycache`` (or
    ``~/.cache/geomcon/pycache``), never inside a checkout.

    >>> cache_folder().parts[-2:]
    ('geomcon', 'pycache')
    """
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "geomcon" / "pycache"


@contextmanager
def bytecode_cached(folder: Path | None = None) -> Iterator[None]:
    """While the block runs (and in processes forked in it), imported modules' byte-code is read from and
    written to ``folder`` (default :func:`cache_folder`) when Python was told not to write it beside the
    sources; both settings are restored afterwards. See the module."""
    prefix, dont = sys.pycache_prefix, sys.dont_write_bytecode
    if dont:
        if prefix is None:
            sys.pycache_prefix = str(folder or cache_folder())
        sys.dont_write_bytecode = False
    try:
        yield
    finally:
        sys.pycache_prefix, sys.dont_write_bytecode = prefix, dont


__all__ = ["bytecode_cached", "cache_folder"]
