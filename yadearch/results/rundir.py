"""The run folder: what ran (case.toml), what happened (series.csv, joints.csv, snapshots.json),
what it means (summary.json) and how it went (run.log). Pure Python: readable without YADE."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase, as_ran

CASE_FILE = "case.toml"
SERIES_FILE = "series.csv"
JOINTS_FILE = "joints.csv"
SNAPSHOTS_FILE = "snapshots.json"
SUMMARY_FILE = "summary.json"
LOG_FILE = "run.log"


@dataclass
class RunFolder:
    """A run folder read back: the resolved case, both tables, snapshots and the summary."""

    path: Path
    case: dict[str, Any]
    series: pd.DataFrame
    joints: pd.DataFrame
    snapshots: dict[str, Any]
    summary: dict[str, Any]


def write_run(out: Path, case_toml: str, series: list[dict], joints: list[dict],
              snapshots: dict[str, Any], summary: dict[str, Any]) -> None:
    """Write every file of a run folder; summary.json last, so its presence means complete."""
    out.mkdir(parents=True, exist_ok=True)
    (out / CASE_FILE).write_text(case_toml)
    pd.DataFrame(series).to_csv(out / SERIES_FILE, index=False, float_format="%.8g")
    pd.DataFrame(joints).to_csv(out / JOINTS_FILE, index=False, float_format="%.8g")
    (out / SNAPSHOTS_FILE).write_text(json.dumps(snapshots, indent=1, default=_json_default))
    (out / SUMMARY_FILE).write_text(json.dumps(summary, indent=2, default=_json_default) + "\n")


def _json_default(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if hasattr(value, "item"):
        return value.item()
    raise TypeError(f"not JSON serialisable: {type(value).__name__}")


def is_complete(path: Path) -> bool:
    """True if the folder holds a finished run (its summary.json is written last)."""
    return (Path(path) / SUMMARY_FILE).is_file()


def case_differences(path: Path, case: ArchCase) -> list[str]:
    """How the finished or started run in `path` differs from `case` ("section.key: ran X, wanted
    Y"), comparing what each runs with (`as_ran`; the name aside)."""
    import tomllib

    ran = as_ran(tomllib.loads((Path(path) / CASE_FILE).read_text()))
    wanted = as_ran(case.to_dict())
    def show(value: Any) -> str:
        return f"{value:.6g}" if isinstance(value, float) else repr(value)

    return [f"{section}.{key}: ran {show(value)}, wanted {show(wanted[section][key])}"
            for section, values in ran.items() if section != "name"
            for key, value in values.items() if value != wanted[section][key]]


def holds_case(path: Path, case: ArchCase) -> bool:
    """True if the folder holds a finished run of `case`, which can be reused instead of run again."""
    return is_complete(path) and not case_differences(path, case)


def read_run(path: str | Path) -> RunFolder:
    """Read a run folder written by `write_run`."""
    import tomllib

    path = Path(path)
    if not is_complete(path):
        raise FileNotFoundError(f"{path} is not a complete run folder (no {SUMMARY_FILE})")
    return RunFolder(
        path=path,
        case=tomllib.loads((path / CASE_FILE).read_text()),
        series=pd.read_csv(path / SERIES_FILE),
        joints=pd.read_csv(path / JOINTS_FILE),
        snapshots=json.loads((path / SNAPSHOTS_FILE).read_text()),
        summary=json.loads((path / SUMMARY_FILE).read_text()),
    )
