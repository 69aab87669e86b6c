"""The caption of a design's choice among labelled candidates: which one (by the label the drawing prints at it)
and why, by the recipe's own order of preference (:func:`geomcon.recipes.common.preference`: C1 folded first,
then A on D's side of C1C2, then the shorter frame).

A step that only said "The textbook's choice of A" left the student to guess which of A1…A4 it was (issue 11):
the caption is computed from the choice itself.

Examples
--------
>>> cands = [Candidate("A1", True, (-1, -1, 261.0)), Candidate("A2", True, (-1, 0, 300.0))]
>>> choice_caption("A", cands, 0)
("The textbook's choice: A = A1 (A on D's side of C1C2; A2 is another solution)", '教材取 A = A1（A 与 D 在 C1C2 同侧；A2 为另一解）')
>>> choice_caption("A", [Candidate("A1", False, None), Candidate("A2", True, (0, 0, 9.0))], 1)[0]
"The textbook's choice: A = A2 (the only valid point)"
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

REASONS = (("C1 folded", "C1 为重叠共线位置"), ("A on D's side of C1C2", "A 与 D 在 C1C2 同侧"),
           ("the shorter frame AD", "机架 AD 较短"))
"""Why a candidate wins, one per component of the preference key (English, Chinese)."""


@dataclass(frozen=True, slots=True)
class Candidate:
    """One candidate of a choice: its printed label, whether it is a valid design, its preference key
    (smaller is preferred; None when invalid)."""

    label: str
    valid: bool
    key: tuple[Any, ...] | None


def reasons(cands: Sequence[Candidate], chosen: int) -> list[int]:
    """The components of the preference key that set the chosen candidate before each other valid one (the
    first where they differ), in order."""
    mine = cands[chosen].key
    out: set[int] = set()
    for j, c in enumerate(cands):
        if j == chosen or not c.valid or c.key is None or mine is None:
            continue
        for k, (a, b) in enumerate(zip(mine, c.key)):
            if a != b:
                out.add(k)
                break
    return sorted(out)


def choice_caption(name: str, cands: Sequence[Candidate], chosen: int | None,
                   words: Sequence[tuple[str, str]] = REASONS, textbook: int | None = None) -> tuple[str, str]:
    """The caption naming the chosen candidate, ``"The textbook's choice: A = A2 (C1 folded)"``, and the
    other valid ones; Chinese with full-width punctuation. ``textbook``: the textbook's choice, when a drawing
    of another solution chose ``chosen`` (``"The solution drawn: A = A3 (the textbook's choice is A1)"``)."""
    if chosen is None:
        return (f"The textbook's choice of {name}: no candidate is a valid design", f"取 {name}：无可行解")
    label = cands[chosen].label
    if textbook is not None and textbook != chosen:
        return (f"The solution drawn: {name} = {label} (the textbook's choice is {cands[textbook].label})",
                f"本图取 {name} = {label}（教材取 {cands[textbook].label}）")
    head_en = f"The textbook's choice: {name}" + ("" if label == name else f" = {label}")
    head_zh = f"教材取 {name}" + ("" if label == name else f" = {label}")
    others = [c.label for j, c in enumerate(cands) if j != chosen and c.valid]
    why = reasons(cands, chosen)
    if not others:
        en, zh = ["the only valid point"], ["唯一可行点"]
    else:
        en, zh = [words[k][0] for k in why], [words[k][1] for k in why]
    tail_en = "; ".join(x for x in (", ".join(en), _others_en(others)) if x)
    tail_zh = "；".join(x for x in ("，".join(zh), _others_zh(others)) if x)
    return f"{head_en} ({tail_en})", f"{head_zh}（{tail_zh}）"


def _others_en(others: list[str]) -> str:
    if not others:
        return ""
    return f"{others[0]} is another solution" if len(others) == 1 else f"{', '.join(others)} are other solutions"


def _others_zh(others: list[str]) -> str:
    return f"{'、'.join(others)} 为另一解" if len(others) == 1 else (f"{'、'.join(others)} 为其他解" if others else "")


def flat_caption(name: str, idx: int | None, labels: tuple[str, ...], *flat: Any) -> tuple[str, str]:
    """:func:`choice_caption` as a scene step's operation: ``flat`` holds (valid, C1_folded, A_near, AD) per
    candidate, as :func:`geomcon.recipes.common.best_index` reads them; ``idx`` the candidate drawn (the
    textbook's choice unless a drawing of another solution fixed it)."""
    from .common import best_index, preference
    cands = [Candidate(lab, bool(v), preference({"C1_folded": f, "A_near": n, "AD": ad}) if v else None)
             for lab, (v, f, n, ad) in zip(labels, (flat[i:i + 4] for i in range(0, len(flat), 4)))]
    return choice_caption(name, cands, idx, textbook=best_index(*flat))


__all__ = ["REASONS", "Candidate", "choice_caption", "flat_caption", "reasons"]
