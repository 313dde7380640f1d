"""The words for a static run's increments check (summary.json `increments_check`, made by
`static.increments_check`): one line for the log, the command line, the warnings and the report."""

from __future__ import annotations

from typing import Any

ANSWERS = ("du", "du_first")


def check_line(check: dict[str, Any]) -> str:
    """One line for the log and the command line: the check's answers and its verdict."""
    if "skipped" in check:
        return f"increments check skipped: {check['skipped']}"
    moved = ", ".join(
        f"{name} {check[f'{name}_mm']:.2f} mm ({check[f'{name}_mm_moved']:+.2%})"
        for name in ANSWERS
        if check[f"{name}_mm_moved"] is not None
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
