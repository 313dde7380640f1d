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
    """The joints of a scene as arrays: block indices and each face's end points relative to its
    block's initial centroid (m), the initial normal (left -> right) and direction (intrados ->
    extrados)."""

    left: np.ndarray
    right: np.ndarray
    left_intrados: np.ndarray
    left_extrados: np.ndarray
    right_intrados: np.ndarray
    right_extrados: np.ndarray
    normal0: np.ndarray
    along0: np.ndarray
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
    normal: np.ndarray  # (n_joints, 2), unit, from the left block to the right one
    compressed_length: np.ndarray
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
    along = (extrados - intrados) / np.linalg.norm(extrados - intrados, axis=1)[:, None]
    c0 = centroids0[:, :2]
    return JointTable(left, right, intrados - c0[left], extrados - c0[left], intrados - c0[right],
                      extrados - c0[right], normal, along, len(centroids0))


def joint_forces(table: JointTable, law: JointLaw, pos: np.ndarray, rot: np.ndarray,
                 vel: np.ndarray, ang_vel: np.ndarray, shear: np.ndarray, dt: float) -> JointForces:
    """Evaluate every joint for blocks at `pos` (n_blocks, 2) rotated by `rot` (rad, about z, since
    the start) moving at `vel` (n_blocks, 2) and `ang_vel` (rad/s); `shear` holds each joint's shear
    force from the previous step and `dt` is the step over which the slip rate acts."""
    left, right = table.left, table.right
    a_left = pos[left] + rotate(table.left_intrados, rot[left])
    b_left = pos[left] + rotate(table.left_extrados, rot[left])
    a_right = pos[right] + rotate(table.right_intrados, rot[right])
    b_right = pos[right] + rotate(table.right_extrados, rot[right])
    mean_rotation = 0.5 * (rot[left] + rot[right])
    normal = rotate(table.normal0, mean_rotation)
    along = rotate(table.along0, mean_rotation)
    origin = 0.5 * (a_left + a_right)

    def coordinates(point: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        offset = point - origin
        return np.einsum("ij,ij->i", offset, along), np.einsum("ij,ij->i", offset, normal)

    (sla, hla), (slb, hlb) = coordinates(a_left), coordinates(b_left)
    (sra, hra), (srb, hrb) = coordinates(a_right), coordinates(b_right)
    start, end = np.maximum(sla, sra), np.minimum(slb, srb)
    shared = end - start

    def height(s: np.ndarray, sa: np.ndarray, ha: np.ndarray, sb: np.ndarray, hb: np.ndarray) -> np.ndarray:
        return ha + (hb - ha) * (s - sa) / (sb - sa)

    def overlap(s: np.ndarray) -> np.ndarray:  # > 0 where the faces interpenetrate
        return height(s, sla, hla, slb, hlb) - height(s, sra, hra, srb, hrb)

    p0, p1 = overlap(start), overlap(end)
    touching = (shared > 0.0) & ((p0 > 0.0) | (p1 > 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        zero_at = np.where(touching, p0 / (p0 - p1), 0.0)  # fraction of `shared` where overlap is 0
    first = np.where(p0 > 0.0, 0.0, zero_at)
    last = np.where(p1 > 0.0, 1.0, zero_at)
    q0, q1 = np.maximum(p0, 0.0), np.maximum(p1, 0.0)
    length = np.where(touching, shared * (last - first), 0.0)
    area = 0.5 * length * (q0 + q1)
    with np.errstate(divide="ignore", invalid="ignore"):
        centroid = start + shared * first + np.where(touching, length * (q0 + 2.0 * q1) / (3.0 * (q0 + q1)), 0.0)
    mid_height = 0.5 * (height(centroid, sla, hla, slb, hlb) + height(centroid, sra, hra, srb, hrb))
    point = origin + centroid[:, None] * along + mid_height[:, None] * normal

    normal_force = law.kn * law.depth * area
    arm_left, arm_right = point - pos[left], point - pos[right]
    velocity_left = vel[left] + ang_vel[left, None] * np.stack([-arm_left[:, 1], arm_left[:, 0]], axis=1)
    velocity_right = vel[right] + ang_vel[right, None] * np.stack([-arm_right[:, 1], arm_right[:, 0]], axis=1)
    slip = np.einsum("ij,ij->i", velocity_right - velocity_left, along) * dt
    cap = law.tan_friction * normal_force
    shear_force = np.where(touching, np.clip(shear - law.ks * law.depth * length * slip, -cap, cap), 0.0)

    force = normal_force[:, None] * normal + shear_force[:, None] * along  # on the right block
    torque_right = arm_right[:, 0] * force[:, 1] - arm_right[:, 1] * force[:, 0]
    torque_left = arm_left[:, 0] * force[:, 1] - arm_left[:, 1] * force[:, 0]
    n = table.n_blocks
    block_force = np.stack([np.bincount(right, force[:, k], n) - np.bincount(left, force[:, k], n)
                            for k in (0, 1)], axis=1)
    block_torque = np.bincount(right, torque_right, n) - np.bincount(left, torque_left, n)
    point = np.where(touching[:, None], point, np.nan)
    return JointForces(normal_force, shear_force, point, normal, length, block_force, block_torque)


def unbalanced_force(forces: JointForces, free: np.ndarray, weights: np.ndarray) -> float:
    """YADE's unbalanced-force ratio for these joints: the mean norm of the resultant force (joints
    plus weight `weights` (n, 2)) on the `free` blocks over the mean norm of the joint forces."""
    contact = np.hypot(forces.normal_force, forces.shear_force)[forces.in_contact]
    if contact.size == 0:
        return float("inf")
    resultant = forces.block_force[free] + weights
    return float(np.mean(np.hypot(resultant[:, 0], resultant[:, 1])) / np.mean(contact))
