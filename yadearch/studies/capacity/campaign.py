"""The capacity map of any case: a campaign over the direction of the support movement (either
engine), the rigid-block limit of every direction beside it, and its table, report and figure
(`yadearch capacity`, `ya.capacity`; docs/movements.md)."""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path
from typing import Any

import pandas as pd
from tqdm import tqdm

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.comparison import fingerprinted
from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.plotting.capacity import capacity_polar_figure
from yadearch.plotting.sweep import ENGINE_LABELS
from yadearch.solve.limit import limit_analysis
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.runner import run_campaign
from yadearch.studies.capacity.directions import (
    DIRECTION_PARAMETER,
    RIGID_FAILED,
    RigidLimit,
    directions,
    map_markdown,
    map_table,
)

RUNS = "runs"
RIGID_CACHE = "rigid_limits.csv"  # the rigid limits solved so far, by arch and direction: a rerun reuses them
TABLE = "capacity.csv"
REPORT = "capacity.md"
FIGURE = "capacity_map"


def rigid_limits(
    case: ArchCase, direction_values: tuple[float, ...], cache: Path | None = None, progress: bool = True
) -> dict[float, RigidLimit]:
    """The rigid limit of every direction on both branches of the keystone's tie where the movement
    is not its own mirror image (kn plays no part); a direction the analysis cannot follow has no du
    and its reason as the mode ("failed: ..."). With a `cache` (a CSV), directions solved before for
    the same arch are read back and the new ones added: a rerun redoes nothing; `progress` shows a bar
    over those it solves."""
    key = rigid_key(case)
    kept = pd.read_csv(cache) if cache is not None and cache.is_file() else pd.DataFrame(columns=RIGID_COLUMNS)
    mine = kept[kept["arch"] == key]
    limits = {float(r.direction_deg): _limit(r) for r in mine.itertuples()}  # a failure: its reason as the mode
    missing = [d for d in direction_values if d not in set(mine["direction_deg"].astype(float))]
    rows = []
    for direction in tqdm(missing, desc="rigid limits", unit="direction", disable=not (progress and missing)):
        try:
            result = limit_analysis(case.with_overrides({DIRECTION_PARAMETER: direction}))
        except YadearchError as exc:  # said in the table (rigid_mode), not left empty
            limits[direction] = RigidLimit(None, "", mode=f"{RIGID_FAILED}{exc}")
            rows.append({"arch": key, "direction_deg": direction, "solved": False, "mode": limits[direction].mode})
            continue
        limits[direction] = RigidLimit(
            result.du_rigid_mm,
            " ".join(result.collapse_hinges),
            result.mirror_du_rigid_mm,
            " ".join(result.mirror_collapse_hinges or ()),
            result.collapse_mode,
        )
        rows.append({"arch": key, "direction_deg": direction, "solved": True, **vars(limits[direction])})
    if cache is not None and rows:
        new = pd.DataFrame(rows).reindex(columns=list(RIGID_COLUMNS))  # every column, a failure's empty
        write_csv_atomically(cache, pd.concat([kept, new], ignore_index=True) if len(kept) else new)
    return {d: limits[d] for d in direction_values if d in limits}


RIGID_COLUMNS = ("arch", "direction_deg", "solved", "du_mm", "hinges", "other_du_mm", "other_hinges", "mode")


def rigid_key(case: ArchCase) -> str:
    """What the rigid limits depend on (the arch, its material's values, loading and defects; not kn,
    the numerics, the direction or a material's name; `fingerprinted`: a parameter a later version adds
    leaves it alone), as a short fingerprint."""
    data = fingerprinted(case.to_dict())
    arch = {k: data[k] for k in ("geometry", "material", "loading", "imperfections")}
    arch["loading"] = {k: v for k, v in arch["loading"].items() if k != DIRECTION_PARAMETER}
    return hashlib.sha1(json.dumps(arch, sort_keys=True, default=str).encode()).hexdigest()[:12]


def _limit(row: Any) -> RigidLimit:
    def mm(value: Any) -> float | None:
        return None if pd.isna(value) else float(value)

    def text(value: Any) -> str:
        return "" if pd.isna(value) else str(value)

    mode = text(getattr(row, "mode", math.nan))  # a cache from before the mode: not recorded
    return RigidLimit(mm(row.du_mm), text(row.hinges), mm(row.other_du_mm), text(row.other_hinges), mode)


def run_capacity(
    case: ArchCase,
    out: Path,
    pool: Pool,
    step_deg: float = 15.0,
    rigid: bool | dict[float, RigidLimit] = True,
    timeout_s: float | None = None,
    figures: bool = True,
) -> pd.DataFrame:
    """du of `case` every `step_deg` from spreading to closing (a resumable campaign in OUT/runs), the
    rigid limit beside it (`rigid`: computed, False: none, or given by direction); writes
    OUT/capacity.csv, capacity.md and (with `figures`) capacity_map.pdf/.png and returns the table."""
    values = directions(step_deg)
    results = run_campaign(
        case, [{DIRECTION_PARAMETER: d} for d in values], Path(out) / RUNS, pool, timeout_s=timeout_s
    )
    cache = Path(out) / RIGID_CACHE
    limits = rigid if isinstance(rigid, dict) else rigid_limits(case, values, cache) if rigid else {}
    table = map_table(case.name, results, limits)
    write_csv_atomically(Path(out) / TABLE, table)
    if figures:
        capacity_polar_figure(table, Path(out) / FIGURE, engine=ENGINE_LABELS[case.numerics.engine])
    write_text_atomically(Path(out) / REPORT, capacity_markdown(case, table, step_deg, FIGURE if figures else ""))
    return table


def capacity_markdown(case: ArchCase, table: pd.DataFrame, step_deg: float, figure: str) -> str:
    """capacity.md: the map of `case` (kn, engine) every `step_deg`, its table and `figure` ("": none drawn)."""
    failed = table[table["status"] != "done"]
    lines = [
        f"# Capacity map of {case.name}",
        "",
        f"du against the direction of the {case.loading.moving_support} support's movement every {step_deg:g}° "
        f"(0 = spreading, -90 = settlement, -180 = closing), kn = {case.interface.kn_N_per_mm3:g} N/mm³, "
        f"{case.numerics.engine} engine, beside the rigid-block limit of each direction (its other branch "
        "where the keystone's two joints tie; docs/movements.md).",
        "",
        *map_markdown(table),
        "",
        *([f"![capacity map]({figure}.png)", ""] if figure else []),
    ]
    lines += [f"- {r.direction_deg:g}°: {r.status} (see runs/{r.folder})." for r in failed.itertuples(index=False)]
    return "\n".join(lines) + "\n"
