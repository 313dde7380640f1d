"""The static model's word on a DEM state (YADE layer): how far Newton's method on the same blocks and
joints (`solve.newton`), from the blocks' poses and the joints' shear forces, moves them to a stable
equilibrium, and how that equilibrium moves with the support. A hold's verdict rests on speeds and an
unbalanced-force ratio, which a state near the end of a folded branch also passes; this distance tells
an equilibrium from such a near-equilibrium (docs/numerics.md, "Collapse")."""

from __future__ import annotations

import math

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.dem.joint_elements import JointElementContacts
from yadearch.dem.live_arch import JOINT_CONTACTS
from yadearch.dem.scene import ArchScene, body_states
from yadearch.model.joint_tangent import BLOCK_DOFS
from yadearch.solve.newton import Equilibrium
from yadearch.solve.prediction import tangent_prediction
from yadearch.solve.stages import Verdict
from yadearch.solve.static_path import StaticLoading

SLOPE_STEP = 1e-6  # support move (m) over which the one-state prediction, linear in it, gives the branch's slope


class StaticCheck:
    """The static model of a DEM scene's case, built once: the distance of the scene's state to its stable
    equilibria at the support's present displacement and the live load the scene carries, and their slope."""

    def __init__(self, case: ArchCase, scene: ArchScene):
        self.loading = StaticLoading.of(case)
        self.scene = scene

    @classmethod
    def of(cls, case: ArchCase, scene: ArchScene) -> StaticCheck | None:
        """The check of `scene`, or None where the static model is not the scene's: CGAL contacts (the
        blocks' overlap, not the joint law), or joints the static engine's banded tangent does not take."""
        if case.numerics.contact_model != JOINT_CONTACTS:
            return None
        try:
            return cls(case, scene)
        except ValueError:
            return None

    def distance(self, delta: float, multiplier: float = 0.0) -> float:
        """The largest block move (m) from the scene's state to the stable equilibrium Newton finds with
        the support at `delta` (m) and the live load at `multiplier`, or where Newton fails, the static
        descent (the hold's implicit analogue); math.inf where neither ends in a stable equilibrium."""
        found = self.equilibrium(delta, multiplier)
        return found.moved if found is not None else math.inf

    def scene_u(self) -> np.ndarray:
        """The scene's blocks as the static model's state vector (x, y, turn x thickness a block)."""
        positions, rotations = body_states(self.scene)
        return np.column_stack([positions[:, :2], rotations * self.loading.arch.length]).ravel()

    def equilibrium(self, delta: float, multiplier: float = 0.0) -> Equilibrium | None:
        """The stable equilibrium of the static model that the scene's state sits in (`distance`'s), None
        where neither Newton nor the descent from it ends in one."""
        loading = self.loading
        u0 = self.scene_u()
        placed = loading.place(u0, delta)
        contacts = self.scene.contacts
        assert isinstance(contacts, JointElementContacts)  # `of` checks the contact model
        shear, springs = contacts.shear.copy(), contacts.fill_springs
        found = loading.solver.newton(placed, u0, shear, multiplier=multiplier, springs=springs)
        if found is None:
            found = loading.solver.descend(placed, u0, shear, loading.runaway, multiplier=multiplier, springs=springs)
            if found.verdict != Verdict.STABLE:
                return None
        return found if found.stable() else None

    def support_slope(self, found: Equilibrium, delta: float, multiplier: float) -> np.ndarray | None:
        """How the voussoirs' centroids (n, 3) move per metre of the support's path from the stable
        equilibrium `found` at `delta` with the live load held at `multiplier` (the static engine's
        prediction from one state, `solve.prediction.tangent_prediction`; x and y), None where its tangent
        is singular."""
        shear = found.joints.forces.shear_force
        try:
            ahead = tangent_prediction(
                self.loading, found.u, delta, shear, found.springs, delta + SLOPE_STEP, held=multiplier
            )
        except (np.linalg.LinAlgError, ValueError):
            return None
        return centroid_rates((ahead - found.u) / SLOPE_STEP)


def centroid_rows(u: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """`rows` (n, 3: the voussoirs' centroids) with x and y from the state vector `u` (the supports too)."""
    rows[:, 0:2] = u.reshape(-1, BLOCK_DOFS)[1:-1, 0:2]
    return rows


def centroid_rates(rate: np.ndarray) -> np.ndarray:
    """How the voussoirs' centroids (n, 3) move for the state vector's rate `rate` (x and y; z zero)."""
    return centroid_rows(rate, np.zeros((len(rate) // BLOCK_DOFS - 2, 3)))
