"""Running the fuzz and counting what went wrong.

Hostile files go through the real command (:func:`geomcon.cli.main`, in-process) and are judged by the
exit-code contract; random valid problems go through :func:`geomcon.solve.solve` and are judged by their
twin checks and by what is known of their answers. Every failure count must be 0:

``internal``   exit 3 or any exception that is not a refusal;
``exit_1``     a check failed (hostile files that are valid problems must not fail either);
``wrong``      an answer differs from what the case was built to have;
``malformed``  a refusal that is not exactly one line ``error: <file>: …`` with nothing on stdout, or a success
               with anything on stderr;
``partial``    an output file (or a temporary) left by a failed run;
``broken``     an output that is not well-formed (JSON by the standard, SVG and HTML as XML);
``hang``       a case over its time limit;
``warning``    a valid problem that made numpy (or anything) warn;
``refused``    a valid problem refused although it was not built at a limit.

Examples
--------
>>> r = run_valid({"demo": lambda rng: __import__("geomcon.fuzz.case", fromlist=["ValidCase"]).ValidCase(
...     {"recipe": "guide_bar.extremes", "given": {"AB": 50.0, "AC": 100.0}}, expect={"theta": (60.0, 1e-9)})},
...     count=2, seed=1)
>>> r.failures(), r.counts["solved"]
(0, 2)
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import random
import shutil
import signal
import tempfile
import time
import warnings
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping

from ..errors import GeomconError
from .case import Generator, ValidCase
from .hostile import mutate

FAILURES = ("internal", "exit_1", "wrong", "malformed", "partial", "broken", "hang", "warning", "refused")
"""The counts that must be 0."""

TIME_LIMIT = 30.0
"""Seconds one case may take before it counts as a hang."""


@dataclass
class Report:
    """Counts by outcome, examples of every failure, and the time per family."""

    counts: dict[str, int] = field(default_factory=dict)
    examples: dict[str, list[str]] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)
    cases: dict[str, int] = field(default_factory=dict)

    def add(self, outcome: str, example: str = "") -> None:
        """Count one outcome (and keep the first few examples of a failure)."""
        self.counts[outcome] = self.counts.get(outcome, 0) + 1
        if outcome in FAILURES and len(self.examples.setdefault(outcome, [])) < 8:
            self.examples[outcome].append(example[:400])

    def failures(self) -> int:
        """Total of the failure counts."""
        return sum(self.counts.get(k, 0) for k in FAILURES)

    def merge(self, other: "Report") -> "Report":
        """This report with ``other``'s counts added."""
        for k, v in other.counts.items():
            self.counts[k] = self.counts.get(k, 0) + v
        for k, v in other.examples.items():
            self.examples.setdefault(k, []).extend(v[: 8 - len(self.examples.get(k, []))])
        self.seconds.update(other.seconds)
        self.cases.update(other.cases)
        return self

    def to_json(self) -> dict[str, Any]:
        """A JSON-able summary."""
        return {"counts": dict(sorted(self.counts.items())), "failures": self.failures(),
                "cases": self.cases, "seconds": {k: round(v, 2) for k, v in self.seconds.items()},
                "examples": self.examples}


class _Timeout(Exception):
    pass


@contextlib.contextmanager
def _time_limit(seconds: float):
    """Raise :class:`_Timeout` in the block after ``seconds`` (POSIX interval timer; no limit elsewhere)."""
    if not hasattr(signal, "setitimer"):
        yield
        return

    def on_alarm(signum, frame):
        raise _Timeout()

    old = signal.signal(signal.SIGALRM, on_alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def _strict_json(text: str) -> Any:
    def no_constant(name: str) -> Any:
        raise ValueError(f"non-standard JSON constant {name}")
    return json.loads(text, parse_constant=no_constant)


def _invoke(argv: list[str]) -> tuple[int | None, str, str]:
    """Run the command in-process: (exit code or None on a hang, stdout, stderr)."""
    from ..cli import main

    out, err = io.StringIO(), io.StringIO()
    try:
        with _time_limit(TIME_LIMIT), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            rc = main(argv)
    except _Timeout:
        return None, out.getvalue(), err.getvalue()
    return rc, out.getvalue(), err.getvalue()


def judge_command(report: Report, label: str, problem: Path, argv: list[str], outputs: Iterable[Path],
                  out_dir: Path) -> None:
    """Run one command and count its outcome by the exit-code contract."""
    from ..cli import one_line

    rc, out, err = _invoke(argv)
    what = f"{label} [{problem.name!r}]: rc={rc} {err.strip()[:200]!r}"
    outputs = list(outputs)
    written = [p for p in outputs if p.exists()]
    temps = [p for p in out_dir.rglob("*") if p.name.endswith(".tmp")]
    if rc is None:
        report.add("hang", what)
    elif rc == 3:
        report.add("internal", what)
    elif rc == 1:
        report.add("exit_1", what)
    elif rc == 2:
        lines = err.split("\n")
        if out or len(lines) != 2 or lines[1] != "" or not lines[0].startswith(f"error: {one_line(str(problem))}: "):
            report.add("malformed", what)
        elif written or temps:
            report.add("partial", what + f" wrote {[p.name for p in written + temps]}")
        else:
            report.add("refusal")
    elif rc == 0:
        if err:
            report.add("malformed", what + " (stderr on success)")
            return
        try:
            _strict_json(out) if argv[2:3] == ["--json"] else None
            for p in outputs:
                if p.suffix in (".svg", ".html"):
                    ET.fromstring(p.read_text(encoding="utf-8"))
            report.add("solved")
        except (ValueError, ET.ParseError, OSError) as exc:
            report.add("broken", what + f" {exc}")
        if temps:
            report.add("partial", what + " temporaries left")
    else:
        report.add("internal", what + " (unknown exit code)")


def _sources(problem_files: Iterable[Path]) -> list[tuple[str, dict]]:
    import tomllib

    return [(p.stem, tomllib.loads(p.read_text(encoding="utf-8"))) for p in problem_files]


def run_hostile(problem_files: Iterable[Path], count: int, seed: int, *, render_every: int = 5) -> Report:
    """Mutate the bundled problems ``count`` times in all and run each mutant through ``geomcon solve``.

    Every ``render_every``-th case also asks for ``--svg`` and ``--html``; some ask for an output path that is
    a directory (nothing may then be written).
    """
    rng = random.Random(seed)
    sources = _sources(problem_files)
    report = Report()
    t0 = time.perf_counter()
    work = Path(tempfile.mkdtemp(prefix="geomcon-fuzz-"))
    try:
        for n in range(count):
            stem, data = sources[n % len(sources)]
            label, raw = mutate(data, rng)
            odd_name = rng.random() < 0.05
            case = work / f"c{n}"
            case.mkdir()
            problem = case / (f"{stem}\n\u0001name.toml" if odd_name else f"{stem}.toml")
            problem.write_bytes(raw)
            out_dir = case / "out"
            argv = ["solve", str(problem), "--json"]
            outputs: list[Path] = []
            if n % render_every == 0:
                outputs = [out_dir / "a.svg", out_dir / "a.html"]
                argv += ["--svg", str(outputs[0]), "--html", str(outputs[1])]
                if rng.random() < 0.2:          # the html target is a directory: refuse, write nothing
                    (out_dir / "d").mkdir(parents=True)
                    argv[-1] = str(out_dir / "d")
                    outputs = [outputs[0]]
                    label += "; --html is a directory"
            out_dir.mkdir(exist_ok=True)
            judge_command(report, f"{stem}: {label}", problem, argv, outputs, out_dir)
            shutil.rmtree(case, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    report.seconds["hostile"] = time.perf_counter() - t0
    report.cases["hostile"] = count
    return report


def _matches(value: Any, want: Any, tol: float) -> bool:
    if isinstance(want, (tuple, list)):
        return (isinstance(value, (tuple, list)) and len(value) == len(want)
                and all(_matches(v, w, tol) for v, w in zip(value, want)))
    if isinstance(want, bool) or isinstance(value, bool):
        return bool(value) == bool(want)
    if isinstance(want, str) or isinstance(value, str) or value == want:   # a word, or an unbounded end (inf)
        return value == want
    return math.isfinite(float(value)) and abs(float(value) - float(want)) <= tol


def judge_valid(report: Report, family: str, case: ValidCase) -> None:
    """Solve one valid case and count its outcome."""
    from ..problems import problem_from_dict
    from ..solve import solve

    what = f"{family} ({case.kind}): {json.dumps(case.problem, default=str)[:300]}"
    try:
        with _time_limit(TIME_LIMIT), warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            sol = solve(problem_from_dict(case.problem, name="fuzz"))
            sols = sol.solution_values
            ok = sol.ok
            json.dumps(sol.to_json(), allow_nan=False)
    except _Timeout:
        report.add("hang", what)
        return
    except GeomconError as exc:
        report.add("refusal" if case.may_refuse else "refused", f"{what} → {exc}")
        return
    except Exception as exc:                    # noqa: BLE001 — any other exception is a defect
        report.add("internal", f"{what} → {type(exc).__name__}: {exc}")
        return
    if caught:
        report.add("warning", f"{what} → {caught[0].category.__name__}: {caught[0].message}")
    if not ok:
        bad = [c for c in sol.checks if not c["ok"]][:2]
        report.add("exit_1", f"{what} → {bad}")
        return
    if case.expect and not any(all(k in s and _matches(s[k], v, tol) for k, (v, tol) in case.expect.items())
                               for s in sols):
        got = [{k: s.get(k) for k in case.expect} for s in sols]
        report.add("wrong", f"{what} → expected {dict(case.expect)}, got {got}")
        return
    report.add("solved")


def all_generators() -> dict[str, Generator]:
    """Every family's generators, by ``module.name``, from the ``valid_*`` modules of this package."""
    import importlib
    import pkgutil

    from .. import fuzz

    out: dict[str, Generator] = {}
    for mod in sorted(m.name for m in pkgutil.iter_modules(fuzz.__path__) if m.name.startswith("valid_")):
        gens = getattr(importlib.import_module(f"{fuzz.__name__}.{mod}"), "GENERATORS", {})
        out.update({name: g for name, g in gens.items()})
    return dict(sorted(out.items()))


def run_valid(generators: Mapping[str, Generator], count: int, seed: int) -> Report:
    """``count`` random valid problems of every generator (each generator seeded from ``seed`` and its name)."""
    report = Report()
    for name, gen in generators.items():
        rng = random.Random(f"{seed}:{name}")
        t0 = time.perf_counter()
        for _ in range(count):
            try:
                case = gen(rng)
            except Exception as exc:            # noqa: BLE001 — a broken generator is a defect too
                report.add("internal", f"{name}: generator failed: {type(exc).__name__}: {exc}")
                continue
            judge_valid(report, name, case)
        report.seconds[name] = time.perf_counter() - t0
        report.cases[name] = count
    return report
