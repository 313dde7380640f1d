"""The run folder: what ran (case.toml), what happened (series.csv, joints.csv, snapshots.json),
what it means (summary.json) and how it went (run.log). Pure Python: readable without YADE."""

from __future__ import annotations

import dataclasses
import json
import tomllib
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

from yadearch.atomic import write_rows_atomically, write_text_atomically
from yadearch.case.config import with_current_names
from yadearch.case.numerics_section import FULL_RUN_FILES, SUMMARY_RUN_FILES
from yadearch.errors import RunFolderError
from yadearch.results.states import STATES_FILE, RunStates, read_states, write_states
from yadearch.results.summary import RunSummary
from yadearch.results.summary_checks import summary_values_problem

if TYPE_CHECKING:
    import pandas as pd

CASE_FILE = "case.toml"
SERIES_FILE = "series.csv"
JOINTS_FILE = "joints.csv"
FIGURES_DIR = "figures"  # a run's figures, inside its run folder (or its report's folder for it)
VTK_DIR = "vtk"  # a run's ParaView export, inside its run folder
STIFFNESS_COLUMN = "min_stiffness_N_per_m"  # series.csv: an equilibrium state's stability (model.stability)
IMPERFECTIONS_FILE = "imperfections.csv"  # the defects drawn for each joint (imperfect arches only)
SNAPSHOTS_FILE = "snapshots.json"
SUMMARY_FILE = "summary.json"
CAMPAIGN_TABLE = "results.csv"  # what a campaign keeps in its folder instead of a summary (studies.campaigns)
LOG_FILE = "run.log"
LOAD_PATH_FILE = "load_path.json"  # in a live load's path folder (results/load_path.py): its answer, written last
STAGING_PREFIX, STAGING_SUFFIX = ".", ".partial"  # a run is written to .NAME.partial beside NAME
SCHEMA_VERSION = 1  # of summary.json; a summary without one predates the marker and is read by its keys
TABLE_FLOAT_FORMAT = "%.8g"  # series.csv and joints.csv: eight significant figures (states to 1e-8 of a metre)
REQUIRED_KEYS = ("du_mm", "hinges_at_collapse", "steps", "wall_s")  # what campaigns and reports read


def hinge_list(hinges: list[dict] | None) -> str:
    """Hinge records (a summary's `hinges_last_equilibrium`, a snapshot's) as "1E 9I 29E 56E"."""
    return " ".join(f"{h['interface']}{h['side']}" for h in hinges or [])


@dataclass
class RunFolder:
    """A run folder read back: the resolved case, snapshots and the summary; both tables are read on
    first use (a run's answer needs neither, nor pandas)."""

    path: Path
    case: dict[str, Any]
    snapshots: dict[str, Any]
    summary: RunSummary
    states: RunStates | None = None  # none in runs written before states were recorded
    load_path: dict[str, Any] | None = None  # a live load's path folder: its answer (load_path.json); None: a run

    @cached_property
    def series(self) -> pd.DataFrame:
        """series.csv: one row every few steps, labelled by stage."""
        return self._table(SERIES_FILE)

    @cached_property
    def joints(self) -> pd.DataFrame:
        """joints.csv: every interface at every equilibrium state and at collapse."""
        return self._table(JOINTS_FILE)

    def _table(self, name: str) -> pd.DataFrame:
        import pandas as pd

        try:
            return pd.read_csv(self.path / name)
        except (OSError, ValueError) as exc:
            raise RunFolderError(f"{self.path}: a file of the run folder cannot be read ({exc})") from None


def is_load_path_folder(path: Path) -> bool:
    """True if `path` is a live load's path folder (`write_load_path_folder`), complete."""
    return (Path(path) / LOAD_PATH_FILE).is_file()


def staging_folder(out: Path) -> Path:
    """Where a run writes its folder `out` until it is complete (then renamed to `out`)."""
    return out.parent / f"{STAGING_PREFIX}{out.name}{STAGING_SUFFIX}"


def final_folder(path: Path) -> Path:
    """The run folder a staging folder becomes when complete (any other folder: itself)."""
    name = path.name
    if name.startswith(STAGING_PREFIX) and name.endswith(STAGING_SUFFIX):
        name = name[len(STAGING_PREFIX) : -len(STAGING_SUFFIX)]
    return path.parent / name


def write_run(
    out: Path,
    case_toml: str,
    series: list[dict],
    joints: list[dict],
    snapshots: dict[str, Any],
    summary: RunSummary,
    imperfections: dict[str, Any] | None = None,
    states: list[dict[str, Any]] | None = None,
    tables: bool = True,
) -> None:
    """Write every file of a run folder, each atomically (imperfections.csv only for an imperfect
    arch, states.npz when the run kept its states; only case.toml and the summary without `tables`,
    numerics.run_files = 'summary'); summary.json last, with its schema version and a completeness
    marker, so that a valid summary means a complete folder."""
    out.mkdir(parents=True, exist_ok=True)
    write_text_atomically(out / CASE_FILE, case_toml)
    if not tables:
        _write_summary(out, dataclasses.replace(summary, table_rows={}))
        return
    write_tables(out, series, joints, snapshots, imperfections, states)
    _write_summary(out, dataclasses.replace(summary, table_rows={SERIES_FILE: len(series), JOINTS_FILE: len(joints)}))


def write_tables(
    out: Path,
    series: list[dict],
    joints: list[dict],
    snapshots: dict[str, Any],
    imperfections: dict[str, Any] | None = None,
    states: list[dict[str, Any]] | None = None,
) -> None:
    """The tables, snapshots and states of a run folder (`write_run`'s, and a live load's path
    folder's), each atomically."""
    if imperfections is not None:
        write_rows_atomically(
            out / IMPERFECTIONS_FILE,
            [dict(zip(imperfections, row)) for row in zip(*imperfections.values(), strict=True)],
        )
    for name, rows in ((SERIES_FILE, series), (JOINTS_FILE, joints)):
        write_rows_atomically(out / name, rows, float_format=TABLE_FLOAT_FORMAT)
    write_text_atomically(out / SNAPSHOTS_FILE, json.dumps(snapshots, indent=1, default=_json_default))
    if states:
        write_states(out / STATES_FILE, states)


def _write_summary(out: Path, summary: RunSummary) -> None:
    """summary.json, marked complete with its schema version (written last: it vouches for the folder)."""
    marked = {**summary.to_json(), "schema_version": SCHEMA_VERSION, "complete": True}
    write_text_atomically(out / SUMMARY_FILE, json.dumps(marked, indent=2, default=_json_default) + "\n")


def _json_default(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if hasattr(value, "item"):
        return value.item()
    raise TypeError(f"not JSON serialisable: {type(value).__name__}")


def summary_problem(path: Path) -> str | None:
    """Why the folder's summary.json does not vouch for a complete run (None: it does)."""
    file = Path(path) / SUMMARY_FILE
    if not Path(path).is_dir():
        return "no such folder"
    if not file.is_file():
        if (Path(path) / CAMPAIGN_TABLE).is_file():
            return f"a campaign's folder ({CAMPAIGN_TABLE}); give one of its runs' folders"
        return f"no {SUMMARY_FILE}"
    try:
        summary = json.loads(file.read_text())
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        return f"{SUMMARY_FILE} is not valid JSON ({exc.msg if hasattr(exc, 'msg') else exc})"
    if not isinstance(summary, dict):
        return f"{SUMMARY_FILE} is not a JSON object"
    version = summary.get("schema_version", 0)
    if not isinstance(version, int) or version > SCHEMA_VERSION:
        return f"{SUMMARY_FILE} has schema version {version!r}; this yadearch reads up to {SCHEMA_VERSION}"
    if version >= 1 and summary.get("complete") is not True:
        return f"{SUMMARY_FILE} is not marked complete"
    missing = [key for key in REQUIRED_KEYS if key not in summary]
    if missing:
        return f"{SUMMARY_FILE} lacks {', '.join(missing)}"
    bad_value = summary_values_problem(summary)
    if bad_value:
        return f"{SUMMARY_FILE}: {bad_value}"
    if not (path / CASE_FILE).is_file():
        return f"no {CASE_FILE}"
    return None


def is_complete(path: Path) -> bool:
    """True if the folder holds a finished run: its summary.json, written last, validates."""
    return summary_problem(Path(path)) is None


def read_summary(path: Path) -> RunSummary:
    """A finished run's summary; RunFolderError in one line if the folder is not complete."""
    problem = summary_problem(Path(path))
    if problem:
        raise RunFolderError(f"{path} is not a complete run folder: {problem}")
    try:
        return RunSummary.from_json(json.loads((Path(path) / SUMMARY_FILE).read_text()))
    except (TypeError, ValueError, KeyError) as exc:
        raise RunFolderError(f"{path / SUMMARY_FILE} cannot be read as a run summary ({exc})") from None


def finished_summary(path: Path) -> RunSummary | None:
    """The summary of a finished run in `path`; None if the folder holds none (missing, unfinished,
    damaged: `summary_problem` says why)."""
    try:
        return read_summary(path)
    except RunFolderError:
        return None


def kept_only_summary(case: dict[str, Any]) -> bool:
    """True if the run of this stored case (today's names) kept only its summary (numerics.run_files)."""
    return case.get("numerics", {}).get("run_files", FULL_RUN_FILES) == SUMMARY_RUN_FILES


def read_run(path: str | Path) -> RunFolder:
    """Read a run folder written by `write_run` (RunFolderError in one line for one that kept only
    its summary: it has nothing to analyse or draw)."""
    path = Path(path)
    return read_tables(path, read_summary(path))


def read_tables(path: Path, summary: RunSummary, load_path: dict[str, Any] | None = None) -> RunFolder:
    """The folder's case, tables, snapshots and states read beside its `summary` (and a live load's
    path's answer `load_path`), the tables' lengths checked against the summary's counts."""
    try:
        case = with_current_names(tomllib.loads((path / CASE_FILE).read_text()))
        if kept_only_summary(case):
            raise RunFolderError(
                f"{path} kept only its summary (numerics.run_files = 'summary'): no tables, states or "
                "snapshots to analyse or draw; run the case again with numerics.run_files = 'full'"
            )
        folder = RunFolder(
            path=path,
            case=case,
            snapshots=json.loads((path / SNAPSHOTS_FILE).read_text()),
            summary=summary,
            states=read_states(path),
            load_path=load_path,
        )
    except (OSError, ValueError, tomllib.TOMLDecodeError) as exc:
        raise RunFolderError(f"{path}: a file of the run folder cannot be read ({exc})") from None
    for name in (SERIES_FILE, JOINTS_FILE):
        written = (summary.table_rows or {}).get(name)  # none in runs written before the counts
        if written is None:
            continue
        rows = _row_count(path / name)
        if rows != written:
            raise RunFolderError(
                f"{path / name} has {rows} rows where the run wrote {written}: it was cut short "
                "or changed; run the case again"
            )
    return folder


def _row_count(file: Path) -> int:
    """The data rows of a table the run wrote (one a line, after the header; no cell holds a newline)."""
    try:
        with open(file, "rb") as handle:
            return max(sum(1 for line in handle if line.strip()) - 1, 0)
    except OSError as exc:
        raise RunFolderError(f"{file.parent}: a file of the run folder cannot be read ({exc})") from None
