"""Backfill over the arch as dead loads on its voussoirs (pure numpy, SI), the standard equivalent loads
of a filled arch bridge: the fill's surface is level, `depth` above the highest point of the extrados;
each voussoir carries the weight of the fill column standing on its extrados face, and a lateral
pressure K x unit weight x depth below the surface acting horizontally on the face's vertical
projection, toward the arch (K the at-rest or active coefficient the user chooses, e.g. 1 - sin(phi)
at rest). Both intensities grow linearly along a face, so both resultants act at the same point of
it. Fill beyond the springings stands on the supports (docs/loads.md, "Backfill"). The fill's passive
resistance to a face pushed into it is `model.passive_fill`'s."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.geometry import ArchGeometry
from yadearch.model.loads import LoadPoints, extrados_chain, extrados_segments


@dataclass(frozen=True)
class Backfill:
    """The fill over the crown's extrados (m; 0: no fill), its unit weight (N/m3) and lateral
    pressure coefficient."""

    depth: float
    unit_weight: float
    lateral_coefficient: float
    passive_coefficient: float = 0.0  # Kp the fill mobilises against a face pushed into it (0: none)
    passive_displacement: float = 0.0  # how far a face moves into the fill to mobilise it whole (m)

    @property
    def present(self) -> bool:
        return self.depth > 0.0 and self.unit_weight > 0.0

    @property
    def resists(self) -> bool:
        """The fill pushes back harder than its at-rest pressure where the arch sways into it."""
        return self.present and self.passive_coefficient > self.lateral_coefficient


def fill_surface(geometry: ArchGeometry, fill: Backfill) -> float:
    """The fill's level (m): `depth` above the extrados' highest point."""
    return max(max(float(a[1]), float(b[1])) for _, a, b in extrados_segments(geometry)) + fill.depth


def backfill_points(geometry: ArchGeometry, fill: Backfill) -> LoadPoints:
    """The fill's loads on the voussoirs as point forces (none without fill): on each face of
    `fill_faces`, its weight down and K x its pressure resultant toward the voussoir."""
    blocks, points, forces = [], [], []
    for face in fill_faces(geometry, fill):
        forces.append((face.inward * fill.lateral_coefficient * face.mean * face.height, -face.mean * face.width))
        blocks.append(face.block)
        points.append(face.point)
    if not blocks:
        return LoadPoints(np.zeros(0, int), np.zeros((0, 2)), np.zeros((0, 2)))
    return LoadPoints(np.array(blocks, int), np.array(points, float), np.array(forces, float))


@dataclass(frozen=True)
class FillFace:
    """One extrados face under the fill: its block, the resultants' point (the trapezoid's centroid on
    the face), unit weight x ring depth x the fill's mean height over it (N/m), the face's horizontal
    and vertical projections (m), and the sign of the horizontal direction toward its block (+1: +x)."""

    block: int
    point: np.ndarray
    mean: float
    width: float
    height: float
    inward: float
    column_y: float  # the height of the centroid of the fill's column over the face (m)


def fill_faces(geometry: ArchGeometry, fill: Backfill) -> list[FillFace]:
    """The extrados faces the fill stands on (none without fill): for each face between its joints'
    extrados corners a and b, with fill heights h_a and h_b above them, the weight unit_weight x depth
    x (h_a + h_b) / 2 x |b_x - a_x| and the pressure resultant per unit K, unit_weight x depth x
    (h_a + h_b) / 2 x |b_y - a_y|, both at the fraction (h_a + 2 h_b) / (3 (h_a + h_b)) of the face from a."""
    if not fill.present:
        return []
    surface = fill_surface(geometry, fill)
    faces = []
    for block in range(1, len(geometry.blocks) - 1):
        chain = extrados_chain(geometry, block)  # from the left joint's corner to the right one's, the ring below
        for p, q in zip(chain[:-1], chain[1:]):
            a, b = (p, q) if p[0] <= q[0] else (q, p)
            h_a, h_b = max(surface - float(a[1]), 0.0), max(surface - float(b[1]), 0.0)
            if h_a + h_b == 0.0:
                continue
            mean = 0.5 * (h_a + h_b) * fill.unit_weight * geometry.depth
            point = a + (h_a + 2.0 * h_b) / (3.0 * (h_a + h_b)) * (b - a)
            inward = float(np.sign(q[1] - p[1]))  # the fill faces the chain's left side: a rise is pushed to +x
            # the column between the level surface and the face: its centroid (h_a^2 + h_a h_b + h_b^2) /
            # (3 (h_a + h_b)) below the surface
            column_y = surface - (h_a * h_a + h_a * h_b + h_b * h_b) / (3.0 * (h_a + h_b))
            faces.append(FillFace(block, point, mean, abs(b[0] - a[0]), abs(b[1] - a[1]), inward, column_y))
    return faces


def fill_inertia(geometry: ArchGeometry, fill: Backfill) -> tuple[tuple[int, float, float, float], ...]:
    """The fill's columns the voussoirs carry, as a horizontal acceleration of 1 g pushes them: per face
    (block, x, y of the column's centroid, its weight N), the pseudo-static equivalent of the fill's mass
    moving with the arch (docs/loads.md, "Backfill"); none without fill."""
    return tuple(
        (face.block, float(face.point[0]), face.column_y, face.mean * face.width) for face in fill_faces(geometry, fill)
    )
