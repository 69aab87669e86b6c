"""Issue 10: the batch's validator of plain rows (plain_validator: a recipe's quantities read once for all rows)
gives exactly validate_given's result, or declines (None) and leaves the row to it; rows from every bundled
problem, moved and spoiled at random (negative, zero, huge, tiny, NaN, int, bool, word, list, missing and
unknown names)."""
from __future__ import annotations

import random
from pathlib import Path

from geomcon.errors import ProblemError
from geomcon.problems import load_problem, plain_validator, validate_given
from geomcon.recipes import get_recipe

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"


def _spoil(rnd: random.Random, v):
    u = rnd.random()
    if u < 0.5 and type(v) is float:
        return v * rnd.uniform(0.5, 1.5)
    return rnd.choice([-1.0, 0.0, 1e12, 1e-9, float("nan"), float("inf"), 3, True, "above", [1.0], v,
                       10 ** 400, rnd.uniform(-100, 400)])


def _outcome(fn, *args):
    try:
        return repr(fn(*args))
    except ProblemError as exc:
        return "refused: " + str(exc)


def test_plain_validator_is_validate_given() -> None:
    rnd = random.Random(20261127)
    taken = declined = 0
    for path in sorted(PROBLEMS.glob("*.toml")):
        p = load_problem(path)
        r = get_recipe(p.recipe)
        run = plain_validator(r)
        base = {k: v for k, v in p.given.items() if v is not None}
        for _ in range(80):
            g = dict(base)
            for k in list(g):
                if rnd.random() < 0.12:
                    g[k] = _spoil(rnd, g[k])
            if rnd.random() < 0.05 and g:
                del g[rnd.choice(list(g))]
            if rnd.random() < 0.03:
                g["nonsense"] = 1.0
            got = _outcome(run, g)
            if got == "None":
                declined += 1
                continue
            taken += 1
            assert got == _outcome(validate_given, r, g), (path.name, g)
    assert taken > 1000 and declined > 1000, (taken, declined)
