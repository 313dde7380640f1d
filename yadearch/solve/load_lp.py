"""The load multiplier of rigid-block limit analysis (scipy's HiGHS): the largest factor on a live
load that the arch, its self-weight held, carries in an admissible equilibrium (no tension: corner
forces N >= 0; Coulomb friction |T| <= tan(phi) (N_I + N_E)), with the collapse mechanism from the
programme's dual (the blocks' virtual velocities), as Livesley and Gilbert formulate it for RING.

The equilibrium matrix is the support-movement analysis's (`solve.limit_lp`); the arch stands at rest.
With enough friction this lower bound equals the least multiplier over the arch's four-hinge
mechanisms (`solve.mechanisms`, the independent check)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from yadearch.case.config import ArchCase
from yadearch.case.held import require_live_load, unheld
from yadearch.case.mechanics import live_load
from yadearch.model.loads import UNITS, LoadPoints, generalised, live_load_points
from yadearch.solve.limit_lp import (
    HINGE_RATE_FRACTION,
    STATUS_INFEASIBLE,
    STATUS_UNBOUNDED,
    equilibrium_matrix,
    linear_programme,
    mechanism_pivots,
    static_constraints,
    weight_load,
    with_passive,
)
from yadearch.solve.pose import march_placement
from yadearch.solve.rigid import LimitError, Pivot, Placement, RigidArch, at_rest, contacts, rigid_arch

FRICTION_CAP_TOLERANCE = 1e-6  # a joint whose shear is within this fraction of its friction cap is at it


@dataclass(frozen=True)
class LoadCapacity:
    """The live load's multiplier at collapse (inf: no collapse however large; NaN: the arch does not
    stand under its self-weight), the mechanism's hinges (left to right) and the corner normal forces
    (joint, intrados/extrados) and shears (N) at collapse."""

    multiplier: float
    pivots: tuple[Pivot, ...]
    normal: np.ndarray = field(repr=False)
    shear: np.ndarray = field(repr=False)
    unit: str = "N"  # of the multiplier: the live load is 1 N, or 1 g
    arch_weight_N: float = math.nan  # the voussoirs' weight, to read a load against
    fill_weight_N: float = 0.0  # the backfill's weight the voussoirs carry
    sliding: tuple[int, ...] = ()  # the interfaces (numbered from 1) the mechanism slides, at their friction cap

    @property
    def hinge_labels(self) -> str:
        return " ".join(p.label for p in self.pivots)


def load_analysis(case: ArchCase, placement: Placement | None = None) -> LoadCapacity:
    """The capacity of `case`'s arch to its live load (`case.loads`), its self-weight held, at rest or
    in `placement` (a state of the support movement's rigid march: the residual capacity)."""
    require_live_load(case)
    arch = rigid_arch(unheld(case))  # the live load grows from nothing; the backfill is held
    load = live_load(case, arch.geometry)
    placement = placement or at_rest(arch)
    found = load_capacity(arch, live_forces(case, arch, placement), placement)
    fill = max(-float(arch.fixed.force[:, 1].sum()), 0.0)  # the fixed loads: the fill's, the live load unheld
    return replace(found, unit=UNITS[load.kind], arch_weight_N=float(arch.weight[1:-1].sum()), fill_weight_N=fill)


def live_forces(case: ArchCase, arch: RigidArch, placement: Placement | None = None) -> np.ndarray:
    """The case's unit live load on `arch` as (n_blocks, 3) generalised forces, each point force where
    `placement` puts its block (default: the undeformed arch)."""
    points = live_load_points(arch.geometry, arch.centroid0, arch.weight, live_load(case, arch.geometry))
    return _placed(points, arch, placement)


def _placed(points: LoadPoints, arch: RigidArch, placement: Placement | None) -> np.ndarray:
    """Point forces as (n_blocks, 3) generalised forces at the points `placement` moves them to."""
    return generalised(points, arch.n_blocks, placement.place(points.point, points.block) if placement else None)


def load_capacity(
    arch: RigidArch,
    live: np.ndarray,
    placement: Placement | None = None,
    friction: bool = True,
) -> LoadCapacity:
    """The largest multiplier of the live load `live` ((n_blocks, 3) generalised forces, as
    `model.loads.generalised` gives them) that the arch carries under its self-weight and the loads it
    holds (`arch.fixed`: the backfill) in `placement` (default: at rest)."""
    placement = placement or at_rest(arch)
    c = contacts(arch, placement)
    m = arch.n_joints
    voussoirs = slice(3, 3 * (arch.n_blocks - 1))
    a_v = equilibrium_matrix(arch, c)[voussoirs]
    held = weight_load(arch, placement)[voussoirs]  # what the contacts supply against the held loads
    scale, rows, bounds, a_ub, b_ub = static_constraints(arch, c, friction)
    pushed, bounds, a_ub = with_passive(arch, placement, a_v, bounds, a_ub, scale)  # the fill's passive pushes
    a_eq = np.column_stack([pushed, np.ravel(live)[voussoirs]]) * rows[:, None]  # ... and the live load
    objective = np.zeros(a_eq.shape[1])
    objective[-1] = -1.0
    bounds = bounds + [(0.0, None)]  # the multiplier
    if a_ub is not None:
        a_ub = np.column_stack([a_ub, np.zeros(2 * m)])
    result = linear_programme(objective, A_ub=a_ub, b_ub=b_ub, A_eq=a_eq, b_eq=held * rows / scale, bounds=bounds)
    if result.status == STATUS_UNBOUNDED:
        return LoadCapacity(math.inf, (), np.zeros((m, 2)), np.zeros(m))
    if result.status == STATUS_INFEASIBLE:
        return LoadCapacity(math.nan, (), np.zeros((m, 2)), np.zeros(m))
    if result.status != 0:
        raise LimitError(f"load multiplier LP failed: {result.message}")
    x = result.x[:-1] * scale
    velocity = result.eqlin.marginals * rows  # the dual: the voussoirs' virtual velocities
    rates = a_v.T @ velocity  # each force's work-conjugate rate: the corners' opening, the joints' sliding
    pivots = _hinges(arch, velocity, rates, c.touching)
    normal = np.column_stack([x[:m], x[m : 2 * m]])
    shear = x[2 * m : 3 * m]
    sliding = _sliding(arch, rates, normal, shear)
    return LoadCapacity(float(result.x[-1] * scale), pivots, normal, shear, sliding=sliding)


def _hinges(arch: RigidArch, velocity: np.ndarray, rates: np.ndarray, touching: np.ndarray) -> tuple[Pivot, ...]:
    """The joints the mechanism (the voussoirs' `velocity`, its forces' `rates`) turns, each about the
    corner that stays closed."""
    m = arch.n_joints
    omega = np.concatenate([[0.0], velocity[2::3], [0.0]])
    gaps = np.abs(np.column_stack([rates[:m], rates[m : 2 * m]]))  # the dual's sign is the programme's
    return mechanism_pivots(arch, omega, gaps, touching)[1]


def _sliding(arch: RigidArch, rates: np.ndarray, normal: np.ndarray, shear: np.ndarray) -> tuple[int, ...]:
    """The interfaces (from 1) the mechanism slides: a sliding rate above HINGE_RATE_FRACTION of the
    largest rate (the dual's, of every corner and shear force), the friction at its cap."""
    m = arch.n_joints
    slide = np.abs(rates[2 * m : 3 * m])
    largest = max(float(np.abs(rates).max()), 1e-300)
    closed = normal.sum(axis=1)
    capped = (closed > 0.0) & (np.abs(shear) >= (1.0 - FRICTION_CAP_TOLERANCE) * arch.tan_phi * closed)
    return tuple(int(k) + 1 for k in np.flatnonzero((slide > HINGE_RATE_FRACTION * largest) & capped))


def residual_capacity(case: ArchCase, at_mm: float) -> LoadCapacity:
    """The live load's capacity after the case's support movement to `at_mm` (along its path), in the
    state the rigid march has the arch there (its hinges open): the residual capacity of a settled arch."""
    placement, march = march_placement(unheld(case), at_mm)  # the movement first, then the load
    if march.du_rigid_mm is not None and march.du_rigid_mm <= at_mm:
        raise LimitError(f"the rigid arch collapses at {march.du_rigid_mm:.2f} mm, before {at_mm:g} mm of movement")
    return load_analysis(case, placement)
