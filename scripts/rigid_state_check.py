"""Is the rigid analysis's state a DEM equilibrium, and how far does the DEM carry the support from
it? Load a case's arch by its self-weight, put the voussoirs and the supports where the rigid-block
limit analysis has them at a support displacement (either branch of the keystone's tie), release
the voussoirs from rest and report how far they move and the hinges they end on; with `--load-on`,
go on loading by the run's increments from that state to collapse (docs/validation.md).

    .venv/bin/python scripts/rigid_state_check.py --preset set2 --kn 3000 --set support_direction_deg=-45 \\
        --at-mm 9.75 [--branch mirrored] [--compliant | --hinges 8I,28E,46I] [--load-on --out DIR]

A state that stays put (blocks moving far less than a millimetre) is an equilibrium of the DEM's
joints too; exit code 1 if a block ran away by the run's `runaway_mm`. `--load-on` writes
DIR, a run folder of the path from the placed state (summary.json with du, its bracket, the
mechanisms and the relaxations; the tables; case.toml) with command.json saying how the state was
placed, which scripts/limit_check.py reads, and prints the progress.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

# YADE runs in this process: numpy's OpenBLAS must start with one thread, or its idle worker spins on
# the second core (two such runs side by side: 300-500 steps/s each instead of 3 600-5 400)
os.environ.setdefault("OMP_NUM_THREADS", "1")

from yadearch.atomic import write_text_atomically  # noqa: E402
from yadearch.cli.options import resolve_case  # noqa: E402
from yadearch.engine.loading import EquilibriumPath  # noqa: E402
from yadearch.engine.runner import Runner  # noqa: E402
from yadearch.engine.scene_state import place_voussoirs  # noqa: E402
from yadearch.model import units  # noqa: E402
from yadearch.results.rundir import hinge_list, write_run  # noqa: E402
from yadearch.results.summary import HingeRef, RunSummary, collapse_fields  # noqa: E402
from yadearch.solve.pose import linkage_pose, rigid_pose  # noqa: E402
from yadearch.solve.stages import Stage, Verdict  # noqa: E402

COMMAND_FILE = "command.json"  # beside the run folder's files: how the state was placed
PLACEMENT_TOLERANCE_MM = 1e-6  # the placed support must read the displacement asked for


def hinge_text(runner: Runner) -> str:
    """The hinges of the scene now, with their rotations."""
    _, hinges = runner.recorder.joint_snapshot()
    return " ".join(f"{h.interface}{h.side} ({abs(h.rotation) * 1e3:.1f} mrad)" for h in hinges)


def load_on(runner: Runner, start_mm: float, out: Path | None, arguments: dict) -> None:
    """Follow the equilibrium path from the placed state at `start_mm` to collapse and report it."""
    loading = EquilibriumPath(runner)
    path = loading.follow(start=units.mm(start_mm))
    hinges = loading.collapse_state(path.upper) if path.collapsed else []
    summary = RunSummary(
        name=runner.case.name,
        kn_N_per_mm3=runner.case.interface.kn_N_per_mm3,
        **collapse_fields(path, runner.movement),
        hinges_last_equilibrium=loading.last_equilibrium_hinges,
        relaxations=loading.relaxations,
        hinges_at_collapse=tuple(HingeRef.of(h) for h in hinges),
        hinges_detail=[h.to_json() for h in hinges],
        steps=runner.total_steps,
        wall_s=time.time() - runner.wall0,
    )
    if path.collapsed:
        print(
            f"du = {summary.du_mm:.2f} mm ({path.upper_verdict} at {units.to_mm(path.upper):.3f}); "
            f"last equilibrium on {hinge_list(loading.last_equilibrium_hinges)}",
            flush=True,
        )
    if out is not None:  # a run folder from the placed state on, with the command that placed it
        records = runner.records
        write_run(out, runner.case.to_toml(), records.series, records.joints, records.snapshots, summary)
        write_text_atomically(out / COMMAND_FILE, json.dumps({**arguments, "start_mm": start_mm}, indent=1) + "\n")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="set2", choices=["set1", "set2"])
    parser.add_argument("--kn", type=float, default=None, help="interface kn (N/mm3)")
    parser.add_argument("--set", dest="settings", action="append", default=[], help="KEY=VALUE, as yadearch run")
    parser.add_argument("--at-mm", type=float, required=True, help="support displacement along the path (mm)")
    parser.add_argument(
        "--branch",
        choices=["direct", "mirrored"],
        default="direct",
        help="the keystone's tie broken toward its left joint (direct) or its right one",
    )
    parser.add_argument(
        "--hinges",
        default=None,
        help="place on this three-hinge linkage instead of the rigid march's state, e.g. 8I,28E,46I",
    )
    parser.add_argument(
        "--compliant", action="store_true", help="place where the compliant-hinge march at the case's kn has the arch"
    )
    parser.add_argument("--load-on", action="store_true", help="go on loading from the state to collapse")
    parser.add_argument(
        "--out", type=Path, default=None, help="run folder of the path from the placed state (with --load-on)"
    )
    args = parser.parse_args()
    case = resolve_case(args.preset, None, args.kn, tuple(args.settings))
    if args.hinges:
        centroids, turns = linkage_pose(case, args.at_mm, tuple(args.hinges.split(",")))
    else:
        centroids, turns = rigid_pose(case, args.at_mm, args.branch == "mirrored", args.compliant)
    runner = Runner(case, log=(lambda text: print(text, flush=True)) if args.load_on else (lambda _: None))
    try:
        runner.selfweight()
        place_voussoirs(runner.scene, centroids, turns, with_supports=True)
        placed_mm = units.to_mm(runner.delta())
        if abs(placed_mm - args.at_mm) > PLACEMENT_TOLERANCE_MM:
            raise SystemExit(f"the placed support reads {placed_mm:.6f} mm, not --at-mm {args.at_mm:g}")
        where = (
            f"linkage {args.hinges}"
            if args.hinges
            else f"{args.branch} branch{', compliant hinges' if args.compliant else ''}"
        )
        print(f"placed at {args.at_mm:g} mm ({where}): {hinge_text(runner)}", flush=True)
        runner.stage = Stage.RELAX
        verdict = runner.hold(max_s=case.numerics.hold_max_s)
        print(
            f"released: {verdict}, largest block motion {units.to_mm(runner.hold_move):.3f} mm; "
            f"now on {hinge_text(runner)}",
            flush=True,
        )
        if args.load_on and verdict == Verdict.STABLE:
            load_on(runner, args.at_mm, args.out, vars(args) | {"out": str(args.out)})
    finally:
        runner.close()
    return 1 if verdict == Verdict.RUNAWAY else 0


if __name__ == "__main__":
    sys.exit(main())
