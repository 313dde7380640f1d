"""The atlas's cases (pure): five shapes of one size, six support movements, ring thicknesses from
below the thinnest that stands to t/R 0.25, and joint stiffness from the paper's softest to nearly
rigid; the DEM's subset is named here too, so that the grid and its cheaper check stay one list."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from yadearch.case.config import ArchCase, preset
from yadearch.case.support import TILT_PIVOT_DEPTH_MM
from yadearch.studies.campaigns.grid import RUN_COLUMN
from yadearch.studies.dem_settings import NO_DEM_SETTINGS, with_dem_settings

REFERENCE_RADIUS_MM = 300.0  # every shape's half span (the paper's intrados radius): t/R is over it
SPAN_MM = 2.0 * REFERENCE_RADIUS_MM
RISE_MM = 200.0  # the elliptical and three-centred arches' rise (a third of the span)
SHAPES: dict[str, dict[str, Any]] = {
    "segmental": {},  # the paper's arch: intrados radius 300 mm, embrace 125 deg
    "semicircular": {"embrace_deg": 180.0},
    "pointed": {"shape": "pointed", "span_mm": SPAN_MM, "pointed_radius_over_span": 1.0},
    "elliptical": {"shape": "elliptical", "span_mm": SPAN_MM, "rise_mm": RISE_MM},
    "three_centred": {"shape": "three_centred", "span_mm": SPAN_MM, "rise_mm": RISE_MM},
}


def _translation(direction_deg: float) -> dict[str, Any]:
    return {"support_motion": "translation", "support_direction_deg": direction_deg}


MOVEMENTS: dict[str, dict[str, Any]] = {
    "settlement": _translation(-90.0),
    "spreading": _translation(0.0),
    "closing": _translation(180.0),
    "down_out_45": _translation(-45.0),
    "down_in_135": _translation(-135.0),
    "tilt": {"support_motion": "rotation", "rotation_pivot_dy_mm": TILT_PIVOT_DEPTH_MM},
}
THICKNESS_OVER_RADIUS = (0.08, 0.15, 0.25)  # 0.08 is the paper's; a semicircle needs about 0.11 to stand
KNS_N_PER_MM3 = (0.25, 5.2, 100.0, 10000.0)  # the paper's two sets, then toward rigid joints
DEM_KN_N_PER_MM3 = 5.2  # the DEM's runs take minutes at this stiffness, hours at the stiffest
DEM_THICKNESS_OVER_RADIUS = (0.15, 0.25)
DEM_MOVEMENTS_THICK = ("settlement", "spreading")  # at the thicker ring, beside every movement at 0.15


@dataclass(frozen=True)
class Geometry:
    """One arch and movement of the atlas: what the rigid march solves (kn plays no part in it)."""

    shape: str
    movement: str
    thickness_over_radius: float

    @property
    def thickness_mm(self) -> float:
        return round(self.thickness_over_radius * REFERENCE_RADIUS_MM, 6)

    @property
    def name(self) -> str:
        return f"{self.shape}-{self.movement}-t{self.thickness_mm:g}"

    def overrides(self) -> dict[str, Any]:
        """The case parameters of this arch and movement (bare names, as a campaign table's columns)."""
        return {**SHAPES[self.shape], **MOVEMENTS[self.movement], "thickness_mm": self.thickness_mm}

    def row(self, kn_N_per_mm3: float) -> dict[str, Any]:
        """The campaign row of this arch at one stiffness, named for all three."""
        return {RUN_COLUMN: f"{self.name}-kn{kn_N_per_mm3:g}", **self.overrides(), "kn_N_per_mm3": kn_N_per_mm3}


def geometries() -> list[Geometry]:
    """Every shape x movement x thickness of the atlas."""
    return [
        Geometry(shape, movement, ratio)
        for shape in SHAPES
        for movement in MOVEMENTS
        for ratio in THICKNESS_OVER_RADIUS
    ]


def static_rows() -> list[dict[str, Any]]:
    """The static engine's runs: every geometry at every stiffness."""
    return [g.row(kn) for g in geometries() for kn in KNS_N_PER_MM3]


def dem_rows() -> list[dict[str, Any]]:
    """The DEM's runs: every shape and movement at t/R 0.15, and settlement and spreading at 0.25."""
    chosen = [
        Geometry(shape, movement, ratio)
        for shape in SHAPES
        for ratio in DEM_THICKNESS_OVER_RADIUS
        for movement in MOVEMENTS
        if ratio == DEM_THICKNESS_OVER_RADIUS[0] or movement in DEM_MOVEMENTS_THICK
    ]
    return [g.row(DEM_KN_N_PER_MM3) for g in chosen]


def engine_base(
    engine: str, numerics: Mapping[str, Any], dem_settings: Mapping[str, Any] = NO_DEM_SETTINGS
) -> ArchCase:
    """The base case of one engine's campaign: set 2 with summary-only run folders and `numerics` (bare
    names), the DEM's also with the study's `dem_settings` (the static engine's never)."""
    settings = {"engine": engine, "run_files": "summary", **numerics}
    base = preset("set2").with_overrides({f"numerics.{key}": value for key, value in settings.items()})
    return with_dem_settings(base, dem_settings) if engine == "dem" else base
