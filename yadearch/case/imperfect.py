"""The case's imperfections in SI: the amplitudes of its [imperfections] section, the defects drawn
for each joint of its arch and their gap profiles (`model.imperfections`), and what a run folder
records of them (imperfections.csv and a summary for campaign tables)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.errors import CaseError
from yadearch.model import units
from yadearch.model.geometry import ArchGeometry
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
    """The defects drawn for a case's joints and the gap profiles they make."""

    defects: JointDefects
    profiles: GapProfiles
    lengths: np.ndarray  # joint lengths (m)

    def wedge_openings(self) -> tuple[np.ndarray, np.ndarray]:
        """The faces' wedge at each joint's intrados and extrados end (m)."""
        return wedge_openings(self.defects, self.lengths)

    def table(self) -> dict[str, np.ndarray]:
        """imperfections.csv's columns: one row a joint, in mm and mrad."""
        return defects_table(self.defects, self.profiles, self.lengths)

    def summary(self) -> dict[str, float]:
        """A few numbers that describe this draw, for campaign tables (mm, mrad)."""
        d, mm = self.defects, units.to_mm
        edges = np.concatenate([d.left_intrados_edge[1:], d.left_extrados_edge[1:],
                                d.right_intrados_edge[:-1], d.right_extrados_edge[:-1]])
        return {"edge_mean_mm": mm(float(edges.mean())), "edge_max_mm": mm(float(edges.max())),
                "face_angle_rms_mrad": units.to_mrad(float(np.sqrt(np.mean(d.face_angle**2)))),
                "face_bump_rms_mm": mm(float(np.sqrt(np.mean(d.face_bump**2)))),
                "offset_rms_mm": mm(float(np.sqrt(np.mean(d.right_offset[:-1] ** 2)))),
                "largest_gap_mm": mm(float(self.profiles.gap.max()))}


def check_contact_model(contact_model: str) -> None:
    """Only the joint elements represent imperfect faces; CaseError naming the parameter otherwise."""
    if contact_model != "joint":
        raise CaseError(f"numerics.contact_model = {contact_model!r} cannot represent imperfect joint faces; "
                        "use 'joint' or set the [imperfections] amplitudes to 0")


def amplitudes(case: ArchCase) -> ImperfectionAmplitudes:
    """The case's [imperfections] amplitudes in SI."""
    i = case.imperfections
    return ImperfectionAmplitudes(i.edge_shape, units.mm(i.edge_radius_mm), units.mm(i.edge_radius_sd_mm),
                                  units.mrad(i.face_angle_mrad), units.mrad(i.face_angle_sd_mrad),
                                  units.mm(i.face_bump_mm), units.mm(i.face_bump_sd_mm),
                                  units.mm(i.voussoir_offset_mm), units.mm(i.voussoir_offset_sd_mm),
                                  units.mm(i.keystone_offset_mm), units.mrad(i.left_support_angle_mrad),
                                  units.mrad(i.right_support_angle_mrad))


def arch_imperfections(case: ArchCase, geometry: ArchGeometry) -> ArchImperfections | None:
    """The defects of the case's joints drawn from its seed (None: a perfect arch)."""
    amps = amplitudes(case)
    if amps.perfect:
        return None
    lengths = np.array([joint.length for joint in geometry.joints])
    defects = draw_defects(amps, len(lengths), case.imperfections.seed, lengths)
    return ArchImperfections(defects, gap_profiles(defects, lengths), lengths)
