"""The joint-element law in pure numpy (no YADE): Winkler normal force and its centroid, no tension,
slipped faces, per-joint Coulomb shear, action and reaction."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import stacked_pairs

from yadearch.model.joint_law import JointLaw, joint_forces, unbalanced_force
from yadearch.model.joint_table import joint_table

KN, KS, TAN_PHI = 5.2e9, 2.6e9, math.tan(math.radians(41.2))
WIDTH, HEIGHT, DEPTH = 0.05, 0.02, 0.1
LAW = JointLaw(KN, KS, TAN_PHI, DEPTH)


def _pairs(n_pairs: int = 1):
    geometry = stacked_pairs([float(k) for k in range(n_pairs)], WIDTH, HEIGHT, DEPTH)
    centroids = np.array([block.mean(axis=0) for block in geometry.blocks])
    return joint_table(geometry, centroids), centroids[:, :2].copy()


def _evaluate(table, pos, rot=None, vel=None, ang_vel=None, shear=None, dt=1e-6):
    n_blocks, n_joints = len(pos), len(table.left)
    return joint_forces(
        table,
        LAW,
        pos,
        np.zeros(n_blocks) if rot is None else rot,
        np.zeros((n_blocks, 2)) if vel is None else vel,
        np.zeros(n_blocks) if ang_vel is None else ang_vel,
        np.zeros(n_joints) if shear is None else shear,
        dt,
    )


def _rotate_about(pos, index, pivot, angle):
    c, s = math.cos(angle), math.sin(angle)
    offset = pos[index] - pivot
    pos[index] = pivot + np.array([c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]])


def test_pressed_joint_carries_kn_area_approach_at_its_middle_along_its_normal():
    table, pos = _pairs()
    pos[1, 1] -= 2e-6
    forces = _evaluate(table, pos)
    assert forces.normal_force[0] == pytest.approx(KN * WIDTH * DEPTH * 2e-6, rel=1e-9)  # 52 N
    assert forces.point[0] == pytest.approx([0.0, -1e-6], abs=1e-12)
    assert forces.block_force[1] == pytest.approx([0.0, 52.0], rel=1e-9)
    assert forces.compressed_length[0] == pytest.approx(WIDTH)


def test_open_joint_carries_nothing():
    table, pos = _pairs()
    pos[1, 1] += 1e-6
    forces = _evaluate(table, pos)
    assert forces.normal_force[0] == 0.0 and forces.shear_force[0] == 0.0
    assert np.isnan(forces.point[0]).all()
    assert not forces.block_force.any()


def test_rotated_joint_carries_the_wedge_at_a_third_of_its_compressed_length():
    """Rotating the top block by a about a point `deep` below the joint's left edge compresses
    deep / tan(a) of the joint in a triangle: force kn V at a third of that from the left edge."""
    table, pos = _pairs()
    angle, deep = 2e-4, 4e-6
    pivot = np.array([-WIDTH / 2, -deep])
    pos[1, 1] -= deep
    _rotate_about(pos, 1, pivot, angle)
    forces = _evaluate(table, pos, rot=np.array([0.0, angle]))
    length = deep / math.tan(angle)  # 20 of the 50 mm
    assert forces.compressed_length[0] == pytest.approx(length, rel=1e-3)
    assert forces.normal_force[0] == pytest.approx(KN * 0.5 * deep * length * DEPTH, rel=1e-3)
    assert forces.point[0, 0] == pytest.approx(-WIDTH / 2 + length / 3, rel=1e-3)


def test_slipped_faces_carry_load_over_their_shared_length_only():
    table, pos = _pairs()
    pos[1] += (0.01, -2e-6)  # 10 of 50 mm slipped off
    forces = _evaluate(table, pos)
    assert forces.normal_force[0] == pytest.approx(KN * 0.04 * DEPTH * 2e-6, rel=1e-9)
    assert forces.point[0, 0] == pytest.approx(0.005, abs=1e-9)  # middle of the shared 40 mm


def test_two_joints_sheared_differently_keep_their_own_shear_forces_up_to_coulomb():
    table, pos = _pairs(2)
    pos[1::2, 1] -= 4e-6
    vel = np.zeros((4, 2))
    vel[1, 0], vel[3, 0] = 1e-3, -1.0  # slips of 1 nm and 1 um per step
    forces = _evaluate(table, pos, vel=vel)
    ks_joint = KS * DEPTH * WIDTH
    assert forces.shear_force[0] == pytest.approx(-ks_joint * 1e-9, rel=1e-9)  # opposes the slip
    cap = TAN_PHI * forces.normal_force[1]  # 91 N
    assert forces.shear_force[1] == pytest.approx(ks_joint * 1e-6, rel=1e-9)  # 13 N: elastic
    again = _evaluate(table, pos, vel=vel * 100, shear=forces.shear_force)
    assert again.shear_force[1] == pytest.approx(cap, rel=1e-12)  # 100 um more: capped
    assert again.shear_force[0] == pytest.approx(forces.shear_force[0] * 101, rel=1e-9)


def test_a_joint_slides_only_as_far_as_its_faces_move():
    """Plastic slip is sliding, never more than the step's relative motion: a joint whose normal force
    falls under a held shear force releases the excess without sliding (a hinge opening to a sliver
    of contact once reported 38.7 mm of slip, docs/numerics.md)."""
    table, pos = _pairs()
    pos[1, 1] -= 1e-7  # a light contact: cap 1.8 N
    held = np.array([50.0])  # shear force left from a heavier contact
    still = _evaluate(table, pos, shear=held)
    assert still.shear_force[0] == pytest.approx(TAN_PHI * still.normal_force[0], rel=1e-12)
    assert still.plastic_slip[0] == 0.0
    vel = np.array([[0.0, 0.0], [-1e-3, 0.0]])  # 1 nm a step along the shear force: slides 1 nm
    sliding = _evaluate(table, pos, vel=vel, shear=held)
    assert sliding.plastic_slip[0] == pytest.approx(1e-9, rel=1e-9)


def test_joint_forces_are_action_and_reaction():
    table, pos = _pairs()
    angle = 1e-4
    pos[1, 1] -= 3e-6
    _rotate_about(pos, 1, np.array([0.0, 0.0]), angle)
    forces = _evaluate(table, pos, rot=np.array([0.0, angle]), vel=np.array([[0, 0], [1e-3, 0]]), shear=np.array([5.0]))
    assert forces.block_force.sum(axis=0) == pytest.approx([0.0, 0.0], abs=1e-9)
    moments = forces.block_torque + pos[:, 0] * forces.block_force[:, 1] - pos[:, 1] * forces.block_force[:, 0]
    assert moments.sum() == pytest.approx(0.0, abs=1e-9)


def test_unbalanced_force_is_zero_for_a_block_resting_on_its_joint():
    table, pos = _pairs()
    weight = KN * WIDTH * DEPTH * 2e-6
    pos[1, 1] -= 2e-6
    forces = _evaluate(table, pos)
    free = np.array([False, True])
    assert unbalanced_force(forces, free, np.array([[0.0, -weight]])) == pytest.approx(0.0, abs=1e-12)
    assert unbalanced_force(forces, free, np.array([[0.0, -2 * weight]])) == pytest.approx(1.0)


def test_a_pressed_joint_is_stable_with_the_stiffness_of_its_interface():
    """The tangent stiffness of a block pressed flat on a fixed one: kn A vertically, ks A
    horizontally, and in rotation about its centroid (h/2 above the joint) kn depth w^3 / 12 plus
    the shear the turn makes at the joint, ks A (h/2)^2; all positive (a stable state)."""
    from yadearch.model.stability import smallest_stiffness, tangent_stiffness

    table, pos = _pairs()
    pos[1, 1] -= 2e-6
    free = np.array([False, True])
    stiffness = tangent_stiffness(table, LAW, pos, np.zeros(2), np.zeros(1), free, WIDTH)
    assert stiffness[1, 1] == pytest.approx(KN * WIDTH * DEPTH, rel=1e-6)
    assert stiffness[0, 0] == pytest.approx(KS * WIDTH * DEPTH, rel=1e-6)
    rocking = KN * DEPTH * WIDTH**3 / 12 + KS * WIDTH * DEPTH * (HEIGHT / 2) ** 2
    assert stiffness[2, 2] == pytest.approx(rocking / WIDTH**2, rel=1e-3)
    assert smallest_stiffness(stiffness) > 0
