"""Geometry of the paper's arch: span, rise, volumes, joints shared exactly by neighbours."""

import math

import numpy as np
import pytest
from conftest import DATA

from yadearch.case.config import preset
from yadearch.case.mechanics import arch_geometry
from yadearch.model.geometry import block_volume, segmental_arch

R, T, D = 0.300, 0.024, 0.120
# the default case's vertex and joint arrays as built before arch shapes (commit af15cd6)
REFERENCE = DATA / "paper_arch.npz"
ROUNDOFF_M = 1e-15  # about 20 ulp of a coordinate of this arch


@pytest.fixture(scope="module")
def arch():
    return segmental_arch(55, 125.0, R, T, D, 0.036)


def test_the_default_case_is_the_paper_arch_to_the_last_bit():
    reference = np.load(REFERENCE)
    geometry = arch_geometry(preset("set2"))
    # to round-off: numpy's vectorised sin/cos differ in the last bit between CPUs (an AMD EPYC gives
    # 1.1e-16 m, 2 ulp, on 452 of the coordinates written on another machine)
    np.testing.assert_allclose(np.array(geometry.blocks), reference["blocks"], rtol=0.0, atol=ROUNDOFF_M)
    joints = np.array([[j.intrados, j.extrados, j.normal] for j in geometry.joints])
    np.testing.assert_allclose(joints, reference["joints"], rtol=0.0, atol=ROUNDOFF_M)


def test_span_and_rise_match_the_paper(arch):
    # paper Fig. 1: net span 533 mm for a 125 deg embrace of radius 300 mm
    assert arch.span == pytest.approx(0.533, abs=1.5e-3)
    assert arch.rise == pytest.approx(R * (1 - math.sin(math.radians(27.5))), rel=1e-12)


def test_voussoir_volumes_sum_to_the_trapezoid_ring(arch):
    delta = math.radians(125.0) / 55
    one = 0.5 * math.sin(delta) * ((R + T) ** 2 - R**2) * D
    volumes = [block_volume(v) for v in arch.voussoirs]
    assert volumes == pytest.approx([one] * 55, rel=1e-9)
    assert sum(volumes) < math.radians(125.0) / 2 * ((R + T) ** 2 - R**2) * D  # chords inside arcs


def test_interfaces_numbered_left_to_right(arch):
    assert [j.number for j in arch.joints] == list(range(1, 57))
    assert arch.joints[0].left == 0 and arch.joints[-1].right == 56
    xs = [j.intrados[0] for j in arch.joints]
    assert xs == sorted(xs)


def test_neighbours_share_their_joint_face_exactly(arch):
    for joint in arch.joints:
        left, right = arch.blocks[joint.left], arch.blocks[joint.right]
        for corner in (joint.intrados, joint.extrados):
            for block in (left, right):
                distances = np.linalg.norm(block[:, :2] - corner, axis=1)
                assert distances.min() < 1e-12
        # every vertex of both blocks lies on its side of the joint plane (no initial overlap)
        origin = joint.intrados
        assert np.all((left[:, :2] - origin) @ joint.normal <= 1e-12)
        assert np.all((right[:, :2] - origin) @ joint.normal >= -1e-12)


def test_joint_planes_are_radial(arch):
    for joint in arch.joints:
        direction = (joint.extrados - joint.intrados) / joint.length
        assert abs(direction @ joint.normal) < 1e-12
        assert joint.length == pytest.approx(T)
        assert abs(np.cross(joint.intrados, direction)) < 1e-12  # line through the centre


def test_semicircular_arch_springs_at_the_horizontal():
    arch = segmental_arch(9, 180.0, 1.0, 0.1, 0.2, 0.1)
    assert arch.span == pytest.approx(2.0)
    assert arch.joints[0].intrados[1] == pytest.approx(0.0, abs=1e-12)


def test_embrace_out_of_range_is_refused():
    with pytest.raises(ValueError, match="embrace_deg"):
        segmental_arch(9, 200.0, 1.0, 0.1, 0.2, 0.1)
