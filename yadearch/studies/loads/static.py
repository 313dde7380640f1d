"""The static engine's live-load paths in the validation study (reports/loads): stiff joints against the
rigid-block capacity, the paper's arch at its own stiffness, and the residual capacity after a
settlement, each beside the rigid answer of the same state (solve.load_path, solve.load_lp)."""

from __future__ import annotations

from collections.abc import Iterable

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.solve.load_path import static_load_path

STIFF_KNS = (10_000.0, 100_000.0)  # N/mm3: stiff joints, the stiffest a case accepts standing for rigid blocks
QUARTER_SPAN = "point load at 0.25 of the span"
PAPER_LOADS: dict[str, dict[str, object]] = {
    QUARTER_SPAN: {"live_load": "vertical", "load_position_over_span": 0.25},
    "point load at mid-span": {"live_load": "vertical", "load_position_over_span": 0.5},
    "horizontal acceleration": {"live_load": "horizontal_acceleration"},
}


def static_row(case: ArchCase, after_mm: float = 0.0) -> dict:
    """One static load path as a table row, with the rigid answer of the same state."""
    path = static_load_path(case, after_mm, descend_to=None)  # the capacity alone
    return {
        "case": case.name,
        "kn_N_per_mm3": case.interface.kn_N_per_mm3,
        "after_mm": after_mm,
        "unit": path.unit,
        "outcome": path.outcome,
        "static_first_loss": path.first_loss,
        "static_capacity": path.capacity,
        "static_hinges": " ".join(path.hinges),
        "collapse_kind": path.kind,
        "rigid_capacity": path.rigid,
        "rigid_hinges": " ".join(path.rigid_hinges),
        "static_over_rigid": path.capacity / path.rigid - 1.0,
        "iterations": path.iterations,
    }


def stiff_check(cases: Iterable[ArchCase]) -> pd.DataFrame:
    """Each case with joints of each of STIFF_KNS on the static path beside its rigid-block capacity."""
    return pd.DataFrame(
        [static_row(case.with_overrides({"interface.kn_N_per_mm3": kn})) for case in cases for kn in STIFF_KNS]
    )


def paper_cases(paper: ArchCase) -> list[ArchCase]:
    """The paper's arch under each of PAPER_LOADS, named for its load."""
    return [paper.with_overrides({**o, "name": f"{paper.name} {what}"}) for what, o in PAPER_LOADS.items()]


def paper_loads(paper: ArchCase, stiffnesses: Iterable[float]) -> pd.DataFrame:
    """The paper's arch under each of PAPER_LOADS at each stiffness (N/mm3)."""
    rows = []
    for kn in stiffnesses:
        for what, overrides in PAPER_LOADS.items():
            case = paper.with_overrides({**overrides, "interface.kn_N_per_mm3": kn})
            rows.append({"load": what, **static_row(case)})
    return pd.DataFrame(rows)


def residual_paths(base: ArchCase, settlements_mm: Iterable[float]) -> pd.DataFrame:
    """The live load of `base` after its support movement to each settlement (mm), on the static path."""
    return pd.DataFrame([static_row(base, at) for at in settlements_mm])


def backfill_capacities(
    paper: ArchCase, depths_mm: Iterable[float], coefficients: Iterable[float], stiffnesses: Iterable[float]
) -> pd.DataFrame:
    """A point load at the quarter span of the paper's arch under each backfill (depth over the crown,
    lateral coefficient), on the static path at each stiffness beside the rigid capacity."""
    rows = []
    for depth in depths_mm:
        for coefficient in coefficients:
            for kn in stiffnesses:
                case = paper.with_overrides(
                    {**PAPER_LOADS[QUARTER_SPAN], "fill_depth_mm": depth, "fill_lateral_coefficient": coefficient,
                     "interface.kn_N_per_mm3": kn}
                )  # fmt: skip
                rows.append({"fill_depth_mm": depth, "fill_lateral_coefficient": coefficient, **static_row(case)})
    return pd.DataFrame(rows)


def static_influence_line(base: ArchCase, positions: Iterable[float]) -> pd.DataFrame:
    """A concentrated load's capacity (N) against its position over the span on the static path, with
    its first loss of stability, hinges and the rigid capacity beside it."""
    rows = []
    for x in positions:
        case = base.with_overrides({"live_load": "vertical", "load_position_over_span": x})
        path = static_load_path(case, descend_to=None)  # the capacity alone
        rows.append(
            {"position_over_span": x, "collapse_load_N": path.capacity, "first_loss_N": path.first_loss,
             "hinges": " ".join(path.hinges), "outcome": path.outcome, "rigid_load_N": path.rigid,
             "rigid_hinges": " ".join(path.rigid_hinges)}
        )  # fmt: skip
    return pd.DataFrame(rows)
