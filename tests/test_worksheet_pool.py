"""No two students share a variant while the pool allows (issue 12), and the generator says so when it does not:
the pool's size and its exact number of acceptable variants, in the terminal line and key.json."""
from __future__ import annotations

import json
import math
from collections import Counter

import pytest

from geomcon.paper import PAPERS
from geomcon.worksheet.accept import Accepted, Rejected
from geomcon.worksheet.assign import BUDGET, TRIES, assign
from geomcon.worksheet.key import key_json
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.spec import parse_spec

SPEC = parse_spec('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                  'AB = {min = 1, max = 2000, step = 1}\nAC = 2900\n')


def sparse(every: int):
    """A judge accepting one pool index in ``every`` (its verdict depends on the index alone, as a real one)."""
    def judge_fn(ex, idx, paper):
        if idx % every == 0:
            return Accepted(idx, ex.given_of(idx), None, None, (), False)
        return Rejected(idx, "require", f"index {idx}")
    return judge_fn


def test_a_sparse_pool_is_searched_past_the_tries_before_anyone_shares():
    """2000 variants, 40 acceptable (one in 50): a student's 200 tries meet about 4 of them, so with the tries
    alone students late in a class of 40 would find only taken ones and share; the pool allows 40 distinct."""
    assert SPEC.exercises[0].pool == 2000 > TRIES
    a = assign(SPEC, numbered(40), PAPERS["A4"], judge_fn=sparse(50))
    idx = [v[0].index for v in a.variants]
    assert len(set(idx)) == 40 and a.stats[0].shared == 0 and a.stats[0].most == 1
    assert all(i % 50 == 0 for i in idx)


def test_an_exhausted_pool_is_shared_evenly_and_said_so():
    a = assign(SPEC, numbered(45), PAPERS["A4"], judge_fn=sparse(100))           # 20 acceptable for 45
    st = a.stats[0]
    assert st.exhausted and st.tried == st.pool == 2000 and st.accepted == 20
    assert st.shared == 25 and st.most == math.ceil(45 / 20)
    held = Counter(v[0].index for v in a.variants)
    assert len(held) == 20 and max(held.values()) - min(held.values()) <= 1
    line = st.line()
    assert "the pool of 2000 variants holds only 20 acceptable ones" in line and "25 students share" in line
    first20 = [v[0].index for v in a.variants[:20]]
    assert len(set(first20)) == 20                     # the first 20 students each have their own


def test_key_json_names_the_pool_and_who_shares():
    a = assign(SPEC, numbered(23), PAPERS["A4"], judge_fn=sparse(100))
    key = json.loads(key_json(SPEC, a, paper="A4", lang="en", seed=None))
    e = key["exercises"][0]
    assert (e["pool"], e["acceptable"], e["pool_exhausted"], e["shared"]) == (2000, 20, True, 3)
    assert "holds only 20 acceptable" in e["sharing"]
    shared = {s["id"]: s["exercises"][0]["shared_with"] for s in key["students"] if "shared_with" in s["exercises"][0]}
    assert len(shared) == 3
    by_id = {s["id"]: s["exercises"][0]["given"] for s in key["students"]}
    for sid, others in shared.items():
        assert all(by_id[o] == by_id[sid] and int(o) < int(sid) for o in others)


def test_a_large_pool_not_exhausted_says_acceptable_is_unknown():
    a = assign(SPEC, numbered(10), PAPERS["A4"], judge_fn=sparse(7))
    key = json.loads(key_json(SPEC, a, paper="A4", lang="en", seed=None))
    e = key["exercises"][0]
    assert e["shared"] == 0 and e["pool_exhausted"] is False and e["acceptable"] is None and "sharing" not in e


@pytest.mark.parametrize("every", [50, 100])
def test_adding_a_student_changes_no_one_else_s_variant(every):
    a = assign(SPEC, numbered(30), PAPERS["A4"], judge_fn=sparse(every))
    b = assign(SPEC, numbered(31), PAPERS["A4"], judge_fn=sparse(every))
    assert [v[0].index for v in a.variants] == [v[0].index for v in b.variants[:30]]


def test_the_budget_ends_the_search_for_an_own_variant_by_sharing():
    """30 000 variants, one in 100 acceptable: the budget of 20 000 judged finds about 200, fewer than the class."""
    big = parse_spec('[[exercise]]\nrecipe = "guide_bar.extremes"\nask = ["theta"]\n[exercise.given]\n'
                     'AB = {min = 1, max = 30000, step = 1}\nAC = 90000\n')
    a = assign(big, numbered(260), PAPERS["A4"], judge_fn=sparse(100))
    st = a.stats[0]
    assert st.tried == BUDGET and not st.exhausted and st.shared == 260 - st.accepted > 0
    assert f"{BUDGET} variants of the pool of 30000 judged found only {st.accepted} acceptable" in st.line()
