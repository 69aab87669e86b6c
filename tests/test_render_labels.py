"""Text widths: the table of advances gives the sum the per-character formula gives, to the last bit."""
from __future__ import annotations

import random

from geomcon.render.labels import char_em, label_runs, rich_runs, text_width

ALPHABET = "ABCDθψγαω0123456789 .,:;()′″ilmwMW=−+<>°作图步骤以为圆心、，。xyz"


def formula(runs, size):
    return sum(char_em(ch) * size * (0.72 if sub else 1.0) for s, sub in runs for ch in s)


def test_text_width_is_the_sum_of_each_characters_advance():
    rng = random.Random(7)
    for _ in range(3000):
        text = "".join(rng.choice(ALPHABET) for _ in range(rng.randint(0, 60)))
        size = rng.choice([2.4, 2.5, 2.7, 2.9, 3.0, 3.2, 5.0, rng.uniform(1.0, 6.0)])
        for runs in (((text, False),), rich_runs(text), label_runs(text or "A")):
            assert text_width(runs, size) == formula(runs, size)
        assert text_width(text, size) == formula(((text, False),), size)
