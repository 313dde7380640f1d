"""Numerics must not decide the answer: run a case at the default settlement rate, at half of it,
with another damping and with two thirds of the time step, and print du, the hinges and the
relative differences.

    .venv/bin/python scripts/convergence.py [--preset set2] [--kn 31.62] [--jobs 2] [--out runs/convergence]
        [--dem-set numerics.KEY=VALUE ...]

Exit code 1 if du moves by more than 1 % or a hinge moves (a hinge whose peak stays within its
spread over adjacent joints has not moved). A complete run folder of the same case
under --out is reused (copy `reports/set2` to `runs/convergence/set2_default` to reuse the
reproduction run). --dem-set gives every run (the default and each variant, all the DEM's) a numerical
setting; each variant is varied from the settings' values.
"""

from __future__ import annotations

import argparse
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from yadearch.case.config import preset
from yadearch.launch.process import run_case_process
from yadearch.results.reuse import holds_case
from yadearch.results.rundir import read_summary
from yadearch.results.summary import RunSummary
from yadearch.studies.dem_settings import add_dem_set_option, dem_settings_of, with_dem_settings

TOLERANCE = 0.01


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="set2", choices=["set1", "set2"])
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (one core each)")
    parser.add_argument("--out", default="runs/convergence")
    parser.add_argument(
        "--kn", type=float, default=None, help="interface kn (N/mm3) instead of the preset's, e.g. a stiff sweep point"
    )
    parser.add_argument(
        "--damping", type=float, default=None, help="the other damping (default: the default damping + 0.1)"
    )
    add_dem_set_option(parser)
    args = parser.parse_args()
    dem_settings = dem_settings_of(parser, args)

    base = with_dem_settings(preset(args.preset), dem_settings)
    prefix = args.preset
    if args.kn is not None:
        base = base.with_overrides({"kn_N_per_mm3": args.kn})
        prefix = f"kn{args.kn:g}"
    rate, damping = base.numerics.support_rate_mm_per_s, base.numerics.damping
    other_damping = args.damping if args.damping is not None else round(damping + 0.1, 3)
    variants = {
        "default": {},
        "half_rate": {"numerics.support_rate_mm_per_s": rate / 2},
        "other_damping": {"numerics.damping": other_damping},
        "small_timestep": {"numerics.timestep_safety": round(base.numerics.timestep_safety * 2 / 3, 3)},
    }
    cases = {}
    for label, overrides in variants.items():
        case = base.with_overrides(overrides)
        case.name = f"{prefix}_{label}"
        cases[label] = case

    def run(label: str) -> RunSummary:
        folder = Path(args.out) / cases[label].name
        if not holds_case(folder, cases[label]):
            run_case_process(cases[label], folder, quiet=True)
        return read_summary(folder)

    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        summaries = dict(zip(variants, pool.map(run, variants)))

    reference = summaries["default"]
    has_reference = reference.du_mm is not None
    ok = has_reference
    print(
        f"{'variant':14s} {'speed mm/s':>9s} {'damping':>7s} {'dt safety':>9s} {'du mm':>8s} {'rel diff':>9s} "
        f"{'steps':>8s} {'wall s':>7s}  hinges at collapse"
    )
    for label, summary in summaries.items():
        case = cases[label]
        du, du_reference = summary.du_mm, reference.du_mm
        rel = (du - du_reference) / du_reference if du is not None and du_reference else float("nan")
        same = summary.same_mechanism(reference)
        ok = ok and du is not None and abs(rel) <= TOLERANCE and same
        print(
            f"{label:14s} {case.support_speed_mm_per_s:9.2f} {case.numerics.damping:7.2f} "
            f"{case.numerics.timestep_safety:9.2f} "
            f"{du if du is not None else float('nan'):8.2f} {rel:+9.2%} {summary.steps:8d} "
            f"{summary.wall_s:7.0f}  {summary.hinge_labels}{'' if same else '  (differs)'}"
        )
    print(
        f"verdict: {'PASS' if ok else 'FAIL'} (du within {TOLERANCE:.0%} and same hinges: same sides, "
        f"each peak within the other's spread)"
    )
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
