"""The free blocks' state for the static engine (compiled with numba, no YADE): the joints' tangent
(`model.joint_tangent`) assembled over the blocks into the residual R = joint forces + weights + point
loads (a live load, backfill) and the band tangent K = -dR/du of the free blocks, each block's degrees
of freedom x, y and its rotation times a lever (so that every entry of K is N/m), in one compiled call."""

from __future__ import annotations

import numpy as np
from numba import njit

from yadearch.model.joint_law import JointForces, JointLaw
from yadearch.model.joint_table import JointTable
from yadearch.model.joint_tangent import BLOCK_DOFS, JointTangent, tangent_kernel
from yadearch.model.kernel_call import KernelCall
from yadearch.model.passive_fill import add_passive


def kernel_table(table: JointTable, law: JointLaw) -> tuple:
    """The joint table's arrays and the law's constants as one tuple, as the compiled kernels of the
    static engine take them (`model.kernel_call` dispatches a tuple of this size without numba's typing)."""
    return (*table.kernel_geometry(), *law.kernel_constants(), *table.kernel_gaps())


def free_state(
    kernel: tuple,
    u: np.ndarray,
    u_before: np.ndarray,
    shear_before: np.ndarray,
    weight: np.ndarray,
    gravity: float,
    length: float,
    band: int,
    loads: np.ndarray,
    factor: float,
    passive: np.ndarray,
) -> tuple[JointTangent, np.ndarray, np.ndarray]:
    """In one compiled call: the joints at generalised coordinates `u` (x, y, rotation x `length`
    per block) having moved from `u_before`, the residual R = joint forces + `gravity` x the weights
    + `factor` x the point loads `loads` (`model.loads.block_loads`) + the fill's `passive` springs
    (`model.passive_fill`) on the free blocks (all but the first and last) and their tangent K in band
    storage; `kernel` is `kernel_table`'s tuple."""
    return as_joints(
        FREE_STATE_KERNEL(kernel, u, u_before, shear_before, weight, gravity, length, band, loads, factor, passive)
    )


def as_joints(state: tuple) -> tuple[JointTangent, np.ndarray, np.ndarray]:
    """`free_state_kernel`'s outputs as (joints, residual, free blocks' band tangent)."""
    *forces, local, residual, stiffness = state
    return JointTangent(JointForces(*forces), local), residual, stiffness


@njit(cache=True)
def free_state_kernel(kernel, u, u_before, shear_before, weight, gravity, lever, band, loads, factor, passive):
    """`tangent_kernel` at the poses of `u`, then the free blocks' residual and band tangent, with
    `factor` x the point loads `loads` (per block: force x, y, and the moment m0 and dot product d0
    of their arms from the centroid with them, unturned; the arms turn with the block) and the fill's
    `passive` springs (`model.passive_fill`; none: an empty table)."""
    (left, right, left_intrados, right_intrados, normal0, along0, length, handedness, n_blocks,
     kn_depth, ks_depth, tan_friction, gap_fraction, gap, imperfect) = kernel  # fmt: skip
    placed, before = u.reshape(-1, BLOCK_DOFS), u_before.reshape(-1, BLOCK_DOFS)
    pos, pos_before = np.ascontiguousarray(placed[:, 0:2]), np.ascontiguousarray(before[:, 0:2])
    rot, rot_before = placed[:, 2] / lever, before[:, 2] / lever
    outputs = tangent_kernel(
        left, right, left_intrados, right_intrados, normal0, along0, length, handedness, n_blocks,
        kn_depth, ks_depth, tan_friction, pos, rot, pos_before, rot_before, shear_before, gap_fraction, gap, imperfect,
    )  # fmt: skip
    block_force, block_torque, local = outputs[5], outputs[6], outputs[7]
    residual = np.empty(BLOCK_DOFS * (n_blocks - 2))
    for b in range(1, n_blocks - 1):  # joint forces + weights, as generalised forces (torque / lever)
        k = BLOCK_DOFS * (b - 1)
        residual[k] = block_force[b, 0] + 0.0
        residual[k + 1] = block_force[b, 1] + -gravity * weight[b]
        residual[k + 2] = block_torque[b] / lever + 0.0
    whole = assemble_band(local, left, right, n_blocks, lever, band)
    stiffness = np.ascontiguousarray(whole[:, BLOCK_DOFS : BLOCK_DOFS * (n_blocks - 1)])
    if factor != 0.0:
        _add_point_loads(residual, stiffness, loads, factor, rot, lever, band)
    if passive.shape[0]:
        add_passive(residual, stiffness, passive, pos, rot, lever, band)
    return (
        outputs[0],
        outputs[1],
        outputs[2],
        outputs[3],
        outputs[4],
        block_force,
        block_torque,
        local,
        residual,
        stiffness,
    )


@njit(cache=True)
def assemble_band(local, left, right, n_blocks, length, band):
    """The blocks' tangent K = -dF/du (N/m) from the joints' local tangents, each block's degrees of
    freedom x, y and its rotation times `length` (so that every entry is N/m), in LAPACK's general
    band storage, (2 band + 1, 3 n_blocks): K[i, j] at [band + i - j, j]; joints between
    neighbouring blocks keep it within `band` = 5 diagonals."""
    size = BLOCK_DOFS * n_blocks
    stiffness = np.zeros((2 * band + 1, size))
    scales = np.array([1.0, 1.0, 1.0 / length])
    for j in range(local.shape[0]):
        blocks = (left[j], right[j])
        for a in range(6):
            row = BLOCK_DOFS * blocks[a // 3] + a % 3
            for b in range(6):
                col = BLOCK_DOFS * blocks[b // 3] + b % 3
                stiffness[band + row - col, col] -= local[j, a, b] * scales[a % 3] * scales[b % 3]
    return stiffness


@njit(cache=True)
def _add_point_loads(residual, stiffness, loads, factor, rot, lever, band):
    """Point loads on the free blocks: their forces, and their moment about the centroid with the arms
    turned by the block's rotation, c m0 - s d0, whose change with the rotation is the loads' own
    stiffness (a load above the centroid softens the block: K += P (s m0 + c d0) / lever^2)."""
    for b in range(1, loads.shape[0] - 1):
        k = BLOCK_DOFS * (b - 1)
        c, s = np.cos(rot[b]), np.sin(rot[b])
        m0, d0 = loads[b, 2], loads[b, 3]
        residual[k] += factor * loads[b, 0]
        residual[k + 1] += factor * loads[b, 1]
        residual[k + 2] += factor * (c * m0 - s * d0) / lever
        stiffness[band, k + 2] += factor * (s * m0 + c * d0) / lever**2


FREE_STATE_KERNEL = KernelCall(free_state_kernel)  # `model.kernel_call`
