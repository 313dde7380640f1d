"""Arch geometry in pure numpy: voussoir and support-block vertices, joint planes.

Conventions (DESIGN.md §2): arch in the x-y plane, y up, depth along z, symmetric about x = 0; the
segmental arch has the centre of its intrados circle at the origin, the other shapes
(`model/intrados.py`) their springing line on y = 0. Voussoirs 1..n and interfaces 1..n+1 are numbered
left to right. All lengths here are in metres; the case converts from the user's millimetres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from yadearch.model.intrados import Intrados, extrados_end, joint_direction, stations

QUADRILATERAL_PRISM = 8  # corners of a block on a quadrilateral: 4 in front, 4 behind


@dataclass(frozen=True)
class Joint:
    """A plane interface between two blocks, in the undeformed configuration.

    `intrados` and `extrados` are the joint's end points in the x-y plane (z = 0), `normal` the unit
    normal pointing from the left body to the right body. `left` and `right` are block indices in
    `ArchGeometry.blocks` order (0 = left support, 1..n = voussoirs, n+1 = right support).
    """

    number: int
    left: int
    right: int
    intrados: np.ndarray
    extrados: np.ndarray
    normal: np.ndarray

    @property
    def length(self) -> float:
        """Joint length across the arch thickness (m)."""
        return float(np.linalg.norm(self.extrados - self.intrados))


@dataclass(frozen=True)
class ArchGeometry:
    """All blocks of an arch on two supports: `blocks[0]` left support, `blocks[1..n]` voussoirs,
    `blocks[n+1]` right support; each block is an (8, 3) array of prism vertices (m)."""

    blocks: list[np.ndarray]
    joints: list[Joint]
    thickness: float  # ring thickness, normal to the intrados (m)
    depth: float
    span: float  # net (intrados) span between the springings (m)
    rise: float  # intrados rise from the springing line to the crown (m)
    voussoir_width: float  # of the narrowest voussoir, between its joints' mid-points (m)
    longest_joint: float  # across the ring (m): the thickness where joints are normal to the intrados

    @property
    def n_voussoirs(self) -> int:
        return len(self.blocks) - 2

    @property
    def voussoirs(self) -> list[np.ndarray]:
        return self.blocks[1:-1]

    @property
    def crown_voussoir(self) -> int:
        """1-based number of the voussoir at (or just left of) the crown."""
        return (self.n_voussoirs + 1) // 2


def _radial(angle: float, radius: float) -> np.ndarray:
    return np.array([radius * np.cos(angle), radius * np.sin(angle)])


def prism(polygon_xy: list[np.ndarray], depth: float) -> np.ndarray:
    """Extrude a convex x-y polygon symmetrically along z into prism vertices."""
    half = depth / 2.0
    front = [np.array([p[0], p[1], -half]) for p in polygon_xy]
    back = [np.array([p[0], p[1], half]) for p in polygon_xy]
    return np.array(front + back)


def segmental_arch(
    n_voussoirs: int,
    embrace_deg: float,
    internal_radius: float,
    thickness: float,
    depth: float,
    support_length: float,
) -> ArchGeometry:
    """Build a symmetric segmental arch of trapezoidal voussoirs with radial joints on two
    support blocks whose faces lie exactly on the springing planes."""
    if not 0 < embrace_deg <= 180:
        raise ValueError(f"embrace_deg must be in (0, 180], got {embrace_deg}")
    embrace = np.radians(embrace_deg)
    theta_left = np.pi / 2 + embrace / 2
    joint_angles = theta_left - embrace * np.arange(n_voussoirs + 1) / n_voussoirs
    r_in, r_out = internal_radius, internal_radius + thickness

    blocks: list[np.ndarray] = []
    left_angle = joint_angles[0]
    outward_left = np.array([-np.sin(left_angle), np.cos(left_angle)])
    blocks.append(
        _support_prism(_radial(left_angle, r_in), _radial(left_angle, r_out), outward_left, support_length, depth)
    )
    for a, b in zip(joint_angles[:-1], joint_angles[1:]):
        polygon = [_radial(a, r_in), _radial(b, r_in), _radial(b, r_out), _radial(a, r_out)]
        blocks.append(prism(polygon, depth))
    right_angle = joint_angles[-1]
    outward_right = np.array([np.sin(right_angle), -np.cos(right_angle)])
    blocks.append(
        _support_prism(_radial(right_angle, r_in), _radial(right_angle, r_out), outward_right, support_length, depth)
    )

    joints = []
    for k, angle in enumerate(joint_angles):
        normal = np.array([np.sin(angle), -np.cos(angle)])  # direction of decreasing angle
        joints.append(Joint(k + 1, k, k + 1, _radial(angle, r_in), _radial(angle, r_out), normal))
    springing = (np.pi - embrace) / 2.0  # angle of the springing planes above the horizontal
    width = 2.0 * (internal_radius + thickness / 2.0) * math.sin(embrace / n_voussoirs / 2.0)
    return ArchGeometry(
        blocks,
        joints,
        thickness,
        depth,
        span=float(2.0 * internal_radius * np.cos(springing)),
        rise=float(internal_radius * (1.0 - np.sin(springing))),
        voussoir_width=float(width),
        longest_joint=thickness,
    )


def arch_on_intrados(
    intrados: Intrados, n_voussoirs: int, orientation: str, thickness: float, depth: float, support_length: float
) -> ArchGeometry:
    """An arch of any shape (`model/intrados.py`): voussoirs of equal intrados length whose joints run
    normal to the intrados, vertically or radially across a ring `thickness` thick (normal to the
    intrados), on two support blocks whose faces lie on the springing joints."""
    ends = []
    for station in stations(intrados, n_voussoirs):
        direction = joint_direction(station, orientation)
        ends.append((station.point, extrados_end(intrados, station, direction, thickness)))
    return arch_from_joints(ends, depth, support_length, thickness, intrados.span, intrados.rise)


@dataclass(frozen=True)
class FacePoints:
    """A voussoir's corners between its two joints (m, left to right, each (k, 2)): on its intrados face
    (a springer's upright face) and on its extrados face (a curved extrados, a springer's back); none:
    a quadrilateral."""

    intrados: np.ndarray
    extrados: np.ndarray


class NotConvexError(ValueError):
    """A voussoir whose corners do not make a convex polygon; `face_corners`: it has corners between its
    joints' (the faces' fault, or the joints')."""

    def __init__(self, message: str, face_corners: bool):
        super().__init__(message)
        self.face_corners = face_corners


def arch_from_joints(
    ends: list[tuple[np.ndarray, np.ndarray]],
    depth: float,
    support_length: float,
    thickness: float,
    span: float,
    rise: float,
    faces: dict[int, FacePoints] | None = None,
) -> ArchGeometry:
    """An arch from its joints' (intrados, extrados) end points, left to right: convex voussoirs between
    consecutive joints (quadrilaterals, or polygons with the `faces` corners of voussoir k = 1..n), on
    two support blocks whose faces lie on the end joints (NotConvexError where a voussoir is not convex)."""
    joints = []
    for k, (inner, outer) in enumerate(ends):
        along = (outer - inner) / np.linalg.norm(outer - inner)
        joints.append(Joint(k + 1, k, k + 1, inner, outer, np.array([along[1], -along[0]])))
    blocks = [_support_prism(*ends[0], -joints[0].normal, support_length, depth)]
    for (a_in, a_out), (b_in, b_out) in zip(ends[:-1], ends[1:]):
        face = (faces or {}).get(len(blocks))
        on_intrados = [] if face is None else list(face.intrados)
        on_extrados = [] if face is None else list(face.extrados[::-1])  # counter-clockwise: right to left
        polygon = [a_in, *on_intrados, b_in, b_out, *on_extrados, a_out]
        if not is_convex_polygon(np.array(polygon)):
            shape = "quadrilateral" if face is None else f"polygon of {len(polygon)} corners"
            raise NotConvexError(f"voussoir {len(blocks)} of this arch is not a convex {shape}", face is not None)
        blocks.append(prism(polygon, depth))
    blocks.append(_support_prism(*ends[-1], joints[-1].normal, support_length, depth))
    middles = np.array([(inner + outer) / 2.0 for inner, outer in ends])
    return ArchGeometry(
        blocks,
        joints,
        thickness,
        depth,
        span,
        rise,
        voussoir_width=float(np.linalg.norm(np.diff(middles, axis=0), axis=1).min()),
        longest_joint=max(j.length for j in joints),
    )


def is_convex_polygon(polygon: np.ndarray) -> bool:
    """Whether a polygon given counter-clockwise turns left at every vertex."""
    edges = _following(polygon) - polygon
    after = _following(edges)
    turns = edges[:, 0] * after[:, 1] - edges[:, 1] * after[:, 0]
    return bool(np.all(turns > 0))


def _support_prism(p_in: np.ndarray, p_out: np.ndarray, outward: np.ndarray, length: float, depth: float) -> np.ndarray:
    """A rectangular support block: one face on the springing joint, extending `length` outward."""
    polygon = [p_in, p_out, p_out + length * outward, p_in + length * outward]
    return prism(polygon, depth)


def _following(rows: np.ndarray) -> np.ndarray:
    """Each row's successor, the first after the last (`np.roll(rows, -1, axis=0)` without its overhead)."""
    return np.concatenate((rows[1:], rows[:1]))


def polygon_area(xy: np.ndarray) -> float:
    """Area of a simple polygon given in order (shoelace formula)."""
    x, y = xy[:, 0], xy[:, 1]
    nxt = _following(xy)
    return 0.5 * abs(float(np.dot(x, nxt[:, 1]) - np.dot(y, nxt[:, 0])))


def polygon_centroid(xy: np.ndarray) -> np.ndarray:
    """Area centroid of a simple polygon given in order (where the weight acts; not the vertex mean)."""
    nxt = _following(xy)
    c = xy[:, 0] * nxt[:, 1] - xy[:, 1] * nxt[:, 0]
    return ((xy + nxt) * c[:, None]).sum(axis=0) / (3.0 * c.sum())


def front_face(vertices: np.ndarray) -> np.ndarray:
    """The x-y polygon of a prism built by `prism` (its front face, counter-clockwise)."""
    return vertices[: len(vertices) // 2, :2]


def block_volume(vertices: np.ndarray) -> float:
    """Volume of a prism built by `prism` (front face = first half of the vertices)."""
    half = len(vertices) // 2
    depth = float(vertices[half, 2] - vertices[0, 2])
    return polygon_area(vertices[:half, :2]) * depth
