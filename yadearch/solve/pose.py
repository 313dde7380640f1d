"""Where the rigid-block limit analysis has the voussoirs at a support displacement, on either branch
of the keystone's tie: the state a DEM scene can be put in to test it (scripts/rigid_state_check.py)."""

from __future__ import annotations

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.model import units
from yadearch.solve.limit import limit_analysis
from yadearch.solve.limit_result import LimitResult
from yadearch.solve.mirror import mirror_image
from yadearch.solve.rigid import SIDES, LimitError, Pivot, Placement, at_rest, close_linkage, rigid_arch

FLIP_X = np.array([-1.0, 1.0])


def parse_pivot(label: str) -> Pivot:
    """A hinge label as the paper writes it ("8I": interface 8, intrados pivot) as a rigid pivot."""
    side = label[-1:].upper()
    if side not in SIDES or not label[:-1].isdigit() or int(label[:-1]) < 1:
        raise LimitError(f"hinge {label!r}: expected an interface number and I or E, e.g. 8I")
    return Pivot(int(label[:-1]) - 1, SIDES.index(side))


def linkage_pose(case: ArchCase, at_mm: float, hinges: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    """Every block's centroid (m) and turn (rad) on the three-hinge linkage `hinges` (e.g. ("8I",
    "28E", "46I")) at `at_mm` of path, closed exactly from the undeformed arch: one of the several
    rigid states a support displacement admits, whichever the march passed through."""
    arch = rigid_arch(case)
    placement = close_linkage(arch, at_rest(arch), tuple(parse_pivot(h) for h in hinges), units.mm(at_mm))
    if placement is None:
        raise LimitError(f"the linkage {' '.join(hinges)} cannot reach {at_mm:g} mm")
    return placement.centroids(arch), placement.rot


def rigid_pose(
    case: ArchCase, at_mm: float, mirrored: bool = False, compliant: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """Every block's centroid (n_blocks, 2; m) and turn (rad) in the rigid analysis of `case` at
    `at_mm` of path; `mirrored`: on the keystone's other branch, solved as the mirror image (the
    other support moving the mirrored way) and reflected back; `compliant`: in the compliant-hinge
    march at the case's kn (where the DEM should be)."""
    solved = mirror_image(case) if mirrored else case
    placement, _ = march_placement(solved, at_mm, compliant)
    turns = placement.rot
    centroids = placement.centroids(rigid_arch(solved))
    if mirrored:  # block k of the mirror image is block n + 1 - k here
        return centroids[::-1] * FLIP_X, -turns[::-1]
    return centroids, turns


def march_placement(case: ArchCase, at_mm: float, compliant: bool = False) -> tuple[Placement, LimitResult]:
    """Where the rigid march of `case` (the compliant-hinge march with `compliant`) has the blocks at
    `at_mm` of path, and the march's result (its du_rigid says whether it got there)."""
    result = limit_analysis(case, max_displacement_mm=at_mm, mirror=False, compliant=compliant)
    return Placement(units.mm(at_mm), np.array(result.rotation_rad), units.mm(np.array(result.shift_mm))), result
