"""Per-contact incremental shear force with a Coulomb cap, applied from Python every step.

YADE 2023.02a's `Law2_PolyhedraGeom_PolyhedraPhys_Volumetric` keeps its running shear force in one
attribute of the law functor, shared by all contacts (DESIGN.md §3), so the scene gives the law a
negligible ks and this engine adds the shear instead: for each contact, the in-plane shear force
s <- s - ks_yade * (shear increment . t), |s| <= tan(phi) * |Fn|, where t = z x n and
ks_yade = ks * depth * compressed length (N/m, see `mechanics.compressed_length`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from yadearch.case.mechanics import ContactStiffness, compressed_length
from yadearch.model.geometry import ArchGeometry


class PerContactShear:
    """Holds one shear force per contact (keyed by body-id pair) and applies it each step."""

    def __init__(self, stiffness: ContactStiffness, geometry: ArchGeometry, body_ids: list[int]):
        self.ks = stiffness.ks
        self.tan_friction = stiffness.tan_friction
        self.depth = geometry.depth
        self.joint_length = geometry.thickness
        self.geometry = geometry
        self.body_ids = body_ids
        self.shear: dict[tuple[int, int], float] = {}
        self._joint_frames: dict[tuple[int, int], tuple[int, Any, Any]] = {}
        self._states: dict[int, Any] = {}

    def bind(self, pos0: np.ndarray, ori0: np.ndarray) -> None:
        """Store each joint's intrados point and direction in its left body's local frame."""
        from yade import O
        from yade.minieigenHP import Quaternion, Vector3

        for joint in self.geometry.joints:
            left_id, right_id = self.body_ids[joint.left], self.body_ids[joint.right]
            w, x, y, z = ori0[joint.left]
            inverse = Quaternion(w, x, y, z).conjugate()
            intrados = Vector3(*joint.intrados, 0.0) - Vector3(*pos0[joint.left])
            direction = Vector3(*(joint.extrados - joint.intrados), 0.0) / joint.length
            self._joint_frames[(left_id, right_id)] = (left_id, inverse * intrados, inverse * direction)
        self._states = {i: O.bodies[i].state for i in self.body_ids}

    def ks_of_contact(self, id1: int, id2: int, contact_point: Any) -> float:
        """ks_yade (N/m) of a contact from the compressed area of its joint."""
        frame = self._joint_frames.get((min(id1, id2), max(id1, id2)))
        if frame is None:  # blocks that are not neighbours: take the nominal joint area
            return self.ks * self.depth * self.joint_length
        left_id, intrados_local, direction_local = frame
        state = self._states[left_id]
        offset = (contact_point - state.pos - state.ori * intrados_local).dot(state.ori * direction_local)
        return self.ks * self.depth * compressed_length(offset, self.joint_length)

    def step(self) -> None:
        """Update and apply every contact's shear force (called by a PyRunner after the law)."""
        from yade import O
        from yade.minieigenHP import Vector3

        add_force, add_torque = O.forces.addF, O.forces.addT
        states = self._states
        shear = self.shear
        tan_friction = self.tan_friction
        for interaction in O.interactions:
            geom = interaction.geom
            id1, id2 = interaction.id1, interaction.id2
            if geom.penetrationVolume <= 0.0:
                shear[(id1, id2)] = 0.0
                continue
            normal = geom.normal
            tangent = Vector3(-normal[1], normal[0], 0.0)
            point = geom.contactPoint
            ks = self.ks_of_contact(id1, id2, point)
            s = shear.get((id1, id2), 0.0) - ks * geom.shearInc.dot(tangent)
            cap = tan_friction * interaction.phys.normalForce.norm()
            s = max(-cap, min(cap, s))
            shear[(id1, id2)] = s
            force = tangent * s  # the law's "shearForce": body 1 receives -force, body 2 +force
            add_force(id1, -force)
            add_force(id2, force)
            add_torque(id1, (point - states[id1].pos).cross(-force))
            add_torque(id2, (point - states[id2].pos).cross(force))

    def shear_force(self, id1: int, id2: int) -> float:
        """Current signed shear force of a contact (N), 0 if not in contact."""
        return self.shear.get((id1, id2), self.shear.get((id2, id1), 0.0))
