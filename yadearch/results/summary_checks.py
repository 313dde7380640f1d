"""summary.json's values checked by type and range when a run folder is read, so that a damaged or
hand-edited summary (du as text, NaN, a negative bracket, an unknown outcome) is one line naming the
key and the value instead of a traceback, or a NaN in a report, further on."""

from __future__ import annotations

import math
from numbers import Real
from typing import Any

# solve.stages.Outcome's values (tests/results/test_summary_checks.py keeps them alike): how a path ended
OUTCOMES = ("collapse", "stands", "unresolved", "cannot stand")
COLLAPSE = "collapse"
ENGINES = ("dem", "static")
SIDES = ("I", "E")  # a hinge pivots about the intrados or the extrados
DISTANCE_KEYS = ("du_mm", "du_first_mm", "last_equilibrium_mm")  # finite, >= 0, or null
BRACKET_KEYS = ("du_bracket_mm", "du_first_bracket_mm")  # [low, high], finite, 0 <= low <= high, or null
TEXT_KEYS = ("collapse_verdict", "collapse_kind", "name")  # a str or null


def _number(value: Any) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool) and math.isfinite(value)


def _count(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool) and value >= 0


def summary_values_problem(data: dict[str, Any]) -> str | None:
    """Why the values of a summary.json object cannot be a run's (None: they can); keys it does
    not know are left to the summary's reader, so a newer field does not make a run unreadable."""
    for key in DISTANCE_KEYS:
        value = data.get(key)
        if value is not None and not (_number(value) and value >= 0):
            return f"{key} must be a finite number >= 0 mm or null, got {value!r:.40}"
    for key in BRACKET_KEYS:
        value = data.get(key)
        if value is not None and not (
            isinstance(value, list) and len(value) == 2 and all(map(_number, value)) and 0 <= value[0] <= value[1]
        ):
            return f"{key} must be [low, high] mm with 0 <= low <= high, or null, got {value!r:.60}"
    components = data.get("du_components_mm")
    if components is not None and not (
        isinstance(components, list) and len(components) == 2 and all(map(_number, components))
    ):
        return f"du_components_mm must be [dx, dy] mm (finite) or null, got {components!r:.60}"
    for key in TEXT_KEYS:
        if data.get(key) is not None and not isinstance(data[key], str):
            return f"{key} must be text or null, got {data[key]!r:.40}"
    return _outcome_problem(data) or _hinges_problem(data.get("hinges_at_collapse")) or _cost_problem(data)


def _outcome_problem(data: dict[str, Any]) -> str | None:
    """The engine and the outcome known, du given exactly when the outcome is a collapse."""
    engine = data.get("engine", ENGINES[0])
    if engine not in ENGINES:
        return f"engine must be one of {', '.join(ENGINES)}, got {engine!r:.40}"
    if "collapsed" in data and not isinstance(data["collapsed"], bool):
        return f"collapsed must be true or false, got {data['collapsed']!r:.40}"
    outcome = data.get("outcome")
    if outcome is None:
        return None
    if outcome not in OUTCOMES:
        return f"outcome must be one of {', '.join(OUTCOMES)}, got {outcome!r:.40}"
    if (outcome == COLLAPSE) != (data.get("du_mm") is not None):
        return (
            f"du_mm must be a number exactly when outcome is {COLLAPSE!r}, got {data.get('du_mm')!r} with {outcome!r}"
        )
    return None


def _hinges_problem(hinges: Any) -> str | None:
    """A list of {interface: an integer >= 1, side: I or E}."""
    if hinges is None:
        return None
    if not isinstance(hinges, list):
        return f"hinges_at_collapse must be a list, got {hinges!r:.40}"
    for hinge in hinges:
        if not (
            isinstance(hinge, dict)
            and _count(hinge.get("interface"))
            and hinge["interface"] >= 1
            and hinge.get("side") in SIDES
        ):
            return f"hinges_at_collapse must hold {{interface: >= 1, side: I or E}}, got {hinge!r:.60}"
    return None


def _cost_problem(data: dict[str, Any]) -> str | None:
    """Steps and iterations counts, the wall time a finite duration."""
    for key in ("steps", "iterations", "increments", "equilibria"):
        value = data.get(key)
        if value is not None and not _count(value):
            return f"{key} must be an integer >= 0, got {value!r:.40}"
    wall = data.get("wall_s")
    if wall is not None and not (_number(wall) and wall >= 0):
        return f"wall_s must be a finite number of seconds >= 0, got {wall!r:.40}"
    rows = data.get("table_rows")
    if rows is not None and not (isinstance(rows, dict) and all(map(_count, rows.values()))):
        return f"table_rows must map each table to its row count, got {rows!r:.60}"
    return None
