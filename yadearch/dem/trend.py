"""The trend of the DEM's path: where its last equilibrium states put the blocks next, so that a snap
made during a support move (the blocks land on another branch before the hold) is told from a step
along the branch, by the static engine's rule (`solve.static_path`: no block further from the
prediction than the snap floor). Pure numpy: the loading keeps it beside its snapshots."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.solve.path import extrapolate

PREDICTOR_POINTS = 3  # states the prediction goes through (a parabola), as the static engine's


@dataclass(frozen=True)
class Trend:
    """The last equilibrium states of one branch: path positions and the voussoirs' centroids there."""

    lams: tuple[float, ...]
    positions: tuple[np.ndarray, ...]
    slope: np.ndarray | None = None  # how the centroids move per unit of the path's parameter at the first state

    @classmethod
    def start(cls, lam: float, positions: np.ndarray, slope: np.ndarray | None = None) -> Trend:
        """A branch known by one state only (the self-weight's, or a snap's landing), predicting along
        `slope` (the static model's tangent there, as the static engine predicts from one state) or not
        at all (None)."""
        return cls((lam,), (positions,), slope)

    def then(self, lam: float, positions: np.ndarray) -> Trend:
        """The trend with the state at `lam` added (the oldest dropped beyond PREDICTOR_POINTS)."""
        return Trend(
            (*self.lams, lam)[-PREDICTOR_POINTS:], (*self.positions, positions)[-PREDICTOR_POINTS:], self.slope
        )

    def with_last(self, positions: np.ndarray) -> Trend:
        """The trend with its last state's centroids replaced (a state settled further in place)."""
        return Trend(self.lams, (*self.positions[:-1], positions), self.slope)

    def _through_states(self) -> bool:
        """Two states or more, at distinct positions: a polynomial goes through them."""
        return len(set(self.lams)) == len(self.lams) >= 2

    def predicts(self) -> bool:
        """Whether the trend can say where the blocks go: through two states or more, or along its slope."""
        return self._through_states() or (len(self.lams) == 1 and self.slope is not None)

    def distance(self, lam: float, positions: np.ndarray) -> float:
        """How far the block furthest from the trend's prediction at `lam` is (m); 0 where the trend
        cannot predict (one state without a slope, or two at one position)."""
        if self._through_states():
            predicted = extrapolate(list(self.lams), list(self.positions), lam)
        elif self.predicts():
            assert self.slope is not None
            predicted = self.positions[0] + (lam - self.lams[0]) * self.slope
        else:
            return 0.0
        return float(np.linalg.norm(positions - predicted, axis=1).max())
