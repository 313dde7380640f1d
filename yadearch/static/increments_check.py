"""A static run's check of its own numerics (numerics.increments_check): the same path solved again from
the same first state with the increments halved (`solve.refined`), and how far du and du_first move."""

from __future__ import annotations

import time
from typing import Any

from yadearch.results.summary import collapse_fields
from yadearch.solve.path import PathResult
from yadearch.solve.refined import SKIPPED, check_record, halved_loading, mode_record
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.static_state import StaticState

ANSWERS = ("du_mm", "du_first_mm")


def increments_check(
    loading: StaticLoading,
    start: StaticState,
    path: PathResult,
    first_loss: tuple[float, float] | None,
    mode_hinges: list[str] | None = None,
) -> dict[str, Any]:
    """summary.json's `increments_check` of `loading`'s followed `path` from `start`: the outcome, du and
    du_first (mm) with the increments halved, their relative moves from the run's, whether the answer is
    resolved, the check's own iterations and wall time, and where both collapse, the check's collapse
    mode beside the run's `mode_hinges` (`solve.refined.mode_record`)."""
    wall0 = time.time()
    again = halved_loading(loading, start)
    if again is None:
        return {"skipped": SKIPPED}
    checked = again.follow()
    ours = _answers(loading, path, first_loss)
    theirs = _answers(again, checked, again.first_loss)
    mode = mode_record(loading, mode_hinges, again, checked) if mode_hinges is not None else {}
    return {**check_record(ours, theirs, ANSWERS, again.iterations, time.time() - wall0), **mode}


def _answers(loading: StaticLoading, path: PathResult, first_loss: tuple[float, float] | None) -> dict[str, Any]:
    """The outcome, du and du_first as the run's summary states them (`results.summary.collapse_fields`)."""
    fields = collapse_fields(path, loading.arch.movement, first_loss)
    return {key: fields.get(key) for key in ("outcome", *ANSWERS)}
