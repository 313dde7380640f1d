"""The case's imperfections in SI: the amplitudes of its [imperfections] section, the voussoirs'
dimension errors (`model.dimensions`), the defects drawn for each joint of its arch and their gap
profiles (`model.imperfections`), and what a run folder records of them (imperfections.csv and a
summary for campaign tables)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.dimensions import DimensionErrors, draw_dimension_errors, with_dimension_errors
from yadearch.model.geometry import QUADRILATERAL_PRISM, ArchGeometry
from yadearch.model.imperfections import (
    GapProfiles,
    ImperfectionAmplitudes,
    JointDefects,
    defects_table,
    draw_defects,
    gap_profiles,
    wedge_openings,
)


@dataclass(frozen=True)
class ArchImperfections:
    """The defects drawn for a case's joints and the gap profiles they make, and the voussoirs'
    dimension errors that made those joints."""

    defects: JointDefects
    profiles: GapProfiles
    lengths: np.ndarray  # joint lengths (m)
    dimensions: DimensionErrors | None = None

    @property
    def perfect_faces(self) -> bool:
        """Whether every joint's faces are flat, parallel, unworn and aligned (only dimension errors)."""
        return not (
            self.profiles.imperfect.any() or self.profiles.left_offset.any() or self.profiles.right_offset.any()
        )

    def wedge_openings(self) -> tuple[np.ndarray, np.ndarray]:
        """The faces' wedge at each joint's intrados and extrados end (m)."""
        return wedge_openings(self.defects, self.lengths)

    def table(self) -> dict[str, np.ndarray]:
        """imperfections.csv's columns: one row a joint, in mm and mrad; the voussoir columns hold
        the voussoir on the joint's right (empty on the last joint)."""
        table = defects_table(self.defects, self.profiles, self.lengths)
        if self.dimensions is not None:
            table["joint_shift_mm"] = units.to_mm(self.dimensions.joint_shift)
            table["joint_length_mm"] = units.to_mm(self.lengths)
            table["right_voussoir_length_error_mm"] = units.to_mm(np.append(self.dimensions.length, np.nan))
            table["right_voussoir_thickness_error_mm"] = units.to_mm(np.append(self.dimensions.thickness, np.nan))
        return table

    def summary(self) -> dict[str, float]:
        """A few numbers that describe this draw, for campaign tables (mm, mrad)."""
        d, mm = self.defects, units.to_mm
        edges = np.concatenate(
            [d.left_intrados_edge[1:], d.left_extrados_edge[1:], d.right_intrados_edge[:-1], d.right_extrados_edge[:-1]]
        )
        return {
            "edge_mean_mm": mm(float(edges.mean())),
            "edge_max_mm": mm(float(edges.max())),
            "face_angle_rms_mrad": units.to_mrad(float(np.sqrt(np.mean(d.face_angle**2)))),
            "face_bump_rms_mm": mm(float(np.sqrt(np.mean(d.face_bump**2)))),
            "offset_rms_mm": mm(float(np.sqrt(np.mean(d.right_offset[:-1] ** 2)))),
            "largest_gap_mm": mm(float(self.profiles.gap.max())),
            **self._dimension_summary(),
        }

    def _dimension_summary(self) -> dict[str, float]:
        if self.dimensions is None:
            return {}
        d = self.dimensions
        return {
            "length_error_rms_mm": units.to_mm(float(np.sqrt(np.mean(d.length**2)))),
            "thickness_error_mean_mm": units.to_mm(float(d.thickness.mean())),
            "thickness_error_rms_mm": units.to_mm(float(np.sqrt(np.mean(d.thickness**2)))),
            "joint_shift_max_mm": units.to_mm(float(np.abs(d.joint_shift).max())),
        }


def check_contact_model(contact_model: str) -> None:
    """Only the joint elements represent imperfect faces; CaseError naming the parameter otherwise."""
    if contact_model != "joint":
        raise CaseError(
            f"numerics.contact_model = {contact_model!r} cannot represent imperfect joint faces; "
            "use 'joint' or set the [imperfections] amplitudes to 0"
        )


def amplitudes(case: ArchCase) -> ImperfectionAmplitudes:
    """The case's [imperfections] amplitudes in SI."""
    i = case.imperfections
    return ImperfectionAmplitudes(
        i.edge_shape,
        units.mm(i.edge_radius_mm),
        units.mm(i.edge_radius_sd_mm),
        units.mrad(i.face_angle_mrad),
        units.mrad(i.face_angle_sd_mrad),
        units.mm(i.face_bump_mm),
        units.mm(i.face_bump_sd_mm),
        units.mm(i.voussoir_offset_mm),
        units.mm(i.voussoir_offset_sd_mm),
        units.mm(i.keystone_offset_mm),
        units.mrad(i.left_support_angle_mrad),
        units.mrad(i.right_support_angle_mrad),
        units.mm(i.voussoir_length_sd_mm),
        units.mm(i.voussoir_thickness_mm),
        units.mm(i.voussoir_thickness_sd_mm),
    )


def dimension_errors(case: ArchCase, n_voussoirs: int) -> DimensionErrors | None:
    """The voussoirs' dimension errors drawn from the case's seed (None: voussoirs as designed)."""
    amps = amplitudes(case)
    if amps.perfect_dimensions:
        return None
    return draw_dimension_errors(
        n_voussoirs,
        case.imperfections.seed,
        amps.voussoir_length_sd,
        amps.voussoir_thickness,
        amps.voussoir_thickness_sd,
    )


def imperfect_geometry(case: ArchCase, geometry: ArchGeometry) -> ArchGeometry:
    """The designed arch `geometry` rebuilt from the case's imperfect voussoirs (itself if they have
    no dimension error); CaseError naming the parameters if the errors break the arch."""
    errors = dimension_errors(case, geometry.n_voussoirs)
    if errors is None:
        return geometry
    g = case.geometry
    polygons = [k for k, block in enumerate(geometry.voussoirs, start=1) if len(block) != QUADRILATERAL_PRISM]
    if polygons:
        raise CaseError(
            f"imperfections.voussoir_length_sd_mm, voussoir_thickness_mm and voussoir_thickness_sd_mm must be 0 "
            f"for voussoirs of more than four corners (voussoir {polygons[0]}, geometry.extrados_points_mm or "
            "intrados_points_mm): a measured polygon is the voussoir as it is"
        )
    if g.shape == "pointed" and g.n_voussoirs % 2 == 0 and case.imperfections.voussoir_length_sd_mm > 0:
        raise CaseError(
            f"imperfections.voussoir_length_sd_mm = {case.imperfections.voussoir_length_sd_mm:g} "
            f"must be 0 for a pointed arch with an even geometry.n_voussoirs ({g.n_voussoirs}): "
            "its crown joint sits on the apex, which a joint moved along the arch would cut"
        )
    try:
        return with_dimension_errors(geometry, errors)
    except ValueError as exc:
        i = case.imperfections
        raise CaseError(
            f"imperfections.voussoir_length_sd_mm = {i.voussoir_length_sd_mm:g}, voussoir_thickness_mm = "
            f"{i.voussoir_thickness_mm:g} and voussoir_thickness_sd_mm = {i.voussoir_thickness_sd_mm:g} "
            f"are too large for this arch (seed {i.seed}): {exc}"
        ) from None


def arch_imperfections(case: ArchCase, geometry: ArchGeometry) -> ArchImperfections | None:
    """The defects of the case's joints drawn from its seed (None: a perfect arch)."""
    amps = amplitudes(case)
    if amps.perfect:
        return None
    lengths = np.array([joint.length for joint in geometry.joints])
    defects = draw_defects(amps, len(lengths), case.imperfections.seed, lengths)
    return ArchImperfections(
        defects, gap_profiles(defects, lengths), lengths, dimension_errors(case, geometry.n_voussoirs)
    )
