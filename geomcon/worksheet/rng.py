"""geomcon's own random numbers for worksheets: SHA-256 of a message, never Python's ``random`` nor numpy's
generators, so a variant depends on its inputs alone and is the same on every platform and version of Python
or numpy.

Each part of the message is written as its type, its length and its UTF-8 bytes, so no two different
messages meet (``("ab", "c")`` and ``("a", "bc")`` differ).

Examples
--------
>>> draw("spec", 1, "2023001", 0) == draw("spec", 1, "2023001", 0)
True
>>> draw("ab", "c") != draw("a", "bc")
True
>>> below(draw("spec", 1, "2023001", 0), 10) in range(10)
True
"""
from __future__ import annotations

import hashlib

DOMAIN = b"geomcon.worksheet/1"
"""Prefix of every message: a new version of the scheme changes it (and every variant with it)."""


def draw(*parts: str | int | None) -> int:
    """A 256-bit integer from the SHA-256 of ``parts`` (strings, integers or None)."""
    h = hashlib.sha256(DOMAIN)
    for p in parts:
        if p is None:
            tag, data = b"n", b""
        elif isinstance(p, bool) or not isinstance(p, (int, str)):
            raise TypeError(f"draw() takes strings, integers and None, got {type(p).__name__}")
        elif isinstance(p, int):
            tag, data = b"i", str(p).encode("ascii")
        else:
            tag, data = b"s", p.encode("utf-8")
        h.update(tag + len(data).to_bytes(8, "big") + data)
    return int.from_bytes(h.digest(), "big")


def below(x: int, n: int) -> int:
    """``x`` reduced to ``range(n)``; for a 256-bit ``x`` the bias is below n / 2**256, i.e. none in practice.

    >>> below(2 ** 256 - 1, 7)
    1
    """
    if n <= 0:
        raise ValueError(f"below() needs n > 0, got {n}")
    return x % n


__all__ = ["DOMAIN", "below", "draw"]
