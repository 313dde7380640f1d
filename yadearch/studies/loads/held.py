"""Load, then movement, on the three solvers (reports/loads/engines): a live load or a backfill held while
the support settles, du on the static engine, in the DEM (a run folder each, read back on a rerun) and
by the rigid march, with the static engine at stiff joints beside the rigid answer."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.case.held import held_multiplier
from yadearch.errors import YadearchError
from yadearch.launch.process import run_case_process
from yadearch.model import units
from yadearch.model.loads import UNITS
from yadearch.results.reuse import holds_case
from yadearch.results.rundir import read_summary
from yadearch.solve.limit import limit_analysis
from yadearch.solve.load_path import hold_the_live_load
from yadearch.solve.static_path import StaticLoading
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings
from yadearch.studies.loads.engines import ENGINES_KN
from yadearch.studies.loads.rigid import CHECK_FRICTION_DEG, paper_arch

STIFF_KN = 100_000.0  # N/mm3: the static engine beside rigid blocks
SMALL = {"n_voussoirs": 15, "friction_deg": CHECK_FRICTION_DEG, "live_load": "vertical", "load_position_over_span": 0.3}
PAPER_HELD_N = (2.0, 4.0, 6.0)  # held at the paper arch's quarter span
SMALL_HELD_N = (2.0, 4.0)  # held at 0.3 of the small arch's span
PAPER_HELD_G = 0.1  # an acceleration held on the paper's arch
PAPER_FILL_MM = 50.0  # backfill over the paper arch's crown (K 0: its weight alone)
SMALL_FILL_MM = 20.0  # over the small arch (K 0; with K 0.3 it stands beyond 150 mm)


def held_cases() -> list[ArchCase]:
    """The paper's arch with a point load held at its quarter span and an acceleration held, and the
    small segmental arch with a point load held at 0.3 of its span, all at kn 5.2 N/mm3."""
    paper = paper_arch().with_overrides({"interface.kn_N_per_mm3": ENGINES_KN})
    quarter = {"live_load": "vertical", "load_position_over_span": 0.25}
    cases = [paper.with_overrides({**quarter, "held_load_N": p, "name": f"paper_held_{p:g}N"}) for p in PAPER_HELD_N]
    cases.append(
        paper.with_overrides(
            {"live_load": "horizontal_acceleration", "held_acceleration_g": PAPER_HELD_G, "name": "paper_held_0.1g"}
        )
    )
    small = ArchCase(name="small").with_overrides({**SMALL, "interface.kn_N_per_mm3": ENGINES_KN})
    cases += [small.with_overrides({"held_load_N": p, "name": f"small_held_{p:g}N"}) for p in SMALL_HELD_N]
    unloaded = {"live_load": "none"}
    cases.append(
        paper.with_overrides({**unloaded, "fill_depth_mm": PAPER_FILL_MM, "name": f"paper_fill_{PAPER_FILL_MM:g}mm"})
    )
    cases.append(
        small.with_overrides({**unloaded, "fill_depth_mm": SMALL_FILL_MM, "name": f"small_fill_{SMALL_FILL_MM:g}mm"})
    )
    return cases


def static_du_mm(case: ArchCase) -> tuple[float, str]:
    """du (mm; NaN without collapse) and the collapse mode's hinges of `case` on the static engine."""
    loading = StaticLoading.of(case)
    loading.selfweight()
    if held_multiplier(case) > 0.0:
        hold_the_live_load(loading, case)
    path = loading.follow()
    if not path.collapsed:
        return math.nan, ""
    return units.to_mm(path.du), " ".join(loading.fold_mode(path.upper).labels)


def held_table(
    cases: list[ArchCase],
    out: Path,
    jobs: int = 2,
    log: Callable[[str], None] = print,
    dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS,
) -> pd.DataFrame:
    """Each case's du on the three solvers (the DEM's run folders in `out`, its runs with `dem_settings`,
    `jobs` at a time; those holding the run already are read back); a DEM run that fails is a row with its reason."""

    def row(case: ArchCase) -> dict:
        static, static_hinges = static_du_mm(case)
        stiff, _ = static_du_mm(case.with_overrides({"interface.kn_N_per_mm3": STIFF_KN}))
        rigid = limit_analysis(case, mirror=False)
        folder = out / case.name
        try:
            lean = {"numerics.engine": "dem", "numerics.run_files": "summary"}  # the summary is the evidence
            dem_case = with_dem_settings(case, dem_settings).with_overrides(lean)
            if not holds_case(folder, dem_case):
                run_case_process(dem_case, folder, quiet=True)
            dem = read_summary(folder)
            dem_du, dem_hinges, failure = dem.du_mm or math.nan, dem.hinge_labels, ""
        except YadearchError as exc:
            dem_du, dem_hinges, failure = math.nan, "", str(exc)
        log(f"{case.name}: static {static:.2f}, DEM {dem_du:.2f}, rigid {rigid.du_rigid_mm} mm")
        return {
            "case": case.name,
            "held": held_multiplier(case),
            "unit": UNITS.get(case.loads.live_load, ""),
            "fill_mm": case.loads.fill_depth_mm,
            "fill_K": case.loads.fill_lateral_coefficient,
            "static_du_mm": static,
            "static_hinges": static_hinges,
            "dem_du_mm": dem_du,
            "dem_hinges": dem_hinges,
            "dem_over_static": dem_du / static - 1.0,
            "stiff_static_du_mm": stiff,
            "rigid_du_mm": rigid.du_rigid_mm if rigid.du_rigid_mm is not None else math.nan,
            "rigid_hinges": " ".join(rigid.collapse_hinges),
            "stiff_over_rigid": stiff / rigid.du_rigid_mm - 1.0 if rigid.du_rigid_mm else math.nan,
            "dem_failure": failure,
        }

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return pd.DataFrame(list(pool.map(row, cases)))
