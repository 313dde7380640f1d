"""A static path solved again with its increments halved: the increments check of a run or of a live
load's path (numerics.increments_check, docs/numerics.md). Near a critical state the compliant model can
hold equilibria a hair apart and the increments choose the branch (docs/atlas.md): an answer that moves
by more than RESOLVED_TOLERANCE under the check is not resolved by the numerics."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from yadearch.model.hinges import SAME_MECHANISM, hinge_change
from yadearch.solve.path import PathResult
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.static_state import StaticState

CHECK_FACTOR = 0.5  # the increments of the check, x the path's
RESOLVED_TOLERANCE = 0.01  # an answer moving less than this (relative) under the check is resolved
SKIPPED = "the first increment halved would not exceed the bracket (du_tolerance_mm)"


def halved_loading(loading: StaticLoading, start: StaticState) -> StaticLoading | None:
    """A loading of `loading`'s arch, settings and parameter (what drives its path) from `start` (its
    path's first state: the self-weight, a support movement's end or a held live load) with the
    increments x CHECK_FACTOR; None where the first halved increment would not exceed the bracket."""
    settings = loading.settings
    first = CHECK_FACTOR * settings.first_increment
    if first <= settings.tolerance:
        return None
    halved = replace(settings, first_increment=first, max_increment=CHECK_FACTOR * settings.max_increment)
    again = StaticLoading(loading.arch, halved, loading.runaway, loading.solver_settings, loading.parameter)
    again.accepted = [start]
    return again


def check_record(
    ours: dict[str, Any], theirs: dict[str, Any], keys: tuple[str, ...], iterations: int, wall_s: float
) -> dict[str, Any]:
    """The check as recorded: the halved path's outcome and answers `keys`, each one's relative move from
    `ours`, whether the answer is resolved, and the check's iterations and wall time."""
    return {
        "factor": CHECK_FACTOR,
        "outcome": theirs["outcome"],
        **{key: theirs[key] for key in keys},
        **{f"{key}_moved": relative(theirs[key], ours[key]) for key in keys},
        "tolerance": RESOLVED_TOLERANCE,
        "resolved": resolved(ours, theirs, keys),
        "iterations": iterations,
        "wall_s": wall_s,
    }


def resolved(ours: dict[str, Any], theirs: dict[str, Any], keys: tuple[str, ...]) -> bool:
    """Whether two answers agree: the same `outcome`, each of `keys` present in both or in neither (a snap
    one path makes and the other does not is a moved answer), and each within RESOLVED_TOLERANCE."""
    if theirs["outcome"] != ours["outcome"]:
        return False
    for key in keys:
        if _missing(ours[key]) != _missing(theirs[key]):
            return False
        move = relative(theirs[key], ours[key])
        if move is not None and abs(move) > RESOLVED_TOLERANCE:
            return False
    return True


def relative(value: float | None, reference: float | None) -> float | None:
    """The signed relative move of `value` from `reference`; None where either is missing or zero."""
    if _missing(value) or _missing(reference) or reference == 0.0:
        return None
    return (value - reference) / reference  # type: ignore[operator]


def _missing(value: float | None) -> bool:
    return value is None or not math.isfinite(value)


def mode_record(
    loading: StaticLoading, mode_hinges: tuple[str, ...] | list[str], halved: StaticLoading, halved_path: PathResult
) -> dict[str, Any]:
    """Where `halved`'s path `halved_path` (the increments halved) collapses, its collapse mode's hinges,
    how they differ from `loading`'s `mode_hinges` (`model.hinges.hinge_change`) and whether the
    mechanism is kept (`mode_resolved`: the same up to a mirror image or a hinge a joint away); else
    nothing."""
    if not halved_path.collapsed:
        return {}
    hinges = halved.fold_mode(halved_path.upper).labels
    change = hinge_change(" ".join(mode_hinges), " ".join(hinges), len(loading.arch.geometry.joints))
    return {"collapse_mode_hinges": hinges, "mode_hinges_change": change, "mode_resolved": change in SAME_MECHANISM}
