"""Import YADE as a library (never through the `yade` launcher, which opens network ports)."""

from __future__ import annotations

import atexit
import contextlib
import os
import shutil
import signal
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

from yadearch.errors import YadeMissingError

YADE_PY_DIRS = ("/usr/lib/x86_64-linux-gnu/yade-double/py", "/usr/lib/x86_64-linux-gnu/yade/py")
DEBIAN_NUMPY_MAJOR = 1  # Debian 12's YADE is built against its numpy 1.24: an interpreter on numpy 2 cannot load it


def yade_problem() -> str | None:
    """Why this interpreter cannot run Debian's YADE, in one line; None if it can (its package is
    installed and this Python's numpy is the 1.x it was built against)."""
    if not any(Path(d, "yade", "__init__.py").is_file() for d in YADE_PY_DIRS):
        return (
            f"YADE is not installed (no yade package under {' or '.join(YADE_PY_DIRS)}); run "
            "`sudo apt-get install -y yade` or `bash scripts/setup.sh`"
        )
    import numpy

    if int(numpy.__version__.split(".")[0]) != DEBIAN_NUMPY_MAJOR:
        return (
            f"this Python ({sys.executable}) has numpy {numpy.__version__}; Debian's YADE needs Debian's numpy "
            "1.24: run DEM cases from the venv `bash scripts/setup.sh` makes (the static engine and the limit "
            "analysis run here)"
        )
    return None


def import_yade(threads: int = 1) -> ModuleType:
    """Import YADE with `threads` OpenMP threads and its polyhedra chatter silenced.

    OMP_NUM_THREADS must be set before the first import, so call this before anything imports YADE.
    """
    os.environ.setdefault("OMP_NUM_THREADS", str(threads))
    for path in YADE_PY_DIRS:
        if os.path.isdir(path) and path not in sys.path:
            sys.path.insert(0, path)
    # YADE makes /tmp/yade-XXXXXX at import and never removes it: a signal is held until its removal at
    # exit is registered, so that no interrupted import leaves one behind
    held = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        with _stdout_silenced():  # YADE prints "Using python version: ..." to stdout at import
            import yade  # noqa: F401  (registers the C++ classes)
            import yade.log
        atexit.register(shutil.rmtree, scratch_folder(), ignore_errors=True)
    except ImportError as exc:
        raise YadeMissingError(
            f"YADE is not importable from {sys.executable} ({exc}); on Debian run "
            "`sudo apt-get install -y yade` and use /usr/bin/python3 or a venv with "
            "--system-site-packages (see README)"
        ) from None
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)
    yade.log.setLevel("Polyhedra_support.cpp", yade.log.ERROR)
    return yade


def scratch_folder() -> Path:
    """The temporary folder YADE made for this process (/tmp/yade-XXXXXX, fixed in libyade, not
    TMPDIR), which YADE leaves behind: removed at exit, or by the parent of a killed simulation."""
    from yade import O

    return Path(O.tmpFilename()).parent


@contextlib.contextmanager
def _stdout_silenced() -> Iterator[None]:
    """Point file descriptor 1 at /dev/null for the block (C++ writes bypass sys.stdout)."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        with open(os.devnull, "w") as devnull:
            os.dup2(devnull.fileno(), 1)
            yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(saved)


def yade_version() -> str:
    """The version string of the importable YADE, or 'unavailable'."""
    try:
        import_yade()
        import yade.config

        return str(yade.config.version)
    except YadeMissingError:
        return "unavailable"
