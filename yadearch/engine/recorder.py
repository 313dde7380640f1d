"""What a run records while it runs (YADE layer): time-series rows, per-interface rows, snapshots of
the block positions, and the largest mobilised friction and slip of the equilibrium states."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from yadearch.case.config import NumericsConfig
from yadearch.engine.driver import SupportDriver
from yadearch.engine.scene import ArchScene, body_states
from yadearch.errors import RunFailedError
from yadearch.model import units
from yadearch.model.hinges import Hinge, hinge_rotation, hinges_at
from yadearch.model.joints import joint_states
from yadearch.results.rundir import STIFFNESS_COLUMN


@dataclass
class Records:
    """Everything the run folder gets: time series rows, per-interface rows, events, snapshots."""

    series: list[dict] = field(default_factory=list)
    joints: list[dict] = field(default_factory=list)
    events: list[str] = field(default_factory=list)
    snapshots: dict[str, dict] = field(default_factory=dict)


class Recorder:
    """Reads the live scene into `records`; `stage` labels every row (docs/numerics.md lists them)."""

    def __init__(self, scene: ArchScene, driver: SupportDriver, numerics: NumericsConfig):
        self.scene = scene
        self.driver = driver
        self.num = numerics
        self.records = Records()
        self.stage = "selfweight"
        self.friction: dict = {}
        self._last_series_iter = -10**9

    def voussoir_speeds(self) -> np.ndarray:
        return np.array([state.vel.norm() for state in self.scene.voussoir_states])

    def reactions(self) -> tuple[np.ndarray, np.ndarray]:
        """Forces the left and right supports exert on the arch (N)."""
        from yade import O

        left = -np.array(O.forces.f(self.scene.left_support))[:2]
        right = -np.array(O.forces.f(self.scene.right_support))[:2]
        return left, right

    def series(self, force: bool = False, stability: bool = False) -> None:
        """Append a time-series row (every `series_every_steps` steps, or now with `force`); with
        `stability`, the state's smallest tangent stiffness too (an equilibrium state's row)."""
        from yade import O, utils

        if not force and O.iter - self._last_series_iter < self.num.series_every_steps:
            return
        self._last_series_iter = O.iter
        left, right = self.reactions()
        crown = self.scene.geometry.crown_voussoir
        crown_id = self.scene.body_ids[crown]
        crown_disp = np.array(O.bodies[crown_id].state.pos) - self.scene.pos0[crown]
        self.records.series.append({
            "stage": self.stage, "step": O.iter, "time_s": O.time,
            "delta_mm": units.to_mm(self.driver.displacement()),
            "left_Rx_N": left[0], "left_Ry_N": left[1], "right_Rx_N": right[0], "right_Ry_N": right[1],
            "crown_dx_mm": units.to_mm(crown_disp[0]), "crown_dy_mm": units.to_mm(crown_disp[1]),
            "kinetic_J": utils.kineticEnergy(), "unbalanced": self.scene.contacts.unbalanced(),
            "max_block_speed_mm_per_s": units.to_mm(float(self.voussoir_speeds().max())),
        })
        if stability:
            self.records.series[-1][STIFFNESS_COLUMN] = self.scene.contacts.smallest_stiffness()

    def joint_snapshot(self) -> tuple[dict, list[Hinge]]:
        """Per-interface state now, and its hinges."""
        from yade import O

        pos, rot = body_states(self.scene)
        if not np.all(np.isfinite(pos)):
            raise RunFailedError(f"NaN in block positions at step {O.iter}")
        points, normal, shear = self.scene.contacts.joint_contacts()
        tan_friction = self.scene.stiffness.tan_friction
        friction_use = np.divide(np.abs(shear), normal * tan_friction, out=np.zeros_like(shear),
                                 where=normal > 0.0)
        js = joint_states(self.scene.geometry, self.scene.pos0, pos, rot, points)
        if self.scene.imperfections is not None:  # the real faces' openings: a wedge closed flat is closed
            wedge_intrados, wedge_extrados = self.scene.imperfections.wedge_openings()
            js = replace(js, opening_intrados=js.opening_intrados + wedge_intrados,
                         opening_extrados=js.opening_extrados + wedge_extrados)
        rotation = hinge_rotation(js.opening_intrados, js.opening_extrados, self.scene.geometry.thickness)
        hinges = hinges_at(rotation, self.num.hinge_rotation_mrad * 1e-3)
        return {"pos": pos, "rot": rot, "js": js, "normal": normal, "shear": shear,
                "friction_use": friction_use, "slip": self.scene.contacts.joint_slip(),
                "hinge_rotation": rotation}, hinges

    def joints(self, label: str | None = None) -> list[Hinge]:
        """Record every interface now (and, with a `label`, the block positions as a snapshot)."""
        snap, hinges = self.joint_snapshot()
        self.write_joints(snap, hinges, label)
        return hinges

    def write_joints(self, snap: dict, hinges: list[Hinge], label: str | None = None) -> None:
        """Append the rows of joints.csv for a `joint_snapshot`, and its snapshot under `label`."""
        from yade import O

        js = snap["js"]
        delta_mm = units.to_mm(self.driver.displacement())
        common = {"stage": self.stage, "step": O.iter, "delta_mm": delta_mm}
        columns = zip(js.rotation.tolist(), units.to_mm(js.opening_intrados).tolist(),
                      units.to_mm(js.opening_extrados).tolist(), js.force_position.tolist(),
                      snap["normal"].tolist(), snap["shear"].tolist(), snap["friction_use"].tolist(),
                      units.to_mm(snap["slip"]).tolist())
        self.records.joints.extend(
            {**common, "interface": k + 1, "rotation_rad": rotation, "opening_intrados_mm": intrados,
             "opening_extrados_mm": extrados, "force_position": position, "normal_force_N": normal,
             "shear_force_N": shear, "friction_use": use, "slip_mm": slip}
            for k, (rotation, intrados, extrados, position, normal, shear, use, slip)
            in enumerate(columns))
        if label:
            self.records.snapshots[label] = {
                "delta_mm": delta_mm, "step": O.iter,
                "pos_m": snap["pos"][:, :2].tolist(), "rot_rad": snap["rot"].tolist(),
                "hinges": [h.to_json() for h in hinges],
            }

    def track_friction(self, snap: dict) -> None:
        """Keep the largest mobilised friction |T| / (N tan phi) and the largest accumulated slip
        met in the equilibrium states, with their interfaces: friction can move du only where
        some joint slides."""
        use, slip = snap["friction_use"], snap["slip"]
        k = int(np.argmax(use))
        if use[k] > self.friction.get("max_friction_use", -1.0):
            self.friction.update(max_friction_use=float(use[k]), friction_interface=k + 1,
                                 friction_delta_mm=units.to_mm(self.driver.displacement()))
        finite = np.nan_to_num(slip, nan=0.0)
        j = int(np.argmax(finite))
        self.friction.update(max_slip_mm=units.to_mm(float(slip[j])), slip_interface=j + 1)
