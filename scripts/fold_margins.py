"""Where a DEM run moved its hinges, against the fold margin of its joints: for each change of the
run's three-hinge mechanism between equilibria, the rigid thrust's distance from the edge of the
joint that took the hinge, on the rigid linkage of the mechanism before, at the two displacements
around the change, beside that joint's fold margin at the run's kn (docs/validation.md).

    .venv/bin/python scripts/fold_margins.py reports/movements/validation-fine/paper_inclined45_kn3000_inc0.5

A hinge that moves as the compliant-hinge theory says moves where the rigid margin crosses the fold
margin (docs/theory.md, "Compliant hinges").
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import pandas as pd

from yadearch.case.config import load_case
from yadearch.model import units
from yadearch.model.hinges import hinge_rotation
from yadearch.results.rundir import CASE_FILE
from yadearch.solve.compliant import joint_margins
from yadearch.solve.limit_lp import solve_statics
from yadearch.solve.pose import parse_pivot
from yadearch.solve.rigid import RigidArch, at_rest, close_linkage, rigid_arch


def mechanisms(folder: Path, hinge_mrad: float, joint_mm: float) -> list[tuple[float, tuple[str, ...]]]:
    """Each equilibrium's support displacement (mm) and hinges: every joint turned beyond
    `hinge_mrad`, about the corner `model.hinges.hinge_rotation` says for joints `joint_mm` long (not
    grouped into spreads)."""
    joints = pd.read_csv(folder / "joints.csv")
    states = []
    for delta, state in joints[joints["stage"] == "equilibrium"].groupby("delta_mm"):
        turned = state[np.abs(state["rotation_rad"]) > units.mrad(hinge_mrad)]
        pivots = hinge_rotation(turned["opening_intrados_mm"], turned["opening_extrados_mm"], joint_mm)
        states.append((float(delta), tuple(f"{k}{'I' if r > 0 else 'E'}" for k, r in zip(turned["interface"], pivots))))
    return states


def margin_mm(arch: RigidArch, kn: float, hinges: tuple[str, ...], at_mm: float, joint: str) -> tuple[float, float]:
    """The rigid thrust's distance from the edge of `joint` (mm) on the linkage `hinges` at `at_mm`,
    and that joint's fold margin (mm); NaN where the linkage has no admissible equilibrium there."""
    pivots = tuple(parse_pivot(h) for h in hinges)
    placement = close_linkage(arch, at_rest(arch), pivots, units.mm(at_mm))
    if placement is None:
        return float("nan"), float("nan")
    statics = solve_statics(arch, placement)
    if statics is None or not statics.feasible:
        return float("nan"), float("nan")
    target = parse_pivot(joint)
    for m in joint_margins(arch, placement, statics.normal, statics.contacts, pivots, kn):
        if m.pivot == target:
            return units.to_mm(m.margin), units.to_mm(m.critical)
    return float("nan"), float("nan")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", type=Path, help="a finished run folder with joints.csv")
    args = parser.parse_args()
    if not (args.run / "joints.csv").is_file() or not (args.run / CASE_FILE).is_file():
        parser.error(f"run {args.run}: no joints.csv and case.toml there (a finished `yadearch run` folder)")
    case = load_case(args.run / CASE_FILE)
    arch, kn = rigid_arch(case), units.stiffness_per_volume(case.interface.kn_N_per_mm3)
    print(
        "| from (mm) | to (mm) | mechanism before | after | joint taking a hinge "
        "| rigid margin before / after (mm) | fold margin (mm) |"
    )
    print("|---|---|---|---|---|---|---|")
    states = mechanisms(args.run, case.numerics.hinge_rotation_mrad, case.geometry.thickness_mm)
    last = next(((d, h) for d, h in states if len(h) == 3), None)
    for delta, hinges in states:
        if last is None or len(hinges) < 3 or set(hinges) == set(last[1]):
            if len(hinges) == 3:
                last = (delta, hinges)
            continue
        for joint in sorted(set(hinges) - set(last[1]), key=lambda h: int(h[:-1])):
            before, critical = margin_mm(arch, kn, last[1], last[0], joint)
            after, _ = margin_mm(arch, kn, last[1], delta, joint)
            print(
                f"| {last[0]:g} | {delta:g} | {' '.join(last[1])} | {' '.join(hinges)} | {joint} "
                f"| {before:.3f} / {after:.3f} | {critical:.3f} |"
            )
        if len(hinges) == 3:
            last = (delta, hinges)
    return 0


if __name__ == "__main__":
    sys.exit(main())
