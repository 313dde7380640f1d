"""The rows joints.csv gets for one state of the arch, and that state's hinges, from the block poses
and the joint forces (pure numpy): one function for both engines, so their folders read alike."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from yadearch.case.imperfect import ArchImperfections
from yadearch.model import units
from yadearch.model.geometry import ArchGeometry
from yadearch.model.hinges import Hinge, hinge_rotation, hinges_at
from yadearch.model.joints import joint_states


def joint_snapshot(
    geometry: ArchGeometry,
    pos0: np.ndarray,
    pos: np.ndarray,
    rot: np.ndarray,
    points: np.ndarray,
    normal: np.ndarray,
    shear: np.ndarray,
    slip: np.ndarray,
    tan_friction: float,
    imperfections: ArchImperfections | None,
    hinge_threshold: float,
) -> tuple[dict[str, Any], list[Hinge]]:
    """Per-interface state (kinematics, forces, friction use, slip, hinge rotation) of blocks at
    `pos`, `rot` with joint contact `points`, forces and accumulated `slip`, and its hinges (rad)."""
    friction_use = mobilised_friction(normal, shear, tan_friction)
    js = joint_states(geometry, pos0, pos, rot, points)
    if imperfections is not None:  # the real faces' openings: a wedge closed flat is closed
        wedge_intrados, wedge_extrados = imperfections.wedge_openings()
        js = replace(
            js,
            opening_intrados=js.opening_intrados + wedge_intrados,
            opening_extrados=js.opening_extrados + wedge_extrados,
        )
    rotation = hinge_rotation(js.opening_intrados, js.opening_extrados, geometry.thickness)
    hinges = hinges_at(rotation, hinge_threshold)
    return {
        "pos": pos,
        "rot": rot,
        "js": js,
        "normal": normal,
        "shear": shear,
        "friction_use": friction_use,
        "slip": slip,
        "hinge_rotation": rotation,
    }, hinges


def mobilised_friction(normal: np.ndarray, shear: np.ndarray, tan_friction: float) -> np.ndarray:
    """Each joint's friction use |T| / (N tan phi) (0 where it carries no normal force)."""
    return np.divide(np.abs(shear), normal * tan_friction, out=np.zeros_like(shear), where=normal > 0.0)


def joint_rows(snap: dict[str, Any], common: dict[str, Any]) -> list[dict[str, Any]]:
    """joints.csv's rows of a `joint_snapshot`, each starting with the `common` columns (stage, step,
    delta_mm)."""
    js = snap["js"]
    columns = zip(
        js.rotation.tolist(),
        units.to_mm(js.opening_intrados).tolist(),
        units.to_mm(js.opening_extrados).tolist(),
        js.force_position.tolist(),
        snap["normal"].tolist(),
        snap["shear"].tolist(),
        snap["friction_use"].tolist(),
        units.to_mm(snap["slip"]).tolist(),
    )
    return [
        {
            **common,
            "interface": k + 1,
            "rotation_rad": rotation,
            "opening_intrados_mm": intrados,
            "opening_extrados_mm": extrados,
            "force_position": position,
            "normal_force_N": normal,
            "shear_force_N": shear,
            "friction_use": use,
            "slip_mm": slip,
        }
        for k, (rotation, intrados, extrados, position, normal, shear, use, slip) in enumerate(columns)
    ]


def snapshot_entry(snap: dict[str, Any], hinges: list[Hinge], delta_mm: float, step: int) -> dict[str, Any]:
    """snapshots.json's entry for a `joint_snapshot`: block positions and rotations, hinges."""
    return {
        "delta_mm": delta_mm,
        "step": step,
        "pos_m": snap["pos"][:, :2].tolist(),
        "rot_rad": snap["rot"].tolist(),
        "hinges": [h.to_json() for h in hinges],
    }


def friction_extremes(friction: dict[str, Any], snap: dict[str, Any], delta_mm: float) -> None:
    """Update `friction` with the largest mobilised friction |T| / (N tan phi) and the largest
    accumulated slip of the state `snap`, with their interfaces (summary.json's `friction`)."""
    use, slip = snap["friction_use"], snap["slip"]
    k = int(np.argmax(use))
    if use[k] > friction.get("max_friction_use", -1.0):
        friction.update(max_friction_use=float(use[k]), friction_interface=k + 1, friction_delta_mm=delta_mm)
    finite = np.nan_to_num(slip, nan=0.0)
    j = int(np.argmax(finite))
    friction.update(max_slip_mm=units.to_mm(float(slip[j])), slip_interface=j + 1)
