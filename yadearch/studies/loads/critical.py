"""The critical position of a concentrated load, as a bridge assessment asks for it: a rigid arch's
capacity dips wherever a load stands over a joint (the hinge under it), so between the even samples of
the influence line the positions that put a load of the group over a joint are tried around each
sampled least, and the best polished between its neighbours (scipy's bounded search, for a load spread
or dispersed off the joints)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
import pandas as pd

from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry, further_loads

CAPACITY = "collapse_load_N"
POSITION = "position_over_span"
SAMPLED = "sampled"  # the influence line's column: True at its even positions, False at the critical ones
POSITION_TOLERANCE = 1e-4  # of the span: where the polishing search stops (0.5 mm on a 5 m span)
POLISH_ITERATIONS = 12  # the polishing search's evaluations at most
TIED = 1e-3  # the mirror position's capacity within this fraction of the critical one: a critical position too


def with_critical(table: pd.DataFrame, row_at: Callable[[float], dict], over_joints: Sequence[float]) -> pd.DataFrame:
    """`table` (an influence line at even positions) with the critical position's row (`row_at(x)`: the
    row of a load at x), and its mirror's where that ties, marked `sampled` False: the least of the
    positions `over_joints` (a load of the group over a joint, fractions of the span) between the
    neighbours of each sampled local least, polished; the table alone where no sample collapses or
    nothing between them carries less."""
    sampled = table.assign(**{SAMPLED: True})
    positions = table[POSITION].to_numpy(float)
    capacity = _capacity(table[CAPACITY])
    if not np.isfinite(capacity).any():  # no position collapses: nothing to refine
        return sampled
    tried: dict[float, dict] = {}

    def capacity_at(x: float) -> float:
        if x not in tried:
            tried[x] = row_at(x)
        value = float(tried[x][CAPACITY])
        return value if np.isfinite(value) else np.inf  # as `_capacity` reads the table

    ends = np.concatenate([[0.0], positions, [1.0]])
    for k in _local_leasts(capacity):
        for x in over_joints:
            if ends[k] < x < ends[k + 2]:
                capacity_at(float(x))
    if not tried:
        return sampled
    best = min(tried, key=capacity_at)
    known = np.sort(np.concatenate([ends, list(tried)]))
    low, high = known[known < best].max(), known[known > best].min()
    from scipy.optimize import minimize_scalar  # here, not at import: scipy.optimize costs ~50 ms

    options = {"xatol": POSITION_TOLERANCE, "maxiter": POLISH_ITERATIONS}
    minimize_scalar(capacity_at, bounds=(low, high), method="bounded", options=options)
    best = min(tried, key=capacity_at)
    capacity_at(1.0 - best)  # the mirror position: a symmetric arch's tie, or less
    best = min(tried, key=capacity_at)
    critical = capacity_at(best)
    if not critical < capacity.min():
        return sampled  # the sampled least is the critical position
    found = [best]
    mirror = 1.0 - best
    if mirror != best and abs(capacity_at(mirror) - critical) <= TIED * critical:  # a symmetric arch: both
        found.append(mirror)
    refined = pd.DataFrame([{**tried[x], SAMPLED: False} for x in found])
    return pd.concat([sampled, refined], ignore_index=True).sort_values(POSITION, kind="stable", ignore_index=True)


def over_joint_positions(case: ArchCase) -> tuple[float, ...]:
    """The positions (fractions of the span, as `loads.load_position_over_span` measures them) that put
    the load, or one of its further loads, over a joint's extrados corner."""
    geometry = arch_geometry(case)
    origin = geometry.joints[0].intrados[0]
    offsets = (0.0, *(offset for offset, _ in further_loads(case, geometry.span)))
    found = {
        (float(joint.extrados[0]) - origin - offset) / geometry.span for joint in geometry.joints for offset in offsets
    }
    return tuple(sorted(x for x in found if 0.0 < x < 1.0))


def _local_leasts(capacity: np.ndarray) -> list[int]:
    """The samples whose capacity is no more than either neighbour's (the line's ends count)."""
    padded = np.concatenate([[np.inf], capacity, [np.inf]])
    return [
        k for k in range(len(capacity)) if np.isfinite(capacity[k]) and padded[k + 1] <= min(padded[k], padded[k + 2])
    ]


def _capacity(values: pd.Series) -> np.ndarray:
    """Capacities as floats, inf where the load does not collapse the arch (NaN: no answer)."""
    numbers = pd.to_numeric(values, errors="coerce").to_numpy(float)
    return np.where(np.isfinite(numbers), numbers, np.inf)
