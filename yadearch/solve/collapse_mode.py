"""The mechanism at a fold, read from the tangent (pure numpy): the joints that turn in the softest
mode of the last stable state's stiffness are the hinges of the collapse, and how the mode moves them
(turning or sliding, how many hinges) names the kind of collapse (docs/theory.md, "Collapse")."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from yadearch.model.hinges import Hinge, hinge_zones, hinges_at
from yadearch.model.joint_tangent import BLOCK_DOFS
from yadearch.model.joints import joint_states, rotate
from yadearch.model.passive_fill import BLOCK, spring_state
from yadearch.solve import banded
from yadearch.solve.statics import StaticArch

MODE_PROBE = 1e-6  # the mode is applied at this largest block displacement (m): linear, clear of round-off
# A joint turning at least this fraction of the largest turn is a hinge of the motion, and so is a run of
# joints turning one way by this fraction of the largest run's summed turn: a tenth dropped the
# springings' smaller turns (docs/atlas.md, "The collapse's kind").
MODE_HINGE_FRACTION = 0.025
MECHANISM_HINGES = 4  # a rigid arch becomes a mechanism with four hinges (or three and a sliding joint)
OPEN_GAP_FRACTION = 1e-4  # a joint whose faces part by this x its length already pivots on its closed end


class CollapseKind(StrEnum):
    """What the softest mode at the fold does."""

    MECHANISM = "four-hinge mechanism"  # four joints turn: the classical mechanism
    SNAP_THROUGH = "snap-through"  # fewer joints turn: the ring's geometry folds (a shallow arch)
    FILL_HELD = "mechanism held by the fill"  # fewer joints turn, the fill's passive springs holding the rest
    SLIDING = "sliding"  # joints slide more than they open


@dataclass(frozen=True)
class FoldMode:
    """The softest mode of a stable state: its eigenvalue (N/m), hinges, kind."""

    eigenvalue: float
    hinges: tuple[Hinge, ...]
    kind: CollapseKind

    @property
    def labels(self) -> list[str]:
        """The mode's hinges as "12I"."""
        return [h.label for h in self.hinges]


def fold_mode(
    arch: StaticArch,
    u: np.ndarray,
    stiffness: np.ndarray,
    failed: np.ndarray | None = None,
    springs: np.ndarray | None = None,
) -> FoldMode:
    """The collapse mode at the last stable state `u` (the fill's `springs` as it holds them): the
    softest mode of `stiffness` (band storage, free dofs), or, given the state the collapse ran away to
    (`failed`), the motion towards it (the same mode carried to a finite amplitude; a stiff arch's
    softest linear mode can be one joint's own); its hinges (`motion_hinges`) and whether it slides."""
    if failed is not None:
        mode = (failed - u)[arch.free_dofs]  # the way the arch ran away: the loads' work released
    else:
        _, mode = banded.softest_mode(stiffness)
        if float(arch.loads()[arch.free_dofs] @ mode) < 0.0:
            mode = -mode  # an eigenvector's sign: the way the weights go down
    hinges, sliding = motion_hinges(arch, u, mode)
    if sliding:
        kind = CollapseKind.SLIDING
    elif len(hinges) >= MECHANISM_HINGES:
        kind = CollapseKind.MECHANISM
    else:
        kind = CollapseKind.FILL_HELD if _fill_holds(arch, u, mode, springs) else CollapseKind.SNAP_THROUGH
    return FoldMode(banded.smallest_eigenvalue(stiffness), hinges, kind)


def _fill_holds(arch: StaticArch, u: np.ndarray, mode: np.ndarray, springs: np.ndarray | None) -> bool:
    """Some passive spring of the fill (`model.passive_fill`), still elastic at `u`, is pushed by `mode`:
    the mode's other segments lean on the fill, whose yielding adds the mechanism's other hinges."""
    pos, rot = arch.poses(u)
    moved = np.zeros(arch.n_blocks * BLOCK_DOFS)
    moved[arch.free_dofs] = mode
    for spring in arch.springs_or_unyielded(springs):
        block = int(spring[BLOCK])
        _, _, arm_y, tangent = spring_state(spring, pos[block, 0], rot[block])
        motion = moved[BLOCK_DOFS * block] - arm_y * moved[BLOCK_DOFS * block + 2] / arch.length
        if tangent > 0.0 and abs(motion) > MODE_HINGE_FRACTION * np.abs(mode).max():
            return True
    return False


def motion_hinges(arch: StaticArch, u: np.ndarray, mode: np.ndarray) -> tuple[tuple[Hinge, ...], bool]:
    """The hinges the free blocks at `u` turn moving along `mode` (free dofs, probed at MODE_PROBE;
    `_hinges`), and whether the motion slides the joints more than it opens them: a collapse's hinges,
    or those of a branch's last step."""
    moved = u.copy()
    translations = mode.reshape(-1, BLOCK_DOFS)[:, 0:2]
    moved[arch.free_dofs] += MODE_PROBE / float(np.hypot(*translations.T).max() or 1.0) * mode
    opening, slide, open_now = _joint_motion(arch, u, moved)
    turn = opening / arch.table.length
    # a joint already open pivots on the end still in contact, whichever way the mode turns it
    parted = np.abs(open_now) > OPEN_GAP_FRACTION * arch.table.length
    turn = np.where(parted, np.abs(turn) * np.sign(open_now), turn)
    largest = float(np.abs(turn).max())
    hinges = _hinges(turn / largest) if largest > 0.0 else ()
    return hinges, float(np.abs(slide).max()) > float(np.abs(opening).max())


def _hinges(turn: np.ndarray) -> tuple[Hinge, ...]:
    """The joints whose turn peaks at MODE_HINGE_FRACTION of the largest (`hinges_at`), or, where they
    are fewer, the runs of joints turning one way by MODE_HINGE_FRACTION of the largest run's summed
    turn (`hinge_zones`): a hinge spread over many soft joints, each turning a little, is one."""
    peaks = hinges_at(turn, MODE_HINGE_FRACTION)
    zones = hinge_zones(turn, MODE_HINGE_FRACTION)
    return tuple(zones if len(zones) > len(peaks) else peaks)


def _joint_motion(arch: StaticArch, u: np.ndarray, moved: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each joint's change of hinge opening (extrados minus intrados, m; > 0 pivots on the intrados)
    and of sliding along it (m) from `u` to `moved`, and its hinge opening at `u`."""
    rest = arch.centroid0
    no_contact = np.full((len(arch.table.length), 2), np.nan)
    states, slides = [], []
    for state in (u, moved):
        pos, rot = arch.poses(state)
        joints = joint_states(arch.geometry, rest, pos, rot, no_contact)
        states.append(joints.opening_extrados - joints.opening_intrados)
        slides.append(_slide(arch, rest, pos, rot))
    return states[1] - states[0], slides[1] - slides[0], states[0]


def _slide(arch: StaticArch, rest: np.ndarray, pos: np.ndarray, rot: np.ndarray) -> np.ndarray:
    """Each joint's relative displacement along its face at its intrados corner (m)."""
    geometry = arch.geometry
    left = np.array([j.left for j in geometry.joints])
    right = np.array([j.right for j in geometry.joints])
    corner = np.array([j.intrados[:2] for j in geometry.joints])
    along = np.array([j.extrados[:2] for j in geometry.joints]) - corner
    along /= np.linalg.norm(along, axis=1)[:, None]

    def placed(blocks: np.ndarray) -> np.ndarray:
        return pos[blocks] + rotate(corner - rest[blocks], rot[blocks])

    return np.einsum("ij,ij->i", placed(right) - placed(left), along)
