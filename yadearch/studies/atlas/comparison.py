"""Two invariance studies of the atlas compared (docs/atlas.md): one made with another snap floor or a
relative bracket as its default against the default study (reports/atlas/invariance.csv)."""

from __future__ import annotations

import pandas as pd

from yadearch.markdown import markdown_table
from yadearch.studies.atlas.invariance import TOLERANCE, held_within, relative_move

ACTED = 1e-4  # an answer moving more than this (relative) between two studies: the change acted on it
LONG_COLLAPSE_MM = 10.0  # collapses compared across snap floors: the 0.1 mm bracket is over 1 % of a shorter du


def floor_comparison(table: pd.DataFrame, default_floor: pd.DataFrame) -> list[str]:
    """The section comparing a study made with another snap floor (`table`) with the default floor's:
    among the arches both collapse beyond LONG_COLLAPSE_MM, du and du_first within 1 % under every
    variant in each, and where this floor's du_first lies against the default's."""
    both = table.merge(default_floor, on="case", suffixes=("", "_default"))
    long = both[
        (both["outcome"] == "collapse")
        & (both["outcome_default"] == "collapse")
        & (both["du_mm_default"] >= LONG_COLLAPSE_MM)
    ]

    spreads = [f"{c}_spread{floor}" for c in ("du_mm", "du_first_mm") for floor in ("", "_default")]
    held = {spread: held_within(long, spread) for spread in spreads}
    moved = (long["du_first_mm"] - long["du_first_mm_default"]) / long["du_first_mm_default"]
    earlier, later = long[moved < -TOLERANCE], int((moved > TOLERANCE).sum())
    lines = [
        "",
        "## Against the default snap floor (invariance.csv)",
        "",
        f"- arches both floors collapse beyond {LONG_COLLAPSE_MM:g} mm: {len(long)}; under every variant du "
        f"within {TOLERANCE * 100:g} % in {held['du_mm_spread']} ({held['du_mm_spread_default']} at the "
        f"default floor), du_first in {held['du_first_mm_spread']} ({held['du_first_mm_spread_default']}).",
        f"- du_first against the default floor's: within {TOLERANCE * 100:g} % in "
        f"{len(long) - len(earlier) - later}, earlier in {len(earlier)} (a smaller snap counted), later in {later}.",
    ]
    if not earlier.empty:
        lines += ["", "Earlier:", ""]
        lines += markdown_table(
            ["case", "du (mm)", "du_first (mm)", "at the default floor (mm)"],
            [
                [r["case"], f"{r['du_mm']:.2f}", f"{r['du_first_mm']:.2f}", f"{r['du_first_mm_default']:.2f}"]
                for _, r in earlier.sort_values("du_first_mm").iterrows()
            ],
        )
    return lines


def bracket_comparison(table: pd.DataFrame, default: pd.DataFrame) -> list[str]:
    """The section comparing a study made with a relative bracket (`table`, `numerics.du_tolerance_ratio`)
    with the default's (absolute alone): du and du_first within 1 % under every variant in each, over every
    arch both collapse and over those beyond LONG_COLLAPSE_MM, and the answers the relative bracket moved."""
    both = table.merge(default, on="case", suffixes=("", "_default"))
    both = both[(both["outcome"] == "collapse") & (both["outcome_default"] == "collapse")]
    lines = ["", "## Against the default bracket, du_tolerance_mm alone (invariance.csv)", ""]
    for name, arches in (
        ("", both),
        (f" beyond {LONG_COLLAPSE_MM:g} mm", both[both["du_mm_default"] >= LONG_COLLAPSE_MM]),
    ):
        held = {spread: held_within(arches, spread) for spread in ("du_mm_spread", "du_first_mm_spread")}
        held_default = {spread: held_within(arches, f"{spread}_default") for spread in held}
        lines.append(
            f"- arches both collapse{name}: {len(arches)}; under every variant du within {TOLERANCE * 100:g} % in "
            f"{held['du_mm_spread']} ({held_default['du_mm_spread']} with the default bracket), du_first in "
            f"{held['du_first_mm_spread']} ({held_default['du_first_mm_spread']})."
        )
    moved = both[
        (both.apply(lambda r: relative_move(r["du_mm"], r["du_mm_default"]), axis=1) > ACTED)
        | (both.apply(lambda r: relative_move(r["du_first_mm"], r["du_first_mm_default"]), axis=1) > ACTED)
    ]
    lines += ["", f"The default answers the relative bracket moves ({len(moved)}):", ""]
    lines += markdown_table(
        ["case", "du (mm)", "with the default bracket", "du_first (mm)", "with the default bracket"],
        [
            [
                r["case"],
                f"{r['du_mm']:.3f}",
                f"{r['du_mm_default']:.3f}",
                f"{r['du_first_mm']:.3f}",
                f"{r['du_first_mm_default']:.3f}",
            ]
            for _, r in moved.sort_values("du_mm").iterrows()
        ],
    )
    return lines
