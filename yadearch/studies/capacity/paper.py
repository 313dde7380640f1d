"""The capacity map of the paper's arch (`scripts/capacity_map.py`, `reports/movements/capacity/`): both
voussoir sets at every direction of the support movement as one campaign, the rigid limit of each
direction, the reaction curves and the report."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case import reference
from yadearch.case.config import preset
from yadearch.plotting.capacity import capacity_polar_figure, reaction_curves_figure
from yadearch.results.rundir import SERIES_FILE
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.capacity.campaign import rigid_limits
from yadearch.studies.capacity.directions import (
    DIRECTION_PARAMETER,
    DIRECTIONS_DEG,
    RigidLimit,
    map_markdown,
    map_table,
    reaction_curve,
    with_rigid,
)
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, dem_arguments, with_dem_settings

SETS = ("set1", "set2")
RUNS = "runs"
TABLE = "capacity.csv"
REPORT = "capacity.md"
POLAR_FIGURE = "capacity_map"
REACTION_FIGURE = "reactions"


def run_paper_directions(
    out: Path, jobs: int, engine: str = "dem", dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> pd.DataFrame:
    """Every set at every direction, as one campaign (the costliest runs first), on `engine` (the DEM
    with `dem_settings`)."""
    kns = [reference.SETS[name]["kn_N_per_mm3"] for name in SETS]
    rows = [{"kn_N_per_mm3": kn, DIRECTION_PARAMETER: direction} for kn in kns for direction in DIRECTIONS_DEG]
    with open_pool(jobs) as pool:
        base = preset(SETS[0]).with_overrides({"numerics.engine": engine})
        return run_campaign(with_dem_settings(base, dem_settings) if engine == "dem" else base, rows, out / RUNS, pool)


def paper_rigid_limits() -> dict[float, RigidLimit]:
    """The rigid limit of every direction of the paper's arch (kn plays no part)."""
    return rigid_limits(preset(SETS[1]), DIRECTIONS_DEG)


def paper_capacity_report(table: pd.DataFrame, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS) -> str:
    """The Markdown report of the paper's capacity map, its command naming the DEM's `dem_settings`."""
    settlement = table[table["direction_deg"] == -90.0]
    lines = [
        "# Capacity map: du against the direction of the support movement",
        "",
        "The paper's arch (55 voussoirs) under a movement of its right support in a fixed direction "
        "(degrees from +x: 0 = spreading, -90 = settlement, -180 = closing), for both voussoir sets "
        "(their kn, `set1` and `set2` presets), beside the rigid-block limit analysis of each direction. "
        "du is the displacement along the path; (du_x, du_y) are its components. Where the movement is "
        "not its own mirror image (every direction but spreading and closing), the rigid arch of an odd "
        "number of voussoirs has two branches: its keystone's two joints tie for the crown hinge, the "
        "rigid march breaks the tie toward the left one, and the other branch is shown beside it "
        f"(docs/movements.md). Regenerate: `.venv/bin/python scripts/capacity_map.py{dem_arguments(dem_settings)}` "
        "(the rigid columns alone: `--rigid-only`).",
        "",
        *map_markdown(table),
        "",
        f"![capacity map]({POLAR_FIGURE}.png)",
        "",
        "The force of the arch on the moving support along its path at the equilibrium states: "
        "positive when the arch pushes the support along its movement (the support holds it back), "
        "negative when the arch resists the movement (closing):",
        "",
        f"![reactions]({REACTION_FIGURE}.png)",
        "",
    ]
    for row in settlement.itertuples(index=False):
        paper = reference.SETS[row.set]["numerical"]["du_mm"]
        lines.append(f"- {row.set} at -90° (the paper's settlement): du {row.du_mm:.2f} mm, paper FE {paper} mm.")
    failed = table[table["status"] != "done"]
    for row in failed.itertuples(index=False):
        lines.append(f"- {row.set} at {row.direction_deg:g}°: {row.status} (see {RUNS}/{row.folder}).")
    return "\n".join(lines) + "\n"


def paper_capacity_map(
    out: Path,
    results: pd.DataFrame | None,
    rigid: dict[float, RigidLimit],
    dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS,
) -> str:
    """Write OUT/capacity.csv, the map, the reaction curves and OUT/capacity.md (its command naming the
    DEM's `dem_settings`) from the campaign's `results` (None: the rigid columns of the committed table
    rewritten alone); returns the report."""
    if results is None:
        table = with_rigid(pd.read_csv(out / TABLE, float_precision="round_trip"), rigid)
        table["hinges"] = table["hinges"].fillna("")
    else:
        table = pd.concat([map_table(name, _runs_of(results, name), rigid) for name in SETS], ignore_index=True)
        curves = {
            name: {
                float(getattr(r, DIRECTION_PARAMETER)): reaction_curve(
                    pd.read_csv(out / RUNS / r.folder / SERIES_FILE), float(getattr(r, DIRECTION_PARAMETER))
                )
                for r in _runs_of(results, name).itertuples(index=False)
                if r.status == "done"
            }
            for name in SETS
        }
        reaction_curves_figure(curves, out / REACTION_FIGURE)
    write_csv_atomically(out / TABLE, table)
    capacity_polar_figure(table, out / POLAR_FIGURE)
    text = paper_capacity_report(table, dem_settings)
    write_text_atomically(out / REPORT, text)
    return text


def _runs_of(results: pd.DataFrame, name: str) -> pd.DataFrame:
    return results[results["kn_N_per_mm3"] == reference.SETS[name]["kn_N_per_mm3"]]
