"""reports/loads: the sections that set the rigid-block LP beside published results for the
semicircular arch (`studies.loads.published`): closed forms of friction, a point load's collapse."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.markdown import markdown_table
from yadearch.studies.loads.published import (
    N_VOUSSOIRS,
    POINT_LOAD_DENSITY_G_PER_CM3,
    POINT_LOAD_DEPTH_MM,
    POINT_LOAD_JOINT,
    POINT_LOAD_RADIUS_MM,
    POINT_LOAD_T_OVER_R,
    POINT_LOAD_VOUSSOIRS,
)
from yadearch.studies.loads.rigid import SEMICIRCLE_RADIUS_MM


def _value(value: float | None, digits: int) -> str:
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) else f"{value:.{digits}f}"


def published_markdown(table: pd.DataFrame) -> str:
    """The table of `published.friction_table` with its sources and what the gaps mean."""
    rows = [
        [r.check, r.solved_for, _value(r.friction_deg, 3), _value(r.t_over_R, 5),
         _value(r.published_friction_deg, 4), _value(r.published_t_over_R, 6)]
        for r in table.itertuples()
    ]  # fmt: skip
    lines = [
        "",
        "## Semicircles against published closed forms: friction",
        "",
        f"A complete semicircle of {N_VOUSSOIRS} voussoirs with radial joints (intrados radius "
        f"{SEMICIRCLE_RADIUS_MM:g} mm, t/R over the centre-line radius) under its own weight, on the rigid "
        "LP (`stands`), bisected on the friction angle or the thickness. Published: Cocchetti and Rizzi "
        "(2020), Frattura ed Integrità Strutturale 51, 356-375, doi:10.3221/IGF-ESIS.51.26, p. 370 (a "
        "continuous ring): below 17.1824 deg (mu 0.309215) no thickness stands, the arch slides; between it "
        "and 21.5952 deg (mu 0.395832) sliding at the shoulders raises the least t/R, to 0.200637 at the "
        "lower end; above, the least t/R is the no-sliding one. A ring of finite voussoirs can hinge or "
        "slide only at its joints, so its least t/R lies a little below the continuous ring's. `solved for`: the "
        "column the LP bisected (the other is given; the t/R just above the sliding friction is taken 0.01 deg "
        "above it, where a ring still stands).",
        "",
        *markdown_table(
            ["check", "solved for", "friction (deg)", "t/R", "published friction (deg)", "published t/R"], rows
        ),
        "",
    ]
    return "\n".join(lines)


def point_load_markdown(table: pd.DataFrame) -> str:
    """The table of `published.point_load_table` with its source and why the LP lies a little below it."""
    rows = [
        [r.method, f"{r.published_N:.0f}", f"{r.lp_N:.1f}", f"{100.0 * r.relative_difference:+.2f} %", r.lp_hinges]
        for r in table.itertuples()
    ]
    weight, sectors = float(table["arch_weight_N"].iloc[0]), float(table["sector_arch_weight_N"].iloc[0])
    lines = [
        "",
        "## A semicircle under a point load against a published example",
        "",
        f"Stockdale et al. (2018), SoftwareX 7, 174-179, doi:10.1016/j.softx.2018.05.006, worked example: a "
        f"semicircle of {POINT_LOAD_VOUSSOIRS} equal voussoirs with radial joints, intrados radius "
        f"{POINT_LOAD_RADIUS_MM / 1000:g} m, thickness {POINT_LOAD_T_OVER_R:g} x that radius, depth "
        f"{POINT_LOAD_DEPTH_MM / 1000:g} m, {POINT_LOAD_DENSITY_G_PER_CM3 * 1000:g} kg/m3, no sliding, a vertical "
        f"point load at the extrados end of the {POINT_LOAD_JOINT}th joint from the left springing (this "
        f"project's joint {POINT_LOAD_JOINT + 1}); the collapse load by their calculator (KCLC) and by an "
        "independent virtual-power construction (the values as a peer's test quotes them; the paper's page was "
        "not read here). Rigid LP here, friction high enough not to slide. The source's voussoirs are circular "
        f"sectors, these polygons with straight faces: the arch weighs {weight:.1f} N here, "
        f"{100.0 * (1.0 - weight / sectors):.2f} % less than the sectors' {sectors:.1f} N, and the LP carries a "
        "little less.",
        "",
        *markdown_table(["published by", "published (N)", "LP (N)", "LP vs published", "LP hinges"], rows),
        "",
    ]
    return "\n".join(lines)
