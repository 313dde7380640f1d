"""The whole runs the benchmark times: DEM runs of the paper's cases (run here through the process
launcher, or read from stored run folders), the slow reference set 2 is checked against, the
campaigns' recorded wall times, and the rigid-block limit analysis of the same arch."""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.launch.process import run_case_process
from yadearch.results.rundir import CASE_FILE, is_complete, read_summary
from yadearch.results.summary import RunSummary
from yadearch.studies.benchmark.verdicts import CAMPAIGN_CORES, TARGET_MONTECARLO_SAMPLES
from yadearch.studies.campaigns.failures import FAILED_FILE
from yadearch.studies.campaigns.runner import RESULTS_FILE

RUN_KEYS = ("wall_s", "du_mm", "steps", "steps_per_s")  # of each benchmarked run, in the report
REFERENCE_RATE_FACTOR = 0.5  # the slow reference: set 2 at this fraction of the settlement rate


def timed_run(case: ArchCase, folder: Path) -> RunSummary:
    """Run a case in its own process (reusing a complete folder of the same case); its summary."""
    if not (is_complete(folder) and (folder / CASE_FILE).read_text() == case.to_toml()):
        run_case_process(case, folder, quiet=True)
    return read_summary(folder)


def stored(folder: str) -> RunSummary | None:
    """The summary of a stored run folder, its provenance printed; None (reason printed) if the
    run failed, e.g. a sweep point that timed out."""
    failed = Path(folder) / FAILED_FILE
    if failed.is_file():
        print(f"  stored run {folder} failed: {json.loads(failed.read_text()).get('reason')}")
        return None
    summary = read_summary(Path(folder))
    print(f"  stored run {folder} (yadearch {summary.git_revision}, {summary.started})")
    return summary


def slow_reference(case: ArchCase) -> ArchCase:
    """Set 2 at half the default settlement rate (the convergence script's `half_rate` variant)."""
    rate = case.numerics.support_rate_mm_per_s * REFERENCE_RATE_FACTOR
    slow = case.with_overrides({"support_rate_mm_per_s": rate})
    slow.name = "set2_half_rate"
    return slow


def run_line(name: str, summary: RunSummary) -> str:
    """One printed line per run: steps, wall time, rate, du, hinges and, if profiled, its overhead."""
    profile = summary.profile or {}
    overhead = (
        f", wall / scene engine time {profile['driver_overhead_ratio']:.3f}"
        if profile.get("driver_overhead_ratio") and "scene_engines_s" in profile
        else ""
    )
    return (
        f"{name}: steps {summary.steps}, wall {summary.wall_s:.0f} s, {summary.steps_per_s:.0f} steps/s, "
        f"du {summary.du_mm:.2f} mm, hinges {summary.hinge_labels}{overhead}"
    )


def campaign_status(folder: Path) -> dict[str, Any]:
    """Done and failed runs of a campaign and the sum of its runs' wall times (results.csv)."""
    table = pd.read_csv(folder / RESULTS_FILE)
    return {
        "done": int((table["status"] == "done").sum()),
        "failed": int((table["status"] == "failed").sum()),
        "run_wall_s": float(table["wall_s"].sum()),
    }


def montecarlo_wall_s(status: dict[str, Any] | None) -> float | None:
    """What the target's samples take on the target's cores: a campaign's samples' own wall times
    (each run beside another) over the cores, if it tried as many samples as the target; None if not.

    The campaign's sessions ran with 1 or 2 jobs and some were killed before they recorded themselves,
    so its session wall time does not say it; a sample that failed (an arch that does not stand) cost
    its time too."""
    if status is None or status["done"] + status["failed"] < TARGET_MONTECARLO_SAMPLES:
        return None
    return status["run_wall_s"] / CAMPAIGN_CORES


def limit_measurement(case: ArchCase) -> dict[str, Any]:
    """The rigid-block limit analysis of `case`, timed in this process (no YADE)."""
    from yadearch.solve.limit import limit_analysis

    start = time.time()
    result = limit_analysis(case)
    wall = time.time() - start
    print(f"rigid-block limit analysis: du_rigid {result.du_rigid_mm:.2f} mm in {wall:.1f} s")
    return {"wall_s": wall, "du_rigid_mm": result.du_rigid_mm}
