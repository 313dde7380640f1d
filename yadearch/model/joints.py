"""Per-interface kinematics in pure numpy: relative rotation, intrados/extrados opening and where the
contact force sits across each joint, from the rigid-body states of the blocks.

A material point X of block b (undeformed position) is now at pos_b + Rz(rot_b) (X - pos0_b): blocks
move in the x-y plane and rotate about z only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from yadearch.model.geometry import ArchGeometry, front_face


@dataclass(frozen=True)
class JointState:
    """Arrays over the n+1 interfaces (index k = interface k+1), SI units.

    opening_*: gap normal to the joint at its intrados / extrados end (m, > 0 open, < 0 overlap);
    rotation: rotation of the right block minus the left block (rad, > 0 counter-clockwise);
    force_position: contact-force point across the joint, 0 = intrados, 1 = extrados (NaN if none).
    """

    rotation: np.ndarray
    opening_intrados: np.ndarray
    opening_extrados: np.ndarray
    force_position: np.ndarray


def rotate(vectors: np.ndarray, angles: np.ndarray | float) -> np.ndarray:
    """Rotate 2-D `vectors` (..., 2) about z by `angles` (rad), element by element (broadcast over the
    leading axes)."""
    if isinstance(angles, float) and np.ndim(vectors) == 1:  # one point: the path places supports so
        cos, sin = math.cos(angles), math.sin(angles)  # hundreds of times a run
        return np.array([cos * vectors[0] - sin * vectors[1], sin * vectors[0] + cos * vectors[1]])
    c, s = np.cos(angles), np.sin(angles)
    x, y = vectors[..., 0], vectors[..., 1]
    return np.stack([c * x - s * y, s * x + c * y], axis=-1)


def z_rotation(ori: np.ndarray, ori0: np.ndarray) -> np.ndarray:
    """Rotation angle about z of ori * conj(ori0) for arrays of (w, x, y, z) quaternions (rad)."""
    w0, x0, y0, z0 = ori0.T
    w1, x1, y1, z1 = ori.T
    # q = q1 * conj(q0); only w and z are needed for a rotation about z
    w = w1 * w0 + x1 * x0 + y1 * y0 + z1 * z0
    z = -w1 * z0 - x1 * y0 + y1 * x0 + z1 * w0
    return 2.0 * np.arctan2(z, w)


@njit(cache=True)
def pair_rotation(pair: np.ndarray, pair0: np.ndarray) -> np.ndarray:
    """Rotation angle about z (rad) of blocks from one pair of their quaternions' components, (w, z)
    or (x, y) (n, 2), and the same pair at the start: turning by t about z maps the pair (a0, b0)
    to (a0 cos t/2 - b0 sin t/2, b0 cos t/2 + a0 sin t/2)."""
    angles = np.empty(pair.shape[0])
    for k in range(pair.shape[0]):
        a, b, a0, b0 = pair[k, 0], pair[k, 1], pair0[k, 0], pair0[k, 1]
        angles[k] = 2.0 * math.atan2(a0 * b - b0 * a, a0 * a + b0 * b)
    return angles


def joint_states(
    geometry: ArchGeometry, pos0: np.ndarray, pos: np.ndarray, rot: np.ndarray, contact_points: np.ndarray
) -> JointState:
    """Kinematics of every joint; `pos0`, `pos` (n_blocks, >=2), `rot` (n_blocks,) in geometry
    order, `contact_points` (n_joints, 2) with NaN rows for joints without contact."""
    left = np.array([j.left for j in geometry.joints])
    right = np.array([j.right for j in geometry.joints])
    intrados = np.array([j.intrados for j in geometry.joints])
    extrados = np.array([j.extrados for j in geometry.joints])
    normals = np.array([j.normal for j in geometry.joints])

    def placed(points: np.ndarray, blocks: np.ndarray) -> np.ndarray:
        return pos[blocks, :2] + rotate(points - pos0[blocks, :2], rot[blocks])

    a_in, a_ex = placed(intrados, left), placed(extrados, left)
    b_in, b_ex = placed(intrados, right), placed(extrados, right)
    normal_now = rotate(normals, rot[left])
    across = a_ex - a_in
    position = np.einsum("ij,ij->i", contact_points - a_in, across) / np.einsum("ij,ij->i", across, across)
    return JointState(
        rotation=rot[right] - rot[left],
        opening_intrados=np.einsum("ij,ij->i", b_in - a_in, normal_now),
        opening_extrados=np.einsum("ij,ij->i", b_ex - a_ex, normal_now),
        force_position=position,
    )


def block_outlines(geometry: ArchGeometry, pos0: np.ndarray, pos: np.ndarray, rot: np.ndarray) -> list[np.ndarray]:
    """Current x-y outline (front face) of every block, for drawing the deformed arch."""
    outlines = []
    for b, vertices in enumerate(geometry.blocks):
        front = front_face(vertices)
        outlines.append(pos[b, :2] + rotate(front - pos0[b, :2], np.full(len(front), rot[b])))
    return outlines
