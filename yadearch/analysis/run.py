"""A run folder's analysis in one object: history, hinges and their formation, mechanism, du."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from yadearch.analysis.blocks import case_geometry, tangential_slip_mm
from yadearch.analysis.history import JointHistory, joint_history
from yadearch.analysis.mechanism import (
    CAP_TOLERANCE,
    SLIP_THRESHOLD_MM,
    SlidingJoint,
    describe_mechanism,
    sliding_joints,
)
from yadearch.analysis.tracking import (
    MAX_JUMP_INTERFACES,
    OPENING_THRESHOLD_MM,
    ROTATION_THRESHOLD_MRAD,
    HingeTrack,
    formation_steps,
    hinge_table,
    sequence,
    track_hinges,
)
from yadearch.errors import YadearchError
from yadearch.results.rundir import RunFolder, read_run


@dataclass(frozen=True)
class Thresholds:
    """Every threshold of the analysis (defaults documented where they are defined)."""

    rotation_mrad: float = ROTATION_THRESHOLD_MRAD
    opening_mm: float = OPENING_THRESHOLD_MM
    cap_tolerance: float = CAP_TOLERANCE
    slip_mm: float = SLIP_THRESHOLD_MM
    max_jump: int = MAX_JUMP_INTERFACES


@dataclass
class RunAnalysis:
    """What a paper needs from one run: du, the hinges (labelled in order of formation), how they
    formed and migrated, sliding joints and the mechanism in words."""

    du_mm: float | None
    collapsed: bool
    history: JointHistory
    tracks: list[HingeTrack]
    hinges: pd.DataFrame
    sliding: list[SlidingJoint]
    mechanism: str
    thresholds: Thresholds

    @property
    def sequence(self) -> str:
        return sequence(self.tracks)

    @property
    def formation(self) -> list[tuple[str, float, str]]:
        """(label, delta at formation (mm), sequence so far), in order of formation."""
        return formation_steps(self.tracks, self.history.delta_mm)


def analyse_history(
    joints: pd.DataFrame,
    joint_length_mm: float,
    friction_deg: float,
    du_mm: float | None,
    collapsed: bool,
    slip_mm: np.ndarray | None = None,
    thresholds: Thresholds = Thresholds(),
    moving_support: str = "right",
) -> RunAnalysis:
    """Analyse a joints.csv table; `slip_mm` (per interface, final state) confirms sliding if given;
    the hinges' letters put C at the `moving_support`."""
    history = joint_history(joints, joint_length_mm, du_mm if collapsed else None)
    tracks = track_hinges(history, thresholds.rotation_mrad, thresholds.opening_mm, thresholds.max_jump, moving_support)
    sliding = sliding_joints(
        history.normal_force_N[-1],
        history.shear_force_N[-1],
        friction_deg,
        slip_mm,
        thresholds.cap_tolerance,
        thresholds.slip_mm,
    )
    return RunAnalysis(
        du_mm=du_mm,
        collapsed=collapsed,
        history=history,
        tracks=tracks,
        hinges=hinge_table(history, tracks, thresholds.rotation_mrad),
        sliding=sliding,
        mechanism=describe_mechanism(tracks, sliding, history.n_interfaces, collapsed),
        thresholds=thresholds,
    )


def load_run(path: str | Path) -> RunFolder:
    """Read a run folder; a path that is not one is a user mistake, reported in one line."""
    if not Path(path).is_dir():
        raise YadearchError(f"{path} is not a run folder (no such folder)")
    return read_run(path)  # says in one line what is wrong with an incomplete folder


def _final_slip_mm(run: RunFolder) -> np.ndarray | None:
    """Slip of every joint between the self-weight and the final snapshot (mm), if both exist."""
    final = run.snapshots.get("collapse") or run.snapshots.get("end")
    if final is None or "selfweight" not in run.snapshots:
        return None
    geometry = case_geometry(run.case)
    return tangential_slip_mm(geometry, final) - tangential_slip_mm(geometry, run.snapshots["selfweight"])


def default_thresholds(case: dict[str, Any]) -> Thresholds:
    """Thresholds with the run's own hinge rotation threshold, so hinges match its summary.json."""
    return Thresholds(rotation_mrad=case.get("numerics", {}).get("hinge_rotation_mrad", ROTATION_THRESHOLD_MRAD))


def analyse_run(run: RunFolder, thresholds: Thresholds | None = None) -> RunAnalysis:
    """Analyse a run folder read with `load_run` / `rundir.read_run`."""
    return analyse_history(
        run.joints,
        run.case["geometry"]["thickness_mm"],
        run.case["material"]["friction_deg"],
        run.summary.du_mm,
        run.summary.collapsed,
        _final_slip_mm(run),
        thresholds or default_thresholds(run.case),
        run.case.get("loading", {}).get("moving_support", "right"),
    )
