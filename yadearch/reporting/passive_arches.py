"""The passive report's section on arches other than the paper's settling one: the static engine's du
and du_first under every numerical setting halved and doubled, and which of them are results."""

from __future__ import annotations

import math

import pandas as pd

from yadearch.markdown import markdown_table
from yadearch.studies.atlas.invariance import TOLERANCE
from yadearch.studies.loads.passive import FILLS_MM, LATERAL_COEFFICIENT, SWEPT_KP


def arches_markdown(verdicts: pd.DataFrame) -> str:
    """One row an arch and stiffness (`studies.loads.passive_arches.arches_verdicts`): the default's
    answers, the largest move of each over the variants and what makes it, and a count of results."""
    rows = [
        [r.arch, f"{r.kn_N_per_mm3:g}", r.outcome, _mm(r.du_mm), _move(r.du_mm_largest_move, r.du_mm_moved_by),
         _mm(r.du_first_mm), _move(r.du_first_mm_largest_move, r.du_first_mm_moved_by), r.outcomes_differ or "none"]
        for r in verdicts.itertuples()
    ]  # fmt: skip
    results = {key: int(verdicts[f"{key}_is_result"].sum()) for key in ("du_mm", "du_first_mm")}
    lines = [
        "",
        "## Other arches under the fill, every numerical setting halved and doubled (arches_numerics.csv)",
        "",
        f"Static engine, {FILLS_MM['paper']:g} mm of fill at K {LATERAL_COEFFICIENT:g} and Kp {SWEPT_KP:g}, u_p 1 mm; "
        "each run again with the increments, the bracket, the runaway bound and the snap floor halved and "
        f"doubled, and the increments x0.25 and x0.125. A result moves by at most {100 * TOLERANCE:g} %: du in "
        f"{results['du_mm']} of {len(verdicts)}, du_first in {results['du_first_mm']} of {len(verdicts)}.",
        "",
        *markdown_table(
            [
                "arch",
                "kn (N/mm³)",
                "outcome",
                "du (mm)",
                "largest du move",
                "du_first (mm)",
                "largest du_first move",
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
