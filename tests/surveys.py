"""Surveys for the tests: an arch's joints listed as a survey would list them, and a ring made thicker
toward its springings (tests/case/test_measured.py, tests/dem/test_measured_yade.py)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from yadearch.api.measured import JOINT_COLUMNS
from yadearch.case.config import ArchCase
from yadearch.case.mechanics import arch_geometry

HAUNCH_GROWTH = 0.5  # the ring at the springings is this much thicker than at the crown (24 -> 36 mm)


def surveyed_joints(case: ArchCase) -> pd.DataFrame:
    """The joints of `case`'s arch as a survey would list them (mm)."""
    rows = [[*(1e3 * j.intrados[:2]), *(1e3 * j.extrados[:2])] for j in arch_geometry(case).joints]
    return pd.DataFrame(rows, columns=list(JOINT_COLUMNS))


def thicker_at_the_haunches(case: ArchCase) -> pd.DataFrame:
    """`case`'s joints with each extrados corner pushed out along its joint, the ring growing from the
    crown's thickness to HAUNCH_GROWTH more at the springings (non-uniform thickness, the same joints)."""
    joints = surveyed_joints(case)
    centre = joints[["x_intrados_mm"]].to_numpy().ravel()
    grow = 1.0 + HAUNCH_GROWTH * (np.abs(centre) / np.abs(centre).max())
    for axis in ("x", "y"):
        joints[f"{axis}_extrados_mm"] = joints[f"{axis}_intrados_mm"] + grow * (
            joints[f"{axis}_extrados_mm"] - joints[f"{axis}_intrados_mm"]
        )
    return joints


def surveyed_blocks(case: ArchCase, gap_mm: float = 0.0, seed: int = 0) -> dict:
    """`case`'s blocks as a survey of blocks would give them (mm): each voussoir's four corners, the two
    supports marked, in a shuffled order, each corner moved up to `gap_mm` at random (a survey's gaps)."""
    rng = np.random.default_rng(seed)
    polygons = [1e3 * b[: len(b) // 2, :2] for b in arch_geometry(case).blocks]
    blocks = [
        {"corners": (p + rng.uniform(-gap_mm, gap_mm, p.shape)).tolist()}
        | ({"support": "left"} if k == 0 else {"support": "right"} if k == len(polygons) - 1 else {})
        for k, p in enumerate(polygons)
    ]
    order = rng.permutation(len(blocks))
    return {"blocks": [blocks[k] for k in order]}
