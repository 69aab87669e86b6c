"""Problem files: TOML with a recipe name, given values and (optionally) the textbook's printed answers.

A problem file looks like::

    recipe = "crank_slider.extremes"
    title = "Offset crank-slider: stroke, extreme positions, time ratio"
    title_zh = "偏置曲柄滑块机构：行程、极限位置与行程速比系数"    # optional: the title of zh sheets
    source = "free text: where the data come from"
    [given]          # lengths in mm, angles in degrees
    AB = 30
    BC = 90
    e = 20
    [published]      # optional: the printed answers, audited, never trusted
    H = 64.6

Everything is validated here, so that a bad file fails with one line naming the key and the value.
Problem files are untrusted: nothing in them is evaluated, and every size is limited up front
(:data:`LIMITS`); every number must lie in its unit's range (:data:`RANGES`), and a recipe may narrow it
(``Quantity.minimum``/``maximum``).

Examples
--------
>>> p = problem_from_dict({"recipe": "guide_bar.extremes", "given": {"AB": 145, "AC": 290}}, name="demo")
>>> p.given                                  # optional givens without a default are None
{'AB': 145.0, 'AC': 290.0, 'e': None, 'L': None}
>>> problem_from_dict({"recipe": "guide_bar.extremes", "given": {"AB": -1, "AC": 290}}, name="demo")
Traceback (most recent call last):
...
geomcon.errors.ProblemError: given 'AB' must be > 0, got -1
"""
from __future__ import annotations

import math
import os
import re
import stat
import tomllib
import unicodedata
from pathlib import Path
from typing import Any, Callable, Mapping

from .errors import ProblemError
from .values import Frozen, store
from .recipes import Quantity, Recipe, get_recipe

TOP_KEYS = ("recipe", "title", "title_zh", "source", "seed", "statement", "notes", "given", "published")

LIMITS = {
    "file_bytes": 1 << 20,       # a problem file is at most 1 MiB
    "list_items": 1000,          # elements of a list given or a published list
    "table_rows": 100,           # rows of a table given (a cam's motion program)
    "text_chars": 20000,         # characters of a text field (title, notes, …)
    "title_zh_chars": 120,       # characters of the Chinese title (one line of a title block)
}
"""Size limits of a problem file, checked before anything is computed."""

RANGES = {
    "mm": (1e-6, 1e9),           # a nonzero length: 1 nm … 1000 km
    "deg": (0.0, 3600.0),        # |angle| ≤ ten turns
    "": (0.0, 1e6),              # ratios, angular speeds (rad/s), counts
    "mm/s": (0.0, 1e14),         # a follower's speed (printed answers only)
    "rad/s": (0.0, 1e6),         # an angular speed
    "count": (0.0, 1e6),         # a whole number of parts (the recipe checks it is whole)
    "rad/s²": (0.0, 1e12),       # an angular acceleration
    "mm/s²": (0.0, 1e20),        # a follower's acceleration (printed answers only)
}
"""Magnitude range of every given number by unit (lengths: a nonzero |x| in [lo, hi]; others |x| ≤ hi)."""

LENGTH_SPAN = 1e10
"""No nonzero given length may be more than this many times smaller than the largest given length."""


_NEW: Any = object()
"""The default of :attr:`Problem.published`: a new dict for each problem."""


class Problem(Frozen):
    """A validated problem: recipe name, normalised givens, published answers (a new empty dict when not
    given) and provenance."""

    _FIELDS = ("id", "recipe", "given", "published", "title", "source", "seed", "statement", "notes", "path",
               "title_zh")
    id: str
    recipe: str
    given: Mapping[str, Any]
    published: Mapping[str, Any]
    title: str
    source: str
    seed: str
    statement: str
    notes: str
    path: str | None
    title_zh: str

    def __init__(self, id: str, recipe: str, given: Mapping[str, Any], published: Mapping[str, Any] = _NEW,
                 title: str = "", source: str = "", seed: str = "", statement: str = "", notes: str = "",
                 path: str | None = None, title_zh: str = "") -> None:
        if published is _NEW:
            published = {}
        for name, value in zip(self._FIELDS, (id, recipe, given, published, title, source, seed, statement, notes,
                                              path, title_zh)):
            store(self, name, value)

    def title_in(self, lang: str) -> str:
        """The title in ``lang`` (:func:`title_in`)."""
        return title_in(self.title, self.title_zh, lang)


def title_in(title: str, title_zh: str, lang: str) -> str:
    r"""The title a sheet, a player or a worksheet prints in ``lang``: ``en`` the English ``title``; ``zh`` the
    Chinese ``title_zh``, or the English one when there is none (a file without ``title_zh`` still draws, and
    ``geomcon solve --lang zh`` says so in a note); ``both`` the two, English first, on two lines (joined by a
    newline: a title block sets them as two lines, a one-line place joins them with :func:`one_line_title`).

    >>> title_in("Crank-rocker", "曲柄摇杆机构", "zh"), title_in("Crank-rocker", "", "zh")
    ('曲柄摇杆机构', 'Crank-rocker')
    >>> title_in("Crank-rocker", "曲柄摇杆机构", "both"), title_in("", "曲柄摇杆机构", "en")
    ('Crank-rocker\n曲柄摇杆机构', '')
    """
    if lang == "zh":
        return title_zh or title
    if lang == "both" and title_zh:
        return f"{title}\n{title_zh}" if title else title_zh
    return title


def one_line_title(title: str) -> str:
    r"""A title of :func:`title_in` on one line (an HTML page's ``<title>``, a text summary): its two languages
    joined by two spaces, as the sheets' bilingual headings are ("Results  结果").

    >>> one_line_title("Crank-rocker\n曲柄摇杆机构")
    'Crank-rocker  曲柄摇杆机构'
    """
    return "  ".join(part for part in title.split("\n") if part)


def _g(x: float) -> str:
    """A number as people write it: ``1e+12`` → ``1e12``.

    Examples
    --------
    >>> _g(1e12), _g(2.5e-7), _g(90.0), _g(2e9)
    ('1e12', '2.5e-7', '90', '2e9')
    """
    return re.sub(r"e\+?(-?)0*(\d)", r"e\1\2", f"{x:g}")


def _short(value: Any, limit: int = 60) -> str:
    """``repr`` of a value, cut to ``limit`` characters (hostile files hold huge values)."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 10 ** 30:
        return f"an integer of {len(str(abs(value)))} digits"
    text = _g(value) if isinstance(value, float) else repr(value)
    return text if len(text) <= limit else text[:limit - 1] + "…"


def _number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ProblemError(f"{where} must be a number, got {_short(value)}")
    if isinstance(value, int) and abs(value) > 1e300:
        raise ProblemError(f"{where} is out of range ({_short(value)})")
    x = float(value)
    if not math.isfinite(x):
        raise ProblemError(f"{where} is not a finite number ({value!r})")
    return x


def check_number(unit: str, value: Any, where: str) -> float:
    """A number from an untrusted file, as every given is checked: a number (not a bool), finite, within its
    unit's range (:data:`RANGES`); the refusal names ``where``.

    Examples
    --------
    >>> check_number("deg", 30, "program[0].angle")
    30.0
    >>> check_number("deg", 2 ** 1100, "program[0].angle")
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: program[0].angle is out of range (an integer of 332 digits)
    """
    return _in_range(unit, _number(value, where), where)


def _in_range(unit: str, x: float, where: str) -> float:
    """Refuse a number outside its unit's range (:data:`RANGES`), naming the limit. Coordinates and list
    elements (positions along a guide…) have no smallest size: 0.0000001 mm from the origin is a place, not a
    length."""
    lo, hi = RANGES.get(unit.removesuffix("[]"), RANGES["mm"] if unit == "point" else RANGES[""])
    if unit.endswith("[]") or unit == "point":
        lo = 0.0
    if abs(x) > hi:
        what = {"mm": "a length", "point": "a coordinate", "deg": "an angle"}.get(unit.removesuffix("[]"), "a value")
        unit_text = {"mm": " mm", "point": " mm", "deg": "°"}.get(unit.removesuffix("[]"), "")
        raise ProblemError(f"{where} = {_g(x)}{unit_text} is out of range: {what} is at most {_g(hi)}{unit_text} "
                           "in size")
    if x != 0 and abs(x) < lo:
        raise ProblemError(f"{where} = {_g(x)} mm is too small: a nonzero length is at least {_g(lo)} mm")
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
        x = _plain(q, value)
        if x is not None:                   # a plain number well inside every limit: no message to prepare
            out[q.name] = x
            continue
        if q.unit == "bool":
            if not isinstance(value, bool):
                raise ProblemError(f"given '{q.name}' must be true or false, got {_short(value)}")
            out[q.name] = value
            continue
        if q.unit == "choice":
            if value not in q.choices:
                raise ProblemError(f"given '{q.name}' must be one of {', '.join(q.choices)}, got {_short(value)}")
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
                raise ProblemError(f"given '{q.name}' must be a non-empty list of numbers, got {_short(value)}")
            if len(value) > LIMITS["list_items"]:
                raise ProblemError(f"given '{q.name}' has {len(value)} elements; at most {LIMITS['list_items']}")
            out[q.name] = tuple(_bounded(q, v, f"given '{q.name}[{i}]'") for i, v in enumerate(value))
            continue
        out[q.name] = _bounded(q, value, f"given '{q.name}'")
    _length_span(recipe, out)
    return out


_SCALAR_UNITS = ("mm", "deg", "", "count", "mm/s", "rad/s", "rad/s²")


def plain_validator(recipe: Recipe) -> Callable[[Any], dict[str, Any] | None]:
    """For many rows of one recipe (a batch): ``run(given)`` gives :func:`validate_given`'s result when
    ``given`` is a dict of known names whose values are all plain numbers passing :func:`_plain`'s checks (the
    recipe's names read once, here, not per row); None when anything else is met (an unknown or missing
    name, a word, a list, a number to refuse), and the caller then calls :func:`validate_given`, which answers
    or refuses in its words. The units' ranges (:data:`RANGES`) are read at each call, as :func:`_plain` does.

    >>> from geomcon.recipes import get_recipe
    >>> run = plain_validator(get_recipe("guide_bar.extremes"))
    >>> run({"AB": 145, "AC": 290.0}), run({"AB": -1.0, "AC": 290.0}), run({"AB": 1.0, "X": 2.0})
    ({'AB': 145.0, 'AC': 290.0, 'e': None, 'L': None}, None, None)
    """
    names = frozenset(recipe.given_names())
    specs = tuple((q.name, q, q.required, q.default) for q in recipe.givens)

    def run(given: Any) -> dict[str, Any] | None:
        if type(given) is not dict:
            return None
        for k in given:
            if k not in names:
                return None
        out: dict[str, Any] = {}
        for name, q, required, default in specs:
            if name not in given:
                if required:
                    return None
                out[name] = default
                continue
            x = _plain(q, given[name])
            if x is None:
                return None
            out[name] = x
        _length_span(recipe, out)
        return out
    return run


def _plain(q: Quantity, value: Any) -> float | None:
    """``value`` as a float when it is a number (not a bool) that passes every check of :func:`_bounded`;
    None otherwise, and the slow path then refuses it with its message.

    >>> _plain(Quantity("AB", "mm", "crank"), 50), _plain(Quantity("AB", "mm", "crank"), -1.0)
    (50.0, None)
    """
    t = type(value)
    if (t is not float and t is not int) or q.unit not in _SCALAR_UNITS:
        return None
    if t is int and not -1e300 <= value <= 1e300:
        return None
    x = float(value)
    lo, hi = RANGES[q.unit]
    if not (x - x == 0.0 and abs(x) <= hi and (x == 0.0 or abs(x) >= lo)):
        return None
    if q.minimum is not None and (x < q.minimum if q.inclusive else x <= q.minimum):
        return None
    if q.maximum is not None and x > q.maximum:
        return None
    return x


def _length_span(recipe: Recipe, given: Mapping[str, Any]) -> None:
    """Refuse given lengths more than :data:`LENGTH_SPAN` apart (the smaller one would be lost in rounding).
    The distances between given points are lengths too (A and D 1e-15 mm apart in a 25 mm problem are one
    point to double precision); coordinates themselves are places, not lengths, and take no part."""
    lengths: list[tuple[float, str]] = []
    points: list[tuple[str, tuple[float, float]]] = []
    for q in recipe.givens:
        v = given.get(q.name)
        if v is None:
            continue
        if q.unit == "mm":
            lengths.append((abs(v), f"'{q.name}'"))
        elif q.unit == "point":
            points.append((q.name, v))
    for i, (n1, p1) in enumerate(points):
        for n2, p2 in points[i + 1:]:
            lengths.append((math.hypot(p1[0] - p2[0], p1[1] - p2[1]), f"the distance {n1}{n2}"))
    nonzero = [t for t in lengths if t[0] > 0]
    if not nonzero:
        return
    big, small = max(nonzero), min(nonzero)
    if big[0] > LENGTH_SPAN * small[0]:
        what = f"given {small[1]}" if small[1].startswith("'") else small[1]
        raise ProblemError(f"{what} = {_g(small[0])} mm is more than {_g(LENGTH_SPAN)} times smaller "
                           f"than {big[1]} = {_g(big[0])} mm: lengths must lie within a ratio of {_g(LENGTH_SPAN)} "
                           "(write 0 for none, or one point for two)")


def _bounded(q: Quantity, value: Any, where: str) -> float:
    x = _number(value, where)
    if q.minimum is not None:
        bad = x < q.minimum if q.inclusive else x <= q.minimum
        if bad:
            op = "≥" if q.inclusive else ">"
            raise ProblemError(f"{where} must be {op} {_g(q.minimum)}, got {_short(value)}")
    if q.maximum is not None and x > q.maximum:
        raise ProblemError(f"{where} must be ≤ {_g(q.maximum)}, got {_short(value)}")
    return _in_range(q.unit, x, where)


def _point(value: Any, where: str) -> tuple[float, float]:
    """``[x, y]`` in mm."""
    if not isinstance(value, list) or len(value) != 2:
        raise ProblemError(f"{where} must be a point [x, y], got {_short(value)}")
    return (_in_range("point", _number(value[0], f"{where}[0]"), f"{where}[0]"),
            _in_range("point", _number(value[1], f"{where}[1]"), f"{where}[1]"))


def _tables(value: Any, where: str) -> tuple[dict[str, Any], ...]:
    """A non-empty list of tables (e.g. a cam's motion program); the recipe checks their contents. A tuple of
    tables (the normalised form this returns, as a drafted variant passes it again) is taken too."""
    if not isinstance(value, (list, tuple)) or not value or not all(isinstance(v, Mapping) for v in value):
        raise ProblemError(f"{where} must be a non-empty list of tables, e.g. [{{kind = \"rise\", angle = 120}}], "
                           f"got {_short(value)}")
    if len(value) > LIMITS["table_rows"]:
        raise ProblemError(f"{where} has {len(value)} rows; at most {LIMITS['table_rows']}")
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
    units = {q.name: q.unit for q in recipe.answers}
    published: dict[str, Any] = {}
    for k, v in published_in.items():
        if k not in units:
            raise ProblemError(f"published '{k}' is not an answer of {recipe.name} (answers: {', '.join(units)})")
        published[k] = _published(units[k], v, f"published '{k}'")
    texts = {k: _text(data.get(k, ""), k) for k in ("title", "source", "seed", "statement", "notes")}
    return Problem(id=name, recipe=recipe.name, given=given, published=published, path=path,
                   title_zh=title_zh(data.get("title_zh", "")), **texts)


def title_zh(value: Any, key: str = "title_zh") -> str:
    """The Chinese title of a problem file (or a worksheet spec): a string of at most
    ``LIMITS['title_zh_chars']`` characters on one line, holding Chinese (an English title belongs in ``title``),
    its punctuation full-width where it touches Chinese (as every Chinese text we print: ``：``, ``（…）``).

    >>> title_zh("曲柄摇杆机构：极限位置、K 与 γmin")
    '曲柄摇杆机构：极限位置、K 与 γmin'
    >>> title_zh("曲柄摇杆机构: 极限位置")
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: 'title_zh' uses half-width punctuation next to Chinese: write '曲柄摇杆机构：极限位置'
    """
    if value == "":
        return ""
    text = _text(value, key)
    if len(text) > LIMITS["title_zh_chars"]:
        raise ProblemError(f"'{key}' has {len(text)} characters; a title is at most {LIMITS['title_zh_chars']} "
                           "(one line of the title block)")
    if "\n" in text or "\t" in text:
        raise ProblemError(f"'{key}' must be one line")
    if not any("\u3400" <= ch <= "\u9fff" for ch in text):
        raise ProblemError(f"'{key}' holds no Chinese character, got {_short(text)} (the English title is 'title')")
    from .render.zh import zh_punct
    fixed = zh_punct(text)
    if fixed != text:
        raise ProblemError(f"'{key}' uses half-width punctuation next to Chinese: write {_short(fixed)}")
    return text


def _published(unit: str, value: Any, where: str) -> Any:
    """A printed answer in its answer's shape: a list for list answers, true/false for bool answers."""
    if unit == "bool":
        if not isinstance(value, bool):
            raise ProblemError(f"{where} must be true or false (the answer is a yes/no), got {_short(value)}")
        return value
    if unit.endswith("[]"):
        if not isinstance(value, list) or not value:
            raise ProblemError(f"{where} must be a non-empty list of numbers (the answer is a list), got {_short(value)}")
        if len(value) > LIMITS["list_items"]:
            raise ProblemError(f"{where} has {len(value)} elements; at most {LIMITS['list_items']}")
        return tuple(_in_range(unit, _number(x, f"{where}[{i}]"), f"{where}[{i}]") for i, x in enumerate(value))
    return _in_range(unit, _number(value, where), where)


def _text(value: Any, key: str) -> str:
    """A free-text field: a string of at most ``LIMITS['text_chars']`` characters, no control characters other
    than tab and newline (they cannot be written to SVG or HTML)."""
    if not isinstance(value, str):
        raise ProblemError(f"'{key}' must be a string, got {_short(value)}")
    if len(value) > LIMITS["text_chars"]:
        raise ProblemError(f"'{key}' has {len(value)} characters; at most {LIMITS['text_chars']}")
    for i, ch in enumerate(value):
        if ch not in "\t\n" and (unicodedata.category(ch) in ("Cc", "Cs") or ch in "\ufffe\uffff"):
            raise ProblemError(f"'{key}' holds the control character U+{ord(ch):04X} at position {i}")
    return value


def load_problem(path: str | Path) -> Problem:
    """Read and validate a TOML problem file.

    Raises
    ------
    ProblemError
        Unreadable file, malformed TOML, or any invalid content; the message names the key and the value
        (the caller adds the file name).
    """
    p = Path(path)
    data = parse_toml(read_limited(p))
    return problem_from_dict(data, name=p.stem, path=str(p))


def read_limited(path: Path, limit: int = LIMITS["file_bytes"]) -> str:
    """The UTF-8 text of a regular file of at most ``limit`` bytes (a leading byte-order mark dropped).

    A FIFO, a device (``/dev/zero``) or a directory is refused before it is opened, so nothing blocks or
    reads without end.
    """
    try:
        st = os.stat(path)
        if not stat.S_ISREG(st.st_mode):
            what = "a directory" if stat.S_ISDIR(st.st_mode) else "not a regular file (a pipe or a device)"
            raise ProblemError(f"cannot read the file: {what}")
        if st.st_size > limit:
            raise ProblemError(f"the file has {st.st_size} bytes; a problem file is at most {limit} bytes")
        with open(path, "rb") as fh:
            raw = fh.read(limit + 1)
    except OSError as exc:
        raise ProblemError(f"cannot read the file: {exc.strerror or exc}") from None
    if len(raw) > limit:
        raise ProblemError(f"the file has more than {limit} bytes; a problem file is at most {limit} bytes")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ProblemError(f"not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    return text.removeprefix("\ufeff")


def parse_toml(text: str) -> dict[str, Any]:
    """Parse TOML text; any failure (syntax, a number too long for Python, nesting too deep) is one line.

    Examples
    --------
    >>> parse_toml("a = [[[]]]")
    {'a': [[[]]]}
    >>> parse_toml("a = " + "[" * 2000 + "]" * 2000)
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: malformed TOML: nested more than 32 levels deep
    """
    depth = max_nesting(text)
    if depth > MAX_NESTING:
        raise ProblemError(f"malformed TOML: nested more than {MAX_NESTING} levels deep")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProblemError(f"malformed TOML: {exc}") from None
    except (ValueError, RecursionError, OverflowError) as exc:      # e.g. an integer of > 4300 digits
        raise ProblemError(f"malformed TOML: {str(exc).splitlines()[0][:120]}") from None


MAX_NESTING = 32
"""Deepest nesting of arrays and inline tables accepted in a problem file."""


def max_nesting(text: str) -> int:
    """An upper bound of the bracket nesting depth of TOML text (brackets inside strings count too, so
    the bound is safe: it never under-counts).

    Examples
    --------
    >>> max_nesting('a = [[1, 2], {b = [3]}]')
    3
    """
    depth = best = 0
    for ch in text:
        if ch in "[{":
            depth += 1
            best = max(best, depth)
        elif ch in "]}":
            depth = max(depth - 1, 0)
    return best
