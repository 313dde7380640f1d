"""The softening of a rigid four-hinge mechanism under a live load (pure numpy): the multiplier that
holds the mechanism in equilibrium at each finite turn, by virtual work on its one degree of freedom,
against the live load's displacement; the rigid limit the static engine's descending branch
approaches with stiff joints (docs/loads.md).

The first segment turns by theta about the first hinge and the chain closes exactly
(`solve.rigid.turn_four_bar`); the weights and dead loads do work W(theta) and the live load of
multiplier 1 does |F| delta(theta), so equilibrium is lambda(theta) = -W'(theta) / (|F| delta'(theta))."""

from __future__ import annotations

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.model.loads import load_displacement
from yadearch.solve.pose import parse_pivot
from yadearch.solve.rigid import LimitError, at_rest, rigid_arch, turn_four_bar
from yadearch.solve.statics import StaticArch, static_arch

TURN_STEP = 1e-6  # rad: the central difference of the works in the mechanism's turn


def rigid_softening(case: ArchCase, hinges: tuple[str, ...], turns: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The live load's displacement (m) and the multiplier in equilibrium (N or g) of the rigid
    mechanism `hinges` (four labels, e.g. ("3I", "6E", "12I", "16E")) at each of the first segment's
    `turns` (rad, >= 0, taken the way the live load does work). LimitError where the chain cannot close."""
    rigid, arch = rigid_arch(case), static_arch(case)
    if len(rigid.passive):
        raise LimitError("the rigid mechanism's softening counts the weights' work only, not the fill's passive pushes")
    pivots = tuple(parse_pivot(h) for h in hinges)
    magnitude = float(np.hypot(arch.live[:, 0], arch.live[:, 1]).sum())

    def works(angle: float) -> np.ndarray:
        """The work of the weights and dead loads (J) and the live load's displacement (m) at `angle`."""
        placement = turn_four_bar(rigid, at_rest(rigid), pivots, angle)
        if placement is None:
            raise LimitError(f"the mechanism {' '.join(hinges)} cannot close at a turn of {angle:g} rad")
        return np.array(_works(arch, rigid.centroid0, placement.centroids(rigid), placement.rot))

    sign = 1.0 if works(TURN_STEP)[1] > 0.0 else -1.0
    moved, multiplier = [], []
    for turn in np.asarray(turns, float):
        ahead, behind = works(sign * (turn + TURN_STEP)), works(sign * (turn - TURN_STEP))
        moved.append(works(sign * turn)[1])
        multiplier.append(-(ahead[0] - behind[0]) / (magnitude * (ahead[1] - behind[1])))
    return np.array(moved), np.array(multiplier)


def _works(arch: StaticArch, centroid0: np.ndarray, centroids: np.ndarray, turn: np.ndarray) -> tuple[float, float]:
    """The work of the weights and dead loads (J) and the live load's displacement (m) from rest to
    the blocks at `centroids` turned by `turn`."""
    rest = np.zeros(len(turn))
    weights = -float(arch.weight @ (centroids[:, 1] - centroid0[:, 1]))
    dead_size = float(np.hypot(arch.dead[:, 0], arch.dead[:, 1]).sum())
    dead = dead_size * load_displacement(arch.dead, centroid0, rest, centroids, turn) if dead_size else 0.0
    return weights + dead, load_displacement(arch.live, centroid0, rest, centroids, turn)
