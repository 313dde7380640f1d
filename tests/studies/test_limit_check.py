"""The rigid limit a DEM run is checked against counts the snaps the run counted: its own runaway
distance, as its summary or its case file records it (a run made before the bound was geometric counted
1 mm)."""

from __future__ import annotations

import pytest

from yadearch.case.config import preset
from yadearch.results.summary import RunSummary
from yadearch.studies.limit_check import _run_runaway_mm


def _summary(relaxations: dict | None) -> RunSummary:
    return RunSummary(name="x", du_mm=1.0, hinges_at_collapse=(), steps=0, wall_s=0.0, relaxations=relaxations)


def test_the_runs_recorded_runaway_distance_is_the_one_checked():
    case = preset("set2")  # its bound now: half the 24 mm ring
    assert _run_runaway_mm(case, _summary({"runaway_mm": 1.0}), {}) == 1.0
    assert _run_runaway_mm(case, _summary(None), {"numerics": {"runaway_mm": 1.0}}) == 1.0  # an older run's file
    assert _run_runaway_mm(case, _summary(None), {}) == pytest.approx(12.0)
