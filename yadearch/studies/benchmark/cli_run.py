"""What a single `yadearch run --preset set2 --engine static` costs a user from the command line, with
its figures and without, against the bare interpreter's start measured in the same invocation (issue
45's targets: under 1 s without figures, 3 s with), the path solved once (--no-check: the increments
check solves it twice, docs/numerics.md)."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path
from typing import Any

from yadearch.studies.benchmark.verdicts import Verdict

TARGET_NO_FIGURES_S = 1.0
TARGET_FIGURES_S = 3.0
VARIANTS = {"bare_interpreter": None, "no_figures": ["--no-figures"], "figures": []}  # None: `python -c pass`


def _wall(command: list[str]) -> float:
    """Wall seconds of one command, its output discarded (a failure raises)."""
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True)
    return time.perf_counter() - start


def static_run_command(out: Path, *extra: str) -> list[str]:
    """`yadearch run --preset set2 --engine static` into `out` (run again), the path solved once
    (--no-check), with `extra` options."""
    cli = str(Path(sys.executable).with_name("yadearch"))
    return [cli, "run", "--preset", "set2", *extra, "--engine", "static", "--no-check", "--out", str(out), "--rerun"]


def cli_run_measurement(repeats: int, runs: Path) -> dict[str, Any]:
    """The best wall time of `repeats` runs of each variant, alternated so that a drift of the machine's
    speed falls on all (one warm-up run of each first: numba's cache and the page cache loaded)."""
    commands = {
        name: [sys.executable, "-c", "pass"] if extra is None else static_run_command(runs / name, *extra)
        for name, extra in VARIANTS.items()
    }
    for command in commands.values():
        _wall(command)
    walls: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(repeats):
        for name, command in commands.items():
            walls[name].append(_wall(command))
    figures: dict[str, Any] = {f"cli_{name}_wall_s": min(times) for name, times in walls.items()}
    figures["cli_repeats"] = repeats
    bare = figures["cli_bare_interpreter_wall_s"]
    print(
        f"yadearch run --preset set2 --engine static --no-check, best of {repeats}: without figures "
        f"{figures['cli_no_figures_wall_s']:.2f} s, with figures {figures['cli_figures_wall_s']:.2f} s; "
        f"the bare interpreter {bare:.3f} s (x{figures['cli_no_figures_wall_s'] / bare:.0f}, "
        f"x{figures['cli_figures_wall_s'] / bare:.0f})"
    )
    return figures


def cli_run_verdicts(figures: dict[str, Any]) -> list[Verdict]:
    """The two targets of a single static run from the command line, each as a ratio to its target."""
    return [
        Verdict(
            f"a static run from the command line {what} <= {target:g} s",
            figures[key] <= target,
            f"{figures[key]:.2f} s (x{figures[key] / target:.2f} the target; best of {figures['cli_repeats']})",
        )
        for what, key, target in (
            ("without figures", "cli_no_figures_wall_s", TARGET_NO_FIGURES_S),
            ("with its figures", "cli_figures_wall_s", TARGET_FIGURES_S),
        )
    ]
