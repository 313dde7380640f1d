"""Voussoir dimension errors (pure): the voussoirs keep sharing their joints without overlapping,
each gets the length and thickness it was drawn, a joint pivots on the shorter face, one seed is
one geometry and no error is the designed arch bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.case.imperfect import arch_imperfections, dimension_errors
from yadearch.case.mechanics import arch_geometry, contact_stiffness
from yadearch.case.shape import build_arch
from yadearch.errors import CaseError
from yadearch.model.dimensions import DimensionErrors, draw_dimension_errors, with_dimension_errors

SD = {"voussoir_length_sd_mm": 0.3, "voussoir_thickness_sd_mm": 0.5}


def _front(block: np.ndarray) -> np.ndarray:
    return block[: len(block) // 2, :2]


def test_no_dimension_error_is_the_designed_arch_bit_for_bit():
    case = preset("set2").with_overrides({"seed": 7, "face_bump_sd_mm": 0.1})
    designed, built = build_arch(case.geometry), arch_geometry(case)
    assert dimension_errors(case, designed.n_voussoirs) is None
    assert all(np.array_equal(a, b) for a, b in zip(designed.blocks, built.blocks))
    assert all(np.array_equal(a.extrados, b.extrados) for a, b in zip(designed.joints, built.joints))


def test_one_seed_gives_one_set_of_voussoirs_and_another_seed_another():
    case = preset("set2").with_overrides({**SD, "seed": 3})
    first, again = arch_geometry(case), arch_geometry(case)
    other = arch_geometry(case.with_overrides({"seed": 4}))
    assert all(np.array_equal(a, b) for a, b in zip(first.blocks, again.blocks))
    assert not all(np.array_equal(a, b) for a, b in zip(first.blocks, other.blocks))


def test_the_face_defects_keep_their_draw_when_dimension_errors_are_added():
    """The dimension errors have their own random stream: a face campaign's draws do not move."""
    faces = preset("set2").with_overrides({"seed": 11, "face_bump_sd_mm": 0.18})
    both = faces.with_overrides(SD)
    bumps = arch_imperfections(faces, arch_geometry(faces)).defects.face_bump
    assert np.array_equal(bumps, arch_imperfections(both, arch_geometry(both)).defects.face_bump)


@pytest.mark.parametrize("shape", [{}, {"shape": "pointed", "n_voussoirs": 21}])
def test_voussoirs_share_their_joints_and_do_not_overlap(shape):
    """Each joint's line separates its two blocks: every vertex of the left block lies on its left
    (within 1e-12 m), every vertex of the right block on its right, and both faces start at the
    joint's intrados point."""
    geometry = arch_geometry(preset("set2").with_overrides({**SD, **shape, "seed": 5}))
    for joint in geometry.joints:
        left = (_front(geometry.blocks[joint.left]) - joint.intrados) @ joint.normal
        right = (_front(geometry.blocks[joint.right]) - joint.intrados) @ joint.normal
        assert left.max() < 1e-12 and right.min() > -1e-12
        for block in (joint.left, joint.right):
            assert np.min(np.linalg.norm(_front(geometry.blocks[block]) - joint.intrados, axis=1)) < 1e-12


def test_each_voussoir_gets_its_drawn_length_and_thickness():
    """Joints move along the intrados by the errors on their left: a voussoir's intrados is its
    designed length plus its error (within 1 % of the errors' s.d.: the joint slides along chords),
    its faces its thickness plus its error, and the joint is as long as the thinner face."""
    designed = build_arch(preset("set2").geometry)
    errors = draw_dimension_errors(designed.n_voussoirs, 9, 3e-4, 0.0, 5e-4)
    assert abs(errors.length.sum()) < 1e-15  # the supports' spacing absorbs the set's mean
    built = with_dimension_errors(designed, errors)
    nominal = np.linalg.norm(np.diff([j.intrados for j in designed.joints], axis=0), axis=1)
    now = np.linalg.norm(np.diff([j.intrados for j in built.joints], axis=0), axis=1)
    assert np.abs(now - (nominal + errors.length)).max() < 0.01 * 3e-4
    faces = np.array(
        [
            [np.linalg.norm(_front(b)[3] - _front(b)[0]), np.linalg.norm(_front(b)[2] - _front(b)[1])]
            for b in built.voussoirs
        ]
    )
    assert faces == pytest.approx(np.column_stack([designed.thickness + errors.thickness] * 2), abs=1e-12)
    shared = np.minimum(np.append(designed.thickness, faces[:, 1]), np.append(faces[:, 0], designed.thickness))
    assert [j.length for j in built.joints] == pytest.approx(shared, abs=1e-12)


def test_a_thinner_keystone_shortens_both_its_joints_to_its_thickness():
    designed = build_arch(preset("set2").geometry)
    n, crown = designed.n_voussoirs, designed.crown_voussoir
    thickness = np.zeros(n)
    thickness[crown - 1] = -2e-3
    built = with_dimension_errors(designed, DimensionErrors(np.zeros(n), thickness))
    assert built.joints[crown - 1].length == pytest.approx(designed.thickness - 2e-3, abs=1e-12)
    assert built.joints[crown].length == pytest.approx(designed.thickness - 2e-3, abs=1e-12)
    assert built.joints[crown + 1].length == pytest.approx(designed.thickness, abs=1e-12)


def test_errors_that_break_the_arch_are_refused_naming_the_parameters():
    with pytest.raises(CaseError, match=r"voussoir_length_sd_mm = 20.*at most 0.45"):
        arch_geometry(preset("set2").with_overrides({"voussoir_length_sd_mm": 20}))
    with pytest.raises(CaseError, match=r"voussoir_thickness_mm = -15.*at least 0.5"):
        arch_geometry(preset("set2").with_overrides({"voussoir_thickness_mm": -15}))


def test_a_pointed_arch_keeps_its_apex_joint_and_elastic_blocks_keep_their_kn():
    """A pointed arch's even count puts a joint on the apex, which a moved joint would cut: refused.
    With elastic blocks, kn comes from the designed voussoir width, the same for every draw."""
    with pytest.raises(CaseError, match="voussoir_length_sd_mm = 0.3 must be 0 for a pointed arch"):
        arch_geometry(preset("set2").with_overrides({**SD, "shape": "pointed", "n_voussoirs": 20}))
    elastic = preset("set2").with_overrides({"block_elasticity": True})
    drawn = elastic.with_overrides({**SD, "seed": 8})
    assert contact_stiffness(drawn, arch_geometry(drawn)).kn == contact_stiffness(elastic, arch_geometry(elastic)).kn
