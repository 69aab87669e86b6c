"""The graded example prepares each variant from the solution its judging built (``grading.example.judged``):
the same alternatives, uses and givens figures as a variant solved again, and a solution of other givens is
never taken for the variant's."""
from __future__ import annotations

from geomcon.grading.diagnosis import prepare
from geomcon.grading.example import CLASS_SPEC, judged
from geomcon.grading.keyfile import key_from_json
from geomcon.grading.moodle import givens_svg
from geomcon.grading.replay import Variant
from geomcon.worksheet import key_and_assignment, make_key
from geomcon.worksheet.roster import numbered
from geomcon.worksheet.solving import solve_given
from geomcon.worksheet.spec import parse_spec


def _key(students: int):
    spec = parse_spec(CLASS_SPEC)
    text, assignment = key_and_assignment(spec, numbered(students))
    return text, key_from_json(text), assignment, spec


def test_the_key_with_its_assignment_is_make_keys_key():
    text, _, _, spec = _key(3)
    assert text == make_key(spec, numbered(3))


def test_a_judged_variant_grades_as_one_solved_again():
    _, key, assignment, _ = _key(3)
    prepared = judged(key, assignment)
    assert len(prepared) == sum(len(s.exercises) for s in key.students.values())
    for student, row in zip(assignment.students, assignment.variants):
        s = key.students[student.id]
        for ex, acc in zip(s.exercises, row):
            p = prepared[(s.variant or s.id, ex.n)]
            assert p.variant.solution is acc.solved.sol            # the judged solution, not a new one
            fresh = prepare(ex)
            assert fresh.variant.solution is not acc.solved.sol
            assert p.alts == fresh.alts and p.uses == fresh.uses and p.steps == fresh.steps
            assert givens_svg(ex, p.variant.solution) == givens_svg(ex)


def test_a_solution_of_other_givens_is_not_used():
    sol = solve_given("guide_bar.extremes", {"AB": 140, "AC": 290})
    assert Variant.of("guide_bar.extremes", {"AB": 140.0, "AC": 290}, sol).solution is sol
    other = Variant.of("guide_bar.extremes", {"AB": 130, "AC": 290}, sol)
    assert other.solution is not sol and other.solution.problem.given["AB"] == 130
    assert Variant.of("guide_bar.extremes", {"AB": 140, "AC": 290}, None).solution is not sol
