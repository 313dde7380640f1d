"""The reference study's numbers, copied into the project so that it stands on its own.

Source: "Effect of geometrical imperfections on the response of dry-joint masonry arches to support
settlements" (1:10 segmental arch, 55 voussoirs; FE micro-model in DIANA), sections 2-4 and Table 1;
its authors, venue and DOI are not in the project's copy of it. The same group's journal paper on the
1:10 arch with one voussoir set: C. Ferrero, M. Rossi, P. Roca, C. Calderini, "Experimental and
numerical analysis of a scaled dry-joint arch on moving supports", International Journal of Masonry
Research and Innovation 6(4) (2021) 405-421, doi:10.1504/IJMRI.2021.118818.
Interfaces are numbered 1..56 from the left support; hinge lists hold every interface the paper names
(a spread hinge such as "29-30-31-32" lists all four).
"""

from __future__ import annotations

from typing import Any

PAPER = "Effect of geometrical imperfections on the response of dry-joint masonry arches to support settlements"

GEOMETRY = {
    "n_voussoirs": 55,
    "embrace_deg": 125.0,
    "internal_radius_mm": 300.0,
    "thickness_mm": 24.0,
    "depth_mm": 120.0,
    "net_span_mm": 533.0,
}
MATERIAL = {"density_g_per_cm3": 1.64, "friction_deg": 41.2, "young_MPa": 941.0, "poisson": 0.2}
KS_OVER_KN = 0.5
KN_SENSITIVITY_RANGE_N_PER_MM3 = (0.1, 100.0)  # paper Fig. 8

SETS: dict[str, dict[str, Any]] = {
    "set1": {
        "description": "1st set: manually milled moulds, more imperfections",
        "kn_N_per_mm3": 0.25,
        "experimental": {"hinge_A": [13], "hinge_B": [32], "hinge_C": [56], "du_mm": 48.9},
        "numerical": {"hinge_A": [11, 12], "hinge_B": [29, 30, 31, 32], "hinge_C": [56], "du_mm": 48.8},
        "sequence_at_collapse": "E-I-E-E (D at the left support, extrados)",
    },
    "set2": {
        "description": "2nd set: CNC-machined moulds, accurate voussoirs",
        "kn_N_per_mm3": 5.2,
        "experimental": {"hinge_A": [9], "hinge_B": [31], "hinge_C": [56], "du_mm": 91.5},
        "numerical": {"hinge_A": [9], "hinge_B": [30], "hinge_C": [56], "du_mm": 91.8},
        "sequence_at_collapse": "E-I-E-E (D at the left support, extrados)",
    },
}
HINGE_SIDES = {"hinge_A": "I", "hinge_B": "E", "hinge_C": "E", "hinge_D": "E"}
HINGE_D_INTERFACE = 1  # both sets: the fourth hinge opens at the left support, extrados

# Where the methods come from: a result lists the keys of what it used (`references_for`), the report
# prints them.
REFERENCES: dict[str, str] = {
    "paper": f"{PAPER} (the reference study: the arch, its material, both sets' kn and Table 1).",
    "yade": "V. Šmilauer et al., Yade Documentation, 3rd ed., The Yade Project, 2021 (the DEM engine).",
    "gilbert": "M. Gilbert, C. Casapulla, H. M. Ahmed, Limit analysis of masonry block structures with "
    "non-associative frictional joints using linear programming, Computers & Structures 84 "
    "(2006) 873-887 (the rigid-block equilibrium LP).",
    "portioli": "F. Portioli, L. Cascini, Large displacement analysis of dry-jointed masonry structures "
    "subjected to settlements using rigid block modelling, Engineering Structures 148 (2017) "
    "485-496 (the incremental rigid-block analysis of settlements).",
}


def references_for(dem: bool = True, limit_analysis: bool = False, paper_case: bool = False) -> list[str]:
    """The references behind a result: the DEM engine, the rigid-block analysis, the reference study."""
    keys = (
        (["paper"] if paper_case else [])
        + (["yade"] if dem else [])
        + (["gilbert", "portioli"] if limit_analysis else [])
    )
    return [REFERENCES[key] for key in keys]
