"""A branch known by one state (the path's start, a snap's landing) is predicted along the free blocks'
whole tangent, the fill's springs with the joints: the prediction is of second order in the step, and
a march with its increments halved finds the same first loss of stability (docs/numerics.md)."""

from __future__ import annotations

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.solve.load_path import hold_the_live_load
from yadearch.solve.prediction import tangent_prediction
from yadearch.solve.static_path import StaticLoading
from yadearch.static.simulate import simulate_static
from yadearch.studies.loads.passive import passive_case

SEMICIRCLE = {"embrace_deg": 180.0, "internal_radius_mm": 277.5, "thickness_mm": 45.0}
STEPS_M = (1e-5, 5e-6)
# measured: 21 of the 26 states; 3 are of first order, 2 between (a kink of the law within the step)
SECOND_ORDER_SHARE = 0.8


def test_a_prediction_from_one_state_is_of_second_order_where_the_fill_pushes():
    loading = StaticLoading.of(passive_case("paper", 1.0, live_load="none"))
    loading.selfweight()
    loading.follow()
    arch = loading.arch
    pushing = [s for s in loading.accepted if np.count_nonzero(arch.passive_forces(s.u, s.springs)[:, 0]) >= 5]
    assert len(pushing) >= 20
    ratios = []
    for state in pushing:
        errors = []
        for step in STEPS_M:
            predicted = loading.predict(state.lam + step, [state])
            found = loading.solver.newton(
                predicted,
                state.u,
                state.forces.shear_force,
                multiplier=loading.parameter.multiplier(state.lam),
                springs=state.springs,
            )
            assert found is not None and found.stable()
            errors.append(np.abs(predicted - found.u).max())
        ratios.append(errors[0] / errors[1])
    # error ~ step^2 (the tangent of the joints alone, which this replaced: ~ step at every state)
    assert np.mean(np.abs(np.array(ratios) - 4.0) < 0.1) >= SECOND_ORDER_SHARE


def test_a_spreading_semicircle_under_its_fill_first_loses_stability_where_halved_increments_do():
    case = passive_case("paper", 1.0, live_load="none").with_overrides(
        {**SEMICIRCLE, "support_direction_deg": 0.0, "interface.kn_N_per_mm3": 10_000.0, "numerics.engine": "static"}
    )
    numerics = case.numerics
    halved = case.with_overrides(
        {
            "numerics.first_increment_mm": 0.5 * numerics.first_increment_mm,
            "numerics.max_increment_mm": 0.5 * numerics.max_increment_mm,
        }
    )
    default, finer = (simulate_static(c, None, log=lambda _line: None) for c in (case, halved))
    assert default.path_outcome == finer.path_outcome == "collapse"
    assert default.du_first_mm == pytest.approx(finer.du_first_mm, rel=0.01)  # was 1.89 against 41.09 mm
    assert default.du_mm == pytest.approx(finer.du_mm, rel=0.01)


def test_a_held_load_turns_with_the_blocks_in_the_prediction_the_dem_reads():
    """The DEM's one-state slope (`StaticCheck.support_slope`) passes the load its scene holds: with it
    the prediction is the static engine's own along its held-load path, to the bit; without it the
    load's turning arms are missing from the tangent and the prediction is another."""
    case = preset("set2").with_overrides(
        {"n_voussoirs": 15, "live_load": "vertical", "held_load_N": 4.0, "numerics.engine": "static"}
    )
    loading = StaticLoading.of(case)
    loading.selfweight()
    hold_the_live_load(loading, case)  # load, then movement, as a run holding it
    loading.follow()
    assert loading.parameter.multiplier(loading.accepted[-1].lam) == 4.0
    for state in loading.accepted[1::4]:
        target = state.lam + STEPS_M[0]
        own = loading.predict(target, [state])
        args = (state.u, state.lam, state.forces.shear_force, state.springs, target)
        assert np.array_equal(tangent_prediction(loading, *args, held=4.0), own)
        assert not np.array_equal(tangent_prediction(loading, *args, held=0.0), own)
