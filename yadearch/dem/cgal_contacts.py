"""The dry joints as YADE's polyhedra contacts: CGAL intersections, the volumetric law for the normal
force and `shear.PerContactShear` for the shear (the law's own shear is shared by all contacts)."""

from __future__ import annotations

from typing import Any

import numpy as np

from yadearch.case.mechanics import ContactStiffness
from yadearch.dem.shear import PerContactShear
from yadearch.model.geometry import ArchGeometry
from yadearch.model.passive_fill import SpringTangent

# Joint j sets bit j % JOINT_MASK_BITS of the collision masks of its two blocks, so the collider only
# pairs blocks sharing a joint (or JOINT_MASK_BITS - 1 or more joints apart, which never touch).
JOINT_MASK_BITS = 6


class CgalContacts:
    """Contact model "cgal": YADE's collider, CGAL polyhedra intersections and volumetric law."""

    name = "cgal"

    def __init__(self, stiffness: ContactStiffness, geometry: ArchGeometry, body_ids: list[int]):
        self.geometry = geometry
        self.body_ids = body_ids
        self.shear = PerContactShear(stiffness, geometry, body_ids)

    def bind(self, pos0: np.ndarray, ori0: np.ndarray, callback: str) -> list[Any]:
        """Set the collision masks and return the engines between ForceResetter and Newton."""
        from yade import O
        from yade.wrapper import (
            Bo1_Polyhedra_Aabb,
            Ig2_Polyhedra_Polyhedra_PolyhedraGeom,
            InsertionSortCollider,
            InteractionLoop,
            Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys,
            Law2_PolyhedraGeom_PolyhedraPhys_Volumetric,
            PyRunner,
        )

        for body_id, mask in zip(self.body_ids, joint_masks(self.geometry)):
            O.bodies[body_id].mask = mask
        self.shear.bind(pos0, ori0)
        return [
            InsertionSortCollider([Bo1_Polyhedra_Aabb()]),
            InteractionLoop(
                [Ig2_Polyhedra_Polyhedra_PolyhedraGeom()],
                [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()],
            ),
            PyRunner(command=f"{callback}.step()", iterPeriod=1, initRun=True),
        ]

    def step(self) -> None:
        self.shear.step()

    def joint_contacts(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Contact point (n_joints, 2; NaN if open), normal and shear force (n_joints,) of every joint."""
        from yade import O

        joints = self.geometry.joints
        points = np.full((len(joints), 2), np.nan)
        normal = np.zeros(len(joints))
        shear = np.zeros(len(joints))
        for k, joint in enumerate(joints):
            a, b = self.body_ids[joint.left], self.body_ids[joint.right]
            inter = O.interactions[a, b] if O.interactions.has(a, b) else None
            if inter is None or not inter.isReal or inter.geom.penetrationVolume <= 0:
                continue
            cp = inter.geom.contactPoint
            points[k] = (cp[0], cp[1])
            normal[k] = inter.phys.normalForce.norm()
            shear[k] = self.shear.shear_force(a, b)
        return points, normal, shear

    def joint_slip(self) -> np.ndarray:
        """Not tracked by this model: NaN for every joint."""
        return np.full(len(self.geometry.joints), np.nan)

    def smallest_stiffness(self, turning: np.ndarray | None = None, springs: SpringTangent | None = None) -> float:
        """Not available from CGAL's contacts (the joint elements compute it): NaN."""
        return float("nan")

    def snapshot(self) -> dict:
        """The contacts' geometry (the intersection's starting hints) and per-contact shear forces."""
        from yade import O

        contacts = {
            (i.id1, i.id2): (tuple(i.geom.contactPoint), tuple(i.geom.normal))
            for i in O.interactions
            if i.geom is not None
        }
        return {"contacts": contacts, "shear": dict(self.shear.shear)}

    def restore(self, snapshot: dict) -> None:
        """Back to a `snapshot` (contacts absent now are recreated by the collider at the next step)."""
        from yade import O

        contacts = snapshot["contacts"]
        for interaction in O.interactions:
            saved = contacts.get((interaction.id1, interaction.id2))
            if saved is not None and interaction.geom is not None:
                interaction.geom.contactPoint, interaction.geom.normal = saved
        self.shear.shear = dict(snapshot["shear"])

    def stopped(self) -> None:
        """Nothing to do: the shear law reads the velocities YADE holds."""

    def unbalanced(self) -> float:
        """YADE's unbalanced force: mean resultant force on the blocks / mean contact force."""
        from yade import utils

        return float(utils.unbalancedForce())


def joint_masks(geometry: ArchGeometry) -> list[int]:
    """Collision mask of each block: one bit per joint number modulo `JOINT_MASK_BITS`.

    Tilted voussoirs two apart have overlapping bounding boxes, so without masks the collider hands
    CGAL about 30 pairs that never touch (55-voussoir arch: 86 interactions for 56 joints, 10 % of
    the step time). A block without joints keeps all bits and may touch anything."""
    all_bits = (1 << JOINT_MASK_BITS) - 1
    masks = [0] * len(geometry.blocks)
    for joint in geometry.joints:
        bit = 1 << (joint.number % JOINT_MASK_BITS)
        masks[joint.left] |= bit
        masks[joint.right] |= bit
    return [mask or all_bits for mask in masks]
