"""Voussoir dimension errors applied to an arch's blocks (pure numpy; docs/theory.md, "Imperfections").

Each voussoir is drawn a length error along the arch and a thickness error. The arch is assembled on
its centering between supports that stay where they were designed, so the lengths' errors are taken
relative to the set's mean (the supports' spacing absorbs the mean) and every joint moves along the
intrados by the sum of the errors on its left: its position and its direction change (the joints'
directions interpolated between the nominal neighbours'). A voussoir's intrados bears on the
centering, so a thicker voussoir stands out at the extrados; two faces of different thickness meet
over the shorter one, which sets where an extrados hinge pivots.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.geometry import ArchGeometry, Joint, is_convex_polygon, prism

DIMENSION_STREAM = 1  # the dimension errors' own random stream of a seed: the face defects keep theirs
MAX_SHIFT_FRACTION = 0.45  # a joint may move at most this fraction of the way to its neighbour
MIN_THICKNESS_FRACTION = 0.5  # a voussoir keeps at least this fraction of the ring's thickness


@dataclass(frozen=True)
class DimensionErrors:
    """Per-voussoir errors (m), voussoirs 1..n in order: `length` along the intrados (mean 0),
    `thickness` across the ring."""

    length: np.ndarray
    thickness: np.ndarray

    @property
    def joint_shift(self) -> np.ndarray:
        """How far each of the n+1 joints moves along the intrados, to the right (m)."""
        return np.concatenate([[0.0], np.cumsum(self.length)[:-1], [0.0]])


def draw_dimension_errors(
    n_voussoirs: int, seed: int, length_sd: float, thickness_mean: float, thickness_sd: float
) -> DimensionErrors:
    """Draw every voussoir's errors from `seed`'s DIMENSION_STREAM; the lengths are centred."""
    rng = np.random.default_rng((seed, DIMENSION_STREAM))
    length = rng.normal(0.0, length_sd, n_voussoirs)
    thickness = rng.normal(thickness_mean, thickness_sd, n_voussoirs)
    return DimensionErrors(length - length.mean(), thickness)


def shift_fractions(geometry: ArchGeometry, errors: DimensionErrors) -> np.ndarray:
    """Each joint's shift as a fraction of the intrados chord toward the neighbour it moves to."""
    intrados = np.array([joint.intrados for joint in geometry.joints])
    chords = np.linalg.norm(np.diff(intrados, axis=0), axis=1)
    shift = errors.joint_shift
    toward = np.where(shift >= 0.0, np.append(chords, np.inf), np.insert(chords, 0, np.inf))
    return shift / toward


def with_dimension_errors(geometry: ArchGeometry, errors: DimensionErrors) -> ArchGeometry:
    """The arch built from voussoirs with `errors`; the supports and the springing joints stay.
    ValueError if a joint would move more than MAX_SHIFT_FRACTION toward its neighbour or a voussoir
    would keep less than MIN_THICKNESS_FRACTION of the ring's thickness."""
    fraction = shift_fractions(geometry, errors)
    if np.any(np.abs(fraction) > MAX_SHIFT_FRACTION):
        raise ValueError(
            f"a joint moves {np.abs(fraction).max():.3g} of the way to its neighbour (at most {MAX_SHIFT_FRACTION:g})"
        )
    scale = 1.0 + errors.thickness / geometry.thickness
    if np.any(scale < MIN_THICKNESS_FRACTION):
        raise ValueError(
            f"a voussoir keeps {scale.min():.3g} of the ring's thickness (at least {MIN_THICKNESS_FRACTION:g})"
        )
    starts, directions, lengths = _moved_joints(geometry, fraction)
    n = geometry.n_voussoirs
    face = [lengths[:-1] * scale, lengths[1:] * scale]  # each voussoir's left and right face (m)
    blocks = [geometry.blocks[0]]
    for i in range(n):
        left_out = starts[i] + face[0][i] * directions[i]
        right_out = starts[i + 1] + face[1][i] * directions[i + 1]
        polygon = np.array([starts[i], starts[i + 1], right_out, left_out])
        if not is_convex_polygon(polygon):
            raise ValueError(f"voussoir {i + 1} with these dimension errors is not a convex quadrilateral")
        blocks.append(prism(list(polygon), geometry.depth))
    blocks.append(geometry.blocks[-1])
    # two faces meet over the shorter one; the supports' faces keep the nominal length
    shared = np.minimum(np.concatenate([[lengths[0]], face[1]]), np.concatenate([face[0], [lengths[-1]]]))
    joints = [
        Joint(
            k + 1,
            k,
            k + 1,
            starts[k],
            starts[k] + shared[k] * directions[k],
            np.array([directions[k][1], -directions[k][0]]),
        )
        for k in range(n + 1)
    ]
    middles = np.array([(j.intrados + j.extrados) / 2.0 for j in joints])
    # `thickness` stays the designed ring's: the hinges' rotation scale and the shear law's joint
    # length, the same in a run and in its analysis; the time step takes the narrowest voussoir
    return ArchGeometry(
        blocks,
        joints,
        thickness=geometry.thickness,
        depth=geometry.depth,
        span=geometry.span,
        rise=geometry.rise,
        voussoir_width=float(np.linalg.norm(np.diff(middles, axis=0), axis=1).min()),
        longest_joint=float(max(face[0].max(), face[1].max(), geometry.longest_joint)),
    )


def _moved_joints(geometry: ArchGeometry, fraction: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each joint's intrados point, unit direction across the ring and nominal length, moved
    `fraction` of the way along the intrados chord toward its neighbour (interpolated)."""
    intrados = np.array([joint.intrados for joint in geometry.joints])
    across = np.array([joint.extrados - joint.intrados for joint in geometry.joints])
    lengths = np.linalg.norm(across, axis=1)
    units = across / lengths[:, None]
    neighbour = np.arange(len(intrados)) + np.where(fraction >= 0.0, 1, -1)
    neighbour = np.clip(neighbour, 0, len(intrados) - 1)
    weight = np.abs(fraction)[:, None]
    starts = (1.0 - weight) * intrados + weight * intrados[neighbour]
    blended = (1.0 - weight) * units + weight * units[neighbour]
    directions = blended / np.linalg.norm(blended, axis=1)[:, None]
    return starts, directions, (1.0 - weight[:, 0]) * lengths + weight[:, 0] * lengths[neighbour]
