"""Which commas are a subscript's is known once (hlook11m's review): zh_punct keeps ASCII exactly the commas that
rich_runs sets in a subscript (labels.subscript_commas); it had a rule of its own (zh._SUB_COMMA) restating
labels._SUB's. A candidate's "C2,4" in a Chinese text is a subscript (its label prints "2,4" as one) and keeps
its comma; a list's comma ("B1,B2") becomes full-width."""
from __future__ import annotations

import pytest

from geomcon.render.labels import rich_runs, subscript_commas
from geomcon.render.zh import zh_punct

SUBSCRIPTS = ["ω2,max", "ε2,max", "ρa,min", "rr,max", "αmax,turn", "r0,ρ", "r0,α", "γw,min", "γq,min", "C2,4", "C2,3"]


def _typeset_commas(text: str) -> set[int]:
    """The positions of the commas rich_runs sets in a subscript (no underscore in these texts)."""
    out, pos = set(), 0
    for run, sub in rich_runs(text):
        out |= {pos + i for i, c in enumerate(run) if c == "," and sub}
        pos += len(run)
    return out


@pytest.mark.parametrize("sym", SUBSCRIPTS)
def test_a_subscript_s_comma_stays_ascii_in_chinese_text(sym):
    text = f"取 {sym} 为解,其余从略"
    assert subscript_commas(text) == _typeset_commas(text) == {2 + sym.index(",")}
    assert zh_punct(text) == f"取 {sym} 为解，其余从略"


@pytest.mark.parametrize("text", ["B1,B2 为铰链", "AB,BC 为杆长", "取 C2,B 为解", "位置 1,2 与 3", "取 C2, 4 为解"])
def test_a_list_s_comma_is_no_subscript(text):
    assert not subscript_commas(text) and not _typeset_commas(text)
    if "," in text and not text[text.index(",") + 1].isdigit() and text[text.index(",") + 1] != " ":
        assert "," not in zh_punct(text)
