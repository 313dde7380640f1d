"""A prescribed support path (pure numpy): the springing point runs along a polyline of displacements
while the support turns, linearly along each segment, about it (docs/movements.md); the path
parameter lam is the distance along the polyline. `model.movement` builds it from a case's table."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from yadearch.model.joints import rotate

MIN_SEGMENT_M = 1e-6  # a path segment must move the springing point at least this far
ON_PATH_M = 1e-9  # a springing point this close to the path is on it


@dataclass(frozen=True)
class PathMotion:
    """A prescribed path: the springing point runs along the polyline through `vertices` (its
    displacement, m, from (0, 0)) while the support turns about it, linearly along each segment, to
    `angles` (rad); lam is the distance along the polyline, `lengths` its value at each vertex."""

    springing: np.ndarray
    vertices: np.ndarray  # (n + 1, 2)
    angles: np.ndarray  # (n + 1,)
    lengths: np.ndarray  # (n + 1,)

    @classmethod
    def from_table(cls, springing: np.ndarray, rows: np.ndarray) -> PathMotion:
        """From rows (dx, dy in m, rotation in rad) of the springing point's displacement and the
        support's rotation, each reached from the previous one (the first from rest)."""
        vertices = np.vstack([np.zeros(2), rows[:, :2]])
        segments = np.linalg.norm(np.diff(vertices, axis=0), axis=1)
        short = np.flatnonzero(segments < MIN_SEGMENT_M)
        if short.size:
            raise ValueError(
                f"path row {short[0] + 1} does not move the springing point from the previous "
                "row (a turn about it alone has no path length; use support_motion 'rotation')"
            )
        return cls(
            springing, vertices, np.concatenate([[0.0], rows[:, 2]]), np.concatenate([[0.0], np.cumsum(segments)])
        )

    def _segment(self, lam: float) -> int:
        return int(np.clip(np.searchsorted(self.lengths, lam, side="right") - 1, 0, len(self.lengths) - 2))

    def angle(self, lam: float) -> float:
        return float(np.interp(lam, self.lengths, self.angles))

    def offset(self, lam: float) -> np.ndarray:
        k = self._segment(lam)
        t = (lam - self.lengths[k]) / (self.lengths[k + 1] - self.lengths[k])
        return self.vertices[k] + t * (self.vertices[k + 1] - self.vertices[k])

    def velocity(self, point_now: np.ndarray, lam: float, speed: float, dt: float) -> tuple[np.ndarray, float]:
        """The velocity (2,) of the support's material point now at `point_now` and its turn rate
        while the path advances at `speed` for `dt`: the chords of that step's motion."""
        step = speed * dt
        return self.displacement_of(point_now, lam, step) / dt, (self.angle(lam + step) - self.angle(lam)) / dt

    @property
    def rotation(self) -> float:
        """Nonzero if the support turns anywhere along the path (its largest turn, rad)."""
        return float(np.max(np.abs(self.angles)))

    @property
    def uniform(self) -> bool:
        return False

    @property
    def level(self) -> bool:
        """The springing point moves only horizontally and the support never turns."""
        return bool(np.all(np.abs(self.vertices[:, 1]) < ON_PATH_M) and self.rotation == 0.0)

    @property
    def horizontal_share(self) -> float:
        """The largest horizontal component of the springing point's unit direction over the segments."""
        steps = np.diff(self.vertices, axis=0)
        return float(np.max(np.abs(steps[:, 0]) / np.linalg.norm(steps, axis=1)))

    @property
    def corners(self) -> tuple[float, ...]:
        return tuple(float(v) for v in self.lengths[1:-1])

    @property
    def length(self) -> float:
        return float(self.lengths[-1])

    def placement(self, lam: float) -> tuple[float, np.ndarray]:
        """(angle, shift) at path `lam`: an undeformed point X of the support is at R(angle) X + shift."""
        angle = self.angle(lam)
        return angle, self.springing + self.offset(lam) - rotate(self.springing, angle)

    def carry(self, point: np.ndarray, lam: float) -> np.ndarray:
        angle, shift = self.placement(lam)
        return rotate(point, angle) + shift

    def rates(self, lam: float) -> np.ndarray:
        """(vx, vy, omega) per unit path rate of the support's material point at the origin."""
        k = self._segment(lam)
        span = self.lengths[k + 1] - self.lengths[k]
        direction = (self.vertices[k + 1] - self.vertices[k]) / span
        omega = (self.angles[k + 1] - self.angles[k]) / span
        at = self.springing + self.offset(lam)
        return np.array([direction[0] + omega * at[1], direction[1] - omega * at[0], omega])

    def displacement_of(self, point_now: np.ndarray, lam: float, step: float) -> np.ndarray:
        """How far (2,) the support's material point now at `point_now` moves from `lam` to
        `lam + step`, exactly, across vertices too."""
        angle, shift = self.placement(lam)
        return self.carry(rotate(point_now - shift, -angle), lam + step) - point_now

    def travelled(self, centroid0: np.ndarray, centroid: Sequence[float], turn: float, hint: float) -> float:
        """The path length at which the springing point of a support body placed so stands: its
        projection on the polyline, the one nearest `hint` where the path passes a point twice."""
        point = rotate(self.springing - np.asarray(centroid0), turn) + np.asarray(centroid) - self.springing
        best: tuple[bool, float, float] | None = None
        for k in range(len(self.lengths) - 1):
            a, b = self.vertices[k], self.vertices[k + 1]
            t = float(np.clip(np.dot(point - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0))
            lam = float(self.lengths[k] + t * (self.lengths[k + 1] - self.lengths[k]))
            distance = float(np.linalg.norm(a + t * (b - a) - point))
            key = (distance > ON_PATH_M, abs(lam - hint), distance)
            if best is None or key < best:
                best, found = key, lam
        return found
