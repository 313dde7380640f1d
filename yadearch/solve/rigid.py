"""A rigid, no-tension voussoir arch placed in the plane (pure numpy): weights, contact corners and
their gaps, and the exact closure of a three-hinge linkage when the right support moves.

A placement moves every block rigidly from the undeformed geometry, X -> R(rot) X + shift. Each
interface has two contact corners, intrados and extrados, carried by both of its blocks; a corner
touches when its two copies coincide (rigid blocks neither overlap nor slide where they touch).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.held import held_multiplier
from yadearch.case.imperfect import arch_imperfections
from yadearch.case.mechanics import arch_geometry, backfill, live_load
from yadearch.case.support import case_movement
from yadearch.errors import YadearchError
from yadearch.model import units
from yadearch.model.backfill import backfill_points
from yadearch.model.geometry import ArchGeometry, block_volume, front_face, polygon_centroid
from yadearch.model.joints import rotate
from yadearch.model.loads import LoadPoints, live_load_points
from yadearch.model.movement import Motion, Movement, SupportMotion
from yadearch.model.passive_fill import passive_springs

INTRADOS, EXTRADOS = 0, 1
SIDES = "IE"  # hinge label of a pivot corner: I = intrados pivot, E = extrados pivot
TOUCH_FRACTION = 1e-7  # corners closer than this fraction of the thickness touch (rigid: round-off)


class LimitError(YadearchError):
    """The arch admits no equilibrium at rest, or moves in a way the limit analysis does not follow."""


class MarchStopped(LimitError):
    """The march started but could not follow the arch further: no du (a failure, never a collapse)."""


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """z component of the cross product of 2-D vectors (..., 2)."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


@dataclass(frozen=True)
class RigidArch:
    """What the limit analysis needs of a case, in SI: per block weight (N) and undeformed centroid;
    per interface its blocks, corners (joint, side, xy) and normal; the supports' movement."""

    geometry: ArchGeometry
    weight: np.ndarray
    centroid0: np.ndarray
    left: np.ndarray
    right: np.ndarray
    corner0: np.ndarray
    normal0: np.ndarray
    movement: Movement
    tan_phi: float
    touch_tol: float
    fixed: LoadPoints  # forces held besides the weights (the backfill, a held live load), undeformed arch
    passive: np.ndarray  # the fill's passive springs (`model.passive_fill`), whose forces are bounded unknowns

    @property
    def n_blocks(self) -> int:
        return len(self.weight)

    @property
    def n_joints(self) -> int:
        return len(self.left)


def rigid_arch(case: ArchCase) -> RigidArch:
    """The rigid model of a case: blocks of density x g x volume, Coulomb friction, no cohesion, the
    backfill's loads and the live load a run holds (`loads.held_load_N`) held on them."""
    geometry = arch_geometry(case)
    unit_weight = units.density(case.material.density_g_per_cm3) * case.loading.gravity_m_per_s2
    weight = np.array([unit_weight * block_volume(b) for b in geometry.blocks])
    centroid0 = np.array([polygon_centroid(front_face(b)) for b in geometry.blocks])
    fill_case = backfill(case)
    fill = backfill_points(geometry, fill_case)
    live = live_load_points(geometry, centroid0, weight, live_load(case, geometry))
    held = held_multiplier(case)
    joints = geometry.joints
    movement = case_movement(case, geometry)
    if movement.moves_rigidly:
        raise LimitError(
            "both supports translate alike (loading.moving_support 'both', "
            f"support_direction_deg {case.loading.support_direction_deg:g}): the arch "
            "is carried as one rigid body and cannot collapse"
        )
    return RigidArch(
        geometry=geometry,
        weight=weight,
        centroid0=centroid0,
        left=np.array([j.left for j in joints]),
        right=np.array([j.right for j in joints]),
        corner0=pivot_corners(case, geometry),
        normal0=np.array([j.normal for j in joints]),
        movement=movement,
        tan_phi=float(np.tan(units.radians(case.material.friction_deg))),
        touch_tol=TOUCH_FRACTION * geometry.thickness,
        fixed=LoadPoints(
            np.concatenate([fill.block, live.block]),
            np.concatenate([fill.point, live.point]),
            np.concatenate([fill.force, held * live.force]),
        ),
        passive=passive_springs(geometry, centroid0, fill_case),
    )


def pivot_corners(case: ArchCase, geometry: ArchGeometry) -> np.ndarray:
    """(joint, side, xy) corners a joint can pivot on: its ends, or, where the voussoirs' edges are
    worn (`[imperfections]` edge_radius_mm), the ends of the faces' shared flat part, moved in along
    the joint by the larger wear of its two faces at that end (a worn edge's pivot sits at the end
    of the wear when the hinge has turned little: docs/theory.md, "Imperfections")."""
    corners = np.array([[j.intrados, j.extrados] for j in geometry.joints])
    drawn = arch_imperfections(case, geometry)
    if drawn is None:
        return corners
    d = drawn.defects
    along = (corners[:, EXTRADOS] - corners[:, INTRADOS]) / drawn.lengths[:, None]
    corners[:, INTRADOS] += np.maximum(d.left_intrados_edge, d.right_intrados_edge)[:, None] * along
    corners[:, EXTRADOS] -= np.maximum(d.left_extrados_edge, d.right_extrados_edge)[:, None] * along
    return corners


@dataclass(frozen=True)
class Placement:
    """Rigid motion of every block from the undeformed geometry at support displacement `delta` (m)."""

    delta: float
    rot: np.ndarray
    shift: np.ndarray

    def place(self, points: np.ndarray, blocks: np.ndarray | int) -> np.ndarray:
        """Current position of undeformed `points` (..., 2) carried by `blocks` (broadcast)."""
        return rotate(points, self.rot[blocks]) + self.shift[blocks]

    def centroids(self, arch: RigidArch) -> np.ndarray:
        return self.place(arch.centroid0, np.arange(arch.n_blocks))


def at_rest(arch: RigidArch) -> Placement:
    return Placement(0.0, np.zeros(arch.n_blocks), np.zeros((arch.n_blocks, 2)))


@dataclass(frozen=True)
class Contacts:
    """Interfaces in a placement: corner points (joint, side, xy) as carried by the left block, unit
    normal (left -> right) and tangent (intrados -> extrados), normal gaps (m, > 0 open), touching."""

    point: np.ndarray
    normal: np.ndarray
    tangent: np.ndarray
    gap: np.ndarray
    touching: np.ndarray


def contacts(arch: RigidArch, placement: Placement) -> Contacts:
    """Corners, directions and gaps of every interface. Where a hinge has opened the two faces are no
    longer parallel; the normal is then their bisector, the direction of a corner-to-corner contact."""
    a = placement.place(arch.corner0, arch.left[:, None])
    b = placement.place(arch.corner0, arch.right[:, None])
    n_left = rotate(arch.normal0, placement.rot[arch.left])
    n_right = rotate(arch.normal0, placement.rot[arch.right])
    normal = n_left + n_right
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    tangent = np.stack([-normal[:, 1], normal[:, 0]], axis=1)
    gap = np.einsum("jsk,jk->js", b - a, normal)
    touching = np.linalg.norm(b - a, axis=2) <= arch.touch_tol
    return Contacts(a, normal, tangent, gap, touching)


@dataclass(frozen=True, order=True)
class Pivot:
    """A hinge of a mechanism: 0-based interface index and the corner it pivots about."""

    joint: int
    side: int

    @property
    def label(self) -> str:
        """The paper's label: interface number (1-based) and pivot side, e.g. '9I'."""
        return f"{self.joint + 1}{SIDES[self.side]}"

    def __repr__(self) -> str:  # the label, not the 0-based index a reader would misread
        return f"Pivot({self.label!r})"


def close_linkage(arch: RigidArch, placement: Placement, pivots: tuple[Pivot, ...], delta: float) -> Placement | None:
    """The placement at support displacement `delta` reached along a three-hinge mechanism, exactly.

    Blocks left of the first hinge move with the left support, those right of the third with the
    right support (either may stand still), the two segments between are rigid bars P1-P2 and P2-P3
    whose new middle pivot is the intersection of two circles (no time integration, so no drift);
    None when the bars cannot reach."""
    if len(pivots) != 3:
        raise ValueError(f"a three-hinge linkage needs three pivots, got {len(pivots)}")
    p1, p2, p3 = sorted(pivots)
    old = [_pivot_point(arch, placement, p) for p in (p1, p2, p3)]
    left, right = (
        SupportStep.between(arch.movement.motion(side), placement.delta, delta) for side in ("left", "right")
    )
    first, last = left.carry(old[0]), right.carry(old[2])
    middle = _middle_joint(old[0], old[1], old[2], first, last)
    if middle is None:
        return None
    new = [first, middle, last]
    rot, shift = placement.rot.copy(), placement.shift.copy()
    _move(rot, shift, slice(p1.joint + 1, p2.joint + 1), old[:2], new[:2])
    _move(rot, shift, slice(p2.joint + 1, p3.joint + 1), old[1:], new[1:])
    left.move(rot, shift, slice(None, p1.joint + 1))
    right.move(rot, shift, slice(p3.joint + 1, None))
    return replace(placement, delta=delta, rot=rot, shift=shift)


@dataclass(frozen=True)
class SupportStep:
    """A support's rigid step between two path lengths: a point P it carries goes to
    R(turn) (P - before) + after."""

    turn: float
    before: np.ndarray
    after: np.ndarray

    @classmethod
    def between(cls, motion: Motion | None, start: float, end: float) -> SupportStep:
        """The step of `motion` from path `start` to `end` (none for a fixed support); a support
        that does not turn translates by exactly its translation's difference."""
        if motion is None:
            return cls(0.0, np.zeros(2), np.zeros(2))
        if motion.rotation == 0.0:
            if isinstance(motion, SupportMotion):
                return cls(0.0, np.zeros(2), (end - start) * motion.translation)
            return cls(0.0, np.zeros(2), motion.offset(end) - motion.offset(start))
        (turn0, shift0), (turn1, shift1) = motion.placement(start), motion.placement(end)
        return cls(turn1 - turn0, shift0, shift1)

    def carry(self, point: np.ndarray) -> np.ndarray:
        return rotate(point - self.before, self.turn) + self.after

    def move(self, rot: np.ndarray, shift: np.ndarray, blocks: slice) -> None:
        """Carry `blocks` (their rotations and shifts, in place) with the support."""
        rot[blocks] += self.turn
        shift[blocks] = self.carry(shift[blocks])


def turn_four_bar(arch: RigidArch, placement: Placement, pivots: tuple[Pivot, ...], angle: float) -> Placement | None:
    """The placement reached at a fixed support along a four-hinge mechanism whose first segment
    turns by `angle` (rad) about the first pivot: the other two segments close the chain exactly."""
    if len(pivots) != 4:
        raise ValueError(f"a four-bar chain needs four pivots, got {len(pivots)}")
    q = sorted(pivots)
    old = [_pivot_point(arch, placement, p) for p in q]
    new = [old[0], old[0] + rotate(old[1] - old[0], angle), None, old[3]]
    new[2] = _middle_joint(old[1], old[2], old[3], new[1], new[3])
    if new[2] is None:
        return None
    rot, shift = placement.rot.copy(), placement.shift.copy()
    for k in range(3):
        _move(rot, shift, slice(q[k].joint + 1, q[k + 1].joint + 1), old[k : k + 2], new[k : k + 2])
    return replace(placement, rot=rot, shift=shift)


def _pivot_point(arch: RigidArch, placement: Placement, pivot: Pivot) -> np.ndarray:
    return placement.place(arch.corner0[pivot.joint, pivot.side], arch.left[pivot.joint])


def _middle_joint(
    first: np.ndarray, middle: np.ndarray, last: np.ndarray, new_first: np.ndarray, new_last: np.ndarray
) -> np.ndarray | None:
    """Where the joint of two rigid bars first-middle and middle-last goes when their ends move to
    `new_first`, `new_last`: the intersection of two circles on the current branch (None: none)."""
    bar1, bar2 = np.linalg.norm(middle - first), np.linalg.norm(middle - last)
    chord = new_last - new_first
    span = float(np.linalg.norm(chord))
    if not abs(bar1 - bar2) < span < bar1 + bar2:
        return None
    along = (bar1**2 - bar2**2 + span**2) / (2.0 * span)
    height = np.sqrt(max(float(bar1**2 - along**2), 0.0))
    unit = chord / span
    branch = np.sign(cross(last - first, middle - first))
    return new_first + along * unit + branch * height * np.array([-unit[1], unit[0]])


def _move(rot: np.ndarray, shift: np.ndarray, blocks: slice, old: list[np.ndarray], new: list[np.ndarray]) -> None:
    """Move `blocks` rigidly so that the segment old[0]-old[1] they carry lands on new[0]-new[1]."""
    before, after = old[1] - old[0], new[1] - new[0]
    angle = float(np.arctan2(cross(before, after), np.dot(before, after)))
    rot[blocks] += angle
    shift[blocks] = new[0] + rotate(shift[blocks] - old[0], angle)
