"""The words for a static path's increments check (summary.json's or a load path's `increments_check`,
made by `solve.refined`): one line for the log, the command line, the warnings and the report."""

from __future__ import annotations

from typing import Any

RUN_ANSWERS = (("du", "du_mm", "mm"), ("du_first", "du_first_mm", "mm"))  # (said as, key, unit) of a run's


def check_line(check: dict[str, Any], answers: tuple[tuple[str, str, str], ...] = RUN_ANSWERS) -> str:
    """One line for the log and the command line: the check's `answers` (said as, key, unit) and its
    verdict."""
    if "skipped" in check:
        return f"increments check skipped: {check['skipped']}"
    moved = ", ".join(
        f"{said} {check[key]:{'.2f' if unit == 'mm' else '.4g'}} {unit} ({check[f'{key}_moved']:+.2%})"
        for said, key, unit in answers
        if check[f"{key}_moved"] is not None
    )
    verdict = (
        "resolved"
        if check["resolved"]
        else f"NOT resolved: the answer moves more than {check['tolerance']:.0%} with the increments "
        "(a branch chosen near a critical state, docs/numerics.md)"
    )
    return f"increments halved: {check['outcome']}" + (f", {moved}" if moved else "") + f": {verdict}"


def unresolved_warning(check: dict[str, Any] | None) -> str | None:
    """The warning of a run whose answer its increments check moved (None: no check, or resolved)."""
    if not check or check.get("resolved", True):
        return None
    return f"the answer is not resolved by the numerics: {check_line(check)}"
