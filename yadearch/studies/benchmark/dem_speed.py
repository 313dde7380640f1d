"""The DEM's speed on the set 2 scene (`dem.speed`): the driver's overhead over YADE's engine loop on
the same steps of loading, the contact models' steps/s, a step split into its parts, and OpenMP
threads; the scene is timed in this process or, where YADE's state must be fresh, in a child."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from typing import Any

CONTACT_MODELS = ("joint", "cgal")  # the default joint elements, and YADE's CGAL polyhedra contacts
THREAD_COUNTS = (1, 2)
SPEED_MODULE = "yadearch.dem.speed"  # `python -m` entry of the children


def loading_measurement(settle_mm: float, set2_steps: int, contact_model: str) -> dict[str, Any]:
    """Set 2's first `settle_mm` of loading with `contact_model` by the runner and by a bare `O.run`
    (`dem.speed.loading_timings`): their ratio is the driver overhead; also the runner's steps/s here
    (set 2's `set2_steps` at that rate) and the load average, which says whether the core was free."""
    from yadearch.dem.speed import loading_timings

    timed = loading_timings(settle_mm, contact_model)
    steps, runner_s, bare_s = timed["steps"], timed["runner_s"], timed["bare_scene_s"]
    rate = steps / runner_s
    result = {
        "contact_model": contact_model,
        "settle_mm": settle_mm,
        "steps": steps,
        "runner_s": runner_s,
        "bare_scene_s": bare_s,
        "bare_contact_python_engine_s": timed["bare_contact_python_engine_s"],
        "driver_overhead_ratio": runner_s / bare_s,
        "steps_per_s": rate,
        "set2_wall_estimate_s": set2_steps / rate,
        "load_average": os.getloadavg()[0],
    }
    print(
        f"[{contact_model}] loading {settle_mm:g} mm of set 2 ({steps} steps): runner {runner_s:.1f} s, "
        f"bare O.run of the same scene {bare_s:.1f} s (ratio {result['driver_overhead_ratio']:.3f}), of "
        f"which the contact model's Python engine {result['bare_contact_python_engine_s']:.1f} s; {rate:.0f} "
        f"steps/s (load average {result['load_average']:.2f}): set 2's {set2_steps} steps would take "
        f"{result['set2_wall_estimate_s']:.0f} s"
    )
    return result


def _child_output(args: list[str], threads: int | None = None) -> str:
    """The last line a `python -m yadearch.dem.speed ARGS` child prints (with `threads` OpenMP threads)."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads)) if threads is not None else None
    out = subprocess.run(
        [sys.executable, "-m", SPEED_MODULE, *args], check=True, capture_output=True, text=True, env=env
    ).stdout
    return out.strip().splitlines()[-1]


def step_breakdown(steps: int) -> dict[str, Any]:
    """Where a step of the set 2 scene goes, in microseconds (`dem.speed.step_breakdown`), in a child
    process: it resets YADE's scene."""
    result = json.loads(_child_output(["breakdown", str(steps)]))
    parts = ", ".join(f"{k} {v:.1f}" for k, v in result["step_breakdown_us"].items())
    print(
        f"a step of the set 2 scene: {result['step_us']:.1f} us ({parts}); whole / bare integrator "
        f"= {result['integrator_ratio']:.1f}"
    )
    return result


def threads_measurement(steps: int) -> dict[str, dict[str, Any]]:
    """`dem.speed.scene_rate` of each contact model with 1 and with 2 OpenMP threads, each in its own
    process (the thread count is fixed when YADE is imported)."""
    result = {}
    for model in CONTACT_MODELS:
        rates = {n: float(_child_output(["scene-rate", str(steps), model], threads=n)) for n in THREAD_COUNTS}
        print(
            f"[{model}] OpenMP threads: 1 thread {rates[1]:.0f} steps/s, 2 threads {rates[2]:.0f} steps/s "
            f"(x{rates[2] / rates[1]:.2f}) over {steps} steps of the set 2 scene"
        )
        result[model] = {
            "steps": steps,
            "steps_per_s_1_thread": rates[1],
            "steps_per_s_2_threads": rates[2],
            "speedup": rates[2] / rates[1],
        }
    return result
