"""The descending branch of a live load's path past its limit point (pure numpy/numba): arc-length
continuation from the last stable state of the load-controlled path, the multiplier an unknown
(docs/loads.md).

Each step goes a length along the path in the free blocks' displacements (a cylindrical arc length:
the multiplier has no weight in it) and solves equilibrium on the plane normal to the predictor there
(Riks 1979, Crisfield 1981): Newton's method on the bordered system [K -f; n' 0], by two banded
solves an iteration, K a = R and K b = f, the multiplier's correction from the plane. The path passes
the fold where the load control stops and follows the mechanism's softening, and a snap-back of the
load's displacement too, as a displacement-controlled test could not.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np
from numba import njit

from yadearch.model.block_state import as_joints, free_state_kernel
from yadearch.model.joint_tangent import BLOCK_DOFS
from yadearch.solve import banded
from yadearch.solve.banded import band_solve
from yadearch.solve.collapse_mode import fold_mode
from yadearch.solve.newton import BACKTRACKS, SUFFICIENT_DECREASE, largest_move
from yadearch.solve.path import extrapolate
from yadearch.solve.stages import Stage
from yadearch.solve.static_path import PREDICTOR_POINTS, StaticLoading
from yadearch.solve.static_state import StaticState
from yadearch.solve.statics import WARM_UP_VOUSSOIRS, static_arch

FIRST_STEP = 5e-3  # the first arc length: this x the ring's thickness
LARGEST_STEP = 0.1  # ... the largest
LEAST_STEP = 1e-5  # ... and the least: a step that must be shorter has lost the branch
STEP_GROWTH = 1.5  # a step that converged quickly is followed by one this much longer
QUICK_ITERATIONS = 6  # ... quickly: within this many iterations
HALVING = 0.5  # a step that fails is tried again this much shorter
ITERATIONS = 30  # Newton iterations a step may take
MAX_STEPS = 300  # steps a branch may take (set 2's at kn 5.2 take 13 to 26 to half the capacity)
DESCEND_TO = 0.5  # by default the branch ends when the multiplier has fallen to this x the capacity
# a branch whose multiplier rises above the capacity by more than the load path's bracket (0.1 %,
# `solve.load_path.TOLERANCE_FRACTION`) shows the load-controlled path stopped short of its limit point
RISE_FRACTION = 1e-3


class DescentEnd(StrEnum):
    """Why the traced descending branch ends."""

    FALLEN = "fallen"  # the multiplier fell to the fraction of the capacity asked for
    RUNAWAY = "runaway"  # a block moved the runaway bound from the last stable state: the mechanism runs
    LOST = "lost"  # no equilibrium near the branch even with the least step
    STEPS = "steps"  # MAX_STEPS taken
    ROSE = "rose"  # the multiplier rose above the capacity: the load control stopped short of its peak


@dataclass
class Descent:
    """The states traced past the last stable one (in order) and why the branch ends."""

    states: list[StaticState] = field(default_factory=list)
    end: DescentEnd = DescentEnd.LOST
    hinges: tuple[str, ...] = ()  # the joints the last step turns: the mechanism where the branch ends


def descend(loading: StaticLoading, capacity: float, descend_to: float = DESCEND_TO) -> Descent:
    """The equilibrium path of `loading` past its limit point by arc length from its last accepted
    (stable) state, until the multiplier falls to `descend_to` x `capacity`, a block runs away
    (`loading.runaway` from that state) or the branch is lost; every state an equilibrium of its
    multiplier (the residual within the solver's tolerance)."""
    arch, solver = loading.arch, loading.solver
    stable = loading.accepted[-1]
    free = arch.free_dofs
    thickness = arch.length
    history = _arc_lengths(loading.accepted[-PREDICTOR_POINTS:], free)
    descent = Descent()
    step = FIRST_STEP * thickness
    while len(descent.states) < MAX_STEPS:
        done, last = history[-1]
        guess_u, guess_lam = _predict(history, done + step) if len(history) > 1 else _tangent(loading, step)
        normal = (guess_u - last.u)[free]
        length = float(np.linalg.norm(normal))
        if not length > 0.0:  # a predictor that does not move (or is not finite) has lost the branch
            return _ended(descent, DescentEnd.LOST, loading)
        normal /= length
        u, lam, iterations, success, state = bordered_kernel(
            arch.kernel, last.u, last.forces.shear_force, arch.weight, thickness, banded.BAND,
            solver.converged, solver.settings.max_step, np.ascontiguousarray(arch.dead),
            np.ascontiguousarray(arch.live), arch.springs_or_unyielded(last.springs), normal, guess_u, guess_lam,
            ITERATIONS,
        )  # fmt: skip
        if not success or largest_move(u, guess_u) > loading.snap_floor or _turned_back(history, u, free):
            step *= HALVING
            if step < LEAST_STEP * thickness:
                return _ended(descent, DescentEnd.LOST, loading)
            continue
        joints, residual, stiffness = as_joints(state)
        forces = joints.forces
        reached = StaticState(
            Stage.EQUILIBRIUM, lam, u, forces, last.slip + forces.plastic_slip, iterations,
            float(np.abs(residual).max()) / solver.scale, stiffness=stiffness, springs=arch.yielded(last.springs, u),
        )  # fmt: skip
        descent.states.append(reached)
        history = (history + [(done + float(np.linalg.norm((u - last.u)[free])), reached)])[-PREDICTOR_POINTS:]
        end = branch_end(lam, capacity, descend_to, largest_move(u, stable.u) >= loading.runaway)
        if end is not None:
            return _ended(descent, end, loading)
        if iterations <= QUICK_ITERATIONS:
            step = min(step * STEP_GROWTH, LARGEST_STEP * thickness)
    return _ended(descent, DescentEnd.STEPS, loading)


def branch_end(load: float, capacity: float, descend_to: float, ran_away: bool) -> DescentEnd | None:
    """Why a branch past the peak ends at a state of multiplier `load`, in this order: risen past the
    `capacity`, fallen to `descend_to` x it, a block `ran_away` from the last stable state; None: on."""
    if load > (1.0 + RISE_FRACTION) * capacity:
        return DescentEnd.ROSE
    if load <= descend_to * capacity:
        return DescentEnd.FALLEN
    return DescentEnd.RUNAWAY if ran_away else None


def _ended(descent: Descent, end: DescentEnd, loading: StaticLoading) -> Descent:
    """`descent` ending for `end`, with the hinges its last step turns (`solve.collapse_mode.fold_mode`
    of that step's motion)."""
    descent.end = end
    if descent.states:
        before = descent.states[-2] if len(descent.states) > 1 else loading.accepted[-1]
        assert before.stiffness is not None  # every state is made from the solver's equilibrium
        mode = fold_mode(loading.arch, before.u, before.stiffness, descent.states[-1].u, before.springs)
        descent.hinges = tuple(mode.labels)
    return descent


def _turned_back(history: list[tuple[float, StaticState]], u: np.ndarray, free: np.ndarray) -> bool:
    """Whether the step to `u` goes back along the path (against the last secant of `history`): the
    plane met the branch behind, where it folds sharply (a hinge moving to the next joint)."""
    if len(history) < 2:
        return False
    last, before = history[-1][1].u, history[-2][1].u
    return float((u - last)[free] @ (last - before)[free]) <= 0.0


def _arc_lengths(states: list[StaticState], free: np.ndarray) -> list[tuple[float, StaticState]]:
    """`states` with their arc length along the path (m; the free blocks' displacements), the states
    that did not move dropped (the predictor's nodes must be distinct)."""
    history = [(0.0, states[0])]
    for state in states[1:]:
        gone = float(np.linalg.norm((state.u - history[-1][1].u)[free]))
        if gone > 0.0:
            history.append((history[-1][0] + gone, state))
    return history


def _predict(history: list[tuple[float, StaticState]], target: float) -> tuple[np.ndarray, float]:
    """The state at arc length `target`: the Lagrange polynomial in the arc length through the last
    states (a parabola through three: the blocks of a turning segment move on arcs, and with stiff
    joints a chord's error alone would open a joint)."""
    lengths = [s for s, _ in history]
    u = extrapolate(lengths, [state.u for _, state in history], target)
    lam = extrapolate(lengths, [np.array([state.lam]) for _, state in history], target)
    return u, float(lam[0])


def _tangent(loading: StaticLoading, step: float) -> tuple[np.ndarray, float]:
    """The state `step` along the tangent from the only state of the path (the load's growth K^-1 f)."""
    state = loading.accepted[-1]
    assert state.stiffness is not None  # every state is made from the solver's equilibrium
    free = loading.arch.free_dofs
    growth = banded.solve(state.stiffness, loading.arch.live_forces(state.u))
    scale = step / float(np.linalg.norm(growth))
    u = state.u.copy()
    u[free] += scale * growth
    return u, state.lam + scale


@njit(cache=True)
def _live_forces(live, u, lever):
    """The live load of multiplier 1 on the free blocks at `u` (`solve.statics.StaticArch.live_forces`):
    the residual's change with the multiplier."""
    n = live.shape[0]
    f = np.zeros(BLOCK_DOFS * (n - 2))
    for b in range(1, n - 1):
        k = BLOCK_DOFS * (b - 1)
        t = u[BLOCK_DOFS * b + 2] / lever
        f[k], f[k + 1] = live[b, 0], live[b, 1]
        f[k + 2] = (np.cos(t) * live[b, 2] - np.sin(t) * live[b, 3]) / lever
    return f


@njit(cache=True)
def bordered_kernel(
    kernel, u_before, shear_before, weight, lever, band, converged, max_step,
    dead, live, passive, normal, u_guess, lam_guess, iterations,
):  # fmt: skip
    """Newton on R(u, lam) = 0 (joint forces + weights + dead loads + lam x live load on the free
    blocks) on the plane through `u_guess` normal to `normal` (a unit vector of the free blocks'
    displacements), from (`u_guess`, `lam_guess`): K a = R, K b = f, d lam = -n.a / n.b, du = a +
    d lam b, which stays on the plane; capped at `max_step` and halved until |R|^2 falls. (u, lam,
    iterations, success, state at u)."""
    u, lam = u_guess.copy(), lam_guess
    loads = dead + lam * live
    state = free_state_kernel(kernel, u, u_before, shear_before, weight, 1.0, lever, band, loads, 1.0, passive)
    first = BLOCK_DOFS
    for iteration in range(iterations):
        residual, stiffness = state[8], state[9]
        if np.abs(residual).max() <= converged:
            return u, lam, iteration, True, state
        a, singular = band_solve(stiffness, residual, 0.0)
        b, singular_too = band_solve(stiffness, _live_forces(live, u, lever), 0.0)
        along = normal @ b
        if singular or singular_too or along == 0.0:
            break
        more = -(normal @ a) / along
        d = a + more * b
        largest = np.abs(d).max()
        if largest > max_step:
            d, more = d * (max_step / largest), more * (max_step / largest)
        merit, alpha, accepted = residual @ residual, 1.0, False
        for _ in range(BACKTRACKS):
            trial = u.copy()
            trial[first : first + d.shape[0]] += alpha * d
            loads = dead + (lam + alpha * more) * live
            trial_state = free_state_kernel(
                kernel, trial, u_before, shear_before, weight, 1.0, lever, band, loads, 1.0, passive
            )
            if trial_state[8] @ trial_state[8] <= (1.0 - SUFFICIENT_DECREASE * alpha) * merit:
                accepted = True
                break
            alpha *= HALVING
        if not accepted:
            break
        u, lam, state = trial, lam + alpha * more, trial_state
    return u, lam, iterations, bool(np.abs(state[8]).max() <= converged), state


def compile_kernel() -> None:
    """Compile the descending branch's kernel once into numba's cache (scripts/setup.sh calls this after
    `solve.statics.compile_kernels`, so that a fresh install's first load path does not wait for it)."""
    from yadearch.case.config import preset

    case = preset("set2").with_overrides({"geometry.n_voussoirs": WARM_UP_VOUSSOIRS, "live_load": "vertical"})
    arch = static_arch(case)
    u, shear = arch.at_rest(), np.zeros(len(arch.table.left))
    normal = np.ones(len(arch.free_dofs)) / np.sqrt(len(arch.free_dofs))
    bordered_kernel(
        arch.kernel, u, shear, arch.weight, arch.length, banded.BAND, 1e-9, 1e-4,
        np.ascontiguousarray(arch.dead), np.ascontiguousarray(arch.live), arch.passive, normal, u, 0.0, 2,
    )  # fmt: skip
