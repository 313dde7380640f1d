"""Build the YADE scene of an arch case: polyhedral blocks, materials, engines, time step.

Only this module, `shear`, `stepping` and `runner` import YADE. The volumetric law's own shear is
switched off (its running shear force is shared by all contacts in YADE 2023.02a); `PerContactShear`
replaces it.
"""

from __future__ import annotations

import __main__
from dataclasses import dataclass
from typing import Any

import numpy as np

from . import units
from .case import ArchCase
from .geometry import ArchGeometry, segmental_arch
from .mechanics import ContactStiffness, contact_stiffness, critical_timestep
from .shear import PerContactShear
from .stepping import close_active
from .yade_env import import_yade

# Poisson ratio given to YADE materials so that Ip2's ks = young*poisson is negligible but not the
# NaN that poisson = 0 produces (0/0 in the harmonic mean).
_NEGLIGIBLE_POISSON = 1e-12
# Name under which the scene's Python callbacks are reachable from PyRunner commands.
CALLBACK_NAME = "_yadearch_scene"
# Joint j sets bit j % JOINT_MASK_BITS of the collision masks of its two blocks, so the collider only
# pairs blocks sharing a joint (or JOINT_MASK_BITS - 1 or more joints apart, which never touch).
JOINT_MASK_BITS = 6


@dataclass
class ArchScene:
    """Handles on a built scene: body ids in geometry order and the undeformed body states."""

    geometry: ArchGeometry
    stiffness: ContactStiffness
    body_ids: list[int]
    pos0: np.ndarray
    ori0: np.ndarray  # quaternions (w, x, y, z)
    shear: PerContactShear
    dt: float

    @property
    def left_support(self) -> int:
        return self.body_ids[0]

    @property
    def right_support(self) -> int:
        return self.body_ids[-1]

    @property
    def voussoir_ids(self) -> list[int]:
        return self.body_ids[1:-1]


def arch_geometry(case: ArchCase) -> ArchGeometry:
    """The SI geometry of a case."""
    g = case.geometry
    return segmental_arch(g.n_voussoirs, g.embrace_deg, units.mm(g.internal_radius_mm),
                          units.mm(g.thickness_mm), units.mm(g.depth_mm), units.mm(g.support_length_mm))


def build_scene(case: ArchCase) -> ArchScene:
    """Reset YADE's global scene and fill it with the case's arch: supports fixed, voussoirs planar."""
    geometry = arch_geometry(case)
    stiffness = contact_stiffness(case, geometry)
    dt = case.numerics.timestep_safety * critical_timestep(case, geometry, stiffness)
    return build_block_scene(
        geometry, stiffness, density=units.density(case.material.density_g_per_cm3),
        gravity=(0.0, -case.loading.gravity_m_per_s2, 0.0), damping=case.numerics.damping, dt=dt,
        fixed={0, len(geometry.blocks) - 1}, threads=case.numerics.threads)


def build_block_scene(geometry: ArchGeometry, stiffness: ContactStiffness, density: float,
                      gravity: tuple[float, float, float], damping: float, dt: float,
                      fixed: set[int], threads: int = 1) -> ArchScene:
    """Reset YADE's global scene and fill it with `geometry.blocks` (indices in `fixed` do not move
    unless driven; the others move in the x-y plane) and the dry-joint contact engines."""
    import_yade(threads)
    from yade import O, polyhedra_utils
    from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Polyhedra_Aabb,
                              InteractionLoop, Ig2_Polyhedra_Polyhedra_PolyhedraGeom,
                              Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys,
                              Law2_PolyhedraGeom_PolyhedraPhys_Volumetric, NewtonIntegrator,
                              PyRunner, PolyhedraMat)

    close_active()
    O.reset()
    material = PolyhedraMat(young=stiffness.material_young, poisson=_NEGLIGIBLE_POISSON,
                            frictionAngle=float(np.arctan(stiffness.tan_friction)), density=density,
                            IsSplitable=False)
    O.materials.append(material)
    body_ids = []
    for index, vertices in enumerate(geometry.blocks):
        body = polyhedra_utils.polyhedra(material, v=[tuple(v) for v in vertices], fixed=index in fixed)
        if index not in fixed:
            body.state.blockedDOFs = "zXY"  # planar motion: no z translation, rotation about z only
        body_ids.append(O.bodies.append(body))
    for body_id, mask in zip(body_ids, joint_masks(geometry)):
        O.bodies[body_id].mask = mask

    shear = PerContactShear(stiffness, geometry, body_ids)
    setattr(__main__, CALLBACK_NAME, shear)
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb()]),
        InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()],
                        [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                        [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
        PyRunner(command=f"{CALLBACK_NAME}.step()", iterPeriod=1),
        NewtonIntegrator(damping=damping, gravity=gravity),
    ]
    O.dt = dt
    pos0 = np.array([list(O.bodies[i].state.pos) for i in body_ids])
    ori0 = np.array([_quat_wxyz(O.bodies[i].state.ori) for i in body_ids])
    shear.bind(pos0, ori0)
    return ArchScene(geometry, stiffness, body_ids, pos0, ori0, shear, dt)


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


def _quat_wxyz(q: Any) -> list[float]:
    """A minieigen Quaternion (indexed x, y, z, w) as [w, x, y, z]."""
    return [q[3], q[0], q[1], q[2]]


def body_states(scene: ArchScene) -> tuple[np.ndarray, np.ndarray]:
    """Current positions (n, 3) and z-rotations since the start (n,) of all blocks, in geometry order."""
    from yade import O

    pos = np.empty((len(scene.body_ids), 3))
    ori = np.empty((len(scene.body_ids), 4))
    for k, i in enumerate(scene.body_ids):
        state = O.bodies[i].state
        pos[k] = list(state.pos)
        ori[k] = _quat_wxyz(state.ori)
    return pos, z_rotation(ori, scene.ori0)


def z_rotation(ori: np.ndarray, ori0: np.ndarray) -> np.ndarray:
    """Rotation angle about z of ori * conj(ori0) for arrays of (w, x, y, z) quaternions (rad)."""
    w0, x0, y0, z0 = ori0.T
    w1, x1, y1, z1 = ori.T
    # q = q1 * conj(q0); only w and z are needed for a rotation about z
    w = w1 * w0 + x1 * x0 + y1 * y0 + z1 * z0
    z = -w1 * z0 - x1 * y0 + y1 * x0 + z1 * w0
    return 2.0 * np.arctan2(z, w)
