"""The static engine against the DEM: every committed DEM run solved again statically, du and the
hinges at collapse side by side (docs/validation-engines.md).

A DEM run is any finished run folder (case.toml and summary.json); the static run takes the same
case with numerics.engine = 'static'. Static runs execute in worker processes, each reused from its
folder when it already holds a finished run of the same case (the cross-check resumes).
"""

from __future__ import annotations

import json
import math
import os
import tomllib
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase, case_from_dict
from yadearch.results.reuse import holds_case
from yadearch.results.rundir import SUMMARY_FILE, is_complete, read_summary
from yadearch.results.summary import RunSummary
from yadearch.studies.campaigns.failures import FAILED_FILE
from yadearch.studies.robustness import same_hinge_set

AGREEMENT_PCT = 1.0  # the target: static du within 1 % of the DEM's where the DEM is converged


@dataclass(frozen=True)
class Pair:
    """One DEM run and the static run of the same case."""

    group: str
    name: str
    case: ArchCase
    dem: RunSummary | str  # the DEM run's summary, or why it failed


def pair_from_folder(group: str, folder: Path) -> Pair:
    """The DEM run in `folder` and its case switched to the static engine."""
    case = case_from_dict(tomllib.loads((folder / "case.toml").read_text()))
    dem: RunSummary | str
    if (folder / SUMMARY_FILE).is_file():
        dem = read_summary(folder)
    else:  # a failed DEM run: its reason, which the static run should share
        failed = folder / FAILED_FILE
        dem = json.loads(failed.read_text()).get("reason", "failed") if failed.is_file() else "no summary"
    return Pair(group, folder.name, case.with_overrides({"numerics.engine": "static"}), dem)


def _run_static(case: ArchCase, folder: Path) -> RunSummary | str:
    """Solve `case` statically into `folder` (reused when it holds this case); its summary, or why
    it failed."""
    from yadearch.static.simulate import simulate_static

    if holds_case(folder, case):
        return read_summary(folder)
    try:
        return simulate_static(case, folder, log=lambda line: None)
    except Exception as exc:  # noqa: BLE001  a failed run is recorded with its reason, the others go on
        return f"{type(exc).__name__}: {exc}"


def run_pairs(pairs: list[Pair], out: Path, jobs: int) -> pd.DataFrame:
    """Every pair's static run (in `out`/GROUP/NAME, `jobs` processes) beside its DEM summary (both
    survive every snap that re-settles: du_first and du side by side)."""
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    folders = [out / pair.group / pair.name for pair in pairs]
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        statics = list(pool.map(_run_static, [p.case for p in pairs], folders))
    return pd.DataFrame([comparison_row(pair, static) for pair, static in zip(pairs, statics)])


def comparison_row(pair: Pair, static_run: RunSummary | str) -> dict[str, Any]:
    """One table row: both engines' du, hinges, verdicts and costs."""
    num = pair.case
    (dem, dem_error), (static, static_error) = _split(pair.dem), _split(static_run)
    dem_du, static_du = dem.du_mm, static.du_mm
    dem_hinges, static_hinges = dem.hinge_labels, static.hinge_labels
    diff = 100.0 * (static_du / dem_du - 1.0) if dem_du and static_du else math.nan
    both_failed = bool(dem_error) and bool(static_error)  # e.g. neither stands under its weight
    snaps = static.snaps or []
    return {
        "group": pair.group,
        "run": pair.name,
        "kn_N_per_mm3": num.interface.kn_N_per_mm3,
        "direction_deg": num.loading.support_direction_deg,
        "seed": num.imperfections.seed,
        "dem_du_mm": dem_du,
        "static_du_mm": static_du,
        "dem_du_first_mm": dem.du_first_mm,
        "static_du_first_mm": static.du_first_mm,
        "static_outcome": static.path_outcome if not static_error else "failed",
        "difference_pct": diff,
        "within_1pct": bool(abs(diff) <= AGREEMENT_PCT) if math.isfinite(diff) else both_failed,
        "dem_hinges": dem_hinges,
        "static_hinges": static_hinges,
        "same_hinges": same_hinge_set(dem_hinges, static_hinges) or both_failed,
        "dem_verdict": dem.collapse_verdict,
        "static_verdict": static.collapse_verdict,
        "static_snaps": len(snaps),
        "largest_snap_mm": max((s["move_mm"] for s in snaps), default=0.0),
        "dem_wall_s": dem.wall_s,
        "static_wall_s": static.wall_s,
        "dem_error": dem_error,
        "static_error": static_error,
    }


def _split(run: RunSummary | str) -> tuple[RunSummary, str]:
    """A run's summary and "", or an empty summary (no du, no hinges) and why the run failed."""
    if isinstance(run, RunSummary):
        return run, ""
    return RunSummary(du_mm=None, hinges_at_collapse=(), steps=0, wall_s=math.nan), run


def dem_folders(root: Path, pattern: str) -> list[Path]:
    """Finished DEM run folders under `root` matching `pattern`, in name order."""
    return sorted(
        f
        for f in root.glob(pattern)
        if f.is_dir() and (f / "case.toml").is_file() and (f / SUMMARY_FILE).is_file() and is_complete(f)
    )


def crosscheck_markdown(table: pd.DataFrame, limits: pd.DataFrame) -> str:
    """crosscheck.md: the agreement per group, every pair outside 1 % or with other hinges, and the
    stiff end against the limit analyses; the engines' costs are the runs' own wall times (a rerun that
    reuses the static runs reports what they took)."""
    lines = [
        "# Static engine against the DEM",
        "",
        "Every committed DEM run solved again by the static engine (same case, `numerics.engine = "
        "'static'`): du and the hinges at collapse. Regenerate with "
        "`.venv/bin/python scripts/static_crosscheck.py` (table: `crosscheck.csv`).",
        "",
        f"{len(table)} pairs; the static runs took {table['static_wall_s'].sum():.0f} s of one core, "
        f"the DEM runs {table['dem_wall_s'].sum() / 3600:.1f} h.",
        "",
        "| group | runs | within 1 % | same hinges (±1 interface) | largest |difference| (%) | "
        "static wall (s, median) | DEM wall (s, median) |",
        "|---|---|---|---|---|---|---|",
    ]
    for group, rows in table.groupby("group", sort=False):
        lines.append(
            f"| {group} | {len(rows)} | {int(rows['within_1pct'].sum())} | {int(rows['same_hinges'].sum())} | "
            f"{rows['difference_pct'].abs().max():.2f} | {rows['static_wall_s'].median():.2f} | "
            f"{rows['dem_wall_s'].median():.0f} |"
        )
    outside = table[~table["within_1pct"] | ~table["same_hinges"]]
    lines += ["", "## Pairs outside 1 % or with other hinges", ""]
    if outside.empty:
        lines.append("None.")
    else:
        lines += [
            "| group | run | kn (N/mm³) | DEM du (mm) | static du (mm) | difference (%) | DEM hinges | "
            "static hinges | static snaps (largest, mm) | du_first DEM / static (mm) |",
            "|---|---|---|---|---|---|---|---|---|---|",
        ]
        for r in outside.itertuples():
            lines.append(
                f"| {r.group} | {r.run} | {r.kn_N_per_mm3:g} | {_mm(r.dem_du_mm)} | {_mm(r.static_du_mm)} | "
                f"{r.difference_pct:+.2f} | {r.dem_hinges} | {r.static_hinges} | "
                f"{r.static_snaps} ({r.largest_snap_mm:.2f}) | {_mm(r.dem_du_first_mm)} / "
                f"{_mm(r.static_du_first_mm)} |"
            )
    for r in table[table["dem_error"].astype(bool)].itertuples():
        lines += [
            "",
            f"{r.run}: neither engine finds an equilibrium (counted as agreement). DEM: {r.dem_error}; "
            f"static: {r.static_error or 'ran'}",
        ]
    if not limits.empty:
        lines += [
            "",
            "## Toward stiff joints: the compliant march and the rigid limit",
            "",
            "| run | kn (N/mm³) | static du (mm) | compliant march (mm) | difference (%) | rigid du (mm) | "
            "difference (%) |",
            "|---|---|---|---|---|---|---|",
        ]
        for r in limits.itertuples():
            rigid = r.rigid_du_mm if isinstance(r.rigid_du_mm, float) and math.isfinite(r.rigid_du_mm) else None
            lines.append(
                f"| {r.run} | {r.kn_N_per_mm3:g} | {_mm(r.static_du_mm)} | {_mm(r.compliant_du_mm)} | "
                f"{_pct(r.static_du_mm, r.compliant_du_mm)} | {_mm(rigid)} | {_pct(r.static_du_mm, rigid)} |"
            )
    return "\n".join(lines) + "\n"


def _mm(value: float | None) -> str:
    return "—" if value is None or not math.isfinite(value) else f"{value:.2f}"


def _pct(value: float | None, reference: float | None) -> str:
    if value is None or reference is None or not math.isfinite(value) or not math.isfinite(reference):
        return "—"
    return f"{100.0 * (value / reference - 1.0):+.2f}"
