"""The results of a campaign that keeps no run folders (`runner.run_campaign(..., folders=False)`):
each batch of runs, once solved, is one JSON Lines file in OUT/batches, written atomically, one
record per run (its results row, the case it ran, the static engine's revision); later files
supersede earlier ones. These files are the campaign's truth, as run folders are otherwise."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

from yadearch.atomic import write_text_atomically
from yadearch.case.comparison import fingerprinted
from yadearch.errors import YadearchError
from yadearch.results.summary import STATIC_REVISION
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.campaigns.table import RunSpec

BATCHES_DIR = "batches"
BATCH_DIGITS = 6  # batch files are numbered in the order they were written: 000001.jsonl, ...
OUTDATED = "made by another revision of the static engine: to be run again"


def case_key(spec: RunSpec) -> str:
    """A short fingerprint of what the run computes (`fingerprinted`: the name and the files kept aside,
    the parameters a later version added at their former behaviour left out)."""
    return hashlib.sha1(json.dumps(fingerprinted(spec.case.to_dict()), sort_keys=True).encode()).hexdigest()[:16]


def read_batches(out: Path) -> dict[str, dict[str, Any]]:
    """The latest record of every run in the campaign's batch files, by run name."""
    records: dict[str, dict[str, Any]] = {}
    numbered = [p for p in (out / BATCHES_DIR).glob("*.jsonl") if p.stem.isdigit()]
    for path in sorted(numbered, key=lambda p: int(p.stem)):  # in the order written, past any width
        for line in path.read_text().splitlines():
            try:
                record = json.loads(line)
            except ValueError:  # a line cut short (the machine stopped mid-write): its run is run again
                continue
            records[record["row"][RUN_COLUMN]] = record
    return records


def stored_row(spec: RunSpec, record: dict[str, Any]) -> dict[str, Any] | None:
    """The stored row of `spec`, None if another revision of the engine made it (to run again);
    refuses a record of another case, as a run folder of another case is refused."""
    if record["case"] != case_key(spec):
        raise YadearchError(
            f"run {spec.name} in {BATCHES_DIR}/ ran another case than this campaign's; use another --out"
        )
    return record["row"] if record["engine_revision"] == STATIC_REVISION else None


def write_batch(out: Path, rows: list[tuple[RunSpec, dict[str, Any]]]) -> Path:
    """Commit the rows of one solved batch as the next batch file (atomically: whole or absent)."""
    folder = out / BATCHES_DIR
    folder.mkdir(parents=True, exist_ok=True)
    last = max((int(p.stem) for p in folder.glob("*.jsonl") if p.stem.isdigit()), default=0)
    lines = (
        json.dumps({"row": row, "case": case_key(spec), "engine_revision": STATIC_REVISION}, default=_plain)
        for spec, row in rows
    )
    return write_text_atomically(folder / f"{last + 1:0{BATCH_DIGITS}d}.jsonl", "\n".join(lines) + "\n")


def _plain(value: Any) -> Any:
    """A numpy number as JSON takes it (NaN stays NaN: Python's json reads it back)."""
    return value.item()
