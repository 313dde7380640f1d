"""The descending branch of a live load's path in YADE (`yadearch loads --engine dem`): from the last
stable state before the limit point the load is driven by its own displacement through a stiff spring
(`model.load_control`), the anchor moved by steps each held to rest, as a displacement-controlled test
follows a specimen's softening. It ends as the static engine's arc length does (`solve.descending`):
fallen to a fraction of the capacity, risen past it, a runaway, a state that does not come to rest, or
MAX_STEPS."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yadearch.dem.live_arch import hold_on
from yadearch.dem.loaded_arch import LoadedArch
from yadearch.dem.loading import HOLD_RETRIES, EquilibriumPath
from yadearch.dem.static_check import StaticCheck
from yadearch.model import units
from yadearch.model.load_control import DisplacementControl
from yadearch.solve.collapse_mode import motion_hinges
from yadearch.solve.descending import MAX_STEPS, DescentEnd, branch_end
from yadearch.solve.stages import Stage, Verdict


@dataclass(frozen=True)
class DemDescent:
    """Why the DEM's branch past the peak ends, and the hinges its last step turns."""

    end: DescentEnd
    hinges: tuple[str, ...]


def dem_descent(
    loading: EquilibriumPath, arch: LoadedArch, capacity: float, control: DisplacementControl
) -> DemDescent:
    """The branch past the limit point from `loading`'s last accepted state until the load falls to
    `control.descend_to` x `capacity`; each state held at rest is recorded (`arch.curve`, the run's tables)."""
    loading.back_to_accepted()
    runner = arch.runner
    origin = runner.positions()
    spring = arch.drive_by_displacement(control.spring_ratio, units.mm(arch.case.support_speed_mm_per_s))
    if spring is None:
        arch.log(f"[{arch.case.name}] past the peak: the last stable state carries no load that has moved its points")
        return DemDescent(DescentEnd.LOST, ())
    step = control.step_thickness_ratio * units.mm(arch.case.geometry.thickness_mm)
    runaway = loading.runaway
    check = runner.static_check
    before = after = check.scene_u() if check is not None else None
    states, end = 0, DescentEnd.STEPS
    while states < MAX_STEPS:
        spring.target = spring.anchor + step
        arch.stage = Stage.INCREMENT
        runner.drive(spring.reached)
        arch.stage = Stage.RELAX
        verdict = _held(arch, runaway - _moved(runner.positions(), origin))
        if verdict == Verdict.RUNAWAY and check is not None:  # the hinges of the step that ran away
            before, after = after, check.scene_u()
        if verdict != Verdict.STABLE:
            end = DescentEnd.RUNAWAY if verdict == Verdict.RUNAWAY else DescentEnd.LOST
            break
        arch.stage = Stage.EQUILIBRIUM
        arch.yield_fill()
        arch.record_equilibrium()
        states += 1
        if check is not None:
            before, after = after, check.scene_u()
        load = arch.driver.multiplier
        arch.log(
            f"[{arch.case.name}] past the peak: {load:.4g} at {arch.curve[-1]['load_displacement_mm']:.3f} mm "
            f"of the load's displacement (step {arch.total_steps})"
        )
        ended = branch_end(load, capacity, control.descend_to, _moved(runner.positions(), origin) >= runaway)
        if ended is not None:
            end = ended
            break
    loading.moved_on()
    hinges = _turning(check, before, after) if check is not None and after is not before else ()
    return DemDescent(end, hinges)


def _held(arch: LoadedArch, runaway: float) -> Verdict:
    """The anchor held still: the blocks brought to rest from rest, the hold going on HOLD_RETRIES times
    where it finds neither rest nor runaway, then settled by the path's settling test (`dem.live_arch.
    hold_on`): the branch's states are read off the curve, so they are held as a bracket's lower end is."""
    if runaway <= 0.0:
        return Verdict.RUNAWAY
    verdict = arch.hold(runaway=runaway)
    for _ in range(HOLD_RETRIES):
        if verdict != Verdict.TIMEOUT:
            break
        verdict = arch.hold(runaway=runaway, from_rest=False)
    return hold_on(arch, runaway) if verdict == Verdict.STABLE else verdict


def _moved(positions: np.ndarray, origin: np.ndarray) -> float:
    """The largest block displacement from `origin` (m)."""
    return float(np.linalg.norm(positions - origin, axis=1).max())


def _turning(check: StaticCheck, before: np.ndarray | None, after: np.ndarray | None) -> tuple[str, ...]:
    """The joints the last step turns (`solve.collapse_mode.motion_hinges`, as the static branch names them)."""
    if before is None or after is None:
        return ()
    arch = check.loading.arch
    hinges, _ = motion_hinges(arch, before, (after - before)[arch.free_dofs])
    return tuple(h.label for h in hinges)
