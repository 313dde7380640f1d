"""Imperfect joint faces in pure numpy (no YADE): the gap profiles the defects make, and what the
joint law does with them (a worn edge moves a hinge's pivot inward, a wedge closes from one end,
zero amplitudes are the perfect joint bit for bit, one seed is one geometry)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import stacked_pairs

from yadearch.case.config import preset
from yadearch.case.imperfect import arch_imperfections
from yadearch.case.mechanics import arch_geometry
from yadearch.model.imperfections import (
    CHAMFER,
    ROUND,
    GapProfiles,
    ImperfectionAmplitudes,
    JointDefects,
    draw_defects,
    gap_profiles,
    keystones,
    wedge_openings,
)
from yadearch.model.joint_law import JointLaw, joint_forces
from yadearch.model.joint_table import joint_table

KN, KS, TAN_PHI = 5.2e9, 2.6e9, math.tan(math.radians(41.2))
WIDTH, HEIGHT, DEPTH = 0.024, 0.02, 0.1
LAW = JointLaw(KN, KS, TAN_PHI, DEPTH)


def _defects(
    intrados_edge: float = 0.0, angle: float = 0.0, bump: float = 0.0, shape: str = ROUND, offset: float = 0.0
) -> JointDefects:
    """One joint whose upper (right) face has a worn intrados edge, an angle, a bump and an offset."""
    zero = np.zeros(1)
    return JointDefects(
        zero,
        zero,
        np.array([intrados_edge]),
        zero,
        np.array([angle]),
        np.array([bump]),
        shape,
        zero,
        np.array([offset]),
    )


def _table(defects: JointDefects | None):
    geometry = stacked_pairs([0.0], WIDTH, HEIGHT, DEPTH)
    centroids = np.array([block.mean(axis=0) for block in geometry.blocks])
    profiles = None if defects is None else gap_profiles(defects, np.array([WIDTH]))
    return joint_table(geometry, centroids, profiles), centroids[:, :2].copy()


def _forces(table, pos, rot=None):
    return joint_forces(
        table, LAW, pos, np.zeros(2) if rot is None else rot, np.zeros((2, 2)), np.zeros(2), np.zeros(1), 1e-6
    )


def _hinge(table, pos, angle: float, deep: float):
    """The upper block turned by `angle` about a point `deep` under the joint's intrados corner."""
    pivot = np.array([-WIDTH / 2, -deep])
    pos = pos.copy()
    pos[1, 1] -= deep
    c, s = math.cos(angle), math.sin(angle)
    offset = pos[1] - pivot
    pos[1] = pivot + np.array([c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]])
    return _forces(table, pos, np.array([0.0, angle]))


@pytest.mark.parametrize("shape", [ROUND, CHAMFER])
def test_a_worn_edge_moves_a_hinge_pivot_inward_by_the_wear(shape):
    """A hinge pressing a tiny zone at the intrados corner: with the edge worn by r the zone moves
    to where the worn profile is as steep as the hinge's relative rotation a (the tangent point):
    r (1 - sin(atan a)) in from the corner for a rounding, r for a 45 deg chamfer (steeper than any
    hinge). The hinge is pressed so that the worn joint carries about the perfect one's force."""
    angle, radius, deep = 0.02, 2e-3, 5e-6
    perfect_table, pos = _table(None)
    perfect = _hinge(perfect_table, pos, angle, deep)
    if shape == ROUND:
        tangent = radius * (1.0 - math.sin(math.atan(angle)))
        standing_back = radius * (1.0 - math.cos(math.atan(angle)))  # the worn profile's gap there
    else:
        tangent, standing_back = radius, 0.0
    worn_table, _ = _table(_defects(intrados_edge=radius, shape=shape))
    worn = _hinge(worn_table, pos, angle, deep + angle * tangent + standing_back)
    assert perfect.point[0, 0] + WIDTH / 2 < 0.05 * radius  # the perfect joint's pivot: at the corner
    assert worn.normal_force[0] == pytest.approx(perfect.normal_force[0], rel=0.5)
    assert worn.point[0, 0] + WIDTH / 2 == pytest.approx(tangent, abs=0.05 * radius)


def test_a_wedge_closes_from_its_touching_end_before_the_joint_carries_full_load():
    """Faces at an angle a touch at the intrados: a closure c presses a triangle c / a long, force
    kn depth c^2 / (2 a) at a third of it, until c = a L; beyond, the whole joint, kn depth (c L - a L^2 / 2)."""
    angle = 1e-3
    table, pos = _table(_defects(angle=angle))
    full = angle * WIDTH  # the closure at which the extrados end touches
    for closure in (0.25 * full, 0.5 * full, 2.0 * full):
        pressed = pos.copy()
        pressed[1, 1] -= closure
        forces = _forces(table, pressed)
        if closure < full:
            length = closure / angle
            assert forces.compressed_length[0] == pytest.approx(length, rel=1e-9)
            assert forces.normal_force[0] == pytest.approx(KN * DEPTH * closure**2 / (2 * angle), rel=1e-9)
            assert forces.point[0, 0] + WIDTH / 2 == pytest.approx(length / 3, rel=1e-9)
        else:
            assert forces.compressed_length[0] == pytest.approx(WIDTH, rel=1e-9)
            expected = KN * DEPTH * (closure * WIDTH - angle * WIDTH**2 / 2)
            assert forces.normal_force[0] == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("angle", [2e-3, -2e-3])
def test_a_wedge_opens_the_real_faces_at_one_end_by_its_angle_times_the_length(angle):
    """The wedge is the whole end gap of a tilted face (so a wedge pressed flat counts as a closed
    joint, not as a hinge rotated by the angle); worn edges and bumps add nothing to it."""
    defects = _defects(angle=angle)
    intrados, extrados = wedge_openings(defects, np.array([WIDTH]))
    gap = gap_profiles(defects, np.array([WIDTH])).gap[0]
    assert (intrados[0], extrados[0]) == pytest.approx((gap[0], gap[-1]), abs=1e-15)
    assert extrados[0] - intrados[0] == pytest.approx(angle * WIDTH)
    worn = wedge_openings(_defects(intrados_edge=2e-3, bump=1e-4), np.array([WIDTH]))
    assert worn == (pytest.approx([0.0]), pytest.approx([0.0]))


@pytest.mark.parametrize("offset", [3e-3, -3e-3])
def test_a_voussoir_set_off_its_neighbour_bears_on_the_shared_part_of_the_joint(offset):
    """The upper face shifted by o along the joint: a closure c presses the W - |o| both faces
    share, force kn depth c (W - |o|) at the middle of that part, o / 2 from the joint's middle."""
    closure = 1e-6
    table, pos = _table(_defects(offset=offset))
    pressed = pos.copy()
    pressed[1, 1] -= closure
    forces = _forces(table, pressed)
    assert forces.compressed_length[0] == pytest.approx(WIDTH - abs(offset), rel=1e-9)
    assert forces.normal_force[0] == pytest.approx(KN * DEPTH * closure * (WIDTH - abs(offset)), rel=1e-9)
    assert forces.point[0, 0] == pytest.approx(offset / 2, abs=1e-12)


def test_a_support_set_askew_wedges_its_springing_joint_only():
    lengths = np.full(6, WIDTH)
    askew = draw_defects(ImperfectionAmplitudes(right_support_angle=2e-3), 6, seed=3, lengths=lengths)
    assert askew.face_angle[-1] == 2e-3 and not askew.face_angle[:-1].any()
    profiles = gap_profiles(askew, lengths)
    assert profiles.imperfect.tolist() == [False] * 5 + [True]
    assert profiles.gap[-1, -1] == pytest.approx(2e-3 * WIDTH)  # gaping at the extrados


def test_voussoir_offsets_are_drawn_per_voussoir_and_the_keystone_gets_its_own():
    amps = ImperfectionAmplitudes(voussoir_offset=1e-4, voussoir_offset_sd=5e-5, keystone_offset=-1e-3)
    defects = draw_defects(amps, 12, seed=7, lengths=np.full(12, WIDTH))  # 11 voussoirs, keystone 6th
    assert defects.left_offset[0] == 0.0 and defects.right_offset[-1] == 0.0  # the supports stay
    assert np.array_equal(defects.right_offset[:-1], defects.left_offset[1:])  # a voussoir's two faces
    voussoirs = defects.right_offset[:-1]
    assert keystones(11) == [5] and keystones(10) == [4, 5]
    assert voussoirs[5] < -5e-4 < voussoirs[np.arange(11) != 5].min()


def test_a_convex_bump_touches_in_the_middle_and_a_hollow_one_at_the_ends():
    bump, closure = 1e-5, 2.5e-6  # 10 um out of flat, closed by a quarter of it
    for sign, middle_touches in ((1.0, True), (-1.0, False)):
        table, pos = _table(_defects(bump=sign * bump))
        pressed = pos.copy()
        pressed[1, 1] -= closure
        forces = _forces(table, pressed)
        assert forces.point[0, 0] == pytest.approx(0.0, abs=1e-9)  # symmetric either way
        assert forces.compressed_length[0] == pytest.approx(
            0.5 * WIDTH if middle_touches else (1 - math.sqrt(0.75)) * WIDTH, rel=0.02
        )


def test_a_profile_of_zero_gaps_integrates_to_the_perfect_joint():
    """The segment-by-segment integration of an imperfect joint, given no gap, is the closed form."""
    perfect_table, pos = _table(None)
    flat_table, _ = _table(_defects())
    flat_table = flat_table.__class__(**{**flat_table.__dict__, "imperfect": np.array([True])})
    for angle, deep in ((0.0, 2e-6), (2e-4, 4e-6), (5e-3, 1e-5)):
        expected, got = _hinge(perfect_table, pos, angle, deep), _hinge(flat_table, pos, angle, deep)
        assert got.normal_force[0] == pytest.approx(expected.normal_force[0], rel=1e-9)
        assert got.point[0] == pytest.approx(expected.point[0], rel=1e-9, abs=1e-12)
        assert got.compressed_length[0] == pytest.approx(expected.compressed_length[0], rel=1e-9)


def test_zero_amplitudes_are_the_perfect_arch_bit_for_bit():
    case = preset("set2")
    geometry = arch_geometry(case)
    assert arch_imperfections(case, geometry) is None
    assert arch_imperfections(case.replace(seed=7), geometry) is None  # a seed alone changes nothing
    lengths = np.array([j.length for j in geometry.joints])
    zero = gap_profiles(draw_defects(ImperfectionAmplitudes(), len(lengths), 3, lengths), lengths)
    assert not zero.imperfect.any() and not zero.gap.any()


def test_one_seed_gives_one_geometry_and_another_seed_another():
    case = preset("set2").replace(
        edge_radius_mm=1.0, edge_radius_sd_mm=0.5, face_angle_sd_mrad=1.0, face_bump_sd_mm=0.005, seed=11
    )
    geometry = arch_geometry(case)
    first, again = arch_imperfections(case, geometry), arch_imperfections(case, geometry)
    other = arch_imperfections(case.replace(seed=12), geometry)
    assert first is not None and again is not None and other is not None
    assert np.array_equal(first.profiles.gap, again.profiles.gap)
    assert not np.array_equal(first.profiles.gap, other.profiles.gap)
    table = first.table()
    assert len(table["interface"]) == 56
    assert table["left_intrados_edge_mm"][0] == 0.0 and table["right_extrados_edge_mm"][-1] == 0.0  # supports
    assert (first.profiles.gap >= 0).all() and (first.profiles.gap.min(axis=1) == 0).all()


def test_edges_are_drawn_non_negative_and_capped_below_half_the_joint():
    lengths = np.full(1000, 0.024)
    defects = draw_defects(ImperfectionAmplitudes(edge_size=1e-3, edge_size_sd=5e-3), 1000, 0, lengths)
    edges = np.concatenate([defects.left_intrados_edge, defects.right_extrados_edge])
    assert edges.min() == 0.0 and edges.max() <= 0.45 * 0.024
    profiles: GapProfiles = gap_profiles(defects, lengths)
    assert (np.diff(profiles.fraction, axis=1) >= 0).all()
