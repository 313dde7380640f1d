"""The campaigns of the imperfection study (`scripts/imperfection_study.py`, docs/validation-imperfections.md):
each kind of defect at its amplitudes and seeds on the accurate arch, the stiff-joint control, and the
final and matching campaigns at the level that brings the median du to set 1's experiment."""

from __future__ import annotations

from yadearch.studies.imperfections.matching import Study

BASE_PRESET = "set2"  # accurate voussoirs: the CNC set's kn
SEED = 1
STIFF_KN_N_PER_MM3 = 100.0
STIFF_PERFECT_DU_MM = 109.09  # reports/stiff/kn100: the perfect arch at kn 100
FINAL = Study(
    "final", "faces not flat, at the level that matches set 1 (the final campaign)", "face_bump_sd_mm", (0.18,), 200
)
MATCH = Study(
    "match",
    "faces not flat, above the final level, on the final campaign's first seeds",
    "face_bump_sd_mm",
    (0.22,),
    40,
)
STUDIES = (
    Study("edge", "rounded edges, every edge alike", "edge_radius_mm", (1.0, 2.0, 3.0, 4.0, 6.0), 1),
    Study("angle", "faces not parallel, random per joint (mean 0)", "face_angle_sd_mrad", (1.0, 2.0, 4.0, 8.0), 3),
    Study("bump", "faces not flat, random per joint (mean 0)", "face_bump_sd_mm", (0.02, 0.05, 0.1, 0.2), 3),
    Study("keystone", "keystone set lower", "keystone_offset_mm", (-0.25, -0.5, -1.0, -2.0), 1),
    Study(
        "offset",
        "voussoirs set off their neighbours, random per voussoir (mean 0)",
        "voussoir_offset_sd_mm",
        (0.1, 0.2, 0.5),
        3,
    ),
    Study(
        "support",
        "moving support set askew (gaping toward the extrados)",
        "right_support_angle_mrad",
        (2.0, 5.0, 10.0, 20.0),
        1,
    ),
    Study(
        "length",
        "voussoirs longer or shorter along the arch, random per voussoir (about the set's mean)",
        "voussoir_length_sd_mm",
        (0.5,),
        3,
    ),
    Study(
        "thickness", "voussoirs thicker or thinner, random per voussoir (mean 0)", "voussoir_thickness_sd_mm", (1.0,), 3
    ),
    Study(
        "stiff",
        f"faces not flat on stiff joints (kn {STIFF_KN_N_PER_MM3:g} N/mm³, the stiff limit; the perfect "
        f"arch gives {STIFF_PERFECT_DU_MM} mm)",
        "face_bump_sd_mm",
        (0.18,),
        2,
        {"kn_N_per_mm3": STIFF_KN_N_PER_MM3},
        STIFF_PERFECT_DU_MM,
    ),
    FINAL,
    MATCH,
)
