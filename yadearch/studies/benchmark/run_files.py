"""What a run folder costs a static Monte Carlo sample kept whole or kept to its summary
(numerics.run_files): CPU time and disk, and whether du stays the same to the bit."""

from __future__ import annotations

import shutil
import time
from pathlib import Path
from typing import Any

from yadearch.case.config import preset
from yadearch.errors import YadearchError
from yadearch.static.simulate import simulate_static
from yadearch.studies.benchmark.static_engine import MONTECARLO_BUMP_SD_MM
from yadearch.studies.benchmark.verdicts import Verdict

RUN_FILES = ("full", "summary")  # the numerics.run_files settings compared
TARGET_DISK_RATIO = 0.1  # a summary-only folder at most this fraction of a whole one
TARGET_CPU_RATIO = 1.0  # and no more CPU


def run_files_measurement(samples: int, runs: Path) -> dict[str, Any]:
    """CPU time and disk a static Monte Carlo sample of the final imperfection case costs with its run
    folder kept whole and kept to its summary, `samples` samples solved in this process (run folders
    in `runs`), the two settings alternated so that a drift of the machine's speed falls on both."""
    base = preset("set2").with_overrides(
        {"numerics.engine": "static", "imperfections.face_bump_sd_mm": MONTECARLO_BUMP_SD_MM}
    )
    cases = [base.with_overrides({"imperfections.seed": seed}) for seed in range(samples)]
    simulate_static(cases[0], runs / "warm", log=lambda _: None)  # numba's cache loaded outside the timing
    cpu = dict.fromkeys(RUN_FILES, 0.0)
    disk = dict(cpu)
    du: dict[str, list] = {files: [] for files in RUN_FILES}
    stood = 0
    for index, case in enumerate(cases):
        try:
            for files in RUN_FILES:
                folder = runs / files / str(index)
                shutil.rmtree(folder, ignore_errors=True)
                start = time.process_time()
                summary = simulate_static(
                    case.with_overrides({"numerics.run_files": files}), folder, log=lambda _: None
                )
                cpu[files] += time.process_time() - start
                disk[files] += sum(f.stat().st_size for f in folder.iterdir())
                du[files].append(summary.du_mm)
            stood += 1
        except YadearchError:  # an arch that does not stand under its own weight: no folder to weigh
            continue
    figures: dict[str, Any] = {
        f"run_files_{files}_{what}": value / stood
        for what, table in (("cpu_s", cpu), ("bytes", disk))
        for files, value in table.items()
    }
    figures["run_files_same_du"] = du["full"] == du["summary"]
    figures["run_files_samples"] = stood
    figures["run_files_cpu_ratio"] = cpu["summary"] / cpu["full"]
    figures["run_files_disk_ratio"] = disk["summary"] / disk["full"]
    print(
        f"run folders of {stood} static samples (of {samples} drawn, the others do not stand): "
        f"whole {figures['run_files_full_cpu_s']:.3f} s CPU and "
        f"{figures['run_files_full_bytes'] / 1024:.0f} KiB a sample, summary only "
        f"{figures['run_files_summary_cpu_s']:.3f} s and {figures['run_files_summary_bytes'] / 1024:.0f} KiB "
        f"(CPU x{figures['run_files_cpu_ratio']:.2f}, disk x{figures['run_files_disk_ratio']:.3f}); "
        f"du {'the same to the bit' if figures['run_files_same_du'] else 'DIFFERS'}"
    )
    return figures


def run_files_verdicts(figures: dict[str, Any]) -> list[Verdict]:
    """A summary-only folder gives the same du on at most a tenth of the disk and no more CPU."""
    disk, cpu = figures["run_files_disk_ratio"], figures["run_files_cpu_ratio"]
    return [
        Verdict(
            "a summary-only folder: the same du, at most 1/10 of the disk, no more CPU",
            figures["run_files_same_du"] and disk <= TARGET_DISK_RATIO and cpu <= TARGET_CPU_RATIO,
            f"disk x{disk:.3f}, CPU x{cpu:.2f}",
        )
    ]
