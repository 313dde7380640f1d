"""The fill's passive resistance measured (reports/loads/passive; docs/loads.md): a small arch and the
paper's under a point load through their fill at Kp 0, 1 and 3 in the three solvers (the rigid LP,
its independent mechanism check, the static engine at the DEM's stiffness and nearly rigid, the DEM),
the static capacity against the spring's mobilisation displacement, and the paper's arch settling under
its fill with and without the passive resistance in both engines."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase, preset
from yadearch.case.numerics_section import SCENE_PATH_STATES, STATIC_ENGINE, STATIC_PATH_STATES
from yadearch.errors import YadearchError
from yadearch.launch.load_process import run_load_process
from yadearch.launch.process import run_case_process
from yadearch.model import units
from yadearch.model.passive_fill import REFERENCE_X
from yadearch.results.load_path import stored_load_path
from yadearch.results.reuse import holds_case
from yadearch.results.rundir import read_summary
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path
from yadearch.solve.load_path_result import LoadPath
from yadearch.solve.static_path import StaticLoading
from yadearch.static.simulate import simulate_static
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings
from yadearch.studies.loads.engines import ENGINES_KN, NUMERICS_VARIANTS, setting_value
from yadearch.studies.loads.held import SMALL
from yadearch.studies.loads.rigid import mechanism_check

PASSIVE_COEFFICIENTS = (0.0, 1.0, 3.0)  # Kp: none, about a third of a loose sand's, a dense sand's third
LATERAL_COEFFICIENT = 0.3  # K at rest, about 1 - sin(45 deg)
FILLS_MM = {"small": 20.0, "paper": 50.0}  # over each arch's crown
STIFF = {"interface.kn_N_per_mm3": 100_000.0, "fill_passive_displacement_mm": 0.001}  # nearly rigid-plastic
MOBILISATION_MM = (0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0)  # the spring's u_p swept on the paper's arch
SWEPT_KP = 1.0
SHORT_UP_MM = 0.1  # a short mobilisation: the pushes reach their capacity early (a case of each kind, both engines)
GRID_KP = (0.5, 1.0, 3.0, 10.0)  # the static engine's grid over the fill's and the joints' parameters
GRID_UP_MM = (0.001, 0.1, 1.0, 10.0)
GRID_KN = (0.25, 5.2, 10_000.0)
SETTLING_VARIANTS = {  # (settings scaled together, factor) of each engine on the settling arch
    "static": (
        (("numerics.first_increment_mm", "numerics.max_increment_mm"), 0.5),
        (("numerics.first_increment_mm", "numerics.max_increment_mm"), 0.25),
        (("numerics.runaway_thickness_ratio",), 0.5),
        (("numerics.runaway_thickness_ratio",), 2.0),
    ),
    "dem": (
        (("numerics.support_acceleration_mm_per_s2",), 0.5),
        (("numerics.support_acceleration_mm_per_s2",), 2.0),
        (("numerics.damping",), 0.5),
        (("numerics.damping",), 2.0),
    ),
}
SMALL_VOUSSOIRS = 15  # the mechanism method's search (C(joints, 4) x 16 mechanisms) on arches this small


def passive_case(arch: str, kp: float, **more: object) -> ArchCase:
    """The `arch` ('small': 15 voussoirs, a point at 0.3 of the span; 'paper': set 2 at the quarter span)
    under its fill (K 0.3) with the passive coefficient `kp`, at the DEM's stiffness unless `more` says."""
    loads = {"live_load": "vertical", "fill_depth_mm": FILLS_MM[arch], "fill_lateral_coefficient": LATERAL_COEFFICIENT}
    base = ArchCase(name="small").with_overrides(SMALL) if arch == "small" else preset("set2")
    overrides = {**loads, "load_position_over_span": 0.3 if arch == "small" else 0.25, "fill_passive_coefficient": kp}
    name = f"{arch}_fill_kp{kp:g}"
    return base.with_overrides({**overrides, "interface.kn_N_per_mm3": ENGINES_KN, "name": name, **more})


def capacity_table(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> pd.DataFrame:
    """A row an arch and Kp: the rigid LP's capacity and hinges, the mechanism method's (the small arch),
    the static engine's at kn 5.2 and nearly rigid, and the DEM's at kn 5.2 with `dem_settings` (its
    files under `out`, `jobs` at a time; those there already read back; a failure is its reason)."""
    cases = [passive_case(arch, kp) for arch in FILLS_MM for kp in PASSIVE_COEFFICIENTS]
    cases.append(passive_case("paper", 3.0, fill_passive_displacement_mm=SHORT_UP_MM, name="paper_fill_kp3_short"))

    def row(case: ArchCase) -> dict:
        rigid = load_analysis(case)
        static = static_load_path(case, descend_to=None)
        stiff = static_load_path(case.with_overrides(STIFF), descend_to=None)
        found = {
            "case": case.name,
            "kp": case.loads.fill_passive_coefficient,
            "u_p_mm": case.loads.fill_passive_displacement_mm,
            "rigid_N": rigid.multiplier,
            "rigid_hinges": rigid.hinge_labels,
            "mechanism_N": _mechanism(case),
            "stiff_static_N": stiff.capacity,
            "static_N": static.capacity,
            "static_first_loss_N": static.first_loss,
            "static_hinges": " ".join(static.hinges),
            "static_kind": static.kind,
        }
        path, failure = _dem_load_path(with_dem_settings(case, dem_settings), out)
        if path is None:
            return {**found, "dem_failure": failure}
        log(f"{case.name}: static {static.capacity:.3f} N, DEM {path.capacity:.3f} N")
        return {**found, "dem_N": path.capacity, "dem_hinges": " ".join(path.hinges), "dem_failure": ""}

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return pd.DataFrame(list(pool.map(row, cases)))


def dem_numerics_table(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> pd.DataFrame:
    """The small arch at Kp SWEPT_KP in the DEM (with `dem_settings`) with each of its numerics halved and
    doubled (the loading rate, damping, time step: `studies.loads.engines.NUMERICS_VARIANTS`): a row a
    variant, its capacity against the default's (files under `out`, read back when there)."""
    default = with_dem_settings(passive_case("small", SWEPT_KP), dem_settings)
    variants = [("default", default)]
    for setting, factor in NUMERICS_VARIANTS:
        variant = f"{setting.split('.')[-1]}_x{factor:g}"
        changed = {setting: setting_value(default, setting) * factor, "name": f"{default.name}_{variant}"}
        variants.append((variant, default.with_overrides(changed)))

    def row(item: tuple[str, ArchCase]) -> dict:
        variant, case = item
        path, failure = _dem_load_path(case, out)
        if path is None:
            return {"variant": variant, "dem_N": None, "dem_hinges": "", "dem_failure": failure}
        log(f"{case.name}: DEM {path.capacity:.3f} N")
        return {
            "variant": variant,
            "dem_N": path.capacity,
            "dem_held_N": path.reach,
            "dem_hinges": " ".join(path.hinges),
            "dem_failure": "",
        }

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        table = pd.DataFrame(list(pool.map(row, variants)))
    table["relative_to_default"] = table["dem_N"] / table["dem_N"].iloc[0] - 1.0
    return table


def mobilisation_table() -> pd.DataFrame:
    """The paper's arch at Kp SWEPT_KP: the static capacity (kn 5.2) for each u_p, beside the rigid LP's."""
    rigid = load_analysis(passive_case("paper", SWEPT_KP)).multiplier
    rows = []
    for u_p in MOBILISATION_MM:
        path = static_load_path(passive_case("paper", SWEPT_KP, fill_passive_displacement_mm=u_p), descend_to=None)
        rows.append({"u_p_mm": u_p, "static_N": path.capacity, "hinges": " ".join(path.hinges), "rigid_N": rigid})
    return pd.DataFrame(rows)


def _dem_load_path(case: ArchCase, out: Path) -> tuple[LoadPath | None, str]:
    """The DEM's load path of `case` (read back from `out` where it is there already, else run into it),
    or None and why it failed."""
    try:
        return stored_load_path(out, case, 0.0) or run_load_process(case, out), ""
    except YadearchError as exc:
        return None, str(exc)


def _mechanism(case: ArchCase) -> float | None:
    """The mechanism method's multiplier (`solve.mechanisms`), on arches small enough for its search."""
    if case.geometry.n_voussoirs > SMALL_VOUSSOIRS:
        return None
    return float(mechanism_check([case]).iloc[0]["mechanism_multiplier"])


def settlement_table(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> pd.DataFrame:
    """The paper's arch under its fill settling to collapse, without and with the passive resistance
    (Kp SWEPT_KP; and with u_p SHORT_UP_MM, the pushes at their capacity), on both engines (the DEM with
    `dem_settings`; run folders under `out`, `jobs` at a time; finished ones read back): a row a run."""
    settlings = [passive_case("paper", kp, live_load="none", name=f"paper_settling_kp{kp:g}") for kp in (0.0, SWEPT_KP)]
    settlings.append(
        passive_case(
            "paper", SWEPT_KP, live_load="none", fill_passive_displacement_mm=SHORT_UP_MM, name="paper_settling_short"
        )
    )
    runs = []
    for settling in settlings:
        for engine in ("static", "dem"):
            case = _on_engine(settling, engine, dem_settings)
            runs.append((case, out / f"{case.name}_{engine}"))
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return pd.DataFrame(list(pool.map(lambda run: _settling_row(run[0], run[1], log), runs)))


def settlement_numerics_table(
    out: Path, jobs: int = 2, log: Callable[[str], None] = print, dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> pd.DataFrame:
    """The settling arch at Kp SWEPT_KP with each engine's numerics halved and doubled (SETTLING_VARIANTS;
    the default's folders are settlement_table's; the DEM with `dem_settings`), the DEM's also with its
    path read the other way (`numerics.support_path_states`), `jobs` at a time: a row a run, its variant and
    the DEM's path reading named."""
    default = passive_case("paper", SWEPT_KP, live_load="none", name=f"paper_settling_kp{SWEPT_KP:g}")
    runs = []
    for engine, variants in SETTLING_VARIANTS.items():
        for states, base in _path_readings(_on_engine(default, engine, dem_settings)):
            runs.append((states, "default", base, out / f"{base.name}_{engine}"))
            for settings, factor in variants:
                variant = f"{'+'.join(s.split('.')[-1] for s in settings)} x{factor:g}"
                changed = {setting: setting_value(base, setting) * factor for setting in settings}
                name = f"{base.name}_{variant.replace('+', '_').replace(' ', '_')}"
                runs.append((states, variant, base.with_overrides({**changed, "name": name}), out / f"{name}_{engine}"))

    def row(run: tuple[str, str, ArchCase, Path]) -> dict:
        states, variant, case, folder = run
        return {"variant": variant, **_settling_row(case, folder, log), "path_states": states}

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return pd.DataFrame(list(pool.map(row, runs)))


def _on_engine(case: ArchCase, engine: str, dem_settings: Mapping[str, Any]) -> ArchCase:
    """`case` solved by `engine`, with the study's `dem_settings` where that is the DEM."""
    on_engine = case.with_overrides({"numerics.engine": engine})
    return on_engine if engine == STATIC_ENGINE else with_dem_settings(on_engine, dem_settings)


def _path_readings(case: ArchCase) -> list[tuple[str, ArchCase]]:
    """The DEM's path readings (`numerics.support_path_states`) of `case`, each with its case: its own,
    then the other, named for it ('': the static engine has no choice)."""
    if case.numerics.engine == STATIC_ENGINE:
        return [("", case)]
    own = case.numerics.path_states
    other = SCENE_PATH_STATES if own == STATIC_PATH_STATES else STATIC_PATH_STATES
    changed = {"numerics.support_path_states": other, "name": f"{case.name}_{other}_states"}
    return [(own, case), (other, case.with_overrides(changed))]


def _settling_row(case: ArchCase, folder: Path, log: Callable[[str], None]) -> dict:
    """The settling run of `case` in `folder` (read back where it is there and current): its outcome,
    du, du_first and hinges, or the reason it failed."""
    found = {"case": case.name, "kp": case.loads.fill_passive_coefficient, "engine": case.numerics.engine}
    try:
        if not holds_case(folder, case):
            run_case_process(case, folder, quiet=True)
        summary = read_summary(folder)
    except YadearchError as exc:
        return {**found, "failure": str(exc)}
    log(f"{case.name} ({case.numerics.engine}): du {summary.du_mm} mm")
    return {
        **found,
        "outcome": summary.path_outcome,
        "du_mm": summary.du_mm,
        "du_first_mm": summary.du_first_mm,
        "first_snap_move_mm": summary.snaps[0]["move_mm"] if summary.snaps else None,
        "hinges": summary.hinge_labels,
        "failure": "",
    }


def settlement_pushes_table() -> pd.DataFrame:
    """The paper's arch settling at Kp SWEPT_KP in the static engine: at each accepted state, how many
    faces push into the fill, their pushes in all (N) and how many have yielded it (reference moved)."""
    loading = StaticLoading.of(passive_case("paper", SWEPT_KP, live_load="none"))
    loading.selfweight()
    loading.follow()
    arch, rows = loading.arch, []
    for state in loading.accepted:
        pushes = arch.passive_forces(state.u, state.springs)[:, 0]
        references = arch.springs_or_unyielded(state.springs)[:, REFERENCE_X]
        rows.append(
            {
                "delta_mm": units.to_mm(state.lam),
                "faces_pushing": int(np.count_nonzero(pushes)),
                "pushes_N": float(np.abs(pushes).sum()),
                "faces_yielded": int(np.count_nonzero(references != arch.passive[:, REFERENCE_X])),
            }
        )
    return pd.DataFrame(rows)


def grid_table() -> pd.DataFrame:
    """The static engine on the paper's arch under its fill over GRID_KP x GRID_UP_MM x GRID_KN, loaded at
    the quarter span and settling (no run folder): a row a run, its outcome, answer, first loss and kind,
    or the error that stopped it (none should: a failure is never a collapse)."""
    rows = []
    for kp, u_p, kn in itertools.product(GRID_KP, GRID_UP_MM, GRID_KN):
        numbers = {"fill_passive_displacement_mm": u_p, "interface.kn_N_per_mm3": kn}
        found = {"kp": kp, "u_p_mm": u_p, "kn_N_per_mm3": kn}
        try:
            path = static_load_path(passive_case("paper", kp, **numbers), descend_to=None)
            rows.append({**found, "test": "load", "outcome": path.outcome, "answer": path.capacity,
                         "first_loss": path.first_loss, "kind": path.kind, "error": ""})  # fmt: skip
        except YadearchError as exc:
            rows.append({**found, "test": "load", "outcome": "error", "error": str(exc)})
        settling = passive_case("paper", kp, live_load="none", **numbers)
        try:
            summary = simulate_static(settling, None, log=lambda _line: None)
            rows.append({**found, "test": "settlement", "outcome": summary.path_outcome, "answer": summary.du_mm,
                         "first_loss": summary.du_first_mm, "kind": summary.collapse_kind, "error": ""})  # fmt: skip
        except YadearchError as exc:
            rows.append({**found, "test": "settlement", "outcome": "error", "error": str(exc)})
    return pd.DataFrame(rows)
