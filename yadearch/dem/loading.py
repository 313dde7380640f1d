"""The loading along the equilibrium path (YADE layer): the oracle `solve.path.follow_path` asks for
increments, relaxations, acceptance and settling, played on the runner's live scene."""

from __future__ import annotations

import math

import numpy as np

from yadearch.case.mechanics import runaway_length
from yadearch.case.numerics_section import RUNAWAY_THICKNESS_RATIO
from yadearch.case.support import path_end_mm
from yadearch.dem.acceptance import StaticAcceptance
from yadearch.dem.live_arch import LiveArch, hold_on, stable_tangent
from yadearch.dem.relaxations import Relaxations
from yadearch.dem.trend import Trend
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.solve.falls import MAX_DESCENT_GOES
from yadearch.solve.path import PathResult, PathSettings, PathStep, first_snap, follow_path, path_settings
from yadearch.solve.stages import Stage, Verdict

HOLD_RETRIES = 1  # a hold that finds neither equilibrium nor runaway goes on this many times more
NEAR_EQUILIBRIUM_HOLDS = 8  # holds an increment's state the static model moves goes on before it is a fold's


class EquilibriumPath:
    """The equilibrium states of the loading (snapshots) and the states failures ended in, kept for
    the bracket of du and for the collapse mechanism."""

    at_rest_when_accepted = False  # a DEM state is accepted still moving slowly: settled before du is bracketed

    def __init__(self, arch: LiveArch, settings: PathSettings | None = None, unit: str = "mm"):
        self.arch = arch
        self.num = arch.case.numerics
        self._accepted: list[dict] = []  # snapshots of the equilibrium states of the loading path
        self._trends: list[Trend] = []  # each accepted state's branch trend (`dem.trend`), ending at it
        self._trial_trend: Trend | None = None  # the trend of the state the last increment reached
        self._at_accepted = True  # the live scene is that state
        self._records: list[tuple[int, int, int]] = []  # where each accepted state's records begin
        self._failures: dict[float, dict] = {}  # support displacement -> state a failure ended in
        self._falls: dict[float, tuple[dict, float, float, int]] = {}  # ... and its relaxation (`collapse_state`)
        self.last_equilibrium_hinges: list[dict] = []
        self.runaway = runaway_length(arch.case)
        # a relaxation moving a block this far (numerics.snap_thickness_ratio x the ring's thickness) and further
        # than its increment moves it quasi-statically (`LiveArch.reach`) is a snap (m)
        self.snap_floor = self.num.snap_thickness_ratio * units.mm(arch.case.geometry.thickness_mm)
        self.relaxations = Relaxations(self.runaway)  # how far each accepted relaxation moved the blocks
        self.snaps: list[dict] = []  # relaxations that carried the arch to another branch
        self._start = 0.0  # where the last increment started (m)
        self._trial_snaps: list[dict] = []  # snaps located on the way of the last increment tried
        # the path's parameter: the support's displacement, or with `settings` a live load's multiplier
        # (in `unit`), the supports held
        self.moves_support = settings is None
        self._relax_move = 0.0  # how far the last relaxation moved a block, over all its holds (m)
        self.settings = settings or path_settings(self.num, path_end_mm(arch.case, arch.movement))
        self.unit = unit
        self.static = StaticAcceptance(arch, self.snap_floor, self.relaxations["off_equilibrium"], self._said)

    def try_increment(self, target: float) -> Verdict:
        """From the last accepted equilibrium state, move the support to `target` and relax there
        with the support held: 'stable', 'runaway' or 'timeout' (see `hold`). A relaxation that snaps
        (`_snapped`), or ends where the static model moves the blocks (`dem.acceptance`: a
        near-equilibrium past a fold), is not taken as it comes: its fold is located by bisection to
        the path's bracket (`PathSettings.bracket`) and the snap made from just past it, held on while
        the static model still moves the blocks as the static engine's descent goes on
        (MAX_DESCENT_GOES), then the path goes on to `target`. A failed state is kept for
        `collapse_state`."""
        if not self._at_accepted:
            self.arch.restore(self._accepted[-1])
        self._at_accepted = False
        start = self._start = self.arch.delta()
        base, trend = self._accepted[-1], self._trends[-1]
        self._trial_snaps = []
        fall = (base, start, target, NEAR_EQUILIBRIUM_HOLDS)  # the last relaxation: its start, from, to, holds
        verdict = self._relax_at(start, target)
        while (self.static.off or (verdict == Verdict.STABLE and self._snapped(trend, start, target))) and (
            target - start > self.settings.bracket(target)
        ):
            low, low_state, high, trend = self._locate_fold(base, trend, start, target)
            self.arch.restore(low_state)
            fall = (low_state, low, high, MAX_DESCENT_GOES)
            verdict = self._relax_at(low, high, MAX_DESCENT_GOES)  # the snap, from the last state before the fold
            if verdict != Verdict.STABLE:
                break
            landing = self._landing(trend, low, high)
            if landing is not None:
                self._record_snap(low, high, landing)
            start, base, trend = high, self.arch.snapshot(), Trend.start(high, *self.arch.branch_start())
            if high >= target:
                break
            fall = (base, start, target, NEAR_EQUILIBRIUM_HOLDS)
            verdict = self._relax_at(start, target)
        if verdict != Verdict.STABLE:
            self._failures[target], self._falls[target] = self.arch.snapshot(), fall
        elif start < target:
            trend = trend.then(target, self.arch.path_positions())
        self._trial_trend = trend
        return verdict

    def _relax_at(
        self, start: float, target: float, near_holds: int = NEAR_EQUILIBRIUM_HOLDS, bound: float | None = None
    ) -> Verdict:
        """From the live state at `start`, move the support to `target` and hold it: the verdict, an
        equilibrium counted only where the static tangent at the poses is positive definite and the
        static model does not move the blocks; a hold that finds neither equilibrium nor runaway goes
        on, and so does one off the static model's equilibrium, up to `near_holds` times (at least
        HOLD_RETRIES) and `StaticAcceptance.accept`; a block `bound` away is a runaway (the path's bound)."""
        bound = self.runaway if bound is None else bound
        self.arch.stage = Stage.INCREMENT
        # every move lasts as long as the largest increment's: the short moves near collapse are
        # gentle, and the arch ends them close to its equilibrium configuration
        fraction = abs(target - start) / self.settings.max_increment
        self.arch.move_support(target, min(1.0, fraction))
        self.arch.stage = Stage.RELAX
        origin = self.arch.path_positions()
        verdict = self.arch.hold(runaway=bound)
        first_move = self.arch.hold_move
        for _ in range(max(HOLD_RETRIES, near_holds)):  # the hold goes on before it is called unresolved
            if verdict != Verdict.TIMEOUT:
                break
            left = bound - self._moved_from(origin)
            verdict = self.arch.hold(runaway=left, from_rest=False) if left > 0.0 else Verdict.RUNAWAY
        verdict = self.static.accept(stable_tangent(self.arch, verdict), near_holds, bound)
        self._relax_move = max(first_move, self._moved_from(origin))
        if verdict == Verdict.STABLE:
            self.arch.yield_fill()  # an equilibrium: the fill yields for good where the faces pushed it past u_p
        return verdict

    def _moved_from(self, origin: np.ndarray) -> float:
        """The largest block displacement from the voussoir centroids `origin` to now (m)."""
        return float(np.linalg.norm(self.arch.path_positions() - origin, axis=1).max())

    def _snapped(self, trend: Trend, start: float, target: float) -> bool:
        """Whether the last relaxation, from `start` to `target` on `trend`'s branch, snapped to another
        branch: it moved a block further than the snap floor (numerics.snap_thickness_ratio) and than
        the increment moves a block quasi-statically, or it left a block further than the floor from
        where the branch's trend puts it (a snap made during the move, as the static engine tells one)."""
        floor = self.snap_floor
        moved = self._relax_move > max(floor, self.arch.reach(target - start))
        return moved or trend.distance(target, self.arch.path_positions()) > floor

    def _landing(self, trend: Trend, low: float, high: float) -> float | None:
        """How far the snap from `low` to `high` took the blocks off `trend`'s branch (m; None: on it), as
        the static engine measures it: from the trend's prediction, else by the relaxation's move."""
        if trend.predicts():
            off = trend.distance(high, self.arch.path_positions())
            return off if off > self.snap_floor else None
        return self._relax_move if self._snapped(trend, low, high) else None

    def _record_snap(self, low: float, high: float, move: float) -> None:
        """A snap between path positions `low` and `high` that moved a block `move` (m), on the way of
        the increment being tried (kept if it is accepted), and its log line."""
        self._trial_snaps.append({"fold_mm": [units.to_mm(low), units.to_mm(high)], "move_mm": units.to_mm(move)})
        self.arch.log(
            f"[{self.arch.case.name}] a snap between {self._said(low)} and {self._said(high)}: a block "
            f"moved {units.to_mm(move):.3f} mm"
        )

    def _locate_fold(self, base: dict, trend: Trend, start: float, target: float) -> tuple[float, dict, float, Trend]:
        """Bisect [start, target] (the live state `base` at `start`, the end of `trend`) by increments
        relaxed without a snap until the bracket is narrower than the path's (`PathSettings.bracket`): its lower end,
        the state there, its upper end (the first position whose relaxation snaps, runs away or times
        out) and the trend extended to the lower end."""
        low, low_state, high = start, base, target
        while high - low > self.settings.bracket(high):
            middle = 0.5 * (low + high)
            self.arch.restore(low_state)
            probe = self._relax_at(low, middle, near_holds=0)  # a state off the static model's is past the fold
            if probe == Verdict.STABLE and not self._snapped(trend, low, middle):
                low, low_state, trend = middle, self.arch.snapshot(), trend.then(middle, self.arch.path_positions())
            else:
                high = middle
        return low, low_state, high, trend

    def accept(self) -> None:
        """The state the last increment relaxed to is the new equilibrium state: keep and record it,
        with how far its relaxation moved the blocks and the snaps located on its way."""
        self.relaxations.record(self.arch.delta(), self.arch.delta() - self._start, self._relax_move)
        self.snaps += self._trial_snaps
        self._trial_snaps = []
        self._accepted.append(self.arch.snapshot())
        assert self._trial_trend is not None  # set by the increment or the hold that reached this state
        self._trends.append(self._trial_trend)
        self._at_accepted = True
        self.arch.stage = Stage.EQUILIBRIUM
        mark, hinges = self.arch.recorder.record_equilibrium()
        self._records.append(mark)
        self.last_equilibrium_hinges = [h.to_json() for h in hinges]

    def back_to_accepted(self) -> None:
        """The live scene at the last accepted state (the path's lower end)."""
        self.arch.restore(self._accepted[-1])
        self._at_accepted = True

    def moved_on(self) -> None:
        """The live scene has left the accepted state by other means (a branch driven past the peak)."""
        self._at_accepted = False

    def settle(self) -> bool:
        """Relax the accepted state, support held and blocks in their motion, until every block is
        slower than `settle_speed_mm_per_s` and the unbalanced force below SETTLE_TOLERANCE_FACTOR x
        `equilibrium_tolerance`, or `hold_max_s` passes (CGAL contacts never get that quiet), and
        keep the state reached. False if it runs away: it was not an equilibrium."""
        if not self._at_accepted:
            self.arch.restore(self._accepted[-1])
        self.arch.stage = Stage.SETTLE
        verdict = hold_on(self.arch)
        self.arch.log(f"[{self.arch.case.name}] settling the state at {self._said(self.arch.delta())}: {verdict}")
        if verdict == Verdict.RUNAWAY:
            self._failures[self.arch.delta()] = self.arch.snapshot()
            self._at_accepted = False
            return False
        self.arch.yield_fill()
        self._accepted[-1] = self.arch.snapshot()
        self._trends[-1] = self._trends[-1].with_last(self.arch.path_positions())
        self._at_accepted = True
        return True

    def resolve(self, target: float) -> Verdict:
        """Hold on with the failure at `target` that found neither equilibrium nor runaway, the blocks in
        their motion, up to MAX_DESCENT_GOES holds (the static engine's descents go on alike,
        `solve.falls`): 'runaway' once a block is the runaway bound from the last accepted state,
        'stable' where it comes to rest (a slow snap survived, recorded as one), else 'timeout'."""
        self.arch.restore(self._accepted[-1])
        origin = self.arch.path_positions()
        self.arch.restore(self._failures[target])
        self.arch.stage = Stage.RELAX
        verdict, holds, off = Verdict.TIMEOUT, 0, None
        while verdict == Verdict.TIMEOUT and holds < MAX_DESCENT_GOES:
            fallen = self._moved_from(origin)
            if fallen >= self.runaway:
                verdict = Verdict.RUNAWAY
                break
            left = self.runaway - fallen
            held = self.static.hold(off, left) if off is not None else self.arch.hold(runaway=left, from_rest=False)
            verdict = stable_tangent(self.arch, held)
            off = self.static.next_distance(verdict, off)
            if off is not None and verdict == Verdict.STABLE:
                verdict = Verdict.TIMEOUT  # not at rest where the static model is: the holds go on
            holds += 1
        self.arch.log(f"[{self.arch.case.name}] held on at {self._said(target)} for {holds} hold(s): {verdict}")
        self._at_accepted = False
        fallen = self._moved_from(origin)
        if verdict != Verdict.STABLE:
            self._failures[target] = self.arch.snapshot()
        elif fallen > self.snap_floor:
            self._record_snap(self._start, target, fallen)
        self._trial_trend = Trend.start(target, *self.arch.branch_start())  # a branch reached by a slow failure
        return verdict

    def discard(self) -> None:
        """Drop the last accepted state (it did not settle): the one before is the accepted one."""
        self._accepted.pop()
        self._trends.pop()
        self._at_accepted = False
        self.arch.recorder.discard_since(self._records.pop())
        discarded = self.relaxations.drop_last()
        self.snaps = [s for s in self.snaps if s["fold_mm"][1] < discarded]  # those on its way are off the path

    @property
    def first_loss(self) -> tuple[float, float] | None:
        """The increment of the first snap on the accepted path (m), None without one."""
        return first_snap(self.snaps)

    def follow(self, start: float = 0.0) -> PathResult:
        """Load by increments relaxed to equilibrium until du is bracketed (`solve.path`), from the
        scene's equilibrium at support displacement `start` (m)."""
        self.arch.yield_fill()  # the state the path starts from (the self-weight's, or a movement's end)
        self._accepted, self._at_accepted = [self.arch.snapshot()], True
        self._trends = [Trend.start(start, *self.arch.branch_start())]
        return follow_path(self, self.settings, on_step=self._log_increment, start=start)

    def _log_increment(self, step: PathStep) -> None:
        self.arch.log(
            f"[{self.arch.case.name}] increment {self._said(step.start)} -> {self._said(step.target)}: "
            f"{step.verdict} (step {self.arch.total_steps})"
        )

    def _said(self, value: float) -> str:
        """A value of the path's parameter with its unit, as the log writes it."""
        return f"{units.to_mm(value):7.3f} mm" if self.moves_support else f"{value:7.4g} {self.unit}"

    def collapse_state(self, upper: float) -> list[Hinge]:
        """Show the mechanism: the failure at du's upper bracket end `upper` where a block has moved the
        default runaway bound whatever the path's, its relaxation made again to that bound where they
        differ (`StaticLoading.collapse_fall` alike); its own state where that relaxation lands."""
        target = min(self._failures, key=lambda d: abs(d - upper))
        reading = RUNAWAY_THICKNESS_RATIO * units.mm(self.arch.case.geometry.thickness_mm)
        shown = False
        if not math.isclose(self.runaway, reading, rel_tol=1e-12) and target in self._falls:
            before, start, end, holds = self._falls[target]
            self.arch.restore(before)
            shown = self._relax_at(start, end, holds, bound=reading) == Verdict.RUNAWAY
        if not shown:
            self.arch.restore(self._failures[target])
        self.arch.stage = Stage.COLLAPSE
        return self.arch.recorder.record_collapse()
