"""Markdown tables and the small texts of the reports every layer writes (studies, reporting, the CLI)."""

from __future__ import annotations

import math
from collections.abc import Iterable


def markdown_table(columns: list[str], rows: Iterable[Iterable[str]]) -> list[str]:
    """The lines of a Markdown table: the header, its rule, then one line per row of cell texts."""
    return [
        "| " + " | ".join(columns) + " |",
        "|---" * len(columns) + "|",
        *("| " + " | ".join(row) + " |" for row in rows),
    ]


def text_cell(value: object) -> str:
    """A table's text cell: empty where the value is missing (None, or the NaN pandas leaves in a column
    some rows do not have)."""
    return "" if value is None or (isinstance(value, float) and math.isnan(value)) else str(value)


def mm_cell(value: float | None) -> str:
    """A length (mm) for a report's table to the hundredth, "-" where there is none (None or NaN)."""
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) else f"{value:.2f}"


def seconds_text(seconds: float) -> str:
    """A duration as a run reports it: hundredths below ten seconds (a static run's 0.37 s is not
    "0 s"), whole seconds above."""
    return f"{seconds:.2f} s" if seconds < 10.0 else f"{seconds:.0f} s"


N_PER_KN = 1000.0  # a line load from 1 kN per metre of width up is said in kN/m
MM_PER_M = 1000.0


def per_width(force_N: float, depth_mm: float) -> str:
    """A force (N) carried by the arch's whole out-of-plane depth (mm) per metre of width, as bridge
    assessment quotes a line load: "82.65 N/m of width", "412.5 kN/m of width"."""
    line = force_N / (depth_mm / MM_PER_M)
    return f"{line / N_PER_KN:.4g} kN/m of width" if line >= N_PER_KN else f"{line:.4g} N/m of width"
