"""Speed benchmark: full runs of set 1, set 2 (and optionally the stiffest sweep case), their du
against a slow reference, and the driver's overhead over YADE's bare engine loop.

    .venv/bin/python scripts/benchmark.py [--out reports/benchmark.json] [--stiff] [--overhead-steps N]

Each run goes through the same process launcher as `yadearch run`. The slow reference is a run of
the same case at half the default settlement rate, made in this invocation unless --reference gives
a stored run folder (its provenance is printed). Prints a verdict line per target of issue 5.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

TARGET_SET2_WALL_S = 60.0
TARGET_SWEEP_WALL_S = 15 * 60.0
TARGET_OVERHEAD = 1.05
TARGET_DU_REL = 0.01


def timed_run(case, folder: Path) -> dict:
    """Run a case in its own process; its summary with the measured wall time of the process."""
    from yadearch.process import run_case_process

    start = time.time()
    run_case_process(case, folder, quiet=True)
    summary = json.loads((folder / "summary.json").read_text())
    summary["process_wall_s"] = time.time() - start
    return summary


def driver_overhead(steps: int) -> dict:
    """Seconds for `steps` steps of the set 2 scene: bare O.run (YADE engines only), O.run with the
    per-contact shear and support callbacks, and the full runner loop with its checks and records."""
    from yadearch.case import preset
    from yadearch.runner import Runner

    case = preset("set2").with_overrides({"progress_every_s": 1e9})
    runner = Runner(case, log=lambda line: None)
    from yade import O

    runner.selfweight()  # a settled arch, so that every variant runs the same contacts
    O.saveTmp("bench")
    engines = list(O.engines)
    timings = {}

    def bare(engine_list) -> float:
        O.loadTmp("bench")
        runner.scene.shear.bind(runner.scene.pos0, runner.scene.ori0)
        runner.driver.bind()
        O.engines = engine_list
        start = time.time()
        O.run(steps, True)
        return time.time() - start

    python_runners = [e for e in engines if type(e).__name__ == "PyRunner"]
    timings["yade_engines_only_s"] = bare([e for e in engines if e not in python_runners])
    timings["with_callbacks_s"] = bare(engines)
    O.loadTmp("bench")
    runner.scene.shear.bind(runner.scene.pos0, runner.scene.ori0)
    runner.driver.bind()
    runner.stage = "loading"
    start = time.time()
    runner.driver.target = 1.0
    done = 0
    while done < steps:
        runner._advance(50)
        runner._check_finite()
        runner._record_series()
        if done % 500 == 0:
            runner._record_joints()
        runner._voussoir_speeds()
        done += 50
    timings["full_runner_s"] = time.time() - start
    timings["steps"] = steps
    return timings


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="reports/benchmark.json")
    parser.add_argument("--runs", default="runs/benchmark")
    parser.add_argument("--reference", help="stored slow reference run folder of set 2")
    parser.add_argument("--set1-run", help="use this complete set 1 run folder instead of running")
    parser.add_argument("--set2-run", help="use this complete set 2 run folder instead of running")
    parser.add_argument("--stiff", action="store_true", help="also run the stiffest sweep case (kn 100)")
    parser.add_argument("--overhead-steps", type=int, default=2000)
    args = parser.parse_args()

    from yadearch.case import preset

    runs = Path(args.runs)
    results: dict = {}
    stored = {"set1": args.set1_run, "set2": args.set2_run}
    for name in ("set1", "set2"):
        if stored[name]:
            summary = json.loads((Path(stored[name]) / "summary.json").read_text())
            print(f"{name}: stored run {stored[name]} (yadearch {summary.get('git_revision')}, "
                  f"{summary.get('started')})")
        else:
            summary = timed_run(preset(name), runs / name)
        results[name] = summary
        print(f"{name}: steps {summary['steps']}, wall {summary['wall_s']:.0f} s, "
              f"{summary['steps_per_s']:.0f} steps/s, du {summary['du_mm']} mm", flush=True)
    if args.reference:
        reference = json.loads((Path(args.reference) / "summary.json").read_text())
        print(f"reference: {args.reference} (yadearch {reference.get('git_revision')}, "
              f"{reference.get('started')})")
    else:
        slow = preset("set2")
        slow = slow.with_overrides({"settlement_rate_mm_per_s": slow.numerics.settlement_rate_mm_per_s / 2})
        slow.name = "set2_half_rate"
        reference = timed_run(slow, runs / "set2_half_rate")
    du, du_ref = results["set2"]["du_mm"], reference["du_mm"]
    rel = abs(du - du_ref) / du_ref if du is not None and du_ref else None
    stiff = None
    if args.stiff:
        case = preset("set2").with_overrides({"kn_N_per_mm3": 100.0})
        case.name = "kn100"
        stiff = timed_run(case, runs / "kn100")
        print(f"kn100: steps {stiff['steps']}, wall {stiff['wall_s']:.0f} s, "
              f"{stiff['steps_per_s']:.0f} steps/s, du {stiff['du_mm']} mm", flush=True)
    overhead = driver_overhead(args.overhead_steps)
    ratio = overhead["full_runner_s"] / overhead["with_callbacks_s"]
    ratio_vs_engines = overhead["full_runner_s"] / overhead["yade_engines_only_s"]
    report = {
        "set1_wall_s": results["set1"]["wall_s"], "set1_du_mm": results["set1"]["du_mm"],
        "set1_steps": results["set1"]["steps"], "set1_steps_per_s": results["set1"]["steps_per_s"],
        "set2_wall_s": results["set2"]["wall_s"], "set2_du_mm": du, "set2_steps": results["set2"]["steps"],
        "set2_du_reference_mm": du_ref, "set2_du_rel_diff": rel,
        "set2_steps_per_s": results["set2"]["steps_per_s"],
        "stiff_kn100": None if stiff is None else {k: stiff[k] for k in ("wall_s", "du_mm", "steps", "steps_per_s")},
        "driver_overhead_ratio": ratio, "driver_overhead_ratio_vs_yade_engines_only": ratio_vs_engines,
        "overhead_timings": overhead, "sweep_wall_s": None,
    }
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text(json.dumps(report, indent=2) + "\n")
    verdicts = [
        ("set 2 wall <= 60 s", results["set2"]["wall_s"] <= TARGET_SET2_WALL_S,
         f"{results['set2']['wall_s']:.0f} s ({results['set2']['wall_s'] / TARGET_SET2_WALL_S:.1f}x the target)"),
        ("set 2 du within 1 % of the slow reference", rel is not None and rel <= TARGET_DU_REL,
         f"{du} vs {du_ref} mm ({rel:.2%})" if rel is not None else "no du"),
        ("driver overhead <= 5 %", ratio <= TARGET_OVERHEAD,
         f"full runner / engines with callbacks = {ratio:.3f}; / YADE engines only = {ratio_vs_engines:.3f}"),
        ("13-point sweep <= 15 min", False, "not run by the benchmark (sweep_wall_s null)"),
    ]
    for label, ok, detail in verdicts:
        print(f"{'PASS' if ok else 'FAIL'}  {label}: {detail}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
