"""A static run's check of its own numerics (numerics.increments_check): the same path solved again from
the same starting state with the increments halved, and how far du and du_first move. Near a critical
state the compliant model can hold several equilibria a hair apart, and the increments choose the
branch (docs/atlas.md, "Are the answers facts of the arch?"): a run says when that moved its answer."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from yadearch.results.summary import collapse_fields
from yadearch.solve.path import PathResult
from yadearch.solve.static_path import StaticLoading

CHECK_FACTOR = 0.5  # the increments of the check, x the run's
RESOLVED_TOLERANCE = 0.01  # an answer moving less than this (relative) under the check is resolved


def halved_loading(loading: StaticLoading) -> StaticLoading | None:
    """A loading of `loading`'s arch from its starting state (the self-weight, or a held live load) with
    the increments x CHECK_FACTOR; None where the first halved increment would not exceed the bracket."""
    settings = loading.settings
    first = CHECK_FACTOR * settings.first_increment
    if first <= settings.tolerance:
        return None
    halved = replace(settings, first_increment=first, max_increment=CHECK_FACTOR * settings.max_increment)
    again = StaticLoading(loading.arch, halved, loading.runaway, loading.solver_settings, loading.parameter)
    again.accepted = [loading.accepted[0]]
    return again


def increments_check(start: StaticLoading, path: PathResult, first_loss: tuple[float, float] | None) -> dict[str, Any]:
    """summary.json's `increments_check`: the run's outcome, du and du_first (mm) with the increments
    halved, their relative moves from the run's (`path`, `first_loss`), and whether both stay within
    RESOLVED_TOLERANCE with the same outcome. `start` holds only the path's starting state."""
    again = halved_loading(start)
    if again is None:
        return {"factor": CHECK_FACTOR, "skipped": "the first increment halved would not exceed du_tolerance_mm"}
    checked = again.follow()
    ours = _answers(start, path, first_loss)
    theirs = _answers(again, checked, again.first_loss)
    moves = {f"{key}_moved": _relative(theirs[key], ours[key]) for key in ours if key != "outcome"}
    resolved = theirs["outcome"] == ours["outcome"] and all(
        move is None or abs(move) <= RESOLVED_TOLERANCE for move in moves.values()
    )
    return {
        "factor": CHECK_FACTOR,
        "outcome": theirs["outcome"],
        "du_mm": theirs["du_mm"],
        "du_first_mm": theirs["du_first_mm"],
        **moves,
        "tolerance": RESOLVED_TOLERANCE,
        "resolved": resolved,
    }


def _answers(loading: StaticLoading, path: PathResult, first_loss: tuple[float, float] | None) -> dict[str, Any]:
    """The outcome, du and du_first as the run's summary states them (`results.summary.collapse_fields`)."""
    fields = collapse_fields(path, loading.arch.movement, first_loss)
    return {key: fields.get(key) for key in ("outcome", "du_mm", "du_first_mm")}


def _relative(value: float | None, reference: float | None) -> float | None:
    """The signed relative move of `value` from `reference`; None where either is missing or zero."""
    if value is None or reference is None or reference == 0.0 or not math.isfinite(reference):
        return None
    return (value - reference) / reference
