"""Equilibrium of the blocks at a fixed support position (pure numpy/scipy): Newton's method with the
consistent tangent and a backtracking line search, and a descent for where Newton cannot go.

The descent takes damped Newton steps (K + mu I) d = R and keeps a step only where it releases
energy (mu falls after such a step, rises otherwise), the implicit analogue of the DEM's hold at a
fixed support. From a state past a fold it creeps toward the nearest stable equilibrium or away from
it, and its verdict is the hold's: stable, runaway (a block moved `runaway` from where it started) or
timeout.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg

from yadearch.model.joint_tangent import BLOCK_DOFS, JointTangent
from yadearch.solve import banded
from yadearch.solve.stages import Verdict
from yadearch.solve.statics import StaticArch

BACKTRACKS = 12  # halvings of a Newton step before it counts as failed
SUFFICIENT_DECREASE = 1e-4  # Armijo constant of the line search on |R|^2
SHIFT_GROWTH = 10.0  # the descent's shift grows by this after a step that would take energy in
SHIFT_FALL = 0.3  # ... and falls by this after one that releases energy
ROUNDOFF = 1e-14  # relative round-off of a position, about 50 machine epsilons
MAX_SHIFT_RATIO = 1e12  # a shift this many times its start means no step releases energy any more
MIN_SHIFT_RATIO = 1e-12  # the shift falls no lower (Newton's own steps)
RETURN_FRACTION = 0.01  # a descent ending this x max_step from the saddle it was kicked off came back
RETURNS_TO_STAND = 2  # ... and one that comes back this many times sits in a well
KICK_FRACTION = 0.02  # an unstable equilibrium is left along its softest mode by this x max_step


@dataclass(frozen=True)
class SolverSettings:
    """Tolerances of the static solver: residual over the largest block weight, the largest move of
    a block in one iteration (m), iteration budgets."""

    tolerance: float = 1e-9
    max_step: float = 2e-4
    newton_iterations: int = 40
    descent_iterations: int = 4000


@dataclass
class Equilibrium:
    """A state the solver ended in: generalised coordinates, joints, free-dof stiffness, residual."""

    u: np.ndarray
    joints: JointTangent
    stiffness: np.ndarray  # on the free degrees of freedom, in band storage (`solve.banded`)
    residual: float
    iterations: int
    verdict: Verdict = Verdict.STABLE
    moved: float = 0.0  # the largest block translation from the start (m)

    def stable(self) -> bool:
        """The free blocks' tangent stiffness is positive definite (its symmetric part)."""
        return banded.positive_definite(self.stiffness)


# near a fold the tangent is nearly singular by nature: the line search and the descent judge the step
warnings.filterwarnings("ignore", category=scipy.linalg.LinAlgWarning, module=__name__)


class Solver:
    """Newton and descent on one arch at a given support position and load history."""

    def __init__(self, arch: StaticArch, settings: SolverSettings):
        self.arch = arch
        self.settings = settings
        self.free = arch.free_dofs
        self.scale = float(arch.weight[1:-1].max())
        # a joint's force is known to its stiffness x the round-off of the positions, no better
        law, size = arch.law, float(np.abs(arch.centroid0).max())
        self.resolution = ROUNDOFF * law.kn * law.depth * float(arch.table.length.max()) * size
        self.evaluations = 0
        self.iterations = 0  # Newton and descent iterations, over every solve

    @property
    def converged(self) -> float:
        """The largest residual force of an equilibrium (N): `tolerance` x the heaviest block's
        weight, or the joints' round-off where that is larger (stiff joints)."""
        return max(self.settings.tolerance * self.scale, self.resolution)

    def state(
        self, u: np.ndarray, u_before: np.ndarray, shear_before: np.ndarray, gravity: float = 1.0
    ) -> tuple[JointTangent, np.ndarray, np.ndarray]:
        """Joints at `u`, the free blocks' residual R = joint forces + weights (generalised) and their
        tangent K in band storage (`solve.banded`), in one compiled call."""
        self.evaluations += 1
        return self.arch.free_state(u, u_before, shear_before, gravity)

    def result(
        self,
        u: np.ndarray,
        joints: JointTangent,
        residual: np.ndarray,
        stiffness: np.ndarray,
        iterations: int,
        start: np.ndarray,
        verdict: Verdict = Verdict.STABLE,
    ) -> Equilibrium:
        return Equilibrium(
            u,
            joints,
            stiffness,
            float(np.abs(residual).max()) / self.scale,
            iterations,
            verdict,
            largest_move(u, start),
        )

    def _capped(self, d: np.ndarray) -> np.ndarray:
        """`d` (free dofs) shortened so that no block moves more than `max_step` in one iteration."""
        largest = float(np.abs(d).max())
        return d * min(1.0, self.settings.max_step / largest) if largest > 0.0 else d

    def newton(
        self, u0: np.ndarray, u_before: np.ndarray, shear_before: np.ndarray, gravity: float = 1.0
    ) -> Equilibrium | None:
        """Newton from `u0` (supports already placed); None if it does not converge."""
        u = u0.copy()
        joints, residual, stiffness = self.state(u, u_before, shear_before, gravity)
        for iteration in range(self.settings.newton_iterations):
            self.iterations += 1
            norm = float(np.abs(residual).max())
            if norm <= self.converged:
                return self.result(u, joints, residual, stiffness, iteration, u0)
            try:
                d = self._capped(banded.solve(stiffness, residual))
            except (np.linalg.LinAlgError, ValueError):
                return None
            merit, alpha = float(residual @ residual), 1.0
            for _ in range(BACKTRACKS):
                trial = u.copy()
                trial[self.free] += alpha * d
                trial_joints, trial_residual, trial_stiffness = self.state(trial, u_before, shear_before, gravity)
                if float(trial_residual @ trial_residual) <= (1.0 - SUFFICIENT_DECREASE * alpha) * merit:
                    break
                alpha *= 0.5
            else:
                return None
            u, joints, residual, stiffness = trial, trial_joints, trial_residual, trial_stiffness
        return None

    def descend(
        self,
        u0: np.ndarray,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        runaway: float,
        gravity: float = 1.0,
        iterations: int | None = None,
        origin: np.ndarray | None = None,
    ) -> Equilibrium:
        """Damped Newton steps (K + mu I) d = R from `u0`, a step kept only where it releases energy
        (the work of the residual forces along it, by the trapezoidal rule, is positive; then mu
        falls, else it rises): the arch creeps downhill, as the DEM's hold lets it. Ends in a stable
        equilibrium (Verdict.STABLE; also a saddle of the tangent's symmetric part that the descent,
        kicked off along its softest mode, comes back to twice: sliding joints make that part
        indefinite at states the incremental law holds), or when a block has moved `runaway` (m) from
        `origin` (default `u0`; a descent that goes on from where another stopped counts from where that
        began) (Verdict.RUNAWAY), or when the budget is spent or no step releases energy (Verdict.TIMEOUT)."""
        budget = iterations or self.settings.descent_iterations
        origin = u0 if origin is None else origin
        u = u0.copy()
        joints, residual, stiffness = self.state(u, u_before, shear_before, gravity)
        floor = self.initial_shift(stiffness)
        shift = floor
        saddle, returns = None, 0
        for iteration in range(budget):
            self.iterations += 1
            if float(np.abs(residual).max()) <= self.converged:
                found = self.result(u, joints, residual, stiffness, iteration, origin)
                if found.stable():
                    return found
                if saddle is not None and largest_move(u, saddle) <= RETURN_FRACTION * self.settings.max_step:
                    returns += 1
                    if returns >= RETURNS_TO_STAND:  # kicked along its softest mode, it comes back:
                        return replace(found, verdict=Verdict.STABLE)  # a well, for the dynamics too
                else:
                    saddle, returns = u.copy(), 0
                u = self._kick(u, stiffness)  # a saddle: leave it along its softest mode
                joints, residual, stiffness = self.state(u, u_before, shear_before, gravity)
                shift = floor
                continue
            if shift > MAX_SHIFT_RATIO * floor:
                if banded.positive_definite(stiffness):
                    break  # no step releases energy in a stable well: stuck where no equilibrium is
                u = self._kick(u, stiffness)  # at a saddle to round-off: leave it along its softest mode
                joints, residual, stiffness = self.state(u, u_before, shear_before, gravity)
                shift = floor
                continue
            try:
                d = self._capped(banded.solve(stiffness, residual, shift))
            except (np.linalg.LinAlgError, ValueError):
                shift *= SHIFT_GROWTH
                continue
            trial = u.copy()
            trial[self.free] += d
            trial_joints, trial_residual, trial_stiffness = self.state(trial, u_before, shear_before, gravity)
            if not float((residual + trial_residual) @ d) > 0.0:
                shift *= SHIFT_GROWTH
                continue
            shift = max(shift * SHIFT_FALL, MIN_SHIFT_RATIO * floor)
            u, joints, residual, stiffness = trial, trial_joints, trial_residual, trial_stiffness
            if largest_move(u, origin) > runaway:
                return self.result(u, joints, residual, stiffness, iteration + 1, origin, Verdict.RUNAWAY)
        return self.result(u, joints, residual, stiffness, budget, origin, Verdict.TIMEOUT)

    def initial_shift(self, stiffness: np.ndarray) -> float:
        """The descent's first shift (N/m): the stiffest diagonal term of the free blocks' tangent, or a
        whole joint's normal stiffness where nothing touches yet (the pseudo-time of one step is then
        a joint's own)."""
        diagonal = np.abs(stiffness[banded.BAND])
        law, table = self.arch.law, self.arch.table
        return max(float(diagonal.max()), law.kn * law.depth * float(table.length.max()))

    def _kick(self, u: np.ndarray, stiffness: np.ndarray) -> np.ndarray:
        """`u` moved along the softest mode of `stiffness`, the way the weights go down."""
        mode = banded.softest_mode(stiffness)
        mode = mode / float(np.abs(mode).max())
        if float(self.arch.loads()[self.free] @ mode) < 0.0:
            mode = -mode
        kicked = u.copy()
        kicked[self.free] += KICK_FRACTION * self.settings.max_step * mode
        return kicked


def largest_move(u: np.ndarray, start: np.ndarray) -> float:
    """The largest translation of a block between two generalised states (m)."""
    moves = (u - start).reshape(-1, BLOCK_DOFS)[:, 0:2]
    return float(np.hypot(moves[:, 0], moves[:, 1]).max())
