"""The self-weight stage of a DEM run (YADE layer): gravity ramped in over the joints' periods, the arch
settled with the supports still, du's origin zeroed at that equilibrium (docs/theory.md, "Self-weight")."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from yadearch.case.mechanics import standing_parameters
from yadearch.dem.live_arch import settle_selfweight
from yadearch.dem.scene import body_states
from yadearch.dem.stepping import CHECK_EVERY_STEPS
from yadearch.errors import CANNOT_STAND, RunFailedError
from yadearch.model import units
from yadearch.solve.stages import Stage
from yadearch.solve.standing import why_not_standing

if TYPE_CHECKING:
    from yadearch.dem.runner import Runner

SELFWEIGHT_COLLAPSE_MM = 50.0  # a block falling this far under self-weight means the arch cannot stand


def apply_selfweight(runner: Runner) -> dict:
    """Apply gravity gradually (over `gravity_ramp_periods` joint periods, so that a soft arch
    does not overshoot past its equilibrium), settle with the supports still (unbalanced force
    and block speeds as in a hold, and the supports carrying the weight within the same
    tolerance, so that the reactions read there are static), and zero du's origin there."""
    from yade import O

    num = runner.num
    runner.stage = Stage.SELFWEIGHT
    start = O.iter
    ramp_s = num.gravity_ramp_periods * math.pi * O.dt / num.timestep_safety
    max_steps = int((num.selfweight_max_s + ramp_s) / O.dt)
    newton = runner.scene.newton
    gravity = np.array(newton.gravity)
    ramp_steps = max(1, int(ramp_s / O.dt))
    runner.weight = (
        sum(O.bodies[i].state.mass for i in runner.scene.voussoir_ids) * runner.case.loading.gravity_m_per_s2
    )
    # the backfill's weight on the voussoirs, which the supports carry beside the arch's
    fill = runner.dead_loads.vertical if runner.dead_loads is not None else 0.0
    unbalanced = math.inf
    while O.iter - start < max_steps:
        fraction = min(1.0, (O.iter - start) / ramp_steps)
        newton.gravity = tuple(gravity * fraction)
        runner.run_steps(CHECK_EVERY_STEPS)
        runner.positions()  # raises on a NaN
        unbalanced = runner.unbalanced()
        runner.progress(f"gravity {fraction:.0%}, unbalanced {unbalanced:.2e}")
        sag = float(np.max(np.abs(body_states(runner.scene)[0] - runner.scene.pos0)))
        if sag > units.mm(SELFWEIGHT_COLLAPSE_MM):
            raise RunFailedError(
                f"{CANNOT_STAND}: a block fell {units.to_mm(sag):.0f} mm ({standing_parameters(runner.case)}); "
                + why_not_standing(runner.case)
            )
        if (
            fraction >= 1.0
            and unbalanced < num.equilibrium_tolerance
            and O.iter - start > ramp_steps + 10 * CHECK_EVERY_STEPS
            and runner.recorder.voussoir_speeds().max() < units.mm(num.still_speed_mm_per_s)
            and runner.recorder.weight_carried_error(runner.weight + fill) < num.equilibrium_tolerance
        ):
            break
    else:
        raise RunFailedError(
            f"no equilibrium under self-weight within {num.selfweight_max_s} s "
            f"(unbalanced force ratio {unbalanced:.3g} > "
            f"{num.equilibrium_tolerance} or blocks still moving)"
        )
    settle_selfweight(runner)
    unbalanced = runner.unbalanced()
    runner.driver.zero_here()
    runner.recorder.series(force=True)
    runner.recorder.joints(Stage.SELFWEIGHT)
    info = runner.recorder.selfweight_record(runner.weight, unbalanced, O.iter - start, fill)
    runner.log(
        f"[{runner.case.name}] self-weight equilibrium after {info['steps']} steps: "
        f"unbalanced {unbalanced:.2e}, reactions {info['vertical_reaction_sum_N']:.3f} N "
        f"for a weight of {runner.weight:.3f} N"
        + (f" and {fill:.3f} N of backfill" if fill else "")
        + f", thrust {info['thrust_N']:.3f} N"
    )
    return info
