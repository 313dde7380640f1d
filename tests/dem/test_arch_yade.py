"""A coarse arch on real YADE, with each contact model: equilibrium under self-weight, also with
voussoirs of erroneous dimensions (built touching, they stand with every joint closed and carrying
compression, no joint overlapping beyond its elastic closure), then three hinges under settlement."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import HAS_YADE, needs_yade

from yadearch.case.config import preset
from yadearch.dem.yade_env import import_yade
from yadearch.model import units

pytestmark = [needs_yade, pytest.mark.yade]
if HAS_YADE:
    import_yade()

COARSE = {"n_voussoirs": 15, "kn_N_per_mm3": 0.25, "equilibrium_tolerance": 1e-4, "progress_every_s": 1e9}
ERRORS = {"voussoir_length_sd_mm": 0.5, "voussoir_thickness_sd_mm": 1.0, "seed": 2}
OVERLAP_TOLERANCE = 1.5  # no joint closes more than this times the perfect arch's largest closure


def _overlaps(runner) -> tuple[dict, np.ndarray]:
    """The joint snapshot and each joint's largest overlap (mm) of a settled arch."""
    snap, _ = runner.recorder.joint_snapshot()
    js = snap["js"]
    return snap, -units.to_mm(np.minimum(js.opening_intrados, js.opening_extrados))


# The tests share one arch and run in file order, each settling the support further: the holds come
# first, while the arch is far from collapse (a hold near it may time out), the 12 mm move last.
@pytest.fixture(scope="module", params=["joint", "cgal"])
def settled(request):
    """A 15-voussoir version of the paper's arch after the self-weight stage, and what the same arch
    of voussoirs with dimension errors settled to before it (self-weight info, joint snapshot, overlaps;
    one scene at a time, so it runs first), with the perfect arch's settled overlaps beside them."""
    from yadearch.dem.runner import Runner

    case = preset("set1").with_overrides({**COARSE, "contact_model": request.param})
    imperfect = Runner(case.with_overrides(ERRORS), log=lambda line: None)
    try:
        errors = (imperfect.selfweight(), *_overlaps(imperfect))
    finally:
        imperfect.close()
    runner = Runner(case, log=lambda line: None)
    info = runner.selfweight()
    yield runner, info, (*errors, _overlaps(runner)[1])
    runner.close()


def test_self_weight_is_carried_by_the_supports(settled):
    runner, info, _ = settled
    assert info["vertical_reaction_sum_N"] == pytest.approx(info["arch_weight_N"], rel=0.005)
    assert abs(info["horizontal_reaction_sum_N"]) < 0.005 * info["thrust_N"]  # equal, opposite thrusts
    # a no-tension arch of this shape pushes outwards: thrust between 0.2 and 0.6 of its weight
    assert 0.2 < info["thrust_N"] / info["arch_weight_N"] < 0.6


def test_voussoirs_with_dimension_errors_stand_in_contact_under_their_weight(settled):
    _, _, (info, snap, overlap, perfect) = settled
    assert info["vertical_reaction_sum_N"] == pytest.approx(info["arch_weight_N"], rel=0.005)
    assert (overlap > 0.0).all() and (snap["normal"] > 0.0).all()  # every joint touches and carries
    assert overlap.max() < OVERLAP_TOLERANCE * perfect.max()


def test_settlement_opens_three_hinges_where_the_mechanism_puts_them(settled):
    runner, *_ = settled
    runner.stage = "loading"
    runner.move_to(units.mm(8.0))
    assert runner.hold() == "stable"  # 8 mm is far from collapse: the arch follows the support
    _, hinges = runner.recorder.joint_snapshot()
    labels = [(h.interface, h.side) for h in hinges]
    n = 15
    assert len(hinges) == 3, labels
    a, b, c = hinges
    assert a.side == "I" and 2 <= a.interface <= n // 2  # A: intrados, left haunch
    assert b.side == "E" and n // 2 < b.interface < n + 1  # B: extrados, right of the crown
    assert (c.interface, c.side) == (n + 1, "E")  # C: extrados at the settling support


def test_collider_pairs_only_blocks_that_share_a_joint():
    from yade import O

    from yadearch.dem.scene import build_scene

    scene = build_scene(preset("set1").with_overrides({**COARSE, "contact_model": "cgal"}))
    O.run(200, True)  # the arch settles onto its joints
    ids = scene.body_ids
    pairs = {(min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions}
    assert pairs == {(ids[k], ids[k + 1]) for k in range(len(ids) - 1)}  # 16 joints, no other pair


def test_a_snapshot_puts_the_arch_back_where_it_was(settled):
    """The search goes back to saved states: a restored snapshot must be the saved configuration
    (support included), with its shear forces, and stand in equilibrium as it did."""
    runner, *_ = settled
    runner.stage = "loading"
    runner.move_to(runner.delta() + units.mm(2.0))
    assert runner.hold() == "stable"
    snapshot, delta = runner.snapshot(), runner.delta()
    positions, shear = runner.positions(), runner.scene.contacts.joint_contacts()[2]
    speeds = runner.recorder.voussoir_speeds()
    runner.move_to(delta + units.mm(3.0))
    runner.run_steps(50)  # caught moving: the restore must bring back the saved velocities too
    assert abs(runner.positions() - positions).max() > units.mm(0.5)  # it did move
    assert abs(runner.recorder.voussoir_speeds() - speeds).max() > units.mm(1.0)
    runner.restore(snapshot)
    assert runner.delta() == pytest.approx(delta, abs=1e-12)
    assert abs(runner.positions() - positions).max() < 1e-12
    assert abs(runner.recorder.voussoir_speeds() - speeds).max() < 1e-12
    assert (runner.scene.contacts.joint_contacts()[2] == shear).all()
    assert runner.hold() == "stable"
    assert abs(runner.positions() - positions).max() < units.mm(0.05)


def test_holds_run_at_hold_damping_and_moves_at_the_loading_damping(settled):
    """du must not depend on the loading damping: the equilibrium verdicts use their own damping."""

    runner, *_ = settled
    num = runner.num
    loading, num.hold_damping = num.hold_damping, 0.35
    try:
        runner.move_to(runner.delta() + units.mm(0.5))
        assert runner.scene.newton.damping == num.damping
        assert runner.hold() == "stable"
        assert runner.scene.newton.damping == 0.35
        runner.move_to(runner.delta() + units.mm(0.5))
        assert runner.scene.newton.damping == num.damping
    finally:
        num.hold_damping = loading


def test_support_follows_the_trapezoidal_profile_to_its_target(settled):
    """The driver sleeps while it cruises and while the support stands still; the support must still
    arrive exactly, in the steps the trapezoid takes (ramp up, cruise, ramp down)."""
    from yade import O

    runner, *_ = settled
    driver = runner.driver
    start, start_iter = runner.delta(), O.iter
    runner.move_to(start + units.mm(12.0))
    assert runner.delta() - start == pytest.approx(units.mm(12.0), abs=1e-9)
    v, ramp = driver.speed, driver.ramp  # 12 mm = 5 mm up + 2 mm cruise + 5 mm down
    expected_steps = (2 * (2 * ramp / v) + units.mm(2.0) / v) / O.dt
    assert O.iter - start_iter == pytest.approx(expected_steps, rel=0.02, abs=3 + 50)
    assert tuple(O.bodies[runner.scene.right_support].state.vel) == (0.0, 0.0, 0.0)


def test_an_engine_error_fails_the_run_in_one_line_instead_of_hanging(settled):
    from yadearch.errors import RunFailedError

    runner, *_ = settled
    contacts = runner.scene.contacts
    original = contacts.step
    contacts.step = lambda: 1 / 0  # a Python engine of the scene raises inside YADE's loop
    try:
        with pytest.raises(RunFailedError, match="an engine probably raised"):
            runner.run_steps(100)
    finally:
        contacts.step = original
        runner.close()
