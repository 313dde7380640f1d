"""The sensitivity study checked by the other engine: the one-at-a-time runs that move du most, run
again on the DEM (or, for a study on the DEM, on the static engine), both answers side by side
(docs/validation-imperfections.md, "What du is sensitive to")."""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.bounds import MAX_CHECKS
from yadearch.case.config import ArchCase
from yadearch.errors import CampaignError
from yadearch.launch.process import STATIC_ENGINE
from yadearch.markdown import markdown_table
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings
from yadearch.studies.sensitivity.indices import BASE_RUN, Factor, tornado_rows

CHECK_RUNS = "check_runs"
AGREEMENT = 0.01  # the two engines' du within this fraction (the cross-check's standard, docs/validation.md)
DEM_ENGINE = "dem"
ENGINE_NAMES = {DEM_ENGINE: "the DEM", STATIC_ENGINE: "the static engine"}


def other_engine(engine: str) -> str:
    """The engine that checks a study made on `engine`."""
    return DEM_ENGINE if engine == STATIC_ENGINE else STATIC_ENGINE


def check_count(count: int) -> None:
    """Refuse a number of checks outside 0..MAX_CHECKS in one line."""
    if not 0 <= count <= MAX_CHECKS:
        raise CampaignError(f"check runs must be between 0 and {MAX_CHECKS}, got {count}")


def check_rows(
    base: ArchCase, factors: tuple[Factor, ...], study_runs: pd.DataFrame, count: int
) -> list[dict[str, Any]]:
    """The `count` one-at-a-time runs (`tornado_rows`) whose du in `study_runs` lies furthest from the
    base case's, as campaign rows."""
    du = dict(zip(study_runs[RUN_COLUMN], study_runs["du_mm"]))
    rows = [row for row in tornado_rows(base, factors) if row[RUN_COLUMN] != BASE_RUN]
    finite = [row for row in rows if math.isfinite(du.get(row[RUN_COLUMN], math.nan))]
    finite.sort(key=lambda row: -abs(du[row[RUN_COLUMN]] - du[BASE_RUN]))
    return finite[:count]


def run_checks(
    base: ArchCase,
    study_runs: pd.DataFrame,
    factors: tuple[Factor, ...],
    count: int,
    out: Path,
    pool: Pool,
    timeout_s: float | None = None,
    progress: bool = True,
    settings: Mapping[str, Any] = NO_DEM_SETTINGS,
) -> pd.DataFrame:
    """Run (or resume) in OUT/check_runs, on the other engine with its numerical `settings`, the `count`
    one-at-a-time runs of `study_runs` (the tornado campaign's results) that move du most; return both
    engines' du, hinges and run times per check (empty if `count` is 0)."""
    rows = check_rows(base, factors, study_runs, count)
    if not rows:
        return pd.DataFrame()
    study, check = base.numerics.engine, other_engine(base.numerics.engine)
    checked = run_campaign(
        with_dem_settings(base.with_overrides({"numerics.engine": check}), settings),
        rows,
        Path(out) / CHECK_RUNS,
        pool,
        timeout_s=timeout_s,
        progress=progress,
    )
    mine = study_runs.set_index(RUN_COLUMN)
    table = []
    for row in checked.itertuples():
        own = mine.loc[row.run]
        table.append(
            {
                RUN_COLUMN: row.run,
                f"{study}_du_mm": own["du_mm"],
                f"{check}_du_mm": row.du_mm,
                "difference_pct": 100.0 * (own["du_mm"] - row.du_mm) / row.du_mm,
                f"{study}_hinges": own["hinges"],
                f"{check}_hinges": row.hinges,
                f"{study}_wall_s": own["wall_s"],
                f"{check}_wall_s": row.wall_s,
            }
        )
    return pd.DataFrame(table)


def checks_markdown(checks: pd.DataFrame, study: str) -> list[str]:
    """The report's section on the checks: a table of both engines' answers and the agreement."""
    if checks.empty:
        return []
    check = other_engine(study)
    agree = int((checks["difference_pct"].abs() <= 100 * AGREEMENT).sum())
    lines = [
        f"## Checked by {ENGINE_NAMES[check]}",
        "",
        f"The one-at-a-time runs that move du most, made again by {ENGINE_NAMES[check]}: {agree} of "
        f"{len(checks)} within {100 * AGREEMENT:g} % (the difference is the {study} du against the {check} du).",
        "",
    ]
    columns = [f"du, {study} (mm)", f"du, {check} (mm)", "difference"]
    columns += [f"hinges, {study}", f"hinges, {check}", f"wall, {study} (s)", f"wall, {check} (s)"]
    rows = (
        [r[RUN_COLUMN], f"{r[f'{study}_du_mm']:.2f}", f"{r[f'{check}_du_mm']:.2f}", f"{r['difference_pct']:+.2f} %"]
        + [r[f"{study}_hinges"], r[f"{check}_hinges"], f"{r[f'{study}_wall_s']:.1f}", f"{r[f'{check}_wall_s']:.1f}"]
        for _, r in checks.iterrows()
    )
    return [*lines, *markdown_table(["run", *columns], rows), ""]
