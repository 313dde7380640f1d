"""A live load's path on disk (either engine): OUT/NAME_load_path.json (the answer and the case that
gave it) and OUT/NAME_load_path.csv (the load-displacement curve), written atomically and read back;
and the static engine's states as the folder OUT/NAME_load_path/, read as a run folder for `yadearch
animate` and `export`: case.toml, series.csv, joints.csv, snapshots.json, states.npz (each state's
load in it) and the answer again, load_path.json, written last (the folder is complete)."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.comparison import as_ran
from yadearch.case.config import ArchCase
from yadearch.errors import RunFolderError
from yadearch.results.rundir import (
    CASE_FILE,
    LOAD_PATH_FILE,
    RunFolder,
    read_tables,
    write_tables,
)
from yadearch.results.summary import HingeRef, RunSummary
from yadearch.solve.load_path import BRANCH
from yadearch.solve.load_path_result import LoadPath
from yadearch.solve.stages import Outcome

LOAD_PATH_SUFFIX = "_load_path"

OLD_REACH_KEY = "largest_multiplier_tried"  # last_stable_multiplier's name in files written before (read both)


def last_stable_multiplier(data: dict[str, Any]) -> float:
    """A load path JSON's last stable multiplier, under its name or the one files written before used."""
    return float(data["last_stable_multiplier"] if "last_stable_multiplier" in data else data[OLD_REACH_KEY])


def load_path_file(folder: Path, name: str, suffix: str = "") -> Path:
    """OUT/NAME_load_path + `suffix` (no suffix: the stem of the figure), whatever dots NAME holds."""
    return Path(folder) / f"{name}{LOAD_PATH_SUFFIX}{suffix}"


def load_path_json(result: LoadPath, case: ArchCase) -> dict[str, Any]:
    """A load path as summary.json-like fields, with the case that gave it."""

    def number(value: float) -> float | None:
        return value if math.isfinite(value) else None

    return {
        "name": case.name,
        "engine": result.engine,
        "live_load": case.loads.live_load,
        "after_mm": result.after_mm,
        "unit": result.unit,
        "outcome": result.outcome,
        "collapse_multiplier": number(result.capacity),
        "first_loss_multiplier": number(result.first_loss),
        "last_stable_multiplier": result.reach,
        "hinges_at_collapse": list(result.hinges),
        "collapse_kind": result.kind,
        "rigid_multiplier": number(result.rigid),
        "rigid_hinges": list(result.rigid_hinges),
        "rigid_note": result.rigid_note or None,
        "iterations" if result.engine == "static" else "steps": result.iterations,
        **_descent_json(result),
        **({"increments_check": result.increments_check} if result.increments_check is not None else {}),
        "case": case.to_dict(),
    }


def _descent_json(result: LoadPath) -> dict[str, Any]:
    """The descending branch: why it ended (None: not traced) and the hinges its last step turns."""
    hinges = list(result.descent_hinges)
    return {"descending_branch_end": result.descent_end or None, "descending_branch_hinges": hinges}


def write_load_path(folder: Path, result: LoadPath, case: ArchCase) -> Path:
    """Write the path's JSON and curve CSV in `folder`; returns their stem."""
    write_csv_atomically(load_path_file(folder, case.name, ".csv"), result.curve)
    write_text_atomically(load_path_file(folder, case.name, ".json"), _json_text(result, case))
    return load_path_file(folder, case.name)


def _json_text(result: LoadPath, case: ArchCase) -> str:
    """The answer as written beside the folder and in it."""
    return json.dumps(load_path_json(result, case), indent=1) + "\n"


def write_load_path_folder(
    folder: Path,
    result: LoadPath,
    case: ArchCase,
    series: list[dict],
    joints: list[dict],
    snapshots: dict[str, Any],
    states: list[dict[str, Any]],
    imperfections: dict[str, Any] | None = None,
) -> Path:
    """Write the folder OUT/NAME_load_path/ of the path's recorded states in `folder` (the rows and
    states of `static.records.load_path_records`), its answer last; returns the folder."""
    out = load_path_file(folder, case.name)
    (out / LOAD_PATH_FILE).unlink(missing_ok=True)  # a folder being written again is not complete
    write_text_atomically(out / CASE_FILE, case.to_toml())
    write_tables(out, series, joints, snapshots, imperfections, states)
    write_text_atomically(out / LOAD_PATH_FILE, _json_text(result, case))
    return out


def read_load_path_folder(path: Path) -> RunFolder:
    """A live load's path folder read as a run folder (its states drawn and exported as a run's): the
    summary says only what the answer says (name, engine, outcome, hinges, the static engine's
    iterations or the DEM's steps; no du, no wall time), `load_path` holds the answer."""
    path = Path(path)
    file = path / LOAD_PATH_FILE
    try:
        answer = json.loads(file.read_text())
        outcome = Outcome(answer["outcome"])
        summary = RunSummary(
            name=str(answer["name"]),
            engine=str(answer["engine"]),
            outcome=outcome,
            collapsed=outcome == Outcome.COLLAPSE,
            du_mm=None,
            hinges_at_collapse=tuple(HingeRef(int(h[:-1]), h[-1]) for h in answer["hinges_at_collapse"]),
            collapse_kind=answer["collapse_kind"],
            steps=int(answer["iterations"] if "iterations" in answer else answer["steps"]),  # static / DEM
            wall_s=math.nan,
        )
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise RunFolderError(
            f"{file} cannot be read as a load path's answer ({exc}); run the load path again"
        ) from None
    return read_tables(path, summary, answer)


def read_load_path(folder: Path, name: str) -> LoadPath:
    """The load path `write_load_path` wrote for the case `name` in `folder`."""
    data = json.loads(load_path_file(folder, name, ".json").read_text())

    def number(key: str) -> float:
        value = data[key]
        return math.nan if value is None else float(value)

    return LoadPath(
        capacity=number("collapse_multiplier"),
        first_loss=number("first_loss_multiplier"),
        outcome=data["outcome"],
        unit=data["unit"],
        hinges=tuple(data["hinges_at_collapse"]),
        kind=data["collapse_kind"],
        curve=read_curve(load_path_file(folder, name, ".csv")),
        after_mm=float(data["after_mm"]),
        reach=last_stable_multiplier(data),
        iterations=int(data.get("iterations", data.get("steps", 0))),
        rigid=number("rigid_multiplier"),
        rigid_hinges=tuple(data["rigid_hinges"]),
        rigid_note=data["rigid_note"] or "",
        engine=data["engine"],
        descent_end=data.get("descending_branch_end") or "",
        descent_hinges=tuple(data.get("descending_branch_hinges", ())),
        increments_check=data.get("increments_check"),
    )


def read_curve(file: Path) -> pd.DataFrame:
    """A load-displacement curve as written: every column a number but `branch`."""
    curve = pd.read_csv(file)
    return curve.astype({c: float for c in curve.columns if c != BRANCH})


def stored_load_path(folder: Path, case: ArchCase, after_mm: float, engine: str = "dem") -> LoadPath | None:
    """The load path `folder` already holds for this very case (as it ran: `case.comparison.as_ran`),
    settlement and engine (a study resumed), or None."""
    try:
        data = json.loads(load_path_file(folder, case.name, ".json").read_text())
    except (OSError, ValueError):
        return None
    stored = data.get("case")
    if not isinstance(stored, dict) or data.get("after_mm") != after_mm or data.get("engine") != engine:
        return None
    if as_ran(stored) != as_ran(case.to_dict()):  # what each runs with: a parameter added since at its old value
        return None
    if not load_path_file(folder, case.name, ".csv").is_file():
        return None
    return read_load_path(folder, case.name)
