"""The static engine's equilibrium oracle (pure numpy, no YADE): self-weight, then each support
position solved by Newton's method from a predictor, a descent where Newton fails, and the same
path logic as the DEM (`solve.path`) to bracket du (docs/theory.md, "The static engine").

An increment is accepted when the arch is in a stable equilibrium (the free blocks' tangent
stiffness positive definite) no block of which stands further than `runaway` from the predicted
state; past a fold, the descent decides as the DEM's hold does: a stable state within `runaway` is
a snap survived, a block moving `runaway` is collapse.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from yadearch.errors import CANNOT_STAND
from yadearch.model.joint_law import JointForces
from yadearch.solve import banded
from yadearch.solve.banded import smallest_eigenvalue
from yadearch.solve.newton import Equilibrium, Solver, SolverSettings
from yadearch.solve.path import PathResult, PathSettings, PathStep, follow_path
from yadearch.solve.stages import Stage, Verdict
from yadearch.solve.statics import StaticArch

GRAVITY_STEPS = 10  # the self-weight is applied in this many equal load steps
SELFWEIGHT_FALL = 0.05  # a block falling this far (m) under self-weight means the arch cannot stand
SNAP_FRACTION = 0.1  # a descent that moves a block this x runaway to a stable state is a snap survived
SUBSTEPS = 8  # an increment Newton cannot solve at once is marched in this many steps
PREDICTOR_POINTS = 3  # accepted states the predictor extrapolates through (a parabola)
COLLAPSE_RUNAWAYS = 10.0  # the mechanism at collapse is shown this many runaway distances on


class StaticEngineError(RuntimeError):
    """The static engine cannot go on (no self-weight equilibrium)."""


@dataclass
class StaticState:
    """An equilibrium (or the collapse) state: where the support was, the blocks, the joints."""

    stage: str
    lam: float
    u: np.ndarray
    forces: JointForces
    slip: np.ndarray  # each joint's accumulated sliding beyond its Coulomb cap (m)
    min_stiffness: float
    iterations: int
    residual: float
    move: float = 0.0  # how far the blocks moved from the predicted state to reach it (m)


@dataclass
class StaticLoading:
    """The path of one arch: its accepted states, the failures, and the solver's counts."""

    arch: StaticArch
    settings: PathSettings
    runaway: float
    solver_settings: SolverSettings = field(default_factory=SolverSettings)

    def __post_init__(self) -> None:
        self.solver = Solver(self.arch, self.solver_settings)
        self.accepted: list[StaticState] = []
        self.failures: dict[float, Equilibrium] = {}
        self.snaps: list[dict] = []  # increments the descent carried to a state SNAP_FRACTION x runaway away
        self.descents = 0  # increments Newton did not solve
        self._trial: StaticState | None = None

    # ---- self-weight ------------------------------------------------------------------------
    def selfweight(self) -> StaticState:
        """Gravity in GRAVITY_STEPS load steps from the blocks exactly touching: the first solved by the
        descent (the joints have no stiffness before they are pressed), the others by Newton from the
        last (by the descent where Newton fails); the joints' shear is carried from step to step, as
        the DEM carries it, so that a joint counts only the sliding it makes while it touches (a change of
        the engine's results raises `results.summary.STATIC_REVISION`)."""
        u = self.arch.with_supports(self.arch.at_rest(), 0.0)
        shear = np.zeros(len(self.arch.table.left))
        slip = np.zeros_like(shear)
        for k in range(1, GRAVITY_STEPS + 1):
            pressed = self.solver.newton(u, u, shear, gravity=k / GRAVITY_STEPS) if k > 1 else None
            found = (
                pressed
                if pressed is not None and pressed.stable()
                else self.solver.descend(u, u, shear, SELFWEIGHT_FALL, gravity=k / GRAVITY_STEPS)
            )
            if found.verdict != Verdict.STABLE:
                raise StaticEngineError(
                    f"{CANNOT_STAND} ({found.verdict} at {k}/{GRAVITY_STEPS} "
                    f"of gravity, a block moved {1e3 * found.moved:.1f} mm)"
                )
            u, shear = found.u, found.joints.forces.shear_force
            slip = slip + found.joints.forces.plastic_slip
        state = self._state(Stage.SELFWEIGHT, 0.0, found, slip, found.joints.forces)
        self.accepted = [state]
        return state

    # ---- the oracle ---------------------------------------------------------------------------
    def try_increment(self, target: float) -> Verdict:
        """Solve the arch with the support at `target` from the last accepted state: Newton from the
        predicted state, or, where that fails, a march to `target` in SUBSTEPS steps (`_march`)."""
        base = self.accepted[-1]
        found = self._newton(self.accepted, target)
        if found is None:
            return self._march(target)
        self._trial = self._state(
            Stage.EQUILIBRIUM, target, found, base.slip + found.joints.forces.plastic_slip, found.joints.forces
        )
        self._trial.move = found.moved
        return Verdict.STABLE

    def _newton(self, history: list[StaticState], target: float) -> Equilibrium | None:
        """Newton from the state predicted at `target` through `history`; None unless it ends in a
        stable equilibrium within `runaway` of the prediction."""
        last = history[-1]
        found = self.solver.newton(self.predict(target, history), last.u, last.forces.shear_force)
        if found is None or not found.stable() or found.moved > self.runaway:
            return None
        return found

    def _march(self, target: float) -> Verdict:
        """From the last accepted state to `target` in SUBSTEPS equal steps, each solved by Newton or,
        where Newton fails (the path folds: a hinge snaps), by the descent from the state predicted
        there, as the DEM's arch snaps during its move, where the fold is, not at the move's end. A
        descent that runs away is the increment's failure; one that settles is a snap survived."""
        history = list(self.accepted[-PREDICTOR_POINTS:])
        start, slip, largest = history[-1].lam, history[-1].slip, 0.0
        for k in range(1, SUBSTEPS + 1):
            lam = start + (target - start) * k / SUBSTEPS
            found = self._newton(history, lam)
            jumped = found is None
            if found is None:
                last = history[-1]
                found = self.solver.descend(self.predict(lam, history), last.u, last.forces.shear_force, self.runaway)
                self.descents += 1
                if found.verdict != Verdict.STABLE:
                    self.failures[target] = found
                    return found.verdict
                if found.moved > SNAP_FRACTION * self.runaway:
                    self.snaps.append({"delta_mm": 1e3 * lam, "move_mm": 1e3 * found.moved})
            largest, slip = max(largest, found.moved), slip + found.joints.forces.plastic_slip
            state = self._state(Stage.EQUILIBRIUM, lam, found, slip, found.joints.forces)
            history = [state] if jumped else (history + [state])[-PREDICTOR_POINTS:]
        self._trial = state
        self._trial.move = largest
        return Verdict.STABLE

    @property
    def iterations(self) -> int:
        """Newton and descent iterations so far."""
        return self.solver.iterations

    def accept(self) -> None:
        assert self._trial is not None
        self._trial.min_stiffness = smallest_eigenvalue(self._stiffness_of(self._trial))
        self.accepted.append(self._trial)
        self._trial = None

    def settle(self) -> bool:
        """A static equilibrium is at rest already: nothing creeps."""
        return True

    def discard(self) -> None:
        self.accepted.pop()

    def predict(self, target: float, history: list[StaticState]) -> np.ndarray:
        """Where the arch should be with the support at `target`: a parabola (or a line) through the
        last states of `history`, or from a single state the tangent's response to the support's move."""
        last = history[-1]
        history = history[-PREDICTOR_POINTS:]
        lams = [s.lam for s in history]
        if len(set(lams)) == len(lams) >= 2:  # Lagrange extrapolation through the last states
            weights = [
                np.prod([(target - lams[m]) / (lams[k] - lams[m]) for m in range(len(lams)) if m != k])
                for k in range(len(lams))
            ]
            return self.arch.with_supports(sum(w * s.u for w, s in zip(weights, history)), target)
        moved = self.arch.with_supports(last.u, target)
        stiffness = self.arch.stiffness(self.solver.state(last.u, last.u, last.forces.shear_force)[0])
        free = self.arch.free_dofs
        driven = np.setdiff1d(np.arange(len(moved)), free)
        load = -stiffness[np.ix_(free, driven)] @ (moved - last.u)[driven]
        try:
            moved[free] += banded.solve(banded.from_dense(stiffness[np.ix_(free, free)]), load)
        except (np.linalg.LinAlgError, ValueError):
            pass  # a singular tangent: the descent starts from the state with only the support moved
        return moved

    # ---- the whole path ---------------------------------------------------------------------------
    def follow(self, on_step: Callable[[PathStep], None] | None = None) -> PathResult:
        """From the self-weight state, increments to collapse (`solve.path.follow_path`)."""
        return follow_path(self, self.settings, on_step=on_step)

    def collapse_state(self, upper: float) -> StaticState:
        """The mechanism at collapse: the failure at du's upper bracket end carried on until a block
        has moved COLLAPSE_RUNAWAYS runaway distances."""
        lam = min(self.failures, key=lambda d: abs(d - upper))
        failure = self.failures[lam]
        base = self.accepted[-1]
        shear = base.forces.shear_force
        carried = self.solver.descend(failure.u, base.u, shear, COLLAPSE_RUNAWAYS * self.runaway)
        end = carried if carried.verdict != Verdict.STABLE else failure
        return self._state(Stage.COLLAPSE, lam, end, base.slip + end.joints.forces.plastic_slip, end.joints.forces)

    def _state(self, stage: str, lam: float, found: Equilibrium, slip: np.ndarray, forces: JointForces) -> StaticState:
        return StaticState(stage, lam, found.u, forces, slip, float("nan"), found.iterations, found.residual)

    def _stiffness_of(self, state: StaticState) -> np.ndarray:
        base = self.accepted[-1]
        joints, _ = self.solver.state(state.u, base.u, base.forces.shear_force)
        return self.solver.free_stiffness(joints)
