"""Point loads on turning blocks (model/loads.py), as both engines apply them: the moment of a load whose
arm turns with its block, that moment's change with the turn (the load's own stiffness, which the
stability test adds), and the displacement a load's work measures."""

from __future__ import annotations

import math

import numpy as np

from yadearch.model.loads import LoadPoints, block_loads, load_displacement, turned_moments, turning_stiffness

CENTROIDS = np.array([[0.0, 0.0], [1.0, 2.0]])
# a downward 3 N load 0.5 m right of and 0.2 m above block 1's centroid, and a sideways 2 N one on block 0
POINTS = LoadPoints(np.array([1, 0]), np.array([[1.5, 2.2], [0.0, 0.1]]), np.array([[0.0, -3.0], [2.0, 0.0]]))
LOADS = block_loads(POINTS, CENTROIDS, 2)
PROBE = 1e-6  # rad


def _moment_by_cross_product(turn: np.ndarray) -> np.ndarray:
    """r x F with each arm turned by its block's rotation, computed directly."""
    moments = np.zeros(2)
    for block, point, force in zip(POINTS.block, POINTS.point, POINTS.force):
        c, s = math.cos(turn[block]), math.sin(turn[block])
        arm = point - CENTROIDS[block]
        turned = np.array([c * arm[0] - s * arm[1], s * arm[0] + c * arm[1]])
        moments[block] += turned[0] * force[1] - turned[1] * force[0]
    return moments


def test_a_load_s_moment_turns_with_its_block():
    for turn in (np.zeros(2), np.array([0.3, -0.2]), np.array([-1.0, 2.5])):
        assert np.allclose(turned_moments(LOADS, turn), _moment_by_cross_product(turn), atol=1e-12)


def test_the_load_s_own_stiffness_is_minus_the_change_of_its_moment():
    turn = np.array([0.1, -0.25])
    ahead, behind = turned_moments(LOADS, turn + PROBE), turned_moments(LOADS, turn - PROBE)
    assert np.allclose(turning_stiffness(LOADS, turn), -(ahead - behind) / (2 * PROBE), rtol=1e-6)
    # a load above its block's centroid softens the block's rotation (the inverted pendulum): negative
    above = block_loads(LoadPoints(np.array([1]), np.array([[1.0, 2.5]]), np.array([[0.0, -1.0]])), CENTROIDS, 2)
    assert turning_stiffness(above, np.zeros(2))[1] < 0.0


def test_a_load_s_displacement_is_its_work_per_newton():
    pos0, turn0 = CENTROIDS.copy(), np.zeros(2)
    shifted = pos0 + np.array([[0.0, 0.0], [0.0, -0.004]])  # block 1 down 4 mm, block 0 still
    # 3 N x 4 mm over the 5 N the two loads weigh: 2.4 mm
    assert math.isclose(load_displacement(LOADS, pos0, turn0, shifted, turn0), 0.0024, rel_tol=1e-12)
    # block 1 turned counterclockwise by dtheta lifts its load's point (0.5 m to the right) by 0.5 dtheta
    dtheta = 1e-6
    turned = load_displacement(LOADS, pos0, turn0, pos0, np.array([0.0, dtheta]))
    assert math.isclose(turned, -3.0 * 0.5 * dtheta / 5.0, rel_tol=1e-5)
