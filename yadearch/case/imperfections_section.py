"""The [imperfections] section of a case: the voussoirs' defects, each a mean and a standard deviation."""

from __future__ import annotations

from dataclasses import dataclass, field

from yadearch.case.fields import number_meta


@dataclass
class ImperfectionsConfig:
    """Geometric imperfections of the voussoirs' joint faces, dimensions and assembly (docs/theory.md), each a
    mean and a standard deviation drawn per joint or voussoir from `seed`; all zero = the perfect
    arch. The supports' faces stay perfect and where they were designed."""

    seed: int = field(
        default=0, metadata=number_meta(0, 2**32 - 1, doc="seed of the random draws (one seed, one geometry)")
    )
    edge_shape: str = field(
        default="round",
        metadata={
            "choices": ("round", "chamfer"),
            "doc": "shape of the voussoirs' worn joint edges: 'round' "
            "(a quarter circle of radius edge_radius_mm) or 'chamfer' (a 45 deg cut of that leg)",
        },
    )
    edge_radius_mm: float = field(
        default=0.0,
        metadata=number_meta(
            0,
            1000,
            doc="mean size of the rounding or "
            "chamfer of each intrados and extrados edge of a voussoir's joint faces (mm)",
        ),
    )
    edge_radius_sd_mm: float = field(
        default=0.0,
        metadata=number_meta(
            0, 1000, doc="standard deviation of edge_radius_mm between edges (mm; drawn sizes below 0 count as 0)"
        ),
    )
    face_angle_mrad: float = field(
        default=0.0,
        metadata=number_meta(
            -1000,
            1000,
            doc="mean angle between a "
            "joint's two faces (mrad; > 0: the joint touches at the intrados and "
            "gapes toward the extrados)",
        ),
    )
    face_angle_sd_mrad: float = field(
        default=0.0, metadata=number_meta(0, 1000, doc="standard deviation of face_angle_mrad between joints (mrad)")
    )
    face_bump_mm: float = field(
        default=0.0,
        metadata=number_meta(
            -1000,
            1000,
            doc="mean out-of-flatness of a "
            "joint (mm; > 0: convex faces touching mid-joint with the ends open by "
            "this much, < 0: hollow faces touching at the ends)",
        ),
    )
    face_bump_sd_mm: float = field(
        default=0.0, metadata=number_meta(0, 1000, doc="standard deviation of face_bump_mm between joints (mm)")
    )
    voussoir_offset_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -1000,
                1000,
                doc="mean assembly error of each voussoir: set higher (> 0, toward the extrados) or "
                "lower than its neighbours, its faces bearing on theirs offset along the joints (mm)",
            ),
            "predates": 0.0,
        },
    )
    voussoir_offset_sd_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(0, 1000, doc="standard deviation of voussoir_offset_mm between voussoirs (mm)"),
            "predates": 0.0,
        },
    )
    keystone_offset_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -1000,
                1000,
                doc="the keystone set higher (> 0) or lower, in addition (mm; both middle voussoirs for an even count)",
            ),
            "predates": 0.0,
        },
    )
    left_support_angle_mrad: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -1000,
                1000,
                doc="the left support set askew: its face turned against the first voussoir's (mrad; "
                "> 0: the springing joint touches at the intrados and gapes toward the extrados)",
            ),
            "predates": 0.0,
        },
    )
    right_support_angle_mrad: float = field(
        default=0.0,
        metadata={
            **number_meta(-1000, 1000, doc="the same for the right support against the last voussoir (mrad)"),
            "predates": 0.0,
        },
    )
    voussoir_length_sd_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                0,
                1000,
                doc="standard deviation of the voussoirs' lengths along the arch (mm; taken about the "
                "set's mean, which the supports' spacing absorbs: each joint moves by the errors on its left)",
            ),
            "predates": 0.0,
        },
    )
    voussoir_thickness_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(
                -1000,
                1000,
                doc="mean error of the voussoirs' thickness (mm; > 0 thicker: the intrados stays on "
                "the centering and the extrados stands out)",
            ),
            "predates": 0.0,
        },
    )
    voussoir_thickness_sd_mm: float = field(
        default=0.0,
        metadata={
            **number_meta(0, 1000, doc="standard deviation of voussoir_thickness_mm between voussoirs (mm)"),
            "predates": 0.0,
        },
    )
