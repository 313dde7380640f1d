"""The joints of a scene as arrays (no YADE): each joint's blocks, its faces' intrados points relative
to the blocks' initial centroids, its initial normal, direction and length, and its initial gap
profile, in the order the compiled joint law (`joint_law`) takes them."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.geometry import ArchGeometry
from yadearch.model.imperfections import GapProfiles


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
    gap_fraction: np.ndarray  # (n_joints, nodes): initial gap profile nodes, fractions of the length
    gap: np.ndarray  # (n_joints, nodes): initial gap between the faces at those nodes (m)
    imperfect: np.ndarray  # (n_joints,) bool: the joints with a gap profile (the others take the
    # closed form of a perfect joint)

    def kernel_geometry(self) -> tuple:
        """The arrays the compiled kernels take first, in their order."""
        return (
            self.left,
            self.right,
            self.left_intrados,
            self.right_intrados,
            self.normal0,
            self.along0,
            self.length,
            self.handedness,
            self.n_blocks,
        )

    def kernel_gaps(self) -> tuple:
        """The initial gap profiles, the compiled kernels' last arguments."""
        return self.gap_fraction, self.gap, self.imperfect


def joint_table(geometry: ArchGeometry, centroids0: np.ndarray, profiles: GapProfiles | None = None) -> JointTable:
    """Arrays of `geometry.joints` relative to the blocks' initial centroids (n_blocks, >=2), with
    the joints' initial gap profiles (`model.imperfections`; None: perfect faces)."""
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
    left_point, right_point = intrados - c0[left], intrados - c0[right]
    if profiles is None:
        fraction, gap, imperfect = np.zeros((len(joints), 2)), np.zeros((len(joints), 2)), np.zeros(len(joints), bool)
    else:
        # a face offset along the joint moves that face's intrados point (the faces keep their length)
        left_point = left_point + profiles.left_offset[:, None] * along
        right_point = right_point + profiles.right_offset[:, None] * along
        fraction, gap, imperfect = profiles.fraction, profiles.gap, profiles.imperfect
    return JointTable(
        left,
        right,
        left_point,
        right_point,
        normal,
        along,
        length,
        handedness,
        np.concatenate([right, left]),
        len(centroids0),
        fraction,
        gap,
        imperfect,
    )
