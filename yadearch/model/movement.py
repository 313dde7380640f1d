"""Support movements as rigid motions of the support blocks along a path parameter (pure numpy).

A moving support translates in a fixed direction, turns about a fixed pivot, or follows a
prescribed path (a table of its springing point's displacement and its rotation); the right
support, the left one, or both mirror-symmetrically about the arch's axis (x = 0). The path
parameter lam (m) is the distance its springing point (the middle of its face on the arch) has
travelled: along a straight line for a translation, an arc for a rotation, a polyline for a path. du is lam at
collapse, and its components are the springing point's displacement (docs/movements.md). The engine
drives YADE's support bodies with it and the rigid-block limit analysis places its supports with it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from yadearch.model.geometry import ArchGeometry
from yadearch.model.joints import rotate
from yadearch.model.path_motion import PathMotion

MOVING_SUPPORTS = ("right", "left", "both")
MOTIONS = ("translation", "rotation", "path")
ROTATION_SENSES = ("clockwise", "counterclockwise")
MIN_PIVOT_ARM_FRACTION = 1e-3  # a pivot closer than this x the joint to the springing point is refused
SAME_DIRECTION = 1e-9  # unit translations closer than this are the same direction


@dataclass(frozen=True)
class SupportMotion:
    """One support's rigid motion per unit path: its `pivot` (m, undeformed position) translates by
    `translation` x lam and the block turns by `rotation` x lam (rad per m) about it."""

    translation: np.ndarray
    rotation: float
    pivot: np.ndarray
    springing: np.ndarray  # the middle of the support's face on the arch, undeformed (m)

    def pivot_at(self, lam: float) -> np.ndarray:
        """Where the pivot is at path `lam` (it moves by the translation only)."""
        return self.pivot + self.translation * lam

    def placement(self, lam: float) -> tuple[float, np.ndarray]:
        """(angle, shift) at path `lam`: an undeformed point X of the support is at R(angle) X + shift."""
        angle = self.rotation * lam
        return angle, self.pivot_at(lam) - rotate(self.pivot, angle)

    def carry(self, point: np.ndarray, lam: float) -> np.ndarray:
        """Where the undeformed support point `point` (2,) is at path `lam`."""
        angle, shift = self.placement(lam)
        return rotate(point, angle) + shift

    def rates(self, lam: float) -> np.ndarray:
        """(vx, vy, omega) per unit path rate of the support's material point at the origin: the
        generalised velocity the limit analysis's equilibrium rows are written for."""
        pivot_now = self.pivot_at(lam)
        return np.array(
            [
                self.translation[0] + self.rotation * pivot_now[1],
                self.translation[1] - self.rotation * pivot_now[0],
                self.rotation,
            ]
        )

    def displacement_of(self, point_now: np.ndarray, lam: float, step: float) -> np.ndarray:
        """How far (2,) the support's material point now at `point_now` moves while the path goes
        from `lam` to `lam + step`: exact, so that a rotating support driven step by step keeps its
        pivot in place to round-off."""
        pivot_now = self.pivot_at(lam)
        return self.translation * step + rotate(point_now - pivot_now, self.rotation * step) + pivot_now - point_now

    @property
    def uniform(self) -> bool:
        """The support moves at one constant velocity (a translation) along the whole path."""
        return self.rotation == 0.0

    @property
    def level(self) -> bool:
        """The support slides horizontally without turning."""
        return self.rotation == 0.0 and abs(float(self.translation[1])) < SAME_DIRECTION

    @property
    def corners(self) -> tuple[float, ...]:
        """Path lengths where the direction changes: none."""
        return ()

    @property
    def length(self) -> float:
        """The path has no end."""
        return math.inf

    def angle(self, lam: float) -> float:
        return self.rotation * lam

    def offset(self, lam: float) -> np.ndarray:
        """The springing point's displacement (m) at path `lam`."""
        return self.carry(self.springing, lam) - self.springing

    def velocity(self, point_now: np.ndarray, lam: float, speed: float, dt: float) -> tuple[np.ndarray, float]:
        """The velocity (2,) of the support's material point now at `point_now` and its turn rate
        while the path advances at `speed` for `dt`: a translation's one velocity, or a turn's chord."""
        if self.rotation == 0.0:
            return self.translation * speed, 0.0
        return self.displacement_of(point_now, lam, speed * dt) / dt, self.rotation * speed

    @property
    def horizontal_share(self) -> float:
        """The horizontal component of the springing point's unit direction of travel, at most
        (a turn: at the start, its direction square to the pivot's arm)."""
        if self.rotation == 0.0:
            return abs(float(self.translation[0]))
        arm = self.springing - self.pivot
        return abs(float(arm[1])) / float(np.linalg.norm(arm))

    def travelled(self, centroid0: np.ndarray, centroid: Sequence[float], turn: float, hint: float) -> float:
        """The path length at which the support body whose centroid moved from `centroid0` to
        `centroid` while turning by `turn` stands: its turn over the rate, or its shift along the line."""
        if self.rotation != 0.0:
            return turn / self.rotation
        return float(
            (centroid[0] - centroid0[0]) * self.translation[0] + (centroid[1] - centroid0[1]) * self.translation[1]
        )


Motion = SupportMotion | PathMotion


@dataclass(frozen=True)
class Movement:
    """The motions of the supports that move (None: fixed) and which one measures the path."""

    left: Motion | None
    right: Motion | None

    @property
    def reference(self) -> Motion:
        """The support whose springing point measures the path: the right one when it moves."""
        motion = self.right if self.right is not None else self.left
        assert motion is not None, "a movement moves at least one support"
        return motion

    def motion(self, side: str) -> Motion | None:
        return self.left if side == "left" else self.right

    @property
    def rotates(self) -> bool:
        return any(m is not None and m.rotation != 0.0 for m in (self.left, self.right))

    @property
    def uniform(self) -> bool:
        """Every moving support translates at one constant velocity."""
        return all(m is None or m.uniform for m in (self.left, self.right))

    @property
    def mirror_is_itself(self) -> bool:
        """The mirror image about the arch's axis is this movement up to a rigid translation of the
        whole arch (both supports moving, each the other's mirror image, or one sliding level): a
        tie the keystone breaks either way then cannot change the response."""
        if self.left is not None and self.right is not None:
            return True
        return self.reference.level

    @property
    def horizontal_share(self) -> float:
        """The largest horizontal component of a moving springing point's unit direction of travel."""
        return max(m.horizontal_share for m in (self.left, self.right) if m is not None)

    @property
    def length(self) -> float:
        """Where the path ends (m): a prescribed path's length, else no end."""
        return self.reference.length

    @property
    def corners(self) -> tuple[float, ...]:
        """Path lengths where a prescribed path changes direction (m)."""
        return self.reference.corners

    @property
    def moves_rigidly(self) -> bool:
        """Both supports translate alike: the arch is carried as one rigid body and cannot collapse."""
        if self.left is None or self.right is None or self.rotates:
            return False
        probes = (1.0, *self.corners, *((self.length,) if math.isfinite(self.length) else ()))
        return all(
            np.allclose(self.left.offset(lam), self.right.offset(lam), rtol=0.0, atol=SAME_DIRECTION) for lam in probes
        )

    def components(self, lam: float) -> tuple[float, float]:
        """The reference springing point's displacement (m) at path `lam`."""
        dx, dy = self.reference.offset(lam)
        return float(dx), float(dy)

    def rotation(self, lam: float) -> float:
        """The reference support's rotation (rad, counter-clockwise) at path `lam`."""
        return self.reference.angle(lam)


def _mirror(motion: Motion) -> Motion:
    """The same motion reflected about the arch's axis x = 0."""
    flip = np.array([-1.0, 1.0])
    if isinstance(motion, PathMotion):
        return PathMotion(motion.springing * flip, motion.vertices * flip, -motion.angles, motion.lengths)
    return SupportMotion(motion.translation * flip, -motion.rotation, motion.pivot * flip, motion.springing * flip)


def right_springing_point(geometry: ArchGeometry) -> np.ndarray:
    """The middle of the right support's face on the arch, its last joint (m)."""
    joint = geometry.joints[-1]
    return 0.5 * (np.asarray(joint.intrados[:2]) + np.asarray(joint.extrados[:2]))


def support_movement(
    geometry: ArchGeometry,
    moving_support: str,
    motion: str,
    direction_deg: float,
    pivot_offset: tuple[float, float],
    sense: str,
    path: np.ndarray | None = None,
) -> Movement:
    """The movement a case describes. `direction_deg` (from +x) is the right support's translation;
    `pivot_offset` (m) places the right support's pivot from its springing intrados point and
    `sense` gives its rotation as seen from the front; `path` rows (dx, dy in m, rotation in rad)
    prescribe its path; the left support mirrors the right one."""
    if moving_support not in MOVING_SUPPORTS or motion not in MOTIONS or sense not in ROTATION_SENSES:
        raise ValueError(f"unknown movement {moving_support!r}, {motion!r}, {sense!r}")
    springing = right_springing_point(geometry)
    right: Motion
    if motion == "path":
        if path is None or len(path) == 0:
            raise ValueError("support_motion 'path' needs at least one row in path_mm_mrad")
        right = PathMotion.from_table(springing, np.asarray(path, dtype=float))
    elif motion == "translation":
        angle = math.radians(direction_deg)
        right = SupportMotion(np.array([math.cos(angle), math.sin(angle)]), 0.0, springing.copy(), springing)
    else:
        pivot = np.asarray(geometry.joints[-1].intrados[:2]) + np.asarray(pivot_offset, dtype=float)
        arm = float(np.linalg.norm(springing - pivot))
        if arm < MIN_PIVOT_ARM_FRACTION * geometry.longest_joint:
            raise ValueError("the rotation pivot is the springing point itself: the path would not move")
        turn = (-1.0 if sense == "clockwise" else 1.0) / arm  # the springing point moves at unit speed
        right = SupportMotion(np.zeros(2), turn, pivot, springing)
    left = _mirror(right)
    return Movement(
        left=left if moving_support in ("left", "both") else None,
        right=right if moving_support in ("right", "both") else None,
    )
