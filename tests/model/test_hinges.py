"""Hinge detection at one state, on constructed joint openings."""

import numpy as np
import pytest

from yadearch.model.hinges import (
    HINGE_CHANGES,
    hinge_change,
    hinge_rotation,
    hinge_zones,
    hinges_at,
    mirror_hinge_labels,
    same_hinges,
)

T = 0.024


def test_three_hinge_pattern_with_a_spread_hinge():
    n = 12
    intrados = np.full(n, -1e-6)
    extrados = np.full(n, -1e-6)
    extrados[3] = 0.8e-3  # I hinge at interface 4 (extrados opens, pivot at intrados)
    intrados[5], intrados[6], intrados[7], intrados[8] = 0.2e-3, 0.5e-3, 0.9e-3, 0.6e-3  # spread E hinge 7-8-9
    intrados[11] = 1.2e-3  # E hinge at the right support
    hinges = hinges_at(hinge_rotation(intrados, extrados, T), 0.2e-3 / T)
    assert [(h.interface, h.side) for h in hinges] == [(4, "I"), (8, "E"), (12, "E")]
    assert hinges[1].interfaces == (7, 8, 9)


def test_a_soft_joint_rotating_by_compression_alone_is_a_hinge():
    intrados = np.array([-1e-5, -0.30e-3, -1e-5])  # intrados crushed into the joint, extrados closed
    extrados = np.array([-1e-5, -0.01e-3, -1e-5])
    hinges = hinges_at(hinge_rotation(intrados, extrados, T), 5e-3)
    assert [(h.interface, h.side) for h in hinges] == [(2, "I")]


def test_uniformly_pressed_joints_give_no_hinge():
    assert hinges_at(hinge_rotation(np.full(5, -1e-5), np.full(5, -1e-5), T), 1e-3) == []


def test_a_hinge_whose_peak_moves_within_its_spread_is_the_same_hinge():
    default = [
        {"interface": 1, "side": "E", "interfaces": [1]},
        {"interface": 11, "side": "I", "interfaces": [10, 11, 12]},
    ]
    shifted = [
        {"interface": 1, "side": "E", "interfaces": [1]},
        {"interface": 12, "side": "I", "interfaces": [11, 12, 13]},
    ]
    moved = [{"interface": 1, "side": "E", "interfaces": [1]}, {"interface": 14, "side": "I", "interfaces": [13, 14]}]
    assert same_hinges(default, shifted)
    assert not same_hinges(default, moved)
    assert not same_hinges(default, default[:1])
    assert not same_hinges(default, [default[0], {**default[1], "side": "E"}])
    assert same_hinges([{"interface": 9, "side": "I"}], [{"interface": 9, "side": "I"}])  # no spread kept


def test_mirror_labels_face_each_other_across_the_crown_and_keep_their_pivot_side():
    # 55 voussoirs: interfaces 1..56; the keystone's joints 28 and 29 face each other
    assert mirror_hinge_labels(["1E", "9I", "28E", "47I"], 56) == ["10I", "29E", "48I", "56E"]
    assert mirror_hinge_labels(mirror_hinge_labels(["8I", "28E", "46I"], 56), 56) == ["8I", "28E", "46I"]


def test_a_hinge_spread_over_many_joints_counts_by_its_summed_turn():
    """A soft ring's fourth hinge: twenty joints each turning 0.012 of the crown's turn (0.24 in all)
    are one hinge, though none alone reaches 0.025; a lone joint's 0.01 is not."""
    turn = np.array([-0.35, 0.0, 1.0, 0.0, -0.7, 0.0, *[0.012] * 20, 0.0, -0.01])
    hinges = hinge_zones(turn, 0.025)
    assert [h.side for h in hinges] == ["E", "I", "E", "I"]
    assert hinges[-1].rotation == pytest.approx(0.24) and hinges[0].interface == 1
    assert [h.label for h in hinges_at(turn, 0.025)] == ["1E", "3I", "5E"]  # peaks alone miss it


def test_hinge_change_tells_a_mirror_tie_from_a_neighbour_and_another_mechanism():
    """The semicircle closing at kn 5.2 (docs/atlas.md): 1E 12I 27E 44I by default and its mirror image
    13I 30E 45I 56E with the increments doubled are one answer of a symmetric problem; a hinge moved a
    joint, a fifth hinge and another linkage are not."""
    same, mirror, neighbour, count, other = HINGE_CHANGES
    default = "1E 12I 27E 44I"
    assert hinge_change(default, default, 56) == same
    assert hinge_change(default, "13I 30E 45I 56E", 56) == mirror
    assert hinge_change(default, "1E 13I 27E 44I", 56) == neighbour
    assert hinge_change(default, "13I 30E 46I 56E", 56) == neighbour  # the mirror image, a hinge a joint on
    assert hinge_change(default, "1E 12I 27E 44I 56E", 56) == count
    assert hinge_change(default, "1E 20I 35E 56E", 56) == other
    assert hinge_change(default, "1E 12E 27E 44I", 56) == other  # a pivot on the other side
