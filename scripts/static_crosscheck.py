"""The static engine against every committed DEM run, and toward stiff joints against the rigid and
compliant limit analyses: reports/static/crosscheck.csv and crosscheck.md.

    .venv/bin/python scripts/static_crosscheck.py [--out reports/static] [--jobs 2]

Static run folders go to runs/static-crosscheck/ (reused when they hold the same case).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case import reference
from yadearch.case.config import preset
from yadearch.results.summary import HingeRef, RunSummary
from yadearch.solve.limit import limit_analysis
from yadearch.studies.capacity.directions import DIRECTION_PARAMETER
from yadearch.studies.crosscheck import Pair, crosscheck_markdown, dem_folders, pair_from_folder, run_pairs

REPORTS = Path("reports")
IMPERFECTION_SAMPLES = 20  # of the imperfection study's final campaign
COMPLIANT_FROM_KN = 16.0  # the compliant march is valid from here up (docs/theory.md)
RIGID_FROM_KN = 1000.0


def dem_pairs() -> list[Pair]:
    """Every DEM run the cross-check covers, grouped."""
    groups = {
        "paper": [REPORTS / "set1", REPORTS / "set2"],
        "kn-sweep": dem_folders(REPORTS / "kn-sweep", "kn*"),
        "kn-sweep-du-first": dem_folders(REPORTS / "kn-sweep-du-first", "kn*"),
        "robustness": dem_folders(REPORTS / "robustness", "*_base"),
        "stiff": dem_folders(REPORTS / "stiff", "kn*"),
        "imperfections": [
            REPORTS / "imperfections" / "final" / f"face_bump_sd0.18_s{seed}"
            for seed in range(1, IMPERFECTION_SAMPLES + 1)
        ],
    }
    pairs = [pair_from_folder(group, folder) for group, folders in groups.items() for folder in folders]
    return pairs + capacity_pairs()


def capacity_pairs() -> list[Pair]:
    """The capacity map's runs (their folders are not committed: the case from its table row)."""
    table = pd.read_csv(REPORTS / "movements" / "capacity" / "capacity.csv")
    pairs = []
    for row in table.itertuples():
        kn = reference.SETS[row.set]["kn_N_per_mm3"]
        case = preset("set1").with_overrides(
            {"interface.kn_N_per_mm3": kn, DIRECTION_PARAMETER: row.direction_deg, "numerics.engine": "static"}
        )
        hinges = (
            tuple(HingeRef(int(h[:-1]), h[-1]) for h in str(row.hinges).split()) if isinstance(row.hinges, str) else ()
        )
        first = float(row.du_first_mm) if pd.notna(row.du_first_mm) else None
        dem = RunSummary(du_mm=row.du_mm, du_first_mm=first, hinges_at_collapse=hinges, steps=0, wall_s=row.wall_s)
        pairs.append(Pair("capacity", f"{row.set}_direction{row.direction_deg:g}", case, dem))
    return pairs


def limits(table: pd.DataFrame, pairs: list[Pair]) -> pd.DataFrame:
    """The rigid du (kn >= RIGID_FROM_KN) and the compliant march's (kn >= COMPLIANT_FROM_KN) of the
    settlement runs on the perfect paper arch."""
    rows = []
    for pair, row in zip(pairs, table.itertuples()):
        kn = pair.case.interface.kn_N_per_mm3
        settlement = pair.group in ("kn-sweep", "robustness", "stiff")
        if not settlement or kn < COMPLIANT_FROM_KN:
            continue
        compliant = limit_analysis(pair.case, compliant=True).du_rigid_mm
        rigid = limit_analysis(pair.case).du_rigid_mm if kn >= RIGID_FROM_KN else None
        rows.append(
            {
                "group": pair.group,
                "run": pair.name,
                "kn_N_per_mm3": kn,
                "static_du_mm": row.static_du_mm,
                "compliant_du_mm": compliant,
                "rigid_du_mm": rigid,
            }
        )
    return pd.DataFrame(rows)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", type=Path, default=REPORTS / "static")
    parser.add_argument("--runs", type=Path, default=Path("runs") / "static-crosscheck")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    pairs = dem_pairs()
    start = time.time()
    table = run_pairs(pairs, args.runs, args.jobs)
    wall = time.time() - start
    limit_table = limits(table, pairs)
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv_atomically(args.out / "crosscheck.csv", table)
    write_csv_atomically(args.out / "limits.csv", limit_table)
    write_text_atomically(args.out / "crosscheck.md", crosscheck_markdown(table, limit_table))
    print(
        f"{len(table)} pairs, {int(table['within_1pct'].sum())} within 1 %, "
        f"{int(table['same_hinges'].sum())} with the same hinges; static runs solved in {wall:.0f} s "
        f"(reused ones in none) -> {args.out}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
