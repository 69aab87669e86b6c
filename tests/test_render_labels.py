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


def reference_wrap(text, width, size, last_reserve=0.0):
    """wrap() measuring every candidate line exactly (as it did before its full-size estimate)."""
    from geomcon.render.labels import _tokens

    lines, cur = [], ""
    for tok in _tokens(text):
        if cur.strip() and text_width(rich_runs(cur + tok.rstrip()), size) > width:
            lines.append(cur.rstrip())
            cur = tok.lstrip()
        else:
            cur += tok
    lines.append(cur.rstrip())
    if last_reserve and len(lines[-1]) and text_width(rich_runs(lines[-1]), size) + last_reserve > width:
        toks = _tokens(lines[-1])              # the last token (a formula whole) to a line of its own
        if len(toks) >= 2 and "".join(toks[:-1]).strip():
            lines[-1:] = ["".join(toks[:-1]).rstrip(), toks[-1]]
        else:
            lines.append("")
    return lines


def test_wrap_breaks_where_measuring_every_line_exactly_breaks():
    from geomcon.render.labels import wrap

    rng = random.Random(11)
    words = ["Join", "AC1", "C2", "γmin", "ψ", "θ", "=", "12.506°", "the", "circle", "k1", "以", "为圆心", "、",
             "作圆", "BC", "−", "AB", "20", "(D1)", "mm", "B′′C′′", "extended", "meets"]
    for _ in range(3000):
        text = " ".join(rng.choice(words) for _ in range(rng.randint(1, 30)))
        size = rng.choice([2.4, 2.7, 3.0])
        width = rng.choice([20.0, 40.0, 78.5, rng.uniform(5.0, 90.0)])
        reserve = rng.choice([0.0, 0.0, 14.3])
        assert wrap(text, width, size, reserve) == reference_wrap(text, width, size, reserve)
    # widths that fall exactly on a line's measured width
    for text in ["Join AC1 and AC2 then measure γmin", "以 A 为圆心、BC − AB = 20 为半径作圆"]:
        for k in range(2, len(text)):
            w = text_width(rich_runs(text[:k]), 2.7)
            assert wrap(text, w, 2.7) == reference_wrap(text, w, 2.7)
