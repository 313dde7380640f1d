"""Segmental-arch geometry in pure numpy: voussoir and support-block vertices, joint planes.

Conventions (DESIGN.md §2): arch in the x-y plane, y up, depth along z, centre of the intrados circle
at the origin, symmetric about x = 0. Voussoirs 1..n and interfaces 1..n+1 are numbered left to
right. All lengths here are in metres; the case converts from the user's millimetres.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


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
    internal_radius: float
    thickness: float
    depth: float
    embrace_rad: float

    @property
    def n_voussoirs(self) -> int:
        return len(self.blocks) - 2

    @property
    def voussoirs(self) -> list[np.ndarray]:
        return self.blocks[1:-1]

    @property
    def springing_angle_rad(self) -> float:
        """Angle of the springing planes above the horizontal (27.5 deg for a 125 deg embrace)."""
        return (np.pi - self.embrace_rad) / 2.0

    @property
    def span(self) -> float:
        """Net (intrados) span between the springings (m)."""
        return 2.0 * self.internal_radius * np.cos(self.springing_angle_rad)

    @property
    def rise(self) -> float:
        """Intrados rise from the springing line to the crown (m)."""
        return self.internal_radius * (1.0 - np.sin(self.springing_angle_rad))

    @property
    def crown_voussoir(self) -> int:
        """1-based number of the voussoir at (or just left of) the crown."""
        return (self.n_voussoirs + 1) // 2


def _radial(angle: float, radius: float) -> np.ndarray:
    return np.array([radius * np.cos(angle), radius * np.sin(angle)])


def _prism(polygon_xy: list[np.ndarray], depth: float) -> np.ndarray:
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
    blocks.append(_support_prism(left_angle, outward_left, r_in, r_out, support_length, depth))
    for a, b in zip(joint_angles[:-1], joint_angles[1:]):
        polygon = [_radial(a, r_in), _radial(b, r_in), _radial(b, r_out), _radial(a, r_out)]
        blocks.append(_prism(polygon, depth))
    right_angle = joint_angles[-1]
    outward_right = np.array([np.sin(right_angle), -np.cos(right_angle)])
    blocks.append(_support_prism(right_angle, outward_right, r_in, r_out, support_length, depth))

    joints = []
    for k, angle in enumerate(joint_angles):
        normal = np.array([np.sin(angle), -np.cos(angle)])  # direction of decreasing angle
        joints.append(Joint(k + 1, k, k + 1, _radial(angle, r_in), _radial(angle, r_out), normal))
    return ArchGeometry(blocks, joints, internal_radius, thickness, depth, embrace)


def _support_prism(
    angle: float, outward: np.ndarray, r_in: float, r_out: float, length: float, depth: float
) -> np.ndarray:
    """A rectangular support block: one face on the springing plane, extending `length` outward."""
    p_in, p_out = _radial(angle, r_in), _radial(angle, r_out)
    polygon = [p_in, p_out, p_out + length * outward, p_in + length * outward]
    return _prism(polygon, depth)


def polygon_area(xy: np.ndarray) -> float:
    """Area of a simple polygon given in order (shoelace formula)."""
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def block_volume(vertices: np.ndarray) -> float:
    """Volume of a prism built by `_prism` (front face = first half of the vertices)."""
    half = len(vertices) // 2
    depth = float(vertices[half, 2] - vertices[0, 2])
    return polygon_area(vertices[:half, :2]) * depth
