"""The DEM's live-load path (dem/load_ramp.py) on a small arch against the static engine's, the same
blocks and joints: a point load at 0.3 of the span of a 15-voussoir segmental arch (kn 5.2 N/mm3). The
DEM finds the static capacity within 1 % on the same four hinges (reports/loads/engines: -0.04 %), and
at every equilibrium of its path the supports carry the weight and the load."""

from __future__ import annotations

import math

import pytest
from conftest import needs_yade

from yadearch.case.config import ArchCase
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path

pytestmark = [needs_yade, pytest.mark.yade]

POINT = {
    "n_voussoirs": 15,
    "friction_deg": 80.0,
    "live_load": "vertical",
    "load_position_over_span": 0.3,
    "interface.kn_N_per_mm3": 5.2,
    "progress_every_s": 1e9,
}
ENGINES_TOLERANCE = 0.01  # the two engines' capacities (docs/loads.md)
BALANCE_TOLERANCE = 1e-3  # the reactions against weight + load, relative (the holds' unbalanced force)


def test_the_dem_load_path_finds_the_static_capacity_and_hinges():
    from yadearch.dem.load_ramp import dem_load_path

    case = ArchCase(name="segmental_point").with_overrides(POINT)
    static = static_load_path(case)
    dem, _ = dem_load_path(case, log=lambda line: None)
    assert dem.outcome == static.outcome == "collapse"
    assert math.isclose(dem.capacity, static.capacity, rel_tol=ENGINES_TOLERANCE), (dem.capacity, static.capacity)
    assert dem.hinges == static.hinges
    assert dem.first_loss == dem.capacity  # no snap on the way: the path folds once, as the static one does
    weight = load_analysis(case).arch_weight_N
    carried = dem.curve["vertical_reactions_N"] - dem.curve["multiplier"]
    assert (abs(carried / weight - 1.0) < BALANCE_TOLERANCE).all(), carried.tolist()
    assert (abs(dem.curve["horizontal_reactions_N"]) < BALANCE_TOLERANCE * weight).all()
