"""The atlas's files: atlas.csv (every run), atlas.md (the targets, each exception, the du of every
arch against kn beside the rigid march's) and atlas.pdf/.png, from the campaigns' results."""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import preset
from yadearch.markdown import markdown_table, mm_cell, text_cell
from yadearch.plotting.atlas import atlas_figure
from yadearch.studies.atlas.check_report import check_section
from yadearch.studies.atlas.grid import DEM_KN_N_PER_MM3, KNS_N_PER_MM3, MOVEMENTS, SHAPES, THICKNESS_OVER_RADIUS
from yadearch.studies.atlas.rigid import COMPLIANT_TABLE, KEY
from yadearch.studies.atlas.rigid import TABLE as TABLE_RIGID
from yadearch.studies.atlas.table import (
    ENGINES_TARGET_PCT,
    FIRST_WIDE_PCT,
    RISE_TOLERANCE_PCT,
    STIFF_TARGET_PCT,
    atlas_table,
    engine_rows,
    rising,
    stiff_first_gaps,
    stiff_rows,
)
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, dem_arguments

TABLE, REPORT, FIGURE = "atlas.csv", "atlas.md", "atlas"
COMMAND = ".venv/bin/python scripts/atlas.py"
OUTCOMES = ("collapse", "stands", "unresolved", "cannot stand", "failed")


def write_atlas(
    out: Path,
    runs: Path,
    static: pd.DataFrame | None,
    rigid: pd.DataFrame | None,
    dem: pd.DataFrame | None,
    dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS,
) -> pd.DataFrame:
    """OUT/atlas.csv, atlas.md (its command naming the DEM's `dem_settings`) and atlas.pdf/.png; parts not
    given are read from RUNS and OUT."""
    static = static if static is not None else _results(runs / "static")
    dem = dem if dem is not None else _results(runs / "dem")
    rigid = rigid if rigid is not None else pd.read_csv(out / TABLE_RIGID)
    compliant = pd.read_csv(out / COMPLIANT_TABLE) if (out / COMPLIANT_TABLE).is_file() else None
    table = atlas_table(static, rigid, dem, compliant)
    write_csv_atomically(out / TABLE, table)
    atlas_figure(table, out / FIGURE, travel_mm())
    write_text_atomically(out / REPORT, atlas_markdown(table, dem_arguments(dem_settings)))
    return table


def travel_mm() -> float:
    """How far the atlas's support moves at most (mm): set 2's, the base of every case."""
    return preset("set2").loading.max_support_displacement_mm


def _results(folder: Path) -> pd.DataFrame | None:
    path = folder / "results.csv"
    return pd.read_csv(path) if path.is_file() else None


def _pct(value: float) -> str:
    return "-" if math.isnan(value) else f"{value:+.1f} %"


def atlas_markdown(table: pd.DataFrame, arguments: str = "") -> str:
    """atlas.md: what was run, the outcome counts, each target with its exceptions, the du table;
    `arguments` name the DEM's settings in its command."""
    lines = [
        "# Atlas: collapse of five arch shapes on six support movements, three solvers",
        "",
        f"Regenerate: `{COMMAND}{arguments}` (resumes; docs/atlas.md says what it checks and why).",
        "",
        f"- Shapes: {', '.join(SHAPES)} (span 600 mm, or the paper's intrados radius 300 mm; 55 voussoirs).",
        f"- Movements of the right support: {', '.join(MOVEMENTS)} (up to {travel_mm():g} mm).",
        f"- Thickness t/R: {', '.join(f'{r:g}' for r in THICKNESS_OVER_RADIUS)} (R = 300 mm);"
        f" kn: {', '.join(f'{k:g}' for k in KNS_N_PER_MM3)} N/mm3; the DEM at kn {DEM_KN_N_PER_MM3:g}.",
        "- du_first: where the path first loses stability (a fold or a snap); du: the end of the path.",
        "",
        "![atlas](atlas.png)",
        "",
        "## Outcomes",
        "",
        *_outcome_counts(table),
        "",
        *_stiff_section(table),
        "",
        *_engines_section(table),
        "",
        *_rising_section(table),
        "",
        *_unresolved_section(table),
        "",
        *check_section(table),
        "",
        "## du of every arch (static, mm) against kn, and the rigid march",
        "",
        "du (du_first where it differs); * the answer moves more than 1 % with the increments halved.",
        "",
        *_du_table(table),
        "",
    ]
    return "\n".join(lines)


def _outcome_counts(table: pd.DataFrame) -> list[str]:
    rigid = table.drop_duplicates(KEY)
    columns = ["solver", "runs", *OUTCOMES]
    rows = []
    solvers = [
        ("static", table, "static_outcome"),
        ("DEM", table[table["dem_outcome"].notna()], "dem_outcome"),
        ("rigid march", rigid, "rigid_outcome"),
    ]
    if "compliant_outcome" in rigid:
        solvers.append((f"compliant march (kn {max(KNS_N_PER_MM3):g})", rigid, "compliant_outcome"))
    for label, frame, column in solvers:
        counts = (
            frame[column].astype("string").fillna("not run").str.split(":").str[0].value_counts()
        )  # "failed: why" -> failed
        rows.append([label, str(int(frame[column].notna().sum())), *(str(int(counts.get(o, 0))) for o in OUTCOMES)])
    return markdown_table(columns, rows)


def _stiff_section(table: pd.DataFrame) -> list[str]:
    stiff = stiff_rows(table)
    outside = stiff[stiff["static_rigid_gap_pct"].abs() > STIFF_TARGET_PCT]
    lines = [
        f"## Static at kn {max(KNS_N_PER_MM3):g} against the rigid march (target {STIFF_TARGET_PCT:g} %)",
        "",
        f"{len(stiff) - len(outside)} of {len(stiff)} arches where both collapse are within {STIFF_TARGET_PCT:g} %"
        " (the rigid branch of the keystone's tie nearest the static du).",
        *_stiff_first_line(stiff),
    ]
    if "static_compliant_gap_pct" in outside:
        explained = outside[outside["static_compliant_gap_pct"].abs() <= ENGINES_TARGET_PCT]
        lines += [
            f"Of the {len(outside)} outside, {len(explained)} are within {ENGINES_TARGET_PCT:g} % of the compliant "
            f"march at kn {max(KNS_N_PER_MM3):g} (`limit --compliant`: the joints beside the hinges folding at "
            "that stiffness's margin): their gap is the joints' compliance, which this kn still has, not numerics.",
        ]
    extra = (
        {"compliant du": ("compliant_branch_du_mm", mm_cell), "gap to compliant": ("static_compliant_gap_pct", _pct)}
        if "compliant_branch_du_mm" in outside
        else {}
    )
    rows = _gap_rows(outside, "static_rigid_gap_pct", ("rigid_branch_du_mm", "rigid_hinges"), "rigid", extra)
    return lines + ["", "Outside:", ""] + rows


def _stiff_first_line(stiff: pd.DataFrame) -> list[str]:
    """How near the static du_first at the stiffest kn lies to the march's (`stiff_first_gaps`)."""
    gaps, bounds = stiff_first_gaps(stiff), (STIFF_TARGET_PCT, FIRST_WIDE_PCT)
    counts = ", ".join(f"{int((gaps <= pct).sum())} of {len(gaps)} within {pct:g} %" for pct in bounds)
    return [f"du_first (both the first snap past the snap floor, or the collapse): {counts}."] if len(gaps) else []


def _engines_section(table: pd.DataFrame) -> list[str]:
    both = engine_rows(table)
    du_out = both[both["dem_static_gap_pct"].abs() > ENGINES_TARGET_PCT]
    first_out = both[both["dem_static_first_gap_pct"].abs() > ENGINES_TARGET_PCT]
    lines = [
        f"## Static against the DEM at kn {DEM_KN_N_PER_MM3:g} (target {ENGINES_TARGET_PCT:g} %)",
        "",
        f"Both collapse in {len(both)} of {int(table['dem_outcome'].notna().sum())} DEM runs; du within "
        f"{ENGINES_TARGET_PCT:g} % in {len(both) - len(du_out)}, du_first in {len(both) - len(first_out)}."
        " du outside:",
        "",
    ]
    lines += _gap_rows(du_out, "dem_static_gap_pct", ("dem_du_mm", "dem_hinges"), "DEM")
    disagree = table[table["dem_outcome"].notna() & table["dem_outcome"].ne(table["static_outcome"])]
    if len(disagree):
        lines += ["", "Outcomes that differ:", ""]
        lines += markdown_table(
            ["run", "static", "DEM"],
            [
                [
                    r.run,
                    f"{text_cell(r.static_outcome) or 'pending'} {mm_cell(r.static_du_mm)}",
                    f"{r.dem_outcome} {mm_cell(r.dem_du_mm)} {text_cell(r.dem_reason)}",
                ]
                for r in disagree.itertuples()
            ],
        )
    return lines


def _gap_rows(
    rows: pd.DataFrame, gap: str, other: tuple[str, str], label: str, extra: dict[str, tuple[str, Any]] | None = None
) -> list[str]:
    """The rows outside a target: the static answer, the other solver's, the gap, and `extra`
    columns (title: (column, formatter))."""
    if rows.empty:
        return ["(none)"]
    extra = extra or {}
    return markdown_table(
        ["run", "static du_first", "static du", "static hinges", f"{label} du", f"{label} hinges", "gap", *extra],
        [
            [
                r["run"],
                mm_cell(r["static_du_first_mm"]),
                mm_cell(r["static_du_mm"]),
                text_cell(r["static_hinges"]),
                mm_cell(r[other[0]]),
                text_cell(r[other[1]]),
                _pct(r[gap]),
                *(shown(r[column]) for column, shown in extra.values()),
            ]
            for _, r in rows.iterrows()
        ],
    )


def _rising_section(table: pd.DataFrame) -> list[str]:
    verdicts = rising(table)
    falling = verdicts[~verdicts["rises"]]
    lines = [
        "## du rising toward the rigid march as kn grows",
        "",
        f"{int(verdicts['rises'].sum())} of {len(verdicts)} arches collapsing at every kn have a du that never"
        f" falls more than {RISE_TOLERANCE_PCT:g} % toward a stiffer kn. Falling:",
        "",
    ]
    if falling.empty:
        return lines + ["(none)"]
    return lines + markdown_table(
        ["arch", "largest fall"], [[r.geometry, f"{r.largest_fall_pct:.1f} %"] for r in falling.itertuples()]
    )


def _unresolved_section(table: pd.DataFrame) -> list[str]:
    rows = table[table["static_outcome"].isin(["unresolved", "failed"])]
    lines = ["## Static runs without an answer", "", f"{len(rows)} runs (never counted as collapse):", ""]
    if rows.empty:
        return lines + ["(none)"]
    return lines + markdown_table(
        ["run", "outcome", "reason", "rigid du_first", "rigid du"],
        [
            [r.run, r.static_outcome, text_cell(r.static_reason), mm_cell(r.rigid_du_first_mm), mm_cell(r.rigid_du_mm)]
            for r in rows.itertuples()
        ],
    )


def _du_table(table: pd.DataFrame) -> list[str]:
    columns = ["arch", *(f"kn {k:g}" for k in KNS_N_PER_MM3), "rigid", "rigid hinges"]
    rows = []
    for name, runs in table.groupby(KEY, sort=False):
        by_kn = runs.set_index("kn_N_per_mm3")
        cells = [_cell(by_kn.loc[k]) for k in KNS_N_PER_MM3]
        first = runs.iloc[0]
        rigid = (
            mm_cell(first["rigid_du_mm"]) if first["rigid_outcome"] == "collapse" else text_cell(first["rigid_outcome"])
        )
        rows.append([name, *cells, rigid, text_cell(first.get("rigid_hinges"))])
    return markdown_table(columns, rows)


def _cell(row: pd.Series) -> str:
    """A static run as du (du_first where it differs), or its outcome."""
    if row["static_outcome"] != "collapse":
        return text_cell(row["static_outcome"]) or "pending"
    first, du = row["static_du_first_mm"], row["static_du_mm"]
    moved = "*" if row.get("static_increments_resolved") is False or row.get("static_increments_resolved") == 0 else ""
    return (mm_cell(du) if abs(first - du) < 0.01 else f"{mm_cell(du)} ({mm_cell(first)})") + moved
