"""Where the static path puts the arch next (pure numpy): a parabola through the path's last states, or
from one state the free blocks' whole tangent (docs/theory.md, "The static engine"); the DEM's static
check predicts with the same tangent (`dem.static_check`)."""

from __future__ import annotations

import numpy as np

from yadearch.solve import banded
from yadearch.solve.newton import Solver
from yadearch.solve.path import extrapolate
from yadearch.solve.static_state import PathParameter, StaticState
from yadearch.solve.statics import StaticArch

PREDICTOR_POINTS = 3  # accepted states the predictor extrapolates through (a parabola)


class Predictions:
    """The predictions of a path of `arch` solved by `solver` along its `parameter` (`solve.static_path`)."""

    arch: StaticArch
    solver: Solver
    parameter: PathParameter

    def predict(self, target: float, history: list[StaticState]) -> np.ndarray:
        """Where the arch should be at `target`: a parabola (or a line) through `history`'s last states, or
        from one state its tangent's response (a singular one: only the supports moved, for the descent)."""
        last, recent = history[-1], history[-PREDICTOR_POINTS:]
        lams = [s.lam for s in recent]
        if len(set(lams)) == len(lams) >= 2:
            return self.place(extrapolate(lams, [s.u for s in recent], target), target)
        try:
            return self.tangent_prediction(last.u, last.lam, last.forces.shear_force, last.springs, target)
        except (np.linalg.LinAlgError, ValueError):
            return self.place(last.u, target)

    def tangent_prediction(
        self,
        u: np.ndarray,
        lam: float,
        shear: np.ndarray,
        springs: np.ndarray | None,
        target: float,
        held: float | None = None,
    ) -> np.ndarray:
        """Where the free blocks' whole tangent (the joints, the loads' turning arms, the fill's springs) at
        the equilibrium `u` (at `lam`, its joints' `shear`, the fill's `springs`) puts the arch at `target`,
        with the path's live load or one `held` (LinAlgError or ValueError where the tangent is singular)."""
        moved = self.place(u, target)
        multiplier = self.parameter.multiplier(lam) if held is None else held
        joints, _, tangent = self.solver.state(u, u, shear, multiplier=multiplier, springs=springs)
        free = self.arch.free_dofs
        driven = np.setdiff1d(np.arange(len(moved)), free)
        load = -self.arch.stiffness(joints)[np.ix_(free, driven)] @ (moved - u)[driven]
        more = self.parameter.multiplier(target) - multiplier if held is None else 0.0
        if more:
            load = load + more * self.arch.live_forces(u)
        moved[free] += banded.solve(tangent, load)
        return moved

    def place(self, u: np.ndarray, lam: float) -> np.ndarray:
        """`u` with the supports where the path's parameter `lam` puts them."""
        return self.arch.with_supports(u, self.parameter.support(lam))
