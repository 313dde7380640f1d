"""The DEM past the peak against the static engine's arc length (reports/loads/descent): each case's live
load driven past its limit point, in the DEM by its own displacement through a stiff spring
(`dem.load_descent`), on the static engine by arc length (`solve.descending`); every state the DEM holds
at rest set beside the static branch's load at the same displacement of the load, and the displacement
control's own numerics (the spring, the anchor's step) and the DEM's halved and doubled on one case."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.launch.load_process import run_load_process
from yadearch.model.load_control import DisplacementControl
from yadearch.results.load_path import stored_load_path
from yadearch.solve.descending import DESCEND_TO
from yadearch.solve.load_path import BRANCH, DESCENDING, static_load_path
from yadearch.solve.load_path_result import LoadPath
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings
from yadearch.studies.loads.engines import NUMERICS_VARIANTS, case_label, engine_cases, setting_value

DESCENT_CASES = (  # of `studies.loads.engines.engine_cases`: a small arch, the paper's under a point load at
    "segmental_point_0.3",  # both stiffnesses, and an acceleration
    "paper_quarter_span",
    "paper_quarter_span_set1",
    "semicircle_t60_acceleration",
    "paper_quarter_span_after_44mm",  # movement, then load: half the paper's du (87.99 mm) settled first
)
VARIED_CASE = DESCENT_CASES[0]  # the numerics halved and doubled on this one
CONTROL_VARIANTS = (
    ("spring_ratio", 0.5),
    ("spring_ratio", 2.0),
    ("step_thickness_ratio", 0.5),
    ("step_thickness_ratio", 2.0),
)
DEFAULT = "default"


@dataclass(frozen=True)
class DescentRun:
    """One load path past its peak on both engines: the static engine's case, the DEM's (the same with the
    study's DEM settings), its displacement control, and what is varied ("default")."""

    case: ArchCase
    dem_case: ArchCase
    control: DisplacementControl
    variant: str = DEFAULT
    name: str = ""  # the case varied (its own name where "")
    after_mm: float = 0.0  # the support's movement before the load

    @property
    def label(self) -> str:
        """The case the run varies, by name."""
        return self.name or self.case.name


def descent_runs(dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS) -> list[DescentRun]:
    """DESCENT_CASES at the default control, then VARIED_CASE with each control setting and each of the
    DEM's numerics (`studies.loads.engines.NUMERICS_VARIANTS`) halved and doubled; the DEM's cases with
    `dem_settings`, a varied numeric scaled from their value."""
    chosen = {case.name: (case, after_mm) for case, after_mm in engine_cases()}
    control = DisplacementControl(DESCEND_TO)
    runs = []
    for name in DESCENT_CASES:
        case, after_mm = chosen[name]
        runs.append(DescentRun(case, with_dem_settings(case, dem_settings), control, after_mm=after_mm))
    varied = chosen[VARIED_CASE][0]
    dem_varied = with_dem_settings(varied, dem_settings)
    for setting, factor in CONTROL_VARIANTS:
        changed = replace(control, **{setting: getattr(control, setting) * factor})
        runs.append(DescentRun(varied, dem_varied, changed, f"{setting}_x{factor:g}", VARIED_CASE))
    for setting, factor in NUMERICS_VARIANTS:
        variant = f"{setting.split('.')[-1]}_x{factor:g}"
        static, dem = (
            case.with_overrides({setting: setting_value(case, setting) * factor, "name": f"{varied.name}_{variant}"})
            for case in (varied, dem_varied)
        )
        runs.append(DescentRun(static, dem, control, variant, VARIED_CASE))
    return runs


def descent_tables(
    runs: list[DescentRun], out: Path, jobs: int = 2, log: Callable[[str], None] = print
) -> tuple[pd.DataFrame, pd.DataFrame, dict[str, tuple[LoadPath, LoadPath | None]]]:
    """Each run on both engines (the DEM its `dem_case`, files under `out`, one folder a control, `jobs` at a
    time; those already there are read back): a row a run, a row a DEM state past the peak with the static
    branch's load at its displacement, and the two engines' paths of each default run by its case in
    words (`engines.case_label`). A DEM run that fails is a row with its reason."""
    statics = {
        run.case.name: static_load_path(run.case, run.after_mm, descend_to=run.control.descend_to) for run in runs
    }

    def both(run: DescentRun) -> tuple[dict, pd.DataFrame, LoadPath | None]:
        static = statics[run.case.name]
        folder = out / _folder(run.control)
        try:
            dem = stored_load_path(folder, run.dem_case, run.after_mm) or run_load_process(
                run.dem_case, folder, run.after_mm, descent=run.control
            )
        except YadearchError as exc:
            return _row(run, static, None, pd.DataFrame(), str(exc)), pd.DataFrame(), None
        states = _states(run, static, dem)
        log(f"{run.label} ({run.variant}): past the peak {len(states)} DEM states, ends {dem.descent_end}")
        return _row(run, static, dem, states, ""), states, dem

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        done = list(pool.map(both, runs))
    paths = {  # by the case's name in words, the figure's panel titles
        case_label(run.case, run.after_mm): (statics[run.case.name], dem)
        for run, (_, _, dem) in zip(runs, done)
        if run.variant == DEFAULT
    }
    rows = pd.DataFrame([row for row, _, _ in done])
    return rows, pd.concat([states for _, states, _ in done], ignore_index=True), paths


def _folder(control: DisplacementControl) -> str:
    """The DEM's files of a displacement control: one folder each, so that a stored path is its own."""
    return f"spring{control.spring_ratio:g}_step{control.step_thickness_ratio:g}_to{control.descend_to:g}"


def _states(run: DescentRun, static: LoadPath, dem: LoadPath) -> pd.DataFrame:
    """The DEM's states past the peak, each with the static branch's load at its displacement (NaN past
    where the static branch first turns back: a snap-back, which displacement control jumps)."""
    past = dem.curve[dem.curve[BRANCH] == DESCENDING] if BRANCH in dem.curve else dem.curve.iloc[:0]
    displacement = past["load_displacement_mm"].to_numpy()
    on_static = static_branch_at(static.curve, displacement)
    return pd.DataFrame(
        {
            "case": run.label,
            "variant": run.variant,
            "load_displacement_mm": displacement,
            "dem_load": past["multiplier"].to_numpy(),
            "static_load": on_static,
            "dem_over_static": past["multiplier"].to_numpy() / on_static - 1.0,
        }
    )


def static_branch_at(curve: pd.DataFrame, displacement_mm: np.ndarray) -> np.ndarray:
    """The static curve's load past its peak at `displacement_mm`, up to where the load's displacement
    first turns back (NaN beyond, and before the peak)."""
    peak = int(np.argmax(curve["multiplier"]))
    branch = curve.iloc[peak:]
    x = branch["load_displacement_mm"].to_numpy()
    forward = np.diff(x) > 0.0
    reach = len(x) if forward.all() else int(np.argmin(forward)) + 1
    x, y = x[:reach], branch["multiplier"].to_numpy()[:reach]
    inside = (displacement_mm >= x[0]) & (displacement_mm <= x[-1])
    return np.where(inside, np.interp(displacement_mm, x, y), math.nan)


def _row(run: DescentRun, static: LoadPath, dem: LoadPath | None, states: pd.DataFrame, reason: str) -> dict:
    """The two engines past the peak for one run, as a table row."""
    off = states["dem_over_static"].abs() if len(states) else pd.Series(dtype=float)
    compared = off.dropna()
    return {
        "case": run.label,
        "variant": run.variant,
        "unit": static.unit,
        "static_capacity": static.capacity,
        "dem_capacity": dem.capacity if dem else math.nan,
        "static_end": static.descent_end,
        "dem_end": dem.descent_end if dem else "failed",
        "static_hinges": " ".join(static.descent_hinges),
        "dem_hinges": " ".join(dem.descent_hinges) if dem else "",
        "static_lowest": float(static.curve["multiplier"].iloc[-1]),
        "dem_lowest": float(dem.curve["multiplier"].iloc[-1]) if dem else math.nan,
        "dem_states": len(states),
        "compared": len(compared),
        "largest_off": float(compared.max()) if len(compared) else math.nan,
        "dem_steps": dem.iterations if dem else 0,
        "dem_failure": reason,
    }
