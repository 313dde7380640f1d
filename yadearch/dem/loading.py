"""The loading along the equilibrium path (YADE layer): the oracle `solve.path.follow_path` asks for
increments, relaxations, acceptance and settling, played on the runner's live scene."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol

from yadearch.case.config import ArchCase, NumericsConfig
from yadearch.case.mechanics import runaway_length
from yadearch.case.support import path_end_mm
from yadearch.errors import CANNOT_STAND, RunFailedError
from yadearch.model import units
from yadearch.model.hinges import Hinge
from yadearch.model.movement import Movement
from yadearch.solve.path import PathResult, PathSettings, PathStep, first_snap, follow_path, path_settings
from yadearch.solve.stages import Stage, Verdict

SETTLE_TOLERANCE_FACTOR = 0.01  # a settled state's unbalanced force, relative to equilibrium_tolerance
HOLD_RETRIES = 1  # a hold that finds neither equilibrium nor runaway goes on this many times more
STABILITY_HOLDS = 2  # an equilibrium whose static tangent is indefinite is held this many times more
JOINT_CONTACTS = "joint"  # numerics.contact_model of the joint elements (quiet at rest, unlike CGAL's)
SNAP_THICKNESS_FRACTION = 0.01  # a relaxation moving a block this x the ring's thickness ...
# ... and further than its increment moves a block quasi-statically (`LiveArch.reach`) is a snap


class PathRecorder(Protocol):
    """What the path records through (dem.recorder.Recorder)."""

    def record_equilibrium(self) -> tuple[tuple[int, int, int], list[Hinge]]: ...

    def discard_since(self, mark: tuple[int, int, int]) -> None: ...

    def record_collapse(self) -> list[Hinge]: ...


class LiveArch(Protocol):
    """What the path needs of a live DEM scene (dem.runner.Runner): move the support, hold it,
    go back to a kept state, record; `stage` labels the records."""

    stage: Stage

    @property
    def case(self) -> ArchCase: ...

    @property
    def movement(self) -> Movement: ...

    @property
    def recorder(self) -> PathRecorder: ...

    @property
    def hold_move(self) -> float: ...  # the largest block displacement of the last hold (m)

    def smallest_stiffness(self) -> float: ...  # the static tangent's smallest eigenvalue at the poses (N/m)

    def reach(self, increment: float) -> float: ...  # how far a path increment moves a block quasi-statically (m)

    @property
    def total_steps(self) -> int: ...

    @property
    def log(self) -> Callable[[str], None]: ...

    def delta(self) -> float: ...

    def snapshot(self) -> dict[str, Any]: ...

    def restore(self, snapshot: dict[str, Any]) -> None: ...

    def move_support(self, target: float, speed_fraction: float) -> None: ...

    def hold(
        self,
        runaway: float | None = None,
        max_s: float | None = None,
        from_rest: bool = True,
        still_speed: float | None = None,
        tolerance: float | None = None,
    ) -> Verdict: ...


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
        }
        self.snaps: list[dict] = []  # relaxations that carried the arch to another branch
        self._start = 0.0  # where the last increment started (m)
        # the path's parameter: the support's displacement, or with `settings` a live load's multiplier
        # (in `unit`), the supports held
        self.moves_support = settings is None
        self.settings = settings or path_settings(self.num, path_end_mm(arch.case, arch.movement))
        self.unit = unit

    def try_increment(self, target: float) -> Verdict:
        """From the last accepted equilibrium state, move the support to `target` and relax there
        with the support held: 'stable', 'runaway' or 'timeout' (see `hold`). A failed state is kept
        for `collapse_state`."""
        if not self._at_accepted:
            self.arch.restore(self._accepted[-1])
        self.arch.stage = Stage.INCREMENT
        self._start = self.arch.delta()
        # every move lasts as long as the largest increment's: the short moves near collapse are
        # gentle, and the arch ends them close to its equilibrium configuration
        fraction = abs(target - self._start) / self.settings.max_increment
        self.arch.move_support(target, min(1.0, fraction))
        self.arch.stage = Stage.RELAX
        verdict = self.arch.hold()
        for _ in range(HOLD_RETRIES):
            if verdict != Verdict.TIMEOUT:
                break
            verdict = self.arch.hold(from_rest=False)  # the hold goes on before it is called unresolved
        verdict = stable_tangent(self.arch, verdict)
        self._at_accepted = False
        if verdict != Verdict.STABLE:
            self._failures[target] = self.arch.snapshot()
        return verdict

    def accept(self) -> None:
        """The state the last increment relaxed to is the new equilibrium state: keep and record it,
        with how far its relaxation moved the blocks (a quasi-static step barely moves them)."""
        increment = self.arch.delta() - self._start
        self.relaxations["delta_mm"].append(units.to_mm(self.arch.delta()))
        self.relaxations["increment_mm"].append(units.to_mm(increment))
        self.relaxations["move_mm"].append(units.to_mm(self.arch.hold_move))
        floor = SNAP_THICKNESS_FRACTION * units.mm(self.arch.case.geometry.thickness_mm)
        if self.arch.hold_move > max(floor, self.arch.reach(increment)):
            self.snaps.append(
                {
                    "fold_mm": [units.to_mm(self._start), units.to_mm(self.arch.delta())],
                    "move_mm": units.to_mm(self.arch.hold_move),
                }
            )
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
        verdict = self.arch.hold(
            from_rest=False,
            still_speed=units.mm(self.num.settle_speed_mm_per_s),
            tolerance=SETTLE_TOLERANCE_FACTOR * self.num.equilibrium_tolerance,
        )
        self.arch.log(f"[{self.arch.case.name}] settling the state at {self._said(self.arch.delta())}: {verdict}")
        if verdict == Verdict.RUNAWAY:
            self._failures[self.arch.delta()] = self.arch.snapshot()
            self._at_accepted = False
            return False
        self._accepted[-1] = self.arch.snapshot()
        self._at_accepted = True
        return True

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


def stable_tangent(arch: LiveArch, verdict: Verdict) -> Verdict:
    """A hold's verdict kept only where the static model agrees: an equilibrium whose tangent at the
    blocks' poses is indefinite is held on (STABILITY_HOLDS times), then unresolved (Verdict.TIMEOUT)."""
    holds = 0
    while verdict == Verdict.STABLE and arch.smallest_stiffness() <= 0.0:
        if holds == STABILITY_HOLDS:
            return Verdict.TIMEOUT
        verdict = arch.hold(from_rest=False)
        holds += 1
    return verdict


def settle_selfweight(arch: LiveArch) -> None:
    """Settle the self-weight state by the path's own test (`settle_speed_mm_per_s`, a hundredth of
    the equilibrium tolerance) and until the static model calls it stable: a state still creeping or
    indefinite is not the path's start (RunFailedError: it cannot stand, or it is unresolved). A settle
    that times out goes on (STABILITY_HOLDS times); with joint elements a state still creeping then is
    unresolved, with CGAL contacts (which never get that quiet) it is kept."""
    num = arch.case.numerics

    def settle() -> Verdict:
        return arch.hold(
            from_rest=False,
            still_speed=units.mm(num.settle_speed_mm_per_s),
            tolerance=SETTLE_TOLERANCE_FACTOR * num.equilibrium_tolerance,
        )

    verdict, holds = settle(), 1
    while verdict == Verdict.TIMEOUT and holds <= STABILITY_HOLDS:
        verdict, holds = settle(), holds + 1
    arch.log(f"[{arch.case.name}] settling the self-weight state: {verdict} after {holds} hold(s)")
    if verdict == Verdict.RUNAWAY:
        raise RunFailedError(f"{CANNOT_STAND}: the self-weight state ran away while settling")
    if verdict == Verdict.TIMEOUT and num.contact_model == JOINT_CONTACTS:
        raise RunFailedError(
            f"unresolved: the self-weight state still creeps after {holds} holds of {num.hold_max_s} s "
            f"(numerics.hold_max_s; a block moved {units.to_mm(arch.hold_move):.3f} mm in the last, blocks "
            f"faster than {num.settle_speed_mm_per_s:g} mm/s): an arch at the edge of standing"
        )
    if verdict == Verdict.STABLE and stable_tangent(arch, verdict) != Verdict.STABLE:
        raise RunFailedError(
            f"unresolved: the self-weight state did not settle to a stable equilibrium within "
            f"{STABILITY_HOLDS + 1} holds of {num.hold_max_s} s (numerics.hold_max_s)"
        )


def criterion_text(n: NumericsConfig) -> str:
    """The loading protocol and collapse criterion with this case's numbers, for summary.json."""
    return (
        "Loading by support increments (first {0} mm, growing x{1} up to {2} mm after each "
        "equilibrium), each from the last equilibrium state: a move (the largest at the support speed, "
        "shorter ones slower in proportion, so that every move lasts as long), then "
        "a relaxation with the support held and the blocks started from rest. Equilibrium: after "
        f"{n.hold_min_s} s, unbalanced force < {n.equilibrium_tolerance} and all blocks slower "
        f"than {n.still_speed_mm_per_s} mm/s, and the static tangent at the blocks' poses positive "
        f"definite (else the hold goes on). No equilibrium: a block moves > {n.runaway_thickness_ratio} ring "
        f"thickness. A hold that finds neither in {n.hold_max_s} s goes on once; then the increment is "
        "unresolved (no du, never a collapse). Relaxations run at local damping "
        f"{n.hold_damping}. After a failed increment the increment halves (bisection); du = "
        "midpoint of the bracket [last support displacement in equilibrium; first without, "
        f"reached from that state], narrowed to < {n.du_tolerance_mm} mm."
    ).format(n.first_increment_mm, n.increment_growth, n.max_increment_mm)
