"""reports/loads: the section that sets the rigid-block LP beside published closed forms of the
semicircular arch (`studies.loads.published`)."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.markdown import markdown_table
from yadearch.studies.loads.published import N_VOUSSOIRS
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
