"""A campaign's sessions (sessions.json): one entry per invocation, so that a resumed campaign's wall
time and core-seconds are the sums over its sessions (the benchmark reads them)."""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_text_atomically
from yadearch.studies.campaigns.executors import Pool

SESSIONS_FILE = "sessions.json"  # one entry per invocation: when, where, how many runs, wall time


def record_session(
    out: Path, started: float, pool: Pool, attempted: int, table: pd.DataFrame, anew: bool = False
) -> None:
    """Append this invocation's wall time to sessions.json, so that a resumed campaign's total wall
    time is the sum of its sessions; a campaign that made every run `anew` (none was there finished)
    starts the record again: the earlier sessions made runs that are no longer there."""
    sessions = [] if anew else _sessions(out) or []
    sessions.append(
        {
            "started": time.strftime("%Y-%m-%dT%H:%M:%S", time.localtime(started)),
            "wall_s": round(time.time() - started, 1),
            "where": pool.where,
            "slots": pool.slots,
            "runs_attempted": attempted,
            "status_after": table["status"].value_counts().to_dict(),
        }
    )
    write_text_atomically(out / SESSIONS_FILE, json.dumps(sessions, indent=2) + "\n")


def _sessions(out: Path) -> list[dict[str, Any]] | None:
    """The invocations a campaign recorded in sessions.json (None if none was)."""
    path = Path(out) / SESSIONS_FILE
    return json.loads(path.read_text()) if path.is_file() else None


def campaign_wall_s(out: Path) -> float | None:
    """Total wall time of a campaign over all its sessions (None if none was recorded)."""
    sessions = _sessions(out)
    return None if sessions is None else sum(s["wall_s"] for s in sessions)


def campaign_core_s(out: Path) -> float | None:
    """Core-seconds a campaign used: each session's wall time times its slots (None if none was
    recorded); what the same runs would cost on any number of cores."""
    sessions = _sessions(out)
    return None if sessions is None else sum(s["wall_s"] * s.get("slots", 1) for s in sessions)
