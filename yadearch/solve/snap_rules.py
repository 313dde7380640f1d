"""The rules a snap obeys in the march (`solve.march`): the weights never rise along it (past a fold,
only on the way to its top), and its chain moves one hinge to a nearby interface; a chain that breaks
them is not a snap the march follows. And the bisection the march places its limits and closures by."""

from __future__ import annotations

from typing import TypeGuard

import numpy as np

from yadearch.solve.limit_lp import Mechanism
from yadearch.solve.rigid import Pivot


def climbs(height: list[float], past_fold: bool, tie: float = 0.0) -> bool:
    """Whether the weights rise along a snap where they may not (heights of its samples; J, closer
    than `tie` being equal): a rigid arch snaps only downhill, else it would rest on four open hinges;
    past a fold the chain may first climb the rigid barrier the fold removed, but must end lower and
    descend from its top."""
    if not past_fold:
        return bool(np.any(np.diff(height) > tie))
    top = int(np.argmax(height))
    return height[-1] >= height[0] - tie or bool(np.any(np.diff(height[top:]) > tie))


def moves_a_hinge(chain: Mechanism | None, pivots: tuple[Pivot, ...], reach: int = 1) -> TypeGuard[Mechanism]:
    """Whether a fixed-support `chain` moves a hinge of `pivots` to another interface: one new hinge,
    at most `reach` interfaces from a hinge it turns back (to close; 1 for a rigid snap, the next
    interface; where it turns back two, the one that closes first re-seats). Any other lowering
    chain is a collapse."""
    if chain is None or chain.power >= 0 or len(chain.pivots) != 4 or not chain.closing:
        return False
    new = [p for p in chain.pivots if p not in pivots]
    hinged = {p.joint for p in pivots}
    return len(new) == 1 and any(b in hinged and 1 <= abs(new[0].joint - b) <= reach for b in chain.closing)


def largest_accepted(ok, high: float, width: float) -> float:
    """The largest offset in [0, high] that `ok` accepts (ok(0) assumed), to within `width`."""
    low = 0.0
    while high - low > width:
        mid = 0.5 * (low + high)
        if mid in (low, high):  # adjacent floats: as close as it gets
            break
        low, high = (mid, high) if ok(mid) else (low, mid)
    return low
