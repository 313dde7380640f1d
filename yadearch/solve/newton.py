"""Equilibrium of the blocks at a fixed support position (numpy and numba): Newton's method with the
consistent tangent and a backtracking line search, and a descent for where Newton cannot go.

The descent takes damped Newton steps (K + mu I) d = R and keeps a step only where it releases
energy (mu falls after such a step, rises otherwise), the implicit analogue of the DEM's hold at a
fixed support. From a state past a fold it creeps toward the nearest stable equilibrium or away from
it, and its verdict is the hold's: stable, runaway (a block moved `runaway` from where it started) or
timeout.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from yadearch.model.block_state import as_joints
from yadearch.model.joint_tangent import BLOCK_DOFS, JointTangent
from yadearch.model.kernel_call import KernelCall
from yadearch.solve import banded
from yadearch.solve.newton_kernel import CONVERGED, RUNAWAY, STUCK, TIMEOUT, descent_kernel, newton_kernel
from yadearch.solve.stages import Verdict
from yadearch.solve.statics import StaticArch

NEWTON_KERNEL, DESCENT_KERNEL = KernelCall(newton_kernel), KernelCall(descent_kernel)  # `model.kernel_call`

BACKTRACKS = 12  # halvings of a Newton step before it counts as failed
SUFFICIENT_DECREASE = 1e-4  # Armijo constant of the line search on |R|^2
ROUNDOFF = 1e-14  # relative round-off of a position, about 50 machine epsilons
RETURN_FRACTION = 0.01  # a descent ending this x max_step from the saddle it was kicked off came back
RETURNS_TO_STAND = 2  # ... and one that comes back this many times sits in a well
KICK_FRACTION = 0.02  # an unstable equilibrium is left along its softest mode by this x max_step,
KICK_RESOLUTION = 10.0  # ... or further, until its negative stiffness pushes this x the converged residual
TIED_LOADS = 1e-9  # a mode the loads barely work on (|loads . mode| below this x |loads|): a symmetric
# arch's antisymmetric mode, whose side is then chosen by the blocks' order, not by round-off


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
    springs: np.ndarray | None = None  # the fill's passive springs as this state leaves them: yielded
    # at a stable equilibrium (`model.passive_fill.yielded`), as they were elsewhere (a fall is no rest)

    def stable(self) -> bool:
        """The free blocks' tangent stiffness is positive definite (its symmetric part)."""
        return banded.positive_definite(self.stiffness)

    def with_slip(self, slip: np.ndarray) -> Equilibrium:
        """This state with `slip` (m, per joint) added to its joints' sliding (that of earlier goes)."""
        forces = replace(self.joints.forces, plastic_slip=self.joints.forces.plastic_slip + slip)
        return replace(self, joints=replace(self.joints, forces=forces))


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
        self,
        u: np.ndarray,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        gravity: float = 1.0,
        multiplier: float = 0.0,
        springs: np.ndarray | None = None,
    ) -> tuple[JointTangent, np.ndarray, np.ndarray]:
        """Joints at `u`, the free blocks' residual R = joint forces + weights + `multiplier` x the live
        load + the fill's pushes (generalised) and their tangent K in band storage (`solve.banded`), in
        one compiled call."""
        self.evaluations += 1
        return self.arch.free_state(u, u_before, shear_before, gravity, multiplier, springs)

    def result(
        self,
        u: np.ndarray,
        joints: JointTangent,
        residual: np.ndarray,
        stiffness: np.ndarray,
        iterations: int,
        start: np.ndarray,
        springs: np.ndarray | None,
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
            self.arch.yielded(springs, u) if verdict == Verdict.STABLE else self.arch.springs_or_unyielded(springs),
        )

    def newton(
        self,
        u0: np.ndarray,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        gravity: float = 1.0,
        multiplier: float = 0.0,
        springs: np.ndarray | None = None,
    ) -> Equilibrium | None:
        """Newton from `u0` (supports already placed), the fill's `springs` as `u_before` left them; None
        if it does not converge. The iterations run compiled (`solve.newton_kernel`): Newton's step capped
        at `max_step`, halved up to BACKTRACKS times (INDEFINITE_BACKTRACKS from an indefinite tangent)
        until |R|^2 falls by SUFFICIENT_DECREASE x the step's fraction."""
        u, loops, evaluations, success, state = NEWTON_KERNEL(
            self._problem(u_before, shear_before, gravity, multiplier, springs),
            u0,
            self.settings.newton_iterations,
            BACKTRACKS,
            SUFFICIENT_DECREASE,
        )
        self.iterations += loops
        self.evaluations += evaluations
        if not success:
            return None
        joints, residual, stiffness = as_joints(state)
        return self.result(u, joints, residual, stiffness, loops - 1, u0, springs)

    def descend(
        self,
        u0: np.ndarray,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        runaway: float,
        gravity: float = 1.0,
        iterations: int | None = None,
        origin: np.ndarray | None = None,
        multiplier: float = 0.0,
        springs: np.ndarray | None = None,
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
        u, iteration, floor, shift = u0.copy(), 0, 0.0, 0.0
        saddle, returns = None, 0
        external = (gravity, multiplier, springs)
        while True:
            u, reached, evaluations, event, floor, shift, state = self._descent_run(
                u, u_before, shear_before, external, floor, shift, origin, runaway, iteration, budget
            )
            self.iterations += reached - iteration + (event in (CONVERGED, STUCK))
            self.evaluations += evaluations
            iteration = reached
            joints, residual, stiffness = as_joints(state)
            if event == RUNAWAY:
                return self.result(u, joints, residual, stiffness, iteration, origin, springs, Verdict.RUNAWAY)
            if event == TIMEOUT:
                return self.result(u, joints, residual, stiffness, budget, origin, springs, Verdict.TIMEOUT)
            if event == CONVERGED:
                found = self.result(u, joints, residual, stiffness, iteration, origin, springs)
                if found.stable():
                    return found
                if saddle is not None and largest_move(u, saddle) <= RETURN_FRACTION * self.settings.max_step:
                    returns += 1
                    if returns >= RETURNS_TO_STAND:  # kicked along its softest mode, it comes back:
                        return replace(found, verdict=Verdict.STABLE)  # a well, for the dynamics too
                else:
                    saddle, returns = u.copy(), 0
            elif banded.positive_definite(stiffness):  # no step releases energy in a stable well:
                return self.result(u, joints, residual, stiffness, budget, origin, springs, Verdict.TIMEOUT)  # stuck
            u = self._kick(u, stiffness)  # a saddle (to round-off): leave it along its softest mode
            shift = floor
            iteration += 1
            if iteration >= budget:
                joints, residual, stiffness = self.state(u, u_before, shear_before, gravity, multiplier, springs)
                return self.result(u, joints, residual, stiffness, budget, origin, springs, Verdict.TIMEOUT)

    def _problem(
        self,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        gravity: float,
        multiplier: float,
        springs: np.ndarray | None = None,
    ) -> tuple:
        """One support position's and load's equilibrium problem as the compiled kernels take it
        (`solve.newton_kernel._evaluate`), the fill's `springs` as `u_before` left them."""
        arch = self.arch
        return (
            arch.kernel,
            u_before,
            shear_before,
            arch.weight,
            gravity,
            arch.length,
            banded.BAND,
            self.converged,
            self.settings.max_step,
            *arch.external(gravity, multiplier, springs),
        )

    def _descent_run(
        self,
        u: np.ndarray,
        u_before: np.ndarray,
        shear_before: np.ndarray,
        external: tuple[float, float, np.ndarray | None],
        floor: float,
        shift: float,
        origin: np.ndarray,
        runaway: float,
        start: int,
        budget: int,
    ) -> tuple:
        """The descent's iterations `start` to `budget` compiled (`solve.newton_kernel.descent_kernel`),
        to the first event the interpreter decides on (an equilibrium, a stuck shift) or an end; `external`
        is gravity's share, the live load's multiplier and the fill's springs."""
        problem = self._problem(u_before, shear_before, *external)
        return DESCENT_KERNEL(problem, u, floor, shift, origin, runaway, start, budget)

    def _kick(self, u: np.ndarray, stiffness: np.ndarray) -> np.ndarray:
        """`u` moved along the softest mode of `stiffness`, the way the weights go down (for a mode they
        do not work on, the way that moves the blocks' weighted order up): by KICK_FRACTION x max_step,
        or as far as needed for the mode's negative stiffness to push KICK_RESOLUTION x the converged
        residual (a nearly neutral mode, near a bifurcation, would otherwise leave a state that still
        passes for an equilibrium), at most max_step."""
        value, mode = banded.softest_mode(stiffness)
        mode = mode / float(np.abs(mode).max())
        loads = self.arch.loads()[self.free]
        side = float(loads @ mode)
        if abs(side) <= TIED_LOADS * float(np.abs(loads).sum()):
            side = float(np.arange(1, mode.size + 1) @ mode)
        if side < 0.0:
            mode = -mode
        step = self.settings.max_step
        length = KICK_FRACTION * step
        if value < 0.0:
            length = max(length, KICK_RESOLUTION * self.converged / -value)
        kicked = u.copy()
        kicked[self.free] += min(length, step) * mode
        return kicked


def largest_move(u: np.ndarray, start: np.ndarray) -> float:
    """The largest translation of a block between two generalised states (m)."""
    moves = (u - start).reshape(-1, BLOCK_DOFS)[:, 0:2]
    return float(np.hypot(moves[:, 0], moves[:, 1]).max())
