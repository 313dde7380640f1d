"""A live load driven by its own displacement through a spring (model/load_control.py), as the DEM drives
a load past its peak: taking over from load control changes nothing, the load falls by the spring's
stiffness as the load's points move along it, and the anchor moves at its rate to its target."""

from __future__ import annotations

import math

import numpy as np
import pytest

from yadearch.model.load_control import LoadSpring
from yadearch.model.loads import LoadPoints, block_loads

CENTROIDS = np.array([[0.0, 0.0], [1.0, 2.0]])
# a downward 3 N load 0.5 m right of block 1's centroid (the load's points move 1 m a metre the block sinks)
LOADS = block_loads(LoadPoints(np.array([1]), np.array([[1.5, 2.0]]), np.array([[0.0, -3.0]])), CENTROIDS, 2)
START = np.column_stack([CENTROIDS, np.zeros(2)])
STIFFNESS = 400.0  # multiplier per metre


def _spring(poses: np.ndarray, multiplier: float) -> LoadSpring:
    return LoadSpring.holding(LOADS, START[:, 0:2], START[:, 2], poses, multiplier, stiffness=STIFFNESS, rate=0.01)


def test_taking_over_from_load_control_keeps_the_load():
    poses = START + np.array([[0.0, 0.0, 0.0], [0.001, -0.004, 0.002]])
    assert math.isclose(_spring(poses, 2.5).multiplier(poses), 2.5, rel_tol=1e-12)


def test_the_load_falls_by_the_spring_as_its_points_move_along_it():
    spring = _spring(START, 2.0)
    sunk = START + np.array([[0.0, 0.0, 0.0], [0.0, -0.001, 0.0]])  # the load's point 1 mm down, along its force
    assert math.isclose(spring.displacement(sunk), 0.001, rel_tol=1e-12)
    assert math.isclose(spring.multiplier(sunk), 2.0 - STIFFNESS * 0.001, rel_tol=1e-12)
    lifted = START + np.array([[0.0, 0.0, 0.0], [0.0, 0.001, 0.0]])
    assert spring.multiplier(lifted) > 2.0


def test_the_anchor_moves_at_its_rate_to_its_target():
    spring = _spring(START, 1.0)
    start = spring.anchor
    spring.target = start + 0.005
    spring.advance(0.2)  # 2 mm at 10 mm/s
    assert math.isclose(spring.anchor, start + 0.002, rel_tol=1e-12) and not spring.reached()
    assert math.isclose(spring.multiplier(START), 1.0 + STIFFNESS * 0.002, rel_tol=1e-9)
    spring.advance(1.0)
    assert spring.anchor == spring.target and spring.reached()


@pytest.mark.parametrize(("stiffness", "rate"), [(0.0, 0.01), (100.0, 0.0), (-1.0, 0.01)])
def test_a_spring_needs_a_positive_stiffness_and_rate(stiffness, rate):
    with pytest.raises(ValueError, match="positive stiffness and rate"):
        LoadSpring(LOADS, START[:, 0:2], START[:, 2], stiffness=stiffness, anchor=0.0, rate=rate)
