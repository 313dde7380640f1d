"""Loads held during the rigid march (solve/rigid.py `fixed`, solve/limit_lp.py, the potential of
solve/compliant.py): a live load held while the support settles enters the rigid-block analysis as the
static engine and the DEM hold it; stiff static within 2 % of rigid blocks; the potential energy counts
the held forces' work."""

from __future__ import annotations

import math

import numpy as np

from yadearch.case.config import preset
from yadearch.model import units
from yadearch.solve.compliant import potential
from yadearch.solve.limit import limit_analysis
from yadearch.solve.load_path import hold_the_live_load
from yadearch.solve.rigid import Placement, at_rest, rigid_arch
from yadearch.solve.static_path import StaticLoading

SMALL = {"n_voussoirs": 15, "friction_deg": 80.0, "live_load": "vertical", "load_position_over_span": 0.3}
STIFF_KN = 100_000.0  # N/mm3
RIGID_TOLERANCE = 0.02  # stiff static within 2 % of rigid blocks


def _static_du_mm(case) -> float:
    loading = StaticLoading.of(case)
    loading.selfweight()
    hold_the_live_load(loading, case)
    return units.to_mm(loading.follow().du)


def test_stiff_static_settles_as_far_as_rigid_blocks_under_a_held_load():
    case = preset("set2").with_overrides({**SMALL, "held_load_N": 2.0})
    rigid = limit_analysis(case, mirror=False).du_rigid_mm  # 104.28 mm; static at kn 1e5: 104.01 mm
    static = _static_du_mm(case.with_overrides({"interface.kn_N_per_mm3": STIFF_KN}))
    assert rigid is not None and abs(static / rigid - 1.0) < RIGID_TOLERANCE, (static, rigid)


def test_a_vanishing_held_load_gives_the_weights_answer():
    bare = limit_analysis(preset("set2").with_overrides({"n_voussoirs": 15, "friction_deg": 80.0}), mirror=False)
    held = limit_analysis(preset("set2").with_overrides({**SMALL, "held_load_N": 1e-6}), mirror=False)
    assert bare.du_rigid_mm is not None and held.du_rigid_mm is not None
    assert math.isclose(held.du_rigid_mm, bare.du_rigid_mm, rel_tol=1e-3)
    assert held.collapse_hinges == bare.collapse_hinges


def test_the_potential_counts_the_held_forces_work():
    """The arch lowered by 1 mm: the potential falls by (weights + held load) x 1 mm."""
    arch = rigid_arch(preset("set2").with_overrides({**SMALL, "held_load_N": 3.0}))
    rest = at_rest(arch)
    lowered = Placement(0.0, rest.rot, rest.shift + np.array([0.0, -1e-3]))
    drop = potential(arch, rest) - potential(arch, lowered)
    assert math.isclose(drop, (float(arch.weight.sum()) + 3.0) * 1e-3, rel_tol=1e-9)


def test_a_held_value_of_another_load_is_refused_and_a_held_load_is_not_mirrored():
    import pytest

    from yadearch.case.plan import plan_run
    from yadearch.errors import CaseError
    from yadearch.solve.mirror import has_other_branch

    with pytest.raises(CaseError, match="loads.held_load_N = 2 holds a vertical load, but loads.live_load is 'none'"):
        plan_run(preset("set2").with_overrides({"held_load_N": 2.0, "numerics.engine": "static"}))
    with pytest.raises(CaseError, match="held_acceleration_g = 0.1 holds a horizontal acceleration load"):
        limit_analysis(preset("set2").with_overrides({"live_load": "vertical", "held_acceleration_g": 0.1}))
    # the keystone's other branch is the mirror image of the movement, not of an off-centre held load
    settling = preset("set2")
    assert has_other_branch(settling)
    assert not has_other_branch(settling.with_overrides({"live_load": "vertical", "held_load_N": 2.0}))
