"""Build the YADE scene of an arch case: polyhedral blocks, materials, engines, time step.

Only this module, the contact models (`joint_elements`, `cgal_contacts`, `shear`), `stepping` and
`runner` import YADE. The dry joints are either zero-thickness joint elements evaluated in numpy
("joint", the default) or YADE's CGAL polyhedra contacts with a per-contact shear ("cgal").
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

import __main__
from yadearch.case.config import ArchCase
from yadearch.case.imperfect import ArchImperfections, arch_imperfections, check_contact_model
from yadearch.case.mechanics import ContactStiffness, arch_geometry, contact_stiffness, critical_timestep
from yadearch.dem.cgal_contacts import CgalContacts
from yadearch.dem.joint_elements import JointElementContacts
from yadearch.dem.stepping import close_active
from yadearch.dem.yade_env import import_yade
from yadearch.model import units
from yadearch.model.geometry import ArchGeometry
from yadearch.model.joints import z_rotation
from yadearch.model.passive_fill import SpringTangent

# Poisson ratio given to YADE materials so that Ip2's ks = young*poisson is negligible but not the
# NaN that poisson = 0 produces (0/0 in the harmonic mean).
_NEGLIGIBLE_POISSON = 1e-12
# Name under which the scene's Python callbacks are reachable from PyRunner commands.
CALLBACK_NAME = "_yadearch_scene"
CONTACT_MODELS: dict[str, Callable[..., ContactModel]] = {"joint": JointElementContacts, "cgal": CgalContacts}


class ContactModel(Protocol):
    """What the runner needs from the dry joints of a scene, whichever engines compute them."""

    name: str

    def bind(self, pos0: np.ndarray, ori0: np.ndarray, callback: str) -> list[Any]: ...
    def step(self) -> None: ...
    def joint_contacts(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]: ...
    def joint_slip(self) -> np.ndarray: ...
    def smallest_stiffness(self, turning: np.ndarray | None = None, springs: SpringTangent | None = None) -> float: ...
    def snapshot(self) -> dict: ...
    def restore(self, snapshot: dict) -> None: ...
    def stopped(self) -> None: ...
    def unbalanced(self) -> float: ...


@dataclass
class ArchScene:
    """Handles on a built scene: body ids in geometry order and the undeformed body states."""

    geometry: ArchGeometry
    stiffness: ContactStiffness
    body_ids: list[int]
    pos0: np.ndarray
    ori0: np.ndarray  # quaternions (w, x, y, z)
    contacts: ContactModel
    dt: float
    states: list[Any]  # YADE State objects in geometry order; a restore assigns into them
    newton: Any  # the scene's NewtonIntegrator: its gravity and damping change with the stages
    imperfections: ArchImperfections | None = None  # the joints' drawn defects (None: perfect)

    @property
    def voussoir_states(self) -> list[Any]:
        return self.states[1:-1]

    @property
    def left_support(self) -> int:
        return self.body_ids[0]

    @property
    def right_support(self) -> int:
        return self.body_ids[-1]

    @property
    def voussoir_ids(self) -> list[int]:
        return self.body_ids[1:-1]


def build_scene(case: ArchCase) -> ArchScene:
    """Reset YADE's global scene and fill it with the case's arch: supports fixed, voussoirs planar."""
    geometry = arch_geometry(case)
    stiffness = contact_stiffness(case, geometry)
    dt = case.numerics.timestep_safety * critical_timestep(case, geometry, stiffness)
    imperfections = arch_imperfections(case, geometry)
    return build_block_scene(
        geometry,
        stiffness,
        density=units.density(case.material.density_g_per_cm3),
        gravity=(0.0, -case.loading.gravity_m_per_s2, 0.0),
        damping=case.numerics.damping,
        dt=dt,
        fixed={0, len(geometry.blocks) - 1},
        threads=case.numerics.threads,
        contact_model=case.numerics.contact_model,
        imperfections=imperfections,
    )


def build_block_scene(
    geometry: ArchGeometry,
    stiffness: ContactStiffness,
    density: float,
    gravity: tuple[float, float, float],
    damping: float,
    dt: float,
    fixed: set[int],
    threads: int = 1,
    contact_model: str = "joint",
    imperfections: ArchImperfections | None = None,
) -> ArchScene:
    """Reset YADE's global scene and fill it with `geometry.blocks` (indices in `fixed` do not move
    unless driven; the others move in the x-y plane) and the engines of `contact_model`; only the
    joint elements take the joints' imperfections."""
    if imperfections is not None and not imperfections.perfect_faces:
        check_contact_model(contact_model)
    import_yade(threads)
    from yade import O, polyhedra_utils
    from yade.wrapper import ForceResetter, NewtonIntegrator, PolyhedraMat

    close_active()
    O.reset()
    material = PolyhedraMat(
        young=stiffness.material_young,
        poisson=_NEGLIGIBLE_POISSON,
        frictionAngle=float(np.arctan(stiffness.tan_friction)),
        density=density,
        IsSplitable=False,
    )
    O.materials.append(material)
    body_ids = []
    for index, vertices in enumerate(geometry.blocks):
        body = polyhedra_utils.polyhedra(material, v=[tuple(v) for v in vertices], fixed=index in fixed)
        if index not in fixed:
            body.state.blockedDOFs = "zXY"  # planar motion: no z translation, rotation about z only
        body_ids.append(O.bodies.append(body))

    if imperfections is not None and contact_model == "joint":
        contacts: ContactModel = JointElementContacts(stiffness, geometry, body_ids, imperfections.profiles)
    else:
        contacts = CONTACT_MODELS[contact_model](stiffness, geometry, body_ids)
    setattr(__main__, CALLBACK_NAME, contacts)
    pos0 = np.array([list(O.bodies[i].state.pos) for i in body_ids])
    ori0 = np.array([_quat_wxyz(O.bodies[i].state.ori) for i in body_ids])
    newton = NewtonIntegrator(damping=damping, gravity=gravity)
    O.engines = [ForceResetter(), *contacts.bind(pos0, ori0, CALLBACK_NAME), newton]
    O.dt = dt
    return ArchScene(
        geometry,
        stiffness,
        body_ids,
        pos0,
        ori0,
        contacts,
        dt,
        [O.bodies[i].state for i in body_ids],
        newton,
        imperfections,
    )


def install_before_integrator(callback_name: str, callback: object, engine: Any) -> None:
    """Make `callback` reachable under `callback_name` from PyRunner commands and put its `engine`
    last before the integrator, so that what it sets on the blocks acts in the same step."""
    from yade import O

    import __main__

    setattr(__main__, callback_name, callback)
    engines = list(O.engines)
    engines.insert(len(engines) - 1, engine)
    O.engines = engines


def _quat_wxyz(q: Any) -> list[float]:
    """A minieigen Quaternion (indexed x, y, z, w) as [w, x, y, z]."""
    return [q[3], q[0], q[1], q[2]]


def body_states(scene: ArchScene) -> tuple[np.ndarray, np.ndarray]:
    """Current positions (n, 3) and z-rotations since the start (n,) of all blocks, in geometry order."""
    rows = np.array(
        [(p[0], p[1], p[2], q[3], q[0], q[1], q[2]) for p, q in ((state.pos, state.ori) for state in scene.states)]
    )
    return rows[:, :3], z_rotation(rows[:, 3:], scene.ori0)


def stop_voussoirs(scene: ArchScene) -> None:
    """Zero the voussoirs' velocities: a hold then tests the configuration statically, without kinetic
    energy from the loading that could carry the arch over a barrier it would not cross."""
    from yade import O

    for i in scene.voussoir_ids:
        O.bodies[i].state.vel = (0.0, 0.0, 0.0)
        O.bodies[i].state.angVel = (0.0, 0.0, 0.0)
    scene.contacts.stopped()
