"""The static engine's equilibrium oracle (pure numpy, no YADE): self-weight, then each support
position solved by Newton's method from a predictor, a descent where Newton fails, and the same
path logic as the DEM (`solve.path`) to bracket du (docs/theory.md, "The static engine").

An increment is accepted when the arch is in a stable equilibrium (the free blocks' tangent
stiffness positive definite) reached by continuation: Newton from the predicted state, no block
further from it than the increment itself. Where continuation fails the fold is located by bisection
(the first loss of stability, du_first) and the descent decides as the DEM's hold does: a stable
state is a snap survived however far it moves, a block moving the runaway bound (a multiple of the
ring's thickness) is collapse, and a descent that finds neither, after its retries, leaves the
increment unresolved, never collapsed.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import runaway_length
from yadearch.case.numerics_section import RUNAWAY_THICKNESS_RATIO
from yadearch.case.support import path_end_mm
from yadearch.model import units
from yadearch.model.joint_law import JointForces
from yadearch.solve.collapse_mode import FoldMode, fold_mode
from yadearch.solve.falls import fall
from yadearch.solve.gravity_ramp import CONFIRMING_STEPS, GRAVITY_STEPS, ramps_to_stand
from yadearch.solve.newton import Equilibrium, Solver, SolverSettings
from yadearch.solve.path import PathResult, PathSettings, PathStep, extrapolate, first_snap, follow_path, path_settings
from yadearch.solve.prediction import tangent_prediction
from yadearch.solve.stages import Stage, Verdict
from yadearch.solve.static_state import PathParameter, StaticState
from yadearch.solve.statics import StaticArch, static_arch

SUBSTEPS = 8  # an increment Newton cannot solve at once is marched in this many steps
PREDICTOR_POINTS = 3  # accepted states the predictor extrapolates through (a parabola)


@dataclass
class StaticLoading:
    """The path of one arch: its accepted states, the failures, and the solver's counts."""

    arch: StaticArch
    settings: PathSettings
    runaway: float
    solver_settings: SolverSettings = field(default_factory=SolverSettings)
    parameter: PathParameter = field(default_factory=PathParameter)

    @classmethod
    def of(cls, case: ArchCase, solver_settings: SolverSettings | None = None) -> StaticLoading:
        """The path of `case`'s arch along its support movement, to its end, runaway bound from the case."""
        arch = static_arch(case)
        settings = path_settings(case.numerics, path_end_mm(case, arch.movement))
        return cls(arch, settings, runaway_length(case), solver_settings or SolverSettings())

    def __post_init__(self) -> None:
        self.solver = Solver(self.arch, self.solver_settings)
        self.accepted: list[StaticState] = []
        self.failures: dict[float, Equilibrium] = {}
        self.falls: dict[float, tuple[list[StaticState], float]] = {}  # each failure's descent: history, where
        self.readings: dict[float, Equilibrium] = {}  # each failure fallen the default bound (`collapse_fall`)
        self.snaps: list[dict] = []  # snaps survived on the accepted path: where, how far the blocks moved
        self.descents = 0  # descents made (Newton's continuation failed)
        self.retries = 0  # descents that found neither equilibrium nor runaway and went on
        # a descent landing further than this from the prediction at the fold is a snap, a new branch: a
        # length of the arch (numerics.snap_thickness_ratio x its thickness), not of the bracket or the step
        self.snap_floor = self.settings.snap_ratio * self.arch.length
        self._trial: StaticState | None = None
        self._trial_snaps: list[dict] = []
        self.ramps: list[dict] = []  # the self-weight's gravity ramps: steps, verdict, gravity reached, move

    # ---- self-weight ------------------------------------------------------------------------
    def selfweight(self) -> StaticState:
        """Gravity in GRAVITY_STEPS load steps from the blocks exactly touching, again in CONFIRMING_STEPS
        where that falls or fails (`gravity_ramp.ramps_to_stand`; both recorded in `ramps`)."""
        self.ramps = []
        found, slip = ramps_to_stand(self.arch, self.solver, self._fall, (GRAVITY_STEPS, CONFIRMING_STEPS), self.ramps)
        state = self._state(Stage.SELFWEIGHT, 0.0, found, slip, found.joints.forces)
        self.accepted = [state]
        return state

    # ---- the oracle ---------------------------------------------------------------------------
    def try_increment(self, target: float) -> Verdict:
        """Solve the arch with the support at `target` from the last accepted state: Newton from the
        predicted state, or, where that fails, a march to `target` in SUBSTEPS steps (`_march`)."""
        self._trial_snaps = []
        history = self.accepted[-PREDICTOR_POINTS:]
        found = self._continue(history, target)
        if found is None:
            return self._march(target)
        self._trial = self._advance(history, target, found)
        self._trial.move = found.moved
        return Verdict.STABLE

    def _continue(self, history: list[StaticState], target: float) -> Equilibrium | None:
        """Newton from the state predicted at `target` through `history`; None unless it ends in a
        stable equilibrium on the same branch: no block further from the prediction than the snap
        floor, whatever the step (a jump hidden in a long step would hide a snap)."""
        last = history[-1]
        found = self.solver.newton(
            self.predict(target, history),
            last.u,
            last.forces.shear_force,
            multiplier=self.parameter.multiplier(target),
            springs=last.springs,
        )
        if found is None or not found.stable() or found.moved > self.snap_floor:
            return None
        return found

    def _march(self, target: float) -> Verdict:
        """From the last accepted state to `target` in SUBSTEPS steps by continuation; where it fails
        (the path folds: a hinge snaps), the fold is located by bisection and the descent goes on from
        the state predicted just past it, as the DEM's arch snaps during its move, where the fold is.
        A descent that runs away (or finds nothing) is the increment's verdict; one that settles is a
        snap survived."""
        history = list(self.accepted[-PREDICTOR_POINTS:])
        lam, largest, step = history[-1].lam, 0.0, (target - history[-1].lam) / SUBSTEPS
        while lam < target:
            ahead = target if target - lam <= 1.001 * step else lam + step
            found = self._continue(history, ahead)
            if found is not None:
                history = (history + [self._advance(history, ahead, found)])[-PREDICTOR_POINTS:]
                lam, largest = ahead, max(largest, found.moved)
                continue
            history, fold = self._locate_fold(history, ahead)
            landed = self._descend(history, fold[1])
            if landed.verdict != Verdict.STABLE:
                self.failures[target], self.falls[target] = landed, (history, fold[1])
                self.readings.pop(target, None)  # read again from this failure if asked
                return landed.verdict
            if landed.moved > self.snap_floor:
                self._trial_snaps.append({"fold_mm": [1e3 * fold[0], 1e3 * fold[1]], "move_mm": 1e3 * landed.moved})
            history = [self._advance(history, fold[1], landed)]
            lam, largest = fold[1], max(largest, landed.moved)
        self._trial = history[-1]
        self._trial.move = largest
        return Verdict.STABLE

    def _locate_fold(self, history: list[StaticState], ahead: float) -> tuple[list[StaticState], tuple[float, float]]:
        """Bisect between the last state of `history` and `ahead` (where continuation failed) by
        continuation until the bracket is narrower than the path's (`PathSettings.bracket`): the history extended to
        the bracket's lower end, and the bracket (m)."""
        low, high = history[-1].lam, ahead
        while high - low > self.settings.bracket(high):
            middle = 0.5 * (low + high)
            found = self._continue(history, middle)
            if found is None:
                high = middle
            else:
                history = (history + [self._advance(history, middle, found)])[-PREDICTOR_POINTS:]
                low = middle
        return history, (low, high)

    def _descend(self, history: list[StaticState], lam: float, bound: float | None = None) -> Equilibrium:
        """The descent at support position `lam` from the state predicted there, going on while it falls
        (`solve.falls.fall`) to the runaway `bound` (the path's by default), then again from the last state
        with only the support moved: a solver's failure is retried before it is reported (Verdict.TIMEOUT),
        never read as collapse."""
        last = history[-1]
        shear = last.forces.shear_force
        start = self.predict(lam, history)
        multiplier = self.parameter.multiplier(lam)
        springs = last.springs
        bound = self.runaway if bound is None else bound
        found = self._fall(start, last.u, shear, bound, multiplier=multiplier, springs=springs)
        self.descents += 1
        if found.verdict == Verdict.TIMEOUT:
            self.retries += 1
            found = self.solver.descend(
                self.place(last.u, lam), last.u, shear, bound, multiplier=multiplier, springs=springs
            )
        return found

    def _fall(self, *arguments: Any, **keywords: Any) -> Equilibrium:
        """`solve.falls.fall` on this path's solver (the descent going on while it falls: start, state
        before, shear, runaway bound, gravity, multiplier, springs), its goes counted."""
        found, goes = fall(self.solver, *arguments, **keywords)
        self.retries += goes - 1
        return found

    def _advance(self, history: list[StaticState], lam: float, found: Equilibrium) -> StaticState:
        """The equilibrium `found` at `lam` as the state after `history`'s last (its sliding added)."""
        last = history[-1]
        return self._state(
            Stage.EQUILIBRIUM, lam, found, last.slip + found.joints.forces.plastic_slip, found.joints.forces
        )

    @property
    def iterations(self) -> int:
        """Newton and descent iterations so far."""
        return self.solver.iterations

    def accept(self) -> None:
        assert self._trial is not None and self._trial.stiffness is not None
        self.accepted.append(self._trial)
        self._trial = None
        self.snaps += self._trial_snaps
        self._trial_snaps = []

    @property
    def first_loss(self) -> tuple[float, float] | None:
        """The first snap's fold bracket on the accepted path (m), None without one."""
        return first_snap(self.snaps)

    at_rest_when_accepted = True  # a static equilibrium: nothing creeps, a failure from it stands

    def settle(self) -> bool:
        """A static equilibrium is at rest already: nothing creeps."""
        return True

    def resolve(self, target: float) -> Verdict:
        """A static failure has gone on while it fell already (`solve.falls`): it stays as it is."""
        return Verdict.TIMEOUT

    def discard(self) -> None:
        self.accepted.pop()  # with the snaps made on its way: they are no longer on the path
        self.snaps = [s for s in self.snaps if units.mm(s["fold_mm"][1]) <= self.accepted[-1].lam]

    def fold_mode(self, upper: float) -> FoldMode:
        """The collapse mode from the last accepted state towards the collapse at du's upper end
        `upper` (`collapse_fall`): the collapse's hinges and kind (`solve.collapse_mode`)."""
        state = self.accepted[-1]
        assert state.stiffness is not None  # every state is made from the solver's equilibrium
        return fold_mode(self.arch, state.u, state.stiffness, self.collapse_fall(upper).u, state.springs)

    def collapse_fall(self, upper: float) -> Equilibrium:
        """Where the failure at du's upper end `upper` has fallen a block the default runaway bound
        (RUNAWAY_THICKNESS_RATIO ring thickness), whatever bound the path counts runaway by: the
        mechanism is the arch's, not the bound's (docs/numerics.md). Its own fall where that bound is
        the default, or where the fall to the default bound lands (a long snap the path's shorter bound
        counted as runaway)."""
        lam = self._failure_at(upper)
        reading = RUNAWAY_THICKNESS_RATIO * self.arch.length
        if math.isclose(self.runaway, reading, rel_tol=1e-12) or lam not in self.falls:
            return self.failures[lam]
        if lam not in self.readings:
            probe = self._descend(*self.falls[lam], bound=reading)
            self.readings[lam] = probe if probe.verdict == Verdict.RUNAWAY else self.failures[lam]
        return self.readings[lam]

    def predict(self, target: float, history: list[StaticState]) -> np.ndarray:
        """Where the arch should be at `target`: a parabola (or a line) through `history`'s last states, or
        from one state its tangent's response (a singular one: only the supports moved, for the descent)."""
        last, recent = history[-1], history[-PREDICTOR_POINTS:]
        lams = [s.lam for s in recent]
        if len(set(lams)) == len(lams) >= 2:
            return self.place(extrapolate(lams, [s.u for s in recent], target), target)
        try:
            return tangent_prediction(self, last.u, last.lam, last.forces.shear_force, last.springs, target)
        except (np.linalg.LinAlgError, ValueError):
            return self.place(last.u, target)

    def place(self, u: np.ndarray, lam: float) -> np.ndarray:
        """`u` with the supports where the path's parameter `lam` puts them."""
        return self.arch.with_supports(u, self.parameter.support(lam))

    # ---- the whole path ---------------------------------------------------------------------------
    def follow(self, on_step: Callable[[PathStep], None] | None = None) -> PathResult:
        """From the self-weight state, increments to collapse (`solve.path.follow_path`)."""
        return follow_path(self, self.settings, on_step=on_step)

    def collapse_state(self, upper: float) -> StaticState:
        """The mechanism at collapse: the state of the failure at du's upper bracket end, fallen a
        block the default runaway bound (`collapse_fall`)."""
        lam = self._failure_at(upper)
        end = self.collapse_fall(upper)
        base = self.accepted[-1]
        return self._state(Stage.COLLAPSE, lam, end, base.slip + end.joints.forces.plastic_slip, end.joints.forces)

    def _failure_at(self, upper: float) -> float:
        """The support position of the failure nearest du's upper bracket end `upper` (m)."""
        return min(self.failures, key=lambda d: abs(d - upper))

    def _state(self, stage: str, lam: float, found: Equilibrium, slip: np.ndarray, forces: JointForces) -> StaticState:
        return StaticState(
            stage,
            lam,
            found.u,
            forces,
            slip,
            found.iterations,
            found.residual,
            stiffness=found.stiffness,
            springs=found.springs,
        )
