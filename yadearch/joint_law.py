"""Zero-thickness joint elements in pure numpy: the dry joint's no-tension Winkler normal pressure
and per-joint Coulomb shear, integrated exactly over each joint of the planar arch.

This is the same law as YADE's volumetric polyhedra contact (DESIGN.md §3: F = kn V at the overlap's
centroid, V = the overlap volume) without its CGAL polyhedron intersection, which costs about 94 % of
a step: the two faces of a joint stay planar, so the overlap across the joint is linear and its
volume and centroid have closed forms. The joint's two faces are followed from the blocks' rigid
motions; the overlap is measured normal to their mean direction over the part of the joint where
both faces are (so a slipped joint carries load over the shared length only). Shear is the same
incremental law as `shear.PerContactShear`: s <- s - ks * depth * compressed length * slip, capped
at tan(phi) N, one force per joint.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .geometry import ArchGeometry
from .joints import rotate


@dataclass(frozen=True)
class JointTable:
    """The joints of a scene as arrays: block indices, each joint's intrados point relative to its
    two blocks' initial centroids (m), its initial normal (left -> right) and direction (intrados ->
    extrados), its length (m) and the sign of direction x normal."""

    left: np.ndarray
    right: np.ndarray
    left_intrados: np.ndarray
    right_intrados: np.ndarray
    normal0: np.ndarray
    along0: np.ndarray
    length: np.ndarray
    handedness: np.ndarray
    both_ends: np.ndarray  # block indices [right..., left...], to sum each joint's force on its blocks
    n_blocks: int


@dataclass(frozen=True)
class JointLaw:
    """SI constants of the joint law: kn and ks per unit area (N/m^3), friction, joint depth (m)."""

    kn: float
    ks: float
    tan_friction: float
    depth: float


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


def joint_table(geometry: ArchGeometry, centroids0: np.ndarray) -> JointTable:
    """Arrays of `geometry.joints` relative to the blocks' initial centroids (n_blocks, >=2)."""
    joints = geometry.joints
    left = np.array([j.left for j in joints])
    right = np.array([j.right for j in joints])
    intrados = np.array([j.intrados for j in joints])
    extrados = np.array([j.extrados for j in joints])
    normal = np.array([j.normal for j in joints])
    length = np.linalg.norm(extrados - intrados, axis=1)
    along = (extrados - intrados) / length[:, None]
    handedness = np.sign(along[:, 0] * normal[:, 1] - along[:, 1] * normal[:, 0])
    c0 = centroids0[:, :2]
    return JointTable(left, right, intrados - c0[left], intrados - c0[right], normal, along, length,
                      handedness, np.concatenate([right, left]), len(centroids0))


def joint_forces(table: JointTable, law: JointLaw, pos: np.ndarray, rot: np.ndarray,
                 vel: np.ndarray, ang_vel: np.ndarray, shear: np.ndarray, dt: float) -> JointForces:
    """Evaluate every joint for blocks at `pos` (n_blocks, 2) rotated by `rot` (rad, about z, since
    the start) moving at `vel` (n_blocks, 2) and `ang_vel` (rad/s); `shear` holds each joint's shear
    force from the previous step and `dt` is the step over which the slip rate acts.

    In the frame of the faces' mean direction, centred between the two faces' intrados points a_l
    and a_r, the faces are straight lines at -+ half their relative rotation r, so the overlap at
    abscissa s is (a_l - a_r).n - 2 h tan(r/2) s (h = +-1, the joint's handedness), over the
    abscissae both faces cover: |(a_l - a_r).e| / 2 to length cos(r/2) - that."""
    left, right = table.left, table.right
    rot_left, rot_right = rot[left], rot[right]
    a_left = pos[left] + rotate(table.left_intrados, rot_left)
    a_right = pos[right] + rotate(table.right_intrados, rot_right)
    half_turn = 0.5 * (rot_right - rot_left)
    mean_rotation = rot_left + half_turn
    cos_mean, sin_mean = np.cos(mean_rotation), np.sin(mean_rotation)
    n0, e0 = table.normal0, table.along0
    nx, ny = cos_mean * n0[:, 0] - sin_mean * n0[:, 1], sin_mean * n0[:, 0] + cos_mean * n0[:, 1]
    ex, ey = cos_mean * e0[:, 0] - sin_mean * e0[:, 1], sin_mean * e0[:, 0] + cos_mean * e0[:, 1]
    gap_x, gap_y = a_left[:, 0] - a_right[:, 0], a_left[:, 1] - a_right[:, 1]
    gap_along = gap_x * ex + gap_y * ey
    gap_normal = gap_x * nx + gap_y * ny
    slope = 2.0 * table.handedness * np.tan(half_turn)
    start = 0.5 * np.abs(gap_along)
    shared = table.length * np.cos(half_turn) - 2.0 * start
    p0 = gap_normal - slope * start
    p1 = p0 - slope * shared

    touching = (shared > 0.0) & ((p0 > 0.0) | (p1 > 0.0))
    q0, q1 = np.maximum(p0, 0.0), np.maximum(p1, 0.0)
    crossing = np.where(touching & (p0 != p1), p0 / np.where(p0 != p1, p0 - p1, 1.0), 0.0)
    first = np.where(p0 > 0.0, 0.0, crossing)  # fractions of `shared` where the overlap starts, ends
    last = np.where(p1 > 0.0, 1.0, crossing)
    length = np.where(touching, shared * (last - first), 0.0)
    total = q0 + q1
    area = 0.5 * length * total
    centroid = start + shared * first + length * (q0 + 2.0 * q1) / (3.0 * np.where(touching, total, 1.0))
    mid_height = 0.5 * slope * 0.5 * gap_along  # the faces' mid-line is at the mean of their heights
    px = 0.5 * (a_left[:, 0] + a_right[:, 0]) + centroid * ex + mid_height * nx
    py = 0.5 * (a_left[:, 1] + a_right[:, 1]) + centroid * ey + mid_height * ny

    normal_force = law.kn * law.depth * area
    arm_lx, arm_ly = px - pos[left, 0], py - pos[left, 1]
    arm_rx, arm_ry = px - pos[right, 0], py - pos[right, 1]
    w_left, w_right = ang_vel[left], ang_vel[right]
    slip_x = vel[right, 0] - w_right * arm_ry - vel[left, 0] + w_left * arm_ly
    slip_y = vel[right, 1] + w_right * arm_rx - vel[left, 1] - w_left * arm_lx
    slip = (slip_x * ex + slip_y * ey) * dt
    cap = law.tan_friction * normal_force
    stiffness = law.ks * law.depth * length
    trial = shear - stiffness * slip
    shear_force = np.where(touching, np.clip(trial, -cap, cap), 0.0)
    excess = np.where(touching, np.abs(trial) - cap, 0.0)
    plastic_slip = np.where(excess > 0.0, excess / np.where(stiffness > 0.0, stiffness, 1.0), 0.0)

    fx = normal_force * nx + shear_force * ex  # on the right block; the left one gets the opposite
    fy = normal_force * ny + shear_force * ey
    ends, n = table.both_ends, table.n_blocks
    block_force = np.stack([np.bincount(ends, np.concatenate([fx, -fx]), n),
                            np.bincount(ends, np.concatenate([fy, -fy]), n)], axis=1)
    torque = np.concatenate([arm_rx * fy - arm_ry * fx, arm_ly * fx - arm_lx * fy])
    block_torque = np.bincount(ends, torque, n)
    point = np.where(touching[:, None], np.stack([px, py], axis=1), np.nan)
    return JointForces(normal_force, shear_force, point, length, plastic_slip, block_force,
                       block_torque)


def unbalanced_force(forces: JointForces, free: np.ndarray, weights: np.ndarray) -> float:
    """YADE's unbalanced-force ratio for these joints: the mean norm of the resultant force (joints
    plus weight `weights` (n, 2)) on the `free` blocks over the mean norm of the joint forces."""
    contact = np.hypot(forces.normal_force, forces.shear_force)[forces.in_contact]
    if contact.size == 0:
        return float("inf")
    resultant = forces.block_force[free] + weights
    return float(np.mean(np.hypot(resultant[:, 0], resultant[:, 1])) / np.mean(contact))
