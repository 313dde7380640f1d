"""Whether a finished run folder can be reused for a case instead of being run again: the same case
(what it runs with, its name aside) and a run today's engines would give alike."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from yadearch.case.comparison import as_ran
from yadearch.case.config import ArchCase, with_current_names
from yadearch.case.numerics_section import FULL_RUN_FILES, SUMMARY_RUN_FILES
from yadearch.results.rundir import CASE_FILE, finished_summary, kept_only_summary
from yadearch.results.summary import STATIC, STATIC_REVISION, RunSummary


def case_differences(path: Path, case: ArchCase) -> list[str]:
    """How the finished or started run in `path` differs from `case` ("section.key: ran X, wanted
    Y"), comparing what each runs with (`as_ran`; the name aside), and a folder that kept only its
    summary where `case` keeps its tables."""
    stored = tomllib.loads((Path(path) / CASE_FILE).read_text())
    ran, wanted = as_ran(stored), as_ran(case.to_dict())

    def show(value: Any) -> str:
        return f"{value:.6g}" if isinstance(value, float) else repr(value)

    differences = [
        f"{section}.{key}: ran {show(value)}, wanted {show(wanted[section][key])}"
        for section, values in ran.items()
        if section != "name"
        for key, value in values.items()
        if value != wanted[section][key]
    ]
    if kept_only_summary(with_current_names(stored)) and case.numerics.keeps_tables:  # the reverse serves
        differences.append(f"numerics.run_files: ran {SUMMARY_RUN_FILES!r} (no tables), wanted {FULL_RUN_FILES!r}")
    return differences


def outdated(path: Path) -> bool:
    """True if the finished run in `path` was made by another revision of the static engine than
    today's, whose results may differ: commands and campaigns make it again instead of reusing it."""
    summary = finished_summary(path)
    return summary is not None and _other_static_revision(summary)


def current_summary(path: Path) -> RunSummary | None:
    """The summary of the finished run in `path` if today's engines would give it alike; None for a
    folder without one or with a run of another static engine revision (`outdated`), whose results
    no table may show as today's."""
    summary = finished_summary(path)
    return None if summary is None or _other_static_revision(summary) else summary


def is_current(path: Path) -> bool:
    """True if the folder holds a finished run that today's engines would give alike (`outdated`)."""
    return current_summary(path) is not None


def _other_static_revision(summary: RunSummary) -> bool:
    return summary.engine == STATIC and summary.engine_revision != STATIC_REVISION


def holds_case(path: Path, case: ArchCase) -> bool:
    """True if the folder holds a finished, current run of `case`, which can be reused instead of run again."""
    return is_current(path) and not case_differences(path, case)
