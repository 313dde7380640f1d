"""The DEM against the static engine on live loads (reports/loads/engines): each case's load path on both
engines, capacities and first losses side by side, and the DEM's numerics halved and doubled on some
cases (a capacity the loading rate, damping or time step moves is not a result)."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.errors import YadearchError
from yadearch.launch.load_process import run_load_process
from yadearch.model.loads import VERTICAL
from yadearch.results.load_path import stored_load_path
from yadearch.solve.load_path import static_load_path
from yadearch.solve.load_path_result import LoadPath
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings
from yadearch.studies.loads.rigid import check_cases, paper_arch
from yadearch.studies.loads.static import PAPER_LOADS, QUARTER_SPAN

ENGINES_KN = 5.2  # N/mm3: the paper's set 2, where both engines are quick
SET1_KN = 0.25  # N/mm3: the paper's set 1, the softest joints
SETTLEMENTS_MM = (22.0, 44.0, 66.0)  # before the load: about 1/4, 1/2 and 3/4 of set 2's static du (87.99 mm)
FILLS_MM = (20.0, 50.0)  # backfill over the paper arch's crown under its quarter-span load
FILL_K = 0.3  # the fill's lateral pressure coefficient there
PAPER_NAMES = ("paper_quarter_span", "paper_mid_span", "paper_acceleration")  # of PAPER_LOADS, in order
NUMERICS_CASES = ("segmental_point_0.3", "semicircle_t60_acceleration")  # the DEM's numerics varied on these
NUMERICS_VARIANTS = (  # (setting, factor): the loading rate (it follows the support's), damping, time step
    ("numerics.support_rate_mm_per_s", 0.5),
    ("numerics.support_rate_mm_per_s", 2.0),
    ("numerics.damping", 0.5),
    ("numerics.damping", 2.0),
    ("numerics.timestep_safety", 0.5),  # doubled it would pass the critical step
)


def engine_cases() -> list[tuple[ArchCase, float]]:
    """The cases of the comparison and the settlement (mm) each is loaded after: the ten small arches of
    the rigid check and the paper's arch under its three loads at kn 5.2, the quarter-span load at kn
    0.25, after each settlement of SETTLEMENTS_MM and under each backfill of FILLS_MM."""
    cases = [(case.with_overrides({"interface.kn_N_per_mm3": ENGINES_KN}), 0.0) for case in check_cases()]
    paper = paper_arch()
    for overrides, name in zip(PAPER_LOADS.values(), PAPER_NAMES):
        cases.append((paper.with_overrides({**overrides, "name": name, "interface.kn_N_per_mm3": ENGINES_KN}), 0.0))
    quarter = {**PAPER_LOADS[QUARTER_SPAN], "interface.kn_N_per_mm3": ENGINES_KN}
    set1 = paper.with_overrides({**quarter, "name": "paper_quarter_span_set1", "interface.kn_N_per_mm3": SET1_KN})
    cases.append((set1, 0.0))
    for settled in SETTLEMENTS_MM:
        cases.append((paper.with_overrides({**quarter, "name": f"paper_quarter_span_after_{settled:g}mm"}), settled))
    for depth in FILLS_MM:
        filled = {**quarter, "fill_depth_mm": depth, "fill_lateral_coefficient": FILL_K}
        cases.append((paper.with_overrides({**filled, "name": f"paper_quarter_span_fill_{depth:g}mm"}), 0.0))
    return cases


def numerics_cases(cases: Iterable[tuple[ArchCase, float]]) -> list[tuple[ArchCase, float]]:
    """NUMERICS_CASES with each of NUMERICS_VARIANTS, named for it."""
    varied = []
    for case, after_mm in cases:
        if case.name in NUMERICS_CASES:
            for setting, factor in NUMERICS_VARIANTS:
                name = f"{case.name}_{setting.split('.')[-1]}_x{factor:g}"
                varied.append(
                    (case.with_overrides({setting: setting_value(case, setting) * factor, "name": name}), after_mm)
                )
    return varied


def setting_value(case: ArchCase, dotted: str) -> float:
    """The value of a case's setting named as `with_overrides` names it."""
    holder: object = case
    for part in dotted.split("."):
        holder = getattr(holder, part)
    assert isinstance(holder, float)
    return holder


def engines_table(
    cases: Iterable[tuple[ArchCase, float]],
    out: Path,
    jobs: int = 2,
    log: Callable[[str], None] = print,
    dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS,
) -> pd.DataFrame:
    """Each case's load path on the static engine and in the DEM with `dem_settings` (its files in `out`,
    `jobs` at a time; those `out` holds already are read back), one row each; a DEM run that fails is a row with its
    reason, and the others go on."""
    cases = list(cases)

    def both(item: tuple[ArchCase, float]) -> dict:
        case, after_mm = item
        try:
            static = static_load_path(case, after_mm, descend_to=None)  # the capacities alone
        except YadearchError as exc:
            log(f"{case.name}: the static engine failed: {exc}")
            return {"case": case.name, "label": case_label(case, after_mm), "after_mm": after_mm,
                    "static_outcome": "failed", "dem_outcome": "not run", "dem_failure": str(exc)}  # fmt: skip
        try:
            dem_case = with_dem_settings(case, dem_settings)
            dem = stored_load_path(out, dem_case, after_mm) or run_load_process(dem_case, out, after_mm)
            reason = ""
        except YadearchError as exc:
            dem, reason = None, str(exc)
        row = _row(case, after_mm, static, dem, reason)
        log(f"{case.name}: static {row['static_capacity']:.5g}, DEM {row['dem_capacity']:.5g} {static.unit}")
        return row

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return pd.DataFrame(list(pool.map(both, cases)))


def _row(case: ArchCase, after_mm: float, static: LoadPath, dem: LoadPath | None, reason: str) -> dict:
    """The two engines' answers for one case as a table row."""
    nan = math.nan
    return {
        "case": case.name,
        "label": case_label(case, after_mm),
        "kn_N_per_mm3": case.interface.kn_N_per_mm3,
        "after_mm": after_mm,
        "unit": static.unit,
        "static_outcome": static.outcome,
        "static_first_loss": static.first_loss,
        "static_capacity": static.capacity,
        "static_hinges": " ".join(static.hinges),
        "dem_outcome": dem.outcome if dem else "failed",
        "dem_first_loss": dem.first_loss if dem else nan,
        "dem_capacity": dem.capacity if dem else nan,
        "dem_hinges": " ".join(dem.hinges) if dem else "",
        "dem_over_static": dem.capacity / static.capacity - 1.0 if dem else nan,
        "first_loss_dem_over_static": dem.first_loss / static.first_loss - 1.0 if dem else nan,
        "dem_steps": dem.iterations if dem else 0,
        "rigid_capacity": static.rigid,
        "dem_failure": reason,
    }


def case_label(case: ArchCase, after_mm: float) -> str:
    """A case of `engine_cases` as a reader names it (the figures' rows and panels): the arch (the first
    word of its name), its live load, and what else it carries or went through (joints other than
    ENGINES_KN, a settlement before the load, backfill)."""
    family = case.name.split("_")[0]
    arch = "paper's arch" if family == "paper" else f"{family}, t {case.geometry.thickness_mm:g} mm"
    if case.loads.live_load == VERTICAL:
        width = case.loads.load_width_mm
        load = f"load at {case.loads.load_position_over_span:g} span" + (f", {width:g} mm wide" if width else "")
    else:
        load = case.loads.live_load.replace("_", " ")
    besides = [f"kn {case.interface.kn_N_per_mm3:g} N/mm\u00b3"] if case.interface.kn_N_per_mm3 != ENGINES_KN else []
    besides += [f"after {after_mm:g} mm settlement"] if after_mm else []
    besides += [f"{case.loads.fill_depth_mm:g} mm fill"] if case.loads.fill_depth_mm else []
    return f"{arch}: {load}" + "".join(f", {item}" for item in besides)


def dem_influence_line(base: ArchCase, positions: Iterable[float], out: Path, jobs: int = 2) -> pd.DataFrame:
    """A concentrated load's capacity (N) against its position over the span on the DEM's path (its
    load paths in `out`, `jobs` at a time; those `out` holds already are read back), with its first loss,
    hinges and the rigid capacity beside it, as `static.static_influence_line` gives the static engine's."""

    def at(x: float) -> dict:
        case = base.with_overrides(
            {"live_load": "vertical", "load_position_over_span": x, "name": f"{base.name}_at_{x:.4f}"}
        )
        try:
            path = stored_load_path(out, case, 0.0) or run_load_process(case, out)
        except YadearchError as exc:  # a failed point is a row with its reason; the others go on
            return {"position_over_span": x, "collapse_load_N": math.nan, "outcome": "failed", "failure": str(exc)}
        return {
            "position_over_span": x,
            "collapse_load_N": path.capacity,
            "first_loss_N": path.first_loss,
            "hinges": " ".join(path.hinges),
            "outcome": path.outcome,
            "rigid_load_N": path.rigid,
            "rigid_hinges": " ".join(path.rigid_hinges),
        }

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return pd.DataFrame(list(pool.map(at, positions)))
