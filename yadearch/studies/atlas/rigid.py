"""The rigid march of every atlas arch and movement (kn plays no part in it), on both branches of the
keystone's tie where the movement has a mirror image, kept in a table that a rerun reuses."""

from __future__ import annotations

import math
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically
from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.solve.limit import limit_analysis
from yadearch.solve.standing import stands
from yadearch.studies.atlas.grid import Geometry

TABLE = "rigid.csv"
COMPLIANT_TABLE = "compliant.csv"
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
    """OUT/rigid.csv: the rigid march of every geometry (`_kept_rows`)."""
    return _kept_rows(Path(out) / TABLE, geometries, partial(rigid_row, base), jobs)


def _kept_rows(
    path: Path, geometries: list[Geometry], row: Callable[[Geometry], dict[str, Any]], jobs: int
) -> pd.DataFrame:
    """The rows of `geometries` in the table at `path`: those it does not hold yet computed by `row`
    on `jobs` processes and added to it, so that a rerun reuses what an earlier one computed."""
    kept = pd.read_csv(path) if path.is_file() else pd.DataFrame(columns=[KEY])
    missing = [g for g in geometries if g.name not in set(kept[KEY])]
    if missing:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            rows = list(pool.map(row, missing))
        kept = pd.concat([kept, pd.DataFrame(rows)], ignore_index=True) if len(kept) else pd.DataFrame(rows)
        write_csv_atomically(path, kept)
    return kept[kept[KEY].isin({g.name for g in geometries})].reset_index(drop=True)


def compliant_row(base: ArchCase, geometry: Geometry, kn_N_per_mm3: float) -> dict[str, Any]:
    """The compliant march of one atlas arch at `kn_N_per_mm3` (the joints beside the hinges folding at
    that stiffness's margin, `solve.compliant`): the du a deformable arch of that kn should reach,
    on both branches of the keystone's tie as the rigid row keeps them."""
    row: dict[str, Any] = {KEY: geometry.name, "compliant_du_mm": math.nan, "compliant_other_du_mm": math.nan}
    try:
        case = base.with_overrides({**geometry.overrides(), "kn_N_per_mm3": kn_N_per_mm3})
        if not stands(case):
            return {**row, "compliant_outcome": "cannot stand"}
        result = limit_analysis(case, compliant=True)
    except YadearchError as exc:
        return {**row, "compliant_outcome": f"failed: {exc}"}
    return {
        **row,
        "compliant_outcome": "stands" if result.du_mm is None else "collapse",
        "compliant_du_mm": _mm(result.du_mm),
        "compliant_hinges": " ".join(result.collapse_hinges),
        "compliant_other_du_mm": _mm(result.mirror_du_rigid_mm),
    }


def compliant_table(
    base: ArchCase, geometries: list[Geometry], kn_N_per_mm3: float, out: Path, jobs: int = 1
) -> pd.DataFrame:
    """OUT/compliant.csv: the compliant march of every geometry at `kn_N_per_mm3` (`_kept_rows`)."""
    return _kept_rows(
        Path(out) / COMPLIANT_TABLE, geometries, partial(compliant_row, base, kn_N_per_mm3=kn_N_per_mm3), jobs
    )
