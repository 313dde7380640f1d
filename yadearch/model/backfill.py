"""Backfill over the arch as dead loads on its voussoirs (pure numpy, SI), the standard equivalent loads
of a filled arch bridge: the fill's surface is level, `depth` above the highest point of the extrados;
each voussoir carries the weight of the fill column standing on its extrados face, and a lateral
pressure K x unit weight x depth below the surface acting horizontally on the face's vertical
projection, toward the arch (K the at-rest or active coefficient the user chooses, e.g. 1 - sin(phi)
at rest). Both intensities grow linearly along a face, so both resultants act at the same point of
it. Fill beyond the springings stands on the supports (docs/loads.md, "Backfill")."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.geometry import ArchGeometry
from yadearch.model.loads import LoadPoints, extrados_segments


@dataclass(frozen=True)
class Backfill:
    """The fill over the crown's extrados (m; 0: no fill), its unit weight (N/m3) and lateral
    pressure coefficient."""

    depth: float
    unit_weight: float
    lateral_coefficient: float

    @property
    def present(self) -> bool:
        return self.depth > 0.0 and self.unit_weight > 0.0


def fill_surface(geometry: ArchGeometry, fill: Backfill) -> float:
    """The fill's level (m): `depth` above the extrados' highest point."""
    return max(max(float(a[1]), float(b[1])) for _, a, b in extrados_segments(geometry)) + fill.depth


def backfill_points(geometry: ArchGeometry, centroids: np.ndarray, fill: Backfill) -> LoadPoints:
    """The fill's loads on the voussoirs as point forces (none without fill): for each extrados face
    between its joints' extrados corners a and b, with fill heights h_a and h_b above them, the weight
    unit_weight x depth x (h_a + h_b) / 2 x |b_x - a_x| down and the pressure resultant
    K unit_weight x depth x (h_a + h_b) / 2 x |b_y - a_y| toward the voussoir, both at the fraction
    (h_a + 2 h_b) / (3 (h_a + h_b)) of the face from a (the centroid of a trapezoid)."""
    if not fill.present:
        return LoadPoints(np.zeros(0, int), np.zeros((0, 2)), np.zeros((0, 2)))
    surface = fill_surface(geometry, fill)
    blocks, points, forces = [], [], []
    for block, a, b in extrados_segments(geometry):
        h_a, h_b = max(surface - float(a[1]), 0.0), max(surface - float(b[1]), 0.0)
        if h_a + h_b == 0.0:
            continue
        mean = 0.5 * (h_a + h_b) * fill.unit_weight * geometry.depth
        along = (h_a + 2.0 * h_b) / (3.0 * (h_a + h_b))
        point = a + along * (b - a)
        inward = -np.sign(point[0] - centroids[block, 0])  # the fill pushes the face toward the block
        forces.append((inward * fill.lateral_coefficient * mean * abs(b[1] - a[1]), -mean * abs(b[0] - a[0])))
        blocks.append(block)
        points.append(point)
    return LoadPoints(np.array(blocks, int), np.array(points, float), np.array(forces, float))
