"""Where static runs execute: long-lived worker processes (`python -m yadearch.static.pool`), up to one
per core, each importing numpy, numba's cached kernels and yadearch once and then solving one case
after another. A static run lasts about a second; a fresh interpreter per run would cost as much
again (a DEM run keeps its own process: YADE has one global scene per interpreter). Workers are plain
child processes fed one line per run, or one line per batch of runs that keep no folder (a lean
campaign: one answer line per run, as it ends), so a script or notebook that starts runs is never
re-imported in them (as multiprocessing's spawn would)."""

from __future__ import annotations

import contextlib
import io
import json
import os
import queue
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

from yadearch.children import child_command, child_environment

WORKER_ENDED = "the static engine's worker process ended"
PROC_UTIME, PROC_STIME = 11, 12  # /proc/PID/stat's CPU ticks, counted after the command's name
STOPPED = (-signal.SIGTERM, -signal.SIGINT)  # a worker stopped by `stop_workers` or a Ctrl-C: runs left pending
_idle: queue.LifoQueue[subprocess.Popen] = queue.LifoQueue()
_all: set[subprocess.Popen] = set()
_lock = threading.Lock()


def _worker() -> subprocess.Popen:
    """An idle worker, or a new one."""
    try:
        worker = _idle.get_nowait()
        if worker.poll() is None:
            return worker
    except queue.Empty:
        pass
    env = child_environment(threads=1)  # one BLAS thread a worker: the cores go to the workers
    worker = subprocess.Popen(
        child_command("yadearch.static.pool"),
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
        env=env,
        start_new_session=True,
    )  # a terminal's Ctrl-C stops the caller, which stops it
    with _lock:
        _all.add(worker)
    return worker


def _answer(worker: subprocess.Popen, timeout_s: float | None) -> str:
    """The worker's one-line answer, waited for at most `timeout_s` (TimeoutExpired): one that came
    later is over the timeout too, though a busy machine woke the waiting thread after it came."""
    box: list[str] = []
    reader = threading.Thread(target=lambda: box.append(worker.stdout.readline() if worker.stdout else ""), daemon=True)
    start = time.monotonic()
    reader.start()
    reader.join(timeout_s)
    if reader.is_alive() or (timeout_s is not None and time.monotonic() - start > timeout_s):
        raise subprocess.TimeoutExpired(["static engine"], timeout_s or 0.0)
    return box[0]


def run_static(case_file: Path, staging: Path, timeout_s: float | None) -> tuple[int, str]:
    """Solve the case file into the staging folder in a worker; the exit code and standard error of
    `yadearch.static.simulate` (subprocess.TimeoutExpired after `timeout_s`, the worker stopped)."""
    worker = _worker()
    try:
        assert worker.stdin is not None
        worker.stdin.write(json.dumps([str(case_file), str(staging)]) + "\n")
        worker.stdin.flush()
        line = _answer(worker, timeout_s)
    except (subprocess.TimeoutExpired, KeyboardInterrupt):
        _stop(worker)  # nothing may go on writing the staging folder once its caller has stopped
        raise
    except (BrokenPipeError, OSError):
        _stop(worker)
        return 1, WORKER_ENDED
    if not line:  # the worker died (killed, or out of memory)
        code = worker.wait()
        _stop(worker)
        return code if code else 1, WORKER_ENDED
    _idle.put(worker)
    code, stderr = json.loads(line)
    return int(code), str(stderr)


def solve_batch(cases: list[dict[str, Any]], timeout_s: float | None) -> list[dict[str, Any]]:
    """Solve cases (`ArchCase.to_dict()`) in a worker, no run folder written: per case its summary
    ({"summary": summary.json's object}), its failure ({"error": reason, "wall_s": seconds}) or, once
    the worker was stopped, {"interrupted": reason}. A case over `timeout_s`, or one its worker died
    under, fails; the rest go on in a new worker."""
    results: list[dict[str, Any]] = []
    while len(results) < len(cases):
        rest = cases[len(results) :]
        worker = _worker()
        try:
            assert worker.stdin is not None
            worker.stdin.write(json.dumps({"cases": rest}) + "\n")
            worker.stdin.flush()
            for _ in rest:
                line = _answer(worker, timeout_s)
                if not line:
                    break
                results.append(json.loads(line))
        except ValueError:  # not an answer line (something written past the capture): that run fails
            _stop(worker)
            results.append({"error": f"{WORKER_ENDED} (an unreadable answer)"})
            continue
        except subprocess.TimeoutExpired:
            _stop(worker)
            results.append({"error": f"timed out after {timeout_s:.0f} s"})
            continue
        except KeyboardInterrupt:
            _stop(worker)
            raise
        except OSError:  # a broken pipe: the worker died, said below
            pass
        if len(results) == len(cases):
            _idle.put(worker)
            break
        code = worker.wait()  # the worker died: stopped (the rest left pending), or killed under a run
        _stop(worker)
        if code in STOPPED:
            results += [{"interrupted": f"{WORKER_ENDED} (signal {-code})"}] * (len(cases) - len(results))
        else:
            ended = f"exit code {code}" if code >= 0 else f"killed by signal {-code}"
            results.append({"error": f"{WORKER_ENDED} ({ended})"})
    return results


def _stop(worker: subprocess.Popen) -> None:
    worker.kill()
    worker.wait()
    with _lock:
        _all.discard(worker)


def workers_cpu_s() -> float:
    """The CPU seconds (user and system) the live workers have used so far (Linux's /proc)."""
    ticks = os.sysconf("SC_CLK_TCK")
    with _lock:
        workers = list(_all)
    total = 0.0
    for worker in workers:
        with contextlib.suppress(OSError):  # a worker that just ended
            fields = Path(f"/proc/{worker.pid}/stat").read_text().rsplit(")", 1)[1].split()
            total += (int(fields[PROC_UTIME]) + int(fields[PROC_STIME])) / ticks
    return total


def stop_workers() -> None:
    """Stop every worker now (an interrupted campaign); later runs start new ones: the idle ones are
    taken out of the queue first, so that none is handed out while its SIGTERM is on its way."""
    with _lock:
        workers = list(_all)
        while True:
            try:
                _idle.get_nowait()
            except queue.Empty:
                break
    for worker in workers:
        worker.terminate()


def serve() -> None:
    """The worker's loop: one JSON line [case_file, staging] in, one [exit code, stderr] out; or one
    line {"cases": [...]} in, one line per case out (`solve_batch`)."""
    from yadearch.static.simulate import main

    for line in sys.stdin:
        request = json.loads(line)
        if isinstance(request, dict):
            for case in request["cases"]:
                sys.stdout.write(_answer_line(_solve(case)) + "\n")
                sys.stdout.flush()
            continue
        case_file, staging = request
        errors = io.StringIO()
        with contextlib.redirect_stderr(errors), contextlib.redirect_stdout(io.StringIO()):
            try:
                code = main([case_file, staging])
            except OSError as exc:  # a full disk or a vanished folder: said, and the worker serves on
                code = 1
                print(f"error: cannot write the run folder {exc.filename or staging}: {exc.strerror}", file=sys.stderr)
        sys.stdout.write(json.dumps([code, errors.getvalue()]) + "\n")
        sys.stdout.flush()


def _answer_line(answer: dict[str, Any]) -> str:
    """A batch run's answer as one JSON line; a summary that cannot be written so fails that run only."""
    try:
        return json.dumps(answer, default=_plain)
    except (TypeError, ValueError) as exc:
        return json.dumps({"error": f"internal error: the run's summary is not JSON: {exc}".splitlines()[0]})


def _solve(data: dict[str, Any]) -> dict[str, Any]:
    """One case of a batch solved in this worker: its summary or why it failed (one line)."""
    from yadearch.case.config import case_from_dict
    from yadearch.errors import YadearchError
    from yadearch.static.simulate import simulate_static

    started = time.time()
    try:  # anything the engine prints must not reach the answer lines on standard output
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            return {"summary": simulate_static(case_from_dict(data), None, log=lambda _: None).to_json()}
    except YadearchError as exc:
        reason = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    except Exception as exc:  # noqa: BLE001 - a defect of the engine fails this run, not the campaign
        reason = f"internal error: {type(exc).__name__}: {exc}".splitlines()[0]
    return {"error": reason, "wall_s": time.time() - started}


def _plain(value: Any) -> Any:
    """A numpy number or array as JSON takes it."""
    return value.tolist() if hasattr(value, "tolist") else value.item()


if __name__ == "__main__":
    serve()
