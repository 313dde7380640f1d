"""Run a case in YADE: self-weight, then the support movement along the equilibrium path to collapse
(`dem.loading`, `solve.path`). The runner is the live arch the path drives: it moves the support,
holds it (`hold`), goes back to kept states and records (docs/theory.md)."""

from __future__ import annotations

import functools
import time
from collections.abc import Callable

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import runaway_length
from yadearch.case.numerics_section import STATIC_PATH_STATES
from yadearch.case.support import case_movement, support_acceleration_mm_per_s2
from yadearch.dem.dead_load import install_dead_loads
from yadearch.dem.driver import SupportDriver
from yadearch.dem.recorder import Recorder, Records
from yadearch.dem.scene import CALLBACK_NAME, build_scene, install_before_integrator, stop_voussoirs
from yadearch.dem.scene_state import capture, put_back
from yadearch.dem.selfweight import apply_selfweight
from yadearch.dem.static_check import StaticCheck, centroid_rows
from yadearch.dem.stepping import CHECK_EVERY_STEPS, SteppingGate
from yadearch.dem.timing import EngineClock
from yadearch.errors import RunFailedError
from yadearch.model import units
from yadearch.results.summary import RunSummary
from yadearch.solve.newton import Equilibrium
from yadearch.solve.stages import Stage, Verdict


class Runner:
    """Drives one scene through the stages and records it."""

    def __init__(self, case: ArchCase, log: Callable[[str], None] = print):
        self.case = case
        self.num = case.numerics
        self.log = log
        self.scene = build_scene(case)
        self.movement = case_movement(case, self.scene.geometry)
        self.full_speed = units.mm(case.support_speed_mm_per_s)
        self.driver = SupportDriver(
            self.scene, self.movement, self.full_speed, units.mm(support_acceleration_mm_per_s2(case, self.movement))
        )
        self._install_driver()
        self.dead_loads = install_dead_loads(self.scene, case)  # the backfill (None without)
        self.recorder = Recorder(self.scene, self.driver, self.num)
        self.recorder.stiffness = self.smallest_stiffness
        self.gate = SteppingGate()
        self.gate.install()
        self.driver.zero_here()
        self.clock = EngineClock(driver_callbacks=(f"{CALLBACK_NAME}_driver",))
        self.wall0 = time.time()
        self.steps_by_stage: dict[str, int] = {}
        self.total_steps = 0  # every step computed, including those a restore later went back on
        self._last_progress = time.time()
        self.weight = 0.0
        self.hold_move = 0.0  # the largest block displacement of the last hold (m)
        self.live_multiplier = 0.0  # the live load the scene holds while its support moves (N or g; 0: none)
        # where the loading stands, as the progress lines say it (a live load's path says its multiplier)
        self.position: Callable[[], str] = lambda: f"delta={units.to_mm(self.delta()):7.2f} mm"

    @property
    def stage(self) -> Stage:
        """The stage the scene is in; it labels every record."""
        return self.recorder.stage

    @stage.setter
    def stage(self, value: Stage) -> None:
        self.recorder.stage = value

    @property
    def records(self) -> Records:
        return self.recorder.records

    # ---- scene plumbing -------------------------------------------------------------------
    def _install_driver(self) -> None:
        install_before_integrator(CALLBACK_NAME + "_driver", self.driver, self.driver.engine())
        self.driver.bind()

    def snapshot(self) -> dict:
        """Snapshot, in memory, of everything that evolves (`dem.scene_state`)."""
        return capture(self.scene.contacts, self.driver)

    def restore(self, snapshot: dict) -> None:
        """Put the live scene back in a `snapshot`."""
        put_back(snapshot, self.scene.contacts, self.driver)

    # ---- measurements ---------------------------------------------------------------------
    def delta(self) -> float:
        return self.driver.displacement()

    def unbalanced(self) -> float:
        """Unbalanced force: mean resultant force on the blocks / mean contact force."""
        return self.scene.contacts.unbalanced()

    def progress(self, extra: str = "", force: bool = False) -> None:
        """A progress line (stage, position, steps/s, wall time), at most every `progress_every_s`."""
        now = time.time()
        if not force and now - self._last_progress < self.num.progress_every_s:
            return
        self._last_progress = now
        wall = now - self.wall0
        rate = self.total_steps / wall if wall > 0 else 0.0
        self.log(
            f"[{self.case.name}] {self.stage:10s} {self.position()} step={self.total_steps} "
            f"{rate:6.0f} steps/s wall={wall:6.0f} s {extra}"
        )

    def _advance(self, n: int) -> None:
        """Run n steps (the only place that steps the scene, so that steps are counted)."""
        if self.total_steps + n > self.num.max_steps:
            raise RunFailedError(
                f"the run reached numerics.max_steps = {self.num.max_steps} steps "
                f"at delta = {units.to_mm(self.delta()):.2f} mm ({self.stage})"
            )
        self.gate.advance(n)
        self.total_steps += n
        self.steps_by_stage[self.stage] = self.steps_by_stage.get(self.stage, 0) + n

    def close(self) -> None:
        """Stop YADE's simulation thread (it finishes the step it is in)."""
        self.gate.close()

    def run_steps(self, n: int) -> None:
        self._advance(n)
        self.recorder.series()

    def positions(self) -> np.ndarray:
        """The voussoirs' centroids now (n, 3; m); a NaN ends the run (the law calls exit(1) on NaN)."""
        from yade import O

        pos = np.array([(p[0], p[1], p[2]) for p in (state.pos for state in self.scene.voussoir_states)])
        if not np.all(np.isfinite(pos)):
            raise RunFailedError(f"NaN in block positions at step {O.iter} ({self.stage})")
        return pos

    # ---- stages ---------------------------------------------------------------------------
    def selfweight(self) -> dict:
        """The self-weight stage (`dem.selfweight`): its record, du's origin zeroed at its equilibrium."""
        return apply_selfweight(self)

    def smallest_stiffness(self, live: np.ndarray | None = None) -> float:
        """The smallest eigenvalue of the free blocks' tangent stiffness at the scene's poses (N/m), with
        the rotational stiffness of the loads on the blocks (the dead loads', the live load's: `live`, or
        the one the run holds, `recorder.turning`) and the fill's passive springs'."""
        held, dead = self.recorder.turning, self.dead_loads
        parts = [t for t in (live, held() if held else None, dead.turning() if dead else None) if t is not None]
        turning = np.sum(parts, axis=0) if parts else None
        return self.scene.contacts.smallest_stiffness(turning, dead.passive_stiffness if dead else None)

    def yield_fill(self) -> None:
        """The blocks rest in an equilibrium of the path: the fill yields for good (`dem.dead_load`)."""
        if self.dead_loads is not None:
            self.dead_loads.yield_fill()

    def reach(self, increment: float) -> float:
        """A support increment moves the blocks it carries at most by as much (m)."""
        return abs(increment)

    def path_positions(self) -> np.ndarray:
        """The centroids the path compares (`numerics.support_path_states`): the scene's, or those of the
        static model's stable equilibrium the scene sits in (the scene's where it has none)."""
        found = self._path_equilibrium()
        return self.positions() if found is None else centroid_rows(found.u, self.positions())

    def branch_start(self) -> tuple[np.ndarray, np.ndarray | None]:
        """A branch's first state, `path_positions`, and with 'static' states how the blocks move per metre
        of the support's path (`dem.static_check`); the scene's states do not predict (docs/numerics.md)."""
        found = self._path_equilibrium()
        if found is None:
            return self.positions(), None
        assert self.static_check is not None  # an equilibrium is the check's
        slope = self.static_check.support_slope(found, self.delta(), self.live_multiplier)
        return centroid_rows(found.u, self.positions()), slope

    def _path_equilibrium(self) -> Equilibrium | None:
        """The static model's stable equilibrium the scene sits in, where the path reads its states there."""
        if self.num.path_states != STATIC_PATH_STATES or self.static_check is None:
            return None
        return self.static_check.equilibrium(self.delta(), self.live_multiplier)

    @functools.cached_property
    def static_check(self) -> StaticCheck | None:
        """The scene's static model (`dem.static_check`), built on its first use: most holds never ask."""
        return StaticCheck.of(self.case, self.scene)

    def static_distance(self) -> float | None:
        """How far the static model moves the blocks to a stable equilibrium (m; inf: none there), None
        where it is not the scene's model (`dem.static_check`)."""
        return self.static_check.distance(self.delta(), self.live_multiplier) if self.static_check else None

    def hold(
        self,
        runaway: float | None = None,
        max_s: float | None = None,
        from_rest: bool = True,
        still_speed: float | None = None,
        tolerance: float | None = None,
    ) -> Verdict:
        """Keep the support still, blocks started from rest (or, `from_rest` false, in their motion).

        'stable': after `hold_min_s`, unbalanced force below `tolerance` (default
        `equilibrium_tolerance`) and every block slower than `still_speed` (m/s, default
        `still_speed_mm_per_s`; a mechanism past its limit point would be accelerating by then);
        'runaway': a block moved `runaway` (default `mechanics.runaway_length`); 'timeout': neither
        within `max_s` (default `hold_max_s`)."""
        from yade import O

        self.driver.target = self.delta()
        self._set_damping(self.num.hold_damping)
        if from_rest:
            stop_voussoirs(self.scene)
        runaway = runaway if runaway is not None else runaway_length(self.case)
        max_steps = int((max_s if max_s is not None else self.num.hold_max_s) / O.dt)
        min_steps = int(self.num.hold_min_s / O.dt)
        still_speed = still_speed if still_speed is not None else units.mm(self.num.still_speed_mm_per_s)
        tolerance = tolerance if tolerance is not None else self.num.equilibrium_tolerance
        start_pos = self.positions()
        start = O.iter
        self.hold_move = 0.0
        while O.iter - start < max_steps:
            self.run_steps(CHECK_EVERY_STEPS)
            moved = np.linalg.norm(self.positions() - start_pos, axis=1).max()
            self.hold_move = max(self.hold_move, moved)
            self.progress(f"holding: max block move {units.to_mm(moved):.3f} mm")
            if moved > runaway:
                return Verdict.RUNAWAY
            if (
                O.iter - start >= min_steps
                and self.unbalanced() < tolerance
                and self.recorder.voussoir_speeds().max() < still_speed
            ):
                return Verdict.STABLE
        return Verdict.TIMEOUT

    def _set_damping(self, damping: float) -> None:
        """The integrator's local damping: each stage sets its own (the loading's, the holds')."""
        self.scene.newton.damping = damping

    def move_support(self, target: float, speed_fraction: float) -> None:
        """Move the support to `target` at `speed_fraction` of the case's support speed."""
        self.driver.set_speed(self.full_speed * speed_fraction)
        self.move_to(target)

    def move_to(self, delta: float) -> None:
        """Move the support to `delta` along the trapezoidal profile."""
        self.driver.target = delta
        self.drive(lambda: self.driver.reached() and self.driver.current_speed == 0.0)

    def drive(self, done: Callable[[], bool]) -> None:
        """Step at the loading's damping until `done()`: a move of the support, or of a live load."""
        self._set_damping(self.num.damping)
        while not done():
            self.run_steps(CHECK_EVERY_STEPS // 5)
            self.positions()  # raises on a NaN

    def run(self) -> RunSummary:
        """All stages (`dem.stages.run_stages`), then YADE's simulation thread stopped; returns what the
        run found and cost (the case's own fields are the caller's to add; records are in `self.records`)."""
        from yadearch.dem.stages import run_stages

        try:
            return run_stages(self)
        finally:
            self.close()
