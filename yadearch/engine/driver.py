"""The driven support: moves it to a target displacement along a trapezoidal speed profile (YADE layer)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from yadearch.engine.scene import CALLBACK_NAME, ArchScene

ARRIVED_M = 1e-12  # the support is on target within this distance (m)
DRIVER_LABEL = "yadearch_support_driver"
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
        self._state: Any = None  # YADE's State of the driven support, once bound
        self._engine: Any = None  # the driver's PyRunner, once bound

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
