"""Launch a live load's DEM path in its own Python process (`yadearch.dem.load_simulate`) and read its
answer back: OUT/NAME_load_path.json, .csv and .log and the folder of its states OUT/NAME_load_path/,
moved into OUT only once complete."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
from dataclasses import asdict
from pathlib import Path

from yadearch.case.config import ArchCase
from yadearch.case.plan import check_dem_load
from yadearch.children import child_command, child_environment
from yadearch.dem.load_simulate import NOT_TRACED
from yadearch.errors import RunFailedError
from yadearch.launch.process import check_yade_installed, exit_reason, run_child, swap_into_place
from yadearch.model.load_control import DisplacementControl
from yadearch.results.load_path import load_path_file, read_load_path
from yadearch.results.rundir import CASE_FILE
from yadearch.solve.load_path_result import LoadPath

LOAD_PATH_FILES = (".csv", ".log", ".json")  # the JSON last: it marks the result complete


def run_load_process(
    case: ArchCase,
    out: Path,
    after_mm: float = 0.0,
    timeout_s: float | None = None,
    quiet: bool = True,
    descent: DisplacementControl | None = None,
) -> LoadPath:
    """The DEM's path of `case`'s live load after its support movement to `after_mm`, past its limit point
    under `descent`'s displacement control (None: it stops there), computed in a child process and written
    to `out`; RunFailedError with the reason if it fails (its log is kept)."""
    check_dem_load(case)
    check_yade_installed()
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{case.name}_load_", dir=out))
    try:
        case_file = staging / CASE_FILE
        case_file.write_text(case.to_toml())
        past = NOT_TRACED if descent is None else json.dumps(asdict(descent))
        cmd = child_command("yadearch.dem.load_simulate", str(case_file), str(staging), repr(after_mm), past)
        env = child_environment(case.numerics.threads)
        try:
            returncode, stderr = run_child(cmd, env, timeout_s, quiet)
        except subprocess.TimeoutExpired:
            raise RunFailedError(f"the load path of {case.name!r} timed out after {timeout_s:.0f} s") from None
        if returncode != 0 or not load_path_file(staging, case.name, ".json").is_file():
            lines = [line for line in stderr.splitlines() if line.startswith("error: ")]
            reason = lines[-1].removeprefix("error: ") if lines else exit_reason(returncode)
            log = load_path_file(out, case.name, ".log")
            if load_path_file(staging, case.name, ".log").is_file():
                shutil.copy(load_path_file(staging, case.name, ".log"), log)
            raise RunFailedError(f"the load path of {case.name!r} failed: {reason} (see {log})")
        swap_into_place(load_path_file(staging, case.name), load_path_file(out, case.name))  # its states
        for suffix in LOAD_PATH_FILES:
            os.replace(load_path_file(staging, case.name, suffix), load_path_file(out, case.name, suffix))
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return read_load_path(out, case.name)
