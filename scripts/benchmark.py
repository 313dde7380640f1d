"""Speed benchmark (docs/speed.md): set 1, set 2 (and kn 100) run or read, set 2's du against a slow
reference, the limit analysis, the contact models' and the driver's speeds, the campaigns' wall times
and (--static) the static engine's; --run-files N, --static-floor, --campaign-runs N, --run-profile N and --cli-run N
measure only that (no YADE).
Prints a verdict line per target and writes the figures to --out (`yadearch.studies.benchmark`).
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import fields
from pathlib import Path

from yadearch.api.campaigns import montecarlo, sweep
from yadearch.studies.benchmark.campaign_runs import campaign_runs_measurement, campaign_runs_verdicts
from yadearch.studies.benchmark.cli_run import cli_run_measurement, cli_run_verdicts
from yadearch.studies.benchmark.report import BenchmarkPlan, run_benchmark
from yadearch.studies.benchmark.run_files import run_files_measurement, run_files_verdicts
from yadearch.studies.benchmark.run_profile import run_profile_measurement
from yadearch.studies.benchmark.static_engine import StaticCampaigns, static_floor_measurement, static_floor_verdicts
from yadearch.studies.benchmark.verdicts import measured_at, print_verdicts, write_report


def parser() -> argparse.ArgumentParser:
    """The benchmark's options."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add = parser.add_argument
    add("--out", default="reports/benchmark.json")
    add("--runs", default="runs/benchmark")
    add("--reference", help="stored slow reference run folder of set 2")
    add("--set1-run", help="use this complete set 1 run folder instead of running")
    add("--set2-run", help="use this complete set 2 run folder instead of running")
    add("--stiff", action="store_true", help="also run the stiffest sweep case (kn 100)")
    add(
        "--static",
        action="store_true",
        help="also time the static engine (set 2, kn 100, "
        "a 100-point kn sweep, 200 Monte Carlo samples) against the DEM runs of this invocation",
    )
    add(
        "--stiff-run",
        help="use this stored run folder of a stiff sweep case (e.g. the "
        "stiffest that finished) instead of running kn 100",
    )
    add("--sweep", help="campaign folder of the dense kn sweep (its sessions.json)")
    add("--montecarlo", help="folder of a Monte Carlo campaign (its sessions.json)")
    add(
        "--measure-mm",
        type=float,
        default=0.0,
        help="also time this much of set 2's loading here, runner vs bare O.run "
        "(the overhead target; run it on a free core)",
    )
    add(
        "--threads-steps",
        type=int,
        default=0,
        help="also time this many steps of the set 2 scene with 1 and 2 OpenMP threads",
    )
    add(
        "--breakdown-steps",
        type=int,
        default=3000,
        help="steps over which a step's time is split into its parts (0: skip)",
    )
    add(
        "--run-files",
        type=int,
        default=0,
        help="only measure this many static samples with whole and summary-only run folders "
        "(numerics.run_files) and write them to --out",
    )
    add(
        "--static-floor",
        action="store_true",
        help="only measure the static solver's CPU against its compiled floor (set 2 and an imperfect "
        "sample; static.cost) and write it to --out",
    )
    add(
        "--cli-run",
        type=int,
        default=0,
        help="only time this many single `yadearch run --preset set2 --engine static` from the command line, "
        "with and without figures, against the bare interpreter, and write them to --out",
    )
    add(
        "--run-profile",
        type=int,
        default=0,
        help="only profile this many of the sensitivity study's Saltelli runs in one process (where a "
        "campaign run's CPU goes: the compiled loops against the rest) and write it to --out",
    )
    add(
        "--campaign-runs",
        type=int,
        default=0,
        help="only measure the CPU a static campaign run costs, over this many runs of the sensitivity "
        "study's Saltelli sample kept in run folders and kept as rows only, and write it to --out",
    )
    return parser


def main() -> int:
    options = parser()
    args = options.parse_args()
    if args.campaign_runs < 0:
        options.error(f"--campaign-runs must be >= 1 (0: not measured), got {args.campaign_runs}")
    if args.cli_run < 0:
        options.error(f"--cli-run must be >= 1 (0: not measured), got {args.cli_run}")
    if args.run_profile < 0:
        options.error(f"--run-profile must be >= 1 (0: not measured), got {args.run_profile}")
    out, runs = Path(args.out), Path(args.runs)
    if args.run_profile:
        write_report(out, {**run_profile_measurement(args.run_profile), "measured": measured_at()})
        return 0
    if args.cli_run:
        figures = cli_run_measurement(args.cli_run, runs / "cli_run")
        write_report(out, {**figures, "measured": measured_at()})
        print_verdicts(cli_run_verdicts(figures))
        return 0
    if args.campaign_runs:
        figures = campaign_runs_measurement(args.campaign_runs, runs / "campaign_runs")
        write_report(out, {**figures, "measured": measured_at()})
        print_verdicts(campaign_runs_verdicts(figures))
        return 0
    if args.static_floor or args.run_files:
        figures = (
            static_floor_measurement()
            if args.static_floor
            else run_files_measurement(args.run_files, runs / "run_files")
        )
        write_report(out, {**figures, "measured": measured_at()})
        print_verdicts(static_floor_verdicts(figures) if args.static_floor else run_files_verdicts(figures))
        return 0
    plan = BenchmarkPlan(runs, **{f.name: getattr(args, f.name) for f in fields(BenchmarkPlan) if f.name != "runs"})
    report, verdicts = run_benchmark(plan, StaticCampaigns(sweep, montecarlo) if args.static else None)
    write_report(out, report)
    print_verdicts(verdicts)
    return 0


if __name__ == "__main__":
    sys.exit(main())
