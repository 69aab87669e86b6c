"""The whole-cycle part of the gallery: for each ``problems/cycles/*.toml`` its JSON, CSV table, s–v–a plots
and animation, and the lines of the gallery index that list them."""
from __future__ import annotations

from pathlib import Path

from ..errors import GeomconError
from .animation import animation_html
from .output import json_text, table_csv
from ..render.page import sheet_names
from .plots import cycle_plot_sheets
from .problem import load_cycle
from .result import solve_cycle


def cycle_files(problems_dir: Path) -> list[Path]:
    """The bundled cycle problems, sorted by name."""
    return sorted((Path(problems_dir) / "cycles").glob("*.toml"))


def cycle_gallery(problems_dir: Path) -> tuple[dict[str, str], list[str]]:
    """``({file name: text}, index lines)`` for every cycle problem."""
    files: dict[str, str] = {}
    rows = []
    for path in cycle_files(problems_dir):
        try:
            r = solve_cycle(load_cycle(path))
        except GeomconError as exc:
            exc.file = str(path)  # type: ignore[attr-defined]
            raise
        pid = r.problem.id
        files[f"{pid}.json"] = json_text(r)
        files[f"{pid}.csv"] = table_csv(r)
        sheets = cycle_plot_sheets(r)           # A4 sheets: {pid}_motion.svg, {pid}_motion-2.svg …
        files.update(zip(sheet_names(f"{pid}_motion.svg", len(sheets)), sheets))
        files[f"{pid}_cycle.html"] = animation_html(r)
        shown = ", ".join(f"{k} = {v:.6g}" for k, v in r.answers.items() if k.startswith(("stroke", "K(", "min(")))
        rows.append(f"| {pid} ([table]({pid}.csv), [s–v–a]({pid}_motion.svg)"
                    + "".join(f" [{i}]({n})" for i, n in enumerate(sheet_names(f"{pid}_motion.svg", len(sheets))[1:], 2))
                    + f", [animation]({pid}_cycle.html), "
                    f"[JSON]({pid}.json)) | {len(r.cycle.phi_deg)} | {shown} |")
    if not rows:
        return files, []
    return files, ["", "## Whole cycles (`geomcon cycle`)", "",
                   "Linkages of class II solved over the crank turn (`problems/cycles/`): the table, the columns "
                   "against the crank angle with the exact extremes, and an animation with the traced paths.", "",
                   "| problem | positions | answers |", "|---|---|---|", *rows]
