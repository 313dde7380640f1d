"""The rigid-block march with compliant joints: where a DEM arch of finite joint stiffness moves its
hinges and collapses (docs/theory.md, "Compliant hinges").

A Winkler joint folds when the rigid thrust comes within `model.compliant_hinge.fold_margin` of an
edge (kn^(-1/3): 0.1 mm beside a hinge at kn 3000 N/mm^3 on the paper's arch), long before the rigid
thrust reaches it. The march (`solve.march`) requires that margin of every closed joint whose thrust
nears an edge. Where one folds, the four-hinge chain that opens it is followed at a fixed support:
if it turns a hinge back until it closes, ending lower than it started, the hinge has moved there
(it may first climb the rigid barrier the fold removed); if it would climb to the closure, the two
joints share the hinge until, further on, the chain descends; if it closes no hinge, the arch
collapses on it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.model.compliant_hinge import fold_margin
from yadearch.solve.limit_lp import Mechanism
from yadearch.solve.rigid import Contacts, Pivot, Placement, RigidArch, contacts, turn_four_bar

CURVATURE_STEP_RAD = 1e-4  # turn of the chain's first segment for the central differences
OPENING_PROBE_RAD = 1e-6  # turn that tells which way the chain opens the folding joint
# measured on the paper's arch: within 0.8 % of the DEM for kn >= 15 N/mm^3, where the largest fold
# margin met stays below 5 % of the joint; at kn <= 13.3 (5.5 %) the DEM's hinge A sits further from
# the springing, moved by the whole arch's deformation, which the march ignores (+15-17 %)
VALID_MARGIN_FRACTION = 0.05
SCREEN_FRACTION = 0.25  # joints whose thrust stays further from both edges (of their length) cannot fold


@dataclass(frozen=True)
class Margin:
    """A closed joint: the corner it would pivot on, the rigid thrust's distance from that corner (m),
    the curvature G of the chain that opens it (N m / rad^2) and the distance at which it folds (m)."""

    pivot: Pivot
    margin: float
    curvature: float
    critical: float

    @property
    def folds(self) -> bool:
        return self.margin < self.critical


def potential(arch: RigidArch, placement: Placement) -> float:
    """The potential energy (J, from the origin) of the weights and of the constant forces held on the
    blocks (`arch.fixed`: -F . r at each force's point where `placement` moves it)."""
    weights = float(arch.weight @ placement.centroids(arch)[:, 1])
    fixed = arch.fixed
    if not len(fixed.block):
        return weights
    return weights - float(np.sum(fixed.force * placement.place(fixed.point, fixed.block)))


def _turn(arch: RigidArch, placement: Placement, joint: int) -> float:
    return float(placement.rot[arch.right[joint]] - placement.rot[arch.left[joint]])


def chain_curvature(arch: RigidArch, placement: Placement, chain: tuple[Pivot, ...], joint: int) -> float:
    """G of the four-hinge `chain` at a fixed support: minus the second derivative of the weights'
    potential energy with respect to the turn of `joint` (N m / rad^2; central differences)."""
    h = CURVATURE_STEP_RAD
    plus, minus = (turn_four_bar(arch, placement, chain, s * h) for s in (1.0, -1.0))
    if plus is None or minus is None:
        return 0.0
    e0, e_plus, e_minus = potential(arch, placement), potential(arch, plus), potential(arch, minus)
    t0 = _turn(arch, placement, joint)
    t_plus, t_minus = _turn(arch, plus, joint) - t0, _turn(arch, minus, joint) - t0
    rate, bend = (t_plus - t_minus) / (2.0 * h), (t_plus + t_minus) / h**2  # the joint's turn per turn
    if abs(rate) < 1e-12:
        return 0.0
    slope, curve = (e_plus - e_minus) / (2.0 * h), (e_plus + e_minus - 2.0 * e0) / h**2
    return -(curve - slope / rate * bend) / rate**2


def joint_margins(
    arch: RigidArch, placement: Placement, normal: np.ndarray, c: Contacts, pivots: tuple[Pivot, ...], kn: float
) -> list[Margin]:
    """The margin of every closed joint whose thrust comes within SCREEN_FRACTION of its length of an
    edge, from the corner normal forces `normal` (joint, side) of an admissible equilibrium; none
    while every hinge is still closed (at rest the joints beside a hinge carry the thrust alike)."""
    if all(c.touching[p.joint].all() for p in pivots):
        return []
    hinged = {p.joint for p in pivots}
    margins = []
    for joint in range(arch.n_joints):
        total = float(normal[joint].sum())
        if joint in hinged or not c.touching[joint].all() or total <= 0.0:
            continue
        side = int(np.argmin(normal[joint, ::-1]))  # the corner the thrust is nearer: the other carries less
        margin = thrust_distance(normal, c, joint, side)
        if margin > SCREEN_FRACTION * _length(c, joint):
            continue
        pivot = Pivot(joint, side)
        curvature = chain_curvature(arch, placement, tuple(sorted((*pivots, pivot))), joint)
        margins.append(Margin(pivot, margin, curvature, fold_margin(curvature, kn, arch.geometry.depth)))
    return margins


def edge_distances(
    arch: RigidArch, normal: np.ndarray, c: Contacts, pivots: tuple[Pivot, ...]
) -> list[tuple[float, Pivot]]:
    """The rigid thrust's distance (m) from the hinge side's corner at each closed joint beside an
    open hinge of `pivots`, from the corner normal forces `normal` (joint, side) of an equilibrium: how
    near the joint is to sharing the hinge (a joint of finite kn folds within `fold_margin`)."""
    hinged = {p.joint for p in pivots}
    found = []
    for p in pivots:
        if c.touching[p.joint].all():
            continue
        for joint in (p.joint - 1, p.joint + 1):
            total = float(normal[joint].sum()) if 0 <= joint < arch.n_joints else 0.0
            if joint in hinged or total <= 0.0 or not c.touching[joint].all():
                continue
            found.append((thrust_distance(normal, c, joint, p.side), Pivot(joint, p.side)))
    return found


def thrust_distance(normal: np.ndarray, c: Contacts, joint: int, side: int) -> float:
    """The rigid thrust's distance (m) from `joint`'s corner on `side`, from the corner normal forces
    `normal` (joint, side) of an equilibrium: the joint's length x the other corner's share."""
    return _length(c, joint) * float(normal[joint, 1 - side]) / float(normal[joint].sum())


def _length(c: Contacts, joint: int) -> float:
    """The joint's length between its two corners (m)."""
    return float(np.linalg.norm(c.point[joint, 1] - c.point[joint, 0]))


def opening_chain(arch: RigidArch, placement: Placement, pivots: tuple[Pivot, ...], fold: Margin) -> Mechanism:
    """The four-hinge chain that opens the folding joint of `fold` about its corner, as a mechanism
    the rigid march's snap follows: it turns back (to close) the open hinges on the folding joint's
    side whose gaps it narrows (one: the hinge moves there; none: the arch collapses on the chain)."""
    chain = tuple(sorted((*pivots, fold.pivot)))
    sign = 1.0
    probe = turn_four_bar(arch, placement, chain, OPENING_PROBE_RAD)
    if probe is None or contacts(arch, probe).gap[fold.pivot.joint, 1 - fold.pivot.side] <= 0.0:
        sign = -1.0
        probe = turn_four_bar(arch, placement, chain, -OPENING_PROBE_RAD)
    closing: tuple[int, ...] = ()
    if probe is not None:
        before, after = contacts(arch, placement).gap, contacts(arch, probe).gap
        closing = tuple(
            p.joint
            for p in pivots
            if p.side == fold.pivot.side and after[p.joint, 1 - p.side] < before[p.joint, 1 - p.side]
        )
    return Mechanism(chain, (sign,) * len(chain), -abs(fold.curvature), closing)


def folds(margins: list[Margin], armed: dict[Pivot, bool]) -> list[Margin]:
    """The joints of `margins` that fold, deepest first. Only a joint that held when first seen with
    the hinges open (`armed`, filled here) can fold: one that never held shares a hinge from the
    start (the keystone's tie, a hinge spread over two joints)."""
    for m in margins:
        armed.setdefault(m.pivot, not m.folds)
    return sorted((m for m in margins if m.folds and armed[m.pivot]), key=lambda m: m.margin - m.critical)
