"""Run a case in YADE: self-weight, then the support movement along the equilibrium path to collapse.

The support advances by increments, each from the last equilibrium state: a move at the support
speed, then a relaxation with the support held (`hold`). An increment that ends in equilibrium is
accepted and the next one grows; one that does not bounds du from above and the increments halve
(`solve.path`). du is the midpoint of the final bracket, both ends reached from the same equilibrium
state, so the loading rate, damping and time step decide only how fast it is found (docs: theory).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from yadearch.model import units
from yadearch.case.config import ArchCase
from yadearch.engine.timing import EngineClock
from yadearch.errors import RunFailedError
from yadearch.model.hinges import Hinge, hinge_rotation, hinges_at
from yadearch.model.joints import joint_states
from yadearch.engine.scene import CALLBACK_NAME, ArchScene, body_states, build_scene
from yadearch.solve.path import RUNAWAY, STABLE, TIMEOUT, PathResult, PathSettings, PathStep, follow_path
from yadearch.engine.stepping import SteppingGate

SELFWEIGHT_COLLAPSE_MM = 50.0  # a block falling this far under self-weight means the arch cannot stand
CHECK_EVERY_STEPS = 50  # steps between the runner's checks (speed, equilibrium, records)
ARRIVED_M = 1e-12  # the support is on target within this distance (m)
DRIVER_LABEL = "yadearch_support_driver"
SETTLE_TOLERANCE_FACTOR = 0.01  # a settled state's unbalanced force, relative to equilibrium_tolerance
DISCARDED_STAGE = "discarded"  # records of an accepted state that ran away while settling
DRIVER_CRUISE_PERIOD = 50  # steps between the support driver's calls while it cruises


class SupportDriver:
    """Moves the driven support towards a target displacement with a trapezoidal speed profile
    (accelerate at `accel` up to `speed`, cruise, brake at `accel` to stop exactly on target; accel
    0 = instantaneous)."""

    def __init__(self, scene: ArchScene, direction: np.ndarray, speed: float, accel: float):
        self.scene = scene
        self.direction = (float(direction[0]), float(direction[1]))
        self.accel = accel if accel > 0 else math.inf
        self.set_speed(speed)
        self._target = 0.0
        self.current_speed = 0.0
        self.origin = (0.0, 0.0)
        self._state = None
        self._engine = None

    def set_speed(self, speed: float) -> None:
        """The cruise speed of the next moves (m/s)."""
        self.speed = speed
        self.ramp = speed * speed / (2.0 * self.accel)  # braking distance from full speed

    def engine(self):
        """The PyRunner that calls `step`, labelled so that `bind` (and the benchmark) find it."""
        from yade.wrapper import PyRunner

        return PyRunner(command=f"{CALLBACK_NAME}_driver.step()", iterPeriod=1, label=DRIVER_LABEL)

    def bind(self) -> None:
        """Attach to the support body and to the driver's engine."""
        from yade import O

        self._state = O.bodies[self.scene.right_support].state
        self._engine = next(e for e in O.engines if getattr(e, "label", "") == DRIVER_LABEL)

    @property
    def target(self) -> float:
        return self._target

    @target.setter
    def target(self, value: float) -> None:
        """A new target wakes the engine up: it is put to sleep while the support stands still."""
        self._target = value
        self._engine.dead = False
        self._engine.iterPeriod = 1

    def zero_here(self) -> None:
        """Measure displacements from the support's current position and stop it there."""
        self.origin = (float(self._state.pos[0]), float(self._state.pos[1]))
        self.target = 0.0

    def displacement(self) -> float:
        """Support displacement along the loading direction since `origin` (m); plain floats, as
        it runs every step."""
        pos, origin, direction = self._state.pos, self.origin, self.direction
        return (pos[0] - origin[0]) * direction[0] + (pos[1] - origin[1]) * direction[1]

    def step(self) -> None:
        """Set the support velocity for this step (called every step before the integrator)."""
        from yade import O

        remaining = self.target - self.displacement()
        dt = O.dt
        if remaining <= ARRIVED_M:  # a float-rounding remainder must not keep the support creeping
            speed = 0.0
        else:
            speed = min(self.speed, self.current_speed + self.accel * dt,
                        math.sqrt(2.0 * self.accel * remaining), remaining / dt)
        self.current_speed = speed
        self._state.vel = (speed * self.direction[0], speed * self.direction[1], 0.0)
        self._schedule(remaining, speed, dt)

    def _schedule(self, remaining: float, speed: float, dt: float) -> None:
        """Call `step` only when the speed can change: never while the support stands on target
        (holds, self-weight), and every `DRIVER_CRUISE_PERIOD` steps at most while it cruises short of
        its braking distance. The support's path is the same as with a call every step."""
        if speed == 0.0 and remaining <= ARRIVED_M:
            self._engine.dead = True
            return
        cruise_steps = 0
        if speed == self.speed:
            cruise_steps = int((remaining - self.ramp) / (speed * dt))
        self._engine.iterPeriod = max(1, min(DRIVER_CRUISE_PERIOD, cruise_steps - 1))

    def reached(self) -> bool:
        return self.target - self.displacement() <= ARRIVED_M


@dataclass
class Records:
    """Everything the run folder gets: time series rows, per-interface rows, events, snapshots."""

    series: list[dict] = field(default_factory=list)
    joints: list[dict] = field(default_factory=list)
    events: list[str] = field(default_factory=list)
    snapshots: dict[str, dict] = field(default_factory=dict)


class Runner:
    """Drives one scene through the stages and records it."""

    def __init__(self, case: ArchCase, log: Callable[[str], None] = print):
        self.case = case
        self.num = case.numerics
        self.log = log
        self.records = Records()
        self.scene = build_scene(case)
        angle = units.radians(case.loading.settlement_direction_deg)
        direction = np.array([math.cos(angle), math.sin(angle), 0.0])
        self._full_speed = units.mm(case.settlement_speed_mm_per_s)
        self.driver = SupportDriver(self.scene, direction, self._full_speed,
                                    units.mm(self.num.support_acceleration_mm_per_s2))
        self._install_driver()
        self.gate = SteppingGate()
        self.gate.install()
        self.driver.zero_here()
        self.clock = EngineClock(driver_callbacks=(f"{CALLBACK_NAME}_driver",))
        self.stage = "selfweight"
        self.wall0 = time.time()
        self.steps_by_stage: dict[str, int] = {}
        self.total_steps = 0  # every step computed, including those a restore later went back on
        self._last_series_iter = -10**9
        self._last_progress = time.time()
        self.weight = 0.0
        self._accepted: list[dict] = []  # snapshots of the equilibrium states of the loading path
        self._at_accepted = True  # the live scene is that state
        self._accepted_records: list[tuple[int, int]] = []  # first series and joints row of each
        self._failures: dict[float, dict] = {}  # support displacement -> state a failure ended in
        self._last_equilibrium_hinges: list[dict] = []
        self._friction: dict = {}
        num, mm = self.num, units.mm
        self._path_settings = PathSettings(
            first_increment=mm(num.first_increment_mm),
            max_increment=mm(max(num.max_increment_mm, num.first_increment_mm)),
            growth=num.increment_growth, tolerance=mm(num.du_tolerance_mm),
            max_displacement=mm(case.loading.max_settlement_mm))

    # ---- scene plumbing -------------------------------------------------------------------
    def _install_driver(self) -> None:
        from yade import O

        import __main__

        setattr(__main__, CALLBACK_NAME + "_driver", self.driver)
        engines = list(O.engines)
        engines.insert(len(engines) - 1, self.driver.engine())
        O.engines = engines
        self.driver.bind()

    def snapshot(self) -> dict:
        """Snapshot, in memory, of everything that evolves: body states, the contact model's state
        (per-contact shear forces, CGAL's intersection hints) and the support driver.

        Not `O.saveTmp`: a scene brought back by `O.loadTmp` steps 28 % slower in YADE 2023.02a's
        polyhedra contact than the live scene (70 vs 97 steps/s, same state), and the search and
        collapse stages run on restored states."""
        from yade import O

        bodies = [(s.pos, s.ori, s.vel, s.angVel) for s in (b.state for b in O.bodies)]
        return {"bodies": bodies, "contacts": self.scene.contacts.snapshot(),
                "target": self.driver.target, "speed": self.driver.current_speed}

    def restore(self, snapshot: dict) -> None:
        """Put the live scene back in a `snapshot`."""
        from yade import O

        for body, (pos, ori, vel, ang_vel) in zip(O.bodies, snapshot["bodies"]):
            state = body.state
            state.pos, state.ori, state.vel, state.angVel = pos, ori, vel, ang_vel
        self.scene.contacts.restore(snapshot["contacts"])
        self.driver.target = snapshot["target"]
        self.driver.current_speed = snapshot["speed"]

    # ---- measurements ---------------------------------------------------------------------
    def delta(self) -> float:
        return self.driver.displacement()

    def _voussoir_speeds(self) -> np.ndarray:
        return np.array([state.vel.norm() for state in self.scene.voussoir_states])

    def _unbalanced(self) -> float:
        """Unbalanced force: mean resultant force on the blocks / mean contact force."""
        return self.scene.contacts.unbalanced()

    def joint_snapshot(self) -> tuple[dict, list[Hinge]]:
        """Per-interface state now, and its hinges."""
        pos, rot = body_states(self.scene)
        if not np.all(np.isfinite(pos)):
            raise RunFailedError(f"NaN in block positions at step {self._iter()}")
        points, normal, shear = self.scene.contacts.joint_contacts()
        tan_friction = self.scene.stiffness.tan_friction
        friction_use = np.divide(np.abs(shear), normal * tan_friction, out=np.zeros_like(shear),
                                 where=normal > 0.0)
        js = joint_states(self.scene.geometry, self.scene.pos0, pos, rot, points)
        rotation = hinge_rotation(js.opening_intrados, js.opening_extrados, self.scene.geometry.thickness)
        hinges = hinges_at(rotation, self.num.hinge_rotation_mrad * 1e-3)
        return {"pos": pos, "rot": rot, "js": js, "normal": normal, "shear": shear,
                "friction_use": friction_use, "slip": self.scene.contacts.joint_slip(),
                "hinge_rotation": rotation}, hinges

    def _iter(self) -> int:
        from yade import O

        return O.iter

    def _reactions(self) -> tuple[np.ndarray, np.ndarray]:
        """Forces the left and right supports exert on the arch (N)."""
        from yade import O

        left = -np.array(O.forces.f(self.scene.left_support))[:2]
        right = -np.array(O.forces.f(self.scene.right_support))[:2]
        return left, right

    def _record_series(self, force: bool = False) -> None:
        from yade import O, utils

        if not force and O.iter - self._last_series_iter < self.num.series_every_steps:
            return
        self._last_series_iter = O.iter
        left, right = self._reactions()
        crown = self.scene.geometry.crown_voussoir
        crown_id = self.scene.body_ids[crown]
        crown_disp = np.array(O.bodies[crown_id].state.pos) - self.scene.pos0[crown]
        self.records.series.append({
            "stage": self.stage, "step": O.iter, "time_s": O.time,
            "delta_mm": units.to_mm(self.delta()),
            "left_Rx_N": left[0], "left_Ry_N": left[1], "right_Rx_N": right[0], "right_Ry_N": right[1],
            "crown_dx_mm": units.to_mm(crown_disp[0]), "crown_dy_mm": units.to_mm(crown_disp[1]),
            "kinetic_J": utils.kineticEnergy(), "unbalanced": self._unbalanced(),
            "max_block_speed_mm_per_s": units.to_mm(float(self._voussoir_speeds().max())),
        })

    def _record_joints(self, label: str | None = None) -> list[Hinge]:
        """Record every interface now (and, with a `label`, the block positions as a snapshot)."""
        snap, hinges = self.joint_snapshot()
        self._write_joints(snap, hinges, label)
        return hinges

    def _write_joints(self, snap: dict, hinges: list[Hinge], label: str | None = None) -> None:
        """Append the rows of joints.csv for a `joint_snapshot`, and its snapshot under `label`."""
        js = snap["js"]
        delta_mm = units.to_mm(self.delta())
        common = {"stage": self.stage, "step": self._iter(), "delta_mm": delta_mm}
        columns = zip(js.rotation.tolist(), units.to_mm(js.opening_intrados).tolist(),
                      units.to_mm(js.opening_extrados).tolist(), js.force_position.tolist(),
                      snap["normal"].tolist(), snap["shear"].tolist(), snap["friction_use"].tolist(),
                      units.to_mm(snap["slip"]).tolist())
        self.records.joints.extend(
            {**common, "interface": k + 1, "rotation_rad": rotation, "opening_intrados_mm": intrados,
             "opening_extrados_mm": extrados, "force_position": position, "normal_force_N": normal,
             "shear_force_N": shear, "friction_use": use, "slip_mm": slip}
            for k, (rotation, intrados, extrados, position, normal, shear, use, slip)
            in enumerate(columns))
        if label:
            self.records.snapshots[label] = {
                "delta_mm": delta_mm, "step": self._iter(),
                "pos_m": snap["pos"][:, :2].tolist(), "rot_rad": snap["rot"].tolist(),
                "hinges": [h.to_json() for h in hinges],
            }

    def _track_friction(self, snap: dict) -> None:
        """Keep the largest mobilised friction |T| / (N tan phi) and the largest accumulated slip
        met in the equilibrium states, with their interfaces: friction can move du only where
        some joint slides."""
        use, slip = snap["friction_use"], snap["slip"]
        k = int(np.argmax(use))
        if use[k] > self._friction.get("max_friction_use", -1.0):
            self._friction.update(max_friction_use=float(use[k]), friction_interface=k + 1,
                                  friction_delta_mm=units.to_mm(self.delta()))
        finite = np.nan_to_num(slip, nan=0.0)
        j = int(np.argmax(finite))
        self._friction.update(max_slip_mm=units.to_mm(float(slip[j])), slip_interface=j + 1)

    def _progress(self, extra: str = "", force: bool = False) -> None:
        from yade import O

        now = time.time()
        if not force and now - self._last_progress < self.num.progress_every_s:
            return
        self._last_progress = now
        wall = now - self.wall0
        rate = self.total_steps / wall if wall > 0 else 0.0
        delta = units.to_mm(self.delta())
        eta = ""
        if self.stage == "loading" and delta > 0 and self.driver.current_speed > 0:
            remaining_s = (self.case.loading.max_settlement_mm - delta) / units.to_mm(
                self.driver.current_speed) / O.dt / max(rate, 1e-9)
            eta = f" ETA<= {remaining_s / 60:.1f} min"
        self.log(f"[{self.case.name}] {self.stage:10s} delta={delta:7.2f} mm step={self.total_steps} "
                 f"{rate:6.0f} steps/s wall={wall:6.0f} s{eta} {extra}")

    def _advance(self, n: int) -> None:
        """Run n steps (the only place that steps the scene, so that steps are counted)."""
        self.gate.advance(n)
        self.total_steps += n
        self.steps_by_stage[self.stage] = self.steps_by_stage.get(self.stage, 0) + n

    def close(self) -> None:
        """Stop YADE's simulation thread (it finishes the step it is in)."""
        self.gate.close()

    def _run_steps(self, n: int) -> None:
        self._advance(n)
        self._record_series()

    def _voussoir_positions(self) -> np.ndarray:
        """Current voussoir centroids (n, 3); a NaN ends the run (the law calls exit(1) on NaN)."""
        from yade import O

        pos = np.array([(p[0], p[1], p[2])
                        for p in (state.pos for state in self.scene.voussoir_states)])
        if not np.all(np.isfinite(pos)):
            raise RunFailedError(f"NaN in block positions at step {O.iter} ({self.stage})")
        return pos

    def _check_finite(self) -> None:
        self._voussoir_positions()

    # ---- stages ---------------------------------------------------------------------------
    def selfweight(self) -> dict:
        """Apply gravity gradually (over `gravity_ramp_periods` joint periods, so that a soft arch
        does not overshoot past its equilibrium), settle with the supports still (unbalanced force
        and block speeds as in a hold, and the supports carrying the weight within the same
        tolerance, so that the reactions read there are static), and zero du's origin there."""
        from yade import O

        self.stage = "selfweight"
        start = O.iter
        ramp_s = self.num.gravity_ramp_periods * math.pi * O.dt / self.num.timestep_safety
        max_steps = int((self.num.selfweight_max_s + ramp_s) / O.dt)
        newton = O.engines[-1]
        gravity = np.array(newton.gravity)
        ramp_steps = max(1, int(ramp_s / O.dt))
        self.weight = sum(O.bodies[i].state.mass for i in self.scene.voussoir_ids) \
            * self.case.loading.gravity_m_per_s2
        unbalanced = math.inf
        while O.iter - start < max_steps:
            fraction = min(1.0, (O.iter - start) / ramp_steps)
            newton.gravity = tuple(gravity * fraction)
            self._run_steps(CHECK_EVERY_STEPS)
            self._check_finite()
            unbalanced = self._unbalanced()
            self._progress(f"gravity {fraction:.0%}, unbalanced {unbalanced:.2e}")
            sag = float(np.max(np.abs(body_states(self.scene)[0] - self.scene.pos0)))
            if sag > units.mm(SELFWEIGHT_COLLAPSE_MM):
                raise RunFailedError(f"the arch does not stand under its own weight: a block fell "
                                     f"{units.to_mm(sag):.0f} mm (kn {self.case.interface.kn_N_per_mm3} N/mm3)")
            if fraction >= 1.0 and unbalanced < self.num.equilibrium_tolerance \
                    and O.iter - start > ramp_steps + 10 * CHECK_EVERY_STEPS \
                    and self._voussoir_speeds().max() < units.mm(self.num.still_speed_mm_per_s) \
                    and self._weight_carried_error() < self.num.equilibrium_tolerance:
                break
        else:
            raise RunFailedError(f"no equilibrium under self-weight within {self.num.selfweight_max_s} s "
                                 f"(unbalanced force ratio {unbalanced:.3g} > "
                                 f"{self.num.equilibrium_tolerance} or blocks still moving)")
        self.driver.zero_here()
        self._record_series(force=True)
        self._record_joints("selfweight")
        left, right = self._reactions()
        crown = self.scene.geometry.crown_voussoir
        info = {
            "steps": O.iter - start, "unbalanced": unbalanced,
            "arch_weight_N": self.weight,
            "vertical_reaction_sum_N": float(left[1] + right[1]),
            "horizontal_reaction_sum_N": float(left[0] + right[0]),
            "thrust_N": float(abs(left[0])),
            "crown_settlement_mm": -units.to_mm(float(O.bodies[self.scene.body_ids[crown]].state.pos[1]
                                                      - self.scene.pos0[crown][1])),
        }
        self.log(f"[{self.case.name}] self-weight equilibrium after {info['steps']} steps: "
                 f"unbalanced {unbalanced:.2e}, reactions {info['vertical_reaction_sum_N']:.3f} N "
                 f"for a weight of {self.weight:.3f} N, thrust {info['thrust_N']:.3f} N")
        return info

    def _weight_carried_error(self) -> float:
        """|sum of vertical support reactions / weight of the voussoirs - 1| (0 in static equilibrium)."""
        left, right = self._reactions()
        return abs((left[1] + right[1]) / self.weight - 1.0)

    def hold(self, runaway: float | None = None, max_s: float | None = None,
             from_rest: bool = True, still_speed: float | None = None,
             tolerance: float | None = None) -> str:
        """Keep the support still, blocks started from rest (or, `from_rest` false, in their motion).

        'stable': after `hold_min_s`, unbalanced force below `tolerance` (default
        `equilibrium_tolerance`) and every block slower than `still_speed` (m/s, default
        `still_speed_mm_per_s`; a mechanism past its limit point would be accelerating by then);
        'runaway': a block moved `runaway_mm`; 'timeout': neither within `hold_max_s`."""
        from yade import O

        self.driver.target = self.delta()
        self._set_damping(self.num.hold_damping)
        if from_rest:
            self._stop_blocks()
        runaway = runaway if runaway is not None else units.mm(self.num.runaway_mm)
        max_steps = int((max_s if max_s is not None else self.num.hold_max_s) / O.dt)
        min_steps = int(self.num.hold_min_s / O.dt)
        still_speed = still_speed if still_speed is not None else units.mm(self.num.still_speed_mm_per_s)
        tolerance = tolerance if tolerance is not None else self.num.equilibrium_tolerance
        start_pos = self._voussoir_positions()
        start = O.iter
        while O.iter - start < max_steps:
            self._run_steps(CHECK_EVERY_STEPS)
            moved = np.linalg.norm(self._voussoir_positions() - start_pos, axis=1).max()
            self._progress(f"holding: max block move {units.to_mm(moved):.3f} mm")
            if moved > runaway:
                return RUNAWAY
            if O.iter - start >= min_steps and self._unbalanced() < tolerance \
                    and self._voussoir_speeds().max() < still_speed:
                return STABLE
        return TIMEOUT

    def _set_damping(self, damping: float) -> None:
        """Local damping of the integrator: `damping` while the support moves, `hold_damping` while
        a hold decides equilibrium (each stage sets its own)."""
        from yade import O

        O.engines[-1].damping = damping

    def _stop_blocks(self) -> None:
        """Zero the blocks' velocities: the hold then tests the configuration statically, without
        kinetic energy from the loading that could carry the arch over a barrier it would not cross."""
        from yade import O

        for i in self.scene.voussoir_ids:
            O.bodies[i].state.vel = (0.0, 0.0, 0.0)
            O.bodies[i].state.angVel = (0.0, 0.0, 0.0)

    def move_to(self, delta: float) -> None:
        """Move the support to `delta` along the trapezoidal profile."""
        self.driver.target = delta
        self._set_damping(self.num.damping)
        while not self.driver.reached() or self.driver.current_speed > 0.0:
            self._run_steps(CHECK_EVERY_STEPS // 5)
            self._check_finite()

    # ---- the equilibrium path (EquilibriumOracle) ------------------------------------------
    def try_increment(self, target: float) -> str:
        """From the last accepted equilibrium state, move the support to `target` and relax there
        with the support held: 'stable', 'runaway' or 'timeout' (see `hold`). A failed state is kept
        for `collapse_state`."""
        if not self._at_accepted:
            self.restore(self._accepted[-1])
        self.stage = "increment"
        # every move lasts as long as the largest increment's: the short moves near collapse are
        # gentle, and the arch ends them close to its equilibrium configuration
        fraction = abs(target - self.delta()) / self._path_settings.max_increment
        self.driver.set_speed(self._full_speed * min(1.0, fraction))
        self.move_to(target)
        self.stage = "relax"
        verdict = self.hold()
        self._at_accepted = False
        if verdict != STABLE:
            self._failures[target] = self.snapshot()
        return verdict

    def accept(self) -> None:
        """The state the last increment relaxed to is the new equilibrium state: keep and record it."""
        self._accepted.append(self.snapshot())
        self._at_accepted = True
        self.stage = "equilibrium"
        first_series, first_joint = len(self.records.series), len(self.records.joints)
        self._record_series(force=True)
        snap, hinges = self.joint_snapshot()
        self._write_joints(snap, hinges)
        self._accepted_records.append((first_series, first_joint))
        self._last_equilibrium_hinges = [h.to_json() for h in hinges]
        self._track_friction(snap)

    def settle(self) -> bool:
        """Relax the accepted state, support held and blocks in their motion, until every block is
        slower than `settle_speed_mm_per_s` and the unbalanced force below SETTLE_TOLERANCE_FACTOR x
        `equilibrium_tolerance`, or `hold_max_s` passes (CGAL contacts never get that quiet), and
        keep the state reached. False if it runs away: it was not an equilibrium."""
        if not self._at_accepted:
            self.restore(self._accepted[-1])
        self.stage = "settle"
        verdict = self.hold(from_rest=False, still_speed=units.mm(self.num.settle_speed_mm_per_s),
                            tolerance=SETTLE_TOLERANCE_FACTOR * self.num.equilibrium_tolerance)
        self.log(f"[{self.case.name}] settling the state at {units.to_mm(self.delta()):.3f} mm: {verdict}")
        if verdict == RUNAWAY:
            self._failures[self.delta()] = self.snapshot()
            self._at_accepted = False
            return False
        self._accepted[-1] = self.snapshot()
        self._at_accepted = True
        return True

    def discard(self) -> None:
        """Drop the last accepted state (it did not settle): the one before is the accepted one."""
        self._accepted.pop()
        self._at_accepted = False
        first_series, first_joint = self._accepted_records.pop()
        for row in self.records.series[first_series:] + self.records.joints[first_joint:]:
            if row["stage"] == "equilibrium":
                row["stage"] = DISCARDED_STAGE

    def follow_equilibrium_path(self) -> PathResult:
        """Load by increments relaxed to equilibrium until du is bracketed (`solve.path`)."""
        self._accepted, self._at_accepted = [self.snapshot()], True
        return follow_path(self, self._path_settings, on_step=self._log_increment)

    def _log_increment(self, step: PathStep) -> None:
        self.log(f"[{self.case.name}] increment {units.to_mm(step.start):7.3f} -> "
                 f"{units.to_mm(step.target):7.3f} mm: {step.verdict} (step {self.total_steps})")

    def collapse_state(self, upper: float) -> list[Hinge]:
        """Show the mechanism: continue the failure at du's upper bracket end `upper` until the
        arch has run away (10 runaway distances more, at most `hold_max_s` more), then read its
        hinges."""
        self.stage = "collapse"
        self.restore(self._failures[min(self._failures, key=lambda d: abs(d - upper))])
        self.hold(runaway=10.0 * units.mm(self.num.runaway_mm), from_rest=False)
        hinges = self._record_joints("collapse")
        self._record_series(force=True)
        return hinges

    def criterion_text(self) -> str:
        """The loading protocol and collapse criterion with this case's numbers, for summary.json."""
        n = self.num
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

    def run(self) -> dict:
        """All stages, then YADE's simulation thread stopped; returns the summary dict (records are
        in `self.records`)."""
        try:
            return self._stages()
        finally:
            self.close()

    def _stages(self) -> dict:
        from yade import O

        selfweight = self.selfweight()
        path = self.follow_equilibrium_path()
        summary: dict = {"selfweight": selfweight}
        lo = units.to_mm(path.lower)
        summary.update(increments=len(path.steps), equilibria=len(path.equilibria),
                       last_equilibrium_mm=lo, hinges_last_equilibrium=self._last_equilibrium_hinges,
                       friction=dict(self._friction))
        if path.collapsed:
            hinges = self.collapse_state(path.upper)
            du, hi = units.to_mm(path.du), units.to_mm(path.upper)
            summary.update(collapsed=True, du_mm=du, du_bracket_mm=[lo, hi])
            self.log(f"[{self.case.name}] du = {du:.2f} mm (no equilibrium at {hi:.2f}, "
                     f"equilibrium at {lo:.2f})")
        else:
            self.log(f"[{self.case.name}] no collapse up to {self.case.loading.max_settlement_mm} mm")
            summary.update(collapsed=False, du_mm=None, du_bracket_mm=None)
            self.stage = "end"
            hinges = self._record_joints("end")
        summary["hinges_at_collapse"] = [{"interface": h.interface, "side": h.side} for h in hinges] \
            if summary["collapsed"] else []
        summary["hinges_detail"] = [h.to_json() for h in hinges]
        summary["steps"] = self.total_steps
        summary["steps_by_stage"] = dict(self.steps_by_stage)
        summary["dt_s"] = O.dt
        wall = time.time() - self.wall0
        summary["wall_s"] = wall
        summary["steps_per_s"] = self.total_steps / wall if wall > 0 else None
        summary["profile"] = self.clock.profile(wall)
        self._progress("done", force=True)
        return summary
