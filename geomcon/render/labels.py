"""Texts: point labels as textbooks print them (C1 → C with subscript 1), subscripts in captions, width
estimates and line wrapping (CJK characters are about 1 em wide, Latin ones about half).

Examples
--------
>>> label_runs("C1")
(('C', False), ('1', True))
>>> label_runs("B′′")
(('B′′', False),)
>>> rich_runs("Join AC2, γmin")
(('Join AC', False), ('2', True), (', γ', False), ('min', True))
>>> rich_runs("α′max, ρa,min")
(('α′', False), ('max', True), (', ρ', False), ('a,min', True))
>>> rich_runs("vmax, rr,max, r0,ρ, ω2,max, φslow")
(('v', False), ('max', True), (', r', False), ('r,max', True), (', r', False), ('0,ρ', True), (', ω', False), ('2,max', True), (', φ', False), ('slow', True))
>>> rich_runs("sin αallow, ρallow = 40, allowance")
(('sin α', False), ('allow', True), (', ρ', False), ('allow', True), (' = 40, allowance', False))
>>> rich_runs("the rise's α_max, B_iK_i")
(("the rise's α", False), ('max', True), (', B', False), ('i', True), ('K', False), ('i', True))
>>> wrap("one two three", 8 * 2.7 * 0.55, 2.7)
['one two', 'three']
"""
from __future__ import annotations

import functools
import re
from itertools import accumulate, chain

from .minus import minus_signs
from .zh_words import is_ideograph, words

Runs = tuple[tuple[str, bool], ...]

_LABEL = re.compile(r"^([^\d]+?)(\d+(?:,\d+)*)([′″‴'*]*)$")
_SUB = re.compile(r"(?=[A-Za-z_\d])(?<=[A-Za-zα-ωΑ-Ω′ⁿᵗʳᵏ])(?:(?<![a-z][a-z])|(?=_))(?:"     # cheap tests first
                  r"(?<=(?<![A-Za-z0-9])[valr])(?:min|max)\b|(?<=(?<![A-Za-z0-9])r)(?:r,max|0,[αρ])(?![A-Za-z])"
                  r"|(?<=[α-ω])\d+,(?:min|max)\b|(?<=[α-ω])max,turn\b|(?<=φ)(?:slow|quick)\b"
                  r"|(?<=(?<![A-Za-z0-9])s)E\d+(?![\d.])|(?<=(?<![A-Za-z0-9])F)[fn](?![A-Za-z])"
                  r"|(?<=(?<![A-Za-z0-9])[xy])[pa](?![A-Za-z])|(?<=(?<![A-Za-z0-9])l)face\b"
                  r"|(?<=(?<![A-Za-z0-9])[valn])[A-Z][A-Z0-9]*|(?<=(?<![A-Za-z0-9])[va][ⁿᵗʳᵏ])[A-Z][A-Z0-9]*"
                  r"|(?<=μ)[val](?![A-Za-z])|(?<=(?<![A-Za-z_])[a-z])\d+(?![\d.])|(?<=[A-Z])d\d+(?![\d.])"
                  r"|(?<=[A-Z])\d+,\d+(?![\d.,])|(?<=[A-Zα-ωΑ-Ω′])(\d+)(?![\d.])|(?<=[α-ω])(min|max|allow|[a-z],min|[a-z],max)\b|(?<=[α-ω]′)(?:min|max)\b"
                  r"|(?<=[A-Zα-ω])i(?![a-z])"
                  r"|(?<=[A-Za-zα-ωΑ-Ω′])_([a-z0-9]+))")
"""What a caption prints as a subscript: a follower's or a roller's bound (vmax, amax, lmin, rr,max: the comma
inside the subscript), a base circle of one limit (r0,α, r0,ρ), an arm's bound (ω2,max), the crank angles of the
two strokes (φslow, φquick), a pin's place (sE1), friction and normal forces (Ff, Fn), a pitch and an actual
profile's coordinates (xp, ya), a flat face's length (lface); digits after a capital or Greek letter (C1, γ1), min/max after a Greek
letter, a prime between or a profile's letter before included (γmin, α′max, ρa,min), an allowed bound (αallow,
ρallow), a lone i after one (Ci, ψi), and a name written with an underscore (α_max, φ_quick, B_i: the
underscore dropped, as the textbook prints αmax), the points after a velocity, acceleration, length or
polygon normal's letter (vC, aCBᵗ, aʳB2B3, lAB, nB: v with subscript C …), a scale's letter (μv, μa, μl), the
digits after a lone small letter (r0, s0, i13, the polygon points b2, n3 as the figure labels them) and a dead
point's d1 (Cd1: C with subscript d1). Each alternative begins with a Latin letter, a digit (\\d) or the
underscore, right after a letter (Latin or Greek), a prime or a modifier letter, and none but the underscore's
begins inside a word after two small Latin letters ("construction"): the tests in front reject every other
position (a space, a sign, a CJK character, a word's third letter) before the alternatives are tried, with the
same matches (the gallery's 8 354 texts and a million random ones): 2.5 times as fast over the gallery's texts."""
_CODE = re.compile(r"\S*\.[A-Za-z]\S*")
"""A word that is code (a file or recipe name, ``cam_psi0.toml``, ``cam.base_radius``): printed as it is."""
_DOT_LETTER = re.compile(r"\.[A-Za-z]")
"""What every match of :data:`_CODE` holds: a text without it has no code, found without :data:`_CODE`'s search
(which tries every start of every word: a sixth of :func:`rich_runs`' time, most of it on step numbers "12. ")."""


_POINTS = re.compile(r"^([valn](?=[A-Z])|[A-Z](?=d\d))([A-Z][A-Z0-9]*|d\d+)([′″‴'*]*)$")
"""A polygon point named after the points it belongs to (nB: the end of B's normal acceleration, n with
subscript B) and a dead point (Cd1: C with subscript d1)."""


_FORCE = re.compile(r"^F[fn]$")
"""A force's label: friction Ff, normal force Fn (F with subscript f, n)."""


def label_runs(label: str) -> Runs:
    """Runs of a point label: letters, then trailing digits as a subscript, then primes; ``"D (D1)"`` (a
    result drawn on the candidate it was chosen from) as both labels.

    >>> label_runs("K2*")
    (('K', False), ('2', True), ('*', False))
    >>> label_runs("nB"), label_runs("Cd1")
    ((('n', False), ('B', True)), (('C', False), ('d1', True)))
    >>> label_runs("C2,3"), label_runs("Ff")
    ((('C', False), ('2,3', True)), (('F', False), ('f', True)))
    >>> label_runs("D (D1)")
    (('D', False), (' (', False), ('D', False), ('1', True), (')', False))
    """
    if label.endswith(")") and " (" in label:
        head, tail = label[:-1].split(" (", 1)
        return label_runs(head) + ((" (", False),) + label_runs(tail) + ((")", False),)
    m = _POINTS.match(label) or _LABEL.match(label)
    if not m:
        return rich_runs(label) if _FORCE.match(label) else ((label, False),)
    out = [(m.group(1), False), (m.group(2), True)]
    if m.group(3):
        out.append((m.group(3), False))
    return tuple(out)


@functools.lru_cache(maxsize=8192)
def rich_runs(text: str) -> Runs:
    """Runs of a caption: digits right after a capital or Greek letter (C1, AB2, γ1), min/max after a Greek
    letter (γmin), a lone i (Ci) and an underscored name (α_max, without its underscore) become subscripts;
    file and recipe names (:data:`_CODE`) are left as they are. Remembered (runs are tuples): two of three
    lines a gallery writes were written before (step numbers, headings, the same caption in another figure).

    >>> rich_runs("C2 = C2,3 (C1 folded)")[:4]          # a candidate's two indices, as its label prints them
    (('C', False), ('2', True), (' = C', False), ('2,3', True))
    >>> rich_runs("φ_slow/φ_quick in 000-04_slotter_cam_psi0.toml")
    (('φ', False), ('slow', True), ('/φ', False), ('quick', True), (' in 000-04_slotter_cam_psi0.toml', False))
    """
    out: list[tuple[str, bool]] = []
    pos = 0
    code = [m.span() for m in _CODE.finditer(text)] if "." in text and _DOT_LETTER.search(text) else None
    for m in _SUB.finditer(text):
        start = m.start()
        if code and any(a <= start < b for a, b in code):
            continue
        if start > pos:
            out.append((text[pos:start], False))
        name = m.group(3)                      # an underscored name, without its underscore
        out.append((m.group(0) if name is None else name, True))
        pos = m.end()
    if pos < len(text):
        out.append((text[pos:], False))
    return tuple(out)


def subscript_commas(text: str) -> frozenset[int]:
    """Where ``text`` holds a comma inside a subscript, as :func:`rich_runs` prints it (ω2,max, ρa,min, rr,max,
    αmax,turn, r0,ρ, a candidate's C2,3): no punctuation, kept ASCII in a Chinese text
    (:func:`geomcon.render.zh.zh_punct`), one rule with the typesetting's.

    >>> sorted(subscript_commas("ω2,max, r0,ρ 与 C2,4")), subscript_commas("B1, B2")
    ([2, 10, 17], frozenset())
    """
    if "," not in text:
        return frozenset()
    return frozenset(i for m in _SUB.finditer(text) if "," in m.group(0)
                     for i in range(m.start(), m.end()) if text[i] == ",")


def plain_text(text: str) -> str:
    """A caption as plain text (a terminal's): its runs joined, subscripts inline as the Results lines print
    them (``γmin``).

    >>> plain_text("α′_max of the return = 36.71° exceeds α_allow = 30°")
    'α′max of the return = 36.71° exceeds αallow = 30°'
    """
    return "".join(s for s, _ in rich_runs(text))


def char_em(ch: str) -> float:
    """Estimated advance of one character in em (Noto Sans CJK / DejaVu Sans metrics, rounded up)."""
    o = ord(ch)
    if 0x2E80 <= o <= 0x9FFF or 0xF900 <= o <= 0xFAFF or 0xFF00 <= o <= 0xFFEF or 0x3000 <= o <= 0x303F:
        return 1.0
    if ch == " ":
        return 0.26
    if ch in "ilj.,:;'|!′″()[]":
        return 0.3
    if ch in "mwMW":
        return 0.85
    if ch.isupper():
        return 0.66
    if ch.isdigit():
        return 0.56
    if ch in "−+=<>×÷→≤≥°":
        return 0.6
    return 0.54


def label_extent(runs: Runs, size: float) -> tuple[float, float]:
    """Width and height (paper mm) of the box a point's label of ``runs`` at font ``size`` is placed in, as it
    prints: its width and 0.15 mm each side; 0.74 of the size high, 0.95 with a subscript (which hangs below the
    baseline). A label naming several points ("B2, C4": :mod:`.coincident`) is measured by its printed parts'
    runs, not as the plain text: measured so, 004-02's ", C4" hung 0.76 mm below its box onto B2's pin.

    >>> [round(v, 3) for v in label_extent(label_runs("C1"), 3.6)]
    [4.128, 3.42]
    >>> [round(v, 3) for v in label_extent(label_runs("B2") + ((", ", False),) + label_runs("C4"), 3.6)]
    [9.971, 3.42]
    >>> [round(v, 3) for v in label_extent(label_runs("B2, C4"), 3.6)]      # the plain text: too wide, too low
    [11.1, 2.664]
    """
    sub = any(s for t, s in runs if t)
    return text_width(runs, size) + 0.3, size * (0.95 if sub else 0.74)


def text_width(text: str | Runs, size: float) -> float:
    """Estimated width (paper mm) of a text or of runs (subscripts at 72 %) at font ``size``: the sum, in
    order, of each character's ``char_em(ch) * size * (0.72 if sub else 1.0)``.

    >>> text_width("C1", 3.0) == 0.66 * 3.0 * 1.0 + 0.56 * 3.0 * 1.0
    True
    """
    if isinstance(text, str):
        return sum(_advances(text, size, False))
    if len(text) == 1:
        return sum(_advances(text[0][0], size, text[0][1]))
    return sum(chain.from_iterable(_advances(s, size, sub) for s, sub in text))


def _advances(s: str, size: float, sub: bool) -> list[float]:
    """Each character's term of :func:`text_width`, from a table by (size, subscript): each glyph's advance is
    computed once (:func:`char_em`), then looked up. A negative number's hyphen is measured as the minus sign
    the sheet prints (:func:`~.serial.minus_signs`: as wide as "+")."""
    if "-" in s:
        s = minus_signs(s)
    table = _ADVANCES.get((size, sub))
    if table is None:
        table = _ADVANCES[size, sub] = {}
    try:
        return list(map(table.__getitem__, s))
    except KeyError:
        for ch in s:
            if ch not in table:
                table[ch] = char_em(ch) * size * (0.72 if sub else 1.0)
        return list(map(table.__getitem__, s))


_ADVANCES: dict[tuple[float, bool], dict[str, float]] = {}
"""Each character's advance term of :func:`text_width`, by (size, subscript), as computed there."""


def _wide(ch: str) -> bool:
    """Whether a character is a CJK one (1 em wide)."""
    out = _WIDE.get(ch)
    if out is None:
        out = _WIDE[ch] = char_em(ch) == 1.0
    return out


_WIDE: dict[str, bool] = {}


def _tokens(s: str) -> list[str]:
    """Breakable pieces: Latin words with their trailing space, Chinese words (:func:`.zh_words.words`: a line
    breaks between words, never inside one), single other CJK characters; closing punctuation stays with the
    piece before it, opening punctuation with the piece after it; a unit with its number and a bracket's short
    first word with the word after it (:func:`_glued`).

    >>> _tokens("以 A 为圆心作曲柄圆（半径 AB），交于 C1")
    ['以 ', 'A ', '为', '圆心', '作', '曲柄', '圆', '（半径 AB），', '交', '于 ', 'C1']
    """
    if _ANY_WIDE.search(s) is None:                 # Latin only: words with their trailing space
        parts = s.split(" ")
        out = [p + " " for p in parts[:-1]]
        if parts[-1]:
            out.append(parts[-1])
        return _glued(out)
    out = []
    word = ""
    for m in _PIECES.finditer(s):             # as the units of _units(s), but a run of Latin ones at once
        kind = m.lastindex
        if kind == 1:                                   # Chinese words
            for unit in words(m.group(1)):
                if word and word[-1] not in _OPENING:   # an opening mark stays with the character after it
                    out.append(word)
                    word = ""
                word += unit
        elif kind == 2:                                 # another CJK character
            unit = m.group(2)
            if unit not in _CLOSING and word and word[-1] not in _OPENING:
                out.append(word)
                word = ""
            word += unit
        elif kind == 3:
            out.append(word + " ")
            word = ""
        else:                                   # Latin: only its first character may start a new piece
            run = m.group(4)
            if word and word[-1] not in _CLOSING_OPENING and _wide(word[-1]) and run[0] not in _CLOSING:
                out.append(word)
                word = ""
            word += run
    if word:
        out.append(word)
    return _glued(out)


_HAN = re.compile("([\u3400-\u9fff\uf900-\ufaff]+)|[^\u3400-\u9fff\uf900-\ufaff]+")
"""A run of Chinese ideographs (group 1), or a run of other characters."""
_ANY_WIDE = re.compile("[\u2e80-\u9fff\uf900-\ufaff\uff00-\uffef]")
"""A CJK character (:func:`_wide`: 1 em wide)."""
_PIECES = re.compile("([\u3400-\u9fff\uf900-\ufaff]+)|([\u2e80-\u9fff\uf900-\ufaff\uff00-\uffef])|( )"
                     "|([^ \u2e80-\u9fff\uf900-\ufaff\uff00-\uffef]+)")
"""What :func:`_tokens` takes one at a time: a run of Chinese ideographs (group 1, cut into words), another CJK
character (group 2), a space (group 3), a run of other characters (group 4: within it no piece begins)."""


def _units(s: str) -> list[str]:
    """The characters of ``s``, but each run of Chinese ideographs cut into its words (:func:`.zh_words.words`).

    >>> _units("取曲柄长 AB")
    ['取', '曲柄', '长', ' ', 'A', 'B']
    """
    out: list[str] = []
    for m in _HAN.finditer(s):
        out += words(m.group()) if m.group(1) else m.group()
    return out


_OPERATORS = frozenset("=+−×÷≤≥<>≈≠") | {"-", "/"}
"""Operators set between spaces: one never starts or ends a line ("δ = 5°", "K + 1" stay together)."""
_FUNCTION_END = re.compile(r"(?<![A-Za-z])(?:arc)?(?:cos|sin|tan|cot) $")
"""A token ending in a function's name: it stays with its argument ("cos α", 001-06b's Chinese step 32 broke as
"…：cos" / "α = √(g(2BC − g))/BC")."""


def _glued(tokens: list[str]) -> list[str]:
    """``tokens`` with every operator token (``"= "``, ``"+ "``, ``"− "`` …) joined to the tokens either side,
    the token after 第 joined to it (an ordinal: 第 2 张), every token that begins with a mark no line may begin
    with (closing punctuation, an ellipsis, a per cent sign: :data:`_NO_START`) or that is a unit after a number
    (``450 mm``, ``2 mm/mm``: :data:`_UNITS`) joined to the token before it, even across a space, a bracket's
    short first word joined to the word after it and a one-character last one to the word before it
    (:func:`_opens_short`, :func:`_closes_short`: no line ends in "(at" or "（即", none begins with "处）").

    >>> _glued(["(at ", "δ ", "= ", "5°)"])
    ['(at δ = 5°)']
    >>> _glued(["1, ", "2, ", "…", "（即"]), _glued(["0.00 ", "%）"])
    (['1, ', '2, …', '（即'], ['0.00 %）'])
    >>> _glued(["360° ", "= ", "450 ", "mm ", "(on ", "sheet ", "2)"]), _glued(["（δ = 5° ", "处）"])
    (['360° = 450 mm ', '(on sheet ', '2)'], ['（δ = 5° 处）'])
    >>> _glued(["见", "第 ", "2 ", "张）"])                   # an ordinal stays with its number
    ['见', '第 2 张）']
    >>> _glued(["最大）：cos ", "α ", "= ", "1"]), _glued(["across ", "α"])     # a function with its argument
    (['最大）：cos α = 1'], ['across ', 'α'])
    """
    out: list[str] = []
    glue = False
    for t in tokens:
        if out and len(t) < 3 and t.strip() in _OPERATORS:             # "= ", "− ": an operator and its space
            out[-1] += t
            glue = True
        elif glue or (out and (t[:1] in _NO_START                  # each test behind a test of one character
                               or (out[-1][-2:] in _FUNCTION_TAILS and _FUNCTION_END.search(out[-1]))
                               or (not _OPEN_SET.isdisjoint(out[-1]) and _opens_short(out[-1]))
                               or ("）" in t and _closes_short(t))
                               or (not _CLOSE_SET.isdisjoint(t) and _closes_pair(out[-1], t))
                               or (t[:1] in _UNIT_START and _unit_after_number(out[-1], t))
                               or ("第" in out[-1] and out[-1].rstrip().endswith("第")))):
            out[-1] += t
            glue = False
        else:
            out.append(t)
    return out


_UNITS = frozenset(("mm", "cm", "m", "mm/mm", "mm/s", "mm/s²", "m/s", "m/s²", "rad", "rad/s", "rad/s²", "rpm",
                    "r/min", "(mm/s)/mm", "(mm/s²)/mm", "°", "%", "‰", "张"))
"""Units a number is printed with: a line never breaks between the number and its unit ("360° = 450 mm",
"μl = 2 mm/mm", "vB = 500 mm/s", a sheet's count "第 2 张")."""
_UNIT_START = frozenset(u[0] for u in _UNITS)
"""The first characters of the units: a token beginning otherwise is no unit."""
_TRAIL = " ,;:.)]）］，；：。、"
"""What may follow a word inside its token: a space, closing punctuation."""


def _unit_after_number(before: str, tok: str) -> bool:
    """Whether ``tok`` is a unit (:data:`_UNITS`, punctuation after it allowed) and ``before`` ends in a digit.

    >>> _unit_after_number("450 ", "mm（画"), _unit_after_number("= 2 ", "mm/mm"), _unit_after_number("AB ", "mm")
    (True, True, False)
    """
    body = before.rstrip()
    if not body or not body[-1].isdigit():
        return False
    word = tok.split("（", 1)[0].split("(", 1)[0] if not tok.startswith("(") else tok.split(" ", 1)[0]
    return word.rstrip(_TRAIL) in _UNITS


_FUNCTION_TAILS = frozenset(("s ", "n ", "t "))
"""The last two characters of a token :data:`_FUNCTION_END` may match (a cheap test first)."""
_OPEN_ANY = "([（［【「『《“‘"
_OPEN_SET = frozenset(_OPEN_ANY)
_CLOSE_ANY = ")]）］】」』》”’"
_CLOSE_SET = frozenset(_CLOSE_ANY)


def _opens_short(tok: str) -> bool:
    """Whether ``tok`` ends inside a bracket it opens, after at most a short first word (:func:`_short`): an
    opening mark alone, "(at", "(the", "(C1", "[190,", "（即", "（位于". Such a token keeps the word after it on its
    line.

    >>> [_opens_short(t) for t in ("(at ", "(the ", "[190, ", "（位于", "(intersection ", "（位于有向", "(a)", "A (")]
    [True, True, True, True, False, False, False, True]
    """
    i = max(map(tok.rfind, _OPEN_ANY))
    if i < 0:
        return False
    inner = tok[i + 1:]
    return not any(c in _CLOSE_ANY for c in inner) and _short(inner)


def _closes_short(tok: str) -> bool:
    """Whether ``tok`` closes a bracket opened before it after a single Chinese character ("处）", "画）"): such a
    token stays on the line of the word before it. (A longer last word may begin a line, and so may a Latin one,
    "B″), else": kept with the words before it, it pushed a protocol's step to a sheet of its own.)

    >>> [_closes_short(t) for t in ("处）；", "左侧）", "2) ", "（处）", "处")]
    [True, False, False, False, False]
    """
    j = tok.find("）")
    return j == 1 and is_ideograph(tok[0])


def _closes_pair(before: str, tok: str) -> bool:
    """Whether ``tok`` closes, with its first word, a bracket of two Latin words that ``before`` opens with the
    first ("(closed " + "form) = 29.995°", "(= " + "analytic)"): the two stay on one line, as no line may begin
    with a bracket's closing word when its opening one ends the line before (400-05's "(=" / "analytic)"; Chinese
    brackets keep their own rules, :func:`_opens_short`, :func:`_closes_short`).

    >>> [_closes_pair(b, t) for b, t in (("(closed ", "form) "), ("A (", "B)"), ("(a b ", "c)"), ("(x) ", "y)"))]
    [True, True, False, False]
    """
    j = min((i for i in map(tok.find, _CLOSE_ANY) if i >= 0), default=-1)
    if j <= 0 or " " in tok[:j] or any(c in _OPEN_SET for c in tok[:j]) or _ANY_WIDE.search(tok[:j]):
        return False
    i = max(map(before.rfind, _OPEN_ANY))
    inner = before[i + 1:].strip()
    return i >= 0 and not any(c in _CLOSE_ANY for c in inner) and " " not in inner and not _ANY_WIDE.search(inner)


def _short(inner: str) -> bool:
    """Whether the text inside a bracket next to its mark is at most a short word: nothing, a Latin word of at most
    4 characters, or one Chinese word (:func:`.zh_words.words`).

    >>> [_short(s) for s in ("", "at ", "190, ", "位于", "位于有向", "the end", "long word")]
    [True, True, True, True, False, False, False]
    """
    inner = inner.strip().rstrip(_TRAIL)
    if " " in inner:
        return False
    han = [m.group() for m in _HAN.finditer(inner) if m.group(1)]
    if han:
        return len(han) == 1 and han[0] == inner and len(words(inner)) <= 1
    return len(inner) <= 4


_OPENING = "（「『《【“‘"
"""Punctuation that never ends a line: it stays with the character after it."""
_CLOSING = "，。、；：）」』！？》】”’…,;:)!?"
"""Punctuation that never begins a line: it stays with the character before it (full-width forms, which Chinese
text uses, the ellipsis, and their ASCII twins)."""
_CLOSING_OPENING = _CLOSING + _OPENING
_NO_START = _CLOSING + "%‰"
"""What never begins a line, even after a space: closing punctuation and the per cent signs ("0.00 %）")."""


def wrap(text: str, width: float, size: float, last_reserve: float = 0.0) -> list[str]:
    """Split ``text`` into lines no wider than ``width`` (estimated, paper mm at font ``size``).

    Latin text breaks at spaces, but not beside an operator set between spaces (``=``, ``+``, ``−`` …), Chinese text
    between words (:mod:`.zh_words`), other CJK text between characters, but not after an opening mark nor before a
    closing one, nor after a bracket's short first word ("(at"), nor before a one-character last one ("处）"),
    nor between a number and its unit ("450 mm": :func:`_glued`). ``last_reserve`` keeps room at the end of the
    last line (for a value appended later).

    Examples
    --------
    >>> wrap("以 A 为圆心、BC − AB = 20 为半径作圆", 20.0, 2.4)      # a formula is not broken at its operators, nor 圆心
    ['以 A 为', '圆心、BC − AB = 20', '为半径作圆']
    >>> wrap("速度突降，刚性冲击）", 21.6, 2.4)        # a closing mark never starts a line
    ['速度突降，刚性', '冲击）']
    >>> wrap("超过许用值 45°（δ = 5.000° 处）", 28.0, 3.5)      # nor the bracket's one-character last word
    ['超过许用值 45°', '（δ = 5.000° 处）']
    >>> wrap("With K = 1.2: θ = 180°(K − 1)/(K + 1)", 60.0, 3.5, last_reserve=20.0)    # room for " = 16.364°"
    ['With K = 1.2:', 'θ = 180°(K − 1)/(K + 1)']
    >>> wrap("运动失真（根切）：否", 12.0, 2.4)         # an opening mark never ends one
    ['运动失真', '（根切）：', '否']
    >>> wrap("以 A 为圆心、曲柄长为半径作圆", 16.0, 2.4)      # nor a word: 曲柄 stays whole
    ['以 A 为圆心、', '曲柄长为半径', '作圆']
    """
    return list(_wrap(text, width, size, last_reserve))


@functools.lru_cache(maxsize=16384)
def _wrap(text: str, width: float, size: float, last_reserve: float) -> tuple[str, ...]:
    """:func:`wrap`, remembered: every frame of a replay wraps the same captions, and a sheet's layout measures
    the same result lines at each width it tries (a gallery wraps about 8000 distinct texts and widths, each
    once). A line takes tokens while their full-size widths (:func:`_measured`) fit; only a token that may
    overflow is measured exactly, with the line's subscripts."""
    lines: list[str] = []
    cur = ""
    full = 0.0          # the width of cur with every character full size: at least its width
    for tok, body, w_tok, w_body, head, w_head in _measured(text, size):
        if (cur.strip() and full + w_body > width - 1e-6
                and text_width(rich_runs(cur + body), size) > width):
            lines.append(cur.rstrip())
            cur = head
            full = w_head
        else:
            cur += tok
            full += w_tok
    lines.append(cur.rstrip())
    if last_reserve and len(lines[-1]) and text_width(rich_runs(lines[-1]), size) + last_reserve > width:
        toks = _tokens(lines[-1])                 # its last word (a formula whole) goes to a line of its own
        if len(toks) >= 2 and "".join(toks[:-1]).strip():
            lines[-1:] = ["".join(toks[:-1]).rstrip(), toks[-1]]
        else:
            lines.append("")
    return tuple(lines)


@functools.lru_cache(maxsize=8192)
def _measured(text: str, size: float) -> tuple[tuple[str, str, float, float, str, float], ...]:
    """The tokens of ``text`` (:func:`_tokens`), each with what :func:`_wrap` needs of it, measured once for all
    widths: (token, token without trailing space, their full-size widths, token without leading space, its
    width). A width is a difference of the running sums of :func:`_advances` (one pass over the text, not three
    sums a token): it differs from the sum of the token's advances in the last bits only, far within the 1e-6 mm
    by which :func:`_wrap` lets these widths pass a token without measuring it exactly.

    >>> [m[:2] for m in _measured("one two", 2.7)]
    [('one ', 'one'), ('two', 'two')]
    """
    cum = [0.0, *accumulate(_advances(text, size, False))]    # "".join(_tokens(text)) == text
    out, at = [], 0
    for tok in _tokens(text):
        end = at + len(tok)
        start, stop = cum[at], cum[end]
        if tok[-1:] == " " and not tok[-2:-1].isspace():         # a word and its space: rstrip() drops one
            body, w_body = tok[:-1], cum[end - 1] - start
        else:
            body = tok.rstrip()
            w_body = cum[at + len(body)] - start
        if tok[:1].isspace():
            head = tok.lstrip()
            w_head = stop - cum[end - len(head)]
        else:
            head, w_head = tok, stop - start
        out.append((tok, body, stop - start, w_body, head, w_head))
        at = end
    return tuple(out)
