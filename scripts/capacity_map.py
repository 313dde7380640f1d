"""The capacity map of the paper's arch: du of both voussoir sets against the direction of the
support movement, every 15 degrees from spreading (0) through settlement (-90) to closing (-180),
beside the rigid-block limit of each direction, with the reaction-displacement curves.

    .venv/bin/python scripts/capacity_map.py [--out reports/movements/capacity] [--jobs 2]
                                             [--report-only | --rigid-only] [--engine dem|static]
                                             [--dem-set numerics.KEY=VALUE ...]

The runs form one resumable campaign (OUT/runs); the report (OUT/capacity.md), the table
(OUT/capacity.csv) and the figures are rewritten from what is finished. --rigid-only rewrites the
rigid columns of the table, the report and the map from the table alone, as the runs' folders are
not kept in the repository. --dem-set gives every DEM run a numerical setting and names it in the
report's command (give it with --report-only and --rigid-only too, or the command loses it).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from yadearch.studies.campaigns.runner import RESULTS_FILE
from yadearch.studies.capacity.paper import RUNS, paper_capacity_map, paper_rigid_limits, run_paper_directions
from yadearch.studies.dem_settings import add_dem_set_option, dem_settings_of


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("reports/movements/capacity"))
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (one core each)")
    parser.add_argument("--report-only", action="store_true", help="write the report from finished runs")
    parser.add_argument(
        "--engine",
        choices=("dem", "static"),
        default="dem",
        help="solver of the runs (static: Newton's method, seconds; docs/theory.md)",
    )
    parser.add_argument(
        "--rigid-only",
        action="store_true",
        help="rewrite the rigid columns of OUT/capacity.csv, the report and the map (no runs needed)",
    )
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    rigid = paper_rigid_limits()
    if args.rigid_only:
        results = None
    elif args.report_only:
        results = pd.read_csv(args.out / RUNS / RESULTS_FILE)
    else:
        results = run_paper_directions(args.out, args.jobs, args.engine, dem_settings)
    print(paper_capacity_map(args.out, results, rigid, dem_settings))
    return 0


if __name__ == "__main__":
    sys.exit(main())
