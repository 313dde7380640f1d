"""The support movement a case describes, in SI (`model.movement`), with its errors as one line."""

from __future__ import annotations

import math

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.geometry import ArchGeometry
from yadearch.model.movement import Movement, support_movement

MOVEMENT_KEY = "movement"  # --set movement=NAME, a table's column: a named movement (MOVEMENT_PRESETS)


def case_movement(case: ArchCase, geometry: ArchGeometry) -> Movement:
    """The movement of `case`'s supports along its path, for the scene's driver and the limit analysis."""
    loading = case.loading
    path = np.array([[units.mm(dx), units.mm(dy), units.mrad(turn)] for dx, dy, turn in loading.path_mm_mrad])
    try:
        return support_movement(
            geometry,
            loading.moving_support,
            loading.support_motion,
            loading.support_direction_deg,
            (units.mm(loading.rotation_pivot_dx_mm), units.mm(loading.rotation_pivot_dy_mm)),
            loading.rotation_sense,
            path.reshape(-1, 3),
        )
    except ValueError as exc:
        detail = (
            f"path_mm_mrad {loading.path_mm_mrad}"
            if loading.support_motion == "path"
            else f"rotation_pivot_dx_mm {loading.rotation_pivot_dx_mm}, "
            f"rotation_pivot_dy_mm {loading.rotation_pivot_dy_mm}"
        )
        raise CaseError(f"loading: {exc} ({detail:.120})") from None


def path_end_mm(case: ArchCase, movement: Movement) -> float:
    """Where a run stops without collapse (mm along the path): max_support_displacement_mm, or the end of a
    shorter prescribed path."""
    return min(case.loading.max_support_displacement_mm, units.to_mm(movement.length))


def support_acceleration_mm_per_s2(case: ArchCase, movement: Movement) -> float:
    """The acceleration of the support along its path (mm/s^2): the case's, lowered so that its
    horizontal component stays within `support_horizontal_acceleration_mm_per_s2` (a horizontal
    jolt loads the arch like a ground acceleration; docs/numerics.md); 0 = instantaneous."""
    num = case.numerics
    return capped_acceleration(
        num.support_acceleration_mm_per_s2, num.support_horizontal_acceleration_mm_per_s2, movement.horizontal_share
    )


def _loading(
    moving_support: str,
    motion: str,
    direction_deg: float = -90.0,
    pivot_dy_mm: float = 0.0,
    path: list[list[float]] | None = None,
) -> dict:
    return {
        "loading.moving_support": moving_support,
        "loading.support_motion": motion,
        "loading.support_direction_deg": direction_deg,
        "loading.rotation_pivot_dx_mm": 0.0,
        "loading.rotation_pivot_dy_mm": pivot_dy_mm,
        "loading.rotation_sense": "clockwise",
        "loading.path_mm_mrad": path or [],
    }


SETTLE_THEN_SPREAD_MM_MRAD = [[0.0, -20.0, 0.0], [60.0, -20.0, 0.0]]  # 20 mm down, then 60 mm outward
TILT_PIVOT_DEPTH_MM = -100.0  # `abutment_tilt`: the pivot 100 mm below the springing's intrados point
MOVEMENT_PRESETS: dict[str, dict] = {
    "settlement": _loading("right", "translation", -90.0),
    "spreading": _loading("right", "translation", 0.0),
    "closing": _loading("right", "translation", 180.0),
    "inclined": _loading("right", "translation", -45.0),  # down and outward at 45 degrees
    "symmetric_spreading": _loading("both", "translation", 0.0),
    "abutment_tilt": _loading("right", "rotation", pivot_dy_mm=TILT_PIVOT_DEPTH_MM),  # springing out and down
    # a pier that settles, then leans outward as its foundation spreads (a prescribed path)
    "settle_then_spread": _loading("right", "path", path=SETTLE_THEN_SPREAD_MM_MRAD),
}


def movement_overrides(name: str) -> dict:
    """The [loading] parameters of a named movement (`--set movement=NAME`, `MOVEMENT_PRESETS`)."""
    if name not in MOVEMENT_PRESETS:
        raise CaseError(f"movement must be one of {', '.join(MOVEMENT_PRESETS)}, got {name!r}")
    return dict(MOVEMENT_PRESETS[name])


def capped_acceleration(accel: float, horizontal_cap: float, horizontal_share: float) -> float:
    """The support's acceleration along its path (mm/s^2, 0 = instantaneous) lowered so that its
    horizontal component, `horizontal_share` of it, stays within `horizontal_cap` (0 = no cap)."""
    if horizontal_cap <= 0.0 or horizontal_share * (accel if accel > 0.0 else math.inf) <= horizontal_cap:
        return accel
    return horizontal_cap / horizontal_share
