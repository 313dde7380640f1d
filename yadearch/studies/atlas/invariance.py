"""Whether the atlas's answers are facts of the arches (issue 41, docs/atlas.md): every arch of the
atlas at the paper's set 2 stiffness and at a stiff one, on the static engine, with each numerical
setting halved and doubled (the increments, the bracket, the runaway bound and the snap floor); the
largest move of du and du_first from the default, its setting, and the outcomes that change."""

from __future__ import annotations

import math
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.markdown import markdown_table
from yadearch.studies.atlas.grid import geometries
from yadearch.studies.campaigns.grid import RUN_COLUMN

INVARIANCE_KNS_N_PER_MM3 = (5.2, 100.0)  # set 2's joints and stiff ones (the stiffest take 10x as long)
FACTORS = (0.5, 2.0)  # each setting halved and doubled
SETTINGS = {  # a setting's name in the table: the numerics it scales together
    "increments": ("first_increment_mm", "max_increment_mm"),
    "bracket": ("du_tolerance_mm",),
    "runaway": ("runaway_thickness_ratio",),
    "snap_floor": ("snap_thickness_ratio",),
}
TOLERANCE = 0.01  # the standard: a result that moves by more than 1 % is not a result yet
BASE = "base"


def variants(base: ArchCase) -> dict[str, dict[str, float]]:
    """Each variant's name and its numerics overrides: the default, then every setting x FACTORS."""
    chosen: dict[str, dict[str, float]] = {BASE: {}}
    for setting, keys in SETTINGS.items():
        for factor in FACTORS:
            chosen[f"{setting}_x{factor:g}"] = {key: getattr(base.numerics, key) * factor for key in keys}
    return chosen


def invariance_rows(base: ArchCase) -> list[dict[str, Any]]:
    """The campaign: every atlas arch at each INVARIANCE_KNS stiffness with every variant."""
    return [
        {**row, RUN_COLUMN: f"{row[RUN_COLUMN]}-{name}", **overrides}
        for geometry in geometries()
        for kn in INVARIANCE_KNS_N_PER_MM3
        for row in (geometry.row(kn),)
        for name, overrides in variants(base).items()
    ]


def _relative(value: float, reference: float) -> float:
    if math.isnan(value) or math.isnan(reference) or reference == 0.0:
        return math.nan
    return abs(value - reference) / reference


def invariance_table(results: pd.DataFrame) -> pd.DataFrame:
    """One row an arch and stiffness: its default outcome, du and du_first, the largest relative move
    of each over the variants and the variant that makes it, and the variants whose outcome differs."""
    split = results[RUN_COLUMN].str.rsplit("-", n=1, expand=True)
    runs = results.assign(case=split[0], variant=split[1])
    rows = []
    for case, group in runs.groupby("case", sort=False):
        base = group[group["variant"] == BASE].iloc[0]
        others = group[group["variant"] != BASE]
        row: dict[str, Any] = {
            "case": case,
            "kn_N_per_mm3": base["kn_N_per_mm3"],
            "outcome": base["outcome"],
            "du_mm": base["du_mm"],
            "du_first_mm": base["du_first_mm"],
        }
        for column in ("du_mm", "du_first_mm"):
            moves = {v: _relative(x, base[column]) for v, x in zip(others["variant"], others[column])}
            finite = {v: m for v, m in moves.items() if not math.isnan(m)}
            worst = max(finite, key=lambda variant: finite[variant]) if finite else ""
            row[f"{column}_spread"] = finite.get(worst, math.nan)
            row[f"{column}_by"] = worst
        row["outcome_changed_by"] = " ".join(others.loc[others["outcome"] != base["outcome"], "variant"])
        rows.append(row)
    return pd.DataFrame(rows)


def invariance_markdown(table: pd.DataFrame) -> str:
    """invariance.md: how many arches keep du and du_first within 1 % under every variant, and each
    exception with the variant that moves it."""
    collapsed = table[table["outcome"] == "collapse"]
    held = {
        column: int((collapsed[f"{column}_spread"].fillna(0.0) <= TOLERANCE).sum())
        for column in ("du_mm", "du_first_mm")
    }
    changed = table[table["outcome_changed_by"].fillna("") != ""]
    lines = [
        "# The atlas's answers against the numerics (static engine)",
        "",
        "Regenerate with `.venv/bin/python scripts/atlas.py --invariance` (docs/atlas.md). Every arch of "
        f"the atlas at kn {', '.join(f'{k:g}' for k in INVARIANCE_KNS_N_PER_MM3)} N/mm³ with each setting "
        f"halved and doubled ({', '.join(SETTINGS)}): {len(table)} arches, {len(collapsed)} collapse by "
        "default.",
        "",
        f"- du within {TOLERANCE * 100:g} % under every variant: {held['du_mm']} of {len(collapsed)}.",
        f"- du_first within {TOLERANCE * 100:g} %: {held['du_first_mm']} of {len(collapsed)}.",
        f"- outcome changed by a variant: {len(changed)} arches.",
        "",
    ]
    outside = collapsed[
        (collapsed["du_mm_spread"] > TOLERANCE) | (collapsed["du_first_mm_spread"] > TOLERANCE)
    ].sort_values("du_first_mm_spread", ascending=False)
    if not outside.empty:
        lines += ["## Moved by more than 1 %", ""]
        lines += markdown_table(
            ["case", "du (mm)", "du spread", "by", "du_first (mm)", "du_first spread", "by"],
            [
                [
                    r["case"],
                    f"{r['du_mm']:.2f}",
                    f"{r['du_mm_spread']:.2%}",
                    r["du_mm_by"],
                    f"{r['du_first_mm']:.2f}",
                    f"{r['du_first_mm_spread']:.2%}",
                    r["du_first_mm_by"],
                ]
                for _, r in outside.iterrows()
            ],
        )
    if not changed.empty:
        lines += ["", "## Outcome changed", ""]
        lines += markdown_table(
            ["case", "default outcome", "changed by"],
            [[r["case"], r["outcome"], r["outcome_changed_by"]] for _, r in changed.iterrows()],
        )
    return "\n".join(lines) + "\n"
