"""The study of set 1 from imperfections of measured size: its rows scale one defect pattern by the
amplitude, arches that cannot stand count as du = 0, and the matching amplitude is read off the
paired medians (tables built here, no runs)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from yadearch.errors import CANNOT_STAND
from yadearch.reporting.imperfection_amplitudes import amplitudes_markdown
from yadearch.studies.dem_settings import dem_arguments
from yadearch.studies.imperfections.amplitudes import (
    KINDS,
    LEVEL,
    hinge_table,
    kind_rows,
    level_summary,
    matching_amplitude,
    nearest_level,
    with_levels,
)

COMBINED = next(k for k in KINDS if k.name == "combined")
PERFECT_MM = 88.0


def _results(kind, du_of) -> pd.DataFrame:
    """A campaign's results table for `kind` with 40 seeds a level, du from `du_of(level, seed)` (None:
    the arch could not stand)."""
    rows = []
    for row in kind_rows(kind, 40):
        level, seed = float(row["run"].split("_")[0][1:]), row["imperfections.seed"]
        du = du_of(level, seed)
        rows.append(
            {
                "run": row["run"],
                "status": "failed" if du is None else "done",
                "collapsed": du is not None,
                "du_mm": np.nan if du is None else du,
                "hinge_A": 12,
                "hinge_B": 31,
                "hinge_C": 56,
                "hinge_D": 1,
                "reason": f"error: {CANNOT_STAND} (runaway)" if du is None else "",
            }
        )
    return pd.DataFrame(rows)


def test_a_kind_scales_one_pattern_and_every_level_draws_the_same_seeds():
    rows = kind_rows(COMBINED, 3, (2.0,))
    assert [r["imperfections.seed"] for r in rows] == [1, 2, 3]
    assert rows[0]["imperfections.face_bump_sd_mm"] == pytest.approx(2 * COMBINED.unit["face_bump_sd_mm"])
    assert rows[0]["imperfections.edge_radius_sd_mm"] / rows[0]["imperfections.edge_radius_mm"] == pytest.approx(0.25)
    assert len({r["run"] for r in kind_rows(COMBINED, 3)}) == 3 * len(COMBINED.levels)


def test_an_arch_that_cannot_stand_counts_as_no_capacity_in_the_median():
    table = with_levels(COMBINED, _results(COMBINED, lambda level, seed: None if seed <= 25 and level >= 3 else 60.0))
    summary = level_summary(COMBINED, table).set_index(LEVEL)
    assert summary.loc[3.0, "cannot_stand"] == 25 and summary.loc[3.0, "median_du_mm"] == 0.0
    assert summary.loc[1.0, "median_du_mm"] == 60.0 and summary.loc[1.0, "samples"] == 40


def test_the_matching_amplitude_is_where_the_median_crosses_the_target_with_a_bracketing_interval():
    """du falling linearly by 20 mm per unit of amplitude (seed scatter +-2 mm) crosses 48.9 mm at
    (88 - 48.9) / 20 = 1.955."""
    rng = np.random.default_rng(0)
    scatter = dict(enumerate(rng.uniform(-2, 2, 41)))
    table = with_levels(COMBINED, _results(COMBINED, lambda level, seed: PERFECT_MM - 20 * level + scatter[seed]))
    summary = level_summary(COMBINED, table)
    match = matching_amplitude(summary, table, 48.9, PERFECT_MM)
    assert match.amplitude == pytest.approx(1.955, abs=0.05)
    assert match.low <= match.amplitude <= match.high and match.high - match.low < 0.3
    assert nearest_level(summary, match.amplitude) == 2.0
    assert np.isnan(matching_amplitude(summary, table, 5.0, PERFECT_MM).amplitude)  # never that low
    hinges = hinge_table(table, 2.0, {"A": 13, "B": 32}).set_index("hinge")
    assert hinges.loc["A", "within_one"] == 1.0 and hinges.loc["B", "within_one"] == 1.0


def test_the_report_names_the_dem_confirmations_settings_in_its_command():
    empty = pd.DataFrame()
    plain = amplitudes_markdown(empty, empty, empty, empty, PERFECT_MM, 48.9, "figure")
    assert "Regenerate: `.venv/bin/python scripts/imperfection_amplitudes.py`." in plain
    arguments = dem_arguments({"numerics.support_path_states": "static"})
    named = amplitudes_markdown(empty, empty, empty, empty, PERFECT_MM, 48.9, "figure", arguments=arguments)
    assert "scripts/imperfection_amplitudes.py --dem-set numerics.support_path_states=static`." in named
