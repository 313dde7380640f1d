"""Launch one simulation in its own Python process and report its outcome."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

from yadearch.case.config import ArchCase
from yadearch.engine.yade_env import YADE_PY_DIRS
from yadearch.errors import RunFailedError, YadeMissingError
from yadearch.results.rundir import LOG_FILE, SUMMARY_FILE


def check_yade_installed() -> None:
    """Fail early, in one line, when Debian's YADE is not installed."""
    if not any(Path(d, "yade", "__init__.py").is_file() for d in YADE_PY_DIRS):
        raise YadeMissingError("YADE is not installed (no yade package under "
                               f"{' or '.join(YADE_PY_DIRS)}); run `sudo apt-get install -y yade` "
                               "or `bash scripts/setup.sh`")


def exit_reason(returncode: int) -> str:
    """A child's exit status in words: a negative code is the signal that ended it."""
    if returncode < 0:
        try:
            return f"killed by {signal.Signals(-returncode).name}"
        except ValueError:
            return f"killed by signal {-returncode}"
    return f"exit code {returncode}"


def run_case_process(case: ArchCase, out: Path, timeout_s: float | None = None,
                     quiet: bool = False) -> Path:
    """Run `case` in a child process writing `out`; raise RunFailedError with the reason if it fails."""
    check_yade_installed()
    out.mkdir(parents=True, exist_ok=True)
    case_file = out / "case.toml"
    case_file.write_text(case.to_toml())
    (out / SUMMARY_FILE).unlink(missing_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=str(case.numerics.threads))
    cmd = [sys.executable, "-m", "yadearch.engine.simulate", str(case_file), str(out)]
    try:
        proc = subprocess.run(cmd, env=env, timeout=timeout_s, text=True,
                              stdout=subprocess.DEVNULL if quiet else None, stderr=subprocess.PIPE)
    except subprocess.TimeoutExpired:
        raise RunFailedError(f"run {case.name!r} timed out after {timeout_s:.0f} s") from None
    if proc.returncode != 0 or not (out / SUMMARY_FILE).is_file():
        lines = [line for line in proc.stderr.splitlines()
                 if line.strip() and not line.startswith(("Using python", "<WARNING>"))]
        reason = lines[-1] if lines else exit_reason(proc.returncode)
        raise RunFailedError(f"run {case.name!r} failed: {reason} (see {out / LOG_FILE})")
    return out
