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
import os
import sys
from pathlib import Path

# YADE runs in this process: numpy's OpenBLAS must start with one thread, or its idle worker spins on
# the second core (two such runs side by side: 300-500 steps/s each instead of 3 600-5 400)
os.environ.setdefault("OMP_NUM_THREADS", "1")

from yadearch.cli.options import resolve_case  # noqa: E402
from yadearch.dem.rigid_state import check_rigid_state  # noqa: E402
from yadearch.errors import YadearchError  # noqa: E402
from yadearch.solve.stages import Verdict  # noqa: E402


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
    try:
        verdict = check_rigid_state(
            case,
            args.at_mm,
            mirrored=args.branch == "mirrored",
            compliant=args.compliant,
            hinges=tuple(args.hinges.split(",")) if args.hinges else None,
            load_on=args.load_on,
            out=args.out,
            command=vars(args) | {"out": str(args.out)},
            log=lambda text: print(text, flush=True),
        )
    except YadearchError as exc:
        raise SystemExit(f"error: {exc}") from None
    return 1 if verdict == Verdict.RUNAWAY else 0


if __name__ == "__main__":
    sys.exit(main())
