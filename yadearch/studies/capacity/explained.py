"""capacity_stiffness.md: the paper arch's capacity map at several stiffnesses on the static engine,
each with the runaway bound halved and doubled from its default (du and du_first must not move), the
rigid march and the DEM's map beside it, with the numbers of this run."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.markdown import markdown_table, mm_cell

INVARIANCE_PCT = 1.0  # the standard: a result moving more than this with a numerical setting is not one
OPENING_SIDE = (-60.0, 0.0)  # directions (deg) where the support moves away from the arch


def _ratio_range(rows: pd.DataFrame) -> str:
    ratio = (rows["du_mm"] / rows["du_rigid_mm"]).dropna()
    return f"{ratio.min():.2f}-{ratio.max():.2f}" if not ratio.empty else "-"


def stiffness_markdown(static: pd.DataFrame, dem: pd.DataFrame, static_wall_s: float, figure: str) -> str:
    """The report of `scripts/capacity_stiffness.py` from its static table (one `label` a kn and
    runaway ratio) and the DEM's map."""
    ratios = sorted(static["runaway_thickness_ratio"].unique())
    lines = [
        "# The capacity map at every stiffness (static engine)",
        "",
        "Regenerate with `.venv/bin/python scripts/capacity_stiffness.py`. The paper's arch, its right support "
        "moving in a fixed direction every 5° from spreading (0°) through settlement (-90°) to closing (-180°), "
        f"at kn {', '.join(f'{k:g}' for k in sorted(static['kn_N_per_mm3'].unique()))} N/mm³, each with the "
        f"runaway bound at {' and '.join(f'{r:g}' for r in ratios)} ring thickness (halved and doubled from the "
        f"default 0.5): {len(static)} static runs in {static_wall_s:.0f} s of runs. The rigid march and the "
        "DEM's map are drawn beside them.",
        "",
        f"![capacity at every stiffness]({figure}.png)",
        "",
        "*Left: du against the direction of the support movement, static engine (solid and dashed: the runaway "
        "bound halved and doubled), the DEM's points and the rigid march. Right: du over the rigid du "
        f"([PDF]({figure}.pdf)).*",
        "",
    ]
    lines += _invariance_section(static, ratios) + _rigid_section(static, dem) + _dem_section(static, dem)
    lines += ["## Every direction: du (du_first where it differs), mm", "", *_every_direction(static), ""]
    return "\n".join(lines)


def _pair(static: pd.DataFrame, ratios: list[float]) -> pd.DataFrame:
    """One row a kn and direction: du and du_first at the smallest and the largest runaway ratio."""
    low = static[static["runaway_thickness_ratio"] == ratios[0]].set_index(["kn_N_per_mm3", "direction_deg"])
    high = static[static["runaway_thickness_ratio"] == ratios[-1]].set_index(["kn_N_per_mm3", "direction_deg"])
    both = low[["du_mm", "du_first_mm"]].join(high[["du_mm", "du_first_mm"]], rsuffix="_high")
    both["du_gap_pct"] = 100 * (both["du_mm_high"] - both["du_mm"]).abs() / both["du_mm"]
    both["first_gap_pct"] = 100 * (both["du_first_mm_high"] - both["du_first_mm"]).abs() / both["du_first_mm"]
    return both.reset_index()


def _invariance_section(static: pd.DataFrame, ratios: list[float]) -> list[str]:
    both = _pair(static, ratios)
    compared = both.dropna(subset=["du_mm", "du_mm_high"])
    moved = compared[(compared["du_gap_pct"] > INVARIANCE_PCT) | (compared["first_gap_pct"] > INVARIANCE_PCT)]
    lines = [
        f"## The runaway bound halved and doubled ({ratios[0]:g} and {ratios[-1]:g} ring thickness)",
        "",
        f"{len(compared) - len(moved)} of {len(compared)} directions and stiffnesses (both collapsing) keep du and "
        f"du_first within {INVARIANCE_PCT:g} %; largest du gap {compared['du_gap_pct'].max():.2f} %, largest "
        f"du_first gap {compared['first_gap_pct'].max():.2f} %. Runs standing or unresolved at one bound only: "
        f"{int(both['du_mm'].isna().ne(both['du_mm_high'].isna()).sum())}.",
        "",
    ]
    if moved.empty:
        return lines
    return (
        lines
        + markdown_table(
            ["kn", "direction (deg)", "du", "du, doubled", "du_first", "du_first, doubled"],
            [
                [
                    f"{r.kn_N_per_mm3:g}",
                    f"{r.direction_deg:g}",
                    mm_cell(r.du_mm),
                    mm_cell(r.du_mm_high),
                    mm_cell(r.du_first_mm),
                    mm_cell(r.du_first_mm_high),
                ]
                for r in moved.itertuples()
            ],
        )
        + [""]
    )


def _rigid_section(static: pd.DataFrame, dem: pd.DataFrame) -> list[str]:
    opening = static[static["direction_deg"].between(*OPENING_SIDE)]
    rows = [
        [f"static, {label}", _ratio_range(runs), _ratio_range(opening[opening["label"] == label])]
        for label, runs in static.groupby("label", sort=False)
    ]
    rows += [
        [label, _ratio_range(runs), _ratio_range(runs[runs["direction_deg"].between(*OPENING_SIDE)])]
        for label, runs in dem.groupby("label", sort=False)
    ]
    return [
        "## du over the rigid march's du",
        "",
        *markdown_table(["curve", "every direction", "opening side (0° to -60°)"], rows),
        "",
    ]


def _dem_section(static: pd.DataFrame, dem: pd.DataFrame) -> list[str]:
    lines = ["## The DEM at its directions against the static engine (du, mm)", ""]
    rows = []
    for point in dem.sort_values(["kn_N_per_mm3", "direction_deg"], ascending=[True, False]).itertuples():
        match = static[
            (static["kn_N_per_mm3"] == point.kn_N_per_mm3) & (static["direction_deg"] == point.direction_deg)
        ]
        cells = ", ".join(mm_cell(v) for v in match["du_mm"])
        gap = (100 * (match["du_mm"].mean() - point.du_mm) / point.du_mm) if len(match) else math.nan
        rows.append(
            [
                f"{point.kn_N_per_mm3:g}",
                f"{point.direction_deg:g}",
                mm_cell(point.du_mm),
                cells,
                "-" if pd.isna(gap) else f"{gap:+.1f} %",
                mm_cell(point.du_rigid_mm),
            ]
        )
    return (
        lines
        + markdown_table(["kn", "direction (deg)", "DEM", "static (halved, doubled)", "gap", "rigid"], rows)
        + [""]
    )


def _every_direction(static: pd.DataFrame) -> list[str]:
    labels = list(dict.fromkeys(static["label"]))
    rigid = static.drop_duplicates("direction_deg").set_index("direction_deg")["du_rigid_mm"]
    cells: dict[float, list[str]] = {}
    for label in labels:
        for r in static[static["label"] == label].itertuples():
            text = mm_cell(r.du_mm)
            if pd.notna(r.du_first_mm) and pd.notna(r.du_mm) and abs(r.du_first_mm - r.du_mm) > 0.01:
                text += f" ({mm_cell(r.du_first_mm)})"
            cells.setdefault(r.direction_deg, []).append(text)
    rows = [[f"{d:g}", mm_cell(rigid[d]), *cells[d]] for d in sorted(cells, reverse=True)]
    return markdown_table(["direction (deg)", "rigid", *labels], rows)
