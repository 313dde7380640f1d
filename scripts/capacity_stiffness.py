"""The capacity map of the paper's arch at every stiffness, on the static engine: du and du_first
against the direction of the right support's movement every 5 degrees at kn 0.25, 5.2 and 100
N/mm^3, each with the runaway bound halved and doubled from its default (0.25 and 1 ring thickness;
neither may move du), beside the rigid march and the DEM's map: reports/movements/capacity/stiffness/.

    .venv/bin/python scripts/capacity_stiffness.py [--out reports/movements/capacity/stiffness] [--jobs 2]

The rigid limits are kept in OUT/rigid_limits.csv and reused (they take minutes; kn plays no part in them).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case import reference
from yadearch.case.config import preset
from yadearch.plotting.capacity import stiffness_figure
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.sessions import campaign_wall_s
from yadearch.studies.capacity.campaign import RIGID_CACHE, rigid_limits, run_capacity
from yadearch.studies.capacity.directions import directions
from yadearch.studies.capacity.explained import stiffness_markdown

STEP_DEG = 5.0
KNS = (0.25, 5.2, 100.0)
RUNAWAY_RATIOS = (0.25, 1.0)  # the runaway bound halved and doubled from its default (ring thicknesses)
DEM_MAP = Path("reports/movements/capacity/capacity.csv")
FIGURE = "capacity_stiffness"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=Path("reports/movements/capacity/stiffness"))
    parser.add_argument("--runs", type=Path, default=Path("runs/capacity-stiffness"))
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rigid = rigid_limits(preset("set2"), directions(STEP_DEG), cache=args.out / RIGID_CACHE)
    tables = []
    with open_pool(args.jobs) as pool:
        for kn in KNS:
            for ratio in RUNAWAY_RATIOS:
                case = preset("set2").with_overrides(
                    {"kn_N_per_mm3": kn, "runaway_thickness_ratio": ratio, "numerics.engine": "static"}
                )
                case.name = f"kn {kn:g}, runaway {ratio:g} t"
                table = run_capacity(case, args.runs / f"kn{kn:g}_runaway{ratio:g}t", pool, STEP_DEG, rigid=rigid)
                tables.append(table.assign(kn_N_per_mm3=kn, runaway_thickness_ratio=ratio, label=case.name))
    # the campaigns' own sessions: a rerun that reuses finished runs does not shorten what they cost
    static_wall = sum(campaign_wall_s(folder / "runs") or 0.0 for folder in sorted(args.runs.glob("kn*t")))
    static = pd.concat(tables, ignore_index=True)
    dem = pd.read_csv(DEM_MAP)
    dem_kn = [reference.SETS[s]["kn_N_per_mm3"] for s in dem["set"]]
    dem = dem.assign(label=[f"DEM, kn {kn:g}" for kn in dem_kn], kn_N_per_mm3=dem_kn)
    write_csv_atomically(args.out / "capacity_stiffness.csv", static)
    stiffness_figure(static, dem, args.out / FIGURE)
    write_text_atomically(args.out / "capacity_stiffness.md", stiffness_markdown(static, dem, static_wall, FIGURE))
    print(f"{len(static)} static runs in {static_wall:.0f} s -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
