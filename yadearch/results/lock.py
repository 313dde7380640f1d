"""One writer per folder: an exclusive lock (flock) on a hidden file beside a run or campaign folder,
taken before anything is written and refused at once, naming the holder, when another process
holds it; the kernel releases it when its holder ends, however it ends."""

from __future__ import annotations

import contextlib
import fcntl
import os
from collections.abc import Iterator
from pathlib import Path

from yadearch.errors import YadearchError

LOCK_SUFFIX = ".lock"


class FolderBusyError(YadearchError):
    """Another process is writing the folder."""


def lock_path(folder: Path) -> Path:
    """The lock file of `folder`: hidden, beside it (the folder itself may be swapped while locked)."""
    return folder.parent / f".{folder.name}{LOCK_SUFFIX}"


@contextlib.contextmanager
def folder_lock(folder: Path, what: str = "run") -> Iterator[None]:
    """Hold the lock of `folder` for the duration of the block; FolderBusyError if another process
    holds it. The lock file is removed on the way out."""
    path = lock_path(Path(folder))
    path.parent.mkdir(parents=True, exist_ok=True)
    handle = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.pread(handle, 64, 0).decode(errors="replace").strip() or "unknown"
            raise FolderBusyError(
                f"{folder} is in use by another {what} (process {holder}); wait for it to end or choose another --out"
            ) from None
        os.ftruncate(handle, 0)
        os.pwrite(handle, f"{os.getpid()}\n".encode(), 0)
        try:
            yield
        finally:
            path.unlink(missing_ok=True)  # still held: a process that opens it now gets a new file
    finally:
        os.close(handle)
