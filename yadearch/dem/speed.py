"""The set 2 scene timed for the speed benchmark (`studies.benchmark`): the runner against YADE's bare
engine loop on the same steps, a bare scene's steps/s, and a step split into its parts.

`python -m yadearch.dem.speed scene-rate STEPS MODEL` and `... breakdown STEPS` print their figure
as the last line (the benchmark runs them in children: a thread count is fixed when YADE is imported,
and the breakdown resets YADE's scene).
"""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable

import __main__
from yadearch.case.config import preset
from yadearch.dem.yade_env import import_yade
from yadearch.solve.stages import Stage

WARM_STEPS = 200  # steps before a bare scene's steps/s is timed
SETTLE_STEPS = 500  # steps before a step's parts are timed: under gravity, the joints in contact
NOOP_NAME = "_benchmark_noop"  # the no-op Python engine's function, in __main__


def loading_timings(settle_mm: float, contact_model: str) -> dict:
    """Set 2's first `settle_mm` of loading with `contact_model`, timed twice on the same steps from the
    same self-weight state: the full runner (driver callback, checks, records, state snapshots) and a
    bare `O.run` of the same scene (its engines, the contact model's Python engine included, the support
    moved by a constant velocity instead of the driver): steps, runner_s, bare_scene_s and the contact
    model's Python engine's own time in the bare run (YADE's engine timing)."""
    from yadearch.dem.driver import DRIVER_LABEL
    from yadearch.dem.runner import Runner
    from yadearch.dem.scene import CALLBACK_NAME
    from yadearch.model import units
    from yadearch.model.movement import SupportMotion

    import_yade()
    from yade import O

    # no acceleration ramp: the bare run moves the support at constant speed, so the runner must too
    case = preset("set2").with_overrides(
        {
            "progress_every_s": 1e9,
            "max_support_displacement_mm": settle_mm,
            "support_acceleration_mm_per_s2": 0.0,
            "contact_model": contact_model,
        }
    )
    runner = Runner(case, log=lambda text: None)
    runner.selfweight()
    settled = runner.snapshot()
    runner.stage = Stage.INCREMENT
    first, start = runner.total_steps, time.time()
    runner.move_to(units.mm(settle_mm))
    runner_s, steps = time.time() - start, runner.total_steps - first

    runner.close()  # the bare run below is YADE's own O.run, without the runner's stepping gate
    runner.restore(settled)
    O.engines = [e for e in O.engines if getattr(e, "label", "") != DRIVER_LABEL]
    settlement = runner.driver.movement.reference
    assert isinstance(settlement, SupportMotion)  # the settlement: a translation, in a unit direction
    dx, dy = settlement.translation
    O.bodies[runner.scene.right_support].state.vel = (runner.driver.speed * dx, runner.driver.speed * dy, 0.0)
    contact_engine = next(e for e in O.engines if getattr(e, "command", "") == f"{CALLBACK_NAME}.step()")
    O.timingEnabled, contact_engine.execTime = True, 0
    begin = time.time()
    O.run(steps, True)
    return {
        "steps": steps,
        "runner_s": runner_s,
        "bare_scene_s": time.time() - begin,
        "bare_contact_python_engine_s": contact_engine.execTime * 1e-9,
    }


def scene_rate(steps: int, contact_model: str) -> float:
    """Steps per second of a bare `O.run` of the set 2 scene with `contact_model` under self-weight
    (this process's OpenMP threads)."""
    from yadearch.dem.scene import build_scene

    import_yade()
    from yade import O

    build_scene(preset("set2").with_overrides({"contact_model": contact_model}))
    O.run(WARM_STEPS, True)
    start = time.time()
    O.run(steps, True)
    return steps / (time.time() - start)


def step_breakdown(steps: int) -> dict:
    """Where a step of the set 2 scene goes (microseconds): the whole step, YADE's bare integrator
    (ForceResetter + NewtonIntegrator on the same bodies), and the joint engine's parts timed on
    their own (state reads, joint law, force application, the call of a Python engine: a no-op
    PyRunner beside the bare integrator); the rest is the driver and the engine's bookkeeping.
    Resets YADE's scene."""
    from yadearch.dem.joint_elements import JointElementContacts
    from yadearch.dem.scene import build_scene

    import_yade()
    from yade import O
    from yade.wrapper import ForceResetter, NewtonIntegrator, PyRunner

    contacts = build_scene(preset("set2")).contacts
    assert isinstance(contacts, JointElementContacts)  # the default contact model: joint elements
    O.run(SETTLE_STEPS, True)

    def per_step_us(action: Callable[[], object]) -> float:
        start = time.perf_counter()
        for _ in range(steps):
            action()
        return (time.perf_counter() - start) / steps * 1e6

    step_us = _run_us(O, steps)
    rows = contacts.read_poses()
    forces = contacts.forces(rows)
    reads_us = per_step_us(contacts.read_poses)
    law_us = per_step_us(lambda: contacts.forces(rows))
    apply_us = per_step_us(lambda: contacts.apply(forces))

    def bare_step_us(*extra) -> float:
        O.engines = [ForceResetter(), *extra, NewtonIntegrator(damping=0.2, gravity=(0.0, -9.81, 0.0))]
        return _run_us(O, steps)

    bare_us = bare_step_us()
    setattr(__main__, NOOP_NAME, lambda: None)
    call_us = bare_step_us(PyRunner(command=f"{NOOP_NAME}()", iterPeriod=1)) - bare_us
    rest = step_us - bare_us - reads_us - law_us - apply_us - call_us
    return {
        "steps": steps,
        "step_us": step_us,
        "integrator_ratio": step_us / bare_us,
        "step_breakdown_us": {
            "yade_integrator": bare_us,
            "state_reads": reads_us,
            "joint_law": law_us,
            "force_application": apply_us,
            "python_engine_call": call_us,
            "driver_and_rest": rest,
        },
    }


def _run_us(omega, steps: int) -> float:
    """Microseconds a step of `omega.run(steps)` takes."""
    start = time.perf_counter()
    omega.run(steps, True)
    return (time.perf_counter() - start) / steps * 1e6


def main(argv: list[str]) -> int:
    """The children of the benchmark: `scene-rate STEPS MODEL` or `breakdown STEPS`."""
    if len(argv) == 3 and argv[0] == "scene-rate":
        print(scene_rate(int(argv[1]), argv[2]))
    elif len(argv) == 2 and argv[0] == "breakdown":
        print(json.dumps(step_breakdown(int(argv[1]))))
    else:
        print("usage: python -m yadearch.dem.speed scene-rate STEPS MODEL | breakdown STEPS", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
