"""Where an equilibrium's tangent puts the arch at another support position (pure numpy): the static
engine's predictor from one state, and the DEM's check of how its holds should move."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from yadearch.solve import banded

if TYPE_CHECKING:
    from yadearch.solve.static_path import StaticLoading


def tangent_prediction(
    loading: StaticLoading,
    u: np.ndarray,
    lam: float,
    shear: np.ndarray,
    springs: np.ndarray | None,
    target: float,
    held: float | None = None,
) -> np.ndarray:
    """Where the free blocks' whole tangent (the joints, the loads' turning arms, the fill's springs) at
    the equilibrium `u` of `loading`'s path (at `lam`, its joints' `shear`, the fill's `springs`) puts
    the arch at `target`, with the path's live load or one `held` (LinAlgError or ValueError where the
    tangent is singular)."""
    moved = loading.place(u, target)
    multiplier = loading.parameter.multiplier(lam) if held is None else held
    joints, _, tangent = loading.solver.state(u, u, shear, multiplier=multiplier, springs=springs)
    free = loading.arch.free_dofs
    driven = np.setdiff1d(np.arange(len(moved)), free)
    load = -loading.arch.stiffness(joints)[np.ix_(free, driven)] @ (moved - u)[driven]
    more = loading.parameter.multiplier(target) - multiplier if held is None else 0.0
    if more:
        load = load + more * loading.arch.live_forces(u)
    moved[free] += banded.solve(tangent, load)
    return moved
