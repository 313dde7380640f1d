"""Support movements (no YADE): the springing point travels the path at unit rate whether the
support translates or turns, the left support mirrors the right one, and the generalised velocity
the limit analysis uses is the motion's own."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.case.mechanics import arch_geometry
from yadearch.case.support import case_movement
from yadearch.errors import CaseError

LAM = 0.02  # m of path


@pytest.fixture(scope="module")
def geometry():
    return arch_geometry(preset("set2"))


def movement(**loading):
    case = preset("set2").with_overrides(loading)
    return case_movement(case, arch_geometry(case))


@pytest.mark.parametrize(
    "loading",
    [
        {},
        {"support_direction_deg": 0.0},
        {"support_motion": "rotation", "rotation_pivot_dy_mm": -200.0},
        {"support_motion": "rotation", "rotation_pivot_dx_mm": 50.0, "rotation_sense": "counterclockwise"},
    ],
)
def test_the_springing_point_travels_the_path_length(loading):
    """Along a straight line for a translation, an arc for a rotation: du is the path length."""
    ref = movement(**loading).reference
    points = np.array([ref.carry(ref.springing, lam) for lam in np.linspace(0.0, LAM, 2001)])
    travelled = np.linalg.norm(np.diff(points, axis=0), axis=1).sum()
    assert travelled == pytest.approx(LAM, rel=1e-6)


def test_the_default_settles_the_right_support_straight_down():
    move = movement()
    assert move.left is None and not move.rotates
    dx, dy = move.components(LAM)
    assert dx == pytest.approx(0.0, abs=1e-15) and dy == pytest.approx(-LAM)


def test_a_clockwise_turn_about_a_pivot_below_moves_the_springing_outward_and_down():
    move = movement(support_motion="rotation", rotation_pivot_dy_mm=-200.0)
    dx, dy = move.components(LAM)
    assert dx > 0.0 and dy < 0.0 and move.rotation(LAM) < 0.0
    ref = move.reference
    pivot_after = ref.carry(ref.pivot, LAM)
    assert np.allclose(pivot_after, ref.pivot, atol=1e-15)  # the pivot stays put


def test_both_supports_move_as_mirror_images():
    move = movement(moving_support="both", support_motion="rotation", rotation_pivot_dy_mm=-150.0)
    right, left = move.right.carry(move.right.springing, LAM), move.left.carry(move.left.springing, LAM)
    assert left == pytest.approx(right * np.array([-1.0, 1.0]))
    assert move.left.rotation == -move.right.rotation


@pytest.mark.parametrize(
    "loading, itself",
    [
        ({"support_direction_deg": 0.0}, True),
        ({"support_direction_deg": 180.0}, True),
        ({"moving_support": "both"}, True),
        ({}, False),
        ({"support_direction_deg": -45.0}, False),
        ({"support_motion": "rotation", "rotation_pivot_dy_mm": -100.0}, False),
        ({"support_motion": "path", "path_mm_mrad": [[10.0, 0.0, 0.0], [30.0, 0.0, 0.0]]}, True),
        ({"support_motion": "path", "path_mm_mrad": [[0.0, -20.0, 0.0], [60.0, -20.0, 0.0]]}, False),
    ],
)
def test_a_movement_is_its_own_mirror_image_only_when_level_or_symmetric(loading, itself):
    """A level slide of one support mirrors to the same slide plus a rigid shift of the whole arch;
    anything vertical or turning mirrors to another movement (the keystone's tie then matters)."""
    assert movement(**loading).mirror_is_itself is itself


def test_the_rates_at_the_origin_move_every_support_point_as_the_placement_does():
    """v(point) = v_origin + omega z x point: the generalised velocity of the limit analysis."""
    ref = movement(support_motion="rotation", rotation_pivot_dx_mm=30.0, rotation_pivot_dy_mm=-120.0).reference
    point = ref.springing + np.array([0.01, -0.05])
    h = 1e-7
    numeric = (ref.carry(point, LAM + h) - ref.carry(point, LAM - h)) / (2 * h)
    vx, vy, omega = ref.rates(LAM)
    now = ref.carry(point, LAM)
    assert numeric == pytest.approx([vx - omega * now[1], vy + omega * now[0]], rel=1e-6)
    central = (ref.displacement_of(now, LAM, h) - ref.displacement_of(now, LAM, -h)) / (2 * h)
    assert numeric == pytest.approx(central, rel=1e-6)
    assert ref.carry(point, LAM + 0.003) == pytest.approx(now + ref.displacement_of(now, LAM, 0.003), abs=1e-15)


def test_equal_settlements_of_both_supports_carry_the_arch_rigidly():
    assert movement(moving_support="both").moves_rigidly
    assert not movement(moving_support="both", support_direction_deg=0.0).moves_rigidly


def test_a_pivot_on_the_springing_point_is_refused_in_one_line(geometry):
    half = math.hypot(*(np.asarray(geometry.joints[-1].extrados[:2]) - geometry.joints[-1].intrados[:2])) / 2
    angle = math.atan2(*(np.asarray(geometry.joints[-1].extrados[:2]) - geometry.joints[-1].intrados[:2])[::-1])
    with pytest.raises(CaseError, match="rotation_pivot_dx_mm"):
        movement(
            support_motion="rotation",
            rotation_pivot_dx_mm=1e3 * half * math.cos(angle),
            rotation_pivot_dy_mm=1e3 * half * math.sin(angle),
        )


@pytest.mark.parametrize(
    "loading, expected",
    [
        ({}, 640.0),  # a settlement: no horizontal component, the default acceleration to the bit
        ({"support_direction_deg": 0.0}, 5.0),
        ({"support_direction_deg": -45.0}, 5.0 / math.cos(math.radians(45.0))),
        ({"support_direction_deg": 0.0, "support_horizontal_acceleration_mm_per_s2": 0.0}, 640.0),  # no cap
        ({"support_motion": "rotation", "rotation_pivot_dy_mm": -200.0}, 5.007),  # the springing starts sideways
    ],
)
def test_the_support_accelerates_gently_where_it_moves_sideways(loading, expected):
    """A horizontal jolt loads the arch like a ground acceleration (docs/validation.md): its
    horizontal component stays within support_horizontal_acceleration_mm_per_s2 (5 mm/s2)."""
    from yadearch.case.support import support_acceleration_mm_per_s2

    case = preset("set2").with_overrides(loading)
    accel = support_acceleration_mm_per_s2(case, case_movement(case, arch_geometry(case)))
    assert accel == pytest.approx(expected, rel=1e-2)
    assert accel == 640.0 or accel * case_movement(case, arch_geometry(case)).horizontal_share <= 5.0 + 1e-9


def test_runs_the_cap_does_not_change_stay_comparable_with_older_ones():
    """A settlement run from before the cap ran as a settlement runs now; a spreading one did not."""
    from yadearch.case.comparison import as_ran

    for direction, same in ((-90.0, True), (0.0, False)):
        old = preset("set2").replace(support_direction_deg=direction).to_dict()
        del old["numerics"]["support_horizontal_acceleration_mm_per_s2"]  # a case.toml of before
        now = preset("set2").replace(support_direction_deg=direction).to_dict()
        assert (as_ran(old) == as_ran(now)) is same
