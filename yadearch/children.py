"""How yadearch starts its child processes (the static engine's workers, a DEM run): on this process's
own copy of the package. `python -m` puts the working folder first on a child's path, so a campaign
started in one checkout beside another installed copy would solve its runs with the other's code."""

from __future__ import annotations

import os
import sys
from pathlib import Path

PACKAGE_ROOT = str(Path(__file__).resolve().parent.parent)  # the folder that holds this yadearch


def child_command(module: str, *args: str) -> list[str]:
    """`python -P -m module args`: no working folder on the child's path (-P), this package first on
    it (`child_environment`)."""
    return [sys.executable, "-P", "-m", module, *args]


def child_environment(threads: int) -> dict[str, str]:
    """This process's environment for a child: this package's folder first on PYTHONPATH, and
    `threads` BLAS and OpenMP threads."""
    path = [PACKAGE_ROOT, *filter(None, [os.environ.get("PYTHONPATH")])]
    return dict(os.environ, OMP_NUM_THREADS=str(threads), PYTHONPATH=os.pathsep.join(path))
