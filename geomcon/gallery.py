"""The gallery: every bundled problem solved and drawn, committed as golden output.

``build_gallery`` renders everything to memory; ``geomcon gallery`` writes it and ``geomcon gallery --check``
compares it with the committed files (a test runs the check, so a stale gallery fails CI).
"""
from __future__ import annotations

import json
from pathlib import Path

from .errors import GeomconError
from .problems import load_problem
from .solve import Solution, solve

GALLERY_PAGE = ("A4", "landscape", "both")
"""The gallery's sheets (paper, orientation, language): A4, the paper every school printer takes; landscape,
as mechanism drawings are wider than tall, unless the paper turned draws a problem's figure at a larger scale
(:func:`problem_sheets`: most cams stand taller than wide); both languages, as the protocol was printed before
``--lang`` existed and a class reads either."""


def gallery_page(lang: str | None = None):
    """:data:`GALLERY_PAGE` as a :class:`~geomcon.render.page.PageSpec`, in ``lang`` when given (imported
    here: a solve that draws nothing never loads the renderer)."""
    from .render.page import PageSpec
    paper, orientation, default = GALLERY_PAGE
    return PageSpec(paper, orientation, lang or default)


PORTRAIT = frozenset({
    "001-05b_guide_bar_design_by_K", "001-06b_crank_slider_redesign_K",
    "001-10c_crank_rocker_design_crank_and_frame", "001-12_crank_rocker_frame_line", "001-16_jaw_crusher_AC1",
    "001-24_cam_displacement_at_100", "001-25_eccentric_knife_centred", "001-25b_eccentric_knife_contact_C",
    "001-31_eccentric_oscillating_roller", "004-02_best_by_K_1_2_offset_limit", "004-03_crank_rocker_best_by_K",
    "200-01_cam_roller_offset", "200-03_cam_roller_undercut", "200-09_base_radius_cycloidal",
    "200-10_base_radius_centred", "200-11_base_radius_rise_and_return", "200-16_cam_poly_4567",
    "200-19_base_radius_alpha_and_rho", "400-04_four_bar_instant_centres"})
"""The problems the gallery prints on A4 portrait: those whose sheet 1 draws larger there and still holds the
results (:func:`geomcon.render.orient.larger_page`, the choice ``geomcon solve`` makes by default). Remembered
rather than chosen on each run, as choosing renders the losing orientation too wherever the drawing alone would
draw larger turned (000-04's slotter cam: 1:2 alone on portrait, 1:5 with its results; twelve problems, +0.9 s of
the gallery's 5 s CPU); ``tests/test_gallery_orientation.py`` renders every problem on the other orientation and
fails, naming the problem, when this set is not the choice."""


def problem_page(pid: str, lang: str | None = None):
    """The page the gallery prints problem ``pid`` (its file's stem) on: :func:`gallery_page`, turned to portrait
    for the problems of :data:`PORTRAIT` (200-01: 1:2 → 1:1)."""
    from .render.orient import turned
    page = gallery_page(lang)
    return turned(page) if pid in PORTRAIT else page


def problem_sheets(sol: Solution, lang: str | None = None):
    """The page the gallery prints ``sol`` on (:func:`problem_page`) and its sheets."""
    page = problem_page(sol.problem.id, lang)
    return page, sol.sheets(page)


def to_json_text(sol: Solution) -> str:
    """The solution's JSON, as ``geomcon solve --json`` prints it."""
    return json.dumps(sol.to_json(), ensure_ascii=False, indent=2, allow_nan=False) + "\n"


def _law_names() -> tuple[str, ...]:
    """The motion laws' names (imported here: a linkage solve never loads the cam modules, nor numpy)."""
    from .cam.custom_laws import HANDBOOK_LAWS
    from .cam.laws import LAW_NAMES
    return (*LAW_NAMES, *HANDBOOK_LAWS)


def problem_files(problems_dir: Path) -> list[Path]:
    """The bundled problem files, sorted by name."""
    return sorted(Path(problems_dir).glob("*.toml"))


def _deviation(row: dict) -> str:
    from .render.results import percent

    rel = row["rel_deviation"]
    how = "exact" if not row["deviation"] else (percent(rel) if rel is not None else f"{row['deviation']:+.3g}")
    return f"{row['quantity']} {row['published']:g} ({how})"


WORKSHEET_SPEC = Path("tests") / "data" / "worksheet_class.toml"
"""The sample worksheet spec the gallery shows (relative to the folder holding ``problems/``)."""


def _page_order(path: str) -> tuple[int, bool]:
    """A worksheet page of the gallery's one student in page order: ``1``, ``1-sd``, ``1-2``, ``1-3``, ``1-3-sd``.

    >>> sorted(["w/1-3-sd.svg", "w/1.svg", "w/1-3.svg", "w/1-2.svg"], key=_page_order)
    ['w/1.svg', 'w/1-2.svg', 'w/1-3.svg', 'w/1-3-sd.svg']
    """
    parts = path.rsplit("/", 1)[-1].removesuffix(".svg").split("-")
    return (int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 1, parts[-1] == "sd")


def worksheet_gallery(spec_path: Path) -> dict[str, str]:
    """One student's worksheet of the sample spec and its key: ``worksheet/sheets/…``, ``worksheet/key/…``,
    ``worksheet/sheets.html``, ``worksheet/key.html`` (the key's answers are in the key pages)."""
    from .worksheet import make_worksheet
    from .worksheet.roster import numbered
    from .worksheet.spec import load_spec

    w = make_worksheet(load_spec(spec_path), numbered(1))
    return {f"worksheet/{name}": text for name, text in w.files.items()
            if name.startswith(("sheets", "key/")) or name == "key.html"}


def problem_gallery(path: Path, lang: str | None = None) -> tuple[dict[str, str], str]:
    """One problem's gallery files (its JSON, SVG sheets, player and, for a cam with a motion program, its
    s–v–a sheet) and its row of the index: one job of :func:`build_gallery`. The figure is built once: the
    player page embeds the very sheets."""
    from .render.page import sheet_names

    try:
        sol = solve(load_problem(path))
    except GeomconError as exc:
        exc.file = str(path)  # type: ignore[attr-defined]  # the CLI names the failing file
        raise
    files: dict[str, str] = {}
    pid = sol.problem.id
    files[f"{pid}.json"] = to_json_text(sol)       # answers first: the JSON's stats show the lazy count
    page, sheets = problem_sheets(sol, lang)
    names = sheet_names(f"{pid}.svg", len(sheets))
    for name, sheet in zip(names, sheets):
        files[name] = sheet
    more = ", ".join(f"[{i}]({n})" for i, n in enumerate(names[1:], 2))
    files[f"{pid}.html"] = sol.html(page, sheets)
    extra = ""
    if "program" in sol.problem.given and sol.problem.given.get("h") is not None:
        files[f"{pid}_motion.svg"] = problem_motion_svg(sol)
        extra = f" ([s–v–a]({pid}_motion.svg))"
    answers = ", ".join(f"{k} = {_short(v)}" for k, v in list(sol.answers.items())[:4])
    devs = "; ".join(_deviation(r) for r in sol.published) or "—"
    turned = "A4 portrait; " if page.orientation != gallery_page().orientation else ""
    return files, (f"| [{pid}]({pid}.svg) ({turned}sheets {more}; [player]({pid}.html)){extra} | `{sol.recipe.name}` | "
                   f"{answers} | {devs} |")


def bench_gallery(problems_dir: Path) -> dict[str, str]:
    """The bench figure drawn from the committed record (``problems/cycles/bench_record.json``), when there is one."""
    from .bench.cycle_record import RECORD, cycle_figure, load_record
    record = Path(problems_dir) / RECORD
    if not record.is_file():
        return {}
    try:
        return {"bench_cycle.svg": cycle_figure(load_record(record))}
    except (ValueError, UnicodeDecodeError) as exc:      # JSONDecodeError is a ValueError
        err = GeomconError(str(exc).removeprefix(f"{record}: "))
        err.file = str(record)  # type: ignore[attr-defined]
        raise err from None


def _kinematics(problems_dir: Path) -> tuple[dict[str, str], list[str], dict[str, str]]:
    """The cycle gallery (its files and index rows) and the bench figure: one job, as both use the kinematics
    modules (imported by the worker that runs it, not before the fork: no other job needs them)."""
    from .kinematics.gallery import cycle_gallery
    files, rows = cycle_gallery(problems_dir)
    return files, rows, bench_gallery(problems_dir)


def _classwork(problems_dir: Path) -> tuple[dict[str, str], dict[str, str]]:
    """The graded example and the sample worksheet: one job, as both use the worksheet and grading modules
    (imported by the worker that runs it, not before the fork: no other job needs them)."""
    from .grading.example import gallery_files
    spec = Path(problems_dir).resolve().parent / WORKSHEET_SPEC
    return gallery_files(), (worksheet_gallery(spec) if spec.is_file() else {})


def _best_table() -> dict[str, str]:
    return {"004-02_best_by_K_table.md": best_by_k_table()}


def _preload() -> None:
    """Import what every worker's jobs use, once, before workers are forked (each worker would import, and
    without a byte-code cache compile, every module it needs again): the renderer, the cams' diagrams and twin,
    every recipe. What one job alone uses (the worksheet and grading modules of :func:`_classwork`, the
    kinematics and bench modules of :func:`_kinematics`) is left to the worker that runs it: imported there, it
    runs beside the other workers' jobs instead of before every job. What every worker decided once on its first
    use is decided here too: the installed version the title blocks print (``importlib.metadata``, ~12 ms a
    process) and whether numpy's power and inverse trigonometry are libm's (``numpy.random``, ~10 ms); and
    ``numpy.ma``, which ``np.unique`` imports on its first call (the placer's clearance counts)."""
    import numpy.ma  # noqa: F401
    from .analytic import cam_motion  # noqa: F401
    from .cam import arm_alpha, diagrams  # noqa: F401
    from .cam.profile import numpy_is_libm
    from .recipes import RECIPES
    from .render import detail, free_area, player, results, svg, warning_words  # noqa: F401
    from .render.page import version
    for name in RECIPES:
        RECIPES[name]
    version()
    for name in ("power", "arctan2", "arccos", "arcsin"):
        numpy_is_libm(name)


EXPECTED_MS = {"_classwork": 775, "200-15_cam_handbook_laws": 136, "_kinematics": 131,
               "000-03_slotter_velocity_polygons": 127, "000-06_slotter_cam_pitch_points": 113,
               "000-07_slotter_cam_actual_profile": 113, "200-16_cam_poly_4567": 113,
               "200-20_oscillating_base_radius_rho": 109, "200-14_oscillating_arm_speeds": 108,
               "000-05_slotter_cam_motion_law": 103, "004-03_crank_rocker_best_by_K": 98,
               "001-06b_crank_slider_redesign_K": 92, "000-04_slotter_cam_psi0": 89, "200-13_cam_valve_speeds": 88,
               "200-03_cam_roller_undercut": 81, "001-10c_crank_rocker_design_crank_and_frame": 80,
               "000-08_slotter_cam_pressure_angle": 75, "100-07_rocker_slider_three_positions": 75,
               "001-31_eccentric_oscillating_roller": 72, "200-19_base_radius_alpha_and_rho": 68,
               "001-11_jaw_crusher_design": 66, "004-02_best_by_K_1_5": 66, "200-07_oscillating_flat_face": 66,
               "200-10_base_radius_centred": 66}
"""The CPU milliseconds of the gallery's longest jobs (parts by function, problems by file stem), measured
2026-11-27 14:50 UTC in one process after the preload (the minimum of two runs, a quiet machine; the median job
took 35 ms); any other job counts as :data:`OTHER_MS`. Jobs are started longest first, so that no long job starts
last while the other cores idle; the results are put together in the fixed order all the same."""
OTHER_MS = 35


def _longest_first(jobs: list) -> list[int]:
    """Indices of ``jobs`` (function, args) by expected cost, longest first; ties keep their order.

    >>> from pathlib import Path
    >>> _longest_first([(_best_table, ()), (problem_gallery, (Path("p/200-20_oscillating_base_radius_rho.toml"), None)),
    ...                 (_classwork, (Path("p"),))])
    [2, 1, 0]
    """
    def cost(job) -> int:
        fn, args = job
        key = args[0].stem if fn is problem_gallery else fn.__name__
        return EXPECTED_MS.get(key, OTHER_MS)
    return sorted(range(len(jobs)), key=lambda i: -cost(jobs[i]))


def holds(path: Path, text: str) -> bool:
    """Whether ``path`` is a regular file holding exactly ``text``'s UTF-8 bytes (as
    :func:`geomcon.fileio.changed` decides what to write): what ``geomcon gallery --check`` calls current.

    >>> import tempfile
    >>> d = Path(tempfile.mkdtemp())
    >>> _ = (d / "a.svg").write_bytes("θ\\n".encode())
    >>> holds(d / "a.svg", "θ\\n"), holds(d / "a.svg", "θ"), holds(d / "b.svg", "")
    (True, False, False)
    """
    try:
        with open(path, "rb") as fh:
            return fh.read() == text.encode("utf-8")
    except OSError:                  # missing, a directory, unreadable: not current
        return False


def _held(out, gallery_dir: Path):
    """A job's output with the text of every file ``gallery_dir`` already :func:`holds` replaced by None (its
    dictionaries are file name → text; rows and other values are kept)."""
    if isinstance(out, dict):
        return {name: None if isinstance(text, str) and holds(gallery_dir / name, text) else text
                for name, text in out.items()}
    if isinstance(out, (tuple, list)):
        return type(out)(_held(x, gallery_dir) for x in out)
    return out


def _against(fn, args: tuple, gallery_dir: Path):
    """``fn(*args)``, its files compared with ``gallery_dir`` in the worker that made them (:func:`_held`)."""
    return _held(fn(*args), gallery_dir)


def build_gallery(problems_dir: Path, lang: str | None = None, jobs: int | None = None,
                  against: Path | None = None) -> dict[str, str | None]:
    """Render every problem: ``{relative file name: text}`` for the JSON, the SVG sheets (``<id>.svg`` the
    drawing, ``<id>-2.svg`` … the protocol) and the HTML player of each, plus an index; and one worksheet with
    its key (:func:`worksheet_gallery`) when the sample spec is beside ``problems/``.

    The problems and the other parts are independent jobs run on ``jobs`` processes (default: every core this
    process may use; :func:`geomcon.workers.run_ordered`) and put together in one fixed order: the files are the
    same bytes for any ``jobs``. The cyclic garbage collector is paused meanwhile
    (:func:`geomcon.workers.collector_paused`: the build is a bounded batch).

    With ``against`` (a gallery folder), a file that folder already :func:`holds` maps to None instead of its
    text: each worker compares the files it made, so the texts of unchanged files (most of the gallery's 17 MB)
    are neither sent back to this process nor compared here (``geomcon gallery`` and ``--check``)."""
    from .workers import collector_paused, run_ordered

    paths = problem_files(problems_dir)
    parts = [(_classwork, (problems_dir,)), (_kinematics, (problems_dir,)), (_best_table, ()), (law_diagrams, ())]
    all_jobs = parts + [(problem_gallery, (p, lang)) for p in paths]
    order = _longest_first(all_jobs)                # started longest first, put back in the fixed order
    done = [None] * len(all_jobs)
    with collector_paused():
        if jobs != 1:
            _preload()
        run = [all_jobs[i] if against is None else (_against, (*all_jobs[i], Path(against))) for i in order]
        for i, result in zip(order, run_ordered(run, jobs)):
            done[i] = result
    ((grading, sheet), (cycle_out, cycle_rows, bench), best, laws), problems = done[:len(parts)], done[len(parts):]
    files: dict[str, str | None] = {}
    rows = []
    for out, row in problems:
        files.update(out)
        rows.append(row)
    files.update(cycle_out)
    if bench:
        files.update(bench)
        cycle_rows = [*cycle_rows, "", "The whole-cycle bench against pylinkage + numba, as recorded from one full "
                      "`geomcon bench` run (`problems/cycles/bench_record.json`): [bench_cycle.svg](bench_cycle.svg)."]
    files.update(best)
    files.update(laws)
    files.update(grading)
    files.update(sheet)
    pages = sorted((n for n in sheet if n.startswith("worksheet/sheets/")), key=_page_order)
    worksheet_line = ("A worksheet of `tests/data/worksheet_class.toml` for one student (`geomcon worksheet … --count 1`): "
                      + ", ".join(f"[{n.split('/')[-1][:-4]}]({n})" for n in pages)
                      + " — [print-ready](worksheet/sheets.html); its key, to lay over the sheet: "
                      + ", ".join(f"[{n.split('/')[-1][:-4]}]({n})" for n in sorted((x for x in sheet if x.startswith("worksheet/key/")), key=_page_order))
                      + " — [key.html](worksheet/key.html).") if sheet else ""
    files["README.md"] = "\n".join([
        "# Gallery",
        "",
        "Generated by `geomcon gallery` from `problems/`; do not edit by hand (`geomcon gallery --check` fails "
        "when these files are stale).",
        "",
        "Each problem is printed on A4 sheets, both languages: `<id>.svg` the drawing at a standard "
        "scale with its results and title block, `<id>-2.svg` … the construction protocol; print them, or the "
        "player, at 100 % and the stated scale is true on paper. The sheets are landscape unless portrait draws the "
        "figure at a larger scale (most cams stand taller than wide): those rows say *A4 portrait*.",
        "",
        "The full optimum table of seed 004 (crank-slider, best working-stroke transmission angle) is in "
        "[004-02_best_by_K_table.md](004-02_best_by_K_table.md).",
        "",
        "The s–v–a diagrams of the five standard motion laws and the handbooks' three (rise 90°, dwell 90°, return 90°, dwell 90°, h = 20 mm): "
        + ", ".join(f"[{n}](law_{n}.svg)" for n in _law_names()) + ".",
        "",
        "A graded class (`geomcon check`, issue 13): the worksheet key [grading_key.json](grading_key.json), a "
        "synthetic class's answers [grading_answers.csv](grading_answers.csv), the gradebook "
        "[grading_grades.csv](grading_grades.csv) ([JSON](grading_grades.json)), the class report "
        "[grading_report.html](grading_report.html), one student's feedback "
        "[grading_feedback_2.txt](grading_feedback_2.txt) and the Moodle bank [grading_bank.xml](grading_bank.xml).",
        "",
        *([worksheet_line, ""] if worksheet_line else []),
        "| problem | recipe | answers | printed answers (deviation from exact) |",
        "|---|---|---|---|",
        *rows,
        *cycle_rows,
        "",
    ])
    if against is not None and holds(Path(against) / "README.md", files["README.md"]):
        files["README.md"] = None
    return files


def _short(v) -> str:
    """An answer for the index table: 4 significant digits, lists and bools as they read."""
    if isinstance(v, bool):
        return str(v).lower()
    if isinstance(v, str):
        return v
    if isinstance(v, (tuple, list)):
        return "[" + ", ".join(_short(x) for x in v[:4]) + (", …]" if len(v) > 4 else "]")
    return f"{v:.4g}"


def problem_motion_svg(sol: Solution) -> str:
    """The s–v–a diagrams of a cam problem's motion program."""
    from .cam.diagrams import motion_diagrams_svg
    from .cam.program import parse_program

    g, p = sol.problem.given, sol.problem
    swings = p.recipe == "cam.oscillating" or g.get("motion") == "oscillating"     # an arm (200-12, 200-20 too)
    unit = "°" if swings else "mm"
    return motion_diagrams_svg(parse_program(g["program"]), g["h"], title=p.title_in("both") or p.id, unit=unit,
                               problem=p.id + ".toml" if p.path else p.id, recipe=p.recipe)


def law_diagrams() -> dict[str, str]:
    """One s–v–a sheet per motion law: rise 90°, dwell 90°, return 90°, dwell 90°, h = 20 mm. Titled as a
    textbook heads a law's diagrams, in both languages ("Cosine acceleration (simple harmonic) motion law",
    "余弦加速度（简谐）运动规律"), the follower's motion stated in words under the heading (there is no problem file)."""
    from .cam.diagrams import follower_motion, motion_diagrams_svg
    from .cam.custom_laws import HANDBOOK_LAWS
    from .cam.laws import LAWS
    from .cam.program import parse_program
    from .render.zh import zh_punct
    from .worksheet.statements import LAWS as LAW_WORDS

    out = {}
    for name, lw in {**LAWS, **HANDBOOK_LAWS}.items():
        prog = parse_program([{"kind": "rise", "angle": 90, "law": name}, {"kind": "dwell", "angle": 90},
                              {"kind": "return", "angle": 90, "law": name}, {"kind": "dwell", "angle": 90}])
        en = LAW_WORDS[name][0]
        out[f"law_{name}.svg"] = motion_diagrams_svg(
            prog, 20.0, title=f"{en[0].upper()}{en[1:]} motion law\n{zh_punct(lw.zh)}", problem="—",
            recipe="cam motion law", motion=follower_motion(prog, 20.0))
    return out


def best_by_k_table(H: float = 100.0) -> str:
    """Seed 004's Table 1 recomputed in full by the construction, each row checked against the twin."""
    from .problems import problem_from_dict

    rows = []
    for i in range(14):
        K = round(1.05 + 0.05 * i, 2)
        sol = solve(problem_from_dict({"recipe": "crank_slider.best_by_K", "given": {"K": K, "H": H}}, name=f"K{K}"))
        a = sol.answers
        rows.append(f"| {K:.2f} | {a['theta']:.3f} | {a['AB']:.3f} | {a['BC']:.3f} | {a['e']:.3f} | "
                    f"{a['gamma_w_min']:.3f} | {a['gamma_min']:.3f} | {'✓' if sol.ok else '✗'} |")
    return "\n".join([
        f"# Seed 004: best offset crank-slider for K (H = {H:g} mm)",
        "",
        "a*, b*, c* maximise the smallest transmission angle of the working (slow) stroke; the construction's",
        "values, each checked against the closed-form twin and rebuilt by `crank_slider.extremes`. The paper's",
        "table lists only rows with (γw,min)max ≥ 40° and its legible a* are 48 or 49 mm throughout, as here;",
        "γw,min falls to 40° at K ≈ 1.704. Generated by `geomcon gallery`.",
        "",
        "| K | θ (°) | a* = AB (mm) | b* = BC (mm) | c* = e (mm) | (γw,min)max (°) | γmin of the cycle (°) | twin |",
        "|---|---|---|---|---|---|---|---|",
        *rows,
        "",
    ])


def stale_files(problems_dir: Path, gallery_dir: Path, lang: str | None = None, jobs: int | None = None) -> list[str]:
    """Names of gallery files that are missing, different (not byte for byte the text built: :func:`holds`), or
    no longer produced (``jobs``: as :func:`build_gallery`)."""
    gallery_dir = Path(gallery_dir)
    want = build_gallery(problems_dir, lang, jobs, against=gallery_dir)
    out = [name for name, text in want.items() if text is not None]
    have = ({p.relative_to(gallery_dir).as_posix() for p in gallery_dir.rglob("*") if p.is_file()}
            if gallery_dir.is_dir() else set())
    out += sorted(f"{name} (not produced any more)" for name in have - set(want))
    return sorted(out)
