"""In-memory snapshots of the live scene: everything that evolves (the bodies' states, the contact
model's state, the support driver), taken and put back so that the loading can return to an accepted
equilibrium or to a failed increment's state.

Not `O.saveTmp`: a scene brought back by `O.loadTmp` steps 28 % slower in YADE 2023.02a's polyhedra
contact than the live scene (70 vs 97 steps/s, same state), and the search and collapse stages run on
restored states.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np

    from yadearch.dem.driver import SupportDriver
    from yadearch.dem.scene import ArchScene, ContactModel


def capture(contacts: ContactModel, driver: SupportDriver) -> dict:
    """The scene's state now: body states, the contact model's state (per-contact shear forces,
    CGAL's intersection hints) and the support driver's target and speed."""
    from yade import O

    # copies: YADE's State.vel and State.angVel are references to the live vectors (pos and ori
    # are copies), so a snapshot holding them would restore whatever velocity the scene has then
    bodies = [(tuple(s.pos), s.ori, tuple(s.vel), tuple(s.angVel)) for s in (b.state for b in O.bodies)]
    return {"bodies": bodies, "contacts": contacts.snapshot(), "target": driver.target, "speed": driver.current_speed}


def put_back(snapshot: dict, contacts: ContactModel, driver: SupportDriver) -> None:
    """Put the live scene back in a `capture`d state."""
    from yade import O

    for body, (pos, ori, vel, ang_vel) in zip(O.bodies, snapshot["bodies"]):
        state = body.state
        state.pos, state.ori, state.vel, state.angVel = pos, ori, vel, ang_vel
    contacts.restore(snapshot["contacts"])
    driver.target = snapshot["target"]
    driver.current_speed = snapshot["speed"]


def place_voussoirs(
    scene: ArchScene, centroids: np.ndarray, rotations: np.ndarray, with_supports: bool = False
) -> None:
    """Put every voussoir (and, `with_supports`, the two supports too) at rest at `centroids`
    (n_blocks, 2; m) turned by `rotations` (n_blocks; rad about z from the undeformed pose), e.g. a
    rigid analysis's placement: a hold then tests whether that configuration is an equilibrium of
    the scene's joints. A support put so has moved along its path as far as the placement says."""
    from yade import O, Quaternion, Vector3

    blocks = range(len(scene.body_ids)) if with_supports else range(1, len(scene.body_ids) - 1)
    for k in blocks:
        state = O.bodies[scene.body_ids[k]].state
        w, x, y, z = scene.ori0[k]
        state.pos = Vector3(float(centroids[k][0]), float(centroids[k][1]), float(scene.pos0[k][2]))
        state.ori = Quaternion(Vector3(0.0, 0.0, 1.0), float(rotations[k])) * Quaternion(w, x, y, z)
        state.vel, state.angVel = Vector3(0.0, 0.0, 0.0), Vector3(0.0, 0.0, 0.0)
    scene.contacts.stopped()
