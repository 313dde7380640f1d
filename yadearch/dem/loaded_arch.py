"""A live DEM scene whose path parameter is the live load's multiplier, the supports held (YADE layer):
what the equilibrium path (`dem.loading`) drives for a load path, and the load-displacement curve it
records; past the peak the load can be driven by its own displacement (`drive_by_displacement`)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.dem.live_load import LOAD_CALLBACK, LoadDriver
from yadearch.dem.runner import Runner
from yadearch.dem.scene import install_before_integrator
from yadearch.dem.static_check import centroid_rates, centroid_rows
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.model.load_control import LoadSpring
from yadearch.model.loads import load_displacement
from yadearch.model.movement import Movement
from yadearch.solve import banded
from yadearch.solve.newton import Equilibrium
from yadearch.solve.stages import Stage, Verdict

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

    def yield_fill(self) -> None:
        """The blocks rest in an equilibrium of the load's path: the fill yields for good (`dem.dead_load`)."""
        self.runner.yield_fill()

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

    def branch_start(self) -> tuple[np.ndarray, np.ndarray | None]:
        """A branch's first state: the centroids as `path_positions` gives them, and how they move per unit of
        the load's multiplier from the static equilibrium the scene sits in (n, 3), its tangent's
        response K^-1 f, from which the static engine predicts a branch known by one state; no slope
        without that equilibrium or where K is singular. One static solve serves both."""
        found = self._equilibrium()
        if found is None:
            return self.runner.positions(), None
        check = self.runner.static_check
        assert check is not None  # an equilibrium is the check's
        arch = check.loading.arch
        try:
            growth = banded.solve(found.stiffness, arch.live_forces(found.u))
        except (np.linalg.LinAlgError, ValueError):
            return self._settled(found), None
        moved = np.zeros_like(found.u)
        moved[arch.free_dofs] = growth
        return self._settled(found), centroid_rates(moved)

    def drive_by_displacement(self, secant_ratio: float, rate: float) -> LoadSpring | None:
        """From now on the load is driven by its displacement through a spring `secant_ratio` x the path's
        secant stiffness here, its anchor moving at `rate` (m/s), placed so that nothing changes until
        the anchor moves (`model.load_control`); None where the load has not moved its points yet."""
        poses = self.driver.contacts.poses
        moved = self._load_displacement(poses)
        if not (moved > 0.0 and self.driver.multiplier > 0.0):
            return None
        stiffness = secant_ratio * self.driver.multiplier / moved
        spring = LoadSpring.holding(
            self.loads,
            self._start[:, 0:2],
            self._start[:, 2],
            poses,
            self.driver.multiplier,
            stiffness=stiffness,
            rate=rate,
        )
        self.driver.drive_by(spring)
        return spring

    def path_positions(self) -> np.ndarray:
        """The voussoirs' centroids (n, 3; m) at the static model's stable equilibrium that the scene's state
        sits in, the scene's own where there is none: the path's trend and snap test compare equilibria,
        not holds within their force tolerance, which over the path's smallest stiffness near the peak is
        the snap floor's order (docs/loads.md, "The DEM against the static engine")."""
        found = self._equilibrium()
        return self.runner.positions() if found is None else self._settled(found)

    def _equilibrium(self) -> Equilibrium | None:
        """The static model's stable equilibrium the scene sits in, with the live load at its multiplier."""
        check = self.runner.static_check
        return check.equilibrium(self.runner.delta(), self.driver.multiplier) if check else None

    def _settled(self, found: Equilibrium) -> np.ndarray:
        """The scene's centroids (n, 3) moved to the equilibrium `found`."""
        return centroid_rows(found.u, self.runner.positions().copy())

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
        moved = self._load_displacement(self.driver.contacts.poses)
        left, right = self.runner.recorder.reactions()
        return {
            "multiplier": self.driver.multiplier,
            "load_displacement_mm": units.to_mm(moved),
            "min_stiffness_N_per_m": self.smallest_stiffness(),
            "horizontal_reactions_N": float(left[0] + right[0]),  # the supports on the arch: its loads' balance
            "vertical_reactions_N": float(left[1] + right[1]),
        }

    def _load_displacement(self, poses: np.ndarray) -> float:
        """The live load's displacement along its forces from the path's start to `poses` (m)."""
        return load_displacement(self.loads, self._start[:, 0:2], self._start[:, 2], poses[:, 0:2], poses[:, 2])

    def discard_since(self, mark: tuple[int, int, int]) -> None:
        if self.recorded:
            self.runner.recorder.discard_since(mark)
        self.curve.pop()

    def record_collapse(self) -> list[Hinge]:
        return self.runner.recorder.record_collapse()
