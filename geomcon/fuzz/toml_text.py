"""Writing a problem table back as TOML text, including values a hostile file may hold (nan, inf, integers of
any size, keys with control characters), so that mutations are made on data and tested on files.

Examples
--------
>>> print(dumps({"recipe": "guide_bar.extremes", "given": {"AB": 50, "AC": float("nan"), "a\\nb": [1, {"x": True}]}}))
recipe = "guide_bar.extremes"
<BLANKLINE>
[given]
AB = 50
AC = nan
"a\\nb" = [1, {x = true}]
<BLANKLINE>
"""
from __future__ import annotations

import json
import math
import re
from typing import Any, Mapping

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def key(k: str) -> str:
    """A bare key where TOML allows one, else a quoted key (JSON escapes are valid TOML basic strings)."""
    return k if _BARE.match(k) else json.dumps(k)


def value(v: Any) -> str:
    """One TOML value."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, Mapping):
        return "{" + ", ".join(f"{key(str(k))} = {value(x)}" for k, x in v.items()) + "}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(x) for x in v) + "]"
    raise TypeError(f"no TOML form for {type(v).__name__}")


def dumps(data: Mapping[str, Any]) -> str:
    """A problem table as TOML: top-level scalars first, then one ``[table]`` per sub-table."""
    lines = [f"{key(k)} = {value(v)}" for k, v in data.items() if not isinstance(v, Mapping)]
    for k, v in data.items():
        if isinstance(v, Mapping):
            lines += ["", f"[{key(k)}]"] + [f"{key(str(kk))} = {value(vv)}" for kk, vv in v.items()]
    return "\n".join(lines) + "\n"
