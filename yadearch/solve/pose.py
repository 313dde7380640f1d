"""Where the rigid-block limit analysis has the voussoirs at a support displacement, on either branch
of the keystone's tie: the state a DEM scene can be put in to test it (scripts/rigid_state_check.py)."""

from __future__ import annotations

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.model import units
from yadearch.solve.limit import limit_analysis, mirror_image
from yadearch.solve.rigid import rigid_arch

FLIP_X = np.array([-1.0, 1.0])


def rigid_pose(case: ArchCase, at_mm: float, mirrored: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """Every block's centroid (n_blocks, 2; m) and turn (rad) in the rigid analysis of `case` at
    `at_mm` of path; `mirrored`: on the keystone's other branch, solved as the mirror image (the
    other support moving the mirrored way) and reflected back."""
    solved = mirror_image(case) if mirrored else case
    result = limit_analysis(solved, max_settlement_mm=at_mm, mirror=False)
    turns = np.array(result.rotation_rad)
    cos, sin = np.cos(turns), np.sin(turns)
    start = rigid_arch(solved).centroid0
    centroids = np.column_stack([cos * start[:, 0] - sin * start[:, 1], sin * start[:, 0] + cos * start[:, 1]])
    centroids += units.mm(np.array(result.shift_mm))
    if mirrored:  # block k of the mirror image is block n + 1 - k here
        return centroids[::-1] * FLIP_X, -turns[::-1]
    return centroids, turns
