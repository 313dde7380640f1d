"""A live load grown to collapse in YADE, the DEM's answer to `yadearch loads --engine dem`: the
self-weight, optionally the support movement to `after_mm`, then the live load's multiplier as the
equilibrium path's parameter with the supports held, by ramps each relaxed to equilibrium
(`dem.loading`), with the static engine's increments, bracket and definitions (`solve.load_path`)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import HELD_SETTINGS, held_multiplier, live_load
from yadearch.dem.live_load import LOAD_CALLBACK, LoadDriver
from yadearch.dem.loading import EquilibriumPath
from yadearch.dem.recorder import Records
from yadearch.dem.runner import Runner
from yadearch.dem.scene import install_before_integrator
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.model.joint_tangent import BLOCK_DOFS
from yadearch.model.loads import UNITS, block_loads, live_load_points, load_displacement
from yadearch.model.movement import Movement
from yadearch.results.summary import HingeRef
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import (
    LoadPath,
    check_carried,
    check_held,
    first_loss_multiplier,
    held_load_settings,
    load_scale,
    load_settings,
    rigid_answer,
)
from yadearch.solve.path import PathSettings, first_snap, path_settings
from yadearch.solve.stages import Stage, Verdict

DEM = "dem"
NOT_RECORDED = (0, 0, 0)  # the mark of an equilibrium the run's tables do not keep


class LoadedArch:
    """A live DEM scene whose path parameter is the live load's multiplier, the supports held (the
    `dem.loading.LiveArch` the equilibrium path drives); it records the load-displacement curve."""

    def __init__(self, runner: Runner, loads: np.ndarray, full_rate: float, recorded: bool = True):
        self.runner = runner
        self.driver = LoadDriver(runner.scene, loads)
        install_before_integrator(LOAD_CALLBACK, self.driver, self.driver.engine())
        self.full_rate = full_rate  # multiplier per second of the largest increment's ramp
        self.recorded = recorded  # its equilibria recorded in the run's tables (not while a run's load is set)
        self.loads = loads
        length = runner.scene.geometry.thickness  # the rotations' lever in the tangent (`model.stability`)
        self.force_norm = float(np.linalg.norm(np.column_stack([loads[:, 0:2], loads[:, 2] / length])))
        self._start = self.driver.contacts.poses.copy()
        self.curve: list[dict[str, float]] = [self._point()]  # the path's start, then each equilibrium

    # ---- the live scene, as the path sees it ----------------------------------------------
    @property
    def stage(self) -> Stage:
        return self.runner.stage

    @stage.setter
    def stage(self, value: Stage) -> None:
        self.runner.stage = value

    @property
    def case(self) -> ArchCase:
        return self.runner.case

    @property
    def movement(self) -> Movement:
        return self.runner.movement

    @property
    def recorder(self) -> LoadedArch:
        return self

    @property
    def hold_move(self) -> float:
        return self.runner.hold_move

    @property
    def total_steps(self) -> int:
        return self.runner.total_steps

    @property
    def log(self) -> Callable[[str], None]:
        return self.runner.log

    def smallest_stiffness(self) -> float:
        """The static tangent's smallest eigenvalue at the poses, the load's own stiffness included."""
        return self.runner.smallest_stiffness(self.driver.turning())

    def reach(self, increment: float) -> float:
        """A load increment moves the blocks quasi-statically at most by its generalised force over the
        last equilibrium's smallest stiffness (m; unbounded where that was not positive)."""
        softest = self.curve[-1]["min_stiffness_N_per_m"]
        return abs(increment) * self.force_norm / softest if softest > 0.0 else math.inf

    def static_distance(self) -> float | None:
        """How far the static model, the live load at the scene's multiplier, moves the blocks to a stable
        equilibrium (m; inf: none there), None where it is not the scene's model (`dem.static_check`):
        a hold is taken for an equilibrium only near one, as on a support's path."""
        check = self.runner.static_check
        return check.distance(self.runner.delta(), self.driver.multiplier) if check else None

    def delta(self) -> float:
        return self.driver.multiplier

    def snapshot(self) -> dict[str, Any]:
        return {"scene": self.runner.snapshot(), "multiplier": self.driver.multiplier}

    def restore(self, snapshot: dict[str, Any]) -> None:
        self.runner.restore(snapshot["scene"])
        self.driver.set(snapshot["multiplier"])

    def move_support(self, target: float, speed_fraction: float) -> None:
        """Ramp the live load to `target` (the supports held) at `speed_fraction` of the full rate."""
        self.driver.ramp_to(target, self.full_rate * speed_fraction)
        self.runner.drive(self.driver.reached)

    def positions(self) -> np.ndarray:
        """The voussoirs' centroids (n, 3; m) at the static model's stable equilibrium that the scene's state
        sits in, the scene's own where there is none: the path's trend and snap test compare equilibria,
        not holds within their force tolerance, which over the path's smallest stiffness near the peak is
        the snap floor's order (docs/loads.md, "The DEM against the static engine")."""
        scene = self.runner.positions()
        check = self.runner.static_check
        found = check.equilibrium(self.runner.delta(), self.driver.multiplier) if check else None
        if found is None:
            return scene
        settled = scene.copy()
        settled[:, 0:2] = found.u.reshape(-1, BLOCK_DOFS)[1:-1, 0:2]
        return settled

    def hold(
        self,
        runaway: float | None = None,
        max_s: float | None = None,
        from_rest: bool = True,
        still_speed: float | None = None,
        tolerance: float | None = None,
    ) -> Verdict:
        return self.runner.hold(runaway, max_s, from_rest, still_speed, tolerance)

    # ---- records: the runner's, and a point of the curve for each equilibrium ------------
    def record_equilibrium(self) -> tuple[tuple[int, int, int], list[Hinge]]:
        self.curve.append(self._point())
        return self.runner.recorder.record_equilibrium() if self.recorded else (NOT_RECORDED, [])

    def _point(self) -> dict[str, float]:
        """The load-displacement curve's point of the scene now (the static engine's columns, and the sums
        of the supports' reactions, which balance the weights and the live load in equilibrium)."""
        poses = self.driver.contacts.poses
        moved = load_displacement(self.loads, self._start[:, 0:2], self._start[:, 2], poses[:, 0:2], poses[:, 2])
        left, right = self.runner.recorder.reactions()
        return {
            "multiplier": self.driver.multiplier,
            "load_displacement_mm": units.to_mm(moved),
            "min_stiffness_N_per_m": self.smallest_stiffness(),
            "horizontal_reactions_N": float(left[0] + right[0]),  # the supports on the arch: its loads' balance
            "vertical_reactions_N": float(left[1] + right[1]),
        }

    def discard_since(self, mark: tuple[int, int, int]) -> None:
        if self.recorded:
            self.runner.recorder.discard_since(mark)
        self.curve.pop()

    def record_collapse(self) -> list[Hinge]:
        return self.runner.recorder.record_collapse()


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
    case: ArchCase, after_mm: float = 0.0, log: Callable[[str], None] = print
) -> tuple[LoadPath, Records, dict[str, Any] | None]:
    """The live load of `case` grown to collapse in YADE after the support movement to `after_mm`: the
    same answer as `solve.load_path.static_load_path` (its `iterations` the DEM's steps), the load
    path's records (series, joints, snapshots and states from the load's start, each with its load) and
    the arch's imperfections table (None for a perfect arch). CaseError as the static engine raises it."""
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
        hinges = loading.collapse_state(path.upper) if path.collapsed else []
    finally:
        runner.close()
    log(f"[{case.name}] {path.outcome} at {path.du if path.collapsed else path.lower:.5g} {unit}")
    labels = tuple(HingeRef.of(h).label for h in hinges)
    result = LoadPath(
        capacity=path.du if path.collapsed else float("nan"),
        first_loss=first_loss_multiplier(path, first_snap(loading.snaps)),
        outcome=path.outcome,
        unit=unit,
        hinges=labels,
        kind=None,
        curve=pd.DataFrame(arch.curve),
        after_mm=after_mm,
        reach=path.lower,
        iterations=runner.total_steps,
        engine=DEM,
        **rigid_answer(case, after_mm, at_rest),
    )
    defects = runner.scene.imperfections
    return result, runner.records, defects.table() if defects is not None else None


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
    return runner.live_multiplier


def _move_supports(runner: Runner, after_mm: float) -> None:
    """The support movement to `after_mm` along its path, which the arch must carry in equilibrium."""
    moving = EquilibriumPath(runner)
    moving.settings = path_settings(runner.case.numerics, after_mm)
    check_carried(moving.follow(), after_mm)
