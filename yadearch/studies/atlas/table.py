"""The atlas's tidy table (pure): one row an arch, movement and stiffness, the static engine's,
the DEM's and the rigid march's du_first and du side by side, with the gaps its targets are read on."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pandas as pd

from yadearch.studies.atlas.grid import KNS_N_PER_MM3, REFERENCE_RADIUS_MM, Geometry, geometries
from yadearch.studies.atlas.rigid import KEY
from yadearch.studies.campaigns.grid import RUN_COLUMN

STIFF_TARGET_PCT = 2.0  # static at the stiffest kn against the rigid march
FIRST_WIDE_PCT = 10.0  # a wider reading of the stiff du_first gap (the snap floor counts snaps alike, not at one place)
ENGINES_TARGET_PCT = 1.0  # static against the DEM, on du and on du_first
RISE_TOLERANCE_PCT = 1.0  # du may fall this much from one kn to the next stiffer and still count as rising
ENGINE_COLUMNS = ("outcome", "du_first_mm", "du_mm", "collapse_kind", "hinges", "reason")
CHECK_COLUMNS = (
    "du_halved_increments_mm",
    "du_first_halved_increments_mm",
    "increments_resolved",
    "increments_mode_resolved",
)  # the static check's


def _engine_part(results: pd.DataFrame | None, prefix: str) -> pd.DataFrame:
    """`results` (a campaign's results.csv) as `prefix`_ columns keyed by run name."""
    columns = [RUN_COLUMN, *(f"{prefix}_{c}" for c in ENGINE_COLUMNS)]
    if results is None or results.empty:
        return pd.DataFrame(columns=columns)
    part = results.reindex(columns=[RUN_COLUMN, *ENGINE_COLUMNS, "status"]).copy()
    part.loc[part["status"].eq("failed") & part["outcome"].fillna("").eq(""), "outcome"] = "failed"
    part.loc[part["status"].eq("pending"), "outcome"] = math.nan  # not run yet
    part = part.drop(columns="status")
    return part.rename(columns={c: f"{prefix}_{c}" for c in ENGINE_COLUMNS})


def stored_engine(table: pd.DataFrame, prefix: str) -> pd.DataFrame:
    """An engine's runs as an atlas table (atlas.csv) holds them, in a campaign's results.csv form (those
    it ran, status done): the report made again from its table where the runs' folders are gone."""
    ran = table[table[f"{prefix}_outcome"].notna()]
    part = ran.reindex(columns=[RUN_COLUMN, *(f"{prefix}_{c}" for c in ENGINE_COLUMNS)])
    return part.rename(columns={f"{prefix}_{c}": c for c in ENGINE_COLUMNS}).assign(status="done")


def _check_part(static: pd.DataFrame | None) -> pd.DataFrame:
    """The static runs' increments check (`numerics.increments_check`) as static_ columns keyed by run
    name: du and du_first with the increments halved, and whether both held within 1 %."""
    columns = {name: f"static_{name}" for name in CHECK_COLUMNS}
    if static is None or static.empty:
        return pd.DataFrame(columns=[RUN_COLUMN, *columns.values()])
    return static.reindex(columns=[RUN_COLUMN, *CHECK_COLUMNS]).rename(columns=columns)


def gap_pct(value: float, reference: float) -> float:
    """100 (value - reference) / reference; NaN where either is missing."""
    if not (np.isfinite(value) and np.isfinite(reference)) or reference == 0.0:
        return math.nan
    return 100.0 * (value - reference) / reference


def nearest_branch_mm(du_mm: float, rigid: float, other: float) -> float:
    """The rigid du of the keystone tie's branch nearest `du_mm` (the branch a deformable arch took)."""
    branches = [b for b in (rigid, other) if np.isfinite(b)]
    if not branches:
        return math.nan
    return min(branches, key=lambda b: abs(b - du_mm)) if np.isfinite(du_mm) else branches[0]


def atlas_table(
    static: pd.DataFrame | None, rigid: pd.DataFrame, dem: pd.DataFrame | None, compliant: pd.DataFrame | None = None
) -> pd.DataFrame:
    """Every atlas run's row: its arch, the three solvers' answers and the gaps between them, and the
    compliant march at the stiffest kn where given (what the joints' compliance alone leaves of the
    rigid du)."""
    keys: list[dict[str, Any]] = []
    for geometry in geometries():
        for kn in KNS_N_PER_MM3:
            keys.append(_key(geometry, kn))
    table = pd.DataFrame(keys)
    table = table.merge(_engine_part(static, "static"), on=RUN_COLUMN, how="left")
    table = table.merge(_check_part(static), on=RUN_COLUMN, how="left")
    table = table.merge(_engine_part(dem, "dem"), on=RUN_COLUMN, how="left")
    table = table.merge(rigid, on=KEY, how="left")
    if compliant is not None:
        table = table.merge(compliant, on=KEY, how="left")
        table["compliant_branch_du_mm"] = [
            nearest_branch_mm(s, c, o) if k == max(KNS_N_PER_MM3) else math.nan
            for s, c, o, k in zip(
                table["static_du_mm"],
                table["compliant_du_mm"],
                table.get("compliant_other_du_mm", np.nan),
                table["kn_N_per_mm3"],
            )
        ]
        table["static_compliant_gap_pct"] = [
            gap_pct(s, c) for s, c in zip(table["static_du_mm"], table["compliant_branch_du_mm"])
        ]
    table["rigid_branch_du_mm"] = [
        nearest_branch_mm(s, r, o)
        for s, r, o in zip(table["static_du_mm"], table["rigid_du_mm"], table.get("rigid_other_du_mm", np.nan))
    ]
    table["static_rigid_gap_pct"] = [gap_pct(s, r) for s, r in zip(table["static_du_mm"], table["rigid_branch_du_mm"])]
    table["static_rigid_first_gap_pct"] = [  # du_first on the case's own branch (the mirror's is not tabulated)
        gap_pct(s, f) if b == r else math.nan
        for s, f, b, r in zip(
            table["static_du_first_mm"], table["rigid_du_first_mm"], table["rigid_branch_du_mm"], table["rigid_du_mm"]
        )
    ]
    table["dem_static_gap_pct"] = [gap_pct(d, s) for d, s in zip(table["dem_du_mm"], table["static_du_mm"])]
    table["dem_static_first_gap_pct"] = [
        gap_pct(d, s) for d, s in zip(table["dem_du_first_mm"], table["static_du_first_mm"])
    ]
    return table


def _key(geometry: Geometry, kn: float) -> dict[str, Any]:
    return {
        RUN_COLUMN: geometry.row(kn)[RUN_COLUMN],
        KEY: geometry.name,
        "shape": geometry.shape,
        "movement": geometry.movement,
        "thickness_mm": geometry.thickness_mm,
        "t_over_R": geometry.thickness_mm / REFERENCE_RADIUS_MM,
        "kn_N_per_mm3": kn,
    }


def stiff_rows(table: pd.DataFrame) -> pd.DataFrame:
    """The rows at the stiffest kn where both the static engine and the rigid march found a collapse."""
    stiff = table[table["kn_N_per_mm3"] == max(KNS_N_PER_MM3)]
    return stiff[stiff["static_outcome"].eq("collapse") & stiff["rigid_outcome"].eq("collapse")]


def engine_rows(table: pd.DataFrame) -> pd.DataFrame:
    """The rows the DEM ran where both engines found a collapse."""
    return table[table["dem_outcome"].eq("collapse") & table["static_outcome"].eq("collapse")]


def rising(table: pd.DataFrame) -> pd.DataFrame:
    """Per arch and movement collapsing at every kn: whether du rises with kn (falls at most
    RISE_TOLERANCE_PCT between neighbours) and its largest fall (%)."""
    rows = []
    for name, runs in table.groupby(KEY, sort=False):
        runs = runs.sort_values("kn_N_per_mm3")
        if not runs["static_outcome"].eq("collapse").all():
            continue
        du = runs["static_du_mm"].to_numpy(dtype=float)
        falls = 100.0 * (du[:-1] - du[1:]) / du[:-1]
        rows.append(
            {KEY: name, "largest_fall_pct": float(falls.max()), "rises": bool(falls.max() <= RISE_TOLERANCE_PCT)}
        )
    return pd.DataFrame(rows, columns=[KEY, "largest_fall_pct", "rises"])


def stiff_first_gaps(stiff: pd.DataFrame) -> pd.Series:
    """The static du_first's gap (%, absolute) to the rigid march's at the stiffest kn (`stiff_rows`), where
    the rigid du is the case's own branch (the mirror branch's du_first is not tabulated)."""
    if "static_rigid_first_gap_pct" not in stiff:
        return pd.Series(dtype=float)
    return stiff["static_rigid_first_gap_pct"].dropna().abs()
