"""The loading along the equilibrium path (YADE layer): the oracle `solve.path.follow_path` asks for
increments, relaxations, acceptance and settling, played on the runner's live scene."""

from __future__ import annotations

from typing import TYPE_CHECKING

from yadearch.case.config import NumericsConfig
from yadearch.case.movement import path_end_mm
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.solve.path import RUNAWAY, STABLE, PathResult, PathStep, follow_path, path_settings

if TYPE_CHECKING:
    from yadearch.engine.runner import Runner

SETTLE_TOLERANCE_FACTOR = 0.01  # a settled state's unbalanced force, relative to equilibrium_tolerance
DISCARDED_STAGE = "discarded"  # records of an accepted state that ran away while settling


class EquilibriumPath:
    """The equilibrium states of the loading (snapshots) and the states failures ended in, kept for
    the bracket of du and for the collapse mechanism."""

    def __init__(self, runner: Runner):
        self.runner = runner
        self._accepted: list[dict] = []  # snapshots of the equilibrium states of the loading path
        self._at_accepted = True  # the live scene is that state
        self._records: list[tuple[int, int]] = []  # first series and joints row of each
        self._failures: dict[float, dict] = {}  # support displacement -> state a failure ended in
        self.last_equilibrium_hinges: list[dict] = []
        # how far the relaxation of each accepted increment moved the blocks (mm), for summary.json
        self.relaxations: dict = {"runaway_mm": runner.num.runaway_mm, "delta_mm": [], "increment_mm": [],
                                  "move_mm": []}
        self._start = 0.0  # where the last increment started (m)
        self.settings = path_settings(runner.num, path_end_mm(runner.case, runner.movement))

    def try_increment(self, target: float) -> str:
        """From the last accepted equilibrium state, move the support to `target` and relax there
        with the support held: 'stable', 'runaway' or 'timeout' (see `hold`). A failed state is kept
        for `collapse_state`."""
        if not self._at_accepted:
            self.runner.restore(self._accepted[-1])
        self.runner.stage = "increment"
        self._start = self.runner.delta()
        # every move lasts as long as the largest increment's: the short moves near collapse are
        # gentle, and the arch ends them close to its equilibrium configuration
        fraction = abs(target - self._start) / self.settings.max_increment
        self.runner.driver.set_speed(self.runner.full_speed * min(1.0, fraction))
        self.runner.move_to(target)
        self.runner.stage = "relax"
        verdict = self.runner.hold()
        self._at_accepted = False
        if verdict != STABLE:
            self._failures[target] = self.runner.snapshot()
        return verdict

    def accept(self) -> None:
        """The state the last increment relaxed to is the new equilibrium state: keep and record it,
        with how far its relaxation moved the blocks (a quasi-static step barely moves them)."""
        self.relaxations["delta_mm"].append(units.to_mm(self.runner.delta()))
        self.relaxations["increment_mm"].append(units.to_mm(self.runner.delta() - self._start))
        self.relaxations["move_mm"].append(units.to_mm(self.runner.hold_move))
        self._accepted.append(self.runner.snapshot())
        self._at_accepted = True
        self.runner.stage = "equilibrium"
        first_series, first_joint = len(self.runner.recorder.records.series), len(self.runner.recorder.records.joints)
        self.runner.recorder.series(force=True, stability=True)
        snap, hinges = self.runner.recorder.joint_snapshot()
        self.runner.recorder.write_joints(snap, hinges)
        self._records.append((first_series, first_joint))
        self.last_equilibrium_hinges = [h.to_json() for h in hinges]
        self.runner.recorder.track_friction(snap)

    def settle(self) -> bool:
        """Relax the accepted state, support held and blocks in their motion, until every block is
        slower than `settle_speed_mm_per_s` and the unbalanced force below SETTLE_TOLERANCE_FACTOR x
        `equilibrium_tolerance`, or `hold_max_s` passes (CGAL contacts never get that quiet), and
        keep the state reached. False if it runs away: it was not an equilibrium."""
        if not self._at_accepted:
            self.runner.restore(self._accepted[-1])
        self.runner.stage = "settle"
        verdict = self.runner.hold(from_rest=False, still_speed=units.mm(self.runner.num.settle_speed_mm_per_s),
                            tolerance=SETTLE_TOLERANCE_FACTOR * self.runner.num.equilibrium_tolerance)
        self.runner.log(f"[{self.runner.case.name}] settling the state at "
                        f"{units.to_mm(self.runner.delta()):.3f} mm: {verdict}")
        if verdict == RUNAWAY:
            self._failures[self.runner.delta()] = self.runner.snapshot()
            self._at_accepted = False
            return False
        self._accepted[-1] = self.runner.snapshot()
        self._at_accepted = True
        return True

    def discard(self) -> None:
        """Drop the last accepted state (it did not settle): the one before is the accepted one."""
        self._accepted.pop()
        self._at_accepted = False
        first_series, first_joint = self._records.pop()
        records = self.runner.recorder.records
        for row in records.series[first_series:] + records.joints[first_joint:]:
            if row["stage"] == "equilibrium":
                row["stage"] = DISCARDED_STAGE

    def follow(self, start: float = 0.0) -> PathResult:
        """Load by increments relaxed to equilibrium until du is bracketed (`solve.path`), from the
        scene's equilibrium at support displacement `start` (m)."""
        self._accepted, self._at_accepted = [self.runner.snapshot()], True
        return follow_path(self, self.settings, on_step=self._log_increment, start=start)

    def _log_increment(self, step: PathStep) -> None:
        self.runner.log(f"[{self.runner.case.name}] increment {units.to_mm(step.start):7.3f} -> "
                 f"{units.to_mm(step.target):7.3f} mm: {step.verdict} (step {self.runner.total_steps})")

    def collapse_state(self, upper: float) -> list[Hinge]:
        """Show the mechanism: continue the failure at du's upper bracket end `upper` until the
        arch has run away (10 runaway distances more, at most `hold_max_s` more), then read its
        hinges."""
        self.runner.stage = "collapse"
        self.runner.restore(self._failures[min(self._failures, key=lambda d: abs(d - upper))])
        self.runner.hold(runaway=10.0 * units.mm(self.runner.num.runaway_mm), from_rest=False)
        hinges = self.runner.recorder.joints("collapse")
        self.runner.recorder.series(force=True)
        return hinges


def criterion_text(n: NumericsConfig) -> str:
    """The loading protocol and collapse criterion with this case's numbers, for summary.json."""
    return ("Loading by support increments (first {0} mm, growing x{1} up to {2} mm after each "
            "equilibrium), each from the last equilibrium state: a move (the largest at the support speed, "
            "shorter ones slower in proportion, so that every move lasts as long), then "
            "a relaxation with the support held and the blocks started from rest. Equilibrium: after "
            f"{n.hold_min_s} s, unbalanced force < {n.equilibrium_tolerance} and all blocks slower "
            f"than {n.still_speed_mm_per_s} mm/s. No equilibrium: a block moves > {n.runaway_mm} mm, "
            f"or {n.hold_max_s} s pass without equilibrium. Relaxations run at local damping "
            f"{n.hold_damping}. After a failed increment the increment halves (bisection); du = "
            "midpoint of the bracket [last support displacement in equilibrium; first without, "
            f"reached from that state], narrowed to < {n.du_tolerance_mm} mm."
            ).format(n.first_increment_mm, n.increment_growth, n.max_increment_mm)

