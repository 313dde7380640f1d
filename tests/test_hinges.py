"""Hinge detection at one state, on constructed joint openings."""

import numpy as np

from yadearch.hinges import hinges_at


def test_three_hinge_pattern_with_a_spread_hinge():
    n = 12
    intrados = np.full(n, -1e-6)
    extrados = np.full(n, -1e-6)
    extrados[3] = 0.8e-3  # I hinge at interface 4 (extrados opens, pivot at intrados)
    intrados[6], intrados[7], intrados[8] = 0.3e-3, 0.9e-3, 0.4e-3  # spread E hinge 7-8-9
    intrados[11] = 1.2e-3  # E hinge at the right support
    hinges = hinges_at(intrados, extrados, 0.2e-3)
    assert [(h.interface, h.side) for h in hinges] == [(4, "I"), (8, "E"), (12, "E")]
    assert hinges[1].interfaces == (7, 8, 9)


def test_closed_joints_give_no_hinge():
    assert hinges_at(np.full(5, -1e-6), np.full(5, 1e-5), 0.2e-3) == []
