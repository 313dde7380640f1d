"""The load multiplier by the mechanism method (Heyman's): every four-hinge mechanism of the rigid arch
at rest is tried by virtual work and the least multiplier is the collapse load (pure numpy; no linear
programme, so it checks `solve.load_lp` independently).

Four hinges at joints h1 < h2 < h3 < h4, each about one corner, split the arch into three moving
bodies: the first turns about hinge 1, the third about hinge 4, the middle one about the
intersection of the lines through hinges 1-2 and 4-3. A mechanism is admissible when every hinge's
other corner opens; its multiplier is minus the dead loads' power over the live load's, plus the
power the fill's passive resistance dissipates where a face moves into it (each spring at its capacity,
`model.passive_fill`) over the live load's. Sliding is not considered (enough friction), and the search
is C(joints, 4) x 16: for arches of tens of blocks.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from yadearch.model.passive_fill import BLOCK, CAPACITY, OUTWARD, spring_points
from yadearch.solve.rigid import Pivot, RigidArch

OPENING_TOLERANCE = 1e-9  # of the largest corner speed: an "opening" rate below this is closed
PARALLEL = 1e-12  # a determinant below this: hinge lines that do not meet (no such mechanism)


def mechanism_multiplier(arch: RigidArch, dead: np.ndarray, live: np.ndarray) -> tuple[float, tuple[Pivot, ...]]:
    """The least multiplier of the live load over the admissible four-hinge mechanisms, with its
    hinges; `dead` and `live` are (n_blocks, 3) generalised applied forces (Fx, Fy, moment about the
    origin), the arch's passive springs (`arch.passive`) resist at their capacity. (inf, ()) if no
    mechanism lets the live load do work."""
    best: tuple[float, tuple[Pivot, ...]] = (math.inf, ())
    for joints in itertools.combinations(range(arch.n_joints), 4):
        for sides in itertools.product((0, 1), repeat=4):
            pivots = tuple(Pivot(j, s) for j, s in zip(joints, sides))
            value = _multiplier(arch, pivots, dead, live)
            if value is not None and value < best[0]:
                best = (value, pivots)
    return best


def _multiplier(arch: RigidArch, pivots: tuple[Pivot, ...], dead: np.ndarray, live: np.ndarray) -> float | None:
    points = np.array([arch.corner0[p.joint, p.side] for p in pivots])
    centre = _meeting(points[0], points[1], points[3], points[2])
    if centre is None:
        return None
    omega_a = 1.0
    omega_b = omega_a * _ratio(points[1] - points[0], points[1] - centre)
    omega_c = omega_b * _ratio(points[2] - centre, points[2] - points[3])
    body = np.zeros(arch.n_blocks, int)  # 0: still; 1, 2, 3: the three moving bodies
    for k, p in enumerate(pivots[:3]):
        body[p.joint + 1 : pivots[k + 1].joint + 1] = k + 1
    omega = np.array([0.0, omega_a, omega_b, omega_c])[body]
    centres = np.array([[0.0, 0.0], points[0], centre, points[3]])[body]
    power_dead, power_live = _power(dead, omega, centres), _power(live, omega, centres)
    if power_live == 0.0:
        return None
    sign = 1.0 if power_live > 0.0 else -1.0  # the direction in which the live load does work
    if not _admissible(arch, pivots, sign * omega, centres):
        return None
    return -power_dead / power_live + _passive_power(arch, sign * omega, centres) / abs(power_live)


def _passive_power(arch: RigidArch, omega: np.ndarray, centres: np.ndarray) -> float:
    """The power the passive springs dissipate: each at its capacity where its point moves into the fill."""
    total = 0.0
    for spring, point in zip(arch.passive, spring_points(arch.passive, arch.centroid0)):
        block = int(spring[BLOCK])
        outward_rate = spring[OUTWARD] * omega[block] * _turned(point - centres[block])[0]
        total += spring[CAPACITY] * max(outward_rate, 0.0)
    return total


def _meeting(a: np.ndarray, b: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray | None:
    """The intersection of line a-b with line c-d (None if they are parallel)."""
    u, v = b - a, d - c
    det = u[0] * v[1] - u[1] * v[0]
    if abs(det) < PARALLEL * max(np.dot(u, u), np.dot(v, v)):
        return None
    t = ((c[0] - a[0]) * v[1] - (c[1] - a[1]) * v[0]) / det
    return a + t * u


def _ratio(numerator: np.ndarray, denominator: np.ndarray) -> float:
    """numerator / denominator for two parallel vectors."""
    return float(np.dot(numerator, denominator) / np.dot(denominator, denominator))


def _power(loads: np.ndarray, omega: np.ndarray, centres: np.ndarray) -> float:
    """The power of generalised loads on blocks turning at `omega` about `centres`."""
    return float(np.sum(omega * (loads[:, 2] - centres[:, 0] * loads[:, 1] + centres[:, 1] * loads[:, 0])))


def _admissible(arch: RigidArch, pivots: tuple[Pivot, ...], omega: np.ndarray, centres: np.ndarray) -> bool:
    """Every hinge's other corner opens (gap rate >= 0 along the joint's normal)."""
    speeds = []
    for p in pivots:
        left, right = arch.left[p.joint], arch.right[p.joint]
        other = arch.corner0[p.joint, 1 - p.side]
        v_left = omega[left] * _turned(other - centres[left])
        v_right = omega[right] * _turned(other - centres[right])
        speeds.append(float(np.dot(v_right - v_left, arch.normal0[p.joint])))
    largest = max(abs(s) for s in speeds)
    return largest > 0.0 and all(s >= -OPENING_TOLERANCE * largest for s in speeds)


def _turned(arm: np.ndarray) -> np.ndarray:
    """k x arm: the velocity of a point at `arm` from a centre turning at unit rate."""
    return np.array([-arm[1], arm[0]])
