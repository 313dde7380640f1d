"""Geometric imperfections of the voussoirs' joint faces as initial gap profiles (pure numpy).

A dry joint between imperfect faces does not close at once: at abscissa s across the joint the two
faces stand apart by a gap g(s) >= 0, and the Winkler pressure is kn max(0, closure(s) - g(s))
(docs/theory.md, "Imperfections"). Three kinds of defect build g, each drawn per edge or per joint
from one seed so that one seed gives one geometry:

- worn edges: the intrados and extrados edges of each voussoir face rounded (a quarter circle) or
  chamfered (45 deg): the contact cannot reach the corner and a hinge's pivot moves inward;
- faces not parallel: an angle between a joint's two faces, a wedge that touches at one end;
- faces not flat: a convex (touching mid-joint) or hollow (touching at the ends) parabolic bump;
- voussoirs set lower or higher (an assembly error, per voussoir, and the keystone's own): a
  voussoir whose faces bear on its neighbours' offset along the joints (a voussoir a hair narrower
  than its neighbours' gap drops until its faces bear), so the faces share less of their length;
- a support set askew (an assembly error): its face turned against the first or last voussoir's,
  a wedge at the springing joint added to that joint's drawn face angle;
- voussoirs longer, shorter, thicker or thinner than designed: the blocks themselves change
  (`model/dimensions.py`), and the defects above are drawn on the joints they make.

The two faces of a joint add their gaps; the profile is then shifted so that its smallest gap is 0
(the blocks are assembled touching). The support blocks' faces are perfect.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.units import to_mm, to_mrad

ROUND, CHAMFER = "round", "chamfer"
EDGE_NODES = 17  # profile nodes across each worn edge (chords of the rounding 5.6 deg apart: they stand
# off the quarter circle by at most 0.12 % of its radius)
MIDDLE_NODES = 33  # profile nodes between the two worn edges (the bump is piecewise linear between them)
PROFILE_NODES = 2 * EDGE_NODES + MIDDLE_NODES
MAX_EDGE_FRACTION = 0.45  # an edge's wear may take at most this fraction of a joint's length


@dataclass(frozen=True)
class ImperfectionAmplitudes:
    """The imperfection model's parameters in SI (m, rad): each a mean and a standard deviation."""

    edge_shape: str = ROUND
    edge_size: float = 0.0
    edge_size_sd: float = 0.0
    face_angle: float = 0.0
    face_angle_sd: float = 0.0
    face_bump: float = 0.0
    face_bump_sd: float = 0.0
    voussoir_offset: float = 0.0  # every voussoir set higher (> 0, toward the extrados) or lower
    voussoir_offset_sd: float = 0.0
    keystone_offset: float = 0.0  # the crown's voussoir (both middle ones for an even count), in addition
    left_support_angle: float = 0.0  # a support set askew: its face turned against the voussoir's (rad)
    right_support_angle: float = 0.0
    voussoir_length_sd: float = 0.0  # each voussoir's length error along the arch (`model.dimensions`)
    voussoir_thickness: float = 0.0  # each voussoir thicker (> 0) or thinner than the ring
    voussoir_thickness_sd: float = 0.0

    @property
    def perfect(self) -> bool:
        return self.perfect_faces and self.perfect_dimensions

    @property
    def perfect_faces(self) -> bool:
        """No defect of the joint faces or of the assembly."""
        return self.flat_aligned_faces and not (self.edge_size or self.edge_size_sd)

    @property
    def flat_aligned_faces(self) -> bool:
        """Faces flat, parallel and aligned (worn edges aside): what the rigid analysis represents."""
        return not any(
            (
                self.face_angle,
                self.face_angle_sd,
                self.face_bump,
                self.face_bump_sd,
                self.voussoir_offset,
                self.voussoir_offset_sd,
                self.keystone_offset,
                self.left_support_angle,
                self.right_support_angle,
            )
        )

    @property
    def perfect_dimensions(self) -> bool:
        """Every voussoir of its designed length and thickness."""
        return not any((self.voussoir_length_sd, self.voussoir_thickness, self.voussoir_thickness_sd))

    @property
    def mirror_symmetric(self) -> bool:
        """Every defect its own mirror image about the crown's axis: nothing drawn at random, no face
        tilted or bumped (a tilt turns the same way at every joint), both supports set alike."""
        drawn = (
            self.edge_size_sd,
            self.face_angle_sd,
            self.face_bump_sd,
            self.voussoir_offset_sd,
            self.voussoir_length_sd,
            self.voussoir_thickness_sd,
        )
        tilted = self.face_angle or self.face_bump
        return not (any(drawn) or tilted) and self.left_support_angle == self.right_support_angle


@dataclass(frozen=True)
class JointDefects:
    """The defects drawn for each joint (arrays over joints, SI). Edge sizes are per face: the left
    block's face (its right end) and the right block's face, at the intrados and at the extrados."""

    left_intrados_edge: np.ndarray
    left_extrados_edge: np.ndarray
    right_intrados_edge: np.ndarray
    right_extrados_edge: np.ndarray
    face_angle: np.ndarray
    face_bump: np.ndarray
    edge_shape: str
    left_offset: np.ndarray  # how far the left block's face sits toward the extrados (m; supports 0)
    right_offset: np.ndarray  # the same for the right block's face

    @property
    def n_joints(self) -> int:
        return len(self.face_angle)


@dataclass(frozen=True)
class GapProfiles:
    """Each joint's initial gap (m) at nodes given as fractions of its length from the intrados
    (0) to the extrados (1); `imperfect` marks the joints whose gap is not zero everywhere."""

    fraction: np.ndarray  # (n_joints, PROFILE_NODES), non-decreasing along each row
    gap: np.ndarray  # (n_joints, PROFILE_NODES), >= 0, smallest 0
    imperfect: np.ndarray  # (n_joints,) bool
    left_offset: np.ndarray  # (n_joints,) the faces' offsets along the joint (m, `JointDefects`)
    right_offset: np.ndarray


def draw_defects(amplitudes: ImperfectionAmplitudes, n_joints: int, seed: int, lengths: np.ndarray) -> JointDefects:
    """Draw every joint's defects from `seed`. The first and last joints (against the supports) get
    the voussoir's face defects on their voussoir side only. Edge sizes below 0 count as 0 and
    above MAX_EDGE_FRACTION of the joint's length are capped there."""
    rng = np.random.default_rng(seed)
    cap = MAX_EDGE_FRACTION * np.asarray(lengths, dtype=float)

    def edges() -> np.ndarray:
        drawn = rng.normal(amplitudes.edge_size, amplitudes.edge_size_sd, n_joints)
        return np.clip(drawn, 0.0, cap)

    left_in, left_out, right_in, right_out = edges(), edges(), edges(), edges()
    left_in[0] = left_out[0] = 0.0  # the left support's face
    right_in[-1] = right_out[-1] = 0.0  # the right support's face
    angle = rng.normal(amplitudes.face_angle, amplitudes.face_angle_sd, n_joints)
    bump = rng.normal(amplitudes.face_bump, amplitudes.face_bump_sd, n_joints)
    voussoirs = rng.normal(amplitudes.voussoir_offset, amplitudes.voussoir_offset_sd, n_joints - 1)
    voussoirs[keystones(n_joints - 1)] += amplitudes.keystone_offset
    angle[0] += amplitudes.left_support_angle  # a support set askew wedges its springing joint
    angle[-1] += amplitudes.right_support_angle
    blocks = np.concatenate([[0.0], voussoirs, [0.0]])  # the supports sit where they were designed
    return JointDefects(
        left_in, left_out, right_in, right_out, angle, bump, amplitudes.edge_shape, blocks[:-1], blocks[1:]
    )


def keystones(n_voussoirs: int) -> list[int]:
    """0-based index of the crown's voussoir: the middle one, or both middle ones for an even count."""
    middle = n_voussoirs // 2
    return [middle] if n_voussoirs % 2 else [middle - 1, middle]


def edge_gap(depth_into_edge: np.ndarray, size: float | np.ndarray, shape: str) -> np.ndarray:
    """How far a worn edge of `size` stands back from the face plane at a distance from the corner
    (0 at and beyond `size`; sizes broadcast against distances): a quarter circle of radius `size`,
    or a 45 deg chamfer."""
    inside = np.clip(size - depth_into_edge, 0.0, None)
    if shape == CHAMFER:
        return inside
    return size - np.sqrt(np.clip(size**2 - inside**2, 0.0, None))


def joint_gaps(s: np.ndarray, lengths: np.ndarray, defects: JointDefects) -> np.ndarray:
    """The gaps (m) of every joint (rows) at abscissae `s` (n_joints, nodes; m from the intrados),
    before the shift that makes each row's smallest value 0."""
    shape = defects.edge_shape
    length = lengths[:, None]
    gap = (
        edge_gap(s, defects.left_intrados_edge[:, None], shape)
        + edge_gap(s, defects.right_intrados_edge[:, None], shape)
        + edge_gap(length - s, defects.left_extrados_edge[:, None], shape)
        + edge_gap(length - s, defects.right_extrados_edge[:, None], shape)
    )
    angle = defects.face_angle[:, None]
    gap = gap + np.where(angle >= 0, angle * s, -angle * (length - s))
    bump = defects.face_bump[:, None]
    centred = (2.0 * s / length - 1.0) ** 2
    return gap + np.where(bump >= 0, bump * centred, -bump * (1.0 - centred))


def wedge_openings(defects: JointDefects, lengths: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """How far the real faces of each joint stand apart at its intrados and extrados ends when the
    nominal faces touch, from the faces' angle alone (m): what a joint's opening and hinge rotation
    add so that a wedge closed flat under load counts as closed, not as a hinge. Worn edges and
    bumps do not tilt the face and add nothing."""
    wedge = defects.face_angle * np.asarray(lengths, dtype=float)
    return np.clip(-wedge, 0.0, None), np.clip(wedge, 0.0, None)


def profile_fractions(lengths: np.ndarray, intrados_edges: np.ndarray, extrados_edges: np.ndarray) -> np.ndarray:
    """PROFILE_NODES fractions of each joint (rows): EDGE_NODES across each worn edge, MIDDLE_NODES
    evenly between."""
    lo, hi = intrados_edges / lengths, 1.0 - extrados_edges / lengths
    # evenly spaced in the rounding's angle: a hinge turned by a touches a rounded edge where its
    # slope is a, and the chords then follow the quarter circle equally well at every rotation
    bend = 1.0 - np.sin(np.linspace(np.pi / 2, 0.0, EDGE_NODES))  # 0 (corner) -> 1 (edge's end)
    inner = lo[:, None] * bend
    middle = np.linspace(lo, hi, MIDDLE_NODES + 2, axis=1)[:, 1:-1]
    outer = 1.0 - (1.0 - hi[:, None]) * bend[::-1]
    return np.concatenate([inner, middle, outer], axis=1)


def gap_profiles(defects: JointDefects, lengths: np.ndarray) -> GapProfiles:
    """The joints' gap profiles from their drawn defects."""
    lengths = np.asarray(lengths, dtype=float)
    intrados = np.maximum(defects.left_intrados_edge, defects.right_intrados_edge)
    extrados = np.maximum(defects.left_extrados_edge, defects.right_extrados_edge)
    fraction = profile_fractions(lengths, intrados, extrados)
    raw = joint_gaps(fraction * lengths[:, None], lengths, defects)
    gap = raw - raw.min(axis=1, keepdims=True)
    return GapProfiles(fraction, gap, gap.max(axis=1) > 0.0, defects.left_offset, defects.right_offset)


def defects_table(defects: JointDefects, profiles: GapProfiles, lengths: np.ndarray) -> dict[str, np.ndarray]:
    """One row per joint, in the user's units (mm, mrad), for the run folder's imperfections.csv."""
    return {
        "interface": np.arange(1, defects.n_joints + 1),
        "left_intrados_edge_mm": to_mm(defects.left_intrados_edge),
        "left_extrados_edge_mm": to_mm(defects.left_extrados_edge),
        "right_intrados_edge_mm": to_mm(defects.right_intrados_edge),
        "right_extrados_edge_mm": to_mm(defects.right_extrados_edge),
        "face_angle_mrad": to_mrad(defects.face_angle),
        "face_bump_mm": to_mm(defects.face_bump),
        "left_face_offset_mm": to_mm(defects.left_offset),
        "right_face_offset_mm": to_mm(defects.right_offset),
        "largest_gap_mm": to_mm(profiles.gap.max(axis=1)),
        "first_contact_mm": to_mm(_first_contact(profiles) * lengths),
    }


def _first_contact(profiles: GapProfiles) -> np.ndarray:
    """Fraction of each joint's length from the intrados where its faces first touch."""
    rows = np.arange(len(profiles.gap))
    return profiles.fraction[rows, np.argmin(profiles.gap, axis=1)]
