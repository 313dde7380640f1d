"""The static engine's answers on a fixed set of 524 cases, to compare two revisions of the engine: 200
Monte Carlo samples of the imperfection study's final case (face bumps s.d. 0.18 mm), the 100-point
kn sweep 0.05-10 000 N/mm3 and the first 224 runs of the sensitivity study's Saltelli sample (docs/speed.md).

    .venv/bin/python scripts/engine_answers.py run answers.json [--jobs 2] [--set numerics.KEY=VALUE ...]
    PYTHONPATH=/path/to/other/checkout .venv/bin/python scripts/engine_answers.py run other.json
    .venv/bin/python scripts/engine_answers.py compare other.json answers.json [--list]

`run` writes each case's du, du_first, outcome, hinges, collapse kind, path length and CPU time (with
`--set`, every case with that numerical setting: what a default would move); `compare` prints how many
answers differ by group and the ratios of CPU time and path length.
"""

from __future__ import annotations

import argparse
import collections
import functools
import json
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from yadearch.atomic import write_text_atomically
from yadearch.case.config import ArchCase, preset
from yadearch.errors import CaseError, YadearchError
from yadearch.static.simulate import simulate_static
from yadearch.studies.benchmark.static_engine import MONTECARLO_BUMP_SD_MM, MONTECARLO_SAMPLES, SWEEP_KN
from yadearch.studies.campaigns.grid import parse_scalar
from yadearch.studies.sensitivity.indices import PAPER_FACTORS, sobol_rows

SALTELLI_BASE_POINTS, SALTELLI_RUNS = 16, 224
ANSWERS = ("du_mm", "du_first_mm", "outcome", "hinges", "kind", "error")
GROUPS = {"mc": "Monte Carlo", "kn": "kn sweep", "b": "Saltelli"}  # by the cases' name prefixes
NUMERICS: dict[str, object] = {}  # `run --set`: numerical settings of every case (each worker's copy)


def use_numerics(settings: dict[str, object]) -> None:
    """Give every case of this process `settings` (a pool's initializer, before `cases` is first built)."""
    NUMERICS.update(settings)


@functools.cache
def cases() -> dict[str, ArchCase]:
    """The compared cases by name, summaries only (built once a process)."""
    static = preset("set2").with_overrides({"numerics.engine": "static", "numerics.run_files": "summary", **NUMERICS})
    found = {
        f"mc{seed}": static.with_overrides(
            {"imperfections.face_bump_sd_mm": MONTECARLO_BUMP_SD_MM, "imperfections.seed": seed}
        )
        for seed in range(MONTECARLO_SAMPLES)
    }
    found.update({f"kn{kn:.6g}": static.replace(kn_N_per_mm3=float(kn)) for kn in SWEEP_KN})
    for row in sobol_rows(PAPER_FACTORS, SALTELLI_BASE_POINTS)[:SALTELLI_RUNS]:
        found[row["run"]] = static.with_overrides({k: v for k, v in row.items() if k != "run"})
    return found


def answer(name: str) -> tuple[str, dict]:
    """One case solved: its answers, path length and CPU seconds (an arch that cannot stand: its error)."""
    start = time.process_time()
    try:
        summary = simulate_static(cases()[name], None, log=lambda _: None)
    except YadearchError as error:
        return name, {"error": str(error).split(" (")[0]}
    return name, {
        "du_mm": summary.du_mm,
        "du_first_mm": summary.du_first_mm,
        "outcome": summary.path_outcome,
        "hinges": summary.hinge_labels,
        "kind": summary.collapse_kind,
        "iterations": summary.iterations,
        "evaluations": summary.joint_evaluations,
        "cpu_s": time.process_time() - start,
    }


def compare(old: dict, new: dict, listed: bool) -> None:
    """Differences of the answers by group, and the new revision's CPU and path length against the old's."""
    differ: collections.Counter = collections.Counter()
    totals: dict[str, np.ndarray] = collections.defaultdict(lambda: np.zeros(4))
    for name, before in old.items():
        after, group = new[name], next(g for prefix, g in GROUPS.items() if name.startswith(prefix))
        totals[group] += [
            before.get("cpu_s", 0),
            after.get("cpu_s", 0),
            before.get("evaluations", 0),
            after.get("evaluations", 0),
        ]
        for key in ANSWERS:
            if before.get(key) != after.get(key):
                differ[(group, key)] += 1
                if listed:
                    print(f"{name} {key}: {before.get(key)} -> {after.get(key)}")
    print("answers that differ:", dict(differ) or "none")
    for group, (cpu_old, cpu_new, ev_old, ev_new) in totals.items():
        print(f"{group}: CPU x{cpu_new / cpu_old:.2f}, joint evaluations x{ev_new / max(ev_old, 1):.2f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("run")
    run.add_argument("out", type=Path)
    run.add_argument("--jobs", type=int, default=2)
    run.add_argument("--set", action="append", default=[], metavar="numerics.KEY=VALUE", help="a numerical setting")
    both = commands.add_parser("compare")
    both.add_argument("old", type=Path)
    both.add_argument("new", type=Path)
    both.add_argument("--list", action="store_true", help="name every answer that differs")
    args = parser.parse_args()
    if args.command == "compare":
        compare(json.loads(args.old.read_text()), json.loads(args.new.read_text()), args.list)
        return 0
    settings = {}
    for item in args.set:
        key, _, value = item.partition("=")
        if not key.startswith("numerics.") or not value:
            parser.error(f"--set {item!r}: give numerics.KEY=VALUE")
        settings[key] = parse_scalar(value)
    try:
        preset("set2").with_overrides(settings)
    except CaseError as error:
        parser.error(f"--set: {error}")
    use_numerics(settings)  # here, and in workers that do not fork from here
    with ProcessPoolExecutor(args.jobs, initializer=use_numerics, initargs=(settings,)) as pool:
        found = dict(pool.map(answer, list(cases()), chunksize=8))
    write_text_atomically(args.out, json.dumps(found, indent=0) + "\n")
    print(f"{len(found)} cases -> {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
