"""reports/loads/engines: the DEM against the static engine on live loads, written as tables, a figure
and a Markdown report (`scripts/loads_engines.py`; minutes of YADE)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.markdown import markdown_table
from yadearch.plotting.loads import plot_engines
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, dem_arguments, with_dem_settings
from yadearch.studies.loads.engines import (
    ENGINES_KN,
    NUMERICS_CASES,
    NUMERICS_VARIANTS,
    dem_influence_line,
    engine_cases,
    engines_table,
    numerics_cases,
)
from yadearch.studies.loads.held import STIFF_KN, held_cases, held_table
from yadearch.studies.loads.rigid import paper_arch
from yadearch.studies.loads.static import static_influence_line

ENGINES_TOLERANCE = 0.01  # the DEM within 1 % of the static engine (issue 44)
INFLUENCE_POSITIONS = 7  # points of the paper's arch's influence line on both engines
HELD_FOLDER = "held_runs"  # the DEM's run folders of the held-load cases (a rerun reads them back)
STIFF_TOLERANCE = 0.02  # stiff static within 2 % of the rigid march
RUNS_FOLDER = "load_paths"  # each DEM load path's files, under the report's folder (a rerun reads them back)


def write_engines_report(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> Path:
    """Run the comparison (the DEM runs with `dem_settings`, `jobs` at a time; those already in
    OUT/load_paths are read back) and write engines.csv, numerics.csv, influence.csv, held.csv,
    engines.pdf/.png and engines.md into `out`; the report's path."""
    out.mkdir(parents=True, exist_ok=True)
    cases = engine_cases()
    table = engines_table(cases, out / RUNS_FOLDER, jobs, log, dem_settings)
    numerics = engines_table(numerics_cases(cases), out / RUNS_FOLDER, jobs, log, dem_settings)
    influence = influence_table(out / RUNS_FOLDER, jobs, dem_settings)
    held = held_table(held_cases(), out / HELD_FOLDER, jobs, log, dem_settings)
    write_csv_atomically(out / "engines.csv", table)
    write_csv_atomically(out / "numerics.csv", numerics)
    write_csv_atomically(out / "influence.csv", influence)
    write_csv_atomically(out / "held.csv", held)
    plot_engines(table, ENGINES_TOLERANCE, out / "engines")
    path = out / "engines.md"
    text = (
        engines_markdown(table, numerics, dem_arguments(dem_settings))
        + influence_markdown(influence)
        + held_markdown(held)
    )
    write_text_atomically(path, text)
    return path


def held_markdown(held: pd.DataFrame) -> str:
    """Load, then movement: du under a held load on the three solvers."""
    done = held[held["dem_failure"].fillna("") == ""]
    within = int((done["dem_over_static"].abs() <= ENGINES_TOLERANCE).sum())
    stiff = int((held["stiff_over_rigid"].abs() <= STIFF_TOLERANCE).sum())
    lines = [
        "## Load, then movement",
        "",
        "A live load or a backfill held while the right support settles (`loads.held_load_N`, "
        "`held_acceleration_g`, `fill_depth_mm` with its lateral coefficient K; docs/loads.md): du by the "
        f"static engine and the DEM at kn {ENGINES_KN:g} N/mm3 (the DEM within "
        f"{100 * ENGINES_TOLERANCE:g} % in {within} of {len(done)}), and by the static engine at kn "
        f"{STIFF_KN:g} beside the rigid march (within {100 * STIFF_TOLERANCE:g} % in {stiff} of {len(held)}). "
        f"The DEM's run folders are in {HELD_FOLDER}/.",
        "",
        *markdown_table(
            [
                "case",
                "held load",
                "static du (mm)",
                "DEM du (mm)",
                "DEM - static",
                "hinges static / DEM",
                "stiff static (mm)",
                "rigid (mm)",
                "stiff - rigid",
                "rigid hinges",
            ],
            (
                [
                    r.case.replace("_", " "),
                    _held_loads(r),
                    _number(r.static_du_mm),
                    _number(r.dem_du_mm),
                    _percent(r.dem_over_static),
                    f"{r.static_hinges} / {r.dem_hinges or r.dem_failure}",
                    _number(r.stiff_static_du_mm),
                    _number(r.rigid_du_mm),
                    _percent(r.stiff_over_rigid),
                    r.rigid_hinges,
                ]
                for r in held.fillna(
                    {"static_hinges": "", "dem_hinges": "", "dem_failure": "", "rigid_hinges": ""}
                ).itertuples()
            ),
        ),  # fmt: skip
        "",
    ]
    return "\n".join(lines)


def _held_loads(row: Any) -> str:
    """What a held-load row holds: its live load, its backfill, or both."""
    parts = [f"{row.held:g} {row.unit}"] if row.held else []
    if row.fill_mm:
        parts.append(f"{row.fill_mm:g} mm of fill (K {row.fill_K:g})")
    return ", ".join(parts)


def influence_table(paths: Path, jobs: int, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS) -> pd.DataFrame:
    """The paper's arch (kn 5.2): a concentrated load's capacity at INFLUENCE_POSITIONS of the span on
    both engines' paths (the DEM with `dem_settings`), side by side."""
    paper = paper_arch().with_overrides({"interface.kn_N_per_mm3": ENGINES_KN, "name": "paper"})
    where = tuple(k / (INFLUENCE_POSITIONS + 1) for k in range(1, INFLUENCE_POSITIONS + 1))
    static = static_influence_line(paper, where)
    dem = dem_influence_line(with_dem_settings(paper, dem_settings), where, paths, jobs)
    table = static[["position_over_span", "collapse_load_N", "first_loss_N", "hinges", "rigid_load_N"]].copy()
    table.columns = ["position_over_span", "static_N", "static_first_loss_N", "static_hinges", "rigid_N"]
    table["dem_N"], table["dem_first_loss_N"], table["dem_hinges"] = (
        dem["collapse_load_N"],
        dem["first_loss_N"],
        dem["hinges"],
    )
    table["dem_over_static"] = table["dem_N"] / table["static_N"] - 1.0
    return table


def influence_markdown(influence: pd.DataFrame) -> str:
    """The influence lines of the two engines, side by side."""
    within = int((influence["dem_over_static"].abs() <= ENGINES_TOLERANCE).sum())
    lines = [
        "## The influence line on both engines",
        "",
        f"The paper's arch at kn {ENGINES_KN:g} N/mm3, a concentrated load at {len(influence)} points of the span "
        f"(`yadearch loads --positions {len(influence)} --engine static|dem`): the DEM within "
        f"{100 * ENGINES_TOLERANCE:g} % of the static engine at {within} of {len(influence)}.",
        "",
        *markdown_table(
            ["position / span", "static (N)", "DEM (N)", "DEM - static", "hinges static", "hinges DEM", "rigid (N)"],
            (
                [
                    f"{r.position_over_span:.3f}",
                    _number(r.static_N),
                    _number(r.dem_N),
                    _percent(r.dem_over_static),
                    r.static_hinges,
                    r.dem_hinges,
                    _number(r.rigid_N),
                ]
                for r in influence.itertuples()
            ),
        ),  # fmt: skip
        "",
    ]
    return "\n".join(lines)


def _percent(value: float) -> str:
    return "-" if not math.isfinite(value) else f"{100.0 * value:+.2f} %"


def _number(value: float) -> str:
    return "-" if not math.isfinite(value) else f"{value:.4g}"


def engines_markdown(table: pd.DataFrame, numerics: pd.DataFrame, arguments: str = "") -> str:
    """The report: the two engines side by side, the agreement counted, and the DEM's numerics;
    `arguments` name the DEM's settings in its command."""
    words = {"static_hinges": "", "dem_hinges": "", "dem_failure": ""}  # a failed row has none
    table, numerics = table.fillna(words), numerics.fillna(words)
    done = table[table["dem_outcome"] != "failed"]
    within = int((done["dem_over_static"].abs() <= ENGINES_TOLERANCE).sum())
    first_within = int((done["first_loss_dem_over_static"].abs() <= ENGINES_TOLERANCE).sum())
    same_hinges = int((done["dem_hinges"] == done["static_hinges"]).sum())
    lines = [
        "# Live loads: the DEM against the static engine",
        "",
        "Each case's live load grown to collapse on both engines' paths, the same blocks and joints, the same",
        "increments (fractions of the rigid capacity), bracket and definitions (docs/loads.md). Regenerate with",
        f"`.venv/bin/python scripts/loads_engines.py --out reports/loads/engines{arguments}` (minutes of two",
        f"cores; the DEM runs' files are kept in {RUNS_FOLDER}/ and read back by a rerun: delete it to run them",
        "again).",
        "",
        f"- Collapse load within {100 * ENGINES_TOLERANCE:g} % in {within} of {len(done)} cases "
        f"(first loss of stability: {first_within} of {len(done)}); the same hinges in {same_hinges} of "
        f"{len(done)}; DEM runs failed: {len(table) - len(done)}.",
        "",
        *markdown_table(
            [
                "case",
                "kn (N/mm3)",
                "after (mm)",
                "static",
                "DEM",
                "DEM - static",
                "first loss static / DEM",
                "hinges static",
                "hinges DEM",
                "rigid",
            ],
            (
                [
                    r.case.replace("_", " "),
                    f"{r.kn_N_per_mm3:g}",
                    f"{r.after_mm:g}",
                    f"{_number(r.static_capacity)} {r.unit}",
                    f"{_number(r.dem_capacity)} {r.unit}",
                    _percent(r.dem_over_static),
                    f"{_number(r.static_first_loss)} / {_number(r.dem_first_loss)}",
                    r.static_hinges,
                    r.dem_hinges or r.dem_failure,
                    _number(r.rigid_capacity),
                ]
                for r in table.itertuples()
            ),
        ),  # fmt: skip
        "",
        "![DEM against the static engine](engines.png)",
        "",
        "## The DEM's numerics",
        "",
        f"On {', '.join(NUMERICS_CASES)}: "
        + ", ".join(f"{s} x {f:g}" for s, f in NUMERICS_VARIANTS)
        + " (the loading rate follows the support's):",
        "",
        *markdown_table(
            ["variant", "DEM", "against the default DEM", "against static", "hinges"],
            (
                [
                    r.case.replace("_", " "),
                    f"{_number(r.dem_capacity)} {r.unit}",
                    _percent(r.dem_capacity / _base(table, r.case) - 1.0),
                    _percent(r.dem_over_static),
                    r.dem_hinges or r.dem_failure,
                ]
                for r in numerics.itertuples()
            ),
        ),  # fmt: skip
        "",
    ]
    return "\n".join(lines)


def _base(table: pd.DataFrame, variant: str) -> float:
    """The default DEM capacity of the case a numerics variant was made from."""
    base = next(name for name in NUMERICS_CASES if variant.startswith(name))
    return float(table.loc[table["case"] == base, "dem_capacity"].iloc[0])
