"""A snap is a jump of the path, not a landing past a floor (studies/atlas/snap_refinement.py, the static
engine): refining the bracket 16 times keeps a real snap's landing and removes a coarse bracket's
prediction error (reports/atlas/snap_refinement.md)."""

from __future__ import annotations

import pandas as pd
import pytest

from yadearch.case.config import preset
from yadearch.studies.atlas.snap_refinement import CONFIRMED, VANISHED, refinement_rows, snap_cases, verdicts


def test_the_arches_the_floor_moves_are_taken_with_the_floor_that_moved_them_and_the_default():
    invariance = pd.DataFrame(
        {
            "case": ["semicircular-tilt-t45-kn100", "segmental-settlement-t24-kn5.2"],
            "kn_N_per_mm3": [100.0, 5.2],
            "du_first_mm_by": ["snap_floor_x2", "increments_x2"],
        }
    )
    assert snap_cases(invariance) == [("semicircular-tilt-t45", 100.0, 1.0), ("semicircular-tilt-t45", 100.0, 2.0)]


def test_a_snap_that_stays_as_the_bracket_shrinks_is_confirmed():
    """The semicircle 45 mm thick tilting at kn 100: its first snap near 1.85 mm lands about 0.5 mm from
    the prediction at every bracket (0.536 / 0.503 / 0.497 mm measured), above the default floor."""
    rows = pd.DataFrame(refinement_rows(preset("set2"), "semicircular-tilt-t45", 100.0, 1.0))
    (verdict,) = verdicts(rows).to_dict("records")
    assert verdict["verdict"] == CONFIRMED
    landings = rows["landing_mm"]
    assert landings.min() > rows["floor_mm"].iloc[0] and landings.max() / landings.min() < 1.2
    assert rows["first_snap_mm"].iloc[-1] == pytest.approx(rows["first_snap_mm"].iloc[0], rel=0.01)


def test_a_landing_that_a_finer_bracket_does_not_find_vanishes():
    """The three-centred arch 75 mm thick closing at kn 5.2 with half the floor: a 0.48 mm landing near
    7.5 mm at the default bracket is gone at a quarter of it; its first loss is then its collapse."""
    rows = pd.DataFrame(refinement_rows(preset("set2"), "three_centred-closing-t75", 5.2, 0.5))
    (verdict,) = verdicts(rows).to_dict("records")
    assert verdict["verdict"] == VANISHED
    assert rows["landing_mm"].iloc[1:].isna().all()
    assert rows["du_first_mm"].iloc[-1] == pytest.approx(rows["du_mm"].iloc[-1])
