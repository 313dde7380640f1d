"""Campaigns as functions: sweeps, Monte Carlo draws, kn calibration, robustness, capacity maps and
sensitivity studies, each resumable in its folder, on local cores or a dask scheduler; each `log`s
what it starts and draws its figures, and the command line prints and exits on what they return."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pandas as pd

from yadearch.api.arguments import check_arguments
from yadearch.api.runs import as_case, with_engine
from yadearch.case.config import ArchCase
from yadearch.case.names import FILE, output_path
from yadearch.errors import ArgumentTypeError, CampaignError
from yadearch.studies.campaigns.grid import check_campaign_size
from yadearch.studies.sensitivity.indices import Factor  # a sensitivity factor, for the API's users too

if TYPE_CHECKING:
    from yadearch.studies.calibration import Calibration
    from yadearch.studies.sensitivity.study import SensitivityResult

Log = Callable[[str], None]


def _quiet(_line: str) -> None:
    """The default `log`: a notebook gets the progress bars, not the messages."""


def sweep(
    case: ArchCase | str,
    out: str | Path,
    jobs: int | None = None,
    scheduler: str | None = None,
    timeout_s: float | None = None,
    engine: str | None = None,
    table: str | Path | None = None,
    retry_failed: bool = True,
    figures: bool = True,
    log: Log = _quiet,
    **values: list[Any],
) -> pd.DataFrame:
    """Run `case` over the grid of parameter `values` (e.g. `kn_N_per_mm3=[0.25, 1, 5.2]`), or the
    rows of a CSV `table` (one column a parameter), as a resumable campaign in `out` (runs recorded
    as failed are run again unless not `retry_failed`); draws du against each swept parameter
    (`figures`) and returns the results table (one row a run)."""
    from yadearch.studies.campaigns.executors import open_pool
    from yadearch.studies.campaigns.grid import grid, read_table
    from yadearch.studies.campaigns.runner import run_campaign
    from yadearch.studies.sweep_figures import sweep_figures

    check_arguments(jobs=jobs, timeout_s=timeout_s, retry_failed=retry_failed, figures=figures)
    folder = output_path(out, "out")
    if table is not None and values:
        raise CampaignError("give either a table of runs or grid values, not both")
    if table is None and not values:
        raise CampaignError("nothing to sweep: give grid values (e.g. kn_N_per_mm3=[...]) or a table of runs")
    base = with_engine(case, engine)
    rows = read_table(output_path(table, "table", FILE)) if table is not None else grid(values)
    with open_pool(jobs, scheduler) as pool:
        log(f"campaign {folder}: {len(rows)} runs on {pool.where}")
        results = run_campaign(base, rows, folder, pool, timeout_s=timeout_s, retry_failed=retry_failed)
    if figures:
        paths = sweep_figures(results, rows, folder, base, note=log)
        if paths:
            log(f"figure -> {', '.join(map(str, paths))}")
    return results


def montecarlo(
    case: ArchCase | str,
    out: str | Path,
    samples: int,
    seed: int = 1,
    jobs: int | None = None,
    scheduler: str | None = None,
    timeout_s: float | None = None,
    engine: str | None = None,
    figures: bool = True,
    log: Log = _quiet,
    **levels: list[Any],
) -> pd.DataFrame:
    """`samples` seeded draws of `case`'s imperfections (at every combination of the amplitude
    `levels`, e.g. `edge_radius_mm=[0.5, 1]`) as a resumable campaign in `out`, with the distribution
    figures (`figures`); returns the table of montecarlo.csv (du, hinges and each sample's
    imperfection summary)."""
    from yadearch.studies.campaigns.executors import open_pool
    from yadearch.studies.montecarlo import check_drawn, run_montecarlo
    from yadearch.studies.montecarlo import levels as level_columns

    check_arguments(samples=samples, seed=seed, jobs=jobs, timeout_s=timeout_s, figures=figures)
    folder = output_path(out, "out")
    base = with_engine(case, engine)
    for key, values in levels.items():
        if isinstance(values, (str, bytes)) or not hasattr(values, "__len__"):
            raise ArgumentTypeError(f"{key}: give a list of amplitude levels, got {values!r:.40}")
    check_campaign_size(samples * math.prod(len(v) for v in levels.values()))
    check_drawn(base, levels)
    with open_pool(jobs, scheduler) as pool:
        n_levels = math.prod(len(v) for v in levels.values())
        log(f"Monte Carlo {folder}: {samples} samples x {n_levels} level(s) on {pool.where}")
        table = run_montecarlo(base, folder, pool, samples, seed, levels or None, timeout_s=timeout_s)
    if figures:
        from yadearch.plotting.montecarlo import campaign_figures

        try:
            paths = campaign_figures(table, folder, level_columns(table, levels))
            log(f"figures -> {', '.join(str(p) for p in paths if p.suffix == '.pdf')}")
        except ValueError as exc:
            log(f"no figure: {exc}")
    return table


def calibrate(
    case: ArchCase | str,
    target_du_mm: float,
    out: str | Path,
    kn_min: float = 0.1,
    kn_max: float = 100.0,
    tolerance_mm: float = 0.5,
    max_runs: int = 12,
    jobs: int | None = None,
    engine: str | None = None,
    scheduler: str | None = None,
    timeout_s: float | None = None,
    log: Log = _quiet,
) -> Calibration:
    """The kn at which `case` collapses at `target_du_mm` (within `tolerance_mm`, at most `max_runs`
    runs), by bracketing root finding over runs kept in `out` (local processes, or the dask
    `scheduler`); returns the `Calibration` (its `write(path)` saves it as JSON)."""
    from yadearch.studies.calibration import calibrate as calibrate_kn
    from yadearch.studies.calibration import campaign_evaluator
    from yadearch.studies.campaigns.executors import open_pool

    check_arguments(
        target_du_mm=target_du_mm,
        kn_min=kn_min,
        kn_max=kn_max,
        tolerance_mm=tolerance_mm,
        max_runs=max_runs,
        jobs=jobs,
        timeout_s=timeout_s,
    )
    if kn_min >= kn_max:
        raise CampaignError(f"kn_min must be below kn_max, got {kn_min:g} and {kn_max:g}")
    folder, base = output_path(out, "out"), with_engine(case, engine)
    with open_pool(jobs, scheduler) as pool:
        found = calibrate_kn(
            campaign_evaluator(base, folder, pool, timeout_s),
            target_du_mm,
            tolerance_mm,
            kn_min,
            kn_max,
            max_runs,
            log=log,
        )
    return dataclasses.replace(found, case=base.name, engine=base.numerics.engine)


def robustness(
    case: ArchCase | str,
    out: str | Path,
    kn_values: tuple[float, ...] | None = None,
    variants: tuple[str, ...] | None = None,
    jobs: int | None = None,
    scheduler: str | None = None,
    timeout_s: float | None = None,
) -> pd.DataFrame:
    """Every kn (default: the study's) with each numerical variant and with higher friction, a
    resumable study in `out` that writes robustness.csv and robustness.md; returns the verdict per
    kn (`studies.robustness.verdicts`)."""
    from yadearch.studies.campaigns.executors import open_pool
    from yadearch.studies.robustness import KN_VALUES, VARIANTS, run_study, verdicts

    check_arguments(jobs=jobs, timeout_s=timeout_s)
    folder, base = output_path(out, "out"), as_case(case)
    if isinstance(kn_values, (str, bytes)) or isinstance(variants, (str, bytes)):
        raise ArgumentTypeError("kn_values and variants must be tuples of values, not a str")
    with open_pool(jobs, scheduler) as pool:
        table = run_study(base, folder, pool, kn_values or KN_VALUES, variants or tuple(VARIANTS), timeout_s=timeout_s)
    return verdicts(table)


def capacity(
    case: ArchCase | str,
    out: str | Path,
    step_deg: float = 15.0,
    engine: str | None = None,
    jobs: int | None = None,
    scheduler: str | None = None,
    timeout_s: float | None = None,
    rigid: bool = True,
    figures: bool = True,
) -> pd.DataFrame:
    """The capacity map of `case`: du against the direction of the support movement every `step_deg`
    from spreading (0) to closing (-180), a resumable campaign in OUT/runs, with the rigid limit of
    each direction (unless not `rigid`); writes OUT/capacity.csv, capacity.md and the polar figure
    (unless not `figures`) and returns the table."""
    from yadearch.studies.campaigns.executors import open_pool
    from yadearch.studies.capacity.campaign import run_capacity
    from yadearch.studies.capacity.directions import directions

    check_arguments(step_deg=step_deg, jobs=jobs, timeout_s=timeout_s, rigid=rigid, figures=figures)
    folder, case = output_path(out, "out"), with_engine(case, engine)
    directions(step_deg)  # refuses a step that does not divide 180 before anything starts
    with open_pool(jobs, scheduler) as pool:
        return run_capacity(case, folder, pool, step_deg, rigid=rigid, timeout_s=timeout_s, figures=figures)


def sensitivity(
    case: ArchCase | str,
    out: str | Path,
    base_points: int | None = None,
    factors: tuple[Factor | str, ...] | None = None,
    engine: str | None = None,
    jobs: int | None = None,
    scheduler: str | None = None,
    timeout_s: float | None = None,
    check_runs: int = 0,
    figures: bool = True,
    check_settings: dict[str, Any] | None = None,
) -> SensitivityResult:
    """What du of `case` is sensitive to: each factor alone at the ends of its range (a tornado) and
    Sobol indices from Saltelli's sample of `base_points` (a power of two; default
    `sensitivity_campaign.DEFAULT_BASE_POINTS`, 128), both resumable campaigns in
    `out`; `factors` (`Factor`s, "NAME=LOW:HIGH[:log|:int]" texts as the command line's --factor, or the
    names of the paper's factors) default to the paper arch's plausible ranges; the `check_runs`
    one-at-a-time runs that move du most are made again on the other engine (the DEM for a static
    study), with the numerical `check_settings` ({"numerics.KEY": value}, e.g. the DEM's
    `numerics.support_path_states`). Writes the tables, figures (unless not `figures`) and
    sensitivity.md; returns the `SensitivityResult`."""
    from yadearch.studies.campaigns.executors import open_pool
    from yadearch.studies.dem_settings import checked_settings
    from yadearch.studies.sensitivity.checks import check_count
    from yadearch.studies.sensitivity.indices import PAPER_FACTORS, as_factor, check_base_points, check_factors
    from yadearch.studies.sensitivity.study import DEFAULT_BASE_POINTS, run_sensitivity

    check_arguments(base_points=base_points, check_runs=check_runs, jobs=jobs, timeout_s=timeout_s, figures=figures)
    folder, case = output_path(out, "out"), with_engine(case, engine)
    chosen = tuple(as_factor(f) for f in factors) if factors else PAPER_FACTORS
    base_points = DEFAULT_BASE_POINTS if base_points is None else base_points
    check_base_points(base_points)  # refused before a pool starts
    check_factors(case, chosen)
    check_campaign_size(base_points * (len(chosen) + 2))  # Saltelli's N x (factors + 2) runs
    check_count(check_runs)
    settings = checked_settings(check_settings or {}, "check_settings")
    with open_pool(jobs, scheduler) as pool:
        return run_sensitivity(
            case,
            folder,
            pool,
            base_points,
            chosen,
            timeout_s=timeout_s,
            check_runs=check_runs,
            figures=figures,
            check_settings=settings,
        )
