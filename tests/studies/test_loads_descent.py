"""The descent study's reading of the static branch (studies/loads/descent.py): the load past the peak at a
DEM state's displacement of the load, none before the peak or past a snap-back, where the static branch
turns back and displacement control cannot follow; and the report's counts (reporting/loads_descent.py)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from yadearch.case.numerics_section import STATIC_PATH_STATES
from yadearch.reporting.loads_descent import descent_markdown
from yadearch.studies.dem_settings import dem_arguments
from yadearch.studies.loads.descent import DEFAULT, descent_runs, static_branch_at

# up to the peak at 1 mm, falling to 4.0 mm, then turning back (a snap-back) to 3.5 mm
CURVE = pd.DataFrame(
    {
        "multiplier": [0.0, 5.0, 8.0, 6.0, 4.0, 2.0],
        "load_displacement_mm": [0.0, 0.2, 1.0, 3.0, 4.0, 3.5],
    }
)


def test_the_static_branch_is_read_from_the_peak_to_where_it_turns_back():
    at = static_branch_at(CURVE, np.array([0.5, 1.0, 2.0, 3.5, 4.0, 4.2]))
    assert math.isnan(at[0]) and math.isnan(at[-1])  # before the peak; past the turn
    assert np.allclose(at[1:5], [8.0, 7.0, 5.0, 4.0])


def test_the_report_counts_runs_within_the_tolerance_and_ending_alike():
    rows = pd.DataFrame(
        [
            {"case": "a", "variant": DEFAULT, "unit": "N", "static_capacity": 8.0, "dem_capacity": 7.99,
             "static_end": "fallen", "dem_end": "fallen", "static_hinges": "1I 2E", "dem_hinges": "1I 2E",
             "static_lowest": 4.0, "dem_lowest": 4.1, "dem_states": 10, "compared": 10, "largest_off": 0.004,
             "dem_steps": 1000, "dem_failure": ""},
            {"case": "b", "variant": DEFAULT, "unit": "g", "static_capacity": 0.2, "dem_capacity": 0.2,
             "static_end": "fallen", "dem_end": "runaway", "static_hinges": "1I", "dem_hinges": "2E",
             "static_lowest": 0.1, "dem_lowest": 0.15, "dem_states": 3, "compared": 3, "largest_off": 0.02,
             "dem_steps": 500, "dem_failure": ""},
        ]
    )  # fmt: skip
    text = descent_markdown(rows)
    assert "within 1 % of the static branch in 1 of 2 runs" in text
    assert "ends the same way on the same hinges in 1 of 2" in text
    assert "| 2.00 % |" in text
    assert "`.venv/bin/python scripts/loads_descent.py --out reports/loads/descent` (minutes" in text
    arguments = dem_arguments({"numerics.support_path_states": STATIC_PATH_STATES})
    named = descent_markdown(rows, arguments)
    assert (
        "scripts/loads_descent.py --out reports/loads/descent --dem-set numerics.support_path_states=static`" in named
    )


def test_the_dem_runs_alone_take_the_study_settings_its_numerics_varied_from_them():
    plain = descent_runs()
    assert all(run.dem_case.to_dict() == run.case.to_dict() for run in plain)  # no settings: the same runs
    runs = descent_runs({"numerics.support_path_states": STATIC_PATH_STATES, "numerics.damping": 0.4})
    for before, run in zip(plain, runs, strict=True):
        assert run.case.to_dict() == before.case.to_dict()  # the static engine's case untouched
        assert run.dem_case.numerics.support_path_states == STATIC_PATH_STATES
        assert run.dem_case.name == run.case.name
    damping = {run.variant: run.dem_case.numerics.damping for run in runs}
    assert damping[DEFAULT] == 0.4 and damping["damping_x0.5"] == 0.2 and damping["damping_x2"] == 0.8
