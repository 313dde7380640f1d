"""A capacity map: du of one arch against the direction of the support movement, every
DIRECTION_STEP_DEG over the half-plane below the horizontal (spreading 0°, settlement -90°, closing
-180°), beside the rigid-block limit of each direction; pure tables, no YADE (docs/movements.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from yadearch.case.bounds import MAX_STEP_DEG, MIN_STEP_DEG
from yadearch.errors import CampaignError
from yadearch.solve.stages import Stage

DIRECTION_STEP_DEG = 15


def directions(step_deg: float = DIRECTION_STEP_DEG) -> tuple[float, ...]:
    """Directions every `step_deg` from spreading (0) through settlement (-90) to closing (-180);
    CampaignError naming the argument unless MIN_STEP_DEG <= step_deg <= MAX_STEP_DEG and it divides 180."""
    count = 180.0 / step_deg if MIN_STEP_DEG <= step_deg <= MAX_STEP_DEG else math.nan
    if not (math.isfinite(count) and abs(count - round(count)) < 1e-9):
        raise CampaignError(f"step_deg must divide 180 and lie in [{MIN_STEP_DEG:g}, {MAX_STEP_DEG}], got {step_deg!r}")
    return tuple(round(-k * step_deg, 9) + 0.0 for k in range(int(round(count)) + 1))


DIRECTIONS_DEG = directions()
DIRECTION_PARAMETER = "support_direction_deg"
HINGING = "hinging"  # the rigid collapse mode the map leaves unsaid
MAP_COLUMNS = (
    "set",
    "direction_deg",
    "du_first_mm",
    "du_mm",
    "du_x_mm",
    "du_y_mm",
    "hinges",
    "mechanism",
    "du_rigid_mm",
    "rigid_hinges",
    "rigid_mode",
    "du_over_rigid",
    "du_rigid_other_mm",
    "rigid_other_hinges",
    "steps",
    "wall_s",
    "status",
    "folder",
)


RIGID_FAILED = "failed: "  # a RigidLimit's mode where the analysis could not follow the direction, its reason after


@dataclass(frozen=True)
class RigidLimit:
    """The rigid-block limit of one direction (mm) and its collapse hinges ("9I 28E ..."), and those of
    the keystone tie's other branch where the movement is not its own mirror image (else None)."""

    du_mm: float | None
    hinges: str
    other_du_mm: float | None = None
    other_hinges: str = ""
    mode: str = ""  # how it collapses (`LimitResult.collapse_mode`: hinging, sliding, snap); "": not recorded


def du_components(du_mm: float, direction_deg: float) -> tuple[float, float]:
    """The horizontal and vertical components (mm) of a support displacement `du_mm` along the
    direction `direction_deg` (from +x, counter-clockwise)."""
    angle = math.radians(direction_deg)
    # rounded to 1e-9 mm (and -0.0 to 0.0): cos(-90 deg) is 6e-17, not 0, in floating point
    return round(du_mm * math.cos(angle), 9) + 0.0, round(du_mm * math.sin(angle), 9) + 0.0


def map_table(name: str, results: pd.DataFrame, rigid: dict[float, RigidLimit]) -> pd.DataFrame:
    """One row a direction for the campaign `results` (results.csv of a sweep over the direction) of
    the joint set `name`, with du's components and the rigid limit of each direction beside it."""
    rows = []
    for run in results.sort_values(DIRECTION_PARAMETER, ascending=False).itertuples(index=False):
        direction = float(getattr(run, DIRECTION_PARAMETER))
        du = float(run.du_mm) if run.status == "done" and pd.notna(run.du_mm) else math.nan
        first = getattr(run, "du_first_mm", math.nan)
        du_x, du_y = du_components(du, direction)
        rows.append(
            {
                "set": name,
                "direction_deg": direction,
                "du_first_mm": float(first) if run.status == "done" and pd.notna(first) else math.nan,
                "du_mm": du,
                "du_x_mm": du_x,
                "du_y_mm": du_y,
                "hinges": run.hinges if isinstance(run.hinges, str) else "",
                "mechanism": run.mechanism if isinstance(run.mechanism, str) else "",
                "steps": run.steps,
                "wall_s": run.wall_s,
                "status": run.status,
                "folder": run.folder,
            }
        )
    return with_rigid(pd.DataFrame(rows), rigid)


def with_rigid(table: pd.DataFrame, rigid: dict[float, RigidLimit]) -> pd.DataFrame:
    """`table` (a capacity map, or its DEM columns) with the rigid columns of `rigid[direction]`
    (re)written: the rigid analysis can change without its DEM runs being made again."""
    limits = [rigid.get(float(d), RigidLimit(None, "")) for d in table["direction_deg"]]
    table = table.assign(
        du_rigid_mm=[math.nan if r.du_mm is None else r.du_mm for r in limits],
        rigid_hinges=[r.hinges for r in limits],
        rigid_mode=[r.mode for r in limits],
        du_rigid_other_mm=[math.nan if r.other_du_mm is None else r.other_du_mm for r in limits],
        rigid_other_hinges=[r.other_hinges for r in limits],
    )
    table["du_over_rigid"] = table["du_mm"] / table["du_rigid_mm"].where(table["du_rigid_mm"] > 0.0)  # 0: no ratio
    return table.reindex(columns=list(MAP_COLUMNS))  # a table from before du_first: its column empty


def reaction_curve(series: pd.DataFrame, direction_deg: float) -> pd.DataFrame:
    """The force of the arch on the moving (right) support along its path at the equilibrium states
    of a run's `series` (series.csv): columns delta_mm and force_N = -(R . d) for the support's
    reaction R on the arch, positive when the arch pushes the support along its movement (a
    settling or spreading support holds the arch back), negative when it resists (closing)."""
    states = series[series["stage"] == Stage.EQUILIBRIUM]
    angle = math.radians(direction_deg)
    reaction = -(states["right_Rx_N"] * math.cos(angle) + states["right_Ry_N"] * math.sin(angle))
    return pd.DataFrame({"delta_mm": states["delta_mm"].to_numpy(), "force_N": reaction.to_numpy()})


SET_COLUMNS = ("du_first (mm)", "du (mm)", "(du_x, du_y) (mm)", "hinges")  # a set's columns in the map's table


def map_markdown(table: pd.DataFrame) -> list[str]:
    """The capacity map as a Markdown table: one row a direction, one column group a set (du_first,
    the first loss of stability, beside du, the end of the path)."""
    sets = list(dict.fromkeys(table["set"]))
    head = "| direction (deg) | " + " | ".join(f"{s} {column}" for s in sets for column in SET_COLUMNS)
    lines = [
        head + " | rigid du (mm) | rigid hinges | rigid du, other branch (mm) | its hinges |",
        "|---" * (1 + len(SET_COLUMNS) * len(sets) + 4) + "|",
    ]
    for direction, rows in table.groupby("direction_deg", sort=False):
        cells = [f"{direction:g}"]
        for name in sets:
            row = rows[rows["set"] == name]
            if row.empty or not np.isfinite(row["du_mm"].iloc[0]):
                cells += ["-"] * len(SET_COLUMNS)
                continue
            r = row.iloc[0]
            cells += [_mm(r.du_first_mm), f"{r.du_mm:.2f}", f"({r.du_x_mm:.1f}, {r.du_y_mm:.1f})", r.hinges or "-"]
        first = rows.iloc[0]
        mode = first.rigid_mode if isinstance(first.rigid_mode, str) else ""
        said = f" ({mode})" if mode and mode != HINGING and np.isfinite(first.du_rigid_mm) else ""  # sliding, a snap
        cells += [
            "failed (rigid_mode in the CSV)" if mode.startswith(RIGID_FAILED) else _mm(first.du_rigid_mm) + said,
            first.rigid_hinges or "-",
            _mm(first.du_rigid_other_mm),
            first.rigid_other_hinges or "-",
        ]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def _mm(value: float) -> str:
    return "-" if not np.isfinite(value) else f"{value:.2f}"
