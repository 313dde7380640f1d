"""The dead loads on the DEM's blocks (YADE layer): the backfill's equivalent loads (`model.backfill`),
held with the weights. They grow with gravity while the self-weight ramps and are applied every step at
their points on the blocks with the arms turned by the blocks' rotations, as the static engine takes
them (gravity x the dead loads, `solve.statics`)."""

from __future__ import annotations

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import backfill
from yadearch.dem.joint_elements import JointElementContacts
from yadearch.dem.live_load import add_block_loads
from yadearch.dem.scene import CALLBACK_NAME, ArchScene, install_before_integrator
from yadearch.errors import CaseError
from yadearch.model.backfill import backfill_points
from yadearch.model.loads import block_loads, turning_stiffness

DEAD_LOAD_LABEL = "yadearch_dead_load"
DEAD_CALLBACK = f"{CALLBACK_NAME}_dead"  # the driver's name in __main__, which its PyRunner calls


class DeadLoadDriver:
    """Applies `loads` (n_blocks, 4: force x, force y and the arm terms m0, d0 at full gravity,
    `model.loads.block_loads`) x gravity's share of `full_gravity` (m/s^2) in the scene now."""

    def __init__(self, scene: ArchScene, loads: np.ndarray, full_gravity: float):
        if not isinstance(scene.contacts, JointElementContacts):
            raise CaseError(
                "loads.fill_depth_mm: backfill in the DEM needs the joint elements (numerics.contact_model = 'joint')"
            )
        self.scene = scene
        self.contacts: JointElementContacts = scene.contacts
        self.loads = loads
        self.full_gravity = full_gravity
        self.loaded = np.flatnonzero(np.any(loads != 0.0, axis=1))
        self._loaded_loads = loads[self.loaded]  # read every step
        self.body_ids = [scene.body_ids[b] for b in self.loaded]
        self.share = 0.0  # gravity's share of its full value at the last step

    def install(self) -> None:
        """Reachable from its PyRunner, which runs every step before the integrator."""
        from yade.wrapper import PyRunner

        engine = PyRunner(command=f"{DEAD_CALLBACK}.step()", iterPeriod=1, label=DEAD_LOAD_LABEL)
        install_before_integrator(DEAD_CALLBACK, self, engine)

    def step(self) -> None:
        """This step's share of the loads: forces and turned moments added to the blocks."""
        share = -float(self.scene.newton.gravity[1]) / self.full_gravity
        if share != self.share:
            self.share = share
            self.contacts.dead_external = share * self.loads[:, 0:2]
        if share != 0.0:
            add_block_loads(self.body_ids, share * self._loaded_loads, self.contacts.poses[self.loaded, 2])

    def turning(self) -> np.ndarray:
        """The loads' own rotational stiffness on each block now (N m/rad), for the stability test."""
        return self.share * turning_stiffness(self.loads, self.contacts.poses[:, 2])

    @property
    def vertical(self) -> float:
        """The loads' total weight at full gravity (N, positive down): what the supports carry besides the arch's."""
        return -float(self.loads[:, 1].sum())


def install_dead_loads(scene: ArchScene, case: ArchCase) -> DeadLoadDriver | None:
    """The case's backfill on the scene's voussoirs, about the bodies' own centroids (None without fill)."""
    fill = backfill(case)
    if not fill.present:
        return None
    centroids = scene.pos0[:, 0:2]
    loads = block_loads(backfill_points(scene.geometry, centroids, fill), centroids, len(scene.body_ids))
    driver = DeadLoadDriver(scene, loads, case.loading.gravity_m_per_s2)
    driver.install()
    return driver
