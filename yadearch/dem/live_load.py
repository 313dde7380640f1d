"""The live load on the DEM's blocks (YADE layer): the case's live load (`model.loads`) times a
multiplier that ramps to a target at a set rate, applied every step at its points on the blocks with
the arms turned by the blocks' rotations, as the static engine applies it."""

from __future__ import annotations

from typing import Any

import numpy as np

from yadearch.dem.joint_elements import JointElementContacts
from yadearch.dem.scene import CALLBACK_NAME, ArchScene
from yadearch.errors import CaseError
from yadearch.model.load_control import LoadSpring
from yadearch.model.loads import turned_moments, turning_stiffness

LOAD_DRIVER_LABEL = "yadearch_live_load"
LOAD_CALLBACK = f"{CALLBACK_NAME}_load"  # the driver's name in __main__, which its PyRunner calls


class LoadDriver:
    """Applies `loads` (n_blocks, 4: force x, force y and the arm terms m0, d0 of a multiplier of 1,
    `model.loads.block_loads`) x `multiplier`, which moves toward `target` at `rate` per second."""

    def __init__(self, scene: ArchScene, loads: np.ndarray):
        if not isinstance(scene.contacts, JointElementContacts):
            raise CaseError("a live load needs the joint elements (numerics.contact_model = 'joint')")
        self.contacts: JointElementContacts = scene.contacts
        self.loads = loads
        self.loaded = np.flatnonzero(np.any(loads != 0.0, axis=1))
        self._loaded_loads = loads[self.loaded]  # read every step
        self.body_ids = [scene.body_ids[b] for b in self.loaded]
        self.multiplier = 0.0
        self.target = 0.0
        self.rate = 0.0  # multiplier per second
        self.spring: LoadSpring | None = None  # past the peak the load is the spring's (`drive_by`)

    def engine(self) -> Any:
        """The PyRunner that calls `step` every step (before the integrator)."""
        from yade.wrapper import PyRunner

        return PyRunner(command=f"{LOAD_CALLBACK}.step()", iterPeriod=1, label=LOAD_DRIVER_LABEL)

    def ramp_to(self, target: float, rate: float) -> None:
        """Move the multiplier to `target` at `rate` per second from the next step."""
        self.target, self.rate = target, rate

    def set(self, multiplier: float) -> None:
        """Put the multiplier at `multiplier` at once (a restored state's), the spring let go."""
        self.spring = None
        self.target = multiplier
        self._put(multiplier)

    def _put(self, multiplier: float) -> None:
        """The multiplier now, and the load's forces the unbalanced force counts (`contacts.external`)."""
        self.multiplier = multiplier
        self.contacts.external = multiplier * self.loads[:, 0:2]

    def reached(self) -> bool:
        return self.multiplier == self.target

    def drive_by(self, spring: LoadSpring) -> None:
        """From the next step on, the multiplier is `spring`'s on the blocks' poses: the load's
        displacement drives it (`model.load_control`)."""
        self.spring = spring

    def step(self) -> None:
        """This step's multiplier, and the load's forces and turned moments added to the blocks."""
        from yade import O

        if self.spring is not None:
            self.spring.advance(O.dt)
            self.target = self.spring.multiplier(self.contacts.poses)
            self._put(self.target)
        elif self.multiplier != self.target:
            change = self.rate * O.dt
            if abs(self.target - self.multiplier) <= change:
                self._put(self.target)
            else:
                self._put(self.multiplier + (change if self.target > self.multiplier else -change))
        if self.multiplier != 0.0:
            add_block_loads(self.body_ids, self.multiplier * self._loaded_loads, self.contacts.poses[self.loaded, 2])

    def turning(self) -> np.ndarray:
        """The load's own rotational stiffness on each block now (N m/rad), for the stability test."""
        return self.multiplier * turning_stiffness(self.loads, self.contacts.poses[:, 2])


def add_block_pushes(body_ids: list[int], pushes: np.ndarray) -> None:
    """Add `pushes` (k, 3: force x, force y and moment about the centroid) to the bodies `body_ids`."""
    from yade import O

    add_force, add_torque = O.forces.addF, O.forces.addT
    for body_id, (fx, fy, tz) in zip(body_ids, pushes.tolist()):
        add_force(body_id, (fx, fy, 0.0))
        add_torque(body_id, (0.0, 0.0, tz))


def add_block_loads(body_ids: list[int], loads: np.ndarray, turn: np.ndarray) -> None:
    """Add `loads` (k, 4; `model.loads.block_loads`) to the bodies `body_ids` in YADE's force container:
    the forces, and their moments about the centroids with the arms turned by the blocks' rotations `turn`."""
    add_block_pushes(body_ids, np.column_stack([loads[:, 0:2], turned_moments(loads, turn)]))
