"""The DEM on the atlas's short collapses with a relative bracket (pure): which runs are short, the gaps
between the engines with the relative bracket and with du_tolerance_mm alone, and the report's counts."""

from __future__ import annotations

import pandas as pd
import pytest

from yadearch.studies.atlas.short_dem import acting_below_mm, short_markdown, short_rows, short_table

ATLAS = pd.DataFrame(
    {
        "run": ["short", "long", "stands"],
        "dem_du_mm": [5.30, 60.0, float("nan")],
        "dem_du_first_mm": [5.30, 40.0, float("nan")],
        "static_du_mm": [5.34, 60.1, float("nan")],
        "static_du_first_mm": [5.34, 40.1, float("nan")],
    }
)


def test_only_the_dem_runs_whose_committed_du_is_short_are_made_again():
    rows = [{"run": "short", "shape": "pointed"}, {"run": "long"}, {"run": "stands"}]
    assert acting_below_mm(0.1, 0.005) == pytest.approx(20.0)  # 0.5 % of du is narrower than 0.1 mm below 20 mm
    assert short_rows(ATLAS, rows, 20.0) == [{"run": "short", "shape": "pointed"}]
    assert short_rows(ATLAS, rows, 100.0) == rows[:2]


def test_the_engines_are_compared_with_the_relative_bracket_and_with_the_absolute_one():
    dem = pd.DataFrame({"run": ["short"], "outcome": ["collapse"], "du_mm": [5.31], "du_first_mm": [5.31]})
    static = pd.DataFrame({"case": ["short"], "du_mm": [5.307], "du_first_mm": [5.307]})
    table = short_table(dem, static, ATLAS)
    row = table.iloc[0]
    assert row["gap_du_mm_pct"] == pytest.approx(100 * (5.31 - 5.307) / 5.307)
    assert row["dem_du_mm_absolute_bracket"] == 5.30 and row["static_du_mm_absolute_bracket"] == 5.34
    assert row["gap_du_mm_absolute_bracket_pct"] == pytest.approx(100 * (5.30 - 5.34) / 5.34)
    text = short_markdown(table, 0.005, "atlas.py --short-dem 0.005", 20.0)
    assert "Regenerate with `atlas.py --short-dem 0.005`" in text
    assert "du in 1 of 1 (1), du_first in 1 (1)." in text  # 0.06 % now, -0.75 % with 0.1 mm
    assert "| short | 5.310 | 5.307 | +0.06 % |" in text
    assert "- DEM runs that did not finish: 0." in text
    assert "did not finish: 1 (long)." in short_markdown(table, 0.005, "atlas.py", 20.0, ["long"])
