"""A prescribed support path (no YADE): the springing point runs through the table's rows, the
support turns as they say, du is the distance along the polyline, and the limit analysis follows a
path that turns a corner (docs/movements.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.case.mechanics import arch_geometry
from yadearch.case.support import case_movement, movement_overrides
from yadearch.errors import CaseError
from yadearch.solve.limit import limit_analysis

ROWS_MM_MRAD = [[0.0, -3.0, 0.0], [4.0, -3.0, 2.0], [4.0, -8.0, 5.0]]  # down, out while turning, down again
LENGTH_M = 0.003 + 0.004 + 0.005


def path_case(rows=ROWS_MM_MRAD, **loading):
    return preset("set2").with_overrides({"loading.support_motion": "path", "loading.path_mm_mrad": rows, **loading})


def movement(rows=ROWS_MM_MRAD, **loading):
    case = path_case(rows, **loading)
    return case_movement(case, arch_geometry(case))


def test_the_springing_point_passes_every_row_at_its_distance_along_the_path():
    move = movement()
    ref = move.reference
    assert move.length == pytest.approx(LENGTH_M) and move.corners == pytest.approx((0.003, 0.007))
    assert move.horizontal_share == 1.0  # its second segment runs sideways: the gentle acceleration
    assert movement([[0.0, -3.0, 0.0], [3.0, -7.0, 0.0]]).horizontal_share == pytest.approx(0.6)
    for lam, (dx, dy, turn) in zip((0.003, 0.007, LENGTH_M), ROWS_MM_MRAD):
        assert move.components(lam) == pytest.approx((dx * 1e-3, dy * 1e-3), abs=1e-15)
        assert move.rotation(lam) == pytest.approx(turn * 1e-3, abs=1e-15)
        assert ref.carry(ref.springing, lam) - ref.springing == pytest.approx([dx * 1e-3, dy * 1e-3], abs=1e-15)
    points = np.array([ref.carry(ref.springing, lam) for lam in np.linspace(0.0, LENGTH_M, 3001)])
    assert np.linalg.norm(np.diff(points, axis=0), axis=1).sum() == pytest.approx(LENGTH_M, rel=1e-9)


def test_the_rates_and_the_exact_step_agree_with_the_placement_inside_a_segment():
    ref = movement().reference
    lam, h = 0.005, 1e-8
    point = ref.springing + np.array([0.02, -0.04])
    now = ref.carry(point, lam)
    numeric = (ref.carry(point, lam + h) - ref.carry(point, lam - h)) / (2 * h)
    vx, vy, omega = ref.rates(lam)
    assert numeric == pytest.approx([vx - omega * now[1], vy + omega * now[0]], rel=1e-6)
    # across a corner the exact step lands where the placement puts the point
    assert ref.carry(point, 0.0075) == pytest.approx(now + ref.displacement_of(now, lam, 0.0025), abs=1e-15)


def test_the_path_length_is_read_back_from_the_support_placement_even_where_the_path_doubles_back():
    ref = movement([[0.0, -4.0, 0.0], [0.0, -1.0, 0.0]]).reference  # down 4 mm, back up 3 mm
    centroid0 = ref.springing + np.array([0.01, -0.02])
    for lam in (0.001, 0.002, 0.0035, 0.005, 0.006):
        angle, shift = ref.placement(lam)
        centroid = ref.carry(centroid0, lam)
        near = ref.travelled(centroid0, centroid, angle, hint=lam + 1e-5)
        assert near == pytest.approx(lam, abs=1e-12)


def test_the_left_support_follows_the_mirror_image():
    move = movement(moving_support="both")
    right, left = move.right, move.left
    for lam in (0.002, 0.006, 0.011):
        assert left.carry(left.springing, lam) == pytest.approx(right.carry(right.springing, lam) * [-1.0, 1.0])
        assert left.angle(lam) == -right.angle(lam)
    assert not move.moves_rigidly
    assert movement([[0.0, -5.0, 0.0], [0.0, -9.0, 0.0]], moving_support="both").moves_rigidly


@pytest.mark.parametrize(
    "rows, match",
    [
        ([[0.0, 0.0, 3.0]], "row 1 does not move the springing point"),
        ([[1.0, 2.0]], r"path_mm_mrad must be a list of \[dx_mm, dy_mm, rotation_mrad\] rows; row 1"),
        ([[1.0, "a", 0.0]], "row 1"),
        ([], "needs at least one row"),
    ],
)
def test_a_bad_path_is_refused_in_one_line(rows, match):
    with pytest.raises(CaseError, match=match) as caught:
        movement(rows)
    assert "\n" not in str(caught.value)


def test_a_straight_path_is_the_straight_translation():
    straight = limit_analysis(path_case([[0.0, -150.0, 0.0]]))
    settlement = limit_analysis(preset("set2"))
    assert straight.du_rigid_mm == pytest.approx(settlement.du_rigid_mm, abs=1e-6)
    assert straight.collapse_hinges == settlement.collapse_hinges


def test_the_limit_analysis_follows_a_path_round_its_corner_and_stops_at_its_end():
    case = preset("set2").with_overrides(movement_overrides("settle_then_spread"))
    result = limit_analysis(case)
    spreading_alone = limit_analysis(preset("set2").replace(support_direction_deg=0.0))
    # 20 mm of settlement leaves the arch standing; the spreading that follows collapses it
    assert 20.0 < result.du_rigid_mm < 20.0 + 60.0
    assert result.du_rigid_mm - 20.0 < spreading_alone.du_rigid_mm
    short = limit_analysis(path_case([[0.0, -10.0, 0.0]]))
    assert short.du_rigid_mm is None and short.collapse_mode == "none"  # the path ends first


def test_the_limit_analysis_turns_the_support_along_a_turning_path():
    """The moving support's block stands where the path puts it at the last admissible state: its
    turn is the path's angle there (to round-off)."""
    case = path_case()
    result = limit_analysis(case)
    end = result.du_rigid_mm if result.du_rigid_mm is not None else movement().length * 1e3
    assert result.rotation_rad[-1] == pytest.approx(movement().reference.angle(end * 1e-3), abs=1e-12)
    assert result.rotation_rad[0] == 0.0  # the left support stays


def test_a_path_round_trips_through_toml(tmp_path):
    from yadearch.case.config import load_case

    case = path_case()
    (tmp_path / "case.toml").write_text(case.to_toml())
    assert load_case(tmp_path / "case.toml").loading.path_mm_mrad == ROWS_MM_MRAD
    assert not math.isinf(case_movement(case, arch_geometry(case)).length)
