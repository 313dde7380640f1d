"""The imperfection study's DEM settings (`scripts/imperfection_study.py --dem-set`): every campaign's
base case carries them over its fixed settings, and the report's command names them (no runs)."""

from __future__ import annotations

import pandas as pd
import pytest
from synthetic_runs import make_run

from yadearch.case.config import preset
from yadearch.case.numerics_section import STATIC_PATH_STATES
from yadearch.studies.dem_settings import dem_arguments
from yadearch.studies.imperfections import report as imperfections
from yadearch.studies.imperfections.plan import STUDIES

STATIC_STATES = {"numerics.support_path_states": STATIC_PATH_STATES}


@pytest.mark.parametrize("study", STUDIES, ids=lambda study: study.name)
def test_every_campaign_takes_the_settings_over_its_fixed_ones(study):
    plain = imperfections.study_case(study)
    assert plain.to_dict() == preset(imperfections.BASE_PRESET).with_overrides(study.fixed).to_dict()
    case = imperfections.study_case(study, STATIC_STATES)
    assert case.numerics.support_path_states == STATIC_PATH_STATES
    assert case.to_dict() == plain.with_overrides(STATIC_STATES).to_dict()


def test_the_report_names_the_settings_in_its_command(tmp_path, monkeypatch):
    make_run(tmp_path / "set1", "set1")
    monkeypatch.setattr(imperfections, "SET1_RUN", tmp_path / "set1")
    sweep = pd.DataFrame({"kn_N_per_mm3": [0.25, 5.2], "du_mm": [40.0, 88.0], "status": "done"})
    assert "Regenerate: `.venv/bin/python scripts/imperfection_study.py`." in imperfections.report(
        tmp_path, sweep, 88.0
    )
    named = imperfections.report(tmp_path, sweep, 88.0, dem_arguments(STATIC_STATES))
    assert "scripts/imperfection_study.py --dem-set numerics.support_path_states=static`." in named
