"""The static engine's speed: set 2 and kn 100 as whole `yadearch run --engine static` runs and their
solver time, a 100-point kn sweep and 200 Monte Carlo samples on 2 cores, against the DEM; and the
solver's CPU against its compiled floor (`static.cost`)."""

from __future__ import annotations

import math
import shutil
import subprocess
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import pandas as pd

from yadearch.case.config import preset
from yadearch.results.rundir import read_summary
from yadearch.results.summary import RunSummary
from yadearch.static.cost import TARGET_FLOOR_RATIO, solver_cost
from yadearch.studies.benchmark.cli_run import static_run_command
from yadearch.studies.benchmark.verdicts import CAMPAIGN_CORES, TARGET_DU_REL, Verdict

MONTECARLO_BUMP_SD_MM = 0.18  # the imperfection study's final case
IMPERFECT_SAMPLE = {"imperfections.face_bump_sd_mm": MONTECARLO_BUMP_SD_MM, "imperfections.seed": 3}  # one sample
SWEEP_KN = np.logspace(np.log10(0.05), 4, 100)  # N/mm^3: the 100-point kn sweep
MONTECARLO_SAMPLES = 200
TARGET_SET2_SOLVER_S = 0.5
TARGET_SET2_WALL_S = 10.0  # the whole run: interpreter, solver, records and figures
TARGET_KN100_SOLVER_S = 2.0
TARGET_SWEEP100_S = 120.0
TARGET_MC200_S = 180.0


class StaticCampaigns(NamedTuple):
    """The API's `sweep` and `montecarlo` (`yadearch.api`, a layer above the studies: the caller hands
    them down) that the static engine's campaigns are timed through, figures included."""

    sweep: Callable[..., pd.DataFrame]
    montecarlo: Callable[..., pd.DataFrame]


def static_measurement(
    runs: Path, dem_set2: RunSummary, dem_stiff: RunSummary | None, campaigns: StaticCampaigns
) -> tuple[dict[str, Any], list[Verdict]]:
    """The static engine's costs (runs in `runs`) and their ratios to the DEM runs `dem_set2` and
    `dem_stiff` of the same invocation, with their verdicts."""
    summaries: dict[str, RunSummary] = {}
    cli_wall: dict[str, float] = {}
    for name, extra in (("set2", []), ("kn100", ["--kn", "100"])):
        folder = runs / name
        start = time.time()
        subprocess.run(
            static_run_command(folder, *extra),
            check=True,
            capture_output=True,
        )
        summaries[name], cli_wall[name] = read_summary(folder), time.time() - start
    jobs = {
        "sweep100": lambda out: campaigns.sweep(
            preset("set2"), out=out, jobs=CAMPAIGN_CORES, engine="static", kn_N_per_mm3=list(SWEEP_KN)
        ),
        "mc200": lambda out: campaigns.montecarlo(
            preset("set2").with_overrides({"imperfections.face_bump_sd_mm": MONTECARLO_BUMP_SD_MM}),
            out=out,
            samples=MONTECARLO_SAMPLES,
            jobs=CAMPAIGN_CORES,
            engine="static",
        ),
    }
    walls, done = {}, {}
    for name, job in jobs.items():
        shutil.rmtree(runs / name, ignore_errors=True)
        start = time.time()
        table = job(runs / name)
        walls[name], done[name] = time.time() - start, (int((table["status"] == "done").sum()), len(table))
    s2, k100 = summaries["set2"], summaries["kn100"]
    figures: dict[str, Any] = {
        "static_set2_wall_s": cli_wall["set2"],
        "static_set2_solver_s": float(s2.solver_wall_s or 0.0),
        "static_set2_du_mm": float(s2.du_mm or 0.0),
        "static_kn100_wall_s": float(k100.solver_wall_s or 0.0),
        "static_kn100_cli_wall_s": cli_wall["kn100"],
        "static_kn100_du_mm": float(k100.du_mm or 0.0),
        "static_sweep100_wall_s": walls["sweep100"],
        "static_mc200_wall_s": walls["mc200"],
        "static_over_dem_speedup": dem_set2.wall_s / cli_wall["set2"],
        "static_kn100_over_dem_speedup": dem_stiff.wall_s / cli_wall["kn100"] if dem_stiff else None,
    }
    dem_du = float(dem_set2.du_mm or math.nan)
    print(
        f"static engine: set 2 {cli_wall['set2']:.1f} s whole run ({figures['static_set2_solver_s']:.2f} s "
        f"solver), {figures['static_over_dem_speedup']:.0f}x faster than the DEM's {dem_set2.wall_s:.0f} s; du "
        f"{figures['static_set2_du_mm']:.2f} against {dem_du:.2f} mm ({_du_diff(figures, dem_du):.2%})"
    )
    return figures, static_verdicts(figures, dem_du, done)


def _du_diff(figures: dict[str, Any], dem_du_mm: float) -> float:
    """The static engine's du on set 2 relative to the DEM's."""
    return abs(figures["static_set2_du_mm"] / dem_du_mm - 1.0)


def static_verdicts(figures: dict[str, Any], dem_du_mm: float, done: dict[str, tuple[int, int]]) -> list[Verdict]:
    """The static engine's targets met or not by its `figures` (`static_measurement`), the DEM's du on
    set 2 and the campaigns' runs `done` (done, of how many)."""
    s2_solver, s2_wall = figures["static_set2_solver_s"], figures["static_set2_wall_s"]
    k100_solver, du_diff = figures["static_kn100_wall_s"], _du_diff(figures, dem_du_mm)
    sweep_s, mc_s = figures["static_sweep100_wall_s"], figures["static_mc200_wall_s"]
    return [
        Verdict(
            f"static set 2 solver <= {TARGET_SET2_SOLVER_S:g} s, whole run <= {TARGET_SET2_WALL_S:g} s",
            s2_solver <= TARGET_SET2_SOLVER_S and s2_wall <= TARGET_SET2_WALL_S,
            f"{s2_solver:.2f} s solver, {s2_wall:.1f} s whole run",
        ),
        Verdict("static set 2 du within 1 % of the DEM's", du_diff <= TARGET_DU_REL, f"{du_diff:.2%}"),
        Verdict(
            f"static kn 100 <= {TARGET_KN100_SOLVER_S:g} s",
            k100_solver <= TARGET_KN100_SOLVER_S,
            f"{k100_solver:.2f} s solver ({figures['static_kn100_cli_wall_s']:.1f} s whole run), du "
            f"{figures['static_kn100_du_mm']:.2f} mm",
        ),
        Verdict(
            f"static 100-point kn sweep 0.05-10000 <= {TARGET_SWEEP100_S / 60:g} min on {CAMPAIGN_CORES} cores",
            sweep_s <= TARGET_SWEEP100_S,
            f"{sweep_s:.0f} s, {done['sweep100'][0]} of {done['sweep100'][1]} done",
        ),
        Verdict(
            f"static {MONTECARLO_SAMPLES} Monte Carlo samples <= {TARGET_MC200_S / 60:g} min on {CAMPAIGN_CORES} cores",
            mc_s <= TARGET_MC200_S,
            f"{mc_s:.0f} s, {done['mc200'][0]} of {done['mc200'][1]} done",
        ),
    ]


def static_floor_measurement() -> dict[str, Any]:
    """The static solver's CPU on set 2 and on an imperfect sample against its compiled floor (the same
    evaluations and solves in a compiled loop, `static.cost`), in this one process."""
    base = preset("set2").with_overrides({"engine": "static"})
    figures: dict[str, Any] = {}
    for name, case in {"set2": base, "imperfect": base.with_overrides(IMPERFECT_SAMPLE)}.items():
        cost = solver_cost(case)
        print(
            f"static solver, {name}: {cost.solver_cpu_s * 1e3:.1f} ms CPU for {cost.evaluations} joint evaluations "
            f"and {cost.iterations} iterations; floor {cost.evaluation_s * 1e6:.1f} us an evaluation, "
            f"{cost.solve_s * 1e6:.1f} us a solve, {cost.floor_cpu_s * 1e3:.1f} ms in all; ratio {cost.ratio:.2f}"
        )
        figures[f"static_floor_{name}"] = {
            "solver_cpu_s": cost.solver_cpu_s,
            "evaluations": cost.evaluations,
            "iterations": cost.iterations,
            "evaluation_s": cost.evaluation_s,
            "solve_s": cost.solve_s,
            "ratio": cost.ratio,
        }
    return figures


def static_floor_verdicts(figures: dict[str, Any]) -> list[Verdict]:
    """Each case's solver at most TARGET_FLOOR_RATIO times its compiled floor (`static_floor_measurement`)."""
    prefix = "static_floor_"
    return [
        Verdict(
            f"static solver of {key.removeprefix(prefix)} <= {TARGET_FLOOR_RATIO:g} x its compiled floor",
            cost["ratio"] <= TARGET_FLOOR_RATIO,
            f"{cost['ratio']:.2f}",
        )
        for key, cost in figures.items()
        if key.startswith(prefix)
    ]
