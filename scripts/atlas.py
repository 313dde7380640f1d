"""The atlas (reports/atlas/): five shapes x six support movements x three ring thicknesses x four
joint stiffnesses in the static engine, the rigid march of every arch and movement, and 40 of them in
the DEM; du_first and du side by side with the targets of docs/atlas.md checked.

    .venv/bin/python scripts/atlas.py [--out reports/atlas] [--runs runs/atlas] [--jobs 2] [--no-dem]
        [--dem-set numerics.KEY=VALUE ...]
    .venv/bin/python scripts/atlas.py --dem-from-table   # the DEM column from OUT/atlas.csv, its runs gone
    .venv/bin/python scripts/atlas.py --invariance   # the static answers with each setting halved and doubled
    .venv/bin/python scripts/atlas.py --invariance --snap-floor 0.001   # the same with another snap floor
    .venv/bin/python scripts/atlas.py --invariance --bracket-ratio 0.005   # ... with du's bracket relative
    .venv/bin/python scripts/atlas.py --short-dem 0.005   # ... and the DEM on the short collapses with it
    .venv/bin/python scripts/atlas.py --snap-refinement   # the snaps the floor moves, against a refined bracket
    .venv/bin/python scripts/atlas.py --dem-static-states   # the DEM column read at static equilibria, RUNS/dem-static
    .venv/bin/python scripts/atlas.py --figure-from-table   # OUT/atlas.pdf/.png redrawn from OUT/atlas.csv

Each part resumes where it stopped (the campaigns' folders under RUNS, the rigid table in OUT), so a
rerun only redoes what changed; --no-dem reuses the DEM runs already in RUNS/dem, --dem-from-table the
DEM column of OUT/atlas.csv (for a change of the static engine or the rigid march on a machine without
the DEM's runs; only while the DEM's answers cannot have changed). --dem-static-states runs the DEM
column with its support paths read at the static model's equilibria (`numerics.support_path_states =
"static"`, docs/numerics.md) into RUNS/dem-static, and writes no report. --dem-set gives every DEM
run (the DEM column, --dem-static-states's too) a numerical setting and names it in atlas.md's command
(give it with --no-dem and --dem-from-table too, or the command loses it).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import preset
from yadearch.case.numerics_section import HALVED_INCREMENTS_CHECK, STATIC_PATH_STATES
from yadearch.errors import CaseError
from yadearch.plotting.atlas import atlas_figure
from yadearch.studies.atlas.comparison import bracket_comparison, floor_comparison
from yadearch.studies.atlas.grid import KNS_N_PER_MM3, dem_rows, engine_base, geometries, static_rows
from yadearch.studies.atlas.invariance import (
    INVARIANCE_COMMAND,
    invariance_markdown,
    invariance_rows,
    invariance_table,
)
from yadearch.studies.atlas.report import COMMAND, FIGURE, TABLE, travel_mm, write_atlas
from yadearch.studies.atlas.rigid import compliant_table, rigid_table
from yadearch.studies.atlas.short_dem import REPORT as SHORT_REPORT
from yadearch.studies.atlas.short_dem import TABLE as SHORT_TABLE
from yadearch.studies.atlas.short_dem import acting_below_mm, short_markdown, short_rows, short_table
from yadearch.studies.atlas.snap_refinement import refinement_markdown, refinement_rows, snap_cases, verdicts
from yadearch.studies.atlas.table import stored_engine
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, add_dem_set_option, dem_arguments, dem_settings_of

RUN_TIMEOUT_S = {"static": 600.0, "dem": 3600.0}
STATES_KEY = "numerics.support_path_states"  # what --dem-static-states sets


def run_engine(
    engine: str,
    rows: list[dict],
    runs: Path,
    jobs: int,
    folder: str | None = None,
    dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS,
    **numerics: Any,
):
    """One engine's campaign of the atlas (summary-only run folders, with `numerics` besides, the DEM's
    with `dem_settings`) in RUNS/`folder` (default: the engine's name), resumed where it stopped."""
    base = engine_base(engine, numerics, dem_settings)
    with open_pool(jobs) as pool:
        return run_campaign(
            base, rows, runs / (folder or engine), pool, timeout_s=RUN_TIMEOUT_S[engine], retry_failed=False
        )


STUDY_DEFAULTS = {  # an invariance study with another default: its option, the setting, its folder's prefix
    "--snap-floor": ("snap_thickness_ratio", "floor"),
    "--bracket-ratio": ("du_tolerance_ratio", "bracket-ratio"),
}


def invariance(out: Path, runs: Path, jobs: int, option: str | None = None, value: float = 0.0) -> None:
    """The static answers of the atlas with each numerical setting halved and doubled: OUT/invariance.csv
    and invariance.md; with `option` (one of STUDY_DEFAULTS) the study with its setting at `value` as the
    default, in OUT/PREFIX-VALUE, against OUT/invariance.csv where it exists."""
    key, prefix = STUDY_DEFAULTS[option] if option else ("", "")
    numerics: dict[str, Any] = {key: value} if option else {}
    base = engine_base("static", numerics)  # the case run_engine starts each run from
    folder, command, default = "invariance", INVARIANCE_COMMAND, None
    if option:
        folder, command = f"invariance-{prefix}-{value:g}", f"{INVARIANCE_COMMAND} {option} {value:g}"
        default = pd.read_csv(out / "invariance.csv") if (out / "invariance.csv").exists() else None
        out = out / f"{prefix}-{value:g}"
        out.mkdir(parents=True, exist_ok=True)
    results = run_engine("static", invariance_rows(base), runs, jobs, folder=folder, **numerics)
    table = invariance_table(results)
    compare = floor_comparison if option == "--snap-floor" else bracket_comparison
    comparison = compare(table, default) if default is not None else []
    write_csv_atomically(out / "invariance.csv", table)
    write_text_atomically(out / "invariance.md", invariance_markdown(table, command, comparison))
    print(f"invariance -> {out / 'invariance.md'}")


def short_dem(out: Path, runs: Path, jobs: int, ratio: float, dem_settings: Mapping[str, Any]) -> None:
    """The atlas's DEM runs with a du (OUT/atlas.csv) short enough for du_tolerance_ratio `ratio` to act, made
    again with it, against the static engine's at the same setting (OUT/bracket-ratio-RATIO/invariance.csv,
    made first by `--invariance --bracket-ratio RATIO`): OUT/bracket-ratio-RATIO/short_dem.csv and .md.
    CaseError for a ratio out of its range, FileNotFoundError without the study or the atlas."""
    base = engine_base("dem", {"du_tolerance_ratio": ratio}, dem_settings)  # refuses a ratio out of range
    folder = out / f"{STUDY_DEFAULTS['--bracket-ratio'][1]}-{ratio:g}"
    static = pd.read_csv(folder / "invariance.csv")
    atlas = pd.read_csv(out / TABLE)
    below_mm = acting_below_mm(base.numerics.du_tolerance_mm, ratio)
    rows = short_rows(atlas, dem_rows(), below_mm)
    dem = run_engine("dem", rows, runs, jobs, f"dem-bracket-ratio-{ratio:g}", dem_settings, du_tolerance_ratio=ratio)
    done = dem["status"] == "done"
    table = short_table(dem[done], static, atlas)
    write_csv_atomically(folder / SHORT_TABLE, table)
    command = f"{COMMAND} --short-dem {ratio:g}{dem_arguments(dem_settings)}"
    unfinished = list(dem.loc[~done, RUN_COLUMN])
    write_text_atomically(folder / SHORT_REPORT, short_markdown(table, ratio, command, below_mm, unfinished))
    print(f"short DEM -> {folder / SHORT_REPORT}")


def snap_refinement(out: Path) -> None:
    """The first snaps that move du_first with the floor (OUT/invariance.csv's), solved again with the
    bracket refined: OUT/snap_refinement.csv (every run) and snap_refinement.md (the verdicts)."""
    base = preset("set2")
    cases = snap_cases(pd.read_csv(out / "invariance.csv"))
    rows = []
    for k, (name, kn, floor) in enumerate(cases, 1):
        print(f"[{k}/{len(cases)}] {name} kn {kn:g}, floor x{floor:g}", flush=True)
        rows += refinement_rows(base, name, kn, floor)
    table = pd.DataFrame(rows)
    write_csv_atomically(out / "snap_refinement.csv", table)
    write_text_atomically(out / "snap_refinement.md", refinement_markdown(verdicts(table)))
    print(f"snap refinement -> {out / 'snap_refinement.md'}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=Path("reports/atlas"))
    parser.add_argument("--runs", type=Path, default=Path("runs/atlas"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument(
        "--engine",
        choices=("all", "static", "rigid", "dem"),
        default="all",
        help="compute one part only (the report is written from what exists)",
    )
    parser.add_argument("--no-dem", action="store_true", help="do not run the DEM; use the runs in RUNS/dem")
    parser.add_argument(
        "--dem-from-table",
        action="store_true",
        help="do not run the DEM; take its column from OUT/atlas.csv (its runs gone; the DEM unchanged since)",
    )
    parser.add_argument(
        "--figure-from-table",
        action="store_true",
        help="only redraw OUT/atlas.pdf/.png from OUT/atlas.csv (a change of the figure, no run)",
    )
    parser.add_argument(
        "--dem-static-states",
        action="store_true",
        help="only the DEM column with numerics.support_path_states = 'static', in RUNS/dem-static",
    )
    parser.add_argument(
        "--invariance", action="store_true", help="only the static answers with each setting halved and doubled"
    )
    parser.add_argument(
        "--snap-floor",
        type=float,
        metavar="RATIO",
        help="with --invariance: the study with the snap floor (numerics.snap_thickness_ratio) at RATIO ring "
        "thicknesses as its default, in OUT/floor-RATIO, against OUT/invariance.csv",
    )
    parser.add_argument(
        "--bracket-ratio",
        type=float,
        metavar="RATIO",
        help="with --invariance: the study with du's bracket at most RATIO of its upper end "
        "(numerics.du_tolerance_ratio) as its default, in OUT/bracket-ratio-RATIO, against OUT/invariance.csv",
    )
    parser.add_argument(
        "--short-dem",
        type=float,
        metavar="RATIO",
        help="only the DEM runs with a du (OUT/atlas.csv) short enough for numerics.du_tolerance_ratio RATIO to "
        "act (below 20 mm at 0.005), made with it, "
        "against OUT/bracket-ratio-RATIO/invariance.csv (--invariance --bracket-ratio RATIO first)",
    )
    parser.add_argument(
        "--snap-refinement",
        action="store_true",
        help="only the snaps that move du_first with the floor, against a refined bracket (reads OUT/invariance.csv)",
    )
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    if args.dem_static_states and STATES_KEY in dem_settings:
        parser.error(f"--dem-static-states sets {STATES_KEY} itself; give it without --dem-set {STATES_KEY}")
    chosen = {option: getattr(args, option[2:].replace("-", "_")) for option in STUDY_DEFAULTS}
    given = [(option, value) for option, value in chosen.items() if value is not None]
    if given and not args.invariance or len(given) > 1:
        parser.error(f"{' or '.join(STUDY_DEFAULTS)} goes with --invariance, one of them at a time")
    if args.short_dem is not None and args.invariance:
        parser.error(
            "--short-dem reads the bracket study --invariance --bracket-ratio makes: run them one after the other"
        )
    args.out.mkdir(parents=True, exist_ok=True)
    if args.invariance:
        option, value = given[0] if given else (None, 0.0)
        try:
            invariance(args.out, args.runs, args.jobs, option, value)
        except CaseError as error:  # a setting out of its range
            parser.error(f"{option}: {error}")
        return 0
    if args.short_dem is not None:
        if args.short_dem <= 0.0:
            parser.error(f"--short-dem {args.short_dem:g}: give a ratio in (0, 0.1]")
        try:
            short_dem(args.out, args.runs, args.jobs, args.short_dem, dem_settings)
        except CaseError as error:
            parser.error(f"--short-dem: {error}")
        except FileNotFoundError as error:
            parser.error(
                f"--short-dem {args.short_dem:g}: {error.filename} is missing (--invariance --bracket-ratio "
                f"{args.short_dem:g} makes the study, the atlas's report makes atlas.csv)"
            )
        return 0
    if args.snap_refinement:
        snap_refinement(args.out)
        return 0
    if args.figure_from_table:
        print(atlas_figure(pd.read_csv(args.out / TABLE), args.out / FIGURE, travel_mm())[1])
        return 0
    if args.dem_static_states:
        states = STATIC_PATH_STATES
        table = run_engine(
            "dem", dem_rows(), args.runs, args.jobs, f"dem-{states}", dem_settings, support_path_states=states
        )
        print(table[["run", "outcome", "du_first_mm", "du_mm", "hinges"]].to_string())
        return 0
    parts = ("static", "rigid", "dem") if args.engine == "all" else (args.engine,)
    static = (  # each static answer checked with the increments halved (docs/numerics.md)
        run_engine("static", static_rows(), args.runs, args.jobs, increments_check=HALVED_INCREMENTS_CHECK)
        if "static" in parts
        else None
    )
    rigid = rigid_table(preset("set2"), geometries(), args.out, args.jobs) if "rigid" in parts else None
    if "rigid" in parts:  # what the joints' compliance alone leaves of the rigid du at the stiffest kn
        compliant_table(preset("set2"), geometries(), max(KNS_N_PER_MM3), args.out, args.jobs)
    if args.dem_from_table:
        dem = stored_engine(pd.read_csv(args.out / TABLE), "dem")
    elif "dem" in parts and not args.no_dem:
        dem = run_engine("dem", dem_rows(), args.runs, args.jobs, dem_settings=dem_settings)
    else:
        dem = None
    if args.engine == "all":
        write_atlas(args.out, args.runs, static, rigid, dem, dem_settings)
        print(f"atlas -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
