"""The rigid march of every atlas arch and movement (kn plays no part in it), on both branches of the
keystone's tie where the movement has a mirror image, kept in a table that a rerun reuses."""

from __future__ import annotations

import math
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically
from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.solve.limit import limit_analysis, stands
from yadearch.studies.atlas.grid import Geometry

TABLE = "rigid.csv"
KEY = "geometry"


def rigid_row(base: ArchCase, geometry: Geometry) -> dict[str, Any]:
    """The rigid march of one atlas arch: du, du_first and hinges on each branch, or why there is none."""
    row: dict[str, Any] = {KEY: geometry.name, "rigid_du_mm": math.nan, "rigid_du_first_mm": math.nan}
    try:
        case = base.with_overrides(geometry.overrides())
        if not stands(case):
            return {**row, "rigid_outcome": "cannot stand"}
        result = limit_analysis(case)
    except YadearchError as exc:
        return {**row, "rigid_outcome": f"failed: {exc}"}
    return {
        **row,
        "rigid_outcome": "stands" if result.du_mm is None else "collapse",
        "rigid_du_mm": _mm(result.du_mm),
        "rigid_du_first_mm": _mm(result.du_first_mm),
        "rigid_hinges": " ".join(result.collapse_hinges),
        "rigid_mode": result.collapse_mode,
        "rigid_other_du_mm": _mm(result.mirror_du_rigid_mm),
        "rigid_other_hinges": " ".join(result.mirror_collapse_hinges or ()),
    }


def _mm(value: float | None) -> float:
    return math.nan if value is None else value


def rigid_table(base: ArchCase, geometries: list[Geometry], out: Path, jobs: int = 1) -> pd.DataFrame:
    """OUT/rigid.csv: the rigid march of every geometry, computed on `jobs` processes for those the
    table does not hold yet (a rerun reuses what an earlier one computed)."""
    path = Path(out) / TABLE
    kept = pd.read_csv(path) if path.is_file() else pd.DataFrame(columns=[KEY])
    missing = [g for g in geometries if g.name not in set(kept[KEY])]
    if missing:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            rows = list(pool.map(rigid_row, [base] * len(missing), missing))
        kept = pd.concat([kept, pd.DataFrame(rows)], ignore_index=True) if len(kept) else pd.DataFrame(rows)
        write_csv_atomically(path, kept)
    return kept[kept[KEY].isin({g.name for g in geometries})].reset_index(drop=True)
