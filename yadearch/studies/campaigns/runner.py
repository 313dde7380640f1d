"""Parametric campaigns: a table of cases, one run folder each, resumable, one tidy results table.

A campaign is a base case plus rows of overrides (a grid or an explicit CSV table). Each row becomes a
run named deterministically from its overrides (`kn_N_per_mm3=0.1` -> `kn0.1`), so re-running the same
campaign finds the finished folders and only redoes the others.
"""

from __future__ import annotations

import hashlib
import math
import time
from collections import Counter
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, Future, wait
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import remove_stale_temporaries, write_atomically, write_csv_atomically
from yadearch.case.config import ArchCase, preset
from yadearch.case.plan import plan_run, static_only_refusal
from yadearch.errors import CaseError, RunFailedError, RunInterruptedError, YadearchError
from yadearch.launch.process import STATIC_ENGINE, check_yade_installed, run_case_process
from yadearch.results.lock import folder_lock
from yadearch.results.reuse import case_differences, is_current
from yadearch.results.rundir import is_complete
from yadearch.static.records import dem_only_keys
from yadearch.studies.campaigns.batches import BATCHES_DIR
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.failures import FAILED_FILE, failure_stands, record_failure
from yadearch.studies.campaigns.grid import RUN_COLUMN, check_campaign_size, check_parameter, named_overrides, run_tag
from yadearch.studies.campaigns.lean import known_rows, run_batches
from yadearch.studies.campaigns.progress import campaign_bar
from yadearch.studies.campaigns.sessions import record_session
from yadearch.studies.campaigns.table import (
    RESULTS_EVERY_S,
    RESULTS_FILE,
    RunSpec,
    override_columns,
    pending_row,
    results_interval,
    results_table,
    run_row,
    tidy,
)

RUNS_FILE = "runs.csv"
SHOWN_DUPLICATES = 5  # a refusal names this many duplicate runs (a grid of rounded values can repeat thousands)
SUBMITTED_PER_SLOT = 2  # runs handed to the executor ahead of time, per slot (a bounded window)


def plan(base: ArchCase, rows: list[dict[str, Any]], out: Path) -> list[RunSpec]:
    """The runs of a campaign, every one to run checked before any runs: an invalid parameter value
    (or an absurd combination, `plan_run`) refuses the campaign in one line naming the run; so does a
    finished folder that holds a different case (resuming would mix campaigns)."""
    check_campaign_size(len(rows))
    specs: list[RunSpec] = []
    invalid: list[str] = []
    for row in rows:
        overrides = {k: v for k, v in row.items() if k != RUN_COLUMN}
        name = str(row.get(RUN_COLUMN) or (run_tag(overrides) if overrides else base.name))
        try:
            case = base.with_overrides({**named_overrides(overrides), "name": name})
            _check_engine_reads(case, overrides)
            spec = RunSpec(name, overrides, out / confined_folder_name(name), case)
            if is_complete(spec.folder):
                _check_same_case(spec)
            if not is_current(spec.folder):  # a finished, current run of this case was planned to run
                plan_run(case)
        except CaseError as exc:
            invalid.append(f"run {name}: {exc}")
            continue
        specs.append(spec)
    if invalid:
        more = f" (and {len(invalid) - 1} more of the {len(rows)} runs)" if len(invalid) > 1 else ""
        raise CaseError(f"{invalid[0]}{more}; nothing was run")
    duplicates = sorted(name for name, count in Counter(s.name for s in specs).items() if count > 1)
    if duplicates:
        more = f" and {len(duplicates) - SHOWN_DUPLICATES} more" if len(duplicates) > SHOWN_DUPLICATES else ""
        raise YadearchError(f"campaign has duplicate runs {duplicates[:SHOWN_DUPLICATES]}{more}")
    return specs


def _check_engine_reads(case: ArchCase, overrides: dict[str, Any]) -> None:
    """CaseError when a run sets a parameter its engine ignores (the static engine and the DEM's
    numerics): two runs that differ only there would give one answer twice."""
    if case.numerics.engine != STATIC_ENGINE:
        refused = static_only_refusal(case.numerics)
        if refused:
            raise CaseError(refused)
        return
    ignored = dem_only_keys(overrides)
    if ignored:
        raise CaseError(f"{ignored[0]} is not used by the static engine (DEM numerics); drop it or use engine dem")


def confined_folder_name(name: str) -> str:
    """`name` if it is a plain folder name, else a stand-in that stays inside the campaign folder
    (a table's `run` cell such as "../../x" must not write outside `--out`)."""
    if name and name == Path(name).name and name not in (".", ".."):
        return name
    return "invalid-name-" + hashlib.sha1(name.encode()).hexdigest()[:8]


def _check_same_case(spec: RunSpec) -> None:
    """Refuse to resume over a finished run folder that ran another case (`reuse.case_differences`:
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
    folders: bool = True,
) -> pd.DataFrame:
    """Run every unfinished run of the campaign on `pool`, then write and return the results table.

    Finished folders are skipped; interrupted and new runs are (re)done, failed ones too unless
    `retry_failed` is false (they keep their recorded reason). Runs start in decreasing
    `expected_cost`. `task` runs one case (default: a child process through `execute`; tests
    inject stand-ins). Without `folders`, a campaign of static runs keeps no run folders: its runs
    are solved in batches and kept as rows (`campaigns.lean`)."""
    out = Path(out)
    specs = plan(base, rows, out)
    lean = not folders and task is execute and all(s.case.numerics.engine == STATIC_ENGINE for s in specs)
    with folder_lock(out, "campaign"):
        if lean:
            return _run_lean(specs, out, pool, timeout_s, progress, retry_failed)
        return _run_planned(specs, out, pool, timeout_s, progress, task, retry_failed)


def _run_lean(
    specs: list[RunSpec], out: Path, pool: Pool, timeout_s: float | None, progress: bool, retry_failed: bool
) -> pd.DataFrame:
    """`run_campaign` without run folders, once planned and locked: its rows from the batch files
    (and any folders an earlier campaign kept), the rest solved in batches."""
    out.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(out)
    remove_stale_temporaries(out / BATCHES_DIR)
    write_run_table(specs, out)
    rows = known_rows(specs, out)
    todo = [
        s for s in specs if rows[s.name]["status"] == "pending" or (retry_failed and rows[s.name]["status"] == "failed")
    ]
    todo.sort(key=lambda spec: expected_cost(spec.case), reverse=True)
    for spec in todo:
        rows[spec.name] = pending_row(spec, "not run yet")
    started = time.time()
    try:
        run_batches(specs, todo, rows, out, pool, timeout_s, progress)
    finally:
        table = tidy(pd.DataFrame(rows.values()))
        write_csv_atomically(out / RESULTS_FILE, table)
        if todo:
            record_session(out, started, pool, len(todo), table, anew=len(todo) == len(specs))
    return table


def _run_planned(
    specs: list[RunSpec], out: Path, pool: Pool, timeout_s: float | None, progress: bool, task: Task, retry_failed: bool
) -> pd.DataFrame:
    """`run_campaign` once its runs are planned and it holds the campaign folder's lock."""
    out.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(out)  # left by a campaign killed while it wrote its tables
    write_run_table(specs, out)
    rows = {s.name: run_row(s, out) for s in specs}  # run names are unique (`plan`)
    complete = {name for name, row in rows.items() if row["status"] == "done"}  # current runs (`run_row`)
    todo = [s for s in specs if s.name not in complete and (retry_failed or not failure_stands(s.folder, s.case))]
    # Longest first: the last runs to start are short, so no core idles while one long run ends
    # the campaign (the 13-point kn sweep's stiffest points take 10-40x its softest).
    todo.sort(key=lambda spec: expected_cost(spec.case), reverse=True)
    for spec in todo:
        (spec.folder / FAILED_FILE).unlink(missing_ok=True)
        rows[spec.name] = run_row(spec, out)  # pending until it ends
    if task is execute and any(s.case.numerics.engine != STATIC_ENGINE for s in todo):
        check_yade_installed()  # a campaign of static runs needs no YADE
    # the table exists before any run starts: a campaign killed (SIGKILL) in its first seconds leaves it
    write_csv_atomically(out / RESULTS_FILE, tidy(pd.DataFrame(rows.values())))
    bar = campaign_bar(out, len(specs), len(todo), progress)
    counts = {"done": len(complete), "failed": len(specs) - len(todo) - len(complete), "interrupted": 0}
    queued = iter(todo)
    futures: dict[Future, RunSpec] = {}

    def submit_next() -> None:
        spec = next(queued, None)
        if spec is not None:
            futures[pool.executor.submit(task, spec.case, spec.folder, timeout_s)] = spec

    started = time.time()
    try:
        # a bounded window of submitted runs, refilled as runs end: waiting on every run of a
        # 14 000-run campaign at once cost the parent most of a core
        for _ in range(SUBMITTED_PER_SLOT * pool.slots):
            submit_next()
        bar.set_postfix(counts, running=min(pool.slots, len(futures)), refresh=False)
        written, interval = time.time(), RESULTS_EVERY_S
        while futures:
            finished, _ = wait(futures, return_when=FIRST_COMPLETED)
            for future in finished:
                spec = futures.pop(future)
                counts[future.result()["status"]] += 1
                rows[spec.name] = run_row(spec, out)
                submit_next()
            if time.time() - written >= interval or not futures:  # the run folders stay the truth
                start = time.time()
                write_csv_atomically(out / RESULTS_FILE, tidy(pd.DataFrame(rows.values())))
                written = time.time()
                interval = results_interval(written - start)
            bar.set_postfix(counts, running=min(pool.slots, len(futures)), refresh=False)
            bar.update(len(finished))
    finally:
        for future in futures:
            future.cancel()
        bar.close()
        table = write_results(specs, out)
        if todo:
            record_session(out, started, pool, len(todo), table, anew=len(todo) == len(specs))
    return table


def write_run_table(specs: list[RunSpec], out: Path) -> None:
    """runs.csv: what the campaign runs (name, folder, overrides), written before anything runs."""
    table = pd.DataFrame(
        [{RUN_COLUMN: s.name, "folder": s.folder.name, **override_columns(s.overrides)} for s in specs]
    )
    write_atomically(out / RUNS_FILE, lambda tmp: table.to_csv(tmp, index=False))


def write_results(specs: list[RunSpec], out: Path) -> pd.DataFrame:
    """results.csv from the run folders as they are now, written atomically; returns the table."""
    table = results_table(specs, out)
    write_csv_atomically(out / RESULTS_FILE, table)
    return table
