"""The dry joints as zero-thickness joint elements evaluated in numpy (`joint_law`) by one Python
engine of the YADE scene: no collider and no CGAL, YADE integrates the blocks' motion."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from yadearch.case.mechanics import ContactStiffness
from yadearch.model.geometry import ArchGeometry
from yadearch.model.imperfections import GapProfiles
from yadearch.model.joint_law import JointForces, JointLaw, joint_forces, unbalanced_force
from yadearch.model.joint_table import joint_table
from yadearch.model.joints import pair_rotation
from yadearch.model.passive_fill import SpringTangent, no_springs
from yadearch.model.stability import smallest_stiffness, tangent_stiffness


class JointElementContacts:
    """Contact model "joint": reads the block states each step, evaluates every joint at once and
    adds the joint forces and torques to YADE's force container."""

    name = "joint"

    def __init__(
        self,
        stiffness: ContactStiffness,
        geometry: ArchGeometry,
        body_ids: list[int],
        profiles: GapProfiles | None = None,
    ):
        self.profiles = profiles  # the joints' initial gap profiles (None: perfect faces)
        self.law = JointLaw(stiffness.kn, stiffness.ks, stiffness.tan_friction, geometry.depth)
        self.geometry = geometry
        self.body_ids = body_ids
        self.shear = np.zeros(len(geometry.joints))
        self.slip = np.zeros(len(geometry.joints))  # accumulated sliding beyond the Coulomb cap (m)
        self.last: JointForces | None = None
        self.external = np.zeros((len(geometry.blocks), 2))  # a live load now (N), for `unbalanced`
        self.dead_external = np.zeros((len(geometry.blocks), 2))  # the dead loads now (N), for `unbalanced`
        self.fill_springs = no_springs()  # the fill's passive springs as the path has yielded them (`dem.dead_load`)

    def bind(self, pos0: np.ndarray, ori0: np.ndarray, callback: str) -> list[Any]:
        """Keep the block states and weights at hand and return the one engine this model needs."""
        from yade import O
        from yade.wrapper import PyRunner

        self.table = joint_table(self.geometry, pos0, self.profiles)
        states = [O.bodies[i].state for i in self.body_ids]
        # a block turning about z keeps the norms of its quaternion's (w, z) and (x, y) pairs: its
        # angle follows from the larger pair alone, two numbers read instead of four
        by_wz = ori0[:, 0] ** 2 + ori0[:, 3] ** 2 >= ori0[:, 1] ** 2 + ori0[:, 2] ** 2
        self._wz_blocks, self._xy_blocks = np.flatnonzero(by_wz), np.flatnonzero(~by_wz)
        self._wz_states = [states[i] for i in self._wz_blocks]
        self._xy_states = [states[i] for i in self._xy_blocks]
        self._pair0 = np.where(by_wz[:, None], ori0[:, [0, 3]], ori0[:, [1, 2]])
        self._states = states
        self._free = np.array([O.bodies[i].dynamic for i in self.body_ids])
        self._masses = np.array([s.mass for s in self._states])
        self._previous: np.ndarray | None = None  # the poses of the last step's evaluation
        return [PyRunner(command=f"{callback}.step()", iterPeriod=1, initRun=True)]

    def read_poses(self) -> np.ndarray:
        """The blocks' current poses (n_blocks, 3): x, y, rotation about z since the start (rad).
        Positions and one quaternion pair only: every number read through YADE's Python API costs
        about 0.1-0.2 us, and the velocities follow from two successive poses (`forces`)."""
        pairs = np.empty((len(self._states), 4))
        if self._wz_states:
            pairs[self._wz_blocks] = [(p[0], p[1], q[3], q[2]) for p, q in ((s.pos, s.ori) for s in self._wz_states)]
        if self._xy_states:  # minieigen quaternions index (x, y, z, w)
            pairs[self._xy_blocks] = [(p[0], p[1], q[0], q[1]) for p, q in ((s.pos, s.ori) for s in self._xy_states)]
        pairs[:, 2] = pair_rotation(pairs[:, 2:4], self._pair0)
        return pairs[:, 0:3]

    def forces(self, poses: np.ndarray) -> JointForces:
        """The joints for block `poses` (`read_poses`), moving since the last step's poses (YADE's
        leapfrog moves a block by its velocity x dt each step, so the difference over dt is the
        velocity YADE holds; blocks stopped or put back by the runner start from rest)."""
        from yade import O

        dt = O.dt
        motion = np.zeros_like(poses) if self._previous is None else poses - self._previous
        motion[:, 2] = np.remainder(motion[:, 2] + math.pi, 2.0 * math.pi) - math.pi  # across +-pi
        return joint_forces(
            self.table, self.law, poses[:, 0:2], poses[:, 2], motion[:, 0:2] / dt, motion[:, 2] / dt, self.shear, dt
        )

    def apply(self, forces: JointForces) -> None:
        """Add the joint forces and torques to YADE's force container."""
        from yade import O

        add_force, add_torque = O.forces.addF, O.forces.addT
        for body_id, (fx, fy), tz in zip(self.body_ids, forces.block_force.tolist(), forces.block_torque.tolist()):
            add_force(body_id, (fx, fy, 0.0))  # a tuple converts faster than a built Vector3
            add_torque(body_id, (0.0, 0.0, tz))

    def _evaluate(self) -> JointForces:
        return self.forces(self.read_poses())

    def step(self) -> None:
        """Evaluate the joints for the current states and add their forces (called every step)."""
        poses = self.read_poses()
        forces = self.forces(poses)
        self._previous = poses
        self.shear = forces.shear_force
        self.slip += forces.plastic_slip
        self.last = forces
        self.apply(forces)

    def joint_contacts(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Contact point (n_joints, 2; NaN if open), normal and shear force (n_joints,) of every joint."""
        forces = self.last if self.last is not None else self._evaluate()
        return forces.point, forces.normal_force, forces.shear_force

    def smallest_stiffness(self, turning: np.ndarray | None = None, springs: SpringTangent | None = None) -> float:
        """The smallest eigenvalue of the free blocks' tangent stiffness now (N/m; `model.stability`), with
        the loads' own rotational stiffness `turning` (n_blocks, N m/rad; `model.loads.turning_stiffness`)
        and the tangent of springs on the blocks (`springs(poses, length)`: every block's x, y and rotation
        x length, N/m; None: none)."""
        poses = self.read_poses()
        length = self.geometry.thickness
        stiffness = tangent_stiffness(self.table, self.law, poses[:, 0:2], poses[:, 2], self.shear, self._free, length)
        if turning is not None:
            rotations = np.arange(2, stiffness.shape[0], 3)  # each free block's x, y, rotation x length
            stiffness[rotations, rotations] += turning[self._free] / length**2
        extra = springs(poses, length) if springs is not None else None
        if extra is not None:
            free = np.flatnonzero(np.repeat(self._free, 3))
            stiffness += extra[np.ix_(free, free)]
        return smallest_stiffness(stiffness)

    @property
    def poses(self) -> np.ndarray:
        """The poses (n_blocks, 3) the joints were last evaluated at (this step's, once they ran)."""
        return self._previous if self._previous is not None else self.read_poses()

    def joint_slip(self) -> np.ndarray:
        """Sliding each joint has accumulated beyond its Coulomb cap since the start (m)."""
        return self.slip.copy()

    def snapshot(self) -> dict:
        """The joints' history (shear forces, slip, the last step's poses) and last evaluation, for
        `restore`."""
        return {
            "shear": self.shear.copy(),
            "slip": self.slip.copy(),
            "last": self.last,
            "previous": self._previous,
            "fill_springs": self.fill_springs.copy(),
        }

    def restore(self, snapshot: dict) -> None:
        """Back to a `snapshot` (the bodies are restored by the runner)."""
        self.shear = snapshot["shear"].copy()
        self.slip = snapshot["slip"].copy()
        self.fill_springs = snapshot["fill_springs"].copy()
        self.last = snapshot["last"]
        self._previous = snapshot["previous"]

    def stopped(self) -> None:
        """The runner has stopped the blocks: the next step starts them from rest."""
        self._previous = None

    def unbalanced(self) -> float:
        """YADE's unbalanced-force ratio computed from the joint forces of the last step."""
        from yade import O
        from yade.wrapper import NewtonIntegrator

        forces = self.last if self.last is not None else self._evaluate()
        newton = next(e for e in O.engines if isinstance(e, NewtonIntegrator))
        gravity = np.array(newton.gravity)[:2]
        weights = self._masses[self._free, None] * gravity
        loads = weights + self.external[self._free] + self.dead_external[self._free]
        return unbalanced_force(forces, self._free, loads)
