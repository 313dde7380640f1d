"""The words for a static path's increments check (summary.json's or a load path's `increments_check`,
made by `solve.refined`): one line for the log, the command line, the warnings and the report."""

from __future__ import annotations

from typing import Any

from yadearch.model.hinges import HINGE_CHANGES, SAME_MECHANISM

RUN_ANSWERS = (("du", "du_mm", "mm"), ("du_first", "du_first_mm", "mm"))  # (said as, key, unit) of a run's


def check_line(
    check: dict[str, Any], answers: tuple[tuple[str, str, str], ...] = RUN_ANSWERS, bracket_mm: float | None = None
) -> str:
    """One line for the log and the command line: the check's `answers` (said as, key, unit) and its
    verdict; an unresolved run's moves all within both paths' brackets of du (each `bracket_mm` wide)
    are laid to the brackets, not to the branch."""
    if "skipped" in check:
        return f"increments check skipped: {check['skipped']}"
    moved = ", ".join(
        f"{said} {check[key]:{'.2f' if unit == 'mm' else '.4g'}} {unit} ({check[f'{key}_moved']:+.2%})"
        for said, key, unit in answers
        if check[f"{key}_moved"] is not None
    )
    cause = "a branch chosen near a critical state, docs/numerics.md"
    if bracket_mm is not None and _within_brackets(check, answers, bracket_mm):
        cause = (
            f"within the two paths' brackets of du, {bracket_mm:.3g} mm wide each (numerics.du_tolerance_mm): "
            "numerics.du_tolerance_ratio narrows them to a share of du"
        )
    verdict = (
        "resolved"
        if check["resolved"]
        else f"NOT resolved: the answer moves more than {check['tolerance']:.0%} with the increments ({cause})"
    )
    change = check.get("mode_hinges_change")  # the collapse mode's hinges beside the run's
    if change is not None:
        hinges = f" ({' '.join(check['collapse_mode_hinges'])})" if change != "the same" else ""
        moved = ", ".join(part for part in (moved, f"collapse mode {change}{hinges}") if part)
        if check["resolved"] and not mode_kept(check):
            answers_said = " and ".join(said for said, key, _ in answers if check.get(f"{key}_moved") is not None)
            verdict = f"{answers_said} resolved, the collapse mode NOT (the increments pick the mechanism)"
    return f"increments halved: {check['outcome']}" + (f", {moved}" if moved else "") + f": {verdict}"


def _within_brackets(check: dict[str, Any], answers: tuple[tuple[str, str, str], ...], bracket_mm: float) -> bool:
    """Whether the same outcome's every answer (mm) moved by no more than two brackets of `bracket_mm`."""
    moves = []
    for _, key, unit in answers:
        moved, value = check.get(f"{key}_moved"), check.get(key)
        if unit != "mm" or moved is None or value is None:
            continue
        moves.append(abs(value - value / (1.0 + moved)))  # the check's answer less the run's
    return bool(moves) and max(moves) <= 2.0 * bracket_mm


def unresolved_warning(check: dict[str, Any] | None, bracket_mm: float | None = None) -> str | None:
    """The warning of a run whose answer or collapse mode its increments check moved (None: no check, or
    both resolved); the run's bracket of du `bracket_mm` wide (`check_line`)."""
    if not check or (check.get("resolved", True) and mode_kept(check)):
        return None
    return f"the answer is not resolved by the numerics: {check_line(check, bracket_mm=bracket_mm)}"


def mode_kept(check: dict[str, Any]) -> bool:
    """Whether the check's collapse mode keeps the run's mechanism: `mode_resolved`, or for a check
    recorded before that field, its `mode_hinges_change` (none recorded: nothing to contradict)."""
    if "mode_resolved" in check:
        return bool(check["mode_resolved"])
    return check.get("mode_hinges_change", HINGE_CHANGES[0]) in SAME_MECHANISM
