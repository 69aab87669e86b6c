"""A student's feedback, ``feedback/<id>.txt``, in the sheet's language (``en``, ``zh`` or both): the score,
what was right, what was wrong with the likely mistake in words, what was blank or unreadable.

A file name is the id made safe for any file system (letters, digits, ``-``, ``_``, ``.``, CJK kept; anything
else ``_``; a name that would repeat another gets ``~2``, ``~3``…).

Examples
--------
>>> file_names(["2023001", "a/b", "a_b", ".."])
['2023001.txt', 'a_b.txt', 'a_b~2.txt', '_...txt']
"""
from __future__ import annotations

import re

from ..problems import title_in
from .credit import GradedRow
from .tables import num

_SAFE = re.compile(r"[^0-9A-Za-z_\-.\u4e00-\u9fff]")
_WORDS = {
    "en": {"score": "Score", "right": "Right", "wrong": "Wrong", "blank": "Not answered", "unreadable": "Could not be read",
           "expected": "expected", "yours": "yours", "likely": "likely mistake", "row": "Your row could not be graded"},
    "zh": {"score": "得分", "right": "正确", "wrong": "错误", "blank": "未作答", "unreadable": "无法识别",
           "expected": "正确值", "yours": "你的答案", "likely": "可能的错误", "row": "此行无法评分"},
}


def file_names(ids: list[str]) -> list[str]:
    """A safe, distinct file name per id (see the module)."""
    out, seen = [], set()
    for i in ids:
        base = _SAFE.sub("_", i)[:64] or "_"
        if base.startswith("."):
            base = "_" + base
        name, k = base, 1
        while name.lower() in seen:
            k += 1
            name = f"{base}~{k}"
        seen.add(name.lower())
        out.append(name + ".txt")
    return out


def _one(r: GradedRow, title: str, lang: str) -> str:
    w = _WORDS[lang]
    lines = [title, f"{r.id} {r.name}".strip(), f"{w['score']}: {num(r.score)} / {num(r.max_score)}", ""]
    if r.problem:
        return "\n".join(lines + [f"{w['row']}: {r.problem}", ""])
    for verdict in ("correct", "wrong", "blank", "unreadable"):
        gs = [g for g in r.answers if g.verdict == verdict]
        if not gs:
            continue
        lines.append(w["right" if verdict == "correct" else verdict] + ":")
        for g in gs:
            if verdict == "correct":
                lines.append(f"  {g.column} = {num(g.value)} (±{num(g.tol)})")
            elif verdict == "wrong":
                why = g.zh if lang == "zh" else g.en
                pts = f" [{num(g.points)}/{num(g.max_points)}]" if g.points else ""
                lines.append(f"  {g.column}: {w['yours']} {num(g.value)}, {w['expected']} {num(g.expected)} "
                             f"(±{num(g.tol)}){pts}" + (f" — {w['likely']}: {why}" if why else ""))
            elif verdict == "blank":
                lines.append(f"  {g.column}")
            else:
                lines.append(f"  {g.column}: {g.why}")
        lines.append("")
    return "\n".join(lines)


def feedback_text(r: GradedRow, title: str, lang: str, title_zh: str = "") -> str:
    """One student's feedback text in ``lang`` (``en``, ``zh`` or ``both``), each language's part headed by the
    title in that language (``title_zh``, when there is one, for Chinese)."""
    langs = ("en", "zh") if lang == "both" else (lang,)
    return "\n".join(_one(r, title_in(title, title_zh, lg), lg) for lg in langs)


__all__ = ["feedback_text", "file_names"]
