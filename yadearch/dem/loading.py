"""The loading along the equilibrium path (YADE layer): the oracle `solve.path.follow_path` asks for
increments, relaxations, acceptance and settling, played on the runner's live scene."""

from __future__ import annotations

import math

import numpy as np

from yadearch.case.config import NumericsConfig
from yadearch.case.mechanics import runaway_length
from yadearch.case.support import path_end_mm
from yadearch.dem.live_arch import SETTLE_TOLERANCE_FACTOR, LiveArch, stable_tangent
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.solve.falls import MAX_DESCENT_GOES
from yadearch.solve.path import PathResult, PathSettings, PathStep, first_snap, follow_path, path_settings
from yadearch.solve.stages import Stage, Verdict

HOLD_RETRIES = 1  # a hold that finds neither equilibrium nor runaway goes on this many times more
NEAR_EQUILIBRIUM_HOLDS = 8  # holds a state the static model moves (`_off_equilibrium`) goes on, then unresolved
SNAP_THICKNESS_FRACTION = 0.01  # a relaxation moving a block this x the ring's thickness ...
# ... and further than its increment moves a block quasi-statically (`LiveArch.reach`) is a snap


class EquilibriumPath:
    """The equilibrium states of the loading (snapshots) and the states failures ended in, kept for
    the bracket of du and for the collapse mechanism."""

    at_rest_when_accepted = False  # a DEM state is accepted still moving slowly: settled before du is bracketed

    def __init__(self, arch: LiveArch, settings: PathSettings | None = None, unit: str = "mm"):
        self.arch = arch
        self.num = arch.case.numerics
        self._accepted: list[dict] = []  # snapshots of the equilibrium states of the loading path
        self._at_accepted = True  # the live scene is that state
        self._records: list[tuple[int, int, int]] = []  # where each accepted state's records begin
        self._failures: dict[float, dict] = {}  # support displacement -> state a failure ended in
        self.last_equilibrium_hinges: list[dict] = []
        # how far the relaxation of each accepted increment moved the blocks (mm), for summary.json
        self.runaway = runaway_length(arch.case)
        self.relaxations: dict = {
            "runaway_mm": units.to_mm(self.runaway),
            "delta_mm": [],
            "increment_mm": [],
            "move_mm": [],
            # states a hold called equilibria that the static model moved: [delta_mm, move_mm (None: no stable state)]
            "off_equilibrium": [],
        }
        self.snaps: list[dict] = []  # relaxations that carried the arch to another branch
        self._start = 0.0  # where the last increment started (m)
        self._trial_snaps: list[dict] = []  # snaps located on the way of the last increment tried
        # the path's parameter: the support's displacement, or with `settings` a live load's multiplier
        # (in `unit`), the supports held
        self.moves_support = settings is None
        self._relax_move = 0.0  # how far the last relaxation moved a block, over all its holds (m)
        self.settings = settings or path_settings(self.num, path_end_mm(arch.case, arch.movement))
        self.unit = unit

    def try_increment(self, target: float) -> Verdict:
        """From the last accepted equilibrium state, move the support to `target` and relax there
        with the support held: 'stable', 'runaway' or 'timeout' (see `hold`). A relaxation that snaps
        (`_snapped`) is not taken as it comes: its fold is located by bisection to the path's tolerance
        and the snap made from just past it, as the static engine makes it, then the path goes on to
        `target`. A failed state is kept for `collapse_state`."""
        if not self._at_accepted:
            self.arch.restore(self._accepted[-1])
        self._at_accepted = False
        start = self._start = self.arch.delta()
        base = self._accepted[-1]
        self._trial_snaps = []
        verdict = self._relax_at(start, target)
        while verdict == Verdict.STABLE and self._snapped(target - start) and target - start > self.settings.tolerance:
            low, low_state, high = self._locate_fold(base, start, target)
            self.arch.restore(low_state)
            verdict = self._relax_at(low, high)  # the snap, from the last state before the fold
            if verdict != Verdict.STABLE:
                break
            if self._snapped(high - low):
                self._record_snap(low, high, self._relax_move)
            if high >= target:
                break
            start, base = high, self.arch.snapshot()
            verdict = self._relax_at(start, target)
        if verdict != Verdict.STABLE:
            self._failures[target] = self.arch.snapshot()
        return verdict

    def _relax_at(self, start: float, target: float) -> Verdict:
        """From the live state at `start`, move the support to `target` and hold it: the verdict, an
        equilibrium counted only where the static tangent at the poses is positive definite and the
        static model does not move the blocks (`_on_equilibrium`)."""
        self.arch.stage = Stage.INCREMENT
        # every move lasts as long as the largest increment's: the short moves near collapse are
        # gentle, and the arch ends them close to its equilibrium configuration
        fraction = abs(target - start) / self.settings.max_increment
        self.arch.move_support(target, min(1.0, fraction))
        self.arch.stage = Stage.RELAX
        origin = self.arch.positions()
        verdict = self.arch.hold()
        first_move = self.arch.hold_move
        for _ in range(HOLD_RETRIES):
            if verdict != Verdict.TIMEOUT:
                break
            verdict = self.arch.hold(from_rest=False)  # the hold goes on before it is called unresolved
        verdict = self._on_equilibrium(stable_tangent(self.arch, verdict))
        self._relax_move = max(first_move, self._moved_from(origin))
        return verdict

    def _on_equilibrium(self, verdict: Verdict) -> Verdict:
        """A hold's 'stable' kept only where the static model does not move the blocks (`_off_equilibrium`):
        a near-equilibrium past a fold is slow and balanced to the tolerance but is not one. Such a
        state is held on, up to NEAR_EQUILIBRIUM_HOLDS times, then unresolved (Verdict.TIMEOUT)."""
        holds = 0
        while verdict == Verdict.STABLE and self._off_equilibrium():
            if holds == NEAR_EQUILIBRIUM_HOLDS:
                self.arch.log(f"[{self.arch.case.name}] still off after {holds} more holds: unresolved")
                return Verdict.TIMEOUT
            verdict = stable_tangent(self.arch, self._hold_on())
            holds += 1
        return verdict

    def _hold_on(self, runaway: float | None = None) -> Verdict:
        """Hold on, the blocks in their motion, until they are at rest by the settling test (blocks slower
        than `settle_speed_mm_per_s`, the unbalanced force SETTLE_TOLERANCE_FACTOR x the tolerance): a
        state creeping past a fold, slow where the fold was, is given the time to leave or to stop."""
        return self.arch.hold(
            runaway=runaway,
            from_rest=False,
            still_speed=units.mm(self.num.settle_speed_mm_per_s),
            tolerance=SETTLE_TOLERANCE_FACTOR * self.num.equilibrium_tolerance,
        )

    def _off_equilibrium(self) -> bool:
        """Whether the static model, from the blocks' poses and shear forces, moves a block further than
        the snap floor to a stable equilibrium (`dem.static_check`); such a state is recorded and logged."""
        distance = self.arch.static_distance()
        if distance is None or distance <= self._snap_floor():
            return False
        landing = units.to_mm(distance) if math.isfinite(distance) else None  # JSON has no infinity
        self.relaxations["off_equilibrium"].append([units.to_mm(self.arch.delta()), landing])
        self.arch.log(
            f"[{self.arch.case.name}] at {self._said(self.arch.delta())} the static model moves the blocks "
            f"{units.to_mm(distance):.3f} mm to a stable equilibrium: holding on"
        )
        return True

    def _moved_from(self, origin: np.ndarray) -> float:
        """The largest block displacement from the voussoir centroids `origin` to now (m)."""
        return float(np.linalg.norm(self.arch.positions() - origin, axis=1).max())

    def _snapped(self, increment: float) -> bool:
        """Whether the last relaxation moved a block further than 0.01 ring thickness and than the
        increment moves a block quasi-statically: a snap to another branch, not a step along one."""
        return self._relax_move > max(self._snap_floor(), self.arch.reach(increment))

    def _snap_floor(self) -> float:
        """The smallest block move that counts as a snap: SNAP_THICKNESS_FRACTION x the ring's thickness (m)."""
        return SNAP_THICKNESS_FRACTION * units.mm(self.arch.case.geometry.thickness_mm)

    def _record_snap(self, low: float, high: float, move: float) -> None:
        """A snap between path positions `low` and `high` that moved a block `move` (m), on the way of
        the increment being tried (kept if it is accepted), and its log line."""
        self._trial_snaps.append({"fold_mm": [units.to_mm(low), units.to_mm(high)], "move_mm": units.to_mm(move)})
        self.arch.log(
            f"[{self.arch.case.name}] a snap between {self._said(low)} and {self._said(high)}: a block "
            f"moved {units.to_mm(move):.3f} mm"
        )

    def _locate_fold(self, base: dict, start: float, target: float) -> tuple[float, dict, float]:
        """Bisect [start, target] (the live state `base` at `start`) by increments relaxed without a
        snap until the bracket is narrower than the path's tolerance: its lower end, the state there,
        its upper end (the first position whose relaxation snaps, runs away or times out)."""
        low, low_state, high = start, base, target
        while high - low > self.settings.tolerance:
            middle = 0.5 * (low + high)
            self.arch.restore(low_state)
            if self._relax_at(low, middle) == Verdict.STABLE and not self._snapped(middle - low):
                low, low_state = middle, self.arch.snapshot()
            else:
                high = middle
        return low, low_state, high

    def accept(self) -> None:
        """The state the last increment relaxed to is the new equilibrium state: keep and record it,
        with how far its relaxation moved the blocks and the snaps located on its way."""
        increment = self.arch.delta() - self._start
        self.relaxations["delta_mm"].append(units.to_mm(self.arch.delta()))
        self.relaxations["increment_mm"].append(units.to_mm(increment))
        self.relaxations["move_mm"].append(units.to_mm(self._relax_move))
        self.snaps += self._trial_snaps
        self._trial_snaps = []
        self._accepted.append(self.arch.snapshot())
        self._at_accepted = True
        self.arch.stage = Stage.EQUILIBRIUM
        mark, hinges = self.arch.recorder.record_equilibrium()
        self._records.append(mark)
        self.last_equilibrium_hinges = [h.to_json() for h in hinges]

    def settle(self) -> bool:
        """Relax the accepted state, support held and blocks in their motion, until every block is
        slower than `settle_speed_mm_per_s` and the unbalanced force below SETTLE_TOLERANCE_FACTOR x
        `equilibrium_tolerance`, or `hold_max_s` passes (CGAL contacts never get that quiet), and
        keep the state reached. False if it runs away: it was not an equilibrium."""
        if not self._at_accepted:
            self.arch.restore(self._accepted[-1])
        self.arch.stage = Stage.SETTLE
        verdict = self._hold_on()
        self.arch.log(f"[{self.arch.case.name}] settling the state at {self._said(self.arch.delta())}: {verdict}")
        if verdict == Verdict.RUNAWAY:
            self._failures[self.arch.delta()] = self.arch.snapshot()
            self._at_accepted = False
            return False
        self._accepted[-1] = self.arch.snapshot()
        self._at_accepted = True
        return True

    def resolve(self, target: float) -> Verdict:
        """Hold on with the failure at `target` that found neither equilibrium nor runaway, the blocks in
        their motion, up to MAX_DESCENT_GOES holds (the static engine's descents go on alike,
        `solve.falls`): 'runaway' once a block is the runaway bound from the last accepted state,
        'stable' where it comes to rest (a slow snap survived, recorded as one), else 'timeout'."""
        self.arch.restore(self._accepted[-1])
        origin = self.arch.positions()
        self.arch.restore(self._failures[target])
        self.arch.stage = Stage.RELAX
        verdict, holds, off = Verdict.TIMEOUT, 0, False
        while verdict == Verdict.TIMEOUT and holds < MAX_DESCENT_GOES:
            fallen = self._moved_from(origin)
            if fallen >= self.runaway:
                verdict = Verdict.RUNAWAY
                break
            left = self.runaway - fallen
            held = self._hold_on(left) if off else self.arch.hold(runaway=left, from_rest=False)
            verdict = stable_tangent(self.arch, held)
            off = verdict == Verdict.STABLE and self._off_equilibrium()
            if off:
                verdict = Verdict.TIMEOUT  # not at rest where the static model is: the holds go on
            holds += 1
        self.arch.log(f"[{self.arch.case.name}] held on at {self._said(target)} for {holds} hold(s): {verdict}")
        self._at_accepted = False
        fallen = self._moved_from(origin)
        if verdict != Verdict.STABLE:
            self._failures[target] = self.arch.snapshot()
        elif fallen > self._snap_floor():
            self._record_snap(self._start, target, fallen)
        return verdict

    def discard(self) -> None:
        """Drop the last accepted state (it did not settle): the one before is the accepted one."""
        self._accepted.pop()
        self._at_accepted = False
        self.arch.recorder.discard_since(self._records.pop())
        discarded = self.relaxations["delta_mm"][-1]
        for key in ("delta_mm", "increment_mm", "move_mm"):
            self.relaxations[key].pop()
        self.snaps = [s for s in self.snaps if s["fold_mm"][1] < discarded]  # those on its way are off the path

    @property
    def first_loss(self) -> tuple[float, float] | None:
        """The increment of the first snap on the accepted path (m), None without one."""
        return first_snap(self.snaps)

    def follow(self, start: float = 0.0) -> PathResult:
        """Load by increments relaxed to equilibrium until du is bracketed (`solve.path`), from the
        scene's equilibrium at support displacement `start` (m)."""
        self._accepted, self._at_accepted = [self.arch.snapshot()], True
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
        """Show the mechanism: the state of the failure at du's upper bracket end `upper`, where a
        block has run away by the runaway bound (as the static engine shows it), and its hinges."""
        self.arch.stage = Stage.COLLAPSE
        self.arch.restore(self._failures[min(self._failures, key=lambda d: abs(d - upper))])
        return self.arch.recorder.record_collapse()


def criterion_text(n: NumericsConfig) -> str:
    """The loading protocol and collapse criterion with this case's numbers, for summary.json."""
    return (
        "Loading by support increments (first {0} mm, growing x{1} up to {2} mm after each "
        "equilibrium), each from the last equilibrium state: a move (the largest at the support speed, "
        "shorter ones slower in proportion, so that every move lasts as long), then "
        "a relaxation with the support held and the blocks started from rest. Equilibrium: after "
        f"{n.hold_min_s} s, unbalanced force < {n.equilibrium_tolerance} and all blocks slower "
        f"than {n.still_speed_mm_per_s} mm/s, the static tangent at the blocks' poses positive "
        "definite, and Newton's method on the static model (the same blocks and joints, from the "
        "blocks' poses and shear forces) moving no block more than 0.01 ring thickness to a stable "
        f"equilibrium (else the hold goes on, up to {NEAR_EQUILIBRIUM_HOLDS} times, each until the blocks "
        f"are slower than {n.settle_speed_mm_per_s} mm/s). No equilibrium: a "
        f"block moves > {n.runaway_thickness_ratio} ring "
        f"thickness. A hold that finds neither in {n.hold_max_s} s goes on once; then the increment is "
        "unresolved (no du, never a collapse). Relaxations run at local damping "
        f"{n.hold_damping}. After a failed increment the increment halves (bisection); du = "
        "midpoint of the bracket [last support displacement in equilibrium; first without, "
        f"reached from that state], narrowed to < {n.du_tolerance_mm} mm."
    ).format(n.first_increment_mm, n.increment_growth, n.max_increment_mm)
