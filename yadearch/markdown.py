"""Markdown tables for the reports every layer writes (studies, reporting)."""

from __future__ import annotations

from collections.abc import Iterable


def markdown_table(columns: list[str], rows: Iterable[Iterable[str]]) -> list[str]:
    """The lines of a Markdown table: the header, its rule, then one line per row of cell texts."""
    return [
        "| " + " | ".join(columns) + " |",
        "|---" * len(columns) + "|",
        *("| " + " | ".join(row) + " |" for row in rows),
    ]
