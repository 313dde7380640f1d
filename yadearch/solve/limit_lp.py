"""The two linear programmes of rigid-block limit analysis at one placement (scipy's HiGHS).

Static: normal forces N >= 0 at the touching corners of every interface and one shear T per
interface with |T| <= tan(phi) (N_I + N_E) balance each voussoir's weight (3 equations per block);
feasible = an admissible equilibrium exists. Kinematic: the voussoirs' velocities for a unit support
speed that make the weights' potential energy fall fastest, with no interpenetration (gap rate >= 0)
and no sliding at touching corners. Both use one equilibrium matrix A (rows: force x, y and moment
about the origin of each block; columns: N_I, N_E and T of each interface): the gap and slip rates of
a velocity field u are A^T u, so by LP duality the kinematic optimum is a quasi-static state, the
mechanism and its complementary forces (force only where a corner stays closed).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from yadearch.model.loads import LoadPoints, generalised
from yadearch.model.passive_fill import BLOCK, CAPACITY, OUTWARD, spring_points
from yadearch.solve.rigid import (
    EXTRADOS,
    INTRADOS,
    Contacts,
    LimitError,
    MarchStopped,
    Pivot,
    Placement,
    RigidArch,
    contacts,
    cross,
)

LP_METHOD = "highs-ds"  # dual simplex: vertex solutions, i.e. mechanisms with the fewest hinges
# HiGHS's default 1e-7 lets a corner force of 1e-6 of the arch's weight go negative: 0.02 mm of support
# motion near a limit, and a feasibility that flickers there; 1e-10 puts that below 1e-4 mm.
LP_OPTIONS = {"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10}
HINGE_RATE_FRACTION = 1e-6  # relative rotation rates below this fraction of the largest are none
CLOSING_RATE_FRACTION = 1e-6  # an open corner closes if its gap rate is below -this x the largest
STATUS_INFEASIBLE, STATUS_UNBOUNDED, STATUS_NUMERICAL = 2, 3, 4  # scipy.optimize.linprog's status codes
# where HiGHS ends the tight programme in an unknown model status (a shallow 30-voussoir ring at rest: status
# 15), the same dual simplex at 1e-9 solves it (seventh user trial: `limit` stopped with the solver's message)
RETRY_OPTIONS = {"primal_feasibility_tolerance": 1e-9, "dual_feasibility_tolerance": 1e-9}


def linear_programme(objective: np.ndarray, **problem: Any) -> Any:
    """scipy's `linprog` of `objective` and `problem` (its constraints and bounds) by LP_METHOD at
    LP_OPTIONS, made again at RETRY_OPTIONS where HiGHS reports numerical difficulties."""
    from scipy.optimize import linprog  # here, not at import: scipy.optimize costs a run ~50 ms

    result = linprog(objective, method=LP_METHOD, options=LP_OPTIONS, **problem)
    if result.status == STATUS_NUMERICAL:
        result = linprog(objective, method=LP_METHOD, options=RETRY_OPTIONS, **problem)
    return result


@dataclass(frozen=True)
class Statics:
    """An admissible equilibrium, if `feasible`: corner normal forces `normal` (joint, side) and
    shears `shear` (N) on the right block of each interface, with the contacts they act at."""

    feasible: bool
    normal: np.ndarray
    shear: np.ndarray
    contacts: Contacts


@dataclass(frozen=True)
class Mechanism:
    """A mechanism's hinges (left to right, each about a touching corner), relative rotation rate of
    each (rad per m of support motion, > 0 counter-clockwise), the weights' potential-energy rate
    (N m per m), and the open hinges it turns back."""

    pivots: tuple[Pivot, ...]
    rates: tuple[float, ...]
    power: float
    closing: tuple[int, ...] = ()  # interfaces whose open corner it closes (a hinge turned back)


def equilibrium_matrix(arch: RigidArch, c: Contacts) -> np.ndarray:
    """(3 n_blocks, 3 n_joints) generalized forces on every block of unit N_I, N_E, T: a corner's
    normal force acts at the corner, the shear at the touching corners' mean (on the joint line)."""
    m = arch.n_joints
    touching = c.touching.astype(float)
    weights = np.where(touching.sum(1, keepdims=True) > 0, touching, 0.5)
    shear_point = (c.point * weights[:, :, None]).sum(1) / weights.sum(1, keepdims=True)
    columns = np.concatenate(
        [
            np.column_stack([c.normal, cross(c.point[:, INTRADOS], c.normal)]),
            np.column_stack([c.normal, cross(c.point[:, EXTRADOS], c.normal)]),
            np.column_stack([c.tangent, cross(shear_point, c.tangent)]),
        ]
    )  # (3m, 3)
    joint = np.tile(np.arange(m), 3)
    matrix = np.zeros((3 * arch.n_blocks, 3 * m))
    for sign, block in ((1.0, arch.right[joint]), (-1.0, arch.left[joint])):
        for dof in range(3):
            matrix[3 * block + dof, np.arange(3 * m)] += sign * columns[:, dof]
    return matrix


def passive_columns(arch: RigidArch, placement: Placement) -> np.ndarray:
    """(3 n_blocks, k) generalised forces on every block of a unit push of each of the fill's passive
    springs (`arch.passive`): horizontal, toward its block, at its point where `placement` carries it."""
    springs = arch.passive
    columns = np.zeros((3 * arch.n_blocks, len(springs)))
    for k, (spring, point) in enumerate(zip(springs, spring_points(springs, arch.centroid0))):
        block = int(spring[BLOCK])
        unit = LoadPoints(np.array([block]), point[None, :], np.array([[-spring[OUTWARD], 0.0]]))
        columns[:, k] = generalised(unit, arch.n_blocks, placement.place(unit.point, unit.block)).ravel()
    return columns


def with_passive(
    arch: RigidArch,
    placement: Placement,
    a_v: np.ndarray,
    bounds: list[tuple[float | None, float | None]],
    a_ub: np.ndarray | None,
    scale: float,
) -> tuple[np.ndarray, list[tuple[float | None, float | None]], np.ndarray | None]:
    """A static programme's voussoir equilibrium `a_v`, bounds and Coulomb rows `a_ub` (None: none) with
    the fill's passive pushes appended as unknowns between nothing and their capacity, in its force
    `scale` (`passive_columns`; no columns without passive resistance)."""
    passive = passive_columns(arch, placement)[3 : 3 * (arch.n_blocks - 1)]
    bounds = bounds + [(0.0, float(capacity) / scale) for capacity in arch.passive[:, CAPACITY]]
    if a_ub is not None:
        a_ub = np.column_stack([a_ub, np.zeros((a_ub.shape[0], passive.shape[1]))])
    return np.column_stack([a_v, passive]), bounds, a_ub


def weight_load(arch: RigidArch, placement: Placement) -> np.ndarray:
    """(3 n_blocks,) what the contacts must supply to each block: the opposite of its weight, i.e.
    force (0, W) and moment W x_centroid about the origin, and of the forces held on it (`arch.fixed`,
    where `placement` moves their points); also the loads' power per velocity."""
    x = placement.centroids(arch)[:, 0]
    load = np.column_stack([np.zeros_like(x), arch.weight, arch.weight * x])
    fixed = arch.fixed
    if len(fixed.block):
        load -= generalised(fixed, arch.n_blocks, placement.place(fixed.point, fixed.block))
    return load.ravel()


def _split(
    arch: RigidArch, matrix: np.ndarray, load: np.ndarray, placement: Placement
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rows of the voussoirs (unknown motion), and the contacts' rates per unit path rate of the
    moving supports (prescribed motion: their generalised velocities at the origin)."""
    n = arch.n_blocks
    vouss = slice(3, 3 * (n - 1))
    rates = np.zeros(matrix.shape[1])
    for side, rows in (("left", slice(0, 3)), ("right", slice(3 * (n - 1), None))):
        motion = arch.movement.motion(side)
        if motion is not None:
            rates += matrix[rows].T @ motion.rates(placement.delta)
    return matrix[vouss], load[vouss], rates


def solve_statics(arch: RigidArch, placement: Placement, friction: bool = True, refine: bool = False) -> Statics:
    """The admissible equilibrium that presses least on the moving support along its motion (the
    dual of the kinematic problem, so at rest it picks the state the mechanism will follow); with
    `refine`, forces corrected by least squares so that equilibrium holds to round-off."""
    c = contacts(arch, placement)
    m = arch.n_joints
    a_v, load, support = _split(arch, equilibrium_matrix(arch, c), weight_load(arch, placement), placement)
    scale, rows, bounds, a_ub, b_ub = static_constraints(arch, c, friction)
    a_v, bounds, a_ub = with_passive(arch, placement, a_v, bounds, a_ub, scale)
    objective = np.concatenate([support, np.zeros(a_v.shape[1] - len(support))])  # the pushes cost nothing
    problem = {
        "A_ub": a_ub,
        "b_ub": b_ub,
        "A_eq": a_v * rows[:, None],
        "b_eq": load * rows / scale,
        "bounds": bounds,
    }
    result = linear_programme(objective, **problem)
    if result.status == STATUS_UNBOUNDED:  # a self-stress (flat arch) relieves the support without end
        result = linear_programme(np.zeros_like(objective), **problem)
    if result.status == STATUS_INFEASIBLE:
        return Statics(False, np.zeros((m, 2)), np.zeros(m), c)
    if result.status != 0:
        raise LimitError(f"static LP failed at {placement.delta * 1e3:.3f} mm: {result.message}")
    x = result.x * scale
    if refine:
        free = np.array([hi is None for _, hi in bounds])
        x[free] += np.linalg.lstsq(a_v[:, free], load - a_v @ x, rcond=None)[0]
    return Statics(True, np.column_stack([x[:m], x[m : 2 * m]]), x[2 * m : 3 * m], c)


def static_constraints(
    arch: RigidArch, c: Contacts, friction: bool
) -> tuple[float, np.ndarray, list[tuple[float | None, float | None]], np.ndarray | None, np.ndarray | None]:
    """What the static programmes share: the force scale (the arch's weight; moments in it x the ring's
    thickness), the voussoirs' row scaling, the bounds of N_I, N_E (>= 0 where the corner touches, else
    0) and T (free), and Coulomb's rows |T| <= tan(phi) (N_I + N_E) as A_ub x <= b_ub (None without
    `friction`)."""
    m = arch.n_joints
    scale = float(arch.weight[1:-1].sum())
    rows = np.tile([1.0, 1.0, 1.0 / arch.geometry.thickness], arch.n_blocks - 2)
    bounds: list[tuple[float | None, float | None]] = [(0.0, None if t else 0.0) for t in c.touching.T.ravel()]
    bounds += [(None, None)] * m
    if not friction:
        return scale, rows, bounds, None, None
    mu = arch.tan_phi * np.eye(m)
    return scale, rows, bounds, np.block([[-mu, -mu, np.eye(m)], [-mu, -mu, -np.eye(m)]]), np.zeros(2 * m)


def mechanism_pivots(
    arch: RigidArch, omega: np.ndarray, gaps: np.ndarray, touching: np.ndarray
) -> tuple[np.ndarray, tuple[Pivot, ...], np.ndarray]:
    """The hinges of a velocity field: the interfaces whose blocks' rotation rates `omega` (every block)
    differ by more than HINGE_RATE_FRACTION of the largest difference, each about the touching corner
    whose gap rate (`gaps`, joint x side) is least; (their indices, pivots, every relative rate)."""
    relative = omega[arch.right] - omega[arch.left]
    hinged = np.flatnonzero(np.abs(relative) > HINGE_RATE_FRACTION * max(np.abs(relative).max(), 1e-300))
    closed_rates = np.where(touching, gaps, np.inf)  # an open corner is no pivot
    return hinged, tuple(Pivot(int(k), int(np.argmin(closed_rates[k]))) for k in hinged), relative


def _support_turn_rate(arch: RigidArch, side: str, placement: Placement, support_speed: float) -> float:
    """How fast a support turns per unit path rate times `support_speed` (0 if it is fixed)."""
    motion = arch.movement.motion(side)
    return 0.0 if motion is None else float(motion.rates(placement.delta)[2]) * support_speed


def solve_kinematics(arch: RigidArch, placement: Placement, support_speed: float = 1.0) -> Mechanism | None:
    """The mechanism of least potential-energy rate for `support_speed` (m per m): None if it is
    unbounded (a mechanism at a fixed support lowers the weights: no admissible equilibrium). With
    `support_speed` 0 the velocities are boxed, giving the collapse mechanism when one exists."""
    c = contacts(arch, placement)
    m = arch.n_joints
    a_v, load, rates = _split(arch, equilibrium_matrix(arch, c), weight_load(arch, placement), placement)
    support = rates * support_speed  # rates from the support motion
    corner = c.touching.T.ravel()
    slip = np.concatenate([np.zeros(2 * m, bool), c.touching.any(axis=1)])
    length = arch.geometry.span  # rotations boxed to 1/length: velocities of order one across the arch
    box = None if support_speed else [(-1.0, 1.0), (-1.0, 1.0), (-1.0 / length, 1.0 / length)]
    bounds = [(None, None)] * len(load) if box is None else box * (len(load) // 3)
    result = linear_programme(
        load,
        A_ub=-a_v.T[np.flatnonzero(corner)],
        b_ub=support[np.flatnonzero(corner)],
        A_eq=a_v.T[slip],
        b_eq=-support[slip],
        bounds=bounds,
    )
    if result.status == STATUS_UNBOUNDED:
        return None
    if result.status == STATUS_INFEASIBLE:
        raise MarchStopped(f"at {placement.delta * 1e3:.3f} mm no mechanism can follow the support")
    if result.status != 0:
        raise MarchStopped(f"kinematic LP failed at {placement.delta * 1e3:.3f} mm: {result.message}")
    rates = a_v.T @ result.x + support  # gap rates (2m) and slip rates (m) of every interface
    gaps = np.column_stack([rates[:m], rates[m : 2 * m]])
    omega = np.concatenate(
        [
            [_support_turn_rate(arch, "left", placement, support_speed)],
            result.x[2::3],
            [_support_turn_rate(arch, "right", placement, support_speed)],
        ]
    )
    hinged, pivots, relative = mechanism_pivots(arch, omega, gaps, c.touching)
    closing = ~c.touching & (gaps < -CLOSING_RATE_FRACTION * np.abs(gaps).max())
    return Mechanism(
        pivots,
        tuple(float(relative[k]) for k in hinged),
        float(result.fun),
        tuple(int(k) for k in np.flatnonzero(closing.any(axis=1))),
    )
