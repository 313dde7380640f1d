"""The fill's passive resistance (model/passive_fill.py): a face pushed into the fill mobilises (Kp - K) x
its pressure resultant over u_p and no more, one moving away nothing; the static engine's tangent with
the springs is exact; the rigid LP's multiplier is the least of the four-hinge mechanisms by virtual work
with each spring dissipating its capacity (the independent check), stiff joints and a short u_p carry
it within 2 %; the supports carry the weights, the fill and the pushes; bad input is one line."""

from __future__ import annotations

import numpy as np
import pytest

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry, backfill
from yadearch.errors import CaseError
from yadearch.model.backfill import fill_faces
from yadearch.model.loads import generalised, live_load_points
from yadearch.model.passive_fill import CAPACITY, OUTWARD, STIFFNESS, block_forces, spring_state
from yadearch.solve import banded
from yadearch.solve.limit import limit_analysis
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import static_load_path
from yadearch.solve.mechanisms import mechanism_multiplier
from yadearch.solve.rigid import LimitError, rigid_arch
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import static_arch

SMALL = {"n_voussoirs": 15, "live_load": "vertical", "load_position_over_span": 0.3, "friction_deg": 80.0}
FILL = {"fill_depth_mm": 20.0, "fill_lateral_coefficient": 0.3, "fill_passive_coefficient": 1.0}
FD_STEP = 1e-9  # m
RIGID_TOLERANCE = 0.02  # stiff static within 2 % of the rigid capacity (issue 44)


def _case(**more) -> ArchCase:
    return ArchCase(name="passive").with_overrides({**SMALL, **FILL, **more})


def test_a_spring_mobilises_its_share_linearly_up_to_its_capacity_and_nothing_moving_away():
    case = _case()
    arch = static_arch(case)
    springs = arch.passive
    faces = [f for f in fill_faces(arch_geometry(case), arch.centroid0, backfill(case)) if f.height > 0.0]
    assert len(springs) == len(faces) > 0  # every face but a level one (the keystone's)
    expected = (1.0 - 0.3) * np.array([f.mean * f.height for f in faces])
    assert np.allclose(springs[:, CAPACITY], expected, rtol=1e-12)
    spring = springs[0]
    u_p = spring[CAPACITY] / spring[STIFFNESS]
    assert u_p == pytest.approx(1e-3, rel=1e-12)  # fill_passive_displacement_mm's default, 1 mm
    x0 = arch.centroid0[int(spring[0]), 0]
    outward = spring[OUTWARD]
    for moved, share in ((-0.5, 0.0), (0.0, 0.0), (0.25, 0.25), (0.5, 0.5), (2.0, 1.0)):
        force, *_ = spring_state(spring, x0 + outward * moved * u_p, 0.0)
        assert force == pytest.approx(-outward * share * spring[CAPACITY], rel=1e-12, abs=1e-15)


def test_the_springs_tangent_in_the_static_engine_is_exact():
    """K = -dR/du with the springs against central differences of the residual, at a state that pushes
    some faces into the fill within u_p (their spring elastic) and turns every voussoir."""
    case = _case(fill_passive_displacement_mm=5.0)
    loading = StaticLoading.of(case)
    loading.selfweight()
    arch, state = loading.arch, loading.accepted[0]
    u = state.u.copy()
    u[arch.free_dofs[0::3]] += np.linspace(-2e-3, 2e-3, len(arch.free_dofs) // 3)  # the ring swayed
    u[arch.free_dofs[2::3]] += 0.02 * arch.length
    forces = block_forces(arch.passive, np.column_stack([arch.poses(u)[0], arch.poses(u)[1]]))
    assert np.count_nonzero(forces[:, 0]) >= 2  # some springs pushed ...
    shear = state.forces.shear_force
    _, _, band = arch.free_state(u, state.u, shear)
    stiffness = banded.to_dense(band)
    differences = np.empty_like(stiffness)
    for column, k in enumerate(arch.free_dofs):
        up, down = u.copy(), u.copy()
        up[k] += FD_STEP
        down[k] -= FD_STEP
        forward, backward = arch.free_state(up, state.u, shear)[1], arch.free_state(down, state.u, shear)[1]
        differences[:, column] = -(forward - backward) / (2.0 * FD_STEP)
    assert np.abs(stiffness - differences).max() < 1e-5 * np.abs(stiffness).max()


def test_the_lp_with_passive_resistance_is_the_least_mechanism_and_above_the_lp_without():
    case = _case()
    arch = rigid_arch(case)
    live = generalised(live_load_points(arch.geometry, arch.centroid0, arch.weight, _load(case)), arch.n_blocks)
    dead = generalised(arch.fixed, arch.n_blocks)
    dead[:, 1] -= arch.weight
    dead[:, 2] -= arch.weight * arch.centroid0[:, 0]
    mechanism, pivots = mechanism_multiplier(arch, dead, live)
    capacity = load_analysis(case)
    assert capacity.multiplier == pytest.approx(mechanism, rel=1e-6)
    assert {(p.joint, p.side) for p in capacity.pivots} == {(p.joint, p.side) for p in pivots}
    assert capacity.multiplier > 1.2 * load_analysis(_case(fill_passive_coefficient=0.0)).multiplier


def test_stiff_joints_and_a_short_mobilisation_carry_the_rigid_capacity():
    case = _case(**{"interface.kn_N_per_mm3": 100_000.0, "fill_passive_displacement_mm": 0.001})
    rigid = load_analysis(case).multiplier
    path = static_load_path(case, descend_to=None)
    assert path.outcome == "collapse"
    assert -RIGID_TOLERANCE < path.capacity / rigid - 1.0 < 0.0


def test_the_supports_carry_the_weights_the_fill_and_the_pushes():
    loading = StaticLoading.of(_case(fill_passive_displacement_mm=0.01))
    loading.selfweight()
    arch, state = loading.arch, loading.accepted[0]
    pressing = -state.forces.block_force[[0, -1]].sum(axis=0)
    poses = np.column_stack([arch.poses(state.u)[0], arch.poses(state.u)[1]])
    pushes = block_forces(arch.passive, poses)[1:-1, 0].sum()
    assert pressing[1] == pytest.approx(arch.weight[1:-1].sum() - arch.dead[1:-1, 1].sum(), rel=1e-9)
    assert pressing[0] == pytest.approx(arch.dead[1:-1, 0].sum() + pushes, abs=1e-9 * pressing[1])


@pytest.mark.parametrize(
    ("overrides", "named"),
    [
        ({"fill_passive_coefficient": 0.2}, "fill_passive_coefficient"),  # not above K 0.3
        ({"fill_depth_mm": 0.0}, "fill_depth_mm"),
    ],
)
def test_a_passive_coefficient_without_meaning_is_refused_in_one_line(overrides, named):
    with pytest.raises(CaseError, match=named) as refused:
        static_arch(_case(**overrides))
    assert "\n" not in str(refused.value)


def test_the_rigid_march_refuses_passive_resistance_in_one_line():
    case = _case(live_load="none")
    with pytest.raises(LimitError, match="fill_passive_coefficient") as refused:
        limit_analysis(case)
    assert "\n" not in str(refused.value)


def _load(case: ArchCase):
    from yadearch.case.mechanics import live_load

    return live_load(case, arch_geometry(case))
