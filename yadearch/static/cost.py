"""What the static engine's solver costs against its floor (issue 45; `scripts/benchmark.py
--static-floor`): the solver's CPU time on a case's whole path beside the time of the same number of
joint evaluations and banded solves in one compiled loop, with nothing else, measured in the same
process; their ratio says how far the solver is from the cost of its arithmetic."""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np
from numba import njit

from yadearch.case.config import ArchCase
from yadearch.model.block_state import free_state_kernel
from yadearch.solve import banded
from yadearch.solve.banded import band_solve
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import compile_kernels

FLOOR_REPEATS = 20  # each accepted state evaluated and solved this many times for the floor
SOLVER_REPEATS = 5  # the path solved this many times, its best CPU time kept (the first call of a
# process loads the kernels from numba's cache; a busy machine slows single runs by up to half)
TARGET_FLOOR_RATIO = 1.5  # issue 45: the solver at most this many times its floor


@dataclass(frozen=True)
class SolverCost:
    """A case's solver CPU time (s), joint evaluations and iterations on its path, and the floor: the
    CPU time of an evaluation and of a banded solve in a compiled loop."""

    name: str
    solver_cpu_s: float
    evaluations: int
    iterations: int
    evaluation_s: float  # one joint evaluation (joints, residual, band tangent) in the compiled loop
    solve_s: float  # one banded LU solve in it

    @property
    def floor_cpu_s(self) -> float:
        """The path's arithmetic alone: its evaluations and one solve an iteration."""
        return self.evaluations * self.evaluation_s + self.iterations * self.solve_s

    @property
    def ratio(self) -> float:
        return self.solver_cpu_s / self.floor_cpu_s


def solver_cost(case: ArchCase, repeats: int = FLOOR_REPEATS) -> SolverCost:
    """Solve `case`'s path by the static engine (self-weight and loading) SOLVER_REPEATS times, keeping
    the best CPU time, then time `repeats` evaluations and solves of each accepted state in the
    compiled floor loop (best of the same number of rounds)."""
    compile_kernels()
    loadings = [StaticLoading.of(case) for _ in range(SOLVER_REPEATS)]  # each path solved afresh
    solver_cpu = _best_cpu_s([partial(_solve, loading) for loading in loadings])
    loading = loadings[-1]
    arch = loading.arch
    states = np.array([s.u for s in loading.accepted])
    shears = np.array([s.forces.shear_force for s in loading.accepted])
    args = (arch.kernel, states, shears, arch.weight, arch.length, banded.BAND, arch.live, arch.passive)
    per_state: list[float] = []
    for solve in (False, True):
        _floor_loop(*args, 1, solve)  # compiled before it is timed
        rounds = [partial(_floor_loop, *args, repeats, solve)] * SOLVER_REPEATS
        per_state.append(_best_cpu_s(rounds) / (repeats * len(states)))
    evaluation, both = per_state
    solver = loading.solver
    return SolverCost(
        case.name, solver_cpu, solver.evaluations, solver.iterations, evaluation, max(both - evaluation, 0.0)
    )


def _solve(loading: StaticLoading) -> None:
    """A path's self-weight and loading, as the engine solves them."""
    loading.selfweight()
    loading.follow()


def _best_cpu_s(calls: Sequence[Callable[[], object]]) -> float:
    """The least CPU time (s) of the `calls`, each timed on its own."""
    best = float("inf")
    for call in calls:
        start = time.process_time()
        call()
        best = min(best, time.process_time() - start)
    return best


@njit(cache=True)
def _floor_loop(kernel, states, shears, weight, lever, band, live, passive, repeats, solve):
    """Evaluate the joints at every state (and solve the tangent, with `solve`), `repeats` times (a
    checksum returned so that nothing is optimised away)."""
    total = 0.0
    for _ in range(repeats):
        for k in range(states.shape[0]):
            state = free_state_kernel(
                kernel, states[k], states[k], shears[k], weight, 1.0, lever, band, live, 0.0, passive
            )
            total += state[8][0]
            if solve:
                d, _singular = band_solve(state[9], state[8], 0.0)
                total += d[0]
    return total
