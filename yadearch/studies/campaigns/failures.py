"""A campaign run's failure record (failed.json): why it failed and, for a static run, which revision of
the static engine failed it, so that a campaign keeps a failure only while today's engines would repeat it."""

from __future__ import annotations

import json
from pathlib import Path

from yadearch.atomic import write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.launch.process import STATIC_ENGINE
from yadearch.results.summary import STATIC_REVISION

FAILED_FILE = "failed.json"


def record_failure(folder: Path, case: ArchCase, reason: str, wall_s: float) -> None:
    """Write failed.json: why the run failed, how long it took and, for a static run, the engine's
    revision (a failure of another revision is tried again, `failure_stands`)."""
    record = {"name": case.name, "status": "failed", "reason": reason, "wall_s": wall_s}
    if case.numerics.engine == STATIC_ENGINE:
        record["engine_revision"] = STATIC_REVISION
    write_text_atomically(folder / FAILED_FILE, json.dumps(record, indent=2) + "\n")


def failure_stands(folder: Path, case: ArchCase) -> bool:
    """True if the run failed before and would fail alike: a DEM run's failure, or a static run's
    recorded by today's static engine (its failures are deterministic)."""
    path = folder / FAILED_FILE
    if not path.is_file():
        return False
    if case.numerics.engine != STATIC_ENGINE:
        return True
    try:
        return json.loads(path.read_text()).get("engine_revision") == STATIC_REVISION
    except (OSError, ValueError, AttributeError):
        return False
