"""Launch one simulation in its own Python process and report its outcome: YADE's, or the static
engine's (`yadearch.static`) for a case whose numerics.engine is 'static'."""

from __future__ import annotations

import contextlib
import io
import os
import shutil
import signal
import subprocess
import threading
from pathlib import Path

from yadearch.case.config import ArchCase
from yadearch.case.numerics_section import STATIC_ENGINE  # a run solved by the static engine (no YADE)
from yadearch.case.plan import plan_run
from yadearch.children import child_command, child_environment
from yadearch.dem.simulate import SCRATCH_RECORD
from yadearch.dem.yade_env import yade_problem
from yadearch.errors import RunFailedError, RunInterruptedError, YadearchError, YadeMissingError
from yadearch.results.lock import LOCK_SUFFIX, folder_lock
from yadearch.results.rundir import CASE_FILE, LOG_FILE, STAGING_PREFIX, STAGING_SUFFIX, is_complete, staging_folder
from yadearch.static.pool import run_static, stop_workers

REPLACED_SUFFIX = ".replaced"  # the previous folder NAME, for the moment of the swap
INTERRUPTED_CODES = (130, -signal.SIGINT, -signal.SIGTERM)  # the child's own exit code, or the signal
_children: set[subprocess.Popen] = set()  # the simulations this process waits on, from any thread
_children_lock = threading.Lock()


def stop_children() -> None:
    """Ask every simulation this process still waits on to stop (SIGTERM): an interrupted campaign
    then ends at once, each run recorded as interrupted and resumed by the next campaign."""
    with _children_lock:
        running = [proc for proc in _children if proc.poll() is None]
    for proc in running:
        proc.terminate()
    stop_workers()


def run_child(cmd: list[str], env: dict[str, str], timeout_s: float | None, quiet: bool) -> tuple[int, str]:
    """Run `cmd` to its end (killed after `timeout_s`: TimeoutExpired), known to `stop_children`
    meanwhile: its exit code and standard error."""
    # its own session: a terminal's Ctrl-C (SIGINT to the foreground group) reaches this process only,
    # which stops the simulation with SIGTERM, the signal it ends on cleanly, as interrupted
    proc = subprocess.Popen(
        cmd,
        env=env,
        text=True,
        stdout=subprocess.DEVNULL if quiet else None,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    with _children_lock:
        _children.add(proc)
    try:
        _, stderr = proc.communicate(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        raise
    except KeyboardInterrupt:
        proc.terminate()
        _, stderr = proc.communicate()
    finally:
        with _children_lock:
            _children.discard(proc)
    return proc.returncode, stderr


def check_yade_installed() -> None:
    """Fail early, in one line, when this interpreter cannot run Debian's YADE (`yade_env.yade_problem`)."""
    problem = yade_problem()
    if problem is not None:
        raise YadeMissingError(problem)


def exit_reason(returncode: int) -> str:
    """A child's exit status in words: a negative code is the signal that ended it."""
    if returncode < 0:
        try:
            return f"killed by {signal.Signals(-returncode).name}"
        except ValueError:
            return f"killed by signal {-returncode}"
    return f"exit code {returncode}"


def run_case_process(
    case: ArchCase, out: Path, timeout_s: float | None = None, quiet: bool = False, single: bool = False
) -> Path:
    """Run `case` in a child process and make `out` its run folder; raise RunFailedError with the
    reason if it fails. The child writes a staging folder beside `out`, swapped into place only
    when complete: a run that does not finish never destroys the finished run `out` may hold (its
    log then stays in the staging folder, which the error names). A `single` static run without a
    timeout is solved in this process instead (no worker to start and import: about a second)."""
    plan_run(case)  # refuse, before any process starts, a case that cannot run or would not end
    static = case.numerics.engine == STATIC_ENGINE
    if not static:
        check_yade_installed()
    out = Path(out)
    check_name_length(out)
    with folder_lock(out):
        return _run_locked(case, out, static, timeout_s, quiet, single and timeout_s is None)


def check_name_length(out: Path) -> None:
    """Refuse a run folder name too long for the names a run derives from it (staging folder, lock)."""
    extra = max(len(STAGING_PREFIX) + len(suffix) for suffix in (STAGING_SUFFIX, REPLACED_SUFFIX, LOCK_SUFFIX))
    parent = next((p for p in (out.parent, *out.parent.parents) if p.is_dir()), Path("."))
    limit = os.pathconf(parent, "PC_NAME_MAX") - extra
    if len(out.name) > limit:
        raise YadearchError(
            f"run folder name {out.name[:20]}... is {len(out.name)} characters; at most {limit} (the "
            f"file system's {limit + extra} less {extra} for the run's staging folder)"
        )


def _run_locked(
    case: ArchCase, out: Path, static: bool, timeout_s: float | None, quiet: bool, here: bool = False
) -> Path:
    """`run_case_process` once it holds the folder's lock (`here`: a static run in this process)."""
    staging = staging_folder(out)
    shutil.rmtree(staging, ignore_errors=True)
    staging.mkdir(parents=True)
    case_file = staging / CASE_FILE
    case_file.write_text(case.to_toml())
    env = child_environment(case.numerics.threads)
    cmd = child_command("yadearch.dem.simulate", str(case_file), str(staging))
    try:
        try:
            if static:
                returncode, stderr = (
                    _run_static_here(case_file, staging, quiet) if here else run_static(case_file, staging, timeout_s)
                )
            else:
                returncode, stderr = run_child(cmd, env, timeout_s, quiet)
        finally:
            _remove_scratch(staging)
    except subprocess.TimeoutExpired:
        where = _keep_failed(staging, out)
        raise RunFailedError(f"run {case.name!r} timed out after {timeout_s:.0f} s (see {where / LOG_FILE})") from None
    if returncode in INTERRUPTED_CODES:
        where = _keep_failed(staging, out)
        raise RunInterruptedError(
            f"run {case.name!r} was interrupted ({exit_reason(returncode)}); "
            f"run it again to resume (see {where / LOG_FILE})"
        )
    if returncode != 0 or not is_complete(staging):
        lines = [
            line for line in stderr.splitlines() if line.strip() and not line.startswith(("Using python", "<WARNING>"))
        ]
        reason = lines[-1].removeprefix("error: ") if lines else exit_reason(returncode)
        where = _keep_failed(staging, out)
        raise RunFailedError(f"run {case.name!r} failed: {reason} (see {where / LOG_FILE})")
    swap_into_place(staging, out)
    return out


def _run_static_here(case_file: Path, staging: Path, quiet: bool) -> tuple[int, str]:
    """`yadearch.static.simulate` on the case file in this process: its exit code and standard error
    (its progress printed unless `quiet`; run.log keeps it either way)."""
    from yadearch.static.simulate import main

    errors = io.StringIO()
    shown = contextlib.nullcontext() if not quiet else contextlib.redirect_stdout(io.StringIO())
    with contextlib.redirect_stderr(errors), shown:
        code = main([str(case_file), str(staging)])
    return code, errors.getvalue()


def _remove_scratch(staging: Path) -> None:
    """Remove the temporary folder YADE made for the simulation (a killed one could not)."""
    record = staging / SCRATCH_RECORD
    if record.is_file():
        scratch = Path(record.read_text().strip())
        if scratch.name.startswith("yade-"):
            shutil.rmtree(scratch, ignore_errors=True)
        record.unlink()


def _keep_failed(staging: Path, out: Path) -> Path:
    """Where a failed run's folder stays: at `out` unless `out` holds a finished run to protect."""
    if is_complete(out):
        return staging
    swap_into_place(staging, out)
    return out


def swap_into_place(staging: Path, out: Path) -> None:
    """Replace `out` by the `staging` folder (two renames; the old folder is removed after)."""
    previous = out.parent / f"{STAGING_PREFIX}{out.name}{REPLACED_SUFFIX}"
    shutil.rmtree(previous, ignore_errors=True)
    if out.exists():
        os.replace(out, previous)
    os.replace(staging, out)
    shutil.rmtree(previous, ignore_errors=True)
