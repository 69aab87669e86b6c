"""Worksheets (issue 12): from one spec, a different well-posed, readable variant of each exercise per student,
and the answer key (``key.json``) that grading reads.

The pieces: :mod:`.spec` parses the untrusted TOML spec, :mod:`.roster` the class list, :mod:`.rng` is
geomcon's own random generator (SHA-256), :mod:`.accept` judges a variant (solves, answers exist, one solution
or the textbook's choice named, ``[require]`` bounds, twin agreement, fit at a standard scale
(:mod:`geomcon.paper`), crossing angles and point gaps (:mod:`.readability`), drafting tolerance
(:mod:`.drafting`)), :mod:`.assign` gives each student a variant, :mod:`.key` writes the key and
:mod:`.statements` holds the statement templates. The pages: :mod:`.pages` lays a page out, :mod:`.givens_figure`
draws the givens to scale and places their labels, :mod:`.sheets` writes the students' sheets
(``sheets/<page>.svg``, ``sheets.html``), :mod:`.overlay` the positional tolerances and :mod:`.key_pages` the key
pages (``key/<page>.svg``, ``key.html``).

Examples
--------
>>> from geomcon.worksheet.spec import parse_spec
>>> from geomcon.worksheet.roster import numbered
>>> spec = parse_spec('''
... title = "Guide bar"
... [[exercise]]
... recipe = "guide_bar.extremes"
... ask = ["theta"]
... [exercise.given]
... AB = {min = 100, max = 140, step = 10}
... AC = 290
... ''')
>>> w = make_worksheet(spec, numbered(2))
>>> sorted(w.files), w.summary[0][:40]
(['key.html', 'key.json', 'key/1.svg', 'key/2.svg', 'sheets.html', 'sheets/1.svg', 'sheets/2.svg', 'variants.csv'], 'exercise 1 (guide_bar.extremes): 2 of 2 ')
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from ..paper import PAPERS
from .assign import Assignment, assign
from .key import key_json, variants_csv
from .roster import Student
from .key_pages import key_files
from .sheets import make_pages, sheet_files
from .spec import Spec

LANGS = ("zh", "en", "both")


@dataclass(frozen=True)
class Worksheet:
    """The files of a worksheet (name → text) and one summary line per exercise."""

    files: dict[str, str]
    summary: tuple[str, ...]
    assignment: Assignment


def make_worksheet(spec: Spec, students: Sequence[Student], *, paper: str = "A4", lang: str = "both",
                   seed: int | str | None = None) -> Worksheet:
    """Assign every student a variant of every exercise and write the key (``key.json``, ``variants.csv``), the
    students' sheets (``sheets/<page>.svg``, ``sheets.html``) and the key pages (``key/<page>.svg``, ``key.html``).

    Raises
    ------
    ProblemError
        When an exercise's variants are too rarely acceptable to fill the class (the line says why).
    """
    a = _assigned(spec, students, paper, lang, seed)
    files = {"key.json": key_json(spec, a, paper=paper, lang=lang, seed=seed),
             "variants.csv": variants_csv(spec, a)}
    pages = make_pages(spec, a, lang)
    files.update(sheet_files(pages, spec.title_in(lang), lang))
    files.update(key_files(pages, spec.title_in(lang), lang))
    return Worksheet(files, tuple(st.line() for st in a.stats), a)


def make_key(spec: Spec, students: Sequence[Student], *, paper: str = "A4", lang: str = "both",
             seed: int | str | None = None) -> str:
    """``key.json``'s text alone: the very bytes of ``make_worksheet(…).files["key.json"]``, without drawing
    the sheets and key pages (the key depends on the assignment only; grading needs nothing else, and the
    pages are most of a worksheet's time).

    Examples
    --------
    >>> from geomcon.worksheet.spec import parse_spec
    >>> from geomcon.worksheet.roster import numbered
    >>> spec = parse_spec('''
    ... title = "Guide bar"
    ... [[exercise]]
    ... recipe = "guide_bar.extremes"
    ... ask = ["theta"]
    ... [exercise.given]
    ... AB = {min = 100, max = 140, step = 10}
    ... AC = 290
    ... ''')
    >>> make_key(spec, numbered(2)) == make_worksheet(spec, numbered(2)).files["key.json"]
    True
    """
    return key_and_assignment(spec, students, paper=paper, lang=lang, seed=seed)[0]


def key_and_assignment(spec: Spec, students: Sequence[Student], *, paper: str = "A4", lang: str = "both",
                       seed: int | str | None = None) -> tuple[str, Assignment]:
    """:func:`make_key`'s text and the assignment it was written from (each accepted variant holds the solution
    its judging built: grading the key's variants can use them instead of solving each again)."""
    a = _assigned(spec, students, paper, lang, seed)
    return key_json(spec, a, paper=paper, lang=lang, seed=seed), a


def _assigned(spec: Spec, students: Sequence[Student], paper: str, lang: str,
              seed: int | str | None) -> Assignment:
    """Every student's variants, after checking ``paper`` and ``lang``."""
    if paper not in PAPERS:
        raise ValueError(f"paper must be one of {', '.join(PAPERS)}, got {paper!r}")
    if lang not in LANGS:
        raise ValueError(f"lang must be one of {', '.join(LANGS)}, got {lang!r}")
    return assign(spec, students, PAPERS[paper], seed)


__all__ = ["LANGS", "Worksheet", "key_and_assignment", "make_key", "make_worksheet"]
