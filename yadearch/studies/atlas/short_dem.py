"""The DEM with a relative bracket on the atlas's short collapses (issue 41, docs/atlas.md): the DEM runs
of the atlas whose committed du is short enough for the relative bracket to act (`acting_below_mm`), made
again with `numerics.du_tolerance_ratio`, against the static engine's answers at the same setting (the
bracket study's default runs) and against both engines' answers with du_tolerance_mm alone (atlas.csv)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Any

import pandas as pd

from yadearch.markdown import markdown_table
from yadearch.solve.refined import relative
from yadearch.studies.atlas.invariance import TOLERANCE
from yadearch.studies.campaigns.grid import RUN_COLUMN

TABLE, REPORT = "short_dem.csv", "short_dem.md"


def acting_below_mm(tolerance_mm: float, ratio: float) -> float:
    """The du (mm) below which a bracket of `ratio` x its upper end is narrower than `tolerance_mm`."""
    return tolerance_mm / ratio


def short_rows(atlas: pd.DataFrame, rows: Iterable[dict[str, Any]], below_mm: float) -> list[dict[str, Any]]:
    """The DEM `rows` of the atlas whose committed DEM du (atlas.csv's dem_du_mm) is below `below_mm`."""
    short = set(atlas.loc[atlas["dem_du_mm"] < below_mm, RUN_COLUMN])
    return [row for row in rows if row[RUN_COLUMN] in short]


def short_table(dem: pd.DataFrame, static: pd.DataFrame, atlas: pd.DataFrame) -> pd.DataFrame:
    """One row a short collapse: the DEM's and the static engine's du and du_first with the relative bracket
    (`dem`, a campaign's results; `static`, the bracket study's invariance.csv) and with du_tolerance_mm alone
    (`atlas`), and the gaps DEM against static in per cent with each bracket."""
    stored = atlas.set_index(RUN_COLUMN)
    static_by_case = static.set_index("case")
    rows = []
    for _, run in dem.iterrows():
        name = run[RUN_COLUMN]
        ours, before = static_by_case.loc[name], stored.loc[name]
        row = {RUN_COLUMN: name, "dem_outcome": run["outcome"]}
        for quantity in ("du_mm", "du_first_mm"):
            row[f"dem_{quantity}"] = run[quantity]
            row[f"static_{quantity}"] = ours[quantity]
            row[f"gap_{quantity}_pct"] = _gap_pct(run[quantity], ours[quantity])
            row[f"dem_{quantity}_absolute_bracket"] = before[f"dem_{quantity}"]
            row[f"static_{quantity}_absolute_bracket"] = before[f"static_{quantity}"]
            row[f"gap_{quantity}_absolute_bracket_pct"] = _gap_pct(
                before[f"dem_{quantity}"], before[f"static_{quantity}"]
            )
        rows.append(row)
    return pd.DataFrame(rows)


def _gap_pct(value: float, reference: float) -> float:
    """`value` against `reference` in per cent (`solve.refined.relative`), NaN where either is missing."""
    gap = relative(value, reference)
    return math.nan if gap is None else 100.0 * gap


def short_markdown(
    table: pd.DataFrame, ratio: float, command: str, below_mm: float, unfinished: Sequence[str] = ()
) -> str:
    """short_dem.md: how many short collapses the two engines agree on within 1 % with the relative bracket
    and with du_tolerance_mm alone, the DEM runs that did not finish (`unfinished`), and every row."""

    def agreeing(column: str) -> int:
        return int((table[column].abs() <= 100 * TOLERANCE).sum())

    agree = {quantity: agreeing(f"gap_{quantity}_pct") for quantity in ("du_mm", "du_first_mm")}
    before = {quantity: agreeing(f"gap_{quantity}_absolute_bracket_pct") for quantity in agree}
    lines = [
        f"# The DEM with du's bracket at most {ratio:g} of its upper end: the atlas's short collapses",
        "",
        f"Regenerate with `{command}` (docs/atlas.md). The atlas's DEM runs whose du (atlas.csv) is below "
        f"{below_mm:g} mm, made again with `numerics.du_tolerance_ratio = {ratio:g}`, against the static engine "
        "with the same setting (invariance.csv's default runs); in brackets, both engines with "
        "`du_tolerance_mm` alone (atlas.csv).",
        "",
        f"- both engines within {TOLERANCE * 100:g} %: du in {agree['du_mm']} of {len(table)} "
        f"({before['du_mm']}), du_first in {agree['du_first_mm']} ({before['du_first_mm']}).",
        f"- DEM runs that did not finish: {len(unfinished)}{' (' + ', '.join(unfinished) + ')' if unfinished else ''}.",
        "",
    ]
    lines += markdown_table(
        ["run", "DEM du (mm)", "static du", "gap", "DEM du_first", "static du_first", "gap", "DEM / static du, 0.1 mm"],
        [
            [
                r[RUN_COLUMN],
                f"{r['dem_du_mm']:.3f}",
                f"{r['static_du_mm']:.3f}",
                f"{r['gap_du_mm_pct']:+.2f} %",
                f"{r['dem_du_first_mm']:.3f}",
                f"{r['static_du_first_mm']:.3f}",
                f"{r['gap_du_first_mm_pct']:+.2f} %",
                f"{r['dem_du_mm_absolute_bracket']:.3f} / {r['static_du_mm_absolute_bracket']:.3f}",
            ]
            for _, r in table.iterrows()
        ],
    )
    return "\n".join(lines) + "\n"
