"""The per-interface history of a run along its quasi-static path, as record-by-interface arrays.

The path is the self-weight record, the equilibrium records of the loading (each accepted increment,
all below du) and the final record ("collapse": the runaway from the first state past du).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from yadearch.model.hinges import hinge_rotation
from yadearch.solve.stages import PATH_STAGES, Stage

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class JointHistory:
    """Arrays over records (rows, in path order) and interfaces (columns, interface k = column k-1).

    rotation: hinge rotation (rad, > 0 pivots about the intrados, see yadearch.hinges);
    opening_*: gap at the intrados / extrados edge (mm, > 0 open); forces in N.
    """

    stage: np.ndarray
    step: np.ndarray
    delta_mm: np.ndarray
    rotation: np.ndarray
    opening_intrados_mm: np.ndarray
    opening_extrados_mm: np.ndarray
    normal_force_N: np.ndarray
    shear_force_N: np.ndarray

    @property
    def n_records(self) -> int:
        return len(self.delta_mm)

    @property
    def n_interfaces(self) -> int:
        return self.rotation.shape[1]

    def hinge_opening_mm(self, record: int, interfaces: tuple[int, ...], side: str) -> float:
        """Largest gap over `interfaces` at the edge opposite the pivot (an I hinge opens at the
        extrados), clipped at 0: a compressed edge is not an opening."""
        gaps = self.opening_extrados_mm if side == "I" else self.opening_intrados_mm
        columns = [k - 1 for k in interfaces]
        return max(float(np.max(gaps[record, columns])), 0.0)


def path_records(joints: pd.DataFrame, du_mm: float | None) -> pd.DataFrame:
    """The rows of joints.csv on the quasi-static path, ordered: self-weight, the loading's
    equilibria (up to du when the arch collapsed), then the final collapse record."""
    rows = joints[joints["stage"].isin(PATH_STAGES)]
    if du_mm is not None and (rows["stage"] == Stage.COLLAPSE).any():
        rows = rows[(rows["stage"] != Stage.EQUILIBRIUM) | (rows["delta_mm"] <= du_mm)]
    order = rows["stage"].map({s: k for k, s in enumerate(PATH_STAGES)})
    return rows.assign(_order=order).sort_values(["_order", "step", "interface"], kind="stable")


def joint_history(joints: pd.DataFrame, joint_length_mm: float, du_mm: float | None) -> JointHistory:
    """Pivot joints.csv into a JointHistory along the quasi-static path."""
    rows = path_records(joints, du_mm)
    keys = ["_order", "step"]
    records = rows.drop_duplicates(keys)[keys + ["stage", "delta_mm"]]

    def table(column: str) -> np.ndarray:
        wide = rows.pivot(index=keys, columns="interface", values=column)
        return wide.loc[list(records[keys].itertuples(index=False, name=None))].to_numpy(float)

    intrados, extrados = table("opening_intrados_mm"), table("opening_extrados_mm")
    return JointHistory(
        stage=records["stage"].to_numpy(),
        step=records["step"].to_numpy(),
        delta_mm=records["delta_mm"].to_numpy(float),
        rotation=hinge_rotation(intrados, extrados, joint_length_mm),
        opening_intrados_mm=intrados,
        opening_extrados_mm=extrados,
        normal_force_N=table("normal_force_N"),
        shear_force_N=table("shear_force_N"),
    )
