"""Parametric campaigns: a table of cases, one run folder each, resumable, one tidy results table.

A campaign is a base case plus rows of overrides (a grid or an explicit CSV table). Each row becomes a
run named deterministically from its overrides (`kn_N_per_mm3=0.1` -> `kn0.1`), so re-running the same
campaign finds the finished folders and only redoes the others.
"""

from __future__ import annotations

import hashlib
import json
import math
import time
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, Future, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd
from tqdm import tqdm

from yadearch.atomic import remove_stale_temporaries, write_atomically, write_csv_atomically
from yadearch.case.config import ArchCase, preset
from yadearch.case.plan import plan_run
from yadearch.engine.process import STATIC_ENGINE, check_yade_installed, run_case_process
from yadearch.errors import CaseError, RunFailedError, RunInterruptedError, YadearchError
from yadearch.model.hinges import PAPER_LABELS
from yadearch.results.lock import folder_lock
from yadearch.results.rundir import case_differences, finished_summary, is_complete, is_current
from yadearch.results.summary import RunSummary
from yadearch.studies.executors import Pool
from yadearch.studies.failures import FAILED_FILE, failure_stands, record_failure
from yadearch.studies.grid import RUN_COLUMN, check_campaign_size, check_parameter, run_tag
from yadearch.studies.sessions import record_session

RUNS_FILE = "runs.csv"
RESULTS_FILE = "results.csv"
RESULTS_EVERY_S = 5.0  # results.csv is rewritten at most this often while runs finish (and at the end)


# ---------------------------------------------------------------- runs


@dataclass
class RunSpec:
    """One run of a campaign: its name, overrides, folder and case."""

    name: str
    overrides: dict[str, Any]
    folder: Path
    case: ArchCase


def plan(base: ArchCase, rows: list[dict[str, Any]], out: Path) -> list[RunSpec]:
    """The runs of a campaign, every one checked before any runs: an invalid parameter value (or an
    absurd combination, `plan_run`) refuses the campaign in one line naming the run; so does a
    finished folder that holds a different case (resuming would mix campaigns)."""
    check_campaign_size(len(rows))
    specs: list[RunSpec] = []
    invalid: list[str] = []
    for row in rows:
        overrides = {k: v for k, v in row.items() if k != RUN_COLUMN}
        name = str(row.get(RUN_COLUMN) or (run_tag(overrides) if overrides else base.name))
        try:
            case = base.with_overrides({**overrides, "name": name})
            plan_run(case)
        except CaseError as exc:
            invalid.append(f"run {name}: {exc}")
            continue
        spec = RunSpec(name, overrides, out / confined_folder_name(name), case)
        if is_complete(spec.folder):
            _check_same_case(spec)
        specs.append(spec)
    if invalid:
        more = f" (and {len(invalid) - 1} more of the {len(rows)} runs)" if len(invalid) > 1 else ""
        raise CaseError(f"{invalid[0]}{more}; nothing was run")
    names = [s.name for s in specs]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise YadearchError(f"campaign has duplicate runs {duplicates}")
    return specs


def confined_folder_name(name: str) -> str:
    """`name` if it is a plain folder name, else a stand-in that stays inside the campaign folder
    (a table's `run` cell such as "../../x" must not write outside `--out`)."""
    if name and name == Path(name).name and name not in (".", ".."):
        return name
    return "invalid-name-" + hashlib.sha1(name.encode()).hexdigest()[:8]


def _check_same_case(spec: RunSpec) -> None:
    """Refuse to resume over a finished run folder that ran another case (`rundir.case_differences`:
    a parameter the run predates counts as the value that keeps its old behaviour)."""
    differences = case_differences(spec.folder, spec.case)
    if differences:
        raise YadearchError(f"run folder {spec.folder} holds a different case ({differences[0]}); use another --out")


BATCH_KEYS = ("description", "preset", "out")  # yade-batch table columns that are not case parameters


def batch_run(params: dict[str, Any]) -> tuple[ArchCase, Path]:
    """The case and run folder of one yade-batch table line (`preset`, `out` = campaign folder, case
    parameters by name), named as `yadearch sweep` names the same run so either can resume the other."""
    overrides = {k: v for k, v in params.items() if k not in BATCH_KEYS}
    for key in overrides:
        check_parameter(key)
    spec = plan(
        preset(str(params.get("preset", "set2"))), [overrides], Path(str(params.get("out", "runs/yade-batch")))
    )[0]
    return spec.case, spec.folder


def execute(case: ArchCase, folder: Path, timeout_s: float | None) -> dict[str, Any]:
    """Run one case in its own process (the task of every executor); a failure writes failed.json."""
    started = time.time()
    try:
        run_case_process(case, folder, timeout_s=timeout_s, quiet=True)
    except RunInterruptedError as exc:  # left pending: the next session runs it again
        return {"status": "interrupted", "reason": str(exc)}
    except RunFailedError as exc:
        record_failure(folder, case, str(exc), time.time() - started)
        return {"status": "failed", "reason": str(exc)}
    return {"status": "done", "reason": ""}


Task = Callable[[ArchCase, Path, float | None], dict[str, Any]]


def expected_cost(case: ArchCase) -> float:
    """A run's CPU cost relative to other runs, to start the longest first: its loading takes
    max settlement / (support speed x time step) steps, and the time step falls as 1/sqrt(kn)."""
    return (
        math.sqrt(case.interface.kn_N_per_mm3) * case.loading.max_support_displacement_mm / case.support_speed_mm_per_s
    )


def run_campaign(
    base: ArchCase,
    rows: list[dict[str, Any]],
    out: Path,
    pool: Pool,
    timeout_s: float | None = None,
    progress: bool = True,
    task: Task = execute,
    retry_failed: bool = True,
) -> pd.DataFrame:
    """Run every unfinished run of the campaign on `pool`, then write and return the results table.

    Finished folders are skipped; interrupted and new runs are (re)done, failed ones too unless
    `retry_failed` is false (they keep their recorded reason). Runs start in decreasing
    `expected_cost`. `task` runs one case (default: a child process through `execute`; tests
    inject stand-ins)."""
    out = Path(out)
    specs = plan(base, rows, out)
    with folder_lock(out, "campaign"):
        return _run_planned(specs, out, pool, timeout_s, progress, task, retry_failed)


def _run_planned(
    specs: list[RunSpec], out: Path, pool: Pool, timeout_s: float | None, progress: bool, task: Task, retry_failed: bool
) -> pd.DataFrame:
    """`run_campaign` once its runs are planned and it holds the campaign folder's lock."""
    out.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(out)  # left by a campaign killed while it wrote its tables
    write_run_table(specs, out)
    complete = {s.name for s in specs if is_current(s.folder)}  # run names are unique (`plan`)
    todo = [s for s in specs if s.name not in complete and (retry_failed or not failure_stands(s.folder, s.case))]
    # Longest first: the last runs to start are short, so no core idles while one long run ends
    # the campaign (the 13-point kn sweep's stiffest points take 10-40x its softest).
    todo.sort(key=lambda spec: expected_cost(spec.case), reverse=True)
    for spec in todo:
        (spec.folder / FAILED_FILE).unlink(missing_ok=True)
    if task is execute and any(s.case.numerics.engine != STATIC_ENGINE for s in todo):
        check_yade_installed()  # a campaign of static runs needs no YADE
    bar = tqdm(
        total=len(specs),
        initial=len(specs) - len(todo),
        unit="run",
        disable=not progress,
        desc=out.name,
        dynamic_ncols=True,
    )
    counts = {"done": len(complete), "failed": len(specs) - len(todo) - len(complete), "interrupted": 0}
    futures: dict[Future, RunSpec] = {}
    started = time.time()
    try:
        futures = {pool.executor.submit(task, s.case, s.folder, timeout_s): s for s in todo}
        pending = set(futures)
        bar.set_postfix(counts, running=min(pool.slots, len(pending)))
        rows = {s.name: run_row(s, out) for s in specs}
        written = time.time()
        while pending:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in finished:
                counts[future.result()["status"]] += 1
                rows[futures[future].name] = run_row(futures[future], out)
            if time.time() - written >= RESULTS_EVERY_S or not pending:  # the run folders stay the truth
                write_csv_atomically(out / RESULTS_FILE, tidy(pd.DataFrame(rows.values())))
                written = time.time()
            bar.set_postfix(counts, running=min(pool.slots, len(pending)), refresh=False)
            bar.update(len(finished))
    finally:
        for future in futures:
            future.cancel()
        bar.close()
        table = write_results(specs, out)
        if todo:
            record_session(out, started, pool, len(todo), table)
    return table


def write_run_table(specs: list[RunSpec], out: Path) -> None:
    """runs.csv: what the campaign runs (name, folder, overrides), written before anything runs."""
    table = pd.DataFrame([{RUN_COLUMN: s.name, "folder": s.folder.name, **_columns(s.overrides)} for s in specs])
    write_atomically(out / RUNS_FILE, lambda tmp: table.to_csv(tmp, index=False))


def write_results(specs: list[RunSpec], out: Path) -> pd.DataFrame:
    """results.csv from the run folders as they are now, written atomically; returns the table."""
    table = results_table(specs, out)
    write_csv_atomically(out / RESULTS_FILE, table)
    return table


def _columns(overrides: dict[str, Any]) -> dict[str, Any]:
    return {k.split(".")[-1]: v for k, v in overrides.items()}


# ---------------------------------------------------------------- results


def label_hinges(summary: RunSummary, n_voussoirs: int) -> dict[str, int | None]:
    """The interface of each of the paper's hinges A-D in a run's collapse mechanism (None where
    the mechanism has no such hinge)."""
    by_label = {label: h.interface for h, label in summary.paper_labels(n_voussoirs + 1).items() if label}
    return {f"hinge_{label}": by_label.get(label) for label in PAPER_LABELS}


def run_row(spec: RunSpec, out: Path) -> dict[str, Any]:
    """One results row: the run's parameters and what its folder says (done, failed or pending)."""
    case = spec.case
    row: dict[str, Any] = {RUN_COLUMN: spec.name, **_columns(spec.overrides)}
    row.setdefault("kn_N_per_mm3", case.interface.kn_N_per_mm3)
    row.setdefault("n_voussoirs", case.geometry.n_voussoirs)
    empty = {
        "du_mm": math.nan,
        "collapsed": None,
        "hinges": "",
        "mechanism": "",
        "hinge_A": None,
        "hinge_B": None,
        "hinge_C": None,
        "hinge_D": None,
        "steps": None,
        "wall_s": math.nan,
        "max_slip_mm": math.nan,
        "max_friction_use": math.nan,
        "friction_interface": None,
        "engine": case.numerics.engine,
    }
    summary = finished_summary(spec.folder)
    if summary is not None:
        du = summary.du_mm
        friction = summary.friction
        row.update(
            max_slip_mm=friction.get("max_slip_mm", math.nan),
            max_friction_use=friction.get("max_friction_use", math.nan),
            friction_interface=friction.get("friction_interface"),
        )
        row.update(
            du_mm=math.nan if du is None else du,
            collapsed=summary.collapsed,
            hinges=summary.hinge_labels,
            mechanism="-".join(h.side for h in summary.hinges_at_collapse),
            **label_hinges(summary, case.geometry.n_voussoirs),
            steps=summary.steps,
            wall_s=summary.wall_s,
            engine=summary.engine,
            status="done",
            reason="" if summary.collapsed else f"no collapse up to {_path_end_mm(summary, case):g} mm",
        )
    elif (spec.folder / FAILED_FILE).is_file():
        failed = json.loads((spec.folder / FAILED_FILE).read_text())
        row.update(empty, wall_s=failed.get("wall_s", math.nan), status="failed", reason=failed.get("reason", ""))
    else:
        row.update(empty, status="pending", reason="not run yet (interrupted?)")
    row["folder"] = str(spec.folder.relative_to(out)) if spec.folder.is_relative_to(out) else str(spec.folder)
    return row


def _path_end_mm(summary: RunSummary, case: ArchCase) -> float:
    """Where a run that did not collapse stopped: its path's end, or the case's largest displacement."""
    return summary.loading.max_displacement_mm if summary.loading else case.loading.max_support_displacement_mm


def results_table(specs: list[RunSpec], out: Path) -> pd.DataFrame:
    """The tidy results table of a campaign (one row per run), read from its run folders."""
    return tidy(pd.DataFrame([run_row(s, out) for s in specs]))


def tidy(table: pd.DataFrame) -> pd.DataFrame:
    """The results table with its integer columns as integers where a run has none (pending, failed)."""
    for column in ("n_voussoirs", "hinge_A", "hinge_B", "hinge_C", "hinge_D", "steps", "friction_interface"):
        table[column] = table[column].astype("Int64")
    return table
