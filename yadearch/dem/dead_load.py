"""The dead loads on the DEM's blocks (YADE layer): the backfill's equivalent loads (`model.backfill`),
held with the weights, and its passive resistance (`model.passive_fill`). They grow with gravity while
the self-weight ramps and are applied every step at their points on the blocks with the arms turned by
the blocks' rotations, the passive springs from the blocks' poses that step, as the static engine
takes them (gravity x the dead loads, `solve.statics`). The springs yield for good at each equilibrium
the DEM's path keeps (`yield_fill`, which the path calls through `LiveArch.yield_fill`, as the static
engine yields them at each equilibrium it solves); between them they load and unload from the last
one's reference. That history is the contacts' (`JointElementContacts.fill_springs`), snapshot and
restored with the joints' shear. Yielded at every step instead, the moves' and holds' transients
yielded the fill and du followed the support's acceleration (CHANGELOG)."""

from __future__ import annotations

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import backfill
from yadearch.dem.joint_elements import JointElementContacts
from yadearch.dem.live_load import add_block_loads, add_block_pushes
from yadearch.dem.scene import CALLBACK_NAME, ArchScene, install_before_integrator
from yadearch.errors import CaseError
from yadearch.model.backfill import backfill_points
from yadearch.model.loads import block_loads, turning_stiffness
from yadearch.model.passive_fill import block_forces, block_stiffness, passive_springs, scaled, yielded

DEAD_LOAD_LABEL = "yadearch_dead_load"
DEAD_CALLBACK = f"{CALLBACK_NAME}_dead"  # the driver's name in __main__, which its PyRunner calls


class DeadLoadDriver:
    """Applies `loads` (n_blocks, 4: force x, force y and the arm terms m0, d0 at full gravity,
    `model.loads.block_loads`) and the fill's `passive` springs (at full gravity) x gravity's share of
    `full_gravity` (m/s^2) in the scene now."""

    def __init__(self, scene: ArchScene, loads: np.ndarray, full_gravity: float, passive: np.ndarray):
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
        self.contacts.fill_springs = passive
        self.resists = len(passive) > 0  # the fill has passive springs on the blocks
        self.share = 0.0  # gravity's share of its full value at the last step

    def install(self) -> None:
        """Reachable from its PyRunner, which runs every step before the integrator."""
        from yade.wrapper import PyRunner

        engine = PyRunner(command=f"{DEAD_CALLBACK}.step()", iterPeriod=1, label=DEAD_LOAD_LABEL)
        install_before_integrator(DEAD_CALLBACK, self, engine)

    def step(self) -> None:
        """This step's share of the loads: forces and turned moments added to the blocks."""
        share = -float(self.scene.newton.gravity[1]) / self.full_gravity
        if share != self.share or self.resists:
            self.share = share
            self.contacts.dead_external = share * self.loads[:, 0:2]
        if share == 0.0:
            return
        poses = self.contacts.poses
        add_block_loads(self.body_ids, share * self._loaded_loads, poses[self.loaded, 2])
        if self.resists:
            pushes = block_forces(scaled(self.contacts.fill_springs, share), poses)
            pushing = np.flatnonzero(pushes[:, 0])  # a face not pushed into the fill takes nothing
            self.contacts.dead_external[pushing, 0] += pushes[pushing, 0]
            add_block_pushes([self.scene.body_ids[b] for b in pushing], pushes[pushing])

    def yield_fill(self) -> None:
        """The blocks are at rest in equilibrium: the fill yields for good where their faces pushed it
        further than u_p (`model.passive_fill.yielded`)."""
        if self.resists:
            self.contacts.fill_springs = yielded(self.contacts.fill_springs, self.contacts.read_poses())

    def turning(self) -> np.ndarray:
        """The loads' own rotational stiffness on each block now (N m/rad), for the stability test."""
        return self.share * turning_stiffness(self.loads, self.contacts.poses[:, 2])

    def passive_stiffness(self, poses: np.ndarray, lever: float) -> np.ndarray | None:
        """The passive springs' tangent at `poses` on every block's x, y and rotation x `lever` (N/m; None
        without springs), for the stability test."""
        springs = self.contacts.fill_springs
        return block_stiffness(scaled(springs, self.share), poses, lever) if self.resists else None

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
    loads = block_loads(backfill_points(scene.geometry, fill), centroids, len(scene.body_ids))
    passive = passive_springs(scene.geometry, centroids, fill)
    driver = DeadLoadDriver(scene, loads, case.loading.gravity_m_per_s2, passive)
    driver.install()
    return driver
