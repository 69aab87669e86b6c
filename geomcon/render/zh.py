"""Chinese text with full-width punctuation (no dependencies: the text summary of a solve uses it without loading
the drawing code).

Examples
--------
>>> zh_punct("曲柄 AB = 50 mm,求极位夹角(用作图法)?")
'曲柄 AB = 50 mm，求极位夹角（用作图法）？'
"""
from __future__ import annotations

import functools
import re

from .labels import subscript_commas


def _cjk(ch: str) -> bool:
    o = ord(ch)
    return 0x2E80 <= o <= 0x9FFF or 0xF900 <= o <= 0xFAFF or 0x3000 <= o <= 0x303F or 0xFF00 <= o <= 0xFFEF




_FULL = {",": "，", ";": "；", ":": "：", "(": "（", ")": "）", "?": "？", "!": "！"}


@functools.lru_cache(maxsize=4096)
def zh_punct(s: str) -> str:
    """Chinese text with full-width punctuation: a comma, semicolon, colon, question or exclamation mark next to
    a Chinese character becomes ，；：？！ (in a text holding Chinese, a comma, semicolon or colon followed by
    neither a space nor a digit too: ``s–δ:δ 轴``), brackets around Chinese text or opened right after a
    Chinese ideograph （）; a formula keeps its ASCII signs (``K = (180° + θ)/(180° − θ)``, ``1:2``, ``[1, 2]``), a subscript its comma
    (``ω2,max``, a candidate's ``C2,4``: where :func:`.labels.rich_runs` sets it in a subscript,
    :func:`.labels.subscript_commas`; hlook11m: 001-31b printed "ω2，max：取 ε2 = 0 处").
    Remembered: a caption is set in the protocol, the step captions and the player, in every layout tried.

    >>> zh_punct("在机架线上取 D,使 AD = 90")
    '在机架线上取 D，使 AD = 90'
    >>> zh_punct("交摇杆圆于 C1(位于直线 AD 上方的交点); K = (180° + θ)/(180° − θ)")
    '交摇杆圆于 C1（位于直线 AD 上方的交点）；K = (180° + θ)/(180° − θ)'
    >>> zh_punct("验证 AB 为曲柄(AC > AB + e),何时不能成为机构?位移线图 s–δ:δ 轴,比例 1:2")
    '验证 AB 为曲柄（AC > AB + e），何时不能成为机构？位移线图 s–δ：δ 轴，比例 1:2'
    >>> zh_punct("曲柄销 B1(重叠共线)与 B2(拉直共线),AB = (AC远 − AC近)/2")
    '曲柄销 B1（重叠共线）与 B2（拉直共线），AB = (AC远 − AC近)/2'
    >>> zh_punct("ω2,max:取 ε2 = 0 处;ρa,min,rr,max 与 r0,ρ")         # a subscript's comma is no punctuation
    'ω2,max：取 ε2 = 0 处；ρa,min，rr,max 与 r0,ρ'
    >>> zh_punct("取 C2,4 为解,B1,B2 为铰链")        # a candidate's two indices too (C2,4 as its label prints)
    '取 C2,4 为解，B1，B2 为铰链'
    """
    out = list(s)
    stack: list[int] = []
    chinese = any(_cjk(c) for c in s)
    keep = subscript_commas(s)
    for i, ch in enumerate(s):
        if ch == "(":
            stack.append(i)
        elif ch == ")" and stack:
            j = stack.pop()
            formula = s[i + 1:i + 2] == "/" or s[:j].rstrip().endswith("=")   # a term of a formula: (AC远 − AC近)/2
            if not formula and (any(_cjk(c) for c in s[j + 1:i]) or (j > 0 and "\u4e00" <= s[j - 1] <= "\u9fff")):
                out[j], out[i] = _FULL["("], _FULL[")"]
        elif ch in ",;:?!":
            if ch == "," and i in keep:
                continue
            before = "".join(out[:i]).rstrip()[-1:]
            after = s[i + 1:].lstrip()[:1]
            nxt = s[i + 1:i + 2]
            if ((before and _cjk(before)) or (after and _cjk(after) and ch not in "?!")
                    or (chinese and ch in ",;:" and nxt and not nxt.isspace() and not nxt.isdigit())):
                out[i] = _FULL[ch]
    text = "".join(out)
    for full in "，；：？！":
        text = text.replace(full + " ", full)
    return text


def zh_brackets(s: str) -> str:
    """An English text with Chinese glosses: ASCII brackets around Chinese text become full-width （）, nothing
    else changes (a formula's brackets, English punctuation) but the spaces around them (a full-width bracket
    carries its own).

    >>> zh_brackets("impacts: soft (柔性冲击) at 0°, 120° (f(x) = 1)")
    'impacts: soft（柔性冲击）at 0°, 120° (f(x) = 1)'
    """
    out = list(s)
    stack: list[int] = []
    for i, ch in enumerate(s):
        if ch == "(":
            stack.append(i)
        elif ch == ")" and stack:
            j = stack.pop()
            if any(_cjk(c) for c in s[j + 1:i]):
                out[j], out[i] = "（", "）"
    return re.sub(r" ?（", "（", re.sub(r"） ?", "）", "".join(out)))


def _last_bracket(text: str) -> str | None:
    """What the bracket that closes ``text`` holds (``None`` when ``text`` does not end in one)."""
    if not text.endswith((")", "）")):
        return None
    depth = 0
    for i in range(len(text) - 1, -1, -1):
        depth += (text[i] in ")）") - (text[i] in "(（")
        if depth == 0:
            return text[i + 1:-1]
    return None


def zh_remark(zh: str, remark: str) -> str:
    """A Chinese caption with a remark (its branch rule) added: inside the caption's closing bracket remark when
    there is one (``交摇杆圆于 C1(曲柄与连杆重叠共线;位于直线 AD 上方的交点)``, not two brackets in a row), else
    in its own brackets. A closing bracket of a formula (no ideograph inside) is left alone.

    >>> zh_remark("交摇杆圆于 C1(曲柄与连杆重叠共线)", "位于直线 AD 上方的交点")
    '交摇杆圆于 C1(曲柄与连杆重叠共线;位于直线 AD 上方的交点)'
    >>> zh_remark("K = (180° + θ)/(180° − θ)", "较近的交点"), zh_remark("两线交于 P", "较近的交点")
    ('K = (180° + θ)/(180° − θ)(较近的交点)', '两线交于 P(较近的交点)')
    """
    inside = _last_bracket(zh)
    if inside is not None and any("\u4e00" <= c <= "\u9fff" for c in inside):
        return f"{zh[:-1]};{remark}{zh[-1]}"
    return f"{zh}({remark})"


def en_remark(en: str, remark: str) -> str:
    """An English caption with a remark (its branch rule, the sheet its diagram is on) added, the twin of
    :func:`zh_remark`: inside the caption's closing bracket remark when there is one (``(the arm's directions;
    diagram on sheet 2)``, not ``(the arm's directions) (diagram on sheet 2)``), else in its own brackets after a
    space. A closing bracket of a formula (no word of three letters inside: ``(A0′P = a/(1 − εψ′))``) is left alone.

    >>> en_remark("Draw the arm (the arm's directions)", "diagram on sheet 2")
    "Draw the arm (the arm's directions; diagram on sheet 2)"
    >>> en_remark("on OA0′ (A0′P = a/(1 − εψ′))", "nearer"), en_remark("They meet at P", "the nearer")
    ('on OA0′ (A0′P = a/(1 − εψ′)) (nearer)', 'They meet at P (the nearer)')
    """
    inside = _last_bracket(en)
    if inside is not None and re.search(r"[A-Za-z]{3}", inside):
        return f"{en[:-1]}; {remark}{en[-1]}"
    return f"{en} ({remark})"


__all__ = ["en_remark", "zh_brackets", "zh_punct", "zh_remark"]
