"""Stability of an equilibrium state from the joints' tangent stiffness (pure numpy, no YADE).

At an equilibrium the free blocks' stiffness matrix K = -dF/du (F the joint forces on them, u their
in-plane displacements and rotations; the weights are constant and add nothing) tells whether the
state is stable: it is while the smallest eigenvalue of K's symmetric part is positive, and a limit
point of the equilibrium path (a collapse under a prescribed support displacement) is where it
falls to zero (docs/numerics.md). K is differentiated numerically through the joint law itself,
shear included (a trial displacement u makes the incremental shear law see the slip u).
"""

from __future__ import annotations

import numpy as np

from yadearch.model.joint_law import JointLaw, joint_forces
from yadearch.model.joint_table import JointTable

PROBE_M = 1e-9  # trial displacement of the central differences (m): far below any overlap of interest


def tangent_stiffness(
    table: JointTable,
    law: JointLaw,
    pos: np.ndarray,
    rot: np.ndarray,
    shear: np.ndarray,
    free: np.ndarray,
    length: float,
) -> np.ndarray:
    """K (3 n_free square, N/m) of the `free` blocks at `pos` (n_blocks, 2), `rot` (rad) with the
    joints' shear forces `shear`; each block's degrees of freedom are x, y and its rotation times
    `length` (m), so that every entry is a stiffness in N/m."""
    blocks = np.flatnonzero(free)
    size = 3 * len(blocks)
    stiffness = np.empty((size, size))
    for k in range(size):
        block, dof = blocks[k // 3], k % 3
        ahead = _free_forces(table, law, pos, rot, shear, blocks, block, dof, PROBE_M, length)
        behind = _free_forces(table, law, pos, rot, shear, blocks, block, dof, -PROBE_M, length)
        stiffness[:, k] = -(ahead - behind) / (2.0 * PROBE_M)
    return stiffness


def _free_forces(
    table: JointTable,
    law: JointLaw,
    pos: np.ndarray,
    rot: np.ndarray,
    shear: np.ndarray,
    blocks: np.ndarray,
    block: int,
    dof: int,
    step: float,
    length: float,
) -> np.ndarray:
    """The joint forces and torques / `length` on the free blocks with one degree of freedom moved."""
    moved_pos, moved_rot = pos.copy(), rot.copy()
    vel, ang_vel = np.zeros_like(pos), np.zeros_like(rot)
    if dof < 2:
        moved_pos[block, dof] += step
        vel[block, dof] = step
    else:
        moved_rot[block] += step / length
        ang_vel[block] = step / length
    forces = joint_forces(table, law, moved_pos, moved_rot, vel, ang_vel, shear, 1.0)
    return np.column_stack([forces.block_force[blocks], forces.block_torque[blocks] / length]).ravel()


def smallest_stiffness(stiffness: np.ndarray) -> float:
    """The smallest eigenvalue of K's symmetric part (N/m): > 0 for a stable state."""
    return float(np.linalg.eigvalsh(0.5 * (stiffness + stiffness.T))[0])
