"""A campaign of static runs that keeps no run folders (issue 45): its runs go to the workers in
batches, one call each, as case dicts (no case.toml to write and read back), and come back as
summaries kept in memory; each batch's rows are committed in one batch file (`batches`), so a killed
campaign resumes after its last whole batch, and results.csv is rewritten from memory."""

from __future__ import annotations

import math
import time
from concurrent.futures import FIRST_COMPLETED, Future, wait
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically
from yadearch.results.summary import RunSummary
from yadearch.static.pool import solve_batch
from yadearch.studies.campaigns.batches import OUTDATED, read_batches, stored_row, write_batch
from yadearch.studies.campaigns.executors import Pool
from yadearch.studies.campaigns.failures import failure_stands
from yadearch.studies.campaigns.progress import campaign_bar
from yadearch.studies.campaigns.table import (
    RESULTS_EVERY_S,
    RESULTS_FILE,
    RunSpec,
    done_row,
    failed_row,
    pending_row,
    results_interval,
    run_row,
    tidy,
)

BATCH_RUNS = 32  # runs a worker call solves at most (about 4 s of a Saltelli sample's runs)
BATCHES_PER_SLOT = 4  # ... and fewer, so that every slot gets this many batches of a small campaign
SUBMITTED_PER_SLOT = 2  # batches handed to the executor ahead of time, per slot


def known_rows(specs: list[RunSpec], out: Path) -> dict[str, dict[str, Any]]:
    """Each run's row as the campaign stands: from its batch record, else from a run folder an
    earlier campaign kept in `out` (`table.run_row`: done, failed or pending; a failure another
    revision of the static engine recorded is pending, as `failures.failure_stands` has it)."""
    records = read_batches(out)
    rows: dict[str, dict[str, Any]] = {}
    for spec in specs:
        record = records.get(spec.name)
        stored = stored_row(spec, record) if record is not None else None
        if stored is not None:
            rows[spec.name] = stored
        elif record is not None:
            rows[spec.name] = pending_row(spec, OUTDATED)
        elif spec.folder.is_dir():
            row = run_row(spec, out)
            stale = row["status"] == "failed" and not failure_stands(spec.folder, spec.case)
            rows[spec.name] = pending_row(spec, OUTDATED) if stale else row  # another revision's failure: again
        else:
            rows[spec.name] = pending_row(spec, "not run yet")
    return rows


def batches_of(todo: list[RunSpec], slots: int) -> list[list[RunSpec]]:
    """`todo` cut into batches of at most BATCH_RUNS, at least BATCHES_PER_SLOT per slot where it can."""
    size = max(1, min(BATCH_RUNS, math.ceil(len(todo) / (BATCHES_PER_SLOT * slots))))
    return [todo[start : start + size] for start in range(0, len(todo), size)]


def solve(batch: list[RunSpec], timeout_s: float | None) -> list[dict[str, Any]]:
    """The rows of a batch solved in a static worker (a run stopped with its worker: pending)."""
    answers = solve_batch([spec.case.to_dict() for spec in batch], timeout_s)
    rows = []
    for spec, answer in zip(batch, answers):
        if "summary" in answer:
            rows.append(done_row(spec, RunSummary.from_json(answer["summary"])))
        elif "error" in answer:
            rows.append(
                failed_row(spec, f"run {spec.name!r} failed: {answer['error']}", answer.get("wall_s", math.nan))
            )
        else:
            rows.append(pending_row(spec, f"interrupted: {answer['interrupted']}"))
    return rows


def run_batches(
    specs: list[RunSpec],
    todo: list[RunSpec],
    rows: dict[str, dict[str, Any]],
    out: Path,
    pool: Pool,
    timeout_s: float | None,
    progress: bool,
) -> None:
    """Solve `todo` (in this order, pending in `rows`) in batches on `pool`, committing each batch's
    rows and keeping `rows` and results.csv current."""
    write_csv_atomically(out / RESULTS_FILE, tidy(pd.DataFrame(rows.values())))
    statuses = [row["status"] for row in rows.values()]
    counts = {"done": statuses.count("done"), "failed": statuses.count("failed"), "interrupted": 0}
    bar = campaign_bar(out, len(specs), len(todo), progress)
    queued = iter(batches_of(todo, pool.slots))
    futures: dict[Future, list[RunSpec]] = {}

    def submit_next() -> None:
        batch = next(queued, None)
        if batch is not None:
            futures[pool.executor.submit(solve, batch, timeout_s)] = batch

    try:
        for _ in range(SUBMITTED_PER_SLOT * pool.slots):
            submit_next()
        written, interval = time.time(), RESULTS_EVERY_S
        while futures:
            finished, _ = wait(futures, return_when=FIRST_COMPLETED)
            for future in finished:
                batch = futures.pop(future)
                solved = [(spec, row) for spec, row in zip(batch, future.result()) if row["status"] != "pending"]
                if solved:
                    write_batch(out, solved)
                for spec, row in zip(batch, future.result()):
                    rows[spec.name] = row
                    counts["interrupted" if row["status"] == "pending" else row["status"]] += 1
                submit_next()
                bar.update(len(batch))
            if time.time() - written >= interval or not futures:
                start = time.time()
                write_csv_atomically(out / RESULTS_FILE, tidy(pd.DataFrame(rows.values())))
                written = time.time()
                interval = results_interval(written - start)
            bar.set_postfix(counts, refresh=False)
    finally:
        for future in futures:
            future.cancel()
        bar.close()
