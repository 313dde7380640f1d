"""An inclined load on the extrados (loads.load_inclination_deg: a braking or raking force): the
rigid LP's multiplier is the least four-hinge mechanism's by virtual work, a symmetric arch mirrors a
load leaning one way at one quarter into the other, the static path's supports carry the weights and
the leaning load at every state, stiff joints carry the rigid capacity within 2 %, and no lean is the
vertical load."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.case.config import ArchCase, preset
from yadearch.case.mechanics import runaway_length
from yadearch.case.plan import check_dem_load
from yadearch.cli.commands import main
from yadearch.errors import CaseError
from yadearch.solve.limit_lp import weight_load
from yadearch.solve.load_lp import live_forces, load_analysis, load_capacity
from yadearch.solve.load_path import load_settings, load_the_live_load, static_load_path
from yadearch.solve.mechanisms import mechanism_multiplier
from yadearch.solve.path import follow_path, path_settings
from yadearch.solve.rigid import at_rest, rigid_arch
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import static_arch

SMALL = {"n_voussoirs": 15, "live_load": "vertical", "load_position_over_span": 0.25}
HIGH_FRICTION = {"friction_deg": 80.0}  # the mechanism method knows no sliding
LEAN_DEG = 30.0
RIGID_TOLERANCE = 0.02  # stiff static within 2 % of the rigid capacity (issue 44)


def _case(lean_deg: float, **more) -> ArchCase:
    return preset("set2").with_overrides({**SMALL, "load_inclination_deg": lean_deg, **more})


@pytest.mark.parametrize("lean_deg", [-LEAN_DEG, LEAN_DEG])
def test_the_lp_multiplier_is_the_least_mechanism_multiplier(lean_deg):
    case = _case(lean_deg, **HIGH_FRICTION)
    arch = rigid_arch(case)
    live = live_forces(case, arch)
    dead = -weight_load(arch, at_rest(arch)).reshape(-1, 3)
    lp = load_capacity(arch, live)
    kinematic, pivots = mechanism_multiplier(arch, dead, live)
    assert lp.multiplier == pytest.approx(kinematic, rel=1e-9)
    assert lp.hinge_labels == " ".join(p.label for p in pivots)


def test_a_symmetric_arch_mirrors_a_leaning_load_and_no_lean_is_the_vertical_load():
    left = load_analysis(_case(LEAN_DEG))
    right = load_analysis(_case(-LEAN_DEG, load_position_over_span=0.75))
    assert left.multiplier == pytest.approx(right.multiplier, rel=1e-9)
    n = rigid_arch(_case(0.0)).n_joints
    assert {(n - 1 - p.joint, p.side) for p in left.pivots} == {(p.joint, p.side) for p in right.pivots}
    vertical = preset("set2").with_overrides(SMALL)
    assert load_analysis(_case(0.0)).multiplier == load_analysis(vertical).multiplier
    assert left.multiplier != pytest.approx(load_analysis(_case(-LEAN_DEG)).multiplier, rel=1e-3)  # it matters


def test_the_supports_carry_the_weights_and_the_leaning_load_at_every_state():
    case = _case(LEAN_DEG)
    loading = StaticLoading(static_arch(case), path_settings(case.numerics, 10.0), runaway_length(case))
    loading.selfweight()
    load_the_live_load(loading, load_settings(load_analysis(case).multiplier, case.numerics.increment_growth))
    follow_path(loading, loading.settings)
    weight = loading.arch.weight[1:-1].sum()
    lean = math.radians(LEAN_DEG)
    assert len(loading.accepted) >= 5
    for state in loading.accepted:
        onto_supports = state.forces.block_force[[0, -1]].sum(axis=0)
        expected = np.array([0.0, weight]) + state.lam * np.array([-math.sin(lean), math.cos(lean)])
        assert np.allclose(-onto_supports, expected, atol=1e-7 * weight), (state.lam, onto_supports)


def test_stiff_joints_carry_the_rigid_capacity_of_a_leaning_load():
    case = _case(LEAN_DEG).with_overrides({"interface.kn_N_per_mm3": 10_000.0})
    rigid = load_analysis(case)
    path = static_load_path(case)
    assert path.outcome == "collapse"
    assert -RIGID_TOLERANCE < path.capacity / rigid.multiplier - 1.0 < 0.0


def test_a_lean_beyond_the_horizontal_is_refused_in_one_line(capsys):
    assert main(["loads", "--preset", "set2", "--set", "live_load=vertical", "--set", "load_inclination_deg=95"]) != 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "load_inclination_deg" in err[0] and "95" in err[0]


def test_the_dem_takes_a_leaning_load_and_a_tandem_before_yade_starts():
    """The DEM's load path checks its case with the live load set apart (`case.plan.check_dem_load`):
    a lean and further loads pass, a further load that could never stand on the arch is refused there."""
    check_dem_load(_case(LEAN_DEG))
    check_dem_load(_case(0.0, further_loads=[[60.0, 1.0]]))
    with pytest.raises(CaseError, match="longer than the span"):
        check_dem_load(_case(0.0, further_loads=[[5000.0, 1.0]]))
