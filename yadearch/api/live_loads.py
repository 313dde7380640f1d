"""The capacity of an arch to a live load (`ya.loads`): the rigid-block limit analysis's load
multiplier and mechanism (solve.load_lp), optionally written as OUT/NAME_loads.json."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

from yadearch.api.runs import as_case
from yadearch.atomic import write_text_atomically
from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry
from yadearch.case.names import check_name, output_path
from yadearch.plotting.load_figure import plot_load_collapse
from yadearch.solve.load_lp import LoadCapacity, load_analysis


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
