"""A surveyed arch as a case (`ya.measured_case`, `yadearch survey`): the joints' intrados and extrados
corners read from a CSV, or the blocks' corners from a JSON survey (`case.survey_blocks`), into
`geometry.joint_points_mm` of shape 'measured' (docs/movements.md, "A surveyed arch"); and any arch
on its piers (`ya.on_piers`, `yadearch piers`)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from yadearch.api.arguments import check_arguments
from yadearch.api.runs import as_case
from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry
from yadearch.case.paper import off_the_paper
from yadearch.case.piers import pier_case
from yadearch.case.shape import MEASURED, MIN_MEASURED_JOINTS
from yadearch.case.survey_blocks import ring_from_blocks
from yadearch.errors import CaseError

JOINT_COLUMNS = ("x_intrados_mm", "y_intrados_mm", "x_extrados_mm", "y_extrados_mm")
BLOCK_COLUMNS = ("block", "x_mm", "y_mm")  # a survey of blocks as a table: a row a corner, in order round it
SUPPORT_COLUMN = "support"  # 'left' or 'right' on an abutment's rows (any of them), empty elsewhere
JSON_SUFFIX = ".json"  # a survey of blocks (their corners, the supports marked) rather than of joints


MIN_MEAN_JOINT_MM = 1.0  # a ring's joints shorter on average are a survey in other units


def measured_case(
    joints: str | Path | pd.DataFrame | dict[str, Any], base: ArchCase | str = "set2", name: str | None = None
) -> ArchCase:
    """`base` (a case or a preset's name: its material, joints, loading and numerics) with the arch of
    the surveyed `joints`: a CSV file or table with the columns JOINT_COLUMNS (one row a joint, left to
    right), or one of the blocks' corners (BLOCK_COLUMNS, `blocks_from_table`), or a JSON file or dict of
    the blocks' corners with the supports marked
    (`case.survey_blocks.ring_from_blocks`: a voussoir may have more than four corners, its faces' other
    corners kept); voussoirs between consecutive joints, `thickness_mm`
    their mean joint length (the nominal thickness the runaway bound and the snap floor scale with);
    CaseError for a table it cannot use."""
    table, faces = _read(joints)
    missing = [c for c in JOINT_COLUMNS if c not in table.columns]
    if missing:
        found = ", ".join(map(str, table.columns))
        one = " (one column: is the file separated by commas?)" if len(table.columns) == 1 else ""
        raise CaseError(
            f"joints: the table needs the columns {', '.join(JOINT_COLUMNS)} (a row a joint) or "
            f"{', '.join(BLOCK_COLUMNS)} (a row a block's corner); missing {', '.join(missing)}, found "
            f"{found}{one}"
        )
    rows = numbers(table, JOINT_COLUMNS)
    if len(rows) < MIN_MEASURED_JOINTS:
        raise CaseError(
            f"joints: a surveyed arch needs {MIN_MEASURED_JOINTS} joints at least (two voussoirs), got {len(rows)}"
        )
    lengths = np.hypot(rows[:, 2] - rows[:, 0], rows[:, 3] - rows[:, 1])
    if lengths.mean() < MIN_MEAN_JOINT_MM:  # a survey in metres read as millimetres, most likely
        raise CaseError(
            f"joints: the survey's joints are {lengths.mean():.3g} mm long on average (at least "
            f"{MIN_MEAN_JOINT_MM:g} mm accepted); its coordinates are read in mm (metres x 1000)"
        )
    overrides = {
        "geometry.shape": MEASURED,
        "geometry.joint_points_mm": rows.tolist(),
        "geometry.n_voussoirs": len(rows) - 1,
        "geometry.thickness_mm": float(lengths.mean()),
        "geometry.intrados_points_mm": faces.get("intrados", []),
        "geometry.extrados_points_mm": faces.get("extrados", []),
    }
    if name is not None:
        overrides["name"] = name
    case = off_the_paper(as_case(base).with_overrides(overrides), named=name is not None)  # not "set2"
    arch_geometry(case)  # refuses, in one line, corners that make no arch
    return case


def _read(joints: str | Path | pd.DataFrame | dict[str, Any]) -> tuple[pd.DataFrame, dict[str, list]]:
    """The joints' table and the faces' other corners (rows [voussoir, x, y] by face, from a survey of
    blocks: a JSON file by its suffix, a dict, or a table of the blocks' corners), from a file or as
    given; CaseError for a file that cannot be read."""
    if isinstance(joints, pd.DataFrame):
        if all(c in joints.columns for c in BLOCK_COLUMNS) and not all(c in joints.columns for c in JOINT_COLUMNS):
            return _read(blocks_from_table(joints))
        return joints, {}
    if isinstance(joints, dict):
        ring = ring_from_blocks(joints)
        table = pd.DataFrame(ring.joints, columns=list(JOINT_COLUMNS))
        return table, {"intrados": ring.intrados_points, "extrados": ring.extrados_points}
    try:
        if Path(joints).suffix.lower() == JSON_SUFFIX:
            data = json.loads(Path(joints).read_text())
            if not isinstance(data, dict):
                raise ValueError("a JSON survey is an object with 'blocks'")
            return _read(data)
        table = pd.read_csv(joints, skipinitialspace=True)
        return _read(table.rename(columns=lambda column: str(column).strip()))
    except CaseError:
        raise
    except (OSError, ValueError, pd.errors.ParserError) as exc:
        raise CaseError(f"joints: cannot read {joints}: {exc}") from None


def numbers(table: pd.DataFrame, columns: tuple[str, ...], what: str = "joints") -> np.ndarray:
    """`table`'s `columns` as floats; CaseError in one line naming the first cell that is not a number
    (its row as a spreadsheet numbers it, the header being row 1: the table's own index, as read)."""
    values = table[list(columns)].apply(pd.to_numeric, errors="coerce")
    bad = values.isna().to_numpy()
    if bad.any():
        row, column = np.argwhere(bad)[0]
        value = table[columns[column]].iloc[row]
        said = "is empty" if pd.isna(value) else f"{value!r} is not a number (mm)"
        raise CaseError(f"{what}: row {table.index[row] + 2}, column {columns[column]}: {said}")
    return values.to_numpy(float)


def blocks_from_table(table: pd.DataFrame) -> dict[str, Any]:
    """A survey of blocks given as a table (BLOCK_COLUMNS, a row a corner, each block's rows in order
    round it; SUPPORT_COLUMN marking the abutments) as `case.survey_blocks.ring_from_blocks` takes it,
    each block named by its label; CaseError for a block marked twice."""
    blocks = []
    for label, rows in table.groupby("block", sort=False):
        block: dict[str, Any] = {"name": str(label), "corners": numbers(rows, ("x_mm", "y_mm"), "survey").tolist()}
        marks = set(rows[SUPPORT_COLUMN].dropna().astype(str).str.strip()) - {""} if SUPPORT_COLUMN in rows else set()
        if len(marks) > 1:
            raise CaseError(f"survey: block {label} is marked {' and '.join(sorted(marks))}; mark one support a block")
        if marks:
            block["support"] = marks.pop()
        blocks.append(block)
    return {"blocks": blocks}


def on_piers(case: ArchCase | str, pier_height_mm: float, pier_width_mm: float, name: str | None = None) -> ArchCase:
    """`case` (or a preset's name) with its arch on two piers, real abutments that can slide or overturn
    on their base joints, the supports moving the ground under them (`case.piers.pier_case`)."""
    check_arguments(pier_height_mm=pier_height_mm, pier_width_mm=pier_width_mm)
    on = pier_case(as_case(case), pier_height_mm, pier_width_mm)
    return on.with_overrides({"name": name}) if name is not None else off_the_paper(on, named=False)  # not set2
