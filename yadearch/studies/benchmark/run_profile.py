"""Where a static campaign run's CPU goes (issue 45; docs/speed.md keeps the last profile): the first
Saltelli runs of the sensitivity study solved in this process, once under cProfile and once without it,
after a warm-up run; the compiled loops' calls and time against everything else."""

from __future__ import annotations

import cProfile
import math
import pstats
import time
from typing import Any

from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.static.simulate import simulate_static
from yadearch.studies.benchmark.campaign_runs import saltelli_base, saltelli_rows
from yadearch.studies.campaigns.grid import RUN_COLUMN

KERNELS = ("descent_kernel", "newton_kernel")  # the compiled loops of the descent and of Newton


def saltelli_cases(runs: int) -> list[ArchCase]:
    """The sensitivity study's first `runs` Saltelli runs as static cases (set 2's base)."""
    base = saltelli_base()
    return [base.with_overrides({k: v for k, v in row.items() if k != RUN_COLUMN}) for row in saltelli_rows(runs)]


def _solve(case: ArchCase) -> None:
    """One run as a lean campaign's worker makes it (no folder); an arch that cannot stand counts too."""
    try:
        simulate_static(case, None, log=lambda _: None)
    except YadearchError:
        pass


def run_profile_measurement(runs: int) -> dict[str, Any]:
    """The CPU a run of the first `runs` Saltelli runs takes without the profiler, and under it each
    compiled loop's calls, time a call and share of the profiled time (all three on the wall's clock,
    the profiler's own: shares that add to one on a loaded machine too)."""
    if runs < 1:
        raise YadearchError(f"--run-profile must be >= 1, got {runs}")
    cases = saltelli_cases(runs + 1)
    _solve(cases[0])  # the imports and the kernels' loading, not a run's
    start = time.process_time()
    for case in cases[1:]:
        _solve(case)
    bare = (time.process_time() - start) / runs
    profile = cProfile.Profile()  # its clock is the wall's (perf_counter): the shares are of the wall time
    start = time.perf_counter()
    profile.enable()
    for case in cases[1:]:
        _solve(case)
    profile.disable()
    profiled = time.perf_counter() - start
    figures: dict[str, Any] = {"profile_runs": runs, "profile_run_cpu_s": bare, "profiled_run_wall_s": profiled / runs}
    stats = pstats.Stats(profile).stats  # type: ignore[attr-defined]  # (file, line, name) -> (cc, nc, tt, ct, callers)
    for kernel in KERNELS:
        entries = [v for (_, _, name), v in stats.items() if name.endswith(f".{kernel}>")]
        calls = sum(e[1] for e in entries)
        spent = sum(e[2] for e in entries)
        figures[f"profile_{kernel}_calls_a_run"] = calls / runs
        figures[f"profile_{kernel}_ms_a_call"] = 1e3 * spent / calls if calls else math.nan
        figures[f"profile_{kernel}_share"] = spent / profiled
    rest = 1.0 - sum(figures[f"profile_{k}_share"] for k in KERNELS)
    print(
        f"a Saltelli run, {runs} in one process: {1e3 * bare:.1f} ms CPU without the profiler "
        f"({1e3 * profiled / runs:.1f} ms of wall time under it)"
    )
    for kernel in KERNELS:
        print(
            f"  {kernel}: {figures[f'profile_{kernel}_calls_a_run']:.1f} calls a run, "
            f"{figures[f'profile_{kernel}_ms_a_call']:.3f} ms a call, {100 * figures[f'profile_{kernel}_share']:.0f} % "
            "of the profiled time"
        )
    print(f"  the rest (Python, records, the arch's geometry, the profiler's own cost): {100 * rest:.0f} %")
    figures["profile_rest_share"] = rest
    return figures
