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


def curved_extrados(case: ArchCase, corners_per_voussoir: int) -> dict:
    """`case`'s segmental arch as a survey of blocks whose voussoirs' extrados are arcs: each voussoir
    its four joint corners and `corners_per_voussoir` more on the extrados circle between them (mm), in
    order round the block (a curved extrados drawn as a polygon), the supports marked."""
    polygons = [1e3 * b[: len(b) // 2, :2] for b in arch_geometry(case).blocks]
    blocks = []
    for k, polygon in enumerate(polygons):
        if k in (0, len(polygons) - 1):
            blocks.append({"corners": polygon.tolist(), "support": "left" if k == 0 else "right"})
            continue
        a_in, b_in, b_out, a_out = polygon  # counter-clockwise, the extrados from right to left
        radius = np.linalg.norm(a_out)
        start, end = np.arctan2(b_out[1], b_out[0]), np.arctan2(a_out[1], a_out[0])
        angles = start + (end - start) * np.arange(1, corners_per_voussoir + 1) / (corners_per_voussoir + 1)
        arc = radius * np.column_stack([np.cos(angles), np.sin(angles)])
        blocks.append({"corners": [a_in.tolist(), b_in.tolist(), b_out.tolist(), *arc.tolist(), a_out.tolist()]})
    return {"blocks": blocks}
