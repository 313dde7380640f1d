"""The sensitivity study checked by the DEM (real YADE): a static study of a 9-voussoir arch with soft
joints (DEM runs of 15-30 s) makes its most influential one-at-a-time runs again on the DEM, and the
two engines agree on them."""

from __future__ import annotations

import pandas as pd
import pytest
from conftest import needs_yade

import yadearch as ya
from yadearch.studies.sensitivity.checks import AGREEMENT
from yadearch.studies.sensitivity.indices import parse_factor

pytestmark = [needs_yade, pytest.mark.yade]


def test_a_static_sensitivity_study_is_checked_by_the_dem(tmp_path):
    """Thickness 22-26 mm moves du more than density (which scales every load alike and moves du
    only through the joints' compliance); the DEM makes thickness's two ends again and meets the
    static engine within 1 %."""
    case = ya.preset("set2").with_overrides({"n_voussoirs": 9, "kn_N_per_mm3": 0.5, "progress_every_s": 1e9})
    factors = (parse_factor("thickness_mm=22:26"), parse_factor("density_g_per_cm3=1.5:1.8"))
    result = ya.sensitivity(case, tmp_path, base_points=8, factors=factors, engine="static", jobs=2, check_runs=2)
    checks = result.checks.set_index("run")
    assert sorted(checks.index) == ["thickness_mm_high", "thickness_mm_low"]
    assert (checks["difference_pct"].abs() <= 100 * AGREEMENT).all(), checks
    assert pd.read_csv(tmp_path / "checks.csv")["dem_du_mm"].notna().all()
    assert "## Checked by the DEM" in (tmp_path / "sensitivity.md").read_text()
