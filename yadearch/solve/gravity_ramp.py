"""The static engine's self-weight as a load ramp (pure numpy): gravity in equal steps from the blocks
exactly touching, each step solved from the last (docs/theory.md, "The static engine")."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from yadearch.errors import CANNOT_STAND, UNRESOLVED
from yadearch.solve.newton import Equilibrium, Solver
from yadearch.solve.stages import Verdict
from yadearch.solve.static_state import StaticEngineError
from yadearch.solve.statics import StaticArch

GRAVITY_STEPS = 10  # the self-weight is applied in this many equal load steps,
CONFIRMING_STEPS = 20  # ... and in this many where those fall or fail, before the arch is said not to stand
SELFWEIGHT_FALL = 0.05  # a block falling this far (m) under self-weight means the arch cannot stand

Fall = Callable[..., Equilibrium]  # the path's descent going on while it falls (`solve.falls.fall`)


def gravity_ramp(arch: StaticArch, solver: Solver, fall: Fall, steps: int) -> tuple[Equilibrium, np.ndarray, dict]:
    """Gravity in `steps` equal load steps from the blocks exactly touching: the first solved by the
    descent (the joints have no stiffness before they are pressed), the others by Newton from the last
    (by the descent where Newton fails), until one does not end stable; the joints' shear is carried
    from step to step, as the DEM carries it, so that a joint counts only the sliding it makes while it
    touches, and the fill's springs with it (`model.passive_fill.yielded`). The last step's equilibrium,
    the sliding, and the ramp's record (steps, verdict, gravity reached, the last step's largest move)."""
    u = arch.with_supports(arch.at_rest(), 0.0)
    shear = np.zeros(len(arch.table.left))
    slip = np.zeros_like(shear)
    springs: np.ndarray | None = None  # the unyielded fill's
    for k in range(1, steps + 1):
        gravity = k / steps
        pressed = solver.newton(u, u, shear, gravity=gravity, springs=springs) if k > 1 else None
        found = (
            pressed
            if pressed is not None and pressed.stable()
            else fall(u, u, shear, SELFWEIGHT_FALL, gravity=gravity, springs=springs)
        )
        if found.verdict != Verdict.STABLE:
            break
        u, shear, springs = found.u, found.joints.forces.shear_force, found.springs
        slip = slip + found.joints.forces.plastic_slip
    record = {
        "gravity_steps": steps,
        "verdict": str(found.verdict),
        "gravity": k / steps,
        "moved_mm": 1e3 * found.moved,
    }
    return found, slip, record


def ramps_to_stand(
    arch: StaticArch, solver: Solver, fall: Fall, steps: tuple[int, ...], ramps: list[dict]
) -> tuple[Equilibrium, np.ndarray]:
    """Gravity ramps of each of `steps` load steps in turn, each recorded in `ramps`, until one reaches a
    stable state under the whole weight (the proof that the arch stands: the first descent, from faces
    exactly touching, can take another way): its equilibrium and sliding. StaticEngineError: the arch
    cannot stand if a ramp fell (a block falling is its motion), unresolved if every one stopped."""
    for count in steps:
        found, slip, ramp = gravity_ramp(arch, solver, fall, count)
        ramps.append(ramp)
        if found.verdict == Verdict.STABLE:
            return found, slip
    said = "; ".join(ramp_text(ramp) for ramp in ramps)
    if any(ramp["verdict"] == Verdict.RUNAWAY for ramp in ramps):
        raise StaticEngineError(f"{CANNOT_STAND} ({said})")
    raise StaticEngineError(
        f"{UNRESOLVED}: the self-weight descent found neither an equilibrium nor a fall of "
        f"{1e3 * SELFWEIGHT_FALL:.0f} mm after its retries ({said}): the solver's failure, not an arch that "
        "cannot stand"
    )


def ramp_text(ramp: dict) -> str:
    """One gravity ramp of the self-weight in words, as a run's message gives it."""
    if ramp["verdict"] == Verdict.STABLE:
        return f"in {ramp['gravity_steps']} load steps it stood"
    went = "fell" if ramp["verdict"] == Verdict.RUNAWAY else "stopped"
    return (
        f"in {ramp['gravity_steps']} load steps it {went} at {ramp['gravity']:.2f} of gravity, a block "
        f"moved {ramp['moved_mm']:.1f} mm"
    )
