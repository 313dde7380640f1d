"""Where a result came from: versions and the git revision of the code that produced it."""

from __future__ import annotations

import functools
import subprocess
from pathlib import Path
from typing import Any

from yadearch import __version__

STARTED_FORMAT = "%Y-%m-%dT%H:%M:%S"  # summary.json's `started`: local time, sortable as text


@functools.lru_cache(maxsize=1)
def git_revision() -> str | None:
    """The git commit of the yadearch source tree (with '+dirty' if modified), or None: asked once a
    process, as the code a process runs is the code it imported (a static worker serves a campaign)."""
    return tree_revision(Path(__file__).resolve().parents[1])


def tree_revision(package: Path) -> str | None:
    """The git commit checked out where the folder `package` is, with '+dirty' where a tracked file in
    that folder is modified; None outside a git checkout."""
    try:
        rev = subprocess.run(
            ["git", "rev-parse", "--short=12", "HEAD"], cwd=package, capture_output=True, text=True, check=True
        ).stdout.strip()
        dirty = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no", "--", "."],
            cwd=package,
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    return rev + ("+dirty" if dirty else "")


def provenance(yade_version: str | None) -> dict[str, Any]:
    """The versions and revision a run records in its summary (RunSummary fields)."""
    return {"yade_version": yade_version, "yadearch_version": __version__, "git_revision": git_revision()}
