"""The capacity of an arch to a live load (`ya.loads`): the rigid-block limit analysis's load
multiplier and mechanism (solve.load_lp), optionally written as OUT/NAME_loads.json."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.api.runs import as_case
from yadearch.atomic import write_csv_atomically, write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry
from yadearch.case.names import check_name, output_path
from yadearch.errors import CaseError
from yadearch.plotting.load_figure import plot_load_collapse
from yadearch.plotting.loads import plot_influence
from yadearch.solve.load_lp import LoadCapacity, load_analysis
from yadearch.solve.rigid import rigid_arch
from yadearch.studies.loads import influence_line


def loads(case: ArchCase | str, out: str | Path | None = None) -> LoadCapacity:
    """The live load (`case.loads`) the arch carries at collapse, its self-weight held: the multiplier
    in N (a vertical load) or g (a horizontal acceleration), the mechanism's hinges; no YADE, under a
    second. With `out`, writes OUT/NAME_loads.json (the result and the case) and the collapse's
    figure OUT/NAME_loads.pdf/.png (`plotting.load_figure`)."""
    case = as_case(case)
    check_name(case.name, "case.name")
    folder = output_path(out, "out") if out is not None else None
    result = load_analysis(case)
    if folder is not None:
        write_text_atomically(loads_file(case, folder), json.dumps(load_json(result, case), indent=1) + "\n")
        if math.isfinite(result.multiplier):
            plot_load_collapse(case, arch_geometry(case), result, folder / f"{case.name}_loads")
    return result


def loads_file(case: ArchCase, out: str | Path) -> Path:
    """Where `loads(..., out=out)` writes."""
    return Path(out) / f"{case.name}_loads.json"


def load_json(result: LoadCapacity, case: ArchCase) -> dict[str, Any]:
    """The result as summary.json-like fields, with the case that gave it."""
    finite = math.isfinite(result.multiplier)
    return {
        "name": case.name,
        "live_load": case.loads.live_load,
        "collapse_multiplier": result.multiplier if finite else None,
        "unit": result.unit,
        "outcome": "collapse" if finite else ("cannot stand" if math.isnan(result.multiplier) else "no collapse"),
        "arch_weight_N": result.arch_weight_N,
        "hinges_at_collapse": [p.label for p in result.pivots],
        "case": case.to_dict(),
    }


POSITIONS_RANGE = (2, 200)  # positions of an influence line across the span


def load_influence(case: ArchCase | str, positions: int = 19, out: str | Path | None = None) -> pd.DataFrame:
    """The influence line of `case`'s arch: a concentrated vertical load's capacity (N) at `positions`
    points evenly across the span (k / (positions + 1)), with each mechanism's hinges; with `out`,
    OUT/NAME_influence.csv and its figure OUT/NAME_influence.pdf/.png."""
    low, high = POSITIONS_RANGE
    if isinstance(positions, bool) or not isinstance(positions, int) or not low <= positions <= high:
        raise CaseError(f"positions must be an integer in [{low}, {high}], got {positions!r}")
    case = as_case(case)
    check_name(case.name, "case.name")
    folder = output_path(out, "out") if out is not None else None
    table = influence_line(case, tuple(k / (positions + 1) for k in range(1, positions + 1)))
    if folder is not None:
        write_csv_atomically(folder / f"{case.name}_influence.csv", table)
        weight = float(rigid_arch(case).weight[1:-1].sum())
        plot_influence(table, weight, folder / f"{case.name}_influence")
    return table
