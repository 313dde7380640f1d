"""Support movements on real YADE (a coarse arch, a few thousand steps each): a turning support
follows its prescribed rotation about a pivot that stays put, and both supports move as mirror
images, each along the path the case describes (docs/movements.md)."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import HAS_YADE, needs_yade

from yadearch.case.config import preset
from yadearch.case.support import movement_overrides
from yadearch.dem.yade_env import import_yade
from yadearch.model import units
from yadearch.model.joints import rotate

pytestmark = [needs_yade, pytest.mark.yade]
if HAS_YADE:
    import_yade()

COARSE = {"n_voussoirs": 15, "kn_N_per_mm3": 0.25, "progress_every_s": 1e9}
PATH_MM = 3.0
PLACE_TOLERANCE_M = 1e-9  # the supports move by velocity x dt: their placement drifts by round-off only
STIFF_KN = 300.0  # N/mm3: joints stiff enough to stand for rigid blocks
PLACED_AT_MM = 6.0  # support path where the rigid state is put in the scene (every rigid hinge beyond 4 mrad)
HINGE_MRAD = 2.0  # a relative turn beyond this is a hinge (the runs' hinge_rotation_mrad)
STAYS_MM = 0.05  # a released state that moves less than this has stayed where it was put


def support_placement(state, pos0: np.ndarray, ori0) -> tuple[float, np.ndarray]:
    """(rotation, shift) of a support body since (pos0, ori0): a point X is now at R X + shift."""
    turn = state.ori * ori0.conjugate()
    angle = 2.0 * np.arctan2(turn[2], turn[3])
    pos = np.array([state.pos[0], state.pos[1]])
    return float(angle), pos - rotate(pos0, angle)


@pytest.mark.parametrize("movement", ["abutment_tilt", "symmetric_spreading"])
def test_moving_supports_follow_the_path_the_case_describes(movement):
    from yade import O

    from yadearch.dem.runner import Runner

    runner = Runner(preset("set1").with_overrides({**COARSE, **movement_overrides(movement)}), log=lambda line: None)
    try:
        runner.selfweight()
        ids = {"left": runner.scene.left_support, "right": runner.scene.right_support}
        start = {side: (np.array(O.bodies[i].state.pos)[:2], O.bodies[i].state.ori) for side, i in ids.items()}
        runner.move_to(runner.delta() + units.mm(PATH_MM))
        assert runner.delta() == pytest.approx(units.mm(PATH_MM), abs=1e-9)
        for side, body in ids.items():
            motion = runner.movement.motion(side)
            angle, shift = support_placement(O.bodies[body].state, *start[side])
            if motion is None:
                assert angle == 0.0 and np.all(shift == 0.0)
                continue
            expected_angle, expected_shift = motion.placement(units.mm(PATH_MM))
            assert angle == pytest.approx(expected_angle, abs=1e-12)
            assert shift == pytest.approx(expected_shift, abs=PLACE_TOLERANCE_M)
            pivot_now = rotate(motion.pivot, angle) + shift
            assert pivot_now == pytest.approx(
                motion.pivot + motion.translation * units.mm(PATH_MM), abs=PLACE_TOLERANCE_M
            )
    finally:
        runner.close()


def test_a_support_on_a_prescribed_path_turns_its_corners_where_the_table_puts_them():
    """Down 1 mm, then 1.5 mm outward while turning 3 mrad: at each row the right support stands
    where the table says, and the driver reads the path length back from its placement."""
    from yade import O

    from yadearch.dem.runner import Runner

    rows = [[0.0, -1.0, 0.0], [1.5, -1.0, 3.0]]
    case = preset("set1").with_overrides({**COARSE, "loading.support_motion": "path", "loading.path_mm_mrad": rows})
    runner = Runner(case, log=lambda line: None)
    try:
        runner.selfweight()
        body = runner.scene.right_support
        start = (np.array(O.bodies[body].state.pos)[:2], O.bodies[body].state.ori)
        motion = runner.movement.right
        for path_mm in (1.0, 2.5):
            runner.move_to(units.mm(path_mm))
            assert runner.delta() == pytest.approx(units.mm(path_mm), abs=1e-9)
            angle, shift = support_placement(O.bodies[body].state, *start)
            expected_angle, expected_shift = motion.placement(units.mm(path_mm))
            assert angle == pytest.approx(expected_angle, abs=1e-9)
            assert shift == pytest.approx(expected_shift, abs=PLACE_TOLERANCE_M)
        springing = rotate(motion.springing, angle) + shift - motion.springing
        assert springing == pytest.approx(units.mm(np.array(rows[-1][:2])), abs=PLACE_TOLERANCE_M)
        assert angle == pytest.approx(units.mrad(rows[-1][2]), abs=1e-9)
    finally:
        runner.close()


@pytest.mark.parametrize("mirrored", [False, True])
def test_the_rigid_analysis_state_is_an_equilibrium_of_stiff_joints(mirrored):
    """Put where the rigid analysis has it 6 mm down and out at 45 deg, on either branch of the
    keystone's tie, an arch of stiff joints stays there: released from rest it moves by far less
    than a millimetre and turns on the rigid hinges (docs/validation.md)."""
    from yadearch.dem.runner import Runner
    from yadearch.dem.scene_state import place_voussoirs
    from yadearch.solve.pose import rigid_pose
    from yadearch.solve.stages import Verdict

    # the support's horizontal acceleration uncapped: the blocks are placed after the move, whose
    # dynamics leave nothing behind (capped at 5 mm/s², the move made the test 82 s instead of 12)
    case = preset("set2").with_overrides(
        {
            **COARSE,
            "kn_N_per_mm3": STIFF_KN,
            "support_direction_deg": -45.0,
            "support_horizontal_acceleration_mm_per_s2": 0.0,
        }
    )
    centroids, turns = rigid_pose(case, PLACED_AT_MM, mirrored)
    rigid_hinges = set(np.flatnonzero(np.abs(np.diff(turns)) > units.mrad(HINGE_MRAD)) + 1)
    runner = Runner(case, log=lambda line: None)
    try:
        runner.selfweight()
        runner.move_to(units.mm(PLACED_AT_MM))
        place_voussoirs(runner.scene, centroids, turns)
        assert runner.hold() == Verdict.STABLE
        assert runner.hold_move < units.mm(STAYS_MM)
        _, hinges = runner.recorder.joint_snapshot()
        assert {h.interface for h in hinges} == rigid_hinges
    finally:
        runner.close()
