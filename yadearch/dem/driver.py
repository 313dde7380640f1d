"""The driven supports: move them along the case's path (`model.movement`) to a target path
length with a trapezoidal speed profile (YADE layer)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from yadearch.dem.scene import CALLBACK_NAME, ArchScene
from yadearch.model.movement import Motion, Movement

ARRIVED_M = 1e-12  # the support is on target within this distance (m)
DRIVER_LABEL = "yadearch_support_driver"
DRIVER_CRUISE_PERIOD = 50  # steps between the support driver's calls while it cruises (translations)


class SupportDriver:
    """Moves the driven supports towards a target path length with a trapezoidal speed profile
    (accelerate at `accel` up to `speed`, cruise, brake at `accel` to stop exactly on target; accel
    0 = instantaneous). A translating support keeps one velocity; a rotating one, or one on a
    prescribed path, has its centroid's velocity set anew every step to the chord of that step's
    motion."""

    def __init__(self, scene: ArchScene, movement: Movement, speed: float, accel: float):
        self.scene = scene
        self.movement = movement
        self.accel = accel if accel > 0 else math.inf
        self.set_speed(speed)
        self._target = 0.0
        self.current_speed = 0.0
        self._moving: list[tuple[Any, Motion]] = []  # YADE State and motion of each moving support
        self._origin: tuple[np.ndarray, Any] = (np.zeros(2), None)  # the reference's pos, ori
        self._last = 0.0  # the path length last read: which pass of a path that crosses itself
        self._engine: Any = None  # the driver's PyRunner, once bound

    def set_speed(self, speed: float) -> None:
        """The cruise speed of the next moves (m/s along the path)."""
        self.speed = speed
        self.ramp = speed * speed / (2.0 * self.accel)  # braking distance from full speed

    def engine(self):
        """The PyRunner that calls `step`, labelled so that `bind` (and the benchmark) find it."""
        from yade.wrapper import PyRunner

        return PyRunner(command=f"{CALLBACK_NAME}_driver.step()", iterPeriod=1, label=DRIVER_LABEL)

    def bind(self) -> None:
        """Attach to the moving support bodies (the path's reference first) and the driver's engine."""
        from yade import O

        bodies = {"left": self.scene.left_support, "right": self.scene.right_support}
        self._moving = []
        for side in ("right", "left"):  # the path's reference first
            motion = self.movement.motion(side)
            if motion is not None:
                self._moving.append((O.bodies[bodies[side]].state, motion))
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
        """Measure the path from the supports' current placement and stop them there."""
        state = self._moving[0][0]
        self._origin = (np.array([state.pos[0], state.pos[1]]), state.ori)
        self._last = 0.0
        self.target = 0.0

    def displacement(self) -> float:
        """Path length travelled since `zero_here` (m), read from the reference support's placement
        (`travelled`: its turn, its shift along the line, or its springing point on the path)."""
        state, motion = self._moving[0]
        angle = 0.0
        if motion.rotation != 0.0:
            turn = state.ori * self._origin[1].conjugate()  # minieigen quaternions index (x, y, z, w)
            angle = 2.0 * math.atan2(turn[2], turn[3])
            angle = (angle + math.pi) % (2.0 * math.pi) - math.pi
        self._last = motion.travelled(self._origin[0], (state.pos[0], state.pos[1]), angle, self._last)
        return self._last

    def step(self) -> None:
        """Set the supports' velocities for this step (called before the integrator)."""
        from yade import O

        lam = self.displacement()
        remaining = self.target - lam
        dt = O.dt
        if remaining <= ARRIVED_M:  # a float-rounding remainder must not keep the support creeping
            speed = 0.0
        else:
            speed = min(
                self.speed,
                self.current_speed + self.accel * dt,
                math.sqrt(2.0 * self.accel * remaining),
                remaining / dt,
            )
        self.current_speed = speed
        for state, motion in self._moving:
            (vx, vy), turn_rate = motion.velocity(np.array([state.pos[0], state.pos[1]]), lam, speed, dt)
            state.vel = (float(vx), float(vy), 0.0)
            state.angVel = (0.0, 0.0, turn_rate)
        self._schedule(remaining, speed, dt)

    def _schedule(self, remaining: float, speed: float, dt: float) -> None:
        """Call `step` only when the speed can change: never while the support stands on target
        (holds, self-weight), and every `DRIVER_CRUISE_PERIOD` steps at most while a translation
        cruises short of its braking distance. The support's path is the same as with a call every step."""
        if speed == 0.0 and remaining <= ARRIVED_M:
            self._engine.dead = True
            return
        cruise_steps = 0
        if speed == self.speed and self.movement.uniform:
            cruise_steps = int((remaining - self.ramp) / (speed * dt))
        self._engine.iterPeriod = max(1, min(DRIVER_CRUISE_PERIOD, cruise_steps - 1))

    def reached(self) -> bool:
        return self.target - self.displacement() <= ARRIVED_M
