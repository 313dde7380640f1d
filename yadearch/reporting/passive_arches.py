"""The passive report's section on arches other than the paper's settling one: the static engine's du
and du_first under every numerical setting halved and doubled, and which of them are results."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.markdown import markdown_table
from yadearch.studies.atlas.invariance import REFINED, SETTINGS, TOLERANCE
from yadearch.studies.loads.passive import FILLS_MM, LATERAL_COEFFICIENT, SWEPT_KP, passive_case


def arches_markdown(verdicts: pd.DataFrame) -> str:
    """One row an arch and stiffness (`studies.loads.passive_arches.arches_verdicts`): the default's
    answers, the largest move of each over the variants and what makes it, and a count of results
    (within TOLERANCE under every setting halved and doubled, the outcome unchanged)."""
    steady = verdicts["outcome_changed_by"].fillna("") == ""
    results = {key: int((steady & (verdicts[f"{key}_spread"] <= TOLERANCE)).sum()) for key in ("du_mm", "du_first_mm")}
    finest = f"x{min(REFINED):g}"
    rows = [
        [r["case"], r["outcome"], _mm(r["du_mm"]), _move(r["du_mm_spread"], r["du_mm_by"]),
         _mm(r[f"du_mm_{finest}"]), _mm(r["du_first_mm"]), _move(r["du_first_mm_spread"], r["du_first_mm_by"]),
         _mm(r[f"du_first_mm_{finest}"]), r["outcome_changed_by"] or "none"]
        for _, r in verdicts.iterrows()
    ]  # fmt: skip
    u_p = passive_case("paper", SWEPT_KP).loads.fill_passive_displacement_mm
    lines = [
        "",
        "## Other arches under the fill, every numerical setting halved and doubled (arches_numerics.csv)",
        "",
        f"Static engine, {FILLS_MM['paper']:g} mm of fill at K {LATERAL_COEFFICIENT:g} and Kp {SWEPT_KP:g}, "
        f"u_p {u_p:g} mm; each run again with its {', '.join(SETTINGS)} halved and doubled, and with the "
        f"increments x{' and x'.join(f'{f:g}' for f in REFINED)}. A result moves by at most {100 * TOLERANCE:g} % "
        f"under every setting halved and doubled, its outcome unchanged: du in {results['du_mm']} of "
        f"{len(verdicts)}, du_first in {results['du_first_mm']} of {len(verdicts)}.",
        "",
        *markdown_table(
            [
                "arch",
                "outcome",
                "du (mm)",
                "largest du move",
                f"du, increments {finest}",
                "du_first (mm)",
                "largest du_first move",
                f"du_first, increments {finest}",
                "outcome differs with",
            ],
            rows,
        ),  # fmt: skip
        "",
    ]
    return "\n".join(lines)


def _mm(value: float) -> str:
    return "" if not math.isfinite(value) else f"{value:.2f}"


def _move(value: float, variant: str) -> str:
    return "" if not math.isfinite(value) else f"{100 * value:.2f} % ({variant})"
