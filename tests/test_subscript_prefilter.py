"""The subscript pattern's cheap tests in front (:data:`geomcon.render.labels._SUB`: a subscript follows a letter,
a prime or a modifier letter, and none but an underscored one begins at a word's third small letter) reject
only positions where none of its alternatives matches: the same runs as the alternatives alone. A new
alternative that begins elsewhere (after a digit, a space, inside a word) must widen the tests in front."""
from __future__ import annotations

import random
import re

from geomcon.render import labels

PREFIX = r"(?=[A-Za-z_\d])(?<=[A-Za-zα-ωΑ-Ω′ⁿᵗʳᵏ])(?:(?<![a-z][a-z])|(?=_))(?:"
WORDS = ["min", "max", "r", "v", "a", "l", "n", "AB", "C1", "γ", "α′", "_max", "r0,ρ", "rr,max", "x", "p", "sE1",
         "Ff", "lface", "φslow", "vC", "aʳB2B3", "i", "Ci", "the", "rise", "2,3", "d1", "Cd1", "μl", "b2", "E", "0,α",
         "ω2,max", "ψi", "B_i", "K_i", "12", "-3.5", "ya", "xp", "Fn", "nB", "aEDⁿ", "曲柄", "Δ", "Ω1", "αmax,turn"]
GLUE = ["", " ", ",", "_", "=", " (", ")", ".", "′", "-"]
CHARS = "abcdefghijklmnopqrstuvwxyzABCDEFGKXYZ0123456789_ ,.′″αγωρφμψεθΔΣΩⁿᵗʳᵏ-=()曲*'"


def _alone() -> re.Pattern[str]:
    pattern = labels._SUB.pattern
    assert pattern.startswith(PREFIX)
    return re.compile(r"(?:" + pattern[len(PREFIX):])


def _matches(rx: re.Pattern[str], s: str) -> list[tuple[tuple[int, int], tuple[str | None, ...]]]:
    return [(m.span(), m.groups()) for m in rx.finditer(s)]


def test_the_tests_in_front_change_no_match():
    alone, rng = _alone(), random.Random(11)
    texts = ["".join(rng.choice(WORDS) + rng.choice(GLUE) for _ in range(rng.randint(1, 6))) for _ in range(40000)]
    texts += ["".join(rng.choice(CHARS) for _ in range(rng.randint(1, 14))) for _ in range(40000)]
    bad = [s for s in texts if _matches(labels._SUB, s) != _matches(alone, s)]
    assert not bad, bad[:5]


def test_a_word_with_an_underscore_inside_keeps_its_subscript():
    assert labels.rich_runs("alpha_max, xyz_i") == (("alpha", False), ("max", True), (", xyz", False), ("i", True))
