"""Zero-thickness joint elements, compiled with numba (no YADE): the dry joint's no-tension Winkler
normal pressure and per-joint Coulomb shear, integrated exactly over each joint of the planar arch.

This is the same law as YADE's volumetric polyhedra contact (docs/numerics.md: F = kn V at the
overlap's centroid, V = the overlap volume) without its CGAL polyhedron intersection, which costs about 94 % of
a step: the two faces of a joint stay planar, so the overlap across the joint is linear and its
volume and centroid have closed forms. The joint's two faces are followed from the blocks' rigid
motions; the overlap is measured normal to their mean direction over the part of the joint where
both faces are (so a slipped joint carries load over the shared length only). Shear is the same
incremental law as `shear.PerContactShear`: s <- s - ks * depth * compressed length * slip, capped
at tan(phi) N, one force per joint. The joints come as the arrays of `joint_table`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from yadearch.model.joint_table import JointTable


@dataclass(frozen=True)
class JointLaw:
    """SI constants of the joint law: kn and ks per unit area (N/m^3), friction, joint depth (m)."""

    kn: float
    ks: float
    tan_friction: float
    depth: float

    def kernel_constants(self) -> tuple[float, float, float]:
        """kn and ks per unit length of joint (N/m^2) and the friction coefficient, as the kernels take them."""
        return self.kn * self.depth, self.ks * self.depth, self.tan_friction


@dataclass(frozen=True)
class JointForces:
    """The state of every joint after one evaluation (arrays over joints, SI), and the resultant
    force (n_blocks, 2) and torque (n_blocks,) the joints put on each block."""

    normal_force: np.ndarray
    shear_force: np.ndarray
    point: np.ndarray  # (n_joints, 2), NaN where the joint carries nothing
    compressed_length: np.ndarray
    plastic_slip: np.ndarray  # |sliding| beyond the Coulomb cap in this evaluation (m)
    block_force: np.ndarray
    block_torque: np.ndarray

    @property
    def in_contact(self) -> np.ndarray:
        return self.normal_force > 0.0


def joint_forces(
    table: JointTable,
    law: JointLaw,
    pos: np.ndarray,
    rot: np.ndarray,
    vel: np.ndarray,
    ang_vel: np.ndarray,
    shear: np.ndarray,
    dt: float,
) -> JointForces:
    """Evaluate every joint for blocks at `pos` (n_blocks, 2) rotated by `rot` (rad, about z, since
    the start) moving at `vel` (n_blocks, 2) and `ang_vel` (rad/s); `shear` holds each joint's shear
    force from the previous step and `dt` is the step over which the slip rate acts."""
    outputs = _joint_kernel(
        *table.kernel_geometry(),
        *law.kernel_constants(),
        pos,
        rot,
        vel,
        ang_vel,
        shear,
        dt,
        *table.kernel_gaps(),
    )
    return JointForces(*outputs)


@njit(cache=True)
def _joint_kernel(
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
    vel,
    ang_vel,
    shear,
    dt,
    gap_fraction,
    gap,
    imperfect,
):
    """The joint law, one joint at a time (compiled; about 1/30 of the array version's time).

    In the frame of the faces' mean direction, centred between the two faces' intrados points a_l
    and a_r, the faces are straight lines at -+ half their relative rotation r, so the overlap at
    abscissa s is (a_l - a_r).n - 2 h tan(r/2) s (h = +-1, the joint's handedness), over the
    abscissae both faces cover: |(a_l - a_r).e| / 2 to length cos(r/2) - that; an imperfect joint
    subtracts its gap profile from that overlap (`_gapped_overlap`). The forces are summed on the
    blocks right ends first, then left ends, joint by joint."""
    n_joints = left.shape[0]
    normal_force, shear_force = np.zeros(n_joints), np.zeros(n_joints)
    point = np.full((n_joints, 2), np.nan)
    compressed, plastic_slip = np.zeros(n_joints), np.zeros(n_joints)
    force_x, force_y = np.zeros(n_joints), np.zeros(n_joints)
    torque_left, torque_right = np.zeros(n_joints), np.zeros(n_joints)
    for j in range(n_joints):
        lb, rb = left[j], right[j]
        c, s = math.cos(rot[lb]), math.sin(rot[lb])
        alx = pos[lb, 0] + (c * left_intrados[j, 0] - s * left_intrados[j, 1])
        aly = pos[lb, 1] + (s * left_intrados[j, 0] + c * left_intrados[j, 1])
        c, s = math.cos(rot[rb]), math.sin(rot[rb])
        arx = pos[rb, 0] + (c * right_intrados[j, 0] - s * right_intrados[j, 1])
        ary = pos[rb, 1] + (s * right_intrados[j, 0] + c * right_intrados[j, 1])
        half_turn = 0.5 * (rot[rb] - rot[lb])
        c, s = math.cos(rot[lb] + half_turn), math.sin(rot[lb] + half_turn)
        nx, ny = c * normal0[j, 0] - s * normal0[j, 1], s * normal0[j, 0] + c * normal0[j, 1]
        ex, ey = c * along0[j, 0] - s * along0[j, 1], s * along0[j, 0] + c * along0[j, 1]
        gap_x, gap_y = alx - arx, aly - ary
        gap_along = gap_x * ex + gap_y * ey
        slope = 2.0 * handedness[j] * math.tan(half_turn)
        start = 0.5 * abs(gap_along)
        shared = length[j] * math.cos(half_turn) - 2.0 * start
        p0 = (gap_x * nx + gap_y * ny) - slope * start
        p1 = p0 - slope * shared
        if not (shared > 0.0 and (p0 > 0.0 or p1 > 0.0)):
            continue
        if imperfect[j]:
            area, centroid, touching_length = _gapped_overlap(
                p0, slope, start, shared, gap_fraction[j], gap[j], length[j] * math.cos(half_turn)
            )
            if area <= 0.0:
                continue
        else:
            q0, q1 = max(p0, 0.0), max(p1, 0.0)
            crossing = p0 / (p0 - p1) if p0 != p1 else 0.0
            first = 0.0 if p0 > 0.0 else crossing  # fractions of `shared` where the overlap starts, ends
            last = 1.0 if p1 > 0.0 else crossing
            touching_length = shared * (last - first)
            centroid = start + shared * first + touching_length * (q0 + 2.0 * q1) / (3.0 * (q0 + q1))
            area = 0.5 * touching_length * (q0 + q1)
        mid_height = 0.5 * slope * 0.5 * gap_along  # the faces' mid-line: the mean of their heights
        px = 0.5 * (alx + arx) + centroid * ex + mid_height * nx
        py = 0.5 * (aly + ary) + centroid * ey + mid_height * ny
        normal = kn_depth * area
        arm_lx, arm_ly = px - pos[lb, 0], py - pos[lb, 1]
        arm_rx, arm_ry = px - pos[rb, 0], py - pos[rb, 1]
        slip_x = vel[rb, 0] - ang_vel[rb] * arm_ry - vel[lb, 0] + ang_vel[lb] * arm_ly
        slip_y = vel[rb, 1] + ang_vel[rb] * arm_rx - vel[lb, 1] - ang_vel[lb] * arm_lx
        cap = tan_friction * normal
        stiffness = ks_depth * touching_length
        step_slip = (slip_x * ex + slip_y * ey) * dt
        trial = shear[j] - stiffness * step_slip
        tangential = min(max(trial, -cap), cap)
        if abs(trial) > cap:  # sliding, at most the step's relative motion: a cap that falls with
            # the normal force releases shear without any sliding
            plastic_slip[j] = min((abs(trial) - cap) / (stiffness if stiffness > 0.0 else 1.0), abs(step_slip))
        fx, fy = normal * nx + tangential * ex, normal * ny + tangential * ey  # on the right block
        normal_force[j], shear_force[j], compressed[j] = normal, tangential, touching_length
        point[j, 0], point[j, 1] = px, py
        force_x[j], force_y[j] = fx, fy
        torque_right[j], torque_left[j] = arm_rx * fy - arm_ry * fx, arm_ly * fx - arm_lx * fy
    block_force, block_torque = np.zeros((n_blocks, 2)), np.zeros(n_blocks)
    for j in range(n_joints):
        block_force[right[j], 0] += force_x[j]
        block_force[right[j], 1] += force_y[j]
        block_torque[right[j]] += torque_right[j]
    for j in range(n_joints):
        block_force[left[j], 0] -= force_x[j]
        block_force[left[j], 1] -= force_y[j]
        block_torque[left[j]] += torque_left[j]
    return normal_force, shear_force, point, compressed, plastic_slip, block_force, block_torque


@njit(cache=True)
def _gapped_overlap(p0, slope, start, shared, fraction, gap, projected_length):
    """Area (m^2), centroid abscissa and touching length of max(0, overlap - gap) over the shared
    abscissae [start, start + shared], the overlap falling linearly from p0 with `slope` and the gap
    piecewise linear on the nodes `fraction` x `projected_length`: exact, segment by segment."""
    area, moment, touching = 0.0, 0.0, 0.0
    end = start + shared
    for k in range(fraction.shape[0] - 1):
        t0, t1 = fraction[k] * projected_length, fraction[k + 1] * projected_length
        a, b = max(t0, start), min(t1, end)
        if b <= a:
            continue
        rate = (gap[k + 1] - gap[k]) / (t1 - t0)
        ua = p0 - slope * (a - start) - (gap[k] + rate * (a - t0))
        ub = p0 - slope * (b - start) - (gap[k] + rate * (b - t0))
        if ua <= 0.0 and ub <= 0.0:
            continue
        if ua < 0.0:
            a, ua = a + (b - a) * ua / (ua - ub), 0.0
        elif ub < 0.0:
            b, ub = a + (b - a) * ua / (ua - ub), 0.0
        width = b - a
        area += 0.5 * width * (ua + ub)
        moment += width * (ua * (2.0 * a + b) + ub * (a + 2.0 * b)) / 6.0
        touching += width
    return area, (moment / area if area > 0.0 else 0.0), touching


def unbalanced_force(forces: JointForces, free: np.ndarray, weights: np.ndarray) -> float:
    """YADE's unbalanced-force ratio for these joints: the mean norm of the resultant force (joints
    plus weight `weights` (n, 2)) on the `free` blocks over the mean norm of the joint forces."""
    contact = np.hypot(forces.normal_force, forces.shear_force)[forces.in_contact]
    if contact.size == 0:
        return float("inf")
    resultant = forces.block_force[free] + weights
    return float(np.mean(np.hypot(resultant[:, 0], resultant[:, 1])) / np.mean(contact))
