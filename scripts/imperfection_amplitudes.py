"""Set 1 from imperfections of measured size: every kind of defect and their combination at several
amplitudes, 200 seeds a level on the static engine, the amplitude that brings the median du to set
1's experiment, the hinges there, and DEM confirmations on the same seeds.

    .venv/bin/python scripts/imperfection_amplitudes.py [--out reports/imperfections/amplitudes]
        [--jobs 2] [--samples 200] [--only bump,combined] [--no-dem] [--dem-set numerics.KEY=VALUE ...]

Every campaign resumes where it stopped. Face bumps are confirmed by the DEM's 200-seed campaign at
0.18 mm (reports/imperfections/final, `scripts/imperfection_study.py --only final`, with its own
--dem-set). --dem-set gives every DEM confirmation run here a numerical setting (the static campaigns
have none) and names it in the report's command (give it with --no-dem too, or the command loses it).
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.analysis.samples import du_statistics
from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case import reference
from yadearch.case.config import preset
from yadearch.plotting.montecarlo import amplitude_panels_figure
from yadearch.reporting.imperfection_amplitudes import amplitudes_markdown
from yadearch.static.simulate import simulate_static
from yadearch.studies.campaigns.executors import open_pool
from yadearch.studies.campaigns.runner import RESULTS_FILE, run_campaign
from yadearch.studies.campaigns.sessions import campaign_wall_s
from yadearch.studies.dem_settings import add_dem_set_option, dem_arguments, dem_settings_of, with_dem_settings
from yadearch.studies.imperfections.amplitudes import (
    KINDS,
    LEVEL,
    Kind,
    hinge_table,
    kind_rows,
    level_summary,
    matching_amplitude,
    nearest_level,
    with_levels,
)

BASE_PRESET = "set2"  # the accurate (CNC) voussoirs' kn: the defects alone must bring du down
SAMPLES = 200  # seeds a level, every kind: the median's 95 % interval within a few percent
DEM_SAMPLES = {"combined": 20}  # DEM confirmations at the matching level (bumps: DEM_BUMP_CAMPAIGN); others 5
OTHER_DEM_SAMPLES = 5
AGREEMENT = 0.03  # DEM and static medians on the same seeds within this
DEM_BUMP_CAMPAIGN = Path("reports/imperfections/final")  # 200 DEM seeds at face_bump_sd_mm = 0.18
DEM_BUMP_LEVEL = 0.18
SET1_HINGES = {"A": 13, "B": 32, "C": 56, "D": 1}  # set 1's experiment (the paper's Table 1)
REPORT = "amplitudes.md"
SUMMARY = "levels.csv"
FIGURE = "du_vs_amplitude"


def static_campaign(kind: Kind, out: Path, samples: int, jobs: int) -> pd.DataFrame:
    """The kind's static campaign (resumed), with amplitudes and du for the statistics."""
    base = preset(BASE_PRESET).with_overrides({"numerics.engine": "static"})
    with open_pool(jobs) as pool:
        # a static run is deterministic: a recorded failure (an arch that cannot stand) is not run again
        return with_levels(
            kind, run_campaign(base, kind_rows(kind, samples), out / kind.name / "static", pool, retry_failed=False)
        )


def dem_campaign(kind: Kind, out: Path, level: float, jobs: int, dem_settings: Mapping[str, Any]) -> pd.DataFrame:
    """The DEM confirmation of a kind at `level`: the first seeds of the static campaign, on YADE with
    the study's `dem_settings`."""
    samples = DEM_SAMPLES.get(kind.name, OTHER_DEM_SAMPLES)
    base = with_dem_settings(preset(BASE_PRESET), dem_settings)
    with open_pool(jobs) as pool:
        return with_levels(kind, run_campaign(base, kind_rows(kind, samples, (level,)), out / kind.name / "dem", pool))


def dem_bumps() -> pd.DataFrame:
    """The DEM's existing 200-seed bump campaign at DEM_BUMP_LEVEL, in this study's naming."""
    table = pd.read_csv(DEM_BUMP_CAMPAIGN / RESULTS_FILE)
    table["run"] = table["run"].str.replace(r"^face_bump_sd[^_]+_", f"a{DEM_BUMP_LEVEL:g}_", regex=True)
    return with_levels(KINDS[0], table)


def confirmation_row(kind: Kind, static: pd.DataFrame, dem: pd.DataFrame) -> dict:
    """Static and DEM medians on the seeds both finished, at the DEM's level."""
    level = float(dem[LEVEL].iloc[0])
    same = static[(static[LEVEL] == level) & static["seed"].isin(dem["seed"])]
    both = same.merge(dem, on="seed", suffixes=("_static", "_dem"))
    both = both.dropna(subset=["du_stat_mm_static", "du_stat_mm_dem"])
    static_median = du_statistics(both["du_stat_mm_static"])["median"]
    dem_median = du_statistics(both["du_stat_mm_dem"])["median"]
    difference = dem_median / static_median - 1.0 if static_median else math.nan
    return {
        "kind": kind.name,
        LEVEL: level,
        "seeds": len(both),
        "static_median_du_mm": static_median,
        "dem_median_du_mm": dem_median,
        "difference_pct": 100 * difference,
        "within": abs(difference) <= AGREEMENT,
        "dem_wall_s": float(dem["wall_s"].sum()),
        "static_wall_s": float(same["wall_s"].sum()),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="reports/imperfections/amplitudes")
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (one core each)")
    parser.add_argument("--samples", type=int, help=f"seeds a level (static; default {SAMPLES})")
    parser.add_argument("--only", default="", help="comma-separated kinds (default: all)")
    parser.add_argument("--no-dem", action="store_true", help="skip the DEM confirmations")
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)
    out = Path(args.out)
    target = reference.SETS["set1"]["experimental"]["du_mm"]
    perfect = simulate_static(preset(BASE_PRESET), out / "perfect", log=lambda _line: None).collapsed_du_mm()
    summaries, confirmations, matches, panels, hinges = [], [], [], [], []
    for kind in KINDS:
        if args.only and kind.name not in args.only.split(","):
            continue
        static = static_campaign(kind, out, args.samples or SAMPLES, args.jobs)
        summary = level_summary(kind, static)
        match = matching_amplitude(summary, static, target, perfect)
        level = nearest_level(summary, match.amplitude)
        matches.append(
            {
                "kind": kind.name,
                "title": kind.title,
                "unit": kind.amplitude_unit,
                "amplitude": match.amplitude,
                "low": match.low,
                "high": match.high,
                "level": level,
                "static_wall_s": campaign_wall_s(out / kind.name / "static") or 0.0,
            }
        )
        hinges.append(hinge_table(static, level, SET1_HINGES).assign(kind=kind.name, level=level))
        summaries.append(summary)
        panels.append(
            (
                static.assign(du_mm=static["du_stat_mm"], status="done"),
                LEVEL,
                kind.axis_label,
                perfect,
            )
        )
        if not args.no_dem:
            dem = dem_bumps() if kind.name == "bump" else dem_campaign(kind, out, level, args.jobs, dem_settings)
            confirmations.append(confirmation_row(kind, static, dem))
    levels = pd.concat(summaries, ignore_index=True)
    write_csv_atomically(out / SUMMARY, levels)
    write_csv_atomically(out / "matches.csv", pd.DataFrame(matches))
    write_csv_atomically(out / "hinges.csv", pd.concat(hinges, ignore_index=True))
    if confirmations:
        write_csv_atomically(out / "confirmations.csv", pd.DataFrame(confirmations))
    kept = args.no_dem and (out / "confirmations.csv").is_file()  # the DEM's, from its last run
    table = pd.read_csv(out / "confirmations.csv") if kept else pd.DataFrame(confirmations)
    amplitude_panels_figure(panels, out / FIGURE, target, f"set 1 experiment, {target} mm")
    write_text_atomically(
        out / REPORT,
        amplitudes_markdown(
            levels,
            pd.DataFrame(matches),
            pd.concat(hinges, ignore_index=True),
            table,
            perfect,
            target,
            FIGURE,
            kept=kept,
            arguments=dem_arguments(dem_settings),
        ),
    )
    print((out / REPORT).read_text())
    return 0


if __name__ == "__main__":
    sys.exit(main())
