"""The whole du(kn) curve of the paper's arch on the static engine, its jumps located to 1 % in kn,
the DEM's sweep on top: reports/kn-curve/ (kn-curve.md, du_vs_kn.pdf/.png, kn_curve.csv, jumps.csv).

    .venv/bin/python scripts/kn_curve.py [--out reports/kn-curve] [--runs runs/kn-curve] [--jobs 2]

The static runs form resumable campaigns in RUNS (grid, then one per bisection round).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import preset
from yadearch.plotting.kn_curve import kn_curve_figure
from yadearch.reporting.kn_curve import kn_curve_markdown
from yadearch.solve.limit import limit_analysis
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.campaigns.sessions import campaign_wall_s
from yadearch.studies.kn_curve import KN, bisect_jumps, grid_values, hinge_moves, jumps_table

DEM_SWEEP = Path("reports/kn-sweep")
COMPLIANT_KN = (16.3, 30.0, 100.0, 300.0, 1000.0, 3000.0, 10000.0)  # the march is valid from kn ~16 up


def compliant_du(case) -> float | None:
    """The compliant march's du at the case's kn (mm)."""
    return limit_analysis(case, compliant=True).du_rigid_mm


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=Path("reports/kn-curve"))
    parser.add_argument("--runs", type=Path, default=Path("runs/kn-curve"))
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    base = preset("set2").with_overrides({"numerics.engine": "static"})
    dem = pd.read_csv(DEM_SWEEP / "results.csv") if (DEM_SWEEP / "results.csv").is_file() else None
    extra = list(COMPLIANT_KN) + ([] if dem is None else [float(k) for k in dem[KN]])
    with open_pool(args.jobs) as pool:
        grid = run_campaign(base, [{KN: v} for v in grid_values(extra)], args.runs / "grid", pool)
        static = bisect_jumps(base, grid, args.runs, pool)
    folders = [args.runs / "grid", *sorted(args.runs.glob("bisect*"))]
    static_wall = sum(campaign_wall_s(f) or 0.0 for f in folders)
    jumps = jumps_table(static)
    done = static[static["status"] == "done"].set_index(KN)
    limits = pd.DataFrame(
        [
            {
                KN: kn,
                "static_du_mm": float(done.loc[kn, "du_mm"]),
                "compliant_du_mm": compliant_du(base.with_overrides({KN: kn})),
            }
            for kn in COMPLIANT_KN
            if kn in done.index
        ]
    )
    du_rigid = limit_analysis(base).du_rigid_mm
    if du_rigid is None:
        raise SystemExit("the rigid analysis finds no collapse of the paper arch: nothing to draw the curve toward")
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv_atomically(args.out / "kn_curve.csv", static.sort_values(KN))
    write_csv_atomically(args.out / "jumps.csv", jumps)
    kn_curve_figure(static, dem, limits, du_rigid, args.out / "du_vs_kn")
    dem_wall = campaign_wall_s(DEM_SWEEP) if dem is not None else None
    write_text_atomically(
        args.out / "kn-curve.md",
        kn_curve_markdown(static, jumps, hinge_moves(static), dem, limits, du_rigid, static_wall, dem_wall),
    )
    print(f"{len(static)} static runs, {len(jumps)} jumps -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
