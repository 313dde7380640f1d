"""What a static run records (no YADE): the rows of series.csv and joints.csv and the snapshots of its
states, in the DEM's columns (docs/usage.md, "The run folder"), so that every reader takes both; and
the same records of a live load's path (its states' parameter the load's multiplier)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.model.joint_law import unbalanced_force
from yadearch.results.joint_rows import (
    friction_extremes,
    joint_rows,
    joint_snapshot,
    mobilised_friction,
    snapshot_entry,
)
from yadearch.results.rundir import STIFFNESS_COLUMN
from yadearch.results.states import LOAD_COLUMN, state_entry
from yadearch.solve.stages import Stage
from yadearch.solve.static_state import StaticState
from yadearch.solve.statics import StaticArch, static_arch

if TYPE_CHECKING:
    from yadearch.solve.load_path_result import LoadPath  # a live load's records only

# numerics of the DEM that a static run does not use: time stepping, damping, holds, the support's speed
DEM_ONLY_NUMERICS = (
    "support_rate_mm_per_s",
    "rate_reference_kn_N_per_mm3",
    "support_acceleration_mm_per_s2",
    "support_horizontal_acceleration_mm_per_s2",
    "damping",
    "hold_damping",
    "timestep_safety",
    "threads",
    "contact_model",
    "equilibrium_tolerance",
    "gravity_ramp_periods",
    "selfweight_max_s",
    "hold_max_s",
    "hold_min_s",
    "still_speed_mm_per_s",
    "settle_speed_mm_per_s",
    "series_every_steps",
    "max_steps",
    "support_path_states",
)


def dem_only_keys(keys: Iterable[str]) -> list[str]:
    """The parameters of `keys` (bare or `section.name`) that only the DEM reads (DEM_ONLY_NUMERICS)."""
    return [key for key in keys if key.split(".")[-1] in DEM_ONLY_NUMERICS]


@dataclass
class StaticRecords:
    """Rows and snapshots of one static run, added state by state (a lean run keeps only what its
    summary reads: the friction extremes; its hinges are asked for, `hinges`)."""

    arch: StaticArch
    hinge_threshold: float  # rad
    keep_tables: bool = True  # rows of series.csv and joints.csv, the states and their stiffness
    held: float = 0.0  # the live load's multiplier held during the movement (N or g; 0: none)
    # a live load's path: each state's `lam` is the load's multiplier in this unit (N or g), the supports
    # held at `after_mm`; "": the supports' path, `lam` their displacement
    load_unit: str = ""
    after_mm: float = 0.0
    series: list[dict[str, Any]] = field(default_factory=list)
    joints: list[dict[str, Any]] = field(default_factory=list)
    snapshots: dict[str, dict[str, Any]] = field(default_factory=dict)
    states: list[dict[str, Any]] = field(default_factory=list)
    friction: dict[str, Any] = field(default_factory=dict)
    iterations: int = 0
    step: int = 0  # the last recorded state's `step`: the Newton iterations so far, at least one more a state

    def add(self, state: StaticState, label: str | None = None) -> None:
        """Record `state`: where the run keeps its tables, a series row, its joints and the snapshot
        under `label`; an equilibrium's friction extremes always (the summary's `friction`)."""
        self.iterations += state.iterations
        # a state its predictor reached without an iteration still has a step of its own (the tables key on it)
        self.step = max(self.step + 1, self.iterations)
        delta_mm = self.after_mm if self.load_unit else units.to_mm(state.lam)
        load = (state.lam, self.load_unit) if self.load_unit else None
        f = state.forces
        if self.keep_tables:
            pos, rot = self.arch.poses(state.u)
            snap, hinges = self._snapshot(state, pos, rot)
            common = {"stage": state.stage, "step": self.step, "delta_mm": delta_mm}
            if load is not None:
                common[f"{LOAD_COLUMN}_{self.load_unit}"] = state.lam
            self.series.append({**common, **self.series_columns(state, pos)})
            self.joints.extend(joint_rows(snap, common))
            self.states.append(state_entry(state.stage, self.step, delta_mm, pos, rot, load))
            if label:
                self.snapshots[label] = snapshot_entry(snap, hinges, delta_mm, self.step)
        if state.stage == Stage.EQUILIBRIUM:
            use = mobilised_friction(f.normal_force, f.shear_force, self.arch.law.tan_friction)
            friction_extremes(self.friction, {"friction_use": use, "slip": state.slip}, delta_mm)

    def hinges(self, state: StaticState) -> list[Hinge]:
        """The hinges of `state` (a lean run's joint snapshot is made only for the states whose hinges
        its summary reads)."""
        return self._snapshot(state, *self.arch.poses(state.u))[1]

    def _snapshot(self, state: StaticState, pos: np.ndarray, rot: np.ndarray) -> tuple[dict[str, Any], list[Hinge]]:
        """`joint_rows.joint_snapshot` of `state`, whose blocks are at `pos`, `rot`."""
        f = state.forces
        return joint_snapshot(
            self.arch.geometry,
            self.arch.centroid0,
            pos,
            rot,
            f.point,
            f.normal_force,
            f.shear_force,
            state.slip,
            self.arch.law.tan_friction,
            self.arch.imperfections,
            self.hinge_threshold,
        )

    def series_columns(self, state: StaticState, pos: np.ndarray | None = None) -> dict[str, Any]:
        """series.csv's columns of `state` (its blocks' positions `pos`, if known): reactions (the
        supports' forces on the arch), the crown's displacement, the residual against the weights, the
        dead loads and the live load (`held`, or a load path's own), the tangent's smallest eigenvalue."""
        pos = self.arch.poses(state.u)[0] if pos is None else pos
        force = state.forces.block_force
        crown = self.arch.geometry.crown_voussoir
        crown_disp = pos[crown] - self.arch.centroid0[crown]
        free = np.zeros(self.arch.n_blocks, bool)
        free[1:-1] = True
        live = state.lam if self.load_unit else self.held  # a load path's own, or the one held during the movement
        dead = self.arch.dead[free] + live * self.arch.live[free]
        loads = np.column_stack([dead[:, 0], dead[:, 1] - self.arch.weight[free]])
        loads[:, 0] += self.arch.passive_forces(state.u, state.springs)[free, 0]  # the fill's pushes (none: zero)
        unbalanced = unbalanced_force(state.forces, free, loads)
        return {
            "left_Rx_N": -force[0, 0],
            "left_Ry_N": -force[0, 1],
            "right_Rx_N": -force[-1, 0],
            "right_Ry_N": -force[-1, 1],
            "crown_dx_mm": units.to_mm(crown_disp[0]),
            "crown_dy_mm": units.to_mm(crown_disp[1]),
            "kinetic_J": 0.0,
            "unbalanced": unbalanced,
            "max_block_speed_mm_per_s": 0.0,
            "iterations": state.iterations,
            STIFFNESS_COLUMN: state.min_stiffness,
        }


def load_path_records(case: ArchCase, result: LoadPath) -> StaticRecords:
    """The states of the static engine's load path `result` of `case` recorded as a run records its own,
    each with its load (the start's and the collapse's also as snapshots, under their stages)."""
    records = StaticRecords(
        static_arch(case), case.numerics.hinge_rotation_mrad * 1e-3, load_unit=result.unit, after_mm=result.after_mm
    )
    for state in result.states:
        records.add(state, label=None if state.stage == Stage.EQUILIBRIUM else state.stage)
    return records
