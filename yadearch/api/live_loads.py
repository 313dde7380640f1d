"""The capacity of an arch to a live load (`ya.loads`): the rigid-block limit analysis's load
multiplier and mechanism (solve.load_lp), optionally written as OUT/NAME_loads.json."""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.api.arguments import check_arguments
from yadearch.api.runs import as_case
from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.held import refuse_fixed_place, refuse_held, require_live_load
from yadearch.case.mechanics import arch_geometry
from yadearch.case.names import check_name, output_path
from yadearch.case.plan import unread_by_rigid_blocks
from yadearch.errors import CaseError
from yadearch.launch.load_process import run_load_process
from yadearch.model.load_control import DisplacementControl
from yadearch.plotting.load_figure import plot_load_collapse
from yadearch.plotting.loads import plot_influence, plot_load_path
from yadearch.results.load_path import load_path_file, write_load_path, write_load_path_folder
from yadearch.solve.descending import DESCEND_TO
from yadearch.solve.load_lp import LoadCapacity, load_analysis, residual_capacity
from yadearch.solve.load_path import static_load_path
from yadearch.solve.load_path_result import LoadPath
from yadearch.solve.rigid import rigid_arch
from yadearch.solve.static_state import StaticEngineError
from yadearch.static.records import load_path_records
from yadearch.static.simulate import selfweight_failure
from yadearch.studies.loads.critical import over_joint_positions, with_critical
from yadearch.studies.loads.engines import dem_influence_line
from yadearch.studies.loads.rigid import influence_line
from yadearch.studies.loads.static import static_influence_line


def loads(
    case: ArchCase | str, out: str | Path | None = None, after_mm: float = 0.0, figures: bool = True
) -> LoadCapacity:
    """The live load (`case.loads`) the rigid arch carries at collapse, its self-weight held: the
    multiplier in N (a vertical load) or g (a horizontal acceleration), the mechanism's hinges; no
    YADE, under a second. With `after_mm`, in the rigid march's state after the case's support
    movement to that point (the load that first moves the settled arch). With `out`, writes
    OUT/NAME_loads.json (the result and the case) and (with `figures`) the collapse's figure
    OUT/NAME_loads.pdf/.png."""
    check_arguments(after_mm=after_mm, figures=figures)
    case = as_case(case)
    check_name(case.name, "case.name")
    refuse_held(case)
    folder = output_path(out, "out") if out is not None else None
    result = residual_capacity(case, after_mm) if after_mm > 0.0 else load_analysis(case)
    if folder is not None:
        data = load_json(result, case, after_mm)
        write_text_atomically(loads_file(case, folder), json.dumps(data, indent=1) + "\n")
        if figures and math.isfinite(result.multiplier) and after_mm == 0.0:
            plot_load_collapse(case, arch_geometry(case), result, folder / f"{case.name}_loads")
    return result


LOAD_PATH_ENGINES = ("static", "dem")  # the engines that follow a live load's path
RESIDUAL_POINTS_RANGE = (1, 50)  # settlements of a residual capacity curve


def load_path(
    case: ArchCase | str,
    out: str | Path | None = None,
    after_mm: float = 0.0,
    engine: str = "static",
    descend_to: float | None = DESCEND_TO,
    figures: bool = True,
) -> LoadPath:
    """The live load grown to collapse on an engine's path after the case's support movement to `after_mm`: its
    first loss of stability, capacity and mechanism, its load-displacement curve, and the rigid capacity
    of the same state. `engine` 'static': the static engine (seconds, no YADE), its curve going on past
    the peak until the multiplier falls to `descend_to` x the capacity (None: it stops at the peak);
    'dem': YADE's DEM by load ramps relaxed to equilibrium (a child process, minutes; needs `out`), past
    the peak the load driven by its displacement through a stiff spring (`dem.load_descent`). With
    `out`, writes OUT/NAME_load_path.json, .csv (the curve), its figure .pdf/.png (with `figures`) and
    its states as the folder OUT/NAME_load_path/ (`open_run(...).animate()`, `.export_vtk()`)."""
    check_arguments(after_mm=after_mm, descend_to=descend_to, figures=figures)
    if engine not in LOAD_PATH_ENGINES:
        raise CaseError(f"engine must be one of {', '.join(LOAD_PATH_ENGINES)}, got {engine!r}")
    case = as_case(case)
    check_name(case.name, "case.name")
    refuse_held(case)
    folder = output_path(out, "out") if out is not None else None
    if engine == "dem":
        if folder is None:
            raise CaseError("out: the DEM's load path is written to a folder; give out")
        descent = DisplacementControl(descend_to) if descend_to is not None else None
        result = run_load_process(case, folder, after_mm, descent=descent)
    else:
        try:
            result = static_load_path(case, after_mm, descend_to=descend_to)
        except StaticEngineError as exc:
            raise CaseError(selfweight_failure(exc, case)) from None
        if folder is not None:
            write_load_path(folder, result, case)
            _keep_states(folder, result, case)
    if folder is not None and figures:
        plot_load_path(result, load_path_file(folder, case.name))
    return result


def _keep_states(folder: Path, result: LoadPath, case: ArchCase) -> Path:
    """The static engine's load path's states as the folder OUT/NAME_load_path/ (`yadearch animate`,
    `export`)."""
    records = load_path_records(case, result)
    defects = records.arch.imperfections
    return write_load_path_folder(
        folder,
        result,
        case,
        records.series,
        records.joints,
        records.snapshots,
        records.states,
        defects.table() if defects is not None else None,
    )


def loads_file(case: ArchCase, out: str | Path) -> Path:
    """Where `loads(..., out=out)` writes."""
    return Path(out) / f"{case.name}_loads.json"


def load_json(result: LoadCapacity, case: ArchCase, after_mm: float = 0.0) -> dict[str, Any]:
    """The result as summary.json-like fields, with the case that gave it; after a support movement the
    multiplier is the load that first moves the settled rigid arch (its open hinges act as pins), not a
    collapse: `first_motion_multiplier`."""
    finite = math.isfinite(result.multiplier)
    moved = "first motion" if after_mm > 0.0 else "collapse"
    return {
        "name": case.name,
        "engine": "rigid",
        "live_load": case.loads.live_load,
        f"{moved.replace(' ', '_')}_multiplier": result.multiplier if finite else None,
        "unit": result.unit,
        "after_mm": after_mm,
        "outcome": moved if finite else ("cannot stand" if math.isnan(result.multiplier) else "no collapse"),
        "unused": unread_by_rigid_blocks(case),  # the case's settings rigid blocks do not read
        "arch_weight_N": result.arch_weight_N,
        **({"fill_weight_N": result.fill_weight_N} if result.fill_weight_N else {}),
        f"hinges_at_{moved.replace(' ', '_')}": [p.label for p in result.pivots],
        "sliding_interfaces": list(result.sliding),
        "case": case.to_dict(),
    }


POSITIONS_RANGE = (2, 200)  # positions of an influence line across the span


INFLUENCE_ENGINES = ("rigid", "static", "dem")


def load_influence(
    case: ArchCase | str,
    positions: int = 19,
    out: str | Path | None = None,
    engine: str = "rigid",
    jobs: int | None = None,
    figures: bool = True,
) -> pd.DataFrame:
    """The influence line of `case`'s arch: a concentrated vertical load's capacity (N) at `positions`
    points evenly across the span (k / (positions + 1)), with each mechanism's hinges, and for rigid blocks
    and the static engine the critical position (`sampled` False: the positions over joints around each
    sampled least tried, the best polished; `studies.loads.critical`), by `engine`:
    'rigid' blocks, or on the 'static' engine's or the 'dem''s path (their first loss and the rigid line
    beside it; the DEM's load paths in child processes, `jobs` at a time, under OUT/NAME_influence_runs,
    so it needs `out`); with `out`, OUT/NAME_influence.csv and (with `figures`) its figure
    OUT/NAME_influence.pdf/.png."""
    _check_count("positions", positions, POSITIONS_RANGE)
    if engine not in INFLUENCE_ENGINES:
        raise CaseError(f"engine must be one of {', '.join(INFLUENCE_ENGINES)}, got {engine!r}")
    check_arguments(jobs=jobs, figures=figures)
    case = as_case(case)
    check_name(case.name, "case.name")
    refuse_held(case)
    refuse_fixed_place(case)
    folder = output_path(out, "out") if out is not None else None
    where = tuple(k / (positions + 1) for k in range(1, positions + 1))
    if engine == "dem":
        if folder is None:
            raise CaseError("out: the DEM's influence line keeps its load paths in a folder; give out")
        cores = max(1, (os.cpu_count() or 1) // case.numerics.threads)  # one core a process by default
        table = dem_influence_line(case, where, folder / f"{case.name}_influence_runs", jobs or cores)
    else:
        line = static_influence_line if engine == "static" else influence_line
        at = case.with_overrides({"live_load": "vertical"})  # the line's own load, whatever the case's
        table = with_critical(line(case, where), lambda x: line(case, (x,)).iloc[0].to_dict(), over_joint_positions(at))
    if folder is not None:
        write_csv_atomically(folder / f"{case.name}_influence.csv", table)
        if figures:
            weight = float(rigid_arch(case).weight[1:-1].sum())
            plot_influence(table, weight, folder / f"{case.name}_influence", engine)
    return table


def residual_curve(
    case: ArchCase | str,
    points: int = 4,
    out: str | Path | None = None,
    figures: bool = True,
    on_row: Callable[[dict], None] | None = None,
) -> pd.DataFrame:
    """The live load's capacity after the case's support movement to `points` fractions of its static
    du (k / points for k = 0 ... points - 1; 4: 0, 25, 50 and 75 %): the static path's first loss and
    collapse and the load that first moves rigid blocks in the settled state, by settlement, each row
    given to `on_row` as it is made; with `out`, OUT/NAME_residual.csv and (with `figures`) its figure
    OUT/NAME_residual.pdf/.png."""
    from yadearch.plotting.loads import plot_residual
    from yadearch.studies.loads.rigid import residual_capacities

    _check_count("points", points, RESIDUAL_POINTS_RANGE)
    check_arguments(figures=figures)
    case = as_case(case)
    check_name(case.name, "case.name")
    require_live_load(case)
    refuse_held(case)
    folder = output_path(out, "out") if out is not None else None
    table = residual_capacities(case, [k / points for k in range(points)], on_row)
    if folder is not None:
        write_csv_atomically(folder / f"{case.name}_residual.csv", table)
        if figures:
            plot_residual(table, str(table["unit"].iloc[0]), folder / f"{case.name}_residual")
    return table


def _check_count(name: str, value: object, bounds: tuple[int, int]) -> None:
    """CaseError unless `value` is an integer within `bounds` (a count of points along a curve)."""
    low, high = bounds
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise CaseError(f"{name} must be an integer in [{low}, {high}], got {value!r}")
