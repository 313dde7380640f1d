"""What a static campaign run costs in CPU (issue 45): the sensitivity study's Saltelli runs as a
campaign on one worker, kept in run folders (numerics.run_files = 'summary') and kept as rows only
(`campaigns.lean`), in the same invocation: the parent's CPU and the worker's, a run on average."""

from __future__ import annotations

import math
import shutil
import time
from pathlib import Path
from typing import Any

import numpy as np

from yadearch.case.config import ArchCase, preset
from yadearch.case.numerics_section import SUMMARY_RUN_FILES
from yadearch.errors import YadearchError
from yadearch.static.pool import workers_cpu_s
from yadearch.studies.benchmark.verdicts import CAMPAIGN_CORES, Verdict
from yadearch.studies.campaigns.executors import local_pool
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.sensitivity.indices import MIN_BASE_POINTS, PAPER_FACTORS, sobol_rows

MODES = {"folders": True, "lean": False}  # run_campaign's `folders`
TARGET_RUN_CPU_S = 0.025  # issue 45: a campaign run at most this much CPU on average
STUDY_BASE_POINTS = 4096  # the sensitivity study the issue wants regenerable ...
TARGET_STUDY_S = 20 * 60.0  # ... in this long on CAMPAIGN_CORES cores
ANSWERS = ["du_mm", "du_first_mm", "hinges", "outcome", "status"]


def saltelli_rows(runs: int) -> list[dict[str, Any]]:
    """The sensitivity study's first `runs` Saltelli rows (the paper's factors)."""
    base_points = max(MIN_BASE_POINTS, 2 ** math.ceil(math.log2(math.ceil(runs / (len(PAPER_FACTORS) + 2)))))
    return sobol_rows(PAPER_FACTORS, base_points)[:runs]


def saltelli_base() -> ArchCase:
    """The case those rows vary: set 2 on the static engine, its runs kept to their summaries."""
    return preset("set2").with_overrides({"numerics.engine": "static", "numerics.run_files": SUMMARY_RUN_FILES})


def campaign_runs_measurement(runs: int, folder: Path) -> dict[str, Any]:
    """The first `runs` runs of the Saltelli sample (static, set 2's base) as a campaign with run
    folders and as a lean one, each on one worker warmed first; CPU a run of the parent and worker."""
    if runs < 1:
        raise YadearchError(f"--campaign-runs must be >= 1, got {runs}")
    rows, base = saltelli_rows(runs), saltelli_base()
    figures: dict[str, Any] = {"campaign_runs": runs}
    tables = {}
    with local_pool(1) as pool:
        for mode, folders in MODES.items():
            out = folder / mode
            shutil.rmtree(out, ignore_errors=True)
            run_campaign(base, rows[:1], folder / "warm", pool, progress=False, folders=folders)  # the worker's imports
            shutil.rmtree(folder / "warm")
            worker0, parent0 = workers_cpu_s(), time.process_time()
            tables[mode] = run_campaign(base, rows, out, pool, progress=False, folders=folders)
            parent, worker = time.process_time() - parent0, workers_cpu_s() - worker0
            figures[f"campaign_{mode}_parent_cpu_s"] = parent / runs
            figures[f"campaign_{mode}_worker_cpu_s"] = worker / runs
            figures[f"campaign_{mode}_run_cpu_s"] = (parent + worker) / runs
    same = all(tables["lean"][c].equals(tables["folders"][c]) for c in ANSWERS)
    figures["campaign_same_answers"] = same
    figures["campaign_runs_done"] = int((tables["lean"]["status"] == "done").sum())
    run_s = figures["campaign_lean_run_cpu_s"]
    figures["sensitivity_4096_estimate_s"] = STUDY_BASE_POINTS * (len(PAPER_FACTORS) + 2) * run_s / CAMPAIGN_CORES
    for mode in MODES:
        print(
            f"campaign with {mode}: {figures[f'campaign_{mode}_run_cpu_s'] * 1e3:.1f} ms CPU a run "
            f"(parent {figures[f'campaign_{mode}_parent_cpu_s'] * 1e3:.1f}, worker "
            f"{figures[f'campaign_{mode}_worker_cpu_s'] * 1e3:.1f}) over {runs} Saltelli runs"
        )
    print(
        f"lean / folders: x{run_s / figures['campaign_folders_run_cpu_s']:.2f}; answers "
        f"{'the same' if same else 'DIFFER'}; median du {np.nanmedian(tables['lean']['du_mm']):.2f} mm"
    )
    return figures


def campaign_runs_verdicts(figures: dict[str, Any]) -> list[Verdict]:
    """A lean campaign run at most TARGET_RUN_CPU_S of CPU with the folder campaign's answers, and the
    4096-base-point sensitivity study on CAMPAIGN_CORES cores estimated from it."""
    run_s, study_s = figures["campaign_lean_run_cpu_s"], figures["sensitivity_4096_estimate_s"]
    return [
        Verdict(
            f"a static campaign run <= {TARGET_RUN_CPU_S * 1e3:g} ms CPU on average, the same answers",
            run_s <= TARGET_RUN_CPU_S and figures["campaign_same_answers"],
            f"{run_s * 1e3:.1f} ms (folders {figures['campaign_folders_run_cpu_s'] * 1e3:.1f} ms), answers "
            + ("the same" if figures["campaign_same_answers"] else "DIFFER"),
        ),
        Verdict(
            f"the {STUDY_BASE_POINTS}-base-point sensitivity study <= {TARGET_STUDY_S / 60:g} min on "
            f"{CAMPAIGN_CORES} cores (estimated from the CPU a run)",
            study_s <= TARGET_STUDY_S,
            f"{study_s / 60:.0f} min",
        ),
    ]
