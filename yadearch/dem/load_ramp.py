"""A live load grown to collapse in YADE, the DEM's answer to `yadearch loads --engine dem`: the
self-weight, optionally the support movement to `after_mm`, then the live load's multiplier as the
equilibrium path's parameter with the supports held, by ramps each relaxed to equilibrium
(`dem.loading`), with the static engine's increments, bracket and definitions (`solve.load_path`);
past the limit point, optionally, the descending branch under displacement control (`dem.load_descent`)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.case.held import HELD_SETTINGS, held_multiplier
from yadearch.case.mechanics import live_load
from yadearch.dem.load_descent import DemDescent, dem_descent
from yadearch.dem.loaded_arch import LoadedArch
from yadearch.dem.loading import EquilibriumPath
from yadearch.dem.recorder import Records
from yadearch.dem.runner import Runner
from yadearch.errors import CaseError, YadearchError
from yadearch.model.load_control import DisplacementControl
from yadearch.model.loads import UNITS, block_loads, live_load_points
from yadearch.results.summary import HingeRef
from yadearch.solve.descending import DescentEnd
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import (
    BRANCH,
    branches,
    check_carried,
    check_held,
    first_loss_multiplier,
    held_load_settings,
    load_scale,
    load_settings,
    rigid_answer,
)
from yadearch.solve.load_path_result import LoadPath
from yadearch.solve.path import PathSettings, first_snap, path_settings
from yadearch.solve.stages import Stage

DEM = "dem"


def scene_live_loads(runner: Runner) -> np.ndarray:
    """The case's live load of multiplier 1 on the scene's blocks (n_blocks, 4; `model.loads`), about
    the bodies' own centroids and with their own weights (an acceleration pushes each by its weight)."""
    scene = runner.scene
    centroids = scene.pos0[:, 0:2]
    weight = np.array([state.mass for state in scene.states]) * runner.case.loading.gravity_m_per_s2
    points = live_load_points(scene.geometry, centroids, weight, live_load(runner.case, scene.geometry))
    return block_loads(points, centroids, len(weight))


def ramp_rate(case: ArchCase, settings: PathSettings) -> float:
    """The load's ramp rate (multiplier per second): its largest increment ramps as long as the largest
    support increment moves at the support speed."""
    return settings.max_increment * case.support_speed_mm_per_s / case.numerics.max_increment_mm


def dem_load_path(
    case: ArchCase,
    after_mm: float = 0.0,
    log: Callable[[str], None] = print,
    descent: DisplacementControl | None = None,
) -> tuple[LoadPath, Records, dict[str, Any] | None]:
    """The live load of `case` grown to collapse in YADE after the support movement to `after_mm`: the same
    answer as `solve.load_path.static_load_path` (its `iterations` the DEM's steps), past a collapse's
    limit point the descending branch under `descent`'s displacement control (None: not traced), the
    load path's records (series, joints, snapshots and states from the load's start, each with its load)
    and the arch's imperfections table (None for a perfect arch). CaseError as the static engine raises
    it."""
    at_rest = load_analysis(case)  # refuses a case without a live load
    scale = load_scale(at_rest)
    settings = load_settings(scale, case.numerics.increment_growth)
    unit = UNITS[case.loads.live_load]
    runner = Runner(case, log=log)
    try:
        runner.selfweight()
        if after_mm > 0.0:
            _move_supports(runner, after_mm)
        arch = LoadedArch(runner, scene_live_loads(runner), ramp_rate(case, settings))
        runner.recorder.stiffness = arch.smallest_stiffness  # series.csv's stiffness with the live load's
        runner.position = lambda: f"load={arch.driver.multiplier:7.4g} {unit}"
        start = Stage.SELFWEIGHT if after_mm == 0.0 else Stage.EQUILIBRIUM
        _record_from_here(runner, lambda: (arch.driver.multiplier, unit), start)
        loading = EquilibriumPath(arch, settings, unit)
        path = loading.follow()
        past = _descent(loading, arch, path.du, descent) if path.collapsed and descent is not None else None
        hinges = loading.collapse_state(path.upper) if path.collapsed else []
    finally:
        runner.close()
    log(f"[{case.name}] {path.outcome} at {path.du if path.collapsed else path.lower:.5g} {unit}")
    labels = tuple(HingeRef.of(h).label for h in hinges)
    curve = pd.DataFrame(arch.curve)
    if past is not None:
        curve[BRANCH] = branches(curve["multiplier"].to_numpy())
    result = LoadPath(
        capacity=path.du if path.collapsed else float("nan"),
        first_loss=first_loss_multiplier(path, first_snap(loading.snaps)),
        outcome=path.outcome,
        unit=unit,
        hinges=labels,
        kind=None,
        curve=curve,
        after_mm=after_mm,
        reach=path.lower,
        iterations=runner.total_steps,
        engine=DEM,
        **rigid_answer(case, after_mm, at_rest),
        descent_end=str(past.end) if past is not None else "",
        descent_hinges=past.hinges if past is not None else (),
    )
    defects = runner.scene.imperfections
    return result, runner.records, defects.table() if defects is not None else None


def _descent(loading: EquilibriumPath, arch: LoadedArch, capacity: float, control: DisplacementControl) -> DemDescent:
    """The branch past the peak (`dem.load_descent`); one the run cannot go on with ends `lost`, logged,
    and the capacity already bracketed stands."""
    try:
        return dem_descent(loading, arch, capacity, control)
    except YadearchError as exc:
        arch.log(f"[{arch.case.name}] past the peak: {exc}")
        return DemDescent(DescentEnd.LOST, ())


def _record_from_here(runner: Runner, load: Callable[[], tuple[float, str]], stage: Stage) -> None:
    """Start the run's records afresh at the live load's start (the self-weight and the movement before it
    are the path's origin, as the static engine's load path keeps them), each row and state with its
    `load`, the start recorded as the path's first state under `stage`."""
    runner.recorder.records = Records()
    runner.recorder.load = load
    runner.stage = stage
    runner.recorder.record_equilibrium()


def hold_the_live_load(runner: Runner) -> float:
    """Grow the case's live load on the load path to the value the run holds while its support moves
    (`case.mechanics.held_multiplier`), and keep it on the scene (load, then movement); the value.
    CaseError, as the static engine's, if the arch does not carry it."""
    case = runner.case
    settings = held_load_settings(case)
    unit = UNITS[case.loads.live_load]
    arch = LoadedArch(runner, scene_live_loads(runner), ramp_rate(case, settings), recorded=False)
    moving_position = runner.position
    runner.position = lambda: f"load={arch.driver.multiplier:7.4g} {unit}"
    loading = EquilibriumPath(arch, settings, unit)
    check_held(loading.follow(), case)
    if not loading.settle():  # the movement starts from a state at rest, as from the self-weight's
        raise CaseError(f"loads.{HELD_SETTINGS[case.loads.live_load]}: the held load's state ran away while settling")
    runner.position = moving_position
    runner.recorder.turning = arch.driver.turning  # the stability test and series.csv count its stiffness
    runner.live_multiplier = held_multiplier(case)  # ... and the static check its load
    runner.stage = Stage.EQUILIBRIUM  # the loaded arch before its support moves: the path's first state
    runner.recorder.record_equilibrium()
    return runner.live_multiplier


def _move_supports(runner: Runner, after_mm: float) -> None:
    """The support movement to `after_mm` along its path, which the arch must carry in equilibrium."""
    moving = EquilibriumPath(runner)
    moving.settings = path_settings(runner.case.numerics, after_mm)
    check_carried(moving.follow(), after_mm)
