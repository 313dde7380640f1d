"""reports/loads/descent: the DEM past the peak against the static engine's arc length, written as tables,
a figure and a Markdown report (`scripts/loads_descent.py`; minutes of YADE)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.markdown import markdown_table
from yadearch.model.load_control import SPRING_RATIO, STEP_THICKNESS_RATIO
from yadearch.plotting.loads import plot_descent
from yadearch.solve.descending import DESCEND_TO
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, dem_arguments
from yadearch.studies.loads.descent import DEFAULT, VARIED_CASE, descent_runs, descent_tables

BRANCH_TOLERANCE = 0.01  # the DEM's states past the peak within 1 % of the static branch
RUNS_FOLDER = "load_paths"  # each DEM load path's files, under the report's folder (a rerun reads them back)


def write_descent_report(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> Path:
    """Run the comparison (the DEM with `dem_settings`, `jobs` at a time; paths already in OUT/load_paths are
    read back) and write descent.csv, states.csv, descent.pdf/.png and descent.md into `out`; the report's path."""
    out.mkdir(parents=True, exist_ok=True)
    table, states, paths = descent_tables(descent_runs(dem_settings), out / RUNS_FOLDER, jobs, log)
    write_csv_atomically(out / "descent.csv", table)
    write_csv_atomically(out / "states.csv", states)
    plot_descent(paths, out / "descent")
    path = out / "descent.md"
    write_text_atomically(path, descent_markdown(table, dem_arguments(dem_settings)))
    return path


def descent_markdown(table: pd.DataFrame, arguments: str = "") -> str:
    """The report: each run's branch on both engines, and the largest gap between them; `arguments` name
    the DEM's settings in its command."""
    table = table.fillna({"static_hinges": "", "dem_hinges": "", "dem_failure": ""})
    done = table[table["dem_failure"] == ""]
    within = int((done["largest_off"] <= BRANCH_TOLERANCE).sum())
    same_end = int(((done["dem_end"] == done["static_end"]) & (done["dem_hinges"] == done["static_hinges"])).sum())
    lines = [
        "# Past the peak: the DEM's descending branch against the static engine's",
        "",
        "Each case's live load grown to collapse on both engines' paths, then past the limit point: on the",
        "static engine by arc length, in the DEM by the load's own displacement through a spring",
        f"{SPRING_RATIO:g} x the path's secant stiffness at its last stable state, the anchor moved",
        f"{STEP_THICKNESS_RATIO:g} x the ring's thickness a step, each state held until at rest by the settling",
        f'test; both down to {DESCEND_TO:g} x the capacity (docs/loads.md, "The DEM past the peak"). Each',
        "DEM state is set beside the static branch's load at the same displacement of the load (states.csv;",
        "none past a snap-back of the static branch, which displacement control jumps). Regenerate with",
        f"`.venv/bin/python scripts/loads_descent.py --out reports/loads/descent{arguments}` "
        "(minutes of two cores; the",
        f"DEM's files are kept in {RUNS_FOLDER}/ and read back by a rerun).",
        "",
        f"- Every DEM state within {100 * BRANCH_TOLERANCE:g} % of the static branch in {within} of {len(done)} "
        f"runs; the branch ends the same way on the same hinges in {same_end} of {len(done)}; DEM runs failed: "
        f"{len(table) - len(done)}.",
        f"- {VARIED_CASE.replace('_', ' ')} with the displacement control's settings and the DEM's numerics "
        "halved and doubled: the rows below its default.",
        "",
        *markdown_table(
            [
                "case",
                "varied",
                "capacity static / DEM",
                "lowest static / DEM",
                "ends static / DEM",
                "hinges there static / DEM",
                "DEM states (compared)",
                "largest gap",
                "DEM steps",
            ],
            (
                [
                    r.case.replace("_", " "),
                    "" if r.variant == DEFAULT else r.variant,
                    f"{_number(r.static_capacity)} / {_number(r.dem_capacity)} {r.unit}",
                    f"{_number(r.static_lowest)} / {_number(r.dem_lowest)}",
                    f"{r.static_end} / {r.dem_end}",
                    f"{r.static_hinges} / {r.dem_hinges or r.dem_failure}",
                    f"{r.dem_states} ({r.compared})",
                    "-" if not math.isfinite(r.largest_off) else f"{100 * r.largest_off:.2f} %",
                    f"{r.dem_steps}",
                ]
                for r in table.itertuples()
            ),
        ),  # fmt: skip
        "",
        "![both engines past the peak](descent.png)",
        "",
    ]
    return "\n".join(lines)


def _number(value: float) -> str:
    return "-" if not math.isfinite(value) else f"{value:.4g}"
