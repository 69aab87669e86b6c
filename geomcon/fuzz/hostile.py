"""Hostile mutations of a problem file: what a careless or malicious file can hold.

Each mutation takes the parsed problem (a dict) and its text and returns ``(label, file bytes)``. They cover
the signatures of issue 9's fuzz: values too big or too deep for TOML, numbers out of every range, wrong
shapes, unknown names with control characters, broken ``[published]``, huge lists and programs, control
characters in texts, byte-level damage (truncation, NUL, invalid UTF-8, a byte-order mark).

Examples
--------
>>> import random
>>> data = {"recipe": "guide_bar.extremes", "given": {"AB": 50, "AC": 100}}
>>> label, raw = mutate(data, random.Random(1))
>>> isinstance(label, str) and isinstance(raw, bytes)
True
"""
from __future__ import annotations

import copy
import random
from typing import Any, Callable

from .toml_text import dumps

NUMBERS: tuple[Any, ...] = (
    0, -1, -1e-300, 1e-15, 1e-9, 1e-7, 1e-6, 0.5, 1, 89.999999999, 90, 179.9999, 180, 360, 1e6, 1e9, 1.0000001e9,
    1e12, 1e13, 4e13, 1e300, -1e300, 1.8e308, 9223372036854775807, 2 ** 1030, float("nan"), float("inf"),
    float("-inf"), 5e-324,
)
"""Replacement numbers: zeros, signs, limits of every range, subnormals, huge integers, nan and inf."""

ODD_VALUES: tuple[Any, ...] = ("12", "", "a\nb", True, [], [1, 2, 3], {"x": 1}, [[1, 2], [3, 4]], [float("nan")] * 3)
"""Replacement values of the wrong type or shape."""


def _given(data: dict) -> dict:
    g = data.get("given")
    if not isinstance(g, dict):
        g = data["given"] = {}
    return g


def _pick(rng: random.Random, d: dict) -> str | None:
    return rng.choice(sorted(d)) if d else None


def m_number(data: dict, rng: random.Random) -> str:
    """One given replaced by an extreme number."""
    g = _given(data)
    k = _pick(rng, g) or "AB"
    v = rng.choice(NUMBERS)
    if isinstance(g.get(k), list) and g[k] and rng.random() < 0.5:
        g[k] = list(g[k])
        i = rng.randrange(len(g[k]))
        g[k][i] = v if not isinstance(g[k][i], dict) else {**g[k][i], "angle": v}
        return f"given {k}[{i}] = {v!r}"[:80]
    g[k] = v
    return f"given {k} = {v!r}"[:80]


def m_scale(data: dict, rng: random.Random) -> str:
    """Every number of the givens multiplied by one factor (a whole problem at another scale)."""
    f = rng.choice((1e-9, 1e-6, 1e-3, 1e3, 1e6, 1e9, 1e12, -1.0))

    def scaled(v: Any) -> Any:
        if isinstance(v, bool) or isinstance(v, str):
            return v
        if isinstance(v, (int, float)):
            try:
                return v * f
            except OverflowError:           # an integer beyond any float stays as it is
                return v
        if isinstance(v, list):
            return [scaled(x) for x in v]
        if isinstance(v, dict):
            return {k: (scaled(x) if k not in ("kind", "law", "angle") else x) for k, x in v.items()}
        return v

    data["given"] = {k: scaled(v) for k, v in _given(data).items()}
    return f"givens × {f:g}"


def m_odd(data: dict, rng: random.Random) -> str:
    """One given replaced by a value of the wrong type or shape."""
    g = _given(data)
    k = _pick(rng, g) or "AB"
    g[k] = rng.choice(ODD_VALUES)
    return f"given {k} = {g[k]!r}"[:80]


def m_remove(data: dict, rng: random.Random) -> str:
    """A given or a top-level key removed."""
    if rng.random() < 0.7 and _given(data):
        k = _pick(rng, _given(data))
        del data["given"][k]
        return f"given {k} removed"
    k = rng.choice(["recipe", "given"])
    data.pop(k, None)
    return f"{k} removed"


def m_names(data: dict, rng: random.Random) -> str:
    """Unknown names, with control characters: a key, a recipe, a law."""
    bad = rng.choice(["zz", "a\nb", "a\u0001b", "\u2028x", "é" * 300, "AB\r", "../../etc", ""])
    what = rng.randrange(3)
    if what == 0:
        _given(data)[bad] = 1
        return f"unknown given {bad!r}"[:80]
    if what == 1:
        data["recipe"] = rng.choice([bad, "crank_rocker.extremes\n", 12, ["guide_bar.extremes"], "guide_bar"])
        return f"recipe = {data['recipe']!r}"[:80]
    data[bad] = "x"
    return f"unknown top key {bad!r}"[:80]


def m_published(data: dict, rng: random.Random) -> str:
    """Broken ``[published]``: unknown answers, wrong shapes, extreme numbers."""
    pub = data.setdefault("published", {})
    if not isinstance(pub, dict):
        pub = data["published"] = {}
    k = rng.choice(sorted(pub) + ["theta", "psi0", "s", "undercut", "r0", "zz", "a\nb", "alpha"])
    pub[k] = rng.choice([12.5, [1.0, 2.0], [1.0] * 2000, True, "x", 1e308, 5e-324, 0, float("nan"), 2 ** 1030,
                         {"a": 1}, []])
    return f"published {k} = {pub[k]!r}"[:80]


def m_texts(data: dict, rng: random.Random) -> str:
    """Control characters, huge or non-string titles and notes."""
    k = rng.choice(["title", "notes", "source", "statement"])
    data[k] = rng.choice(["a\u0001b", "a\u0000b", "x" * 30000, "<svg>&amp;</svg>]]>", "\ud7ff\ue000 ok", 12,
                          ["t"], "\x1b[31mred", "\ufffe"])
    return f"{k} = {str(data[k])[:30]!r}"


def m_sizes(data: dict, rng: random.Random) -> str:
    """Lists and programs too long, nesting too deep."""
    g = _given(data)
    what = rng.randrange(4)
    if what == 0:
        n = rng.choice((999, 1000, 1001, 100000))
        g["at"] = [i * 360.0 / n for i in range(n)]
        return f"at with {n} angles"
    if what == 1:
        n = rng.choice((64, 65, 100, 101, 1000))
        g["program"] = [{"kind": "rise", "angle": 1.0, "law": "cycloidal"}] + [
            {"kind": "dwell", "angle": 358.0 / (n - 2)}] * (n - 2) + [{"kind": "return", "angle": 1.0, "law": "cycloidal"}]
        return f"program of {n} segments"
    if what == 2:
        k = _pick(rng, g) or "AB"
        deep: Any = 1.0
        for _ in range(rng.choice((20, 40, 200))):
            deep = [deep]
        g[k] = deep
        return f"given {k} nested"
    k = _pick(rng, g) or "AB"
    g[k] = [1.0] * rng.choice((2, 1001, 5000))
    return f"given {k} as a list of {len(g[k])}"


MUTATIONS: tuple[Callable[[dict, random.Random], str], ...] = (
    m_number, m_number, m_number, m_scale, m_odd, m_remove, m_names, m_published, m_texts, m_sizes)
"""Data mutations, weighted by repetition (extreme numbers are the most common defect)."""


def _bytes(text: str, rng: random.Random) -> tuple[str, bytes]:
    """Byte-level damage of a file's text."""
    raw = text.encode("utf-8")
    what = rng.randrange(7)
    if what == 0:
        cut = rng.randrange(len(raw) + 1)
        return f"truncated at byte {cut}", raw[:cut]
    if what == 1:
        i = rng.randrange(len(raw) + 1)
        return f"NUL at byte {i}", raw[:i] + b"\x00" + raw[i:]
    if what == 2:
        i = rng.randrange(len(raw) + 1)
        return f"invalid UTF-8 at byte {i}", raw[:i] + b"\xff\xfe" + raw[i:]
    if what == 3:
        return "byte-order mark", b"\xef\xbb\xbf" + raw
    if what == 4:
        return "CRLF line ends", raw.replace(b"\n", b"\r\n")
    if what == 5:
        return "huge integer literal", raw + b"\n[zz]\nx = " + b"9" * 5000 + b"\n"
    return "nesting 600 deep", b"a = " + b"[" * 600 + b"]" * 600 + b"\n" + raw


def mutate(data: dict, rng: random.Random) -> tuple[str, bytes]:
    """One hostile variant of a parsed problem: one to three data mutations, or byte-level damage."""
    text_before = dumps(data)
    if rng.random() < 0.2:
        return _bytes(text_before, rng)
    d = copy.deepcopy(data)
    labels = [rng.choice(MUTATIONS)(d, rng) for _ in range(rng.choice((1, 1, 2, 3)))]
    return "; ".join(labels), dumps(d).encode("utf-8")
