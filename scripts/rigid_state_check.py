"""Is the rigid analysis's state a DEM equilibrium? Load a case's arch by its self-weight, move the
support to a displacement, put the voussoirs where the rigid-block limit analysis has them there
(either branch of the keystone's tie), release them from rest and report how far they move and the
hinges they end on (docs/validation.md).

    .venv/bin/python scripts/rigid_state_check.py --preset set2 --kn 3000 --set settlement_direction_deg=-45 \\
        --at-mm 9.75 [--branch mirrored]

A state that stays put (blocks moving far less than a millimetre) is an equilibrium of the DEM's
joints too; exit code 1 if a block ran away by the run's `runaway_mm`.
"""

from __future__ import annotations

import argparse
import sys

from yadearch.cli.options import resolve_case
from yadearch.engine.runner import Runner
from yadearch.engine.scene_state import place_voussoirs
from yadearch.model import units
from yadearch.solve.path import RUNAWAY
from yadearch.solve.pose import rigid_pose


def hinge_text(runner: Runner) -> str:
    """The hinges of the scene now, with their rotations."""
    _, hinges = runner.recorder.joint_snapshot()
    return " ".join(f"{h.interface}{h.side} ({abs(h.rotation) * 1e3:.1f} mrad)" for h in hinges)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="set2", choices=["set1", "set2"])
    parser.add_argument("--kn", type=float, default=None, help="interface kn (N/mm3)")
    parser.add_argument("--set", dest="settings", action="append", default=[], help="KEY=VALUE, as yadearch run")
    parser.add_argument("--at-mm", type=float, required=True, help="support displacement along the path (mm)")
    parser.add_argument("--branch", choices=["direct", "mirrored"], default="direct",
                        help="the keystone's tie broken toward its left joint (direct) or its right one")
    args = parser.parse_args()
    case = resolve_case(args.preset, None, args.kn, tuple(args.settings))
    centroids, turns = rigid_pose(case, args.at_mm, args.branch == "mirrored")
    runner = Runner(case, log=lambda _: None)
    try:
        runner.selfweight()
        runner.move_to(units.mm(args.at_mm))
        place_voussoirs(runner.scene, centroids, turns)
        print(f"placed at {args.at_mm:g} mm ({args.branch} branch): {hinge_text(runner)}")
        verdict = runner.hold(max_s=case.numerics.hold_max_s)
        print(f"released: {verdict}, largest block motion {units.to_mm(runner.hold_move):.3f} mm; "
              f"now on {hinge_text(runner)}")
    finally:
        runner.close()
    return 1 if verdict == RUNAWAY else 0


if __name__ == "__main__":
    sys.exit(main())
