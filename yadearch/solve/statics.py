"""The arch as the static engine sees it (pure numpy/numba, no YADE): rigid planar blocks, the DEM's
own joint function, the blocks' weights, and the supports placed along their path.

A state is every block's pose (x, y, rotation) together with the joints' shear forces. The
generalised coordinates are x, y and rotation x `length` (the ring's thickness), so that the tangent
stiffness K = -dF/du is in N/m throughout, as `model.stability` records it for the DEM.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.imperfect import ArchImperfections, arch_imperfections
from yadearch.case.mechanics import arch_geometry, backfill, contact_stiffness, live_load
from yadearch.case.support import case_movement
from yadearch.model import units
from yadearch.model.backfill import backfill_points
from yadearch.model.block_state import assemble_band, free_state, kernel_table
from yadearch.model.geometry import ArchGeometry, block_volume, front_face, polygon_centroid
from yadearch.model.joint_law import JointLaw
from yadearch.model.joint_table import JointTable, joint_table
from yadearch.model.joint_tangent import BLOCK_DOFS, JointTangent, joint_tangent
from yadearch.model.joints import rotate
from yadearch.model.loads import block_loads, live_load_points, turned_moments
from yadearch.model.movement import Movement
from yadearch.model.passive_fill import block_forces, passive_springs, scaled, yielded
from yadearch.solve import banded
from yadearch.solve.newton_kernel import descent_kernel, newton_kernel

WARM_UP_VOUSSOIRS = 3  # the smallest arch that compiles every kernel


@dataclass(frozen=True)
class StaticArch:
    """A case's blocks for the static engine: geometry, joints, weights (N, per block), undeformed
    centroids (m), the supports' movement, and which blocks are free."""

    geometry: ArchGeometry
    table: JointTable
    law: JointLaw
    weight: np.ndarray
    centroid0: np.ndarray
    movement: Movement
    imperfections: ArchImperfections | None
    live: np.ndarray  # the live load of 1 N (or 1 g) on each block (`model.loads.block_loads`)
    dead: np.ndarray  # the dead loads besides the weights (the backfill), in the same form, x gravity
    passive: np.ndarray  # the fill's passive springs at full gravity (`model.passive_fill`; none: empty)

    @property
    def n_blocks(self) -> int:
        return len(self.weight)

    @property
    def length(self) -> float:
        """The rotation's lever (m) in the generalised coordinates: the ring's thickness."""
        return self.geometry.thickness

    @property
    def free_dofs(self) -> np.ndarray:
        """Indices of the voussoirs' degrees of freedom in the generalised vector (supports are driven)."""
        return np.arange(BLOCK_DOFS, BLOCK_DOFS * (self.n_blocks - 1))

    def loads(self, gravity_fraction: float = 1.0) -> np.ndarray:
        """The weights as generalised forces (n_blocks x 3), a fraction of them while gravity is ramped."""
        forces = np.zeros((self.n_blocks, BLOCK_DOFS))
        forces[:, 1] = -gravity_fraction * self.weight
        return forces.ravel()

    def supports_at(self, lam: float) -> tuple[np.ndarray, np.ndarray]:
        """The two support blocks' centroids (2, 2) and rotations (2,) at path length `lam` (m)."""
        centroids, turns = self.centroid0[[0, -1]].copy(), np.zeros(2)
        for k, side in enumerate(("left", "right")):
            motion = self.movement.motion(side)
            if motion is not None:
                angle, offset = motion.placement(lam)
                centroids[k] = rotate(self.centroid0[[0, -1][k]], angle) + offset
                turns[k] = angle
        return centroids, turns

    def with_supports(self, u: np.ndarray, lam: float) -> np.ndarray:
        """`u` (generalised, all blocks) with both supports placed at path length `lam`."""
        placed = u.reshape(-1, BLOCK_DOFS).copy()
        centroids, turns = self.supports_at(lam)
        placed[[0, -1], 0:2] = centroids
        placed[[0, -1], 2] = turns * self.length
        return placed.ravel()

    def live_forces(self, u: np.ndarray) -> np.ndarray:
        """The live load of multiplier 1 on the free blocks as generalised forces at `u` (its moment
        with the arm turned by each block's rotation, / `length`)."""
        turn = self.poses(u)[1][1:-1]
        live = self.live[1:-1]
        moment = turned_moments(live, turn)
        return np.column_stack([live[:, 0], live[:, 1], moment / self.length]).ravel()

    def at_rest(self) -> np.ndarray:
        """The undeformed generalised coordinates: blocks exactly touching, nothing turned."""
        return np.column_stack([self.centroid0, np.zeros(self.n_blocks)]).ravel()

    def poses(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Positions (n_blocks, 2) and rotations (rad) of generalised coordinates `u`."""
        placed = u.reshape(-1, BLOCK_DOFS)
        return placed[:, 0:2], placed[:, 2] / self.length

    def evaluate(self, u: np.ndarray, u_before: np.ndarray, shear_before: np.ndarray) -> JointTangent:
        """The joints at `u`, having moved from `u_before` where their shear forces were `shear_before`."""
        pos, rot = self.poses(u)
        pos_before, rot_before = self.poses(u_before)
        return joint_tangent(
            self.table,
            self.law,
            np.ascontiguousarray(pos),
            np.ascontiguousarray(rot),
            np.ascontiguousarray(pos_before),
            np.ascontiguousarray(rot_before),
            shear_before,
        )

    def free_state(
        self,
        u: np.ndarray,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        gravity: float = 1.0,
        multiplier: float = 0.0,
        springs: np.ndarray | None = None,
    ) -> tuple[JointTangent, np.ndarray, np.ndarray]:
        """The joints at `u` (moved from `u_before`, where their shear forces were `shear_before`), the
        free blocks' residual R = joint forces + `gravity` x (the weights and the dead loads) +
        `multiplier` x the live load + the fill's pushes (`springs` as `u_before` left them; default the
        unyielded fill) (generalised) and their tangent K in band storage (`solve.banded`), in one
        compiled call."""
        return free_state(
            self.kernel, u, u_before, shear_before, self.weight, gravity, self.length, banded.BAND,
            *self.external(gravity, multiplier, springs),
        )  # fmt: skip

    def external(
        self, gravity: float, multiplier: float, springs: np.ndarray | None = None
    ) -> tuple[np.ndarray, float, np.ndarray]:
        """The loads besides the weights as the kernels take them: `gravity` x the dead loads +
        `multiplier` x the live load, the factor on them (0 where there are none: skipped), and the
        fill's passive springs (`springs`, default the unyielded `passive`) at `gravity`'s share."""
        loads = gravity * self.dead + multiplier * self.live
        return loads, (1.0 if loads.any() else 0.0), scaled(self.springs_or_unyielded(springs), gravity)

    def springs_or_unyielded(self, springs: np.ndarray | None) -> np.ndarray:
        """`springs`, or the fill's springs before anything has yielded where None."""
        return self.passive if springs is None else springs

    def yielded(self, springs: np.ndarray | None, u: np.ndarray) -> np.ndarray:
        """The fill's springs once the blocks reach `u` from where `springs` were (`model.passive_fill.yielded`)."""
        springs = self.springs_or_unyielded(springs)
        if not len(springs):
            return springs
        pos, rot = self.poses(u)
        return yielded(springs, np.column_stack([pos, rot]))

    def passive_forces(self, u: np.ndarray, springs: np.ndarray | None = None) -> np.ndarray:
        """(n_blocks, 3) the fill's passive pushes on every block at `u` (force x, y, moment; full gravity),
        its springs as `springs` (default: unyielded)."""
        pos, rot = self.poses(u)
        return block_forces(self.springs_or_unyielded(springs), np.column_stack([pos, rot]))

    @functools.cached_property
    def kernel(self) -> tuple:
        """The joint table and law as the compiled kernels take them (`model.block_state.kernel_table`)."""
        return kernel_table(self.table, self.law)

    def generalised_forces(self, joints: JointTangent) -> np.ndarray:
        """The joints' forces on every block as a generalised vector (torques / `length`)."""
        f = joints.forces
        return np.column_stack([f.block_force, f.block_torque / self.length]).ravel()

    def stiffness(self, joints: JointTangent) -> np.ndarray:
        """K = -dF/du on every degree of freedom (N/m), dense (for tests and the first predictor)."""
        return banded.to_dense(self.band_stiffness(joints, banded.BAND))

    def band_stiffness(self, joints: JointTangent, band: int) -> np.ndarray:
        """The same K in LAPACK's general band storage with `band` diagonals either side."""
        return assemble_band(joints.local, self.table.left, self.table.right, self.n_blocks, self.length, band)


def static_arch(case: ArchCase) -> StaticArch:
    """The static engine's model of `case`: its geometry with every imperfection, the DEM's joint
    law and stiffnesses, the blocks' weights (density x g x volume) and the supports' movement."""
    geometry = arch_geometry(case)
    if any(j.right != j.left + 1 for j in geometry.joints):
        raise ValueError("the static engine's banded tangent needs every joint between consecutive blocks")
    imperfections = arch_imperfections(case, geometry)
    stiffness = contact_stiffness(case, geometry)
    centroid0 = np.array([polygon_centroid(front_face(b)) for b in geometry.blocks])
    profiles = imperfections.profiles if imperfections is not None else None
    unit_weight = units.density(case.material.density_g_per_cm3) * case.loading.gravity_m_per_s2
    weight = np.array([unit_weight * block_volume(b) for b in geometry.blocks])
    points = live_load_points(geometry, centroid0, weight, live_load(case, geometry))
    fill = backfill(case)
    return StaticArch(
        geometry=geometry,
        table=joint_table(geometry, centroid0, profiles),
        law=JointLaw(stiffness.kn, stiffness.ks, stiffness.tan_friction, geometry.depth),
        weight=weight,
        centroid0=centroid0,
        movement=case_movement(case, geometry),
        imperfections=imperfections,
        live=block_loads(points, centroid0, len(weight)),
        dead=block_loads(backfill_points(geometry, fill), centroid0, len(weight)),
        passive=passive_springs(geometry, centroid0, fill),
    )


def compile_kernels() -> None:
    """Compile the static engine's kernels once and leave them in numba's cache (scripts/setup.sh calls
    this, so that the first run of a fresh install is not the one that waits ~10 s for them)."""
    from yadearch.case.config import preset

    arch = static_arch(preset("set2").with_overrides({"geometry.n_voussoirs": WARM_UP_VOUSSOIRS}))
    u, shear = arch.at_rest(), np.zeros(len(arch.table.left))
    joints = arch.evaluate(u, u, shear)
    arch.band_stiffness(joints, banded.BAND)
    problem = (arch.kernel, u, shear, arch.weight, 1.0, arch.length, banded.BAND, 1e-9, 1e-4, *arch.external(1.0, 0.0))
    newton_kernel(problem, u, 2, 2, 1e-4)
    descent_kernel(problem, u, 0.0, 0.0, u, 1e-3, 0, 2)
