"""What a run records while it runs (YADE layer): time-series rows, per-interface rows, snapshots of
the block positions, and the largest mobilised friction and slip of the equilibrium states."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from yadearch.case.config import NumericsConfig
from yadearch.dem.driver import SupportDriver
from yadearch.dem.scene import ArchScene, body_states
from yadearch.errors import RunFailedError
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.results.joint_rows import friction_extremes, joint_rows, joint_snapshot, snapshot_entry
from yadearch.results.rundir import STIFFNESS_COLUMN
from yadearch.results.states import LOAD_COLUMN, state_entry
from yadearch.solve.stages import Stage

DISCARDED_STAGE = "discarded"  # rows of an accepted state that ran away while settling
RowMark = tuple[int, int, int]  # how many series rows, joints rows and states there were: where a state begins


@dataclass
class Records:
    """Everything the run folder gets: time series rows, per-interface rows, the block poses of each
    state of joints.csv, events, snapshots."""

    series: list[dict] = field(default_factory=list)
    joints: list[dict] = field(default_factory=list)
    states: list[dict] = field(default_factory=list)
    events: list[str] = field(default_factory=list)
    snapshots: dict[str, dict] = field(default_factory=dict)


class Recorder:
    """Reads the live scene into `records`; `stage` labels every row (docs/numerics.md lists them)."""

    def __init__(self, scene: ArchScene, driver: SupportDriver, numerics: NumericsConfig):
        self.scene = scene
        self.driver = driver
        self.num = numerics
        self.records = Records()
        self.stage = Stage.SELFWEIGHT
        self.turning: Callable[[], np.ndarray] | None = None  # a held live load's stiffness (`dem.load_ramp`)
        # the static tangent's smallest eigenvalue at the poses, the loads' stiffness included (the runner's)
        self.stiffness: Callable[[], float] = scene.contacts.smallest_stiffness
        self.load: Callable[[], tuple[float, str]] | None = None  # a live load's path: its multiplier now, unit
        self.friction: dict = {}
        self._last_series_iter = -(10**9)

    def voussoir_speeds(self) -> np.ndarray:
        return np.array([state.vel.norm() for state in self.scene.voussoir_states])

    def reactions(self) -> tuple[np.ndarray, np.ndarray]:
        """Forces the left and right supports exert on the arch (N)."""
        from yade import O

        left = -np.array(O.forces.f(self.scene.left_support))[:2]
        right = -np.array(O.forces.f(self.scene.right_support))[:2]
        return left, right

    def weight_carried_error(self, weight: float) -> float:
        """|sum of the supports' vertical reactions / the voussoirs' `weight` - 1| (0 in static equilibrium)."""
        left, right = self.reactions()
        return abs((left[1] + right[1]) / weight - 1.0)

    def selfweight_record(self, weight: float, unbalanced: float, steps: int, fill: float = 0.0) -> dict:
        """What the self-weight equilibrium is, for summary.json: its reactions, thrust and crown sag, and
        the backfill's weight `fill` (N) where there is one."""
        left, right = self.reactions()
        crown = self.scene.geometry.crown_voussoir
        crown_y = body_states(self.scene)[0][crown][1]
        return {
            "steps": steps,
            "unbalanced": unbalanced,
            "arch_weight_N": weight,
            "vertical_reaction_sum_N": float(left[1] + right[1]),
            "horizontal_reaction_sum_N": float(left[0] + right[0]),
            "thrust_N": float(abs(left[0])),
            "crown_settlement_mm": -units.to_mm(float(crown_y - self.scene.pos0[crown][1])),
            **({"fill_weight_N": fill} if fill else {}),
        }

    def series(self, force: bool = False, stability: bool = False) -> None:
        """Append a time-series row (every `series_every_steps` steps, or now with `force`); with
        `stability`, the state's smallest tangent stiffness too (an equilibrium state's row)."""
        from yade import O, utils

        if not force and O.iter - self._last_series_iter < self.num.series_every_steps:
            return
        self._last_series_iter = O.iter
        left, right = self.reactions()
        crown = self.scene.geometry.crown_voussoir
        crown_id = self.scene.body_ids[crown]
        crown_disp = np.array(O.bodies[crown_id].state.pos) - self.scene.pos0[crown]
        self.records.series.append(
            {
                "stage": self.stage,
                "step": O.iter,
                "time_s": O.time,
                "delta_mm": units.to_mm(self.driver.displacement()),
                **_load_column(self.load() if self.load else None),
                "left_Rx_N": left[0],
                "left_Ry_N": left[1],
                "right_Rx_N": right[0],
                "right_Ry_N": right[1],
                "crown_dx_mm": units.to_mm(crown_disp[0]),
                "crown_dy_mm": units.to_mm(crown_disp[1]),
                "kinetic_J": utils.kineticEnergy(),
                "unbalanced": self.scene.contacts.unbalanced(),
                "max_block_speed_mm_per_s": units.to_mm(float(self.voussoir_speeds().max())),
            }
        )
        if stability:
            self.records.series[-1][STIFFNESS_COLUMN] = self.stiffness()

    def joint_snapshot(self) -> tuple[dict, list[Hinge]]:
        """Per-interface state now, and its hinges (`results.joint_rows`)."""
        from yade import O

        pos, rot = body_states(self.scene)
        if not np.all(np.isfinite(pos)):
            raise RunFailedError(f"NaN in block positions at step {O.iter}")
        points, normal, shear = self.scene.contacts.joint_contacts()
        return joint_snapshot(
            self.scene.geometry,
            self.scene.pos0,
            pos,
            rot,
            points,
            normal,
            shear,
            self.scene.contacts.joint_slip(),
            self.scene.stiffness.tan_friction,
            self.scene.imperfections,
            self.num.hinge_rotation_mrad * 1e-3,
        )

    def joints(self, label: str | None = None) -> list[Hinge]:
        """Record every interface now (and, with a `label`, the block positions as a snapshot)."""
        snap, hinges = self.joint_snapshot()
        self.write_joints(snap, hinges, label)
        return hinges

    def write_joints(self, snap: dict, hinges: list[Hinge], label: str | None = None) -> None:
        """Append the rows of joints.csv for a `joint_snapshot`, and its snapshot under `label`."""
        from yade import O

        delta_mm = units.to_mm(self.driver.displacement())
        load = self.load() if self.load else None
        where = {"stage": self.stage, "step": O.iter, "delta_mm": delta_mm, **_load_column(load)}
        self.records.joints.extend(joint_rows(snap, where))
        self.records.states.append(state_entry(self.stage, O.iter, delta_mm, snap["pos"], snap["rot"], load))
        if label:
            self.records.snapshots[label] = snapshot_entry(snap, hinges, delta_mm, O.iter)

    def record_equilibrium(self) -> tuple[RowMark, list[Hinge]]:
        """Record the live scene as an equilibrium state of the path (a series row with its stability,
        every joint, the friction it mobilises); where its rows begin, and its hinges."""
        mark = (len(self.records.series), len(self.records.joints), len(self.records.states))
        self.series(force=True, stability=True)
        snap, hinges = self.joint_snapshot()
        self.write_joints(snap, hinges)
        self.track_friction(snap)
        return mark, hinges

    def discard_since(self, mark: RowMark) -> None:
        """Relabel the equilibrium rows recorded since `mark`: that state turned out not to be one."""
        for row in self.records.series[mark[0] :] + self.records.joints[mark[1] :] + self.records.states[mark[2] :]:
            if row["stage"] == Stage.EQUILIBRIUM:
                row["stage"] = DISCARDED_STAGE

    def record_collapse(self) -> list[Hinge]:
        """Record the collapse mechanism (every joint, the snapshot, a series row); its hinges."""
        hinges = self.joints(Stage.COLLAPSE)
        self.series(force=True)
        return hinges

    def track_friction(self, snap: dict) -> None:
        """Keep the largest mobilised friction and slip met in the equilibrium states, with their
        interfaces: friction can move du only where some joint slides."""
        friction_extremes(self.friction, snap, units.to_mm(self.driver.displacement()))


def _load_column(load: tuple[float, str] | None) -> dict[str, float]:
    """On a live load's path, its `load` (value, unit) as the rows give it (the static engine's column)."""
    return {} if load is None else {f"{LOAD_COLUMN}_{load[1]}": load[0]}
