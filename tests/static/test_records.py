"""The static run's records (static/records.py): every recorded state has a step of its own, which
the joints' history keys on (a 10 m arch's state reached by its predictor without a Newton iteration
repeated the step before it, and drawing the run's figures failed: sixth user trial)."""

from __future__ import annotations

from dataclasses import replace

import pandas as pd

from yadearch.analysis.history import joint_history
from yadearch.case.config import preset
from yadearch.solve.stages import Stage
from yadearch.solve.static_path import StaticLoading
from yadearch.static.records import StaticRecords

HINGE_ROTATION = 1e-3  # rad


def test_a_state_reached_without_an_iteration_has_a_step_of_its_own():
    loading = StaticLoading.of(preset("set2"))
    start = loading.selfweight()
    records = StaticRecords(loading.arch, HINGE_ROTATION)
    records.add(start)
    for lam_mm, iterations in ((1.0, 4), (2.0, 0), (3.0, 2)):  # the second: the predictor's state as it stands
        records.add(replace(start, stage=Stage.EQUILIBRIUM, lam=lam_mm * 1e-3, iterations=iterations))
    steps = [row["step"] for row in records.series]
    assert steps == [start.iterations, start.iterations + 4, start.iterations + 5, start.iterations + 6]
    assert records.iterations == start.iterations + 6  # the Newton iterations themselves are not changed
    history = joint_history(pd.DataFrame(records.joints), 24.0, None)
    assert list(history.delta_mm) == [0.0, 1.0, 2.0, 3.0]
