"""The fill's passive resistance (model/passive_fill.py): a face pushed into the fill mobilises (Kp - K) x
its pressure resultant over u_p and no more, one moving away nothing; a face pushed past u_p has
yielded the fill for good (moving back, its push falls off over u_p, in the static engine's path too);
the static engine's tangent with
the springs is exact; the rigid LP's multiplier is the least of the four-hinge mechanisms by virtual work
with each spring dissipating its capacity (the independent check), stiff joints and a short u_p carry
it within 2 %; the supports carry the weights, the fill and the pushes; bad input is one line."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from conftest import differenced_tangent

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry, backfill, runaway_length
from yadearch.errors import CaseError
from yadearch.model.backfill import fill_faces
from yadearch.model.loads import generalised, live_load_points
from yadearch.model.passive_fill import (
    CAPACITY,
    OUTWARD,
    REFERENCE_X,
    STIFFNESS,
    block_forces,
    block_stiffness,
    spring_state,
    yielded,
)
from yadearch.solve import banded
from yadearch.solve.collapse_mode import CollapseKind
from yadearch.solve.limit import limit_analysis
from yadearch.solve.load_lp import load_analysis
from yadearch.solve.load_path import load_settings, load_the_live_load, static_load_path
from yadearch.solve.mechanisms import mechanism_multiplier
from yadearch.solve.path import path_settings
from yadearch.solve.rigid import LimitError, rigid_arch
from yadearch.solve.static_path import StaticLoading
from yadearch.solve.statics import static_arch
from yadearch.studies.loads.passive import passive_case

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
    faces = [f for f in fill_faces(arch_geometry(case), backfill(case)) if f.height > 0.0]
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


def test_a_face_pushed_past_u_p_has_yielded_the_fill_and_moving_back_loses_its_push_over_u_p():
    """Pushed 3 u_p into the fill the spring carries its capacity (the same before and after the
    yielding's update); moved back by u_p / 2 it pushes half of it, by u_p and more nothing, where an
    elastic spring would still push its whole capacity. A spring that never went past u_p keeps its
    reference: unloading it retraces its loading."""
    arch = static_arch(_case())
    springs = arch.passive
    spring = springs[0]
    block, outward = int(spring[0]), spring[OUTWARD]
    u_p = spring[CAPACITY] / spring[STIFFNESS]
    rest = np.column_stack([arch.centroid0, np.zeros(arch.n_blocks)])

    def pushed_to(reach: float) -> np.ndarray:
        poses = rest.copy()
        poses[block, 0] += outward * reach * u_p
        return poses

    def push(table: np.ndarray, reach: float) -> float:
        return -outward * block_forces(table, pushed_to(reach))[block, 0] / spring[CAPACITY]

    after = yielded(springs, pushed_to(3.0))
    assert push(springs, 3.0) == pytest.approx(1.0, rel=1e-12) and push(after, 3.0) == pytest.approx(1.0, rel=1e-12)
    for back, share in ((0.5, 0.5), (1.0, 0.0), (2.0, 0.0)):
        assert push(after, 3.0 - back) == pytest.approx(share, rel=1e-9, abs=1e-12)
        assert push(springs, 3.0 - back) == pytest.approx(1.0, rel=1e-12)  # the unyielded spring, elastic
    within = yielded(springs, pushed_to(0.6))
    assert np.array_equal(within, springs)
    assert push(within, 0.3) == pytest.approx(0.3, rel=1e-9)


def test_each_state_of_the_static_path_is_in_equilibrium_with_the_yielded_springs_it_hands_on(monkeypatch):
    """The paper's arch settling under its fill (Kp 1, u_p 0.1 mm): every accepted state balances its
    weights, joints and pushes with the springs as it leaves them (yielding changes no push where it
    happens); a spring's reference only ever moves into the fill; by collapse some faces have yielded;
    and springs that never yield (pushing back their capacity until the face is home) give a du more than
    10 % lower (measured: 49.16 against 60.96 mm)."""
    case = passive_case("paper", 1.0, live_load="none", fill_passive_displacement_mm=0.1)
    loading = StaticLoading.of(case)
    loading.selfweight()
    path = loading.follow()
    assert path.collapsed
    arch, converged = loading.arch, loading.solver.converged
    for before, state in zip(loading.accepted, loading.accepted[1:]):
        residual = arch.free_state(state.u, state.u, state.forces.shear_force, springs=state.springs)[1]
        assert np.abs(residual).max() <= 2.0 * converged
        moved = state.springs[:, REFERENCE_X] - before.springs[:, REFERENCE_X]
        assert np.all(state.springs[:, OUTWARD] * moved >= 0.0)
    yielded_faces = loading.accepted[-1].springs[:, REFERENCE_X] != arch.passive[:, REFERENCE_X]
    assert np.count_nonzero(yielded_faces) > 0
    monkeypatch.setattr(type(arch), "yielded", lambda self, springs, u: self.springs_or_unyielded(springs))
    forgetful = StaticLoading.of(case)
    forgetful.selfweight()
    assert forgetful.follow().du < 0.9 * path.du


def test_a_descent_that_does_not_come_to_rest_hands_on_the_springs_it_started_from():
    """The fill yields only where the blocks rest in equilibrium: a descent cut short (a timeout) or run
    away leaves the springs as they were, however far its faces pushed on the way."""
    case = passive_case("paper", 1.0, live_load="none", fill_passive_displacement_mm=0.1)
    loading = StaticLoading.of(case)
    loading.selfweight()
    arch, state = loading.arch, loading.accepted[0]
    pushed = state.u.copy()
    pushed[arch.free_dofs[0::3]] += np.sign(arch.centroid0[1:-1, 0]) * 5e-3  # every face 5 mm into the fill
    for budget, bound in ((2, 1.0), (4000, 1e-4)):  # a timeout, a runaway
        found = loading.solver.descend(
            pushed, state.u, state.forces.shear_force, bound, iterations=budget, springs=state.springs
        )
        assert found.verdict != "stable"
        assert np.array_equal(found.springs, state.springs)


def test_the_springs_tangent_in_the_static_engine_is_exact():
    """The springs' part of K = -dR/du (K less the same arch's without springs) against central
    differences of their part of the residual, at a state that pushes some faces into the fill within
    u_p (their spring elastic) and turns every voussoir."""
    case = _case(fill_passive_displacement_mm=5.0)
    loading = StaticLoading.of(case)
    loading.selfweight()
    arch, state = loading.arch, loading.accepted[0]
    bare = replace(arch, passive=arch.passive[:0])
    u = state.u.copy()
    u[arch.free_dofs[0::3]] += np.linspace(-2e-3, 2e-3, len(arch.free_dofs) // 3)  # the ring swayed
    u[arch.free_dofs[2::3]] += 0.02 * arch.length
    pushes = arch.passive_forces(u)[:, 0]
    assert np.count_nonzero(pushes) >= 2 and np.abs(pushes).max() < arch.passive[:, CAPACITY].max()  # elastic
    shear = state.forces.shear_force
    springs = banded.to_dense(arch.free_state(u, state.u, shear)[2] - bare.free_state(u, state.u, shear)[2])
    differences = differenced_tangent(arch, u, state.u, shear, FD_STEP) - differenced_tangent(
        bare, u, state.u, shear, FD_STEP
    )
    assert np.abs(springs).max() > 0.0
    assert np.abs(springs - differences).max() < 1e-6 * np.abs(springs).max()


def test_the_dems_stability_tangent_of_the_springs_is_their_forces_derivative():
    """`block_stiffness` (the DEM's stability test) against central differences of `block_forces`."""
    arch = static_arch(_case(fill_passive_displacement_mm=5.0))
    rng = np.random.default_rng(7)
    poses = np.column_stack([arch.centroid0, np.zeros(arch.n_blocks)])
    poses[:, 0] += rng.uniform(-2e-3, 2e-3, arch.n_blocks)
    poses[:, 2] += rng.uniform(-0.02, 0.02, arch.n_blocks)
    lever = arch.length
    stiffness = block_stiffness(arch.passive, poses, lever)
    differences = np.zeros_like(stiffness)
    for column in range(stiffness.shape[0]):
        block, dof = divmod(column, 3)
        up, down = poses.copy(), poses.copy()
        step = FD_STEP / lever if dof == 2 else FD_STEP
        up[block, dof] += step
        down[block, dof] -= step
        forward, backward = block_forces(arch.passive, up), block_forces(arch.passive, down)
        forward[:, 2] /= lever
        backward[:, 2] /= lever
        differences[:, column] = -(forward - backward).ravel() / (2.0 * FD_STEP)
    assert np.abs(stiffness).max() > 0.0
    assert np.abs(stiffness - differences).max() < 1e-6 * np.abs(stiffness).max()


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


def test_the_supports_carry_the_weights_the_fill_the_load_and_the_pushes():
    """At the last stable state of the load path, where the pushes are tens of newtons."""
    case = _case()
    loading = StaticLoading(static_arch(case), path_settings(case.numerics, 10.0), runaway_length(case))
    loading.selfweight()
    load_the_live_load(loading, load_settings(load_analysis(case).multiplier, case.numerics.increment_growth))
    loading.follow()
    arch, state = loading.arch, loading.accepted[-1]
    pushes = arch.passive_forces(state.u)[1:-1, 0].sum()
    assert abs(pushes) > 1.0  # newtons
    pressing = -state.forces.block_force[[0, -1]].sum(axis=0)
    loads = arch.dead[1:-1, 0:2].sum(axis=0) + state.lam * arch.live[1:-1, 0:2].sum(axis=0)
    assert pressing[1] == pytest.approx(arch.weight[1:-1].sum() - loads[1], rel=1e-9)
    assert pressing[0] == pytest.approx(-(loads[0] + pushes), abs=1e-9 * pressing[1])  # what the supports push with


def test_a_fold_that_leans_on_the_fills_springs_turns_the_four_hinges_the_dem_shows():
    """The paper's arch at Kp 1: the fold's motion turns the DEM's four hinges (6I 18E 31I 50E, one
    joint apart at most), the outer two less than the crown's, the fill's springs still elastic there."""
    path = static_load_path(passive_case("paper", 1.0), descend_to=None)
    assert path.kind == CollapseKind.MECHANISM
    found = [(int(h[:-1]), h[-1]) for h in path.hinges]
    dem = [(6, "I"), (18, "E"), (31, "I"), (50, "E")]
    assert len(found) == len(dem) and all(s == t and abs(j - k) <= 1 for (j, s), (k, t) in zip(found, dem))
    assert static_load_path(passive_case("paper", 0.0), descend_to=None).kind == CollapseKind.MECHANISM


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
