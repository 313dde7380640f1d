"""Shared fixtures: small real YADE scenes of a few blocks."""

from __future__ import annotations

import os

# tests run YADE in this process: numpy's OpenBLAS must start with one thread, or its idle worker
# spins on the second core (beside another run, 300-500 steps/s instead of 3 600-5 400)
os.environ.setdefault("OMP_NUM_THREADS", "1")

from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from yadearch.dem.yade_env import yade_problem  # noqa: E402

REPO = Path(__file__).resolve().parents[1]  # the project's root, for tests in any sub-folder
DATA = Path(__file__).resolve().with_name("data")  # reference arrays written by earlier code
HAS_YADE = yade_problem() is None  # Debian's YADE, and the numpy 1.x it was built against
needs_yade = pytest.mark.skipif(not HAS_YADE, reason="no YADE this interpreter can load (Debian's yade, numpy 1.x)")


def box(x0: float, x1: float, y0: float, y1: float, depth: float) -> np.ndarray:
    """Prism vertices of an axis-aligned x-y rectangle extruded over `depth` along z."""
    h = depth / 2
    front = [(x0, y0, -h), (x1, y0, -h), (x1, y1, -h), (x0, y1, -h)]
    return np.array(front + [(x, y, h) for x, y, _ in front])


def stacked_pairs(offsets_x: list[float], width: float, height: float, depth: float, overlap: float = 0.0):
    """For each x offset, a base block under y = 0 and a top block above it pressed down by
    `overlap`; returns an ArchGeometry-like assembly with one horizontal joint per pair."""
    from yadearch.model.geometry import ArchGeometry, Joint

    blocks, joints = [], []
    for k, x in enumerate(offsets_x):
        blocks.append(box(x - width / 2, x + width / 2, -height, 0.0, depth))
        blocks.append(box(x - width / 2, x + width / 2, -overlap, height - overlap, depth))
        joints.append(
            Joint(
                k + 1,
                2 * k,
                2 * k + 1,
                np.array([x - width / 2, 0.0]),
                np.array([x + width / 2, 0.0]),
                np.array([0.0, 1.0]),
            )
        )
    return ArchGeometry(
        blocks,
        joints,
        thickness=width,
        depth=depth,
        span=offsets_x[-1] - offsets_x[0] + width,
        rise=height,
        voussoir_width=height,
        longest_joint=width,
    )


def differenced_tangent(arch, u: np.ndarray, u_before: np.ndarray, shear: np.ndarray, step: float, **loads):
    """K = -dR/du of a static arch's free blocks at `u` by central differences of its residual (`loads`:
    free_state's gravity and multiplier), the oracle of the compiled tangent."""
    columns = []
    for k in arch.free_dofs:
        up, down = u.copy(), u.copy()
        up[k] += step
        down[k] -= step
        forward = arch.free_state(up, u_before, shear, **loads)[1]
        backward = arch.free_state(down, u_before, shear, **loads)[1]
        columns.append(-(forward - backward) / (2.0 * step))
    return np.column_stack(columns)
