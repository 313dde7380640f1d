"""The imperfection study's pure parts: the equivalent kn of a du, the amplitude that reaches a
target du, and the per-level table."""

import math

import pandas as pd
import pytest
from synthetic_runs import BuiltHinge, BuiltRun

from yadearch.studies.imperfections.matching import (
    TOWARD_CROWN,
    TOWARD_SPRINGING,
    Study,
    amplitude_for,
    equivalent_kn,
    hinge_shift,
    level_rows,
    paired_amplitude_interval,
    paired_medians,
)

SWEEP = pd.DataFrame(
    {"kn_N_per_mm3": [0.1, 1.0, 0.5, 10.0, 100.0], "du_mm": [20.0, 60.0, 40.0, 90.0, 100.0], "status": ["done"] * 5}
)


def test_equivalent_kn_interpolates_in_log_kn_between_the_bracketing_points():
    assert equivalent_kn(40.0, SWEEP) == pytest.approx(0.5)
    assert equivalent_kn(75.0, SWEEP) == pytest.approx(10**0.5)  # halfway between kn 1 and 10
    assert math.isnan(equivalent_kn(10.0, SWEEP)) and math.isnan(equivalent_kn(120.0, SWEEP))


def test_equivalent_kn_takes_the_first_crossing_of_a_non_monotonic_curve():
    dip = pd.DataFrame(
        {"kn_N_per_mm3": [1.0, 2.0, 3.0, 4.0], "du_mm": [50.0, 70.0, 55.0, 80.0], "status": ["done"] * 4}
    )
    assert equivalent_kn(60.0, dip) == pytest.approx(2**0.5)


def test_amplitude_for_interpolates_between_the_levels_that_bracket_the_target():
    rows = [
        {"level": 1.0, "median_du_mm": 80.0},
        {"level": 2.0, "median_du_mm": 60.0},
        {"level": 3.0, "median_du_mm": 40.0},
    ]
    assert amplitude_for(rows, 48.9) == pytest.approx(2.555)
    assert math.isnan(amplitude_for(rows, 30.0))


def test_level_rows_summarise_each_level_with_its_hinges():
    study = Study("edge", "worn", "edge_radius_mm", (1.0, 2.0), 2)
    table = pd.DataFrame(
        {
            "edge_radius_mm": [1.0, 1.0, 2.0, 2.0],
            "du_mm": [78.0, 80.0, 40.0, math.nan],
            "status": ["done", "done", "done", "failed"],
            "hinge_A": [9, 10, 11, math.nan],
            "hinge_B": [28, 28, 27, math.nan],
            "hinge_C": [56] * 4,
            "hinge_D": [1] * 4,
        }
    )
    first, second = level_rows(study, table, SWEEP)
    assert (first["samples"], first["median_du_mm"]) == (2, 79.0)
    assert first["equivalent_kn_N_per_mm3"] == pytest.approx(equivalent_kn(79.0, SWEEP))
    assert "B 28 (100%)" in first["hinges"]
    assert second["samples"] == 1 and second["median_du_mm"] == 40.0


def test_paired_medians_compare_levels_on_the_seeds_finished_at_both():
    low = pd.DataFrame(
        {
            "face_bump_sd_mm": 0.18,
            "seed": [1, 2, 3, 4],
            "status": ["done"] * 3 + ["failed"],
            "du_mm": [50.0, 60.0, 70.0, math.nan],
        }
    )
    high = pd.DataFrame(
        {"face_bump_sd_mm": 0.22, "seed": [1, 2, 3, 5], "status": ["done"] * 4, "du_mm": [30.0, 40.0, 44.0, 99.0]}
    )
    rows = paired_medians([low, high], "face_bump_sd_mm")
    assert [(r["level"], r["samples"], r["median_du_mm"]) for r in rows] == [(0.18, 3, 60.0), (0.22, 3, 40.0)]
    assert amplitude_for(rows, 50.0) == pytest.approx(0.20)


def test_the_paired_amplitude_interval_holds_the_amplitude_of_the_whole_set():
    seeds = list(range(1, 41))
    low = pd.DataFrame(
        {"face_bump_sd_mm": 0.18, "seed": seeds, "status": "done", "du_mm": [55.0 + (s % 7) for s in seeds]}
    )
    high = pd.DataFrame(
        {"face_bump_sd_mm": 0.22, "seed": seeds, "status": "done", "du_mm": [42.0 + (s % 5) for s in seeds]}
    )
    rows = paired_medians([low, high], "face_bump_sd_mm")
    whole = amplitude_for(rows, 48.9)
    lower, upper = paired_amplitude_interval([low, high], "face_bump_sd_mm", 48.9)
    assert 0.18 < lower <= whole <= upper < 0.22


@pytest.mark.parametrize(("new", "way"), [(5, TOWARD_CROWN), (3, TOWARD_SPRINGING)])
def test_hinge_shift_tells_which_way_hinge_a_moved_before_the_collapse(new, way):
    # an I hinge opens at 4 (of 11 interfaces: the crown at 6), fades while its neighbour opens
    built = BuiltRun(
        [
            BuiltHinge({4: 1.0}, "I", opens_mm=5.0, fades_mm=(15.0, 19.0)),
            BuiltHinge({new: 1.0}, "I", opens_mm=16.0),
            BuiltHinge({8: 1.0}, "E", opens_mm=12.0),
            BuiltHinge({11: 1.0}, "E", opens_mm=20.0),
        ]
    )
    tracks = built.analyse().tracks
    assert hinge_shift(tracks, "A", 11) == (4, new, way)
    assert hinge_shift(tracks, "D", 11) is None  # no hinge at the fixed support
