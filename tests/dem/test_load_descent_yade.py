"""The DEM's load path past its peak (dem/load_descent.py) against the static engine's arc length, the same
blocks and joints: a point load at 0.3 of the span of a 15-voussoir segmental arch (kn 5.2 N/mm3), driven
past its limit point by its own displacement through a stiff spring, until it falls to half the capacity.
Every state the DEM holds at rest lies on the static branch (measured within 0.22 %), the branch ends the
same way on the same hinges, and the supports carry the weight and the load at each state."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import needs_yade
from test_load_ramp_yade import POINT

from yadearch import api
from yadearch.case.config import ArchCase
from yadearch.solve.descending import DescentEnd
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import ASCENDING, BRANCH, DESCENDING

pytestmark = [needs_yade, pytest.mark.yade]

BRANCH_TOLERANCE = 0.005  # the DEM's load against the static branch's at the same load displacement
DESCEND_TO = 0.5


def _static_branch_at(static_curve, displacement_mm: np.ndarray) -> np.ndarray:
    """The static engine's load on its descending branch (from the peak) at `displacement_mm`."""
    peak = int(np.argmax(static_curve["multiplier"]))
    branch = static_curve.iloc[peak:]
    assert np.all(np.diff(branch["load_displacement_mm"]) > 0.0)  # no snap-back: one load a displacement
    return np.interp(displacement_mm, branch["load_displacement_mm"], branch["multiplier"])


def test_past_the_peak_the_dem_follows_the_static_branch(tmp_path):
    case = ArchCase(name="segmental_point").with_overrides(POINT)
    static = api.load_path(case, descend_to=DESCEND_TO, figures=False)
    dem = api.load_path(case, out=tmp_path, engine="dem", descend_to=DESCEND_TO, figures=False)
    assert dem.descent_end == static.descent_end == DescentEnd.FALLEN
    assert dem.descent_hinges == static.descent_hinges
    curve = dem.curve
    past = curve[curve[BRANCH] == DESCENDING]
    assert (curve[BRANCH].iloc[: len(curve) - len(past)] == ASCENDING).all() and len(past) >= 10
    # under displacement control the load falls as its point goes on down
    assert np.all(np.diff(past["multiplier"]) < 0.0) and np.all(np.diff(past["load_displacement_mm"]) > 0.0)
    assert past["multiplier"].iloc[-1] <= DESCEND_TO * dem.capacity < past["multiplier"].iloc[-2]
    on_static = _static_branch_at(static.curve, past["load_displacement_mm"].to_numpy())
    off = np.abs(past["multiplier"].to_numpy() / on_static - 1.0)
    assert off.max() < BRANCH_TOLERANCE, off
    # the supports carry the weight and the load at each state past the peak, as before it
    weight = load_analysis(case).arch_weight_N
    balance = case.geometry.n_voussoirs * case.numerics.equilibrium_tolerance
    assert (abs((past["vertical_reactions_N"] - past["multiplier"]) / weight - 1.0) < balance).all()
    # the run's folder keeps the branch's states, read back as written
    again = api.open_run(tmp_path / f"{case.name}_load_path")
    assert len(again.states) >= len(curve)
