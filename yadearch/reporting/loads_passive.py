"""reports/loads/passive: the fill's passive resistance in the three solvers, written as tables, a figure
and a Markdown report (`scripts/loads_passive.py`; minutes of YADE)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.markdown import markdown_table, text_cell
from yadearch.plotting.loads import plot_passive
from yadearch.reporting.passive_arches import arches_markdown
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, dem_arguments
from yadearch.studies.loads.passive import (
    FILLS_MM,
    LATERAL_COEFFICIENT,
    STIFF,
    SWEPT_KP,
    capacity_table,
    dem_numerics_table,
    grid_table,
    mobilisation_table,
    passive_case,
    settlement_numerics_table,
    settlement_pushes_table,
    settlement_table,
)
from yadearch.studies.loads.passive_arches import arches_numerics_table, arches_verdicts

ENGINES_TOLERANCE = 0.01  # static and DEM within 1 %
RIGID_TOLERANCE = 0.02  # the nearly rigid static engine within 2 % of the rigid LP
RUNS_FOLDER = "runs"  # the DEM's load paths and the settling runs, under the report's folder
ARCHES_FOLDER = "arches"  # the other arches' lean static campaign, under RUNS_FOLDER


def write_passive_report(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> Path:
    """Run the study (the DEM with `dem_settings`, `jobs` at a time; what OUT/runs holds is read back) and
    write capacities.csv, dem_numerics.csv, mobilisation.csv, settlement.csv, settlement_numerics.csv, grid.csv,
    arches_numerics.csv, passive.pdf/.png and passive.md into `out`; the report's path."""
    out.mkdir(parents=True, exist_ok=True)
    capacities = capacity_table(out / RUNS_FOLDER, jobs, log, dem_settings)
    numerics = dem_numerics_table(out / RUNS_FOLDER, jobs, log, dem_settings)
    mobilisation = mobilisation_table()
    settlement = settlement_table(out / RUNS_FOLDER, jobs, log, dem_settings)
    settling_numerics = settlement_numerics_table(out / RUNS_FOLDER, jobs, log, dem_settings)
    pushes = settlement_pushes_table()
    grid = grid_table()
    arches = arches_numerics_table(out / RUNS_FOLDER / ARCHES_FOLDER, jobs)
    tables = {
        "capacities": capacities,
        "dem_numerics": numerics,
        "mobilisation": mobilisation,
        "settlement": settlement,
        "settlement_numerics": settling_numerics,
        "settlement_pushes": pushes,
        "grid": grid,
        "arches_numerics": arches,
    }
    for name, table in tables.items():
        write_csv_atomically(out / f"{name}.csv", table)
    without = capacities.loc[capacities["case"] == passive_case("paper", 0.0).name, "static_N"].iloc[0]
    default_up = passive_case("paper", SWEPT_KP).loads.fill_passive_displacement_mm
    plot_passive(capacities[capacities["u_p_mm"] == default_up], mobilisation, float(without), out / "passive")
    path = out / "passive.md"
    text = passive_markdown(capacities, numerics, mobilisation, settlement, dem_arguments(dem_settings))
    text += pushes_markdown(pushes) + settling_numerics_markdown(settling_numerics) + grid_markdown(grid)
    text += arches_markdown(arches_verdicts(arches))
    write_text_atomically(path, text)
    return path


def passive_markdown(
    capacities: pd.DataFrame,
    numerics: pd.DataFrame,
    mobilisation: pd.DataFrame,
    settlement: pd.DataFrame,
    arguments: str = "",
) -> str:
    """The report: the capacities in the three solvers, the DEM's numerics varied, the mobilisation sweep,
    the settling arch; `arguments` name the DEM's settings in its command."""
    capacities = capacities.fillna({"dem_failure": "", "dem_hinges": ""})
    engines = capacities.dropna(subset=["dem_N"])
    within = int(((engines["dem_N"] / engines["static_N"] - 1.0).abs() <= ENGINES_TOLERANCE).sum())
    stiff_gap = capacities["stiff_static_N"] / capacities["rigid_N"] - 1.0
    checked = capacities.dropna(subset=["mechanism_N"])
    mechanism_gap = (checked["rigid_N"] / checked["mechanism_N"] - 1.0).abs().max()
    lines = [
        "# The fill's passive resistance in the three solvers",
        "",
        f"A point load through the fill (K {LATERAL_COEFFICIENT:g} at rest) on a 15-voussoir segmental arch "
        f"({FILLS_MM['small']:g} mm",
        "of fill, the load at 0.3 of the span, friction 80 deg) and on the paper's arch "
        f"({FILLS_MM['paper']:g} mm, the quarter span),",
        "with the fill's passive coefficient Kp 0 (none), 1 and 3 (docs/loads.md, \"The fill's passive",
        "resistance\"). The rigid blocks (the limit analysis's LP) mobilise each face's passive push up to its",
        "capacity; the static engine",
        "and the DEM push with a spring that reaches it after u_p = "
        f"{passive_case('paper', SWEPT_KP).loads.fill_passive_displacement_mm:g} mm of the face's movement into "
        "the fill.",
        f"Regenerate with `.venv/bin/python scripts/loads_passive.py --out reports/loads/passive{arguments}`",
        f"(minutes of two cores; the DEM's files are kept in {RUNS_FOLDER}/ and read back by a rerun).",
        "",
        f"- Static and DEM within {100 * ENGINES_TOLERANCE:g} % in {within} of {len(engines)} cases.",
        f"- The static engine nearly rigid (kn {STIFF['interface.kn_N_per_mm3']:g} N/mm³, u_p "
        f"{STIFF['fill_passive_displacement_mm']:g} mm) within {100 * RIGID_TOLERANCE:g} % of the rigid blocks in "
        f"{int(((stiff_gap > -RIGID_TOLERANCE) & (stiff_gap <= 0.0)).sum())} of {len(capacities)} (below it by "
        f"{_percent(-stiff_gap.max())} to {_percent(-stiff_gap.min())}).",
        f"- The LP against the mechanism method by virtual work (the small arch): largest gap {mechanism_gap:.1e}.",
        "",
        *markdown_table(
            [
                "case",
                "Kp",
                "u_p (mm)",
                "rigid blocks (N)",
                "hinges",
                "static nearly rigid (N)",
                "static kn 5.2 (N)",
                "kind",
                "DEM kn 5.2 (N)",
                "static / DEM hinges",
            ],  # fmt: skip
            (
                [
                    r.case.replace("_", " "),
                    f"{r.kp:g}",
                    f"{r.u_p_mm:g}",
                    f"{r.rigid_N:.3f}",
                    r.rigid_hinges,
                    f"{r.stiff_static_N:.3f}",
                    f"{r.static_N:.3f}",
                    r.static_kind,
                    _number(getattr(r, "dem_N", math.nan)) if not r.dem_failure else f"failed: {r.dem_failure}",
                    f"{r.static_hinges} / {r.dem_hinges}",
                ]
                for r in capacities.itertuples()
            ),
        ),
        "",
        f"## The DEM's numerics halved and doubled (the small arch, Kp {SWEPT_KP:g})",
        "",
        f"Largest move from the default: {_percent(numerics['relative_to_default'].abs().max())} "
        "(dem_numerics.csv). The DEM's capacity is the middle of its last bracket, from the largest load it",
        f"held to the first it lost ({_percent(_bracket(numerics))} of it wide at the default): a variant",
        "that holds and loses the same increments gives it to the bit.",
        "",
        *markdown_table(
            ["variant", "DEM (N)", "against the default", "hinges"],
            (
                [
                    r.variant.replace("_", " "),
                    _number(r.dem_N),
                    _percent(r.relative_to_default),
                    r.dem_hinges or r.dem_failure,
                ]  # fmt: skip
                for r in numerics.itertuples()
            ),
        ),
        "",
        f"## The mobilisation displacement (the paper's arch, Kp {SWEPT_KP:g}, static engine at kn 5.2)",
        "",
        "u_p is the fill's, not the solver's: how far a face moves into the fill to mobilise its whole passive",
        "pressure. The capacity falls as it grows, toward the arch without passive resistance (mobilisation.csv).",
        "",
        *markdown_table(
            ["u_p (mm)", "static (N)", "hinges", "rigid blocks (N)"],
            ([f"{r.u_p_mm:g}", f"{r.static_N:.3f}", r.hinges, f"{r.rigid_N:.3f}"] for r in mobilisation.itertuples()),
        ),
        "",
        "## The paper's arch settling under its fill",
        "",
        *markdown_table(
            ["case", "engine", "outcome", "du (mm)", "du_first (mm)", "hinges"],
            (
                [
                    r.case.replace("_", " "),
                    r.engine,
                    getattr(r, "outcome", ""),
                    _number(getattr(r, "du_mm", math.nan)),
                    _number(getattr(r, "du_first_mm", math.nan)),
                    text_cell(getattr(r, "hinges", "")) or text_cell(r.failure),
                ]  # fmt: skip
                for r in settlement.itertuples()
            ),
        ),
        "",
        "![passive](passive.png)",
        "",
    ]
    return "\n".join(lines)


def pushes_markdown(pushes: pd.DataFrame) -> str:
    """The fill's pushes along the static settlement at Kp 1: where they are largest and at the last
    state before collapse, with the faces that have yielded the fill by then."""
    largest, last = pushes.loc[pushes["pushes_N"].idxmax()], pushes.iloc[-1]

    def said(row: pd.Series) -> str:
        return (
            f"at {row.delta_mm:.2f} mm {int(row.faces_pushing)} faces push {row.pushes_N:.2f} N in all, "
            f"{int(row.faces_yielded)} have yielded the fill"
        )

    return "\n".join(
        [
            "",
            "The static engine's pushes along the settlement at Kp 1 (settlement_pushes.csv): largest "
            f"{said(largest)}; {said(last)} (the last state before du).",
            "",
        ]
    )


def settling_numerics_markdown(table: pd.DataFrame) -> str:
    """The settling arch at Kp 1 with each engine's numerics halved and doubled: du and du_first against
    that engine's default, and for each engine and quantity whether it stays within the 1 % a result needs."""
    rows, verdicts = [], []
    labels = [
        f"{e}, {p} states" if isinstance(p, str) and p else e for e, p in zip(table["engine"], table["path_states"])
    ]
    for engine, runs in table.groupby(pd.Series(labels, index=table.index), sort=False):
        default = runs[runs["variant"] == "default"].iloc[0]
        moves = {key: runs[key] / default[key] - 1.0 for key in ("du_mm", "du_first_mm")}
        for k, r in enumerate(runs.itertuples()):
            rows.append(
                [engine, r.variant, _number(r.du_mm), _percent(moves["du_mm"].iloc[k]), _number(r.du_first_mm),
                 _percent(moves["du_first_mm"].iloc[k]), text_cell(r.hinges) or text_cell(r.failure)]
            )  # fmt: skip
        for key, name in (("du_mm", "du"), ("du_first_mm", "du_first")):
            largest = float(moves[key].abs().max())
            said = "a result" if largest <= ENGINES_TOLERANCE else "not a result"
            verdicts.append(f"{engine} {name} {_percent(largest)} ({said})")
    lines = [
        "",
        "## The settling arch's numerics halved and doubled (Kp 1, settlement_numerics.csv)",
        "",
        "The largest move from each engine's default, a result staying within 1 %: " + "; ".join(verdicts) + ".",
        "",
        *markdown_table(["engine", "variant", "du (mm)", "du move", "du_first (mm)", "du_first move", "hinges"], rows),
        "",
    ]
    return "\n".join(lines)


def grid_markdown(grid: pd.DataFrame) -> str:
    """The static engine's grid over Kp, u_p and kn: how each test ended, and any error."""
    counts = grid.groupby(["test", "outcome"]).size()
    errors = grid[grid["outcome"] == "error"]
    lines = [
        "",
        "## The static engine over Kp, u_p and kn (grid.csv)",
        "",
        f"The paper's arch under its fill, Kp {', '.join(f'{k:g}' for k in sorted(grid['kp'].unique()))}, u_p "
        f"{', '.join(f'{u:g}' for u in sorted(grid['u_p_mm'].unique()))} mm, kn "
        f"{', '.join(f'{k:g}' for k in sorted(grid['kn_N_per_mm3'].unique()))} N/mm³, loaded at the quarter span and",
        "settling: "
        + "; ".join(f"{test} {outcome} {n}" for (test, outcome), n in counts.items())
        + f"; errors {len(errors)}.",
        *(f"- {r.test} Kp {r.kp:g} u_p {r.u_p_mm:g} kn {r.kn_N_per_mm3:g}: {r.error}" for r in errors.itertuples()),
        "",
    ]
    return "\n".join(lines)


def _bracket(numerics: pd.DataFrame) -> float:
    """The default DEM run's last bracket over its capacity: twice the gap from its largest held load."""
    default = numerics.iloc[0]
    return 2.0 * (default["dem_N"] - default["dem_held_N"]) / default["dem_N"]


def _number(value: float | None) -> str:
    return "" if value is None or not math.isfinite(value) else f"{value:.3f}"


def _percent(value: float) -> str:
    return "" if not math.isfinite(value) else f"{100 * value:.2f} %"
