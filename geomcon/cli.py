"""The ``geomcon`` command: solve, cycle, recipes, gallery, bench.

Bad input never shows a traceback: it prints one line ``error: <file>: <what>`` on stderr and exits 2,
and no output file is written (everything is rendered before anything is written).
"""
from __future__ import annotations

import argparse
import gc
import os
import sys
import warnings
from functools import partial
from pathlib import Path
from typing import Callable, Sequence

from .errors import GeomconError, ProblemError

EXIT_BAD_INPUT = 2
EXIT_CHECK_FAILED = 1


def one_line(text: str) -> str:
    """``text`` with every control character escaped (``\\n``, ``\\x01``, ``\\u2028``…), so that a hostile
    key, recipe or file name can never split the one error line.

    Examples
    --------
    >>> one_line("given 'a\\nb'")
    "given 'a\\\\nb'"
    """
    out = []
    for ch in str(text):
        if ch.isprintable() or ch == " ":
            out.append(ch)
        else:
            out.append(ch.encode("unicode_escape").decode("ascii"))
    return "".join(out)


def _fail(where: str, msg: str) -> int:
    print(f"error: {one_line(where)}: {one_line(msg)}", file=sys.stderr)
    return EXIT_BAD_INPUT


def _fail_write(where: str, exc: OSError) -> int:
    """The one error line of an output that could not be written."""
    return _fail(where, f"cannot write output: {exc.strerror or exc}" + (f" ({exc.filename})" if exc.filename else ""))


def _summary(sol, lang: str = "en") -> str:
    """The text a solve prints: the header (with "— solution N of M" when the problem has several valid
    solutions, as the sheet of solution N says it), the results as the figure prints them (``θ = 12.506° (= analytic;
    textbook 12.5, -0.04 %)``, in ``lang``), the other valid solutions, the warnings as the figure words them
    (``published θ = 25``, not the file's ``theta``; ``警告：`` and the Chinese sentence for zh, both for ``both``) and the steps evaluated."""
    from .render.results import result_line

    from .solve import solution_note

    title = sol.problem.title_in(lang)
    count = len(sol.solution_values)
    if title and count > 1:                       # which solution this is, as a drawing of solution N titles it
        title = solution_note(title, sol.solution_numbers[0], count)
    title = title.replace("\n", "  ")                               # both: "English  中文", as the headings
    lines = [f"{sol.problem.id}: {sol.recipe.name}" + (f" — {title}" if title else "")]
    lines += [f"  {line}" for line in sol.figure_lines(lang)]
    others = sol.solution_values[1:]
    numbers = sol.solution_numbers
    units = {q.name: q.unit for q in sol.recipe.answers}
    zh = lang == "zh"
    if others:
        if zh:
            which = ("教材所取的解（解 1）" if numbers[0] == 1 else f"解 {numbers[0]}（--solution {numbers[0]}；教材所取的为解 1）")
            lines.append(f"  共 {len(others) + 1} 个有效解；上面是{which}；其余的解（--solution N 画出解 N）：")
        else:
            which = ("the textbook's choice (solution 1)" if numbers[0] == 1 else
                     f"solution {numbers[0]} (--solution {numbers[0]}; the textbook's choice is solution 1)")
            lines.append(f"  {len(others) + 1} valid solutions; the one above is {which}; the others "
                         "(--solution N draws solution N):")
        for i, other in zip(numbers[1:], others):
            shown = ("，" if zh else ", ").join(result_line(k, v, units.get(k, ""), lang="zh" if zh else "en",
                                                            recipe=sol.recipe.name) for k, v in other.items())
            lines.append(f"    {'解' if zh else 'solution'} {i}{'：' if zh else ': '}{shown}")
    if sol.warnings:                           # their rules are compiled when imported: only for a warning to say
        from .render.labels import plain_text
        from .render.warning_words import english_words, printed_words, warning_zh
        from .render.zh import zh_brackets
    for w in sol.warnings:
        words = warning_zh(w) if lang != "en" else None
        if lang != "zh" or words is None:
            lines.append(f"  warning: {plain_text(zh_brackets(printed_words(english_words(w))))}")
        if words is not None:
            lines.append(f"  警告：{plain_text(printed_words(words, zh=True))}")
    st = sol.stats
    lines.append(f"  steps evaluated {st['steps_evaluated']} of {st['steps_total']}")
    return "\n".join(lines)


def _solution_number(text: str) -> int:
    """The N of ``--solution N``: a whole number from 1 (refused with the value otherwise).

    >>> _solution_number("2")
    2
    """
    t = str(text).strip()
    if not (t.isascii() and t.isdigit()) or len(t) > 6 or int(t) < 1:
        raise ProblemError(f"--solution: expected a whole number ≥ 1, got {text!r}")
    return int(t)


def cmd_solve(args: argparse.Namespace) -> int:
    from .fileio import check_targets, write_all
    from .problems import load_problem
    from .solve import solve

    path = args.file
    outputs = {"--svg": args.svg, "--html": args.html, "--profile-csv": getattr(args, "profile_csv", None)}
    try:
        dirs = {k: v for k, v in (("--steps", args.steps), ("--diagrams", getattr(args, "diagrams", None))) if v}
        check_targets({k: v for k, v in outputs.items() if v}, dirs)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")           # numpy's floating-point chatter never reaches stderr
            sol = solve(load_problem(path))
            if getattr(args, "solution", None) is not None:
                sol = sol.as_solution(_solution_number(args.solution))
            if args.json:
                from .gallery import to_json_text
                text = to_json_text(sol)
            else:
                text = _summary(sol, args.lang) + "\n"
            files: dict[Path, str] = {}
            if args.svg or args.html or args.steps:
                from .render.page import PageSpec, sheet_names
                page = PageSpec(args.paper, args.orientation or "landscape", args.lang)
                if args.orientation is None:          # the way the figure draws larger, as the gallery prints it
                    from .render.orient import larger_page
                    page, sheets = larger_page(sol, page)
                else:
                    sheets = sol.sheets(page)
                if args.svg:
                    names = sheet_names(args.svg, len(sheets))
                    check_targets({f"--svg (sheet {i})": n for i, n in enumerate(names[1:], 2)})
                    files.update((Path(n), sheet) for n, sheet in zip(names, sheets))
                if args.html:
                    files[Path(args.html)] = sol.html(page, sheets)
                if args.steps:
                    for k, frame in enumerate(sol.frames(page, sheets[0]), 1):
                        files[Path(args.steps) / f"step-{k:03d}.svg"] = frame
            if getattr(args, "diagrams", None):
                from .gallery import problem_motion_svg
                if "program" not in sol.problem.given or sol.problem.given.get("h") is None:
                    raise ProblemError(f"--diagrams: recipe {sol.recipe.name} has no motion program to draw "
                                       "(s–v–a diagrams are for cam.translating, cam.oscillating, cam.base_radius)")
                files[Path(args.diagrams) / f"{sol.problem.id}_motion.svg"] = problem_motion_svg(sol)
            if getattr(args, "profile_csv", None):
                from .recipes.cam_common import profile_csv
                files[Path(args.profile_csv)] = profile_csv(sol.drawing_scene, sol.recipe.name)
        write_all(files)
    except GeomconError as exc:
        return _fail(path, str(exc))
    except OSError as exc:
        return _fail_write(path, exc)
    if args.lang == "zh" and sol.problem.title and not sol.problem.title_zh:
        print(f"note: {one_line(path)}: no title_zh: the title stays in English", file=sys.stderr)
    sys.stdout.write(text)
    return 0 if sol.ok else EXIT_CHECK_FAILED


UNIT_WORDS = {"mm": "mm", "interval[]": "[[low, high], …] mm", "deg": "°", "": "ratio", "count": "whole number",
              "bool": "true/false", "point": "[x, y] mm", "mm[]": "list, mm", "deg[]": "list, °", "[]": "list",
              "table[]": "list of tables", "choice": "one of", "mm/s": "mm/s", "rad/s": "rad/s", "mm/s²": "mm/s²",
              "rad/s²": "rad/s²", "mm/s[]": "list, mm/s", "mm/s²[]": "list, mm/s²", "rad/s[]": "list, rad/s",
              "rad/s²[]": "list, rad/s²"}
"""How ``geomcon recipes`` names a given's unit (a flag is written true or false in a problem file)."""
ANSWER_WORDS = {**UNIT_WORDS, "bool": "yes/no (JSON true/false)"}
"""How ``geomcon recipes`` names an answer's unit: a flag reads yes or no, as the results print it."""


def _unit_words(q, words: dict[str, str] = UNIT_WORDS) -> str:
    """A quantity's unit as ``geomcon recipes`` prints it, with the words a choice may take.

    >>> from geomcon.recipes.base import Quantity
    >>> _unit_words(Quantity("K", "", "time-ratio coefficient")), _unit_words(Quantity("ok", "bool", "x"), ANSWER_WORDS)
    ('ratio', 'yes/no (JSON true/false)')
    >>> _unit_words(Quantity("arm", "choice", "side", choices=("left", "right")))
    'one of left|right'
    """
    unit = words.get(q.unit, q.unit)
    for name, word, other in q.unit_when:                       # cam.base_radius's h: ° for an arm
        unit += f", {words.get(other, other)} if {name} = {word}"
    return f"{unit} {'|'.join(q.choices)}" if q.choices else unit


def _given_line(q) -> str:
    """One given of ``geomcon recipes``: name, unit, required or its default, range, meaning."""
    need = "required" if q.required else ("optional" if q.default is None else f"default {_shown(q.default)}")
    return f"    {q.name:<18} {_unit_words(q):<30} {need:<19} {q.doc}"


def _answer_line(q) -> str:
    """One answer of ``geomcon recipes``: name, unit (yes/no for a flag), meaning.

    >>> from geomcon.recipes.base import Quantity
    >>> _answer_line(Quantity("A_near", "bool", "yes when A lies on D's side of C1C2")).split()
    ['A_near', 'yes/no', '(JSON', 'true/false)', 'yes', 'when', 'A', 'lies', 'on', "D's", 'side', 'of', 'C1C2']
    """
    return f"    {q.name:<18} {_unit_words(q, ANSWER_WORDS):<30} {'':<19} {q.doc}"


def _shown(v) -> str:
    if isinstance(v, bool):
        return str(v).lower()
    if isinstance(v, float):
        return f"{v:g}"
    return str(v)


def cmd_cycle(args: argparse.Namespace) -> int:
    """``geomcon cycle FILE``: a linkage over its crank turn (issue 15): the answers (stroke, K, extremes), and
    on request the table (--csv), the s–v–a plots (--svg), the animation (--html), or the JSON (--json)."""
    from .fileio import check_targets, write_all
    from .kinematics.animation import animation_html
    from .kinematics.output import json_text, summary, table_csv
    from .kinematics.plots import cycle_plot_sheets
    from .render.page import sheet_names
    from .kinematics.problem import load_cycle
    from .kinematics.result import solve_cycle

    path = args.file
    outputs = {"--csv": args.csv, "--svg": args.svg, "--html": args.html}
    try:
        check_targets({k: v for k, v in outputs.items() if v})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = solve_cycle(load_cycle(path))
            text = json_text(r) if args.json else summary(r)
            makers = {"--csv": table_csv, "--html": animation_html}
            files = {Path(v): makers[k](r) for k, v in outputs.items() if v and k != "--svg"}
            if args.svg:                # A4 sheets: FILE, FILE-2 … (five panels a sheet)
                sheets = cycle_plot_sheets(r)
                files.update({Path(n): t for n, t in zip(sheet_names(args.svg, len(sheets)), sheets)})
        write_all(files)
    except GeomconError as exc:
        return _fail(path, str(exc))
    except OSError as exc:
        return _fail_write(path, exc)
    sys.stdout.write(text)
    return 0


def cmd_recipes(args: argparse.Namespace) -> int:
    from .recipes import RECIPES

    if args.json:
        import json
        data = {name: {"title": r.title,
                       "given": {q.name: {"unit": q.unit, "doc": q.doc, "required": q.required,
                                          **({"unit_when": [{"given": n, "is": w, "unit": u} for n, w, u in q.unit_when]}
                                             if q.unit_when else {}),
                                          **({"default": q.default} if q.default is not None else {}),
                                          **({"choices": list(q.choices)} if q.choices else {})} for q in r.givens},
                       "answers": {q.name: {"unit": q.unit, "doc": q.doc} for q in r.answers},
                       "points": list(r.points)} for name, r in sorted(RECIPES.items())}
        print(json.dumps(data, ensure_ascii=False, indent=2))
        return 0
    for name, r in sorted(RECIPES.items()):
        print(f"{name}  —  {r.title}")
        print("  given:")
        for q in r.givens:
            print(_given_line(q))
        print("  answers:")
        for q in r.answers:
            print(_answer_line(q))
        print()
    return 0


def cmd_gallery(args: argparse.Namespace) -> int:
    from .fileio import write_all
    from .gallery import build_gallery, problem_files, stale_files

    problems, out = Path(args.problems), Path(args.out)
    if not problem_files(problems):
        return _fail(str(problems), "no *.toml problem files here")
    try:
        if args.check:
            stale = stale_files(problems, out, lang=args.lang, jobs=args.jobs)
            if stale:
                print(f"gallery is stale ({len(stale)} files): " + ", ".join(stale), file=sys.stderr)
                print("run: geomcon gallery", file=sys.stderr)
                return EXIT_CHECK_FAILED
            print(f"gallery is up to date ({len(problem_files(problems))} problems)")
            return 0
        files = build_gallery(problems, lang=args.lang, jobs=args.jobs, against=out)    # None: already as built
    except GeomconError as exc:
        return _fail(_current_file(exc, problems), str(exc))
    new = {out / name: text for name, text in files.items() if text is not None}   # a file already as built stays
    write_all(new)
    for stale in sorted(p for p in out.rglob("*") if p.is_file() and p.relative_to(out).as_posix() not in files):
        stale.unlink()
    same = f" ({len(files) - len(new)} unchanged)" if len(new) < len(files) else ""
    print(f"wrote {len(new)} file{'' if len(new) == 1 else 's'}{same} to {out}/ from {len(problem_files(problems))} problems")
    return 0


def _jobs(text: str) -> int:
    """``--jobs``: a whole number of at least 1."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of processes, got {text!r}") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected at least 1 process, got {n}")
    return n


def _current_file(exc: Exception, problems: Path) -> str:
    return str(getattr(exc, "file", problems))


def cmd_bench(args: argparse.Namespace) -> int:
    from .bench import run_bench

    return run_bench(quick=args.quick, out=Path(args.out),
                     cycle_record=Path(args.cycle_record) if args.cycle_record else None)


def cmd_fuzz(args: argparse.Namespace) -> int:
    from .fuzz.runner import FAILURES, Report, all_generators, run_hostile, run_valid
    from .gallery import problem_files

    _limit_memory(args.memory_gib)
    report = Report()
    if args.hostile:
        report.merge(run_hostile(problem_files(Path(args.problems)), args.hostile, args.seed))
    if args.valid:
        gens = {k: g for k, g in all_generators().items() if not args.only or args.only in k}
        report.merge(run_valid(gens, args.valid, args.seed))
    if args.json:
        import json
        print(json.dumps(report.to_json(), ensure_ascii=False, indent=2))
    else:
        for name, n in report.cases.items():
            print(f"{name}: {n} cases in {report.seconds.get(name, 0):.1f} s")
        print("counts: " + ", ".join(f"{k} {v}" for k, v in sorted(report.counts.items())))
        for k in FAILURES:
            for ex in report.examples.get(k, []):
                print(f"{k}: {one_line(ex)}")
        print(f"{report.failures()} failures")
    return 0 if report.failures() == 0 else EXIT_CHECK_FAILED


def _limit_memory(gib: float) -> None:
    """Cap the address space, so that a memory blow-up is a MemoryError (counted) and not a dead machine."""
    try:
        import resource
        limit = int(gib * 2 ** 30)
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    except (ImportError, ValueError, OSError):
        pass


def cmd_worksheet(args: argparse.Namespace) -> int:
    """``geomcon worksheet SPEC.toml --out DIR``: a variant of each exercise per student, the key (``key.json``,
    ``variants.csv``), the students' sheets (``sheets/``, ``sheets.html``) and the key pages (``key/``,
    ``key.html``)."""
    from .fileio import check_targets, write_all
    from .worksheet import make_worksheet
    from .worksheet.roster import load_roster, numbered
    from .worksheet.spec import load_spec

    path = args.file
    try:
        check_targets({}, {"--out": args.out})
        spec = load_spec(path)
    except GeomconError as exc:
        return _fail(path, str(exc))
    try:
        students = load_roster(args.students) if args.students else numbered(args.count)
    except GeomconError as exc:
        return _fail(args.students or path, str(exc))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            w = make_worksheet(spec, students, paper=args.paper, lang=args.lang, seed=args.seed)
        write_all({Path(args.out) / name: text for name, text in w.files.items()})
    except GeomconError as exc:
        return _fail(path, str(exc))
    except OSError as exc:
        return _fail_write(path, exc)
    for line in w.summary:
        print(line)
    pages = sum(1 for name in w.files if name.startswith("sheets/"))
    keys = sum(1 for name in w.files if name.startswith("key/"))
    print(f"wrote key.json, variants.csv, sheets.html ({pages} pages in sheets/), key.html ({keys} pages in key/) "
          f"for {len(students)} students to {args.out}/")
    return 0


def cmd_check(args: argparse.Namespace) -> int:
    """``geomcon check KEY.json|PROBLEM.toml ANSWERS.csv --out DIR``: grades.csv, grades.json, report.html and
    feedback/<id>.txt; exit 0 when grading completed, 2 (one line, nothing written) for an unusable file."""
    from .fileio import check_targets, write_all
    from .grading import grade
    from .grading.answers import MAX_BYTES, read_answers
    from .grading.feedback import feedback_text, file_names
    from .grading.keyfile import load_key
    from .grading.report import report_html
    from .grading.tables import grades_csv, grades_json

    out = Path(args.out)
    try:
        check_targets({}, {"--out": out})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            key = load_key(args.file)
    except GeomconError as exc:
        return _fail(args.file, str(exc))
    try:
        p = Path(args.answers)
        if not p.is_file():
            raise ProblemError("not a regular file")
        if p.stat().st_size > MAX_BYTES:
            raise ProblemError(f"the answers file has {p.stat().st_size} bytes; at most {MAX_BYTES} ({MAX_BYTES // 2 ** 20} MiB)")
        sheet = read_answers(p.read_bytes())
        if not any(c in key.columns for c in sheet.columns):
            raise ProblemError("no column names an answer of the key (the key's: "
                               + ", ".join(key.columns[:12]) + (" …" if len(key.columns) > 12 else "") + ")")
    except OSError as exc:
        return _fail(args.answers, f"cannot read: {exc.strerror or exc}")
    except GeomconError as exc:
        return _fail(args.answers, str(exc))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            book = grade(key, sheet)
        files = {out / "grades.csv": grades_csv(book), out / "grades.json": grades_json(book),
                 out / "report.html": report_html(book)}
        for r, name in zip(book.rows, file_names([r.id or f"line-{r.line}" for r in book.rows])):
            files[out / "feedback" / name] = feedback_text(r, book.key.title, book.key.lang, book.key.title_zh)
        write_all(files)
    except GeomconError as exc:
        return _fail(args.file, str(exc))
    except OSError as exc:
        return _fail(args.file, f"cannot write output: {exc.strerror or exc}" + (f" ({exc.filename})" if exc.filename else ""))
    graded = [r for r in book.rows if not r.problem]
    print(f"graded {len(graded)} of {len(book.rows)} rows against {len(book.columns)} answers; "
          f"wrote grades.csv, grades.json, report.html and {len(book.rows)} feedback files to {out}/")
    for note in book.notes[:20]:
        print(f"note: {one_line(note)}")
    if len(book.notes) > 20:
        print(f"note: … {len(book.notes) - 20} more in grades.json")
    return 0


def cmd_moodle(args: argparse.Namespace) -> int:
    """``geomcon moodle KEY.json --out bank.xml``: a Moodle XML question bank."""
    from .fileio import check_targets, write_all
    from .grading.keyfile import load_key
    from .grading.moodle import moodle_xml

    try:
        check_targets({"--out": args.out})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            key = load_key(args.file)
            if key.source != "key":
                raise ProblemError("a Moodle bank is made from a worksheet's key.json, not from a problem file")
            text = moodle_xml(key, figures=not args.no_figures)
        write_all({Path(args.out): text})
    except GeomconError as exc:
        return _fail(args.file, str(exc))
    except OSError as exc:
        return _fail(args.file, f"cannot write output: {exc.strerror or exc}")
    questions = text.count("<question type=") - text.count('<question type="category">')
    print(f"wrote {args.out}: {questions} questions")
    return 0


def _page_arguments(s: argparse.ArgumentParser) -> None:
    """--paper, --portrait/--landscape and --lang of the drawing commands."""
    s.add_argument("--paper", choices=("A4", "A3"), default="A4", help="paper of the sheets (default A4)")
    o = s.add_mutually_exclusive_group()
    o.add_argument("--landscape", dest="orientation", action="store_const", const="landscape",
                   help="landscape sheets (default: landscape, or portrait when that draws the figure at a larger "
                   "scale, as most cams)")
    o.add_argument("--portrait", dest="orientation", action="store_const", const="portrait", help="portrait sheets")
    s.set_defaults(orientation=None)
    s.add_argument("--lang", choices=("en", "zh", "both"), default="both",
                   help="language of captions, results and headings: en, zh (full-width punctuation) or both "
                   "(default)")


def _solve_arguments(s: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon solve``."""
    s.add_argument("file")
    s.add_argument("--json", action="store_true", help="print the result as one JSON object")
    s.add_argument("--svg", metavar="OUT", help="write the drawing sheet (OUT: drawing at a standard scale, results, "
                   "title block) and the protocol sheets (OUT stem + -2, -3 …), each printable at 100 %%")
    s.add_argument("--steps", metavar="DIR", help="write one SVG per construction step (the drawing sheet at that step)")
    s.add_argument("--html", metavar="OUT", help="write a self-contained step player page (prints one sheet a page)")
    _page_arguments(s)
    s.add_argument("--profile-csv", metavar="OUT", help="cam recipes: write the actual profile as x,y,delta (mm, mm, deg)")
    s.add_argument("--diagrams", metavar="DIR", help="cam recipes: write the motion program's s–v–a (ψ–δ) diagrams "
                   "as DIR/<problem>_motion.svg")
    s.add_argument("--solution", metavar="N", help="a problem with several valid solutions: report and draw solution N "
                   "(1 = the textbook's choice; the text output lists them all)")


def _cycle_arguments(c: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon cycle``."""
    c.add_argument("file", help="a cycle problem (problems/cycles/*.toml)")
    c.add_argument("--json", action="store_true", help="print the result as one JSON object")
    c.add_argument("--csv", metavar="OUT", help="write the table: phi_deg and the problem's columns")
    c.add_argument("--svg", metavar="OUT", help="write the columns against the crank angle (s–v–a, ω, ε)")
    c.add_argument("--html", metavar="OUT", help="write a self-contained animation of the linkage")


def _recipes_arguments(r: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon recipes``."""
    r.add_argument("--json", action="store_true")


def _gallery_arguments(g: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon gallery``."""
    g.add_argument("--check", action="store_true", help="exit 1 when the committed gallery is stale")
    g.add_argument("--problems", default="problems", metavar="DIR")
    g.add_argument("--out", default="gallery", metavar="DIR")
    g.add_argument("--lang", choices=("en", "zh", "both"), default="both",
                   help="language of captions, results and headings (default both)")
    g.add_argument("--jobs", type=_jobs, default=None, metavar="N",
                   help="worker processes (default: every core; 1 = this process alone); the files are the same "
                        "bytes for any N")


def _bench_arguments(b: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon bench``."""
    b.add_argument("--quick", action="store_true", help="fewer repetitions and sweep sizes (about 15 s instead of 45 s)")
    b.add_argument("--out", default="bench.svg", metavar="SVG", help="where to write the plot")
    b.add_argument("--cycle-record", default=None, metavar="JSON",
                   help="also write the whole-cycle rows as the record the gallery draws "
                        "(problems/cycles/bench_record.json)")


def _fuzz_arguments(f: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon fuzz``."""
    f.add_argument("--hostile", type=int, default=200, metavar="N", help="mutated problem files in all")
    f.add_argument("--valid", type=int, default=50, metavar="N", help="random valid problems per generator")
    f.add_argument("--seed", type=int, default=9)
    f.add_argument("--only", default="", metavar="TEXT", help="only the generators whose name contains TEXT")
    f.add_argument("--problems", default="problems", metavar="DIR")
    f.add_argument("--memory-gib", type=float, default=4.0, help="address-space cap of the fuzzing process")
    f.add_argument("--json", action="store_true")


def _worksheet_arguments(w: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon worksheet``."""
    w.add_argument("file", metavar="SPEC.toml")
    w.add_argument("--out", required=True, metavar="DIR", help="where to write the sheets, the key pages, key.json and variants.csv")
    who = w.add_mutually_exclusive_group(required=True)
    who.add_argument("--students", metavar="CLASS.csv", help="class list: a header with id (and name); "
                     "UTF-8 (± BOM) or GBK/GB18030")
    who.add_argument("--count", type=int, metavar="N", help="N students numbered 1 … N")
    w.add_argument("--seed", type=int, default=None, help="overrides the spec's seed")
    w.add_argument("--lang", choices=("zh", "en", "both"), default="both", help="language of the statements")
    w.add_argument("--paper", choices=("A4", "A3"), default="A4")


def _check_arguments(c: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon check``."""
    c.add_argument("file", metavar="KEY.json|PROBLEM.toml")
    c.add_argument("answers", metavar="ANSWERS.csv", help="id (and name), then one column per answer ('1.AB'); "
                   "UTF-8 (± BOM), UTF-16, GBK/GB18030")
    c.add_argument("--out", required=True, metavar="DIR")


def _moodle_arguments(m: argparse.ArgumentParser) -> None:
    """The arguments of ``geomcon moodle``."""
    m.add_argument("file", metavar="KEY.json")
    m.add_argument("--out", required=True, metavar="bank.xml")
    m.add_argument("--no-figures", action="store_true", help="leave out the givens figures")


def help_width() -> int:
    """The width argparse's help formatter gives itself, ``shutil.get_terminal_size().columns - 2`` ($COLUMNS
    when a positive whole number, else the terminal's width, else 80), found without importing :mod:`shutil`:
    argparse imports it in every formatter it makes (one per argument), and it loads bz2, lzma and zlib, ~3 %
    of a whole ``geomcon solve``. ``tests/test_startup.py`` holds it equal to shutil's.

    >>> import shutil; help_width() == shutil.get_terminal_size().columns - 2
    True
    """
    try:
        columns = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns or 80
        except (AttributeError, ValueError, OSError):
            columns = 80
    return columns - 2


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The argument parser of the ``geomcon`` command.

    Every command is listed (``geomcon --help``, a misspelt command's choices), but when the first word of
    ``argv`` names a command only that command gets its arguments: their help formatters are most of the
    parser's set-up (about 10 ms, as long as the rest of ``geomcon solve``). Without ``argv``, or when its first
    word is no command, every command gets them.

    Examples
    --------
    >>> build_parser(["solve", "x.toml"]).parse_args(["solve", "x.toml"]).lang
    'both'
    >>> build_parser().parse_args(["recipes", "--json"]).json
    True
    """
    asked = argv[0] if argv else None
    only = asked if any(asked == name for name, *_ in COMMANDS) else None
    fmt = partial(argparse.HelpFormatter, width=help_width())
    p = argparse.ArgumentParser(prog="geomcon", description="Replay textbook mechanism constructions exactly.",
                                formatter_class=fmt)
    sub = p.add_subparsers(dest="command", required=True)
    for name, help_text, arguments, func in COMMANDS:
        s = sub.add_parser(name, help=help_text, formatter_class=fmt)
        if only is None or only == name:
            arguments(s)
        s.set_defaults(func=func)
    return p


COMMANDS: tuple[tuple[str, str, Callable[[argparse.ArgumentParser], None], Callable[[argparse.Namespace], int]], ...] = (
    ("solve", "solve one problem file", _solve_arguments, cmd_solve),
    ("cycle", "a linkage (crank + Assur dyads) over its crank turn: table, extremes, stroke and K, s–v–a plots, "
     "animation", _cycle_arguments, cmd_cycle),
    ("recipes", "list recipes with their given and answer names", _recipes_arguments, cmd_recipes),
    ("gallery", "solve every bundled problem and write the gallery", _gallery_arguments, cmd_gallery),
    ("bench", "speed targets as ratios to references timed in the same run (the lean core); time against error: "
     "construction vs crank sweep, vs sympy; answers vs drawing", _bench_arguments, cmd_bench),
    ("fuzz", "seeded fuzz: hostile problem files and random valid problems; exit 1 on any failure", _fuzz_arguments,
     cmd_fuzz),
    ("worksheet", "a class set of randomized exercises from one spec: the students' sheets, the key pages and "
     "key.json", _worksheet_arguments, cmd_worksheet),
    ("check", "grade a class's answers against a worksheet key or a problem file: grades.csv, grades.json, "
     "report.html, feedback/<id>.txt", _check_arguments, cmd_check),
    ("moodle", "a Moodle XML question bank from a worksheet key", _moodle_arguments, cmd_moodle),
)
"""The commands in the order ``geomcon --help`` lists them: name, help, the function adding its arguments to
its sub-parser, the function running it."""


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``geomcon`` console script (and of ``python -m geomcon``).

    Without ``argv`` (the process's own arguments: the process ends after the command), every object left is
    frozen before returning (``gc.freeze``): the interpreter's last collection at exit walks only what is not
    frozen, instead of every object of every module imported (numpy, shapely, the renderer, the recipes). At
    the end of ``geomcon gallery --check`` the process's exit took 116–162 ms of CPU, 40–61 ms so (measured from the
    CPU the process had spent when the command returned to its CPU at exit, 6 runs each, alternated)."""
    if argv is None:
        code = main(sys.argv[1:])
        gc.freeze()
        return code
    args = build_parser(argv).parse_args(argv)
    try:
        return args.func(args)
    except BrokenPipeError:     # `geomcon recipes | head`: the reader has gone; nothing is wrong
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except Exception as exc:  # a defect of geomcon, not of the input: still one line, no traceback
        if os.environ.get("GEOMCON_DEBUG"):
            raise
        where = getattr(args, "file", None) or args.command
        print(f"error: {one_line(where)}: internal error ({type(exc).__name__}: {one_line(str(exc))[:300]}); "
              "rerun with GEOMCON_DEBUG=1 for the traceback", file=sys.stderr)
        return 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
