"""The joint law with its consistent tangent, for the static engine (compiled with numba, no YADE).

The same arithmetic as `joint_law._joint_kernel`, term for term, carried in dual numbers
(`model.dual`): each joint's force on its right block and the torques on both blocks come with their
exact derivatives with respect to the six degrees of freedom of its two blocks (an imperfect joint's
overlap with its derivatives in closed form, `model.gapped_overlap`). Shear is the same
incremental law, the slip being the blocks' motion since the last accepted equilibrium state
(backward Euler: the return to the Coulomb cap is made once per load increment, whatever the
Newton iterations in between), so that the DEM's `dt` x velocity becomes that motion.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from yadearch.model.dual import add, const, dabs, dcos, div, dsin, dtan, mul, scale, shift, sub, var
from yadearch.model.gapped_overlap import gapped_overlap
from yadearch.model.joint_law import JointForces, JointLaw
from yadearch.model.joint_table import JointTable

BLOCK_DOFS = 3  # x, y, rotation


@dataclass(frozen=True)
class JointTangent:
    """The joints' forces (as `joint_law.joint_forces` returns them) and, per joint, the derivatives
    (n_joints, 6, 6) of the generalised forces on its left block (fx, fy, torque) then right block
    with respect to the left block's (x, y, rotation) then the right block's (SI: N/m, N, N m)."""

    forces: JointForces
    local: np.ndarray


def joint_tangent(
    table: JointTable,
    law: JointLaw,
    pos: np.ndarray,
    rot: np.ndarray,
    pos_before: np.ndarray,
    rot_before: np.ndarray,
    shear_before: np.ndarray,
) -> JointTangent:
    """Every joint for blocks at `pos` (n_blocks, 2), `rot` (rad), having moved from `pos_before`,
    `rot_before`, where the joints' shear forces were `shear_before`."""
    outputs = tangent_kernel(
        *table.kernel_geometry(),
        *law.kernel_constants(),
        pos,
        rot,
        pos_before,
        rot_before,
        shear_before,
        *table.kernel_gaps(),
    )
    *forces, local = outputs
    return JointTangent(JointForces(*forces), local)


@njit(cache=True)
def _placed_intrados(x, y, turn, point):
    c, s = dcos(turn), dsin(turn)
    return (add(x, sub(scale(c, point[0]), scale(s, point[1]))), add(y, add(scale(s, point[0]), scale(c, point[1]))))


@njit(cache=True)
def _turned(c, s, vector):
    """`vector` (2,) turned by the angle whose cosine and sine are the duals `c`, `s`."""
    return (sub(scale(c, vector[0]), scale(s, vector[1])), add(scale(s, vector[0]), scale(c, vector[1])))


@njit(cache=True)
def _perfect_overlap(p0, p1, start, shared):
    """Area, centroid abscissa and touching length of max(0, overlap) over the shared abscissae."""
    zero, one = const(0.0), const(1.0)
    q0 = p0 if p0[0] > 0.0 else zero
    q1 = p1 if p1[0] > 0.0 else zero
    crossing = div(p0, sub(p0, p1)) if p0[0] != p1[0] else zero
    first = zero if p0[0] > 0.0 else crossing
    last = one if p1[0] > 0.0 else crossing
    touching = mul(shared, sub(last, first))
    q_sum = add(q0, q1)
    centroid = add(add(start, mul(shared, first)), div(mul(touching, add(q0, scale(q1, 2.0))), scale(q_sum, 3.0)))
    return scale(mul(touching, q_sum), 0.5), centroid, touching


@njit(cache=True)
def tangent_kernel(
    left,
    right,
    left_intrados,
    right_intrados,
    normal0,
    along0,
    length,
    handedness,
    n_blocks,
    kn_depth,
    ks_depth,
    tan_friction,
    pos,
    rot,
    pos_before,
    rot_before,
    shear_before,
    gap_fraction,
    gap,
    imperfect,
):
    """`joint_law._joint_kernel` with velocity x dt = the motion since the `_before` state, every
    quantity a dual number over the joint's six degrees of freedom; returns its outputs and the
    (n_joints, 6, 6) local tangents."""
    n_joints = left.shape[0]
    normal_force, shear_force = np.zeros(n_joints), np.zeros(n_joints)
    point = np.full((n_joints, 2), np.nan)
    compressed, plastic_slip = np.zeros(n_joints), np.zeros(n_joints)
    block_force, block_torque = np.zeros((n_blocks, 2)), np.zeros(n_blocks)
    local = np.zeros((n_joints, 6, 6))
    for j in range(n_joints):
        lb, rb = left[j], right[j]
        xl, yl, tl = var(pos[lb, 0], 0), var(pos[lb, 1], 1), var(rot[lb], 2)
        xr, yr, tr = var(pos[rb, 0], 3), var(pos[rb, 1], 4), var(rot[rb], 5)
        alx, aly = _placed_intrados(xl, yl, tl, left_intrados[j])
        arx, ary = _placed_intrados(xr, yr, tr, right_intrados[j])
        half_turn = scale(sub(tr, tl), 0.5)
        c, s = dcos(add(tl, half_turn)), dsin(add(tl, half_turn))
        nx, ny = _turned(c, s, normal0[j])
        ex, ey = _turned(c, s, along0[j])
        gap_x, gap_y = sub(alx, arx), sub(aly, ary)
        gap_along = add(mul(gap_x, ex), mul(gap_y, ey))
        slope = scale(dtan(half_turn), 2.0 * handedness[j])
        start = scale(dabs(gap_along), 0.5)
        projected = scale(dcos(half_turn), length[j])
        shared = sub(projected, scale(start, 2.0))
        p0 = sub(add(mul(gap_x, nx), mul(gap_y, ny)), mul(slope, start))
        p1 = sub(p0, mul(slope, shared))
        if not (shared[0] > 0.0 and (p0[0] > 0.0 or p1[0] > 0.0)):
            continue
        if imperfect[j]:
            area, centroid, touching = gapped_overlap(p0, slope, start, shared, gap_fraction[j], gap[j], projected)
            if area[0] <= 0.0:
                continue
        else:
            area, centroid, touching = _perfect_overlap(p0, p1, start, shared)
        mid_height = scale(mul(slope, gap_along), 0.25)
        px = add(add(scale(add(alx, arx), 0.5), mul(centroid, ex)), mul(mid_height, nx))
        py = add(add(scale(add(aly, ary), 0.5), mul(centroid, ey)), mul(mid_height, ny))
        normal = scale(area, kn_depth)
        arm_lx, arm_ly, arm_rx, arm_ry = sub(px, xl), sub(py, yl), sub(px, xr), sub(py, yr)
        turn_l, turn_r = shift(tl, -rot_before[lb]), shift(tr, -rot_before[rb])
        slip_x = sub(
            sub(shift(xr, -pos_before[rb, 0]), mul(turn_r, arm_ry)),
            sub(shift(xl, -pos_before[lb, 0]), mul(turn_l, arm_ly)),
        )
        slip_y = sub(
            add(shift(yr, -pos_before[rb, 1]), mul(turn_r, arm_rx)),
            add(shift(yl, -pos_before[lb, 1]), mul(turn_l, arm_lx)),
        )
        cap = scale(normal, tan_friction)
        stiffness = scale(touching, ks_depth)
        step_slip = add(mul(slip_x, ex), mul(slip_y, ey))
        trial = sub(const(shear_before[j]), mul(stiffness, step_slip))
        tangential = trial
        if trial[0] > cap[0]:
            tangential = cap
        elif trial[0] < -cap[0]:
            tangential = scale(cap, -1.0)
        if abs(trial[0]) > cap[0]:
            plastic_slip[j] = min(
                (abs(trial[0]) - cap[0]) / (stiffness[0] if stiffness[0] > 0.0 else 1.0), abs(step_slip[0])
            )
        fx, fy = add(mul(normal, nx), mul(tangential, ex)), add(mul(normal, ny), mul(tangential, ey))
        torque_r = sub(mul(arm_rx, fy), mul(arm_ry, fx))
        torque_l = sub(mul(arm_ly, fx), mul(arm_lx, fy))
        normal_force[j], shear_force[j], compressed[j] = normal[0], tangential[0], touching[0]
        point[j, 0], point[j, 1] = px[0], py[0]
        for k in range(6):
            local[j, 0, k], local[j, 1, k], local[j, 2, k] = -fx[k + 1], -fy[k + 1], torque_l[k + 1]
            local[j, 3, k], local[j, 4, k], local[j, 5, k] = fx[k + 1], fy[k + 1], torque_r[k + 1]
        block_force[rb, 0] += fx[0]
        block_force[rb, 1] += fy[0]
        block_torque[rb] += torque_r[0]
        block_force[lb, 0] -= fx[0]
        block_force[lb, 1] -= fy[0]
        block_torque[lb] += torque_l[0]
    return normal_force, shear_force, point, compressed, plastic_slip, block_force, block_torque, local
