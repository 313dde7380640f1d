"""The atlas report's section on the static answers with the increments halved
(`numerics.increments_check`): how many keep du and du_first, how many change their mechanism, and
each answer that moves."""

from __future__ import annotations

import pandas as pd

from yadearch.markdown import markdown_table, mm_cell, text_cell


def _mode_words(checked: pd.DataFrame) -> list[str]:
    """How many checked collapses changed their mechanism with the increments halved, as a paragraph
    (none for a table made before `increments_mode_resolved`)."""
    if checked.get("static_increments_mode_resolved", pd.Series(dtype=object)).isna().all():
        return []
    changed = checked.loc[checked["static_increments_mode_resolved"].eq(False), "run"].tolist()
    return [f"The collapse mode changes its mechanism in {len(changed)}: {', '.join(changed) or 'none'}.", ""]


def check_section(table: pd.DataFrame) -> list[str]:
    """How many static runs keep their answer with the increments halved (`numerics.increments_check`):
    their outcome, du and du_first within 1 %; and each one that does not, with both answers."""
    checked = table[table["static_increments_resolved"].notna()]
    moved = checked[~checked["static_increments_resolved"].astype(bool)]
    lines = ["## The static answers with the increments halved", ""]
    if checked.empty:
        return lines + ["Not checked (the static runs ran without numerics.increments_check)."]
    collapses = int(checked["static_outcome"].eq("collapse").sum())
    lines.append(
        "Every static run is solved again from its self-weight with the increments halved: of the "
        f"{len(checked)} with an answer ({collapses} collapse), {len(checked) - len(moved)} keep their outcome, du "
        f"and du_first within 1 % (resolved); {len(moved)} do not" + (":" if len(moved) else ".")
    )
    lines[2:2] = _mode_words(checked)  # after the heading
    if moved.empty:
        return lines
    return lines + [
        "",
        *markdown_table(
            ["run", "outcome", "du", "halved", "du_first", "halved"],
            [
                [
                    r.run,
                    text_cell(r.static_outcome),
                    mm_cell(r.static_du_mm),
                    mm_cell(r.static_du_halved_increments_mm),
                    mm_cell(r.static_du_first_mm),
                    mm_cell(r.static_du_first_halved_increments_mm),
                ]
                for r in moved.itertuples()
            ],
        ),
    ]
