"""The figures of a sweep: du against each swept parameter, or the paper's Fig. 8 with the hinges and
the rigid-block asymptote when kn alone is swept."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.case.paper import is_paper_arch
from yadearch.errors import YadearchError
from yadearch.studies.campaigns.grid import NAME_COLUMNS

KN_KEY = "kn_N_per_mm3"


def sweep_figures(
    table: pd.DataFrame, rows: list[dict[str, Any]], folder: Path, base: ArchCase, note: Callable[[str], None]
) -> list[Path]:
    """Draw the sweep's figures into `folder`; their paths (PDF and PNG), or none with a `note` saying
    why (no numeric parameter takes two values, too few runs done)."""
    from yadearch.plotting.sweep import ENGINE_LABELS, kn_sweep_figure, parameter_sweep_figure, swept_columns

    swept = list(dict.fromkeys(k.split(".")[-1] for row in rows for k in row if k not in NAME_COLUMNS))
    columns = swept_columns(table, swept)  # results.csv names an override by its last part
    try:
        if swept == [KN_KEY.split(".")[-1]]:
            return list(
                kn_sweep_figure(
                    table,
                    folder / "du_vs_kn",
                    _rigid_limit_mm(base, note),
                    engine=ENGINE_LABELS[base.numerics.engine],
                    paper=is_paper_arch(base),
                )
            )
        if columns:
            return [p for c in columns for p in parameter_sweep_figure(table, c, folder / f"du_vs_{c}", swept)]
        note("no figure: no numeric parameter takes two values in this campaign")
    except ValueError as exc:
        note(f"no figure: {exc}")
    return []


def _rigid_limit_mm(base: ArchCase, note: Callable[[str], None]) -> float | None:
    """du of the rigid-block limit analysis of the sweep's arch (the stiff asymptote), or None with a
    note when the analysis cannot treat the case."""
    from yadearch.solve.limit import limit_analysis

    try:
        return limit_analysis(base).du_rigid_mm
    except YadearchError as exc:
        note(f"no rigid-block asymptote in the figure: {exc}")
        return None
