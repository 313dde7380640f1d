"""Where campaign runs execute: local worker threads (each waits on its own simulation process) or a
dask.distributed cluster. Both are standard `concurrent.futures.Executor`s; no scheduler of our own."""

from __future__ import annotations

import os
from collections.abc import Iterator
from concurrent.futures import Executor, ThreadPoolExecutor
from contextlib import contextmanager
from dataclasses import dataclass

from yadearch.errors import YadearchError
from yadearch.launch.process import stop_children


@dataclass
class Pool:
    """An executor and how many runs it executes at once (for the progress bar's `running`)."""

    executor: Executor
    slots: int
    where: str


@contextmanager
def local_pool(jobs: int | None = None) -> Iterator[Pool]:
    """`jobs` runs at once on this machine (default: one per core). Threads suffice: each run is a
    child process (`yadearch.process`), the thread only waits for it."""
    jobs = jobs or os.cpu_count() or 1
    if jobs < 1:
        raise YadearchError(f"--jobs must be >= 1, got {jobs}")
    executor = ThreadPoolExecutor(max_workers=jobs, thread_name_prefix="yadearch-run")
    try:
        yield Pool(executor, jobs, f"{jobs} local process{'es' if jobs > 1 else ''}")
    except BaseException:  # interrupted (Ctrl-C, SIGTERM): stop the running simulations, not wait for them
        stop_children()
        raise
    finally:
        executor.shutdown(wait=True, cancel_futures=True)


@contextmanager
def dask_pool(scheduler: str) -> Iterator[Pool]:
    """Runs on the dask.distributed cluster at `scheduler` (e.g. tcp://host:8786). The workers need
    yadearch and YADE installed and the campaign's output folder on a shared file system."""
    try:
        from distributed import Client
    except ImportError:
        raise YadearchError(
            "--scheduler needs dask.distributed: install the 'cluster' extra "
            "(pip install 'yadearch[cluster]') or Debian's python3-distributed"
        ) from None
    try:
        client = Client(scheduler, timeout="20s")
    except (OSError, TimeoutError) as exc:
        raise YadearchError(f"cannot reach the dask scheduler at {scheduler}: {exc}") from None
    try:
        slots = sum(client.nthreads().values()) or 1
        yield Pool(client.get_executor(pure=False), slots, f"dask cluster {scheduler} ({slots} slots)")
    finally:
        client.close()


@contextmanager
def open_pool(jobs: int | None = None, scheduler: str | None = None) -> Iterator[Pool]:
    """The dask cluster at `scheduler` if given, else `jobs` local processes."""
    if scheduler:
        with dask_pool(scheduler) as pool:
            yield pool
    else:
        with local_pool(jobs) as pool:
            yield pool
