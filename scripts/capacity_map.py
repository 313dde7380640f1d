"""The capacity map of the paper's arch: du of both voussoir sets against the direction of the
support movement, every 15 degrees from spreading (0) through settlement (-90) to closing (-180),
beside the rigid-block limit of each direction, with the reaction-displacement curves.

    .venv/bin/python scripts/capacity_map.py [--out reports/movements/capacity] [--jobs 2]
                                             [--report-only | --rigid-only] [--engine dem|static]

The runs form one resumable campaign (OUT/runs); the report (OUT/capacity.md), the table
(OUT/capacity.csv) and the figures are rewritten from what is finished. --rigid-only rewrites the
rigid columns of the table, the report and the map from the table alone, as the runs' folders are
not kept in the repository.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from yadearch.atomic import write_text_atomically
from yadearch.case import reference
from yadearch.case.config import preset
from yadearch.plotting.capacity import capacity_polar_figure, reaction_curves_figure
from yadearch.results.rundir import SERIES_FILE
from yadearch.solve.limit import limit_analysis
from yadearch.studies.campaign import RESULTS_FILE, run_campaign
from yadearch.studies.capacity import (
    DIRECTION_PARAMETER,
    DIRECTIONS_DEG,
    RigidLimit,
    map_markdown,
    map_table,
    reaction_curve,
    with_rigid,
)
from yadearch.studies.executors import open_pool

SETS = ("set1", "set2")
RUNS = "runs"
TABLE = "capacity.csv"
REPORT = "capacity.md"
POLAR_FIGURE = "capacity_map"
REACTION_FIGURE = "reactions"


def run_campaign_of_directions(out: Path, jobs: int, engine: str = "dem") -> pd.DataFrame:
    """Every set at every direction, as one campaign (the costliest runs first), on `engine`."""
    kns = [reference.SETS[name]["kn_N_per_mm3"] for name in SETS]
    rows = [{"kn_N_per_mm3": kn, DIRECTION_PARAMETER: direction} for kn in kns for direction in DIRECTIONS_DEG]
    with open_pool(jobs) as pool:
        return run_campaign(preset(SETS[0]).with_overrides({"numerics.engine": engine}), rows, out / RUNS, pool)


def rigid_limits() -> dict[float, RigidLimit]:
    """The rigid limit of every direction, on both branches of the keystone's tie where the movement
    is not its own mirror image (kn plays no part)."""
    limits = {}
    for direction in DIRECTIONS_DEG:
        result = limit_analysis(preset(SETS[1]).with_overrides({DIRECTION_PARAMETER: direction}))
        limits[direction] = RigidLimit(result.du_rigid_mm, " ".join(result.collapse_hinges),
                                       result.mirror_du_rigid_mm, " ".join(result.mirror_collapse_hinges or ()))
    return limits


def report(table: pd.DataFrame) -> str:
    """The Markdown report of the capacity map."""
    settlement = table[table["direction_deg"] == -90.0]
    lines = ["# Capacity map: du against the direction of the support movement", "",
             "The paper's arch (55 voussoirs) under a movement of its right support in a fixed direction "
             "(degrees from +x: 0 = spreading, -90 = settlement, -180 = closing), for both voussoir sets "
             "(their kn, `set1` and `set2` presets), beside the rigid-block limit analysis of each direction. "
             "du is the displacement along the path; (du_x, du_y) are its components. Where the movement is "
             "not its own mirror image (every direction but spreading and closing), the rigid arch of an odd "
             "number of voussoirs has two branches: its keystone's two joints tie for the crown hinge, the "
             "rigid march breaks the tie toward the left one, and the other branch is shown beside it "
             "(docs/movements.md). Regenerate: `.venv/bin/python scripts/capacity_map.py` (the rigid columns "
             "alone: `--rigid-only`).", "",
             *map_markdown(table), "",
             f"![capacity map]({POLAR_FIGURE}.png)", "",
             "The force of the arch on the moving support along its path at the equilibrium states: "
             "positive when the arch pushes the support along its movement (the support holds it back), "
             "negative when the arch resists the movement (closing):", "",
             f"![reactions]({REACTION_FIGURE}.png)", ""]
    for row in settlement.itertuples(index=False):
        paper = reference.SETS[row.set]["numerical"]["du_mm"]
        lines.append(f"- {row.set} at -90° (the paper's settlement): du {row.du_mm:.2f} mm, paper FE {paper} mm.")
    failed = table[table["status"] != "done"]
    for row in failed.itertuples(index=False):
        lines.append(f"- {row.set} at {row.direction_deg:g}°: {row.status} (see {RUNS}/{row.folder}).")
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/movements/capacity"))
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (one core each)")
    parser.add_argument("--report-only", action="store_true", help="write the report from finished runs")
    parser.add_argument("--engine", choices=("dem", "static"), default="dem",
                        help="solver of the runs (static: Newton's method, seconds; docs/theory.md)")
    parser.add_argument("--rigid-only", action="store_true",
                        help="rewrite the rigid columns of OUT/capacity.csv, the report and the map (no runs needed)")
    args = parser.parse_args()
    rigid = rigid_limits()
    if args.rigid_only:
        table = with_rigid(pd.read_csv(args.out / TABLE, float_precision="round_trip"), rigid)
        table["hinges"] = table["hinges"].fillna("")
    else:
        results = (pd.read_csv(args.out / RUNS / RESULTS_FILE) if args.report_only
                   else run_campaign_of_directions(args.out, args.jobs, args.engine))
        table = pd.concat([map_table(name, _runs_of(results, name), rigid) for name in SETS], ignore_index=True)
        curves = {name: {float(getattr(r, DIRECTION_PARAMETER)): reaction_curve(
            pd.read_csv(args.out / RUNS / r.folder / SERIES_FILE), float(getattr(r, DIRECTION_PARAMETER)))
            for r in _runs_of(results, name).itertuples(index=False) if r.status == "done"} for name in SETS}
        reaction_curves_figure(curves, args.out / REACTION_FIGURE)
    write_text_atomically(args.out / TABLE, table.to_csv(index=False))
    capacity_polar_figure(table, args.out / POLAR_FIGURE)
    text = report(table)
    write_text_atomically(args.out / REPORT, text)
    print(text)
    return 0


def _runs_of(results: pd.DataFrame, name: str) -> pd.DataFrame:
    return results[results["kn_N_per_mm3"] == reference.SETS[name]["kn_N_per_mm3"]]


if __name__ == "__main__":
    sys.exit(main())
