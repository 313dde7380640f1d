"""A static run's check of its own numerics (numerics.increments_check): the same path solved again from
the same starting state with the increments halved, and how far du and du_first move. Near a critical
state the compliant model can hold several equilibria a hair apart, and the increments choose the
branch (docs/atlas.md, "Are the answers facts of the arch?"): a run says when that moved its answer."""

from __future__ import annotations

import math
import time
from dataclasses import replace
from typing import Any

from yadearch.results.summary import collapse_fields
from yadearch.solve.path import PathResult
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.static_state import StaticState

CHECK_FACTOR = 0.5  # the increments of the check, x the run's
RESOLVED_TOLERANCE = 0.01  # an answer moving less than this (relative) under the check is resolved
ANSWERS = ("du_mm", "du_first_mm")


def halved_loading(loading: StaticLoading, start: StaticState) -> StaticLoading | None:
    """A loading of `loading`'s arch, settings and parameter (what drives its path) from `start` (its
    path's first state: the self-weight, or a held live load) with the increments x CHECK_FACTOR; None
    where the first halved increment would not exceed the bracket."""
    settings = loading.settings
    first = CHECK_FACTOR * settings.first_increment
    if first <= settings.tolerance:
        return None
    halved = replace(settings, first_increment=first, max_increment=CHECK_FACTOR * settings.max_increment)
    again = StaticLoading(loading.arch, halved, loading.runaway, loading.solver_settings, loading.parameter)
    again.accepted = [start]
    return again


def increments_check(
    loading: StaticLoading, start: StaticState, path: PathResult, first_loss: tuple[float, float] | None
) -> dict[str, Any]:
    """summary.json's `increments_check` of `loading`'s followed `path` from `start`: the outcome, du and
    du_first (mm) with the increments halved, their relative moves from the run's, whether the answer is
    resolved (`resolved`), and the check's own iterations and wall time."""
    wall0 = time.time()
    again = halved_loading(loading, start)
    if again is None:
        return {"factor": CHECK_FACTOR, "skipped": "the first increment halved would not exceed du_tolerance_mm"}
    checked = again.follow()
    ours = _answers(loading, path, first_loss)
    theirs = _answers(again, checked, again.first_loss)
    return {
        "factor": CHECK_FACTOR,
        "outcome": theirs["outcome"],
        **{key: theirs[key] for key in ANSWERS},
        **{f"{key}_moved": _relative(theirs[key], ours[key]) for key in ANSWERS},
        "tolerance": RESOLVED_TOLERANCE,
        "resolved": resolved(ours, theirs),
        "iterations": again.iterations,
        "wall_s": time.time() - wall0,
    }


def resolved(ours: dict[str, Any], theirs: dict[str, Any]) -> bool:
    """Whether two answers (outcome, du_mm, du_first_mm) agree: the same outcome, each distance present
    in both or in neither (a snap one path makes and the other does not is a moved answer), and each
    within RESOLVED_TOLERANCE."""
    if theirs["outcome"] != ours["outcome"]:
        return False
    for key in ANSWERS:
        if (ours[key] is None) != (theirs[key] is None):
            return False
        move = _relative(theirs[key], ours[key])
        if move is not None and abs(move) > RESOLVED_TOLERANCE:
            return False
    return True


def _answers(loading: StaticLoading, path: PathResult, first_loss: tuple[float, float] | None) -> dict[str, Any]:
    """The outcome, du and du_first as the run's summary states them (`results.summary.collapse_fields`)."""
    fields = collapse_fields(path, loading.arch.movement, first_loss)
    return {key: fields.get(key) for key in ("outcome", *ANSWERS)}


def _relative(value: float | None, reference: float | None) -> float | None:
    """The signed relative move of `value` from `reference`; None where either is missing or zero."""
    if value is None or reference is None or reference == 0.0 or not math.isfinite(reference):
        return None
    return (value - reference) / reference
