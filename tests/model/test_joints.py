"""Joint kinematics from rigid-block states: openings, rotation and force position (pure numpy)."""

import math

import numpy as np
import pytest

from yadearch.model.geometry import segmental_arch
from yadearch.model.joints import joint_states, pair_rotation, z_rotation


def _centroids(arch):
    return np.array([[*b[:4, :2].mean(axis=0), 0.0] for b in arch.blocks])


def test_rocking_a_voussoir_about_its_intrados_opens_its_extrados_by_t_times_the_angle():
    arch = segmental_arch(5, 120.0, 1.0, 0.1, 0.2, 0.1)
    pos0 = _centroids(arch)
    pos, rot = pos0.copy(), np.zeros(len(pos0))
    joint = arch.joints[2]  # between voussoirs 2 and 3
    angle = 0.01  # voussoir 3 turns clockwise about the joint's intrados corner
    b = joint.right
    c, s = math.cos(-angle), math.sin(-angle)
    arm = pos0[b, :2] - joint.intrados
    pos[b, :2] = joint.intrados + np.array([c * arm[0] - s * arm[1], s * arm[0] + c * arm[1]])
    rot[b] = -angle
    contact = np.full((len(arch.joints), 2), np.nan)
    contact[2] = joint.intrados + 0.1 * (joint.extrados - joint.intrados)
    js = joint_states(arch, pos0, pos, rot, contact)
    assert js.opening_intrados[2] == pytest.approx(0.0, abs=1e-12)
    assert js.opening_extrados[2] == pytest.approx(0.1 * math.sin(angle), rel=1e-6)
    assert js.rotation[2] == pytest.approx(-angle)
    assert js.force_position[2] == pytest.approx(0.1)
    untouched = [k for k in range(len(arch.joints)) if k not in (2, 3)]
    assert np.allclose(js.opening_intrados[untouched], 0.0) and np.allclose(js.opening_extrados[untouched], 0.0)


def test_z_rotation_of_quaternions_relative_to_an_arbitrary_start():
    def quat(axis, angle):
        axis = np.asarray(axis, float) / np.linalg.norm(axis)
        return np.array([math.cos(angle / 2), *(axis * math.sin(angle / 2))])

    def mul(p, q):
        w1, x1, y1, z1 = p
        w2, x2, y2, z2 = q
        return np.array(
            [
                w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
                w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
                w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
            ]
        )

    start = quat([0.3, -1.0, 0.5], 1.1)  # principal axes of a polyhedron: any orientation
    now = mul(quat([0, 0, 1], 0.25), start)
    assert z_rotation(now[None, :], start[None, :])[0] == pytest.approx(0.25)
    # either pair of components gives the angle: (w, z) and (x, y)
    for pair in ([0, 3], [1, 2]):
        assert pair_rotation(now[None, pair], start[None, pair])[0] == pytest.approx(0.25, abs=1e-14)
