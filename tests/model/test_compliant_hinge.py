"""The fold margin of a Winkler joint beside a hinge (no YADE): the joint's turn against the project's
own joint law, and the fold of the joint-plus-chain model it comes from (docs/theory.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import stacked_pairs

from yadearch.model.compliant_hinge import fold_margin, joint_turn
from yadearch.model.joint_law import JointLaw, joint_forces
from yadearch.model.joint_table import joint_table

KN, DEPTH, WIDTH, HEIGHT = 3.0e12, 0.12, 0.024, 0.012  # kn 3000 N/mm^3, the paper's joint
CHAIN_CURVATURE = 0.21  # N m / rad^2: the paper arch's chain beside hinge A at 38 mm (about N x one voussoir)


@pytest.mark.parametrize("turn", [5e-4, 2e-3, 1e-2])
def test_the_turn_is_the_one_the_joint_law_opens_for_its_force_and_margin(turn):
    """Turn the top block of a joint about its left edge pressed in by `turn` x 0.3 mm: the joint law's
    force N and its position a from the edge give back the turn through joint_turn(N, a), to the
    joint law's second-order terms in the turn (it measures across the faces' mean direction)."""
    geometry = stacked_pairs([0.0], WIDTH, HEIGHT, DEPTH)
    centroids = np.array([block.mean(axis=0) for block in geometry.blocks])
    table = joint_table(geometry, centroids)
    law = JointLaw(KN, 0.5 * KN, math.tan(math.radians(41.2)), DEPTH)
    pos, rot = centroids[:, :2].copy(), np.zeros(2)
    contact = 3e-4  # compressed length (m): the edge goes in by turn x contact
    pivot = np.array([-WIDTH / 2 + contact, 0.0])  # the point the top face turns about
    offset = pos[1] - pivot
    c, s = math.cos(turn), math.sin(turn)
    pos[1] = pivot + np.array([c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]])
    rot[1] = turn
    forces = joint_forces(table, law, pos, rot, np.zeros((2, 2)), np.zeros(2), np.zeros(1), 1e-6)
    margin = forces.point[0][0] + WIDTH / 2
    assert margin == pytest.approx(contact / 3, rel=turn)
    assert joint_turn(forces.normal_force[0], margin, KN, DEPTH) == pytest.approx(turn, rel=turn)


def test_the_fold_margin_is_the_least_rigid_margin_at_which_the_joint_still_holds():
    """Beside a hinge, the joint's own turn moves the thrust toward its edge by (G/N) x turn: the
    joint holds at rigid margin a_r only if a_r = a + (G/N) joint_turn(N, a) has a root a > 0."""
    normal_force = 18.0
    lever = CHAIN_CURVATURE / normal_force
    a = np.geomspace(1e-6, 1e-3, 200_001)
    rigid_margin = a + lever * joint_turn(normal_force, a, KN, DEPTH)
    assert rigid_margin.min() == pytest.approx(fold_margin(CHAIN_CURVATURE, KN, DEPTH), rel=1e-6)


def test_the_margin_falls_as_the_cube_root_of_the_stiffness_and_is_a_tenth_of_a_millimetre_at_kn_3000():
    margin = fold_margin(CHAIN_CURVATURE, KN, DEPTH)
    assert margin == pytest.approx(9.6e-5, rel=0.02)  # the DEM's hinges moved at 0.09-0.10 mm (docs)
    assert fold_margin(CHAIN_CURVATURE, 8 * KN, DEPTH) == pytest.approx(margin / 2, rel=1e-12)


def test_a_chain_that_does_not_lower_the_weights_never_folds_and_bad_stiffness_is_refused():
    assert fold_margin(-0.1, KN, DEPTH) == 0.0
    with pytest.raises(ValueError, match="kn and depth must be positive"):
        fold_margin(CHAIN_CURVATURE, 0.0, DEPTH)
