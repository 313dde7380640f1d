"""The rigid march's re-seating at a fixed support, decided by energy and broken ties, so that one
input gives one answer on any machine (docs/theory.md, "Rigid-block limit analysis").

Past a limit point of the three-hinge path the static LP has no admissible equilibrium, and a
four-hinge chain (the three hinges and one closed corner) lowers the weights at the fixed support.
Which chain, and where it lands, is not asked of the kinematic LP, whose optimum is degenerate
where two corners tie (the keystone's two joints, the two haunches of a symmetric spreading): every
chain through a closed corner is tried, those that lower the weights at first order are followed
until one of their open hinges closes (the hinge re-seated) without the weights rising on the way,
and the landing with an admissible equilibrium and the lowest weights is kept. Energies closer than
`TIE_FRACTION` of the arch's weight times the ring's thickness tie, and ties go to the chain whose
hinges come first from the left support. A chain that moves a block further than `runaway` (a
multiple of the ring's thickness) before it closes a hinge runs away: the collapse.

The same energy check picks the three-hinge mechanism that follows the support (`follow_tie`): the
LP's mechanism against those with one hinge at any other closed joint, either side, compared by the
weights' potential a small support step on; the LP cannot tell them apart where they tie to first
order (the keystone's two joints, or a thrust line touching the ring at joints far apart).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from yadearch.solve.compliant import potential
from yadearch.solve.limit_lp import Mechanism
from yadearch.solve.rigid import Pivot, Placement, RigidArch, close_linkage, contacts, turn_four_bar

# Two energies closer than this fraction of (arch weight x the distance the weights move: the ring's
# thickness for a snap, the probe step for a tie of mechanisms) are equal. Round-off in the weights'
# potential is ~1e-14 of it and inputs perturbed by 1e-12 move the differences by ~1e-12, while the
# ties that matter (the keystone's two joints under an inclined movement) differ by ~1e-5: 1e-9
# sits three decades from both, so a perturbed input breaks a tie the same way on any machine.
TIE_FRACTION = 1e-9
# a chain whose energy rate is below this fraction of (weight x thickness) per radian neither lowers
# nor raises the weights: 100 times the central difference's round-off, 1e-4 of the rate 0.05 mm past a limit
RATE_FRACTION = 1e-7
PROBE_RAD = 1e-6  # turn of a chain's first segment that tells its first-order energy rate and direction
# a corner whose gap closes faster than this fraction of the thickness per radian of turn penetrates
# (a rigid joint's round-off is ~1e-10 of it; a hinge turned the wrong way closes at ~ its length)
PENETRATION_RATE_FRACTION = 1e-6
FOLLOW_PROBE_FRACTION = 1e-2  # support step (of the ring's thickness) at which tied mechanisms are compared
# mechanisms whose energy rates (N: J per m of support) differ by less than this fraction of the
# arch's weight tie to first order: the keystone's two joints differ by ~1e-8 of it (the rate's
# O(step^2) error), a hinge one joint further by >1e-4 where the first order decides
RATE_TIE_FRACTION = 1e-6
CLOSURE_BISECTIONS = 60  # halvings that put a closing corner on its contact to round-off
FIRST_TURN_RAD = 1e-7  # the first turn tried when searching where a chain closes a hinge
SNAP_SAMPLES = 9  # points along a snap where the weights must keep descending


@dataclass(frozen=True)
class Landing:
    """Where a chain at a fixed support re-seats: the placement, the hinges left open, the chain, the
    weights' potential (J) and the largest block movement from the snap's start (m)."""

    placement: Placement
    pivots: tuple[Pivot, ...]
    chain: Mechanism
    energy: float
    move: float


def energy_tolerance(arch: RigidArch, length: float | None = None) -> float:
    """Energies closer than this tie (J): `TIE_FRACTION` of the arch's weight times `length` (m, the
    distance the weights move: by default the ring's thickness)."""
    return TIE_FRACTION * float(arch.weight.sum()) * (arch.geometry.thickness if length is None else length)


def _ranked(items: Sequence, energy: Callable, order: Callable, tolerance: float) -> list:
    """`items` by energy, ties (within `tolerance`) by `order`."""
    rest, ranked = list(range(len(items))), []
    while rest:
        low = min(energy(items[i]) for i in rest)
        pick = min((i for i in rest if energy(items[i]) - low <= tolerance), key=lambda i: order(items[i]))
        ranked.append(items[pick])
        rest.remove(pick)
    return ranked


def penetrates(arch: RigidArch, before: Placement, after: Placement | None, turn: float) -> bool:
    """Whether a touching corner of `before` closes into its neighbour on the way to `after`, reached
    by a turn of `turn` rad (None: unreachable, counted as penetrating)."""
    if after is None:
        return True
    c0, c1 = contacts(arch, before), contacts(arch, after)
    rate = (c1.gap - c0.gap) / abs(turn)
    limit = PENETRATION_RATE_FRACTION * arch.geometry.thickness
    return bool(np.any(c0.touching & (rate < -limit)) or np.any(~c0.touching & (c1.gap < 0.0)))


def descending_chains(arch: RigidArch, placement: Placement, pivots: tuple[Pivot, ...]) -> list[Mechanism]:
    """Every four-hinge chain at a fixed support made of `pivots` and one closed corner that can turn
    (no corner penetrating) lowering the weights at first order, steepest first: each with the sign
    of its first segment's turn (`rates`), its energy rate (`power`, J per m of the kinematic LP's
    velocity box: the same measure as its collapse chains) and the open hinges it closes. Rates that
    tie within TIE_FRACTION of the weight go to the hinges nearest the left support."""
    hinged = {p.joint for p in pivots}
    c = contacts(arch, placement)
    weight = float(arch.weight.sum())
    tol = RATE_FRACTION * weight * arch.geometry.thickness
    found = []
    for joint in range(arch.n_joints):
        if joint in hinged:
            continue
        for side in (0, 1):
            if not c.touching[joint, side]:
                continue
            chain = tuple(sorted((*pivots, Pivot(joint, side))))
            plus, minus = (turn_four_bar(arch, placement, chain, s * PROBE_RAD) for s in (1.0, -1.0))
            if plus is None or minus is None:
                continue
            rate = (potential(arch, plus) - potential(arch, minus)) / (2.0 * PROBE_RAD)
            sign, ahead = (-1.0, minus) if rate > 0 else (1.0, plus)
            if abs(rate) <= tol or penetrates(arch, placement, ahead, PROBE_RAD):
                continue
            gap = contacts(arch, ahead).gap
            closing = tuple(p.joint for p in pivots if gap[p.joint, 1 - p.side] < c.gap[p.joint, 1 - p.side])
            power = -abs(rate) / _box_speed(arch, plus, minus, PROBE_RAD)
            found.append(Mechanism(chain, (sign,) * 4, power, closing))
    return _ranked(found, lambda m: m.power, lambda m: m.pivots, TIE_FRACTION * weight)


def _box_speed(arch: RigidArch, plus: Placement, minus: Placement, turn: float) -> float:
    """The largest of a chain's block velocities per radian as the kinematic LP boxes them: the
    velocity of the point at the origin (each component) and the spin times the span."""
    spin = (plus.rot - minus.rot) / (2.0 * turn)
    shift_rate = (plus.shift - minus.shift) / (2.0 * turn)
    mid = 0.5 * (plus.shift + minus.shift)
    origin = shift_rate - spin[:, None] * np.stack([-mid[:, 1], mid[:, 0]], axis=1)
    return float(max(np.abs(origin).max(), np.abs(spin).max() * arch.geometry.span))


def migrates(chain: Mechanism, pivots: tuple[Pivot, ...]) -> bool:
    """Whether `chain` moves an open hinge of `pivots` to its neighbouring joint: its new hinge sits
    one joint from a hinge on the same side that it turns back (to close)."""
    new = [p for p in chain.pivots if p not in pivots]
    return len(new) == 1 and any(
        p.side == new[0].side and abs(p.joint - new[0].joint) == 1 and p.joint in chain.closing for p in pivots
    )


def closing_path(
    arch: RigidArch, state: Placement, chain: Mechanism, origin: Placement, runaway: float, to_bound: bool = False
) -> list[Placement] | None:
    """SNAP_SAMPLES placements along `chain` at a fixed support from `state` until a hinge it turns
    back closes; None if it straightens, or runs away first (a block further than `runaway` (m) from
    `origin`) unless `to_bound`, which then ends the placements where a block reaches `runaway`."""
    sign = float(np.sign(chain.rates[0]))
    start = origin.centroids(arch)

    def turned(angle: float) -> Placement | None:
        placement = turn_four_bar(arch, state, chain.pivots, sign * angle)
        if placement is None or np.any(contacts(arch, placement).gap[~contacts(arch, state).touching] < 0.0):
            return None
        return placement

    def far(placement: Placement) -> bool:
        return float(np.linalg.norm(placement.centroids(arch) - start, axis=1).max()) > runaway

    angle = FIRST_TURN_RAD
    while (reached := turned(angle)) is not None and not far(reached):
        angle *= 2.0
    if reached is not None and not to_bound:
        return None

    def within(angle: float) -> bool:
        placement = turned(angle)
        return placement is not None and not (to_bound and far(placement))

    low, high = 0.0, angle
    for _ in range(CLOSURE_BISECTIONS):
        mid = 0.5 * (low + high)
        if mid in (low, high):
            break
        low, high = (mid, high) if within(mid) else (low, mid)
    reached_path = [turned(a) for a in np.linspace(0.0, low, SNAP_SAMPLES)]
    path = [p for p in reached_path if p is not None]
    if len(path) < len(reached_path) or far(path[-1]):
        return None
    return path


def land(arch: RigidArch, state: Placement, chain: Mechanism, origin: Placement, runaway: float) -> Landing | None:
    """Follow `chain` from `state` until it re-seats a hinge, the weights never rising: the landing,
    or None (it runs away, straightens, climbs, or closes other than one of its open hinges)."""
    path = closing_path(arch, state, chain, origin, runaway)
    if path is None:
        return None
    height = np.array([potential(arch, p) for p in path])
    if np.any(np.diff(height) > energy_tolerance(arch)) or height[-1] >= height[0]:
        return None
    before, after = contacts(arch, state).touching, contacts(arch, path[-1]).touching
    closed = set(np.flatnonzero((after & ~before).any(axis=1)))
    if len(closed) != 1 or not closed <= {p.joint for p in chain.pivots}:
        return None
    pivots = tuple(p for p in chain.pivots if p.joint not in closed)
    move = float(np.linalg.norm(path[-1].centroids(arch) - origin.centroids(arch), axis=1).max())
    return Landing(path[-1], pivots, chain, float(height[-1]), move)


def _tie_candidates(pivots: tuple[Pivot, ...], closed: np.ndarray) -> list[tuple[Pivot, ...]]:
    """The LP's `pivots` and every linkage with one of them, at a joint still `closed`, moved to another
    closed joint on either side (each once, sorted)."""
    found = {tuple(sorted(pivots))}
    for k, pivot in enumerate(pivots):
        others = pivots[:k] + pivots[k + 1 :]
        if not closed[pivot.joint]:
            continue
        taken = {p.joint for p in others}
        for joint in np.flatnonzero(closed):
            if int(joint) not in taken:
                found.update(tuple(sorted((*others, Pivot(int(joint), side)))) for side in (0, 1))
    return sorted(found)


def rank_landings(arch: RigidArch, landings: list[Landing]) -> list[Landing]:
    """Landings from the lowest weights up; ties go to the hinges nearest the left support."""
    return _ranked(landings, lambda g: g.energy, lambda g: g.pivots, energy_tolerance(arch))


class _Probe(NamedTuple):
    """A candidate mechanism probed two steps on: its first-order energy rate (N), its energy there (J)
    and its placement there."""

    rate: float
    energy_ahead: float
    ahead: Placement


def follow_tie(
    arch: RigidArch, state: Placement, mechanism: Mechanism, admissible: Callable[[Placement], bool]
) -> Mechanism:
    """The three-hinge mechanism to follow from `state`: the LP's `mechanism`, or one with a hinge moved
    to any other closed joint (either side) whose first-order energy rate ties with it (within
    RATE_TIE_FRACTION of the weight) and whose weights sit lower a step `FOLLOW_PROBE_FRACTION` of the
    ring's thickness on, where it must still hold an `admissible` equilibrium (a first-order tie within
    the tolerance is not an exact one): of two tied mechanisms the higher would re-seat into the lower
    at the fixed support. Ties of the second order go to the hinges nearest the left support."""
    step = FOLLOW_PROBE_FRACTION * arch.geometry.thickness
    closed = contacts(arch, state).touching.all(axis=1)  # only a hinge still closed can form elsewhere
    e0 = potential(arch, state)
    options: dict[tuple[Pivot, ...], _Probe] = {}
    for pivots in _tie_candidates(mechanism.pivots, closed):
        one, two = (close_linkage(arch, state, pivots, state.delta + n * step) for n in (1, 2))
        if one is None or two is None or penetrates(arch, state, one, step / arch.geometry.span):
            continue
        e1, e2 = potential(arch, one) - e0, potential(arch, two) - e0
        options[pivots] = _Probe((4.0 * e1 - e2) / (2.0 * step), e2, two)  # the rate to O(step^2)
    if len(options) < 2:
        return mechanism
    weight = float(arch.weight.sum())
    low = min(o.rate for o in options.values())
    own = tuple(sorted(mechanism.pivots))
    tied = [
        p
        for p, o in options.items()
        if o.rate - low <= RATE_TIE_FRACTION * weight and (p == own or admissible(o.ahead))
    ]
    if not tied:
        return mechanism
    best = _ranked(tied, lambda p: options[p].energy_ahead, lambda p: p, energy_tolerance(arch, 2.0 * step))[0]
    if set(best) == set(mechanism.pivots):
        return mechanism
    return Mechanism(best, mechanism.rates, mechanism.power, mechanism.closing)
