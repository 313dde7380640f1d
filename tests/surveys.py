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
