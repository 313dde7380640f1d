"""Newton's iterations at one support position compiled whole (numba): each iteration evaluates the
joints, residual and band tangent in one kernel (`model.block_state.free_state_kernel`), solves by
the banded LU (`solve.banded.band_solve`), caps the step and backtracks on |R|^2, the same arithmetic
in the same order as the Python loop it replaces, without an interpreter round trip an iteration."""

from __future__ import annotations

import numpy as np
from numba import njit

from yadearch.model.block_state import free_state_kernel
from yadearch.model.joint_tangent import BLOCK_DOFS
from yadearch.solve.banded import band_solve, positive_definite

INDEFINITE_BACKTRACKS = 3  # halvings of a step from an indefinite tangent before Newton gives up, a
# heuristic: past a fold a solve stalled in the fold's ghost (|R| stuck near 1e-4 N for 4-20 iterations,
# the last line search spending all 12 halvings); a solve near the fold that would still have reached a
# stable state is given up too, and the fold's bracket falls one step lower (docs/speed.md)


@njit(cache=True)
def newton_kernel(problem, u0, iterations, backtracks, sufficient_decrease):
    """Newton from `u0` with a backtracking line search on `problem` (`_evaluate`): (u, loops,
    evaluations, success, state), the state being `free_state_kernel`'s outputs at u; loops counts
    the iterations begun, as the interpreted loop counts them. A step whose line search has halved it
    INDEFINITE_BACKTRACKS times from an indefinite tangent fails the solve."""
    u = u0.copy()
    state = _evaluate(problem, u)
    converged, max_step = problem[7], problem[8]
    evaluations = 1
    first = BLOCK_DOFS
    for iteration in range(iterations):
        residual, stiffness = state[8], state[9]
        if np.abs(residual).max() <= converged:
            return u, iteration + 1, evaluations, True, state
        d, singular = band_solve(stiffness, residual, 0.0)
        if singular:
            return u, iteration + 1, evaluations, False, state
        largest = np.abs(d).max()
        if largest > 0.0:
            d = d * min(1.0, max_step / largest)
        merit, alpha = residual @ residual, 1.0
        accepted = False
        trial = u.copy()
        for halvings in range(backtracks):
            if halvings == INDEFINITE_BACKTRACKS and not positive_definite(stiffness):
                break  # past a fold, most likely: give the solve up (INDEFINITE_BACKTRACKS)
            trial = u.copy()
            trial[first : first + d.shape[0]] += alpha * d
            trial_state = _evaluate(problem, trial)
            evaluations += 1
            trial_residual = trial_state[8]
            if trial_residual @ trial_residual <= (1.0 - sufficient_decrease * alpha) * merit:
                accepted = True
                break
            alpha *= 0.5
        if not accepted:
            return u, iteration + 1, evaluations, False, state
        u, state = trial, trial_state
    return u, iterations, evaluations, False, state


CONVERGED, STUCK, RUNAWAY, TIMEOUT = 0, 1, 2, 3  # why `descent_kernel` hands back
SHIFT_GROWTH = 10.0  # the descent's shift grows by this after a step that would take energy in
SHIFT_FALL = 0.3  # ... and falls by this after one that releases energy
MAX_SHIFT_RATIO = 1e12  # a shift this many times its start means no step releases energy any more
MIN_SHIFT_RATIO = 1e-12  # the shift falls no lower (Newton's own steps)


@njit(cache=True)
def descent_kernel(
    problem,
    u0,
    floor,
    shift,
    origin,
    runaway,
    start,
    budget,
):
    """The descent's damped Newton steps (K + shift I) d = R from `u0`, iterations `start` to
    `budget`, until an equilibrium (CONVERGED), a shift past `MAX_SHIFT_RATIO` x `floor` (STUCK), a
    block `runaway` from `origin` (RUNAWAY) or the budget's end (TIMEOUT): (u, iteration, evaluations,
    event, floor, shift, state). A `floor` <= 0 is set from the first state: its stiffest diagonal
    term, or a whole joint's normal stiffness where nothing touches yet."""
    u = u0.copy()
    state = _evaluate(problem, u)
    converged, max_step = problem[7], problem[8]
    evaluations = 1
    if floor <= 0.0:
        kn_depth, length, band = problem[0][9], problem[0][6], problem[6]
        floor = max(np.abs(state[9][band]).max(), kn_depth * length.max())
        shift = floor
    first = BLOCK_DOFS
    for iteration in range(start, budget):
        residual, stiffness = state[8], state[9]
        if np.abs(residual).max() <= converged:
            return u, iteration, evaluations, CONVERGED, floor, shift, state
        if shift > MAX_SHIFT_RATIO * floor:
            return u, iteration, evaluations, STUCK, floor, shift, state
        d, singular = band_solve(stiffness, residual, shift)
        if singular:
            shift *= SHIFT_GROWTH
            continue
        largest = np.abs(d).max()
        if largest > 0.0:
            d = d * min(1.0, max_step / largest)
        trial = u.copy()
        trial[first : first + d.shape[0]] += d
        trial_state = _evaluate(problem, trial)
        evaluations += 1
        if not (residual + trial_state[8]) @ d > 0.0:
            shift *= SHIFT_GROWTH
            continue
        shift = max(shift * SHIFT_FALL, MIN_SHIFT_RATIO * floor)
        u, state = trial, trial_state
        if _largest_move(u, origin) > runaway:
            return u, iteration + 1, evaluations, RUNAWAY, floor, shift, state
    return u, budget, evaluations, TIMEOUT, floor, shift, state


@njit(cache=True)
def _evaluate(problem, u):
    """`free_state_kernel` at `u` for a `problem`: (kernel table, u_before, shear_before, weights,
    gravity, lever, band, converged residual, largest step, the loads besides the weights, their
    factor, the fill's passive springs), as `solve.newton.Solver` packs it."""
    kernel, u_before, shear_before, weight, gravity, lever, band = problem[:7]
    loads, factor, passive = problem[9], problem[10], problem[11]
    return free_state_kernel(kernel, u, u_before, shear_before, weight, gravity, lever, band, loads, factor, passive)


@njit(cache=True)
def _largest_move(u, start):
    """`solve.newton.largest_move`: the largest translation of a block between two states (m)."""
    largest = 0.0
    for b in range(u.shape[0] // BLOCK_DOFS):
        dx, dy = u[BLOCK_DOFS * b] - start[BLOCK_DOFS * b], u[BLOCK_DOFS * b + 1] - start[BLOCK_DOFS * b + 1]
        largest = max(largest, np.hypot(dx, dy))
    return largest
