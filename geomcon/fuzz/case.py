"""What a random valid problem is: the problem table, and what is known of its answers by construction.

Examples
--------
>>> c = ValidCase({"recipe": "guide_bar.extremes", "given": {"AB": 50.0, "AC": 100.0}},
...               expect={"theta": (60.0, 1e-9)}, kind="random")
>>> c.problem["recipe"], c.expect["theta"]
('guide_bar.extremes', (60.0, 1e-09))
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping
import random


@dataclass(frozen=True)
class ValidCase:
    """One random valid problem.

    Parameters
    ----------
    problem : mapping
        As a problem file reads once parsed: ``{"recipe": …, "given": {…}}`` (lists, not tuples).
    expect : mapping
        Ground truth known by how the case was made (e.g. the linkage a design problem was stated from):
        ``answer name -> (value, absolute tolerance)``; for a list answer the value is a tuple. A problem with
        several solutions passes when *some* solution matches every expected value.
    kind : str
        ``"random"`` or ``"near-degenerate: <what>"`` — reported in the fuzz counts.
    may_refuse : bool
        True when a clean refusal (exit 2, one line) is an acceptable outcome (a case built at or beyond a
        documented limit); a refusal of any other case counts as a failure.
    """

    problem: Mapping[str, Any]
    expect: Mapping[str, tuple[Any, float]] = field(default_factory=dict)
    kind: str = "random"
    may_refuse: bool = False


Generator = Callable[[random.Random], ValidCase]
"""A generator of random valid problems of one family."""
