"""What the static engine's path is made of (pure numpy): its accepted states, what its parameter
drives (the supports, or a live load with the supports held), and its one failure that is not a
path's (an arch that does not stand)."""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from yadearch.model.joint_law import JointForces
from yadearch.solve.banded import smallest_eigenvalue


class StaticEngineError(RuntimeError):
    """The static engine cannot go on (no self-weight equilibrium)."""


@dataclass(frozen=True)
class PathParameter:
    """What the path's parameter drives: the supports along their movement (m), the live load held at
    `held` (N or g), or, with `live`, the live load's multiplier with the supports held at `support_at`
    (m along their movement)."""

    live: bool = False
    support_at: float = 0.0
    held: float = 0.0

    def support(self, lam: float) -> float:
        return self.support_at if self.live else lam

    def multiplier(self, lam: float) -> float:
        return lam if self.live else self.held


@dataclass
class StaticState:
    """An equilibrium (or the collapse) state: where the support was, the blocks, the joints."""

    stage: str
    lam: float
    u: np.ndarray
    forces: JointForces
    slip: np.ndarray  # each joint's accumulated sliding beyond its Coulomb cap (m)
    iterations: int
    residual: float
    move: float = 0.0  # how far the blocks moved from the predicted state to reach it (m)
    stiffness: np.ndarray | None = None  # the free blocks' tangent as the solver found it (band storage)
    springs: np.ndarray | None = None  # the fill's passive springs as this state leaves them
    # (`model.passive_fill.yielded`; None: the unyielded fill): where the next solve starts from

    @functools.cached_property
    def min_stiffness(self) -> float:
        """The smallest eigenvalue of the free blocks' tangent (N/m; NaN without one), computed when a
        record asks for it (series.csv), not for every accepted state of a campaign's lean run."""
        return smallest_eigenvalue(self.stiffness) if self.stiffness is not None else float("nan")
