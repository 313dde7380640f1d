"""A descent that goes on while the arch is still falling (pure numpy): the static engine's answer to
a solver's timeout is more of the same motion, never a collapse, until the motion stops or a budget
is spent (docs/theory.md, "The static engine")."""

from __future__ import annotations

import numpy as np

from yadearch.solve.newton import Equilibrium, Solver, largest_move
from yadearch.solve.stages import Verdict

DESCENT_RETRIES = 2  # a descent that finds neither equilibrium nor runaway goes on this many times more,
FALLING_FRACTION = 0.02  # ... and on while each go moves a block this x the runaway bound (still falling)
UNBALANCED = 1e-3  # ... or ends pushed by this x the heaviest block's weight on an indefinite tangent
# (not at rest: a stiff ring's fall crawls down a narrow valley of its joints' energy), ...
MAX_DESCENT_GOES = 40  # ... up to this many goes of the solver's descent_iterations


def fall(
    solver: Solver,
    start: np.ndarray,
    u_before: np.ndarray,
    shear: np.ndarray,
    bound: float,
    gravity: float = 1.0,
    multiplier: float = 0.0,
    springs: np.ndarray | None = None,
) -> tuple[Equilibrium, int]:
    """The solver's descent from `start` (runaway `bound`, m) and how many goes it took: where a go finds
    neither equilibrium nor runaway the next goes on from where it stopped (DESCENT_RETRIES times, and
    on while each go moves a block FALLING_FRACTION of the bound or ends far from rest, UNBALANCED, up
    to MAX_DESCENT_GOES), the joints' shear carried from go to go as the DEM carries it step by step
    (a long fall is not one elastic step from where it began), and the fill's `springs` with it."""
    found = solver.descend(start, u_before, shear, bound, gravity=gravity, multiplier=multiplier, springs=springs)
    before, goes, slip = start, 1, np.zeros_like(shear)
    while found.verdict == Verdict.TIMEOUT and goes < MAX_DESCENT_GOES:
        falling = largest_move(found.u, before) >= FALLING_FRACTION * bound
        pushed = found.residual > UNBALANCED and not found.stable()
        if goes > DESCENT_RETRIES and not (falling or pushed):
            break
        before, goes, slip = found.u, goes + 1, slip + found.joints.forces.plastic_slip
        carried, springs = found.joints.forces.shear_force, found.springs
        found = solver.descend(
            found.u, found.u, carried, bound, gravity=gravity, origin=start, multiplier=multiplier, springs=springs
        ).with_slip(slip)
    return found, goes
