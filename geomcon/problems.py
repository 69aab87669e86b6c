"""Problem files: TOML with a recipe name, given values and (optionally) the textbook's printed answers.

A problem file looks like::

    recipe = "crank_slider.extremes"
    title = "Offset crank-slider: stroke, extreme positions, time ratio"
    source = "free text: where the data come from"
    [given]          # lengths in mm, angles in degrees
    AB = 30
    BC = 90
    e = 20
    [published]      # optional: the printed answers, audited, never trusted
    H = 64.6

Everything is validated here, so that a bad file fails with one line naming the key and the value.

Examples
--------
>>> p = problem_from_dict({"recipe": "guide_bar.extremes", "given": {"AB": 145, "AC": 290}}, name="demo")
>>> p.given
{'AB': 145.0, 'AC': 290.0}
>>> problem_from_dict({"recipe": "guide_bar.extremes", "given": {"AB": -1, "AC": 290}}, name="demo")
Traceback (most recent call last):
...
geomcon.errors.ProblemError: given 'AB' must be > 0, got -1
"""
from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from .errors import ProblemError
from .recipes import Quantity, Recipe, get_recipe

TOP_KEYS = ("recipe", "title", "source", "seed", "statement", "notes", "given", "published")


@dataclass(frozen=True)
class Problem:
    """A validated problem: recipe name, normalised givens, published answers and provenance."""

    id: str
    recipe: str
    given: Mapping[str, Any]
    published: Mapping[str, Any] = field(default_factory=dict)
    title: str = ""
    source: str = ""
    seed: str = ""
    statement: str = ""
    notes: str = ""
    path: str | None = None


def _number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ProblemError(f"{where} must be a number, got {value!r}")
    x = float(value)
    if not math.isfinite(x):
        raise ProblemError(f"{where} is not a finite number ({value!r})")
    return x


def validate_given(recipe: Recipe, given: Mapping[str, Any]) -> dict[str, Any]:
    """Check ``given`` against the recipe's givens; return them normalised (floats, defaults filled in)."""
    if not isinstance(given, Mapping):
        raise ProblemError("[given] must be a table of name = value")
    names = recipe.given_names()
    extra = [k for k in given if k not in names]
    if extra:
        raise ProblemError(f"unknown given '{extra[0]}' for recipe {recipe.name} (it takes {', '.join(names)})")
    out: dict[str, Any] = {}
    for q in recipe.givens:
        if q.name not in given:
            if q.required:
                raise ProblemError(f"missing given '{q.name}' ({q.doc}) for recipe {recipe.name}")
            out[q.name] = q.default
            continue
        value = given[q.name]
        if q.unit == "bool":
            if not isinstance(value, bool):
                raise ProblemError(f"given '{q.name}' must be true or false, got {value!r}")
            out[q.name] = value
            continue
        if q.unit == "choice":
            if value not in q.choices:
                raise ProblemError(f"given '{q.name}' must be one of {', '.join(q.choices)}, got {value!r}")
            out[q.name] = value
            continue
        if q.unit == "point":
            out[q.name] = _point(value, f"given '{q.name}'")
            continue
        if q.unit == "table[]":
            out[q.name] = _tables(value, f"given '{q.name}'")
            continue
        if q.unit.endswith("[]"):
            if not isinstance(value, list) or not value:
                raise ProblemError(f"given '{q.name}' must be a non-empty list of numbers, got {value!r}")
            out[q.name] = tuple(_bounded(q, v, f"given '{q.name}[{i}]'") for i, v in enumerate(value))
            continue
        out[q.name] = _bounded(q, value, f"given '{q.name}'")
    return out


def _bounded(q: Quantity, value: Any, where: str) -> float:
    x = _number(value, where)
    if q.minimum is not None:
        bad = x < q.minimum if q.inclusive else x <= q.minimum
        if bad:
            op = "≥" if q.inclusive else ">"
            raise ProblemError(f"{where} must be {op} {q.minimum:g}, got {value!r}")
    return x


def _point(value: Any, where: str) -> tuple[float, float]:
    """``[x, y]`` in mm."""
    if not isinstance(value, list) or len(value) != 2:
        raise ProblemError(f"{where} must be a point [x, y], got {value!r}")
    return (_number(value[0], f"{where}[0]"), _number(value[1], f"{where}[1]"))


def _tables(value: Any, where: str) -> tuple[dict[str, Any], ...]:
    """A non-empty list of tables (e.g. a cam's motion program); the recipe checks their contents."""
    if not isinstance(value, list) or not value or not all(isinstance(v, Mapping) for v in value):
        raise ProblemError(f"{where} must be a non-empty list of tables, e.g. [{{kind = \"rise\", angle = 120}}], got {value!r}")
    return tuple(dict(v) for v in value)


def problem_from_dict(data: Mapping[str, Any], *, name: str, path: str | None = None) -> Problem:
    """Validate a parsed problem table and build a :class:`Problem`."""
    extra = [k for k in data if k not in TOP_KEYS]
    if extra:
        raise ProblemError(f"unknown key '{extra[0]}' (a problem file takes {', '.join(TOP_KEYS)})")
    if "recipe" not in data:
        raise ProblemError("missing key 'recipe'")
    if not isinstance(data["recipe"], str):
        raise ProblemError(f"'recipe' must be a string, got {data['recipe']!r}")
    recipe = get_recipe(data["recipe"])
    given = validate_given(recipe, data.get("given", {}))
    published_in = data.get("published", {})
    if not isinstance(published_in, Mapping):
        raise ProblemError("[published] must be a table of answer = value")
    answers = [q.name for q in recipe.answers]
    published: dict[str, Any] = {}
    for k, v in published_in.items():
        if k not in answers:
            raise ProblemError(f"published '{k}' is not an answer of {recipe.name} (answers: {', '.join(answers)})")
        if isinstance(v, list):
            published[k] = tuple(_number(x, f"published '{k}[{i}]'") for i, x in enumerate(v))
        elif isinstance(v, bool):
            published[k] = v
        else:
            published[k] = _number(v, f"published '{k}'")
    texts = {}
    for k in ("title", "source", "seed", "statement", "notes"):
        v = data.get(k, "")
        if not isinstance(v, str):
            raise ProblemError(f"'{k}' must be a string, got {v!r}")
        texts[k] = v
    return Problem(id=name, recipe=recipe.name, given=given, published=published, path=path, **texts)


def load_problem(path: str | Path) -> Problem:
    """Read and validate a TOML problem file.

    Raises
    ------
    ProblemError
        Unreadable file, malformed TOML, or any invalid content; the message names the key and the value
        (the caller adds the file name).
    """
    p = Path(path)
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except OSError as exc:
        raise ProblemError(f"cannot read the file: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise ProblemError(f"not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    except tomllib.TOMLDecodeError as exc:
        raise ProblemError(f"malformed TOML: {exc}") from None
    return problem_from_dict(data, name=p.stem, path=str(p))
