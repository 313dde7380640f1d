"""The DEM's loading path locates a snap's fold as the static engine does (docs/numerics.md,
"Collapse"): a relaxation that snaps is not taken as it comes; the fold is bisected to the path's
tolerance and the snap made from just past it. A state the hold calls an equilibrium but the static
model moves is held on. Fake live arches, no YADE."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np
import pytest

from yadearch.case.config import preset
from yadearch.dem.loading import EquilibriumPath
from yadearch.solve.path import PathSettings
from yadearch.solve.stages import Stage, Verdict

FOLD = 0.03137  # where the fake arch's branch ends (m)
JUMP = 0.004  # how far its blocks move when it snaps to the next branch (m)
CREEP = 0.05  # a block moves this x the increment in a quasi-static relaxation
SETTINGS = PathSettings(first_increment=0.001, max_increment=0.0025, growth=1.5, tolerance=1e-4, max_displacement=0.05)


class FakeRecorder:
    def __init__(self) -> None:
        self.marks = 0

    def record_equilibrium(self) -> tuple[tuple[int, int, int], list]:
        self.marks += 1
        return (self.marks, 0, 0), []

    def discard_since(self, mark: tuple[int, int, int]) -> None:
        pass

    def record_collapse(self) -> list:
        return []


class SnappingArch:
    """One support coordinate and a branch: a relaxation that crosses FOLD from the first branch
    moves a block by JUMP (wherever the move ended), any other by CREEP x its increment."""

    def __init__(self) -> None:
        self.case = preset("set2")
        self.stage = Stage.INCREMENT
        self.recorder = FakeRecorder()
        self.log = lambda line: None
        self.total_steps = 0
        self.hold_move = 0.0
        self.position, self.branch, self._from = 0.0, 0, 0.0
        self.snaps_made_at: list[float] = []  # where each snap's move ended

    def smallest_stiffness(self) -> float:
        return 1.0

    def static_distance(self) -> float | None:
        return None  # no static model: the hold's verdict alone

    def path_positions(self) -> np.ndarray:
        return np.array([[self.branch * JUMP, 0.0, 0.0]])

    def reach(self, increment: float) -> float:
        return abs(increment)

    def yield_fill(self) -> None:
        pass  # no fill

    def branch_start(self) -> tuple[np.ndarray, np.ndarray | None]:
        return self.path_positions(), None  # a support movement's: no prediction from one state

    def delta(self) -> float:
        return self.position

    def snapshot(self) -> dict[str, Any]:
        return {"position": self.position, "branch": self.branch}

    def restore(self, snapshot: dict[str, Any]) -> None:
        self.position, self.branch = snapshot["position"], snapshot["branch"]

    def move_support(self, target: float, speed_fraction: float) -> None:
        self._from, self.position = self.position, target

    def hold(self, **_: Any) -> Verdict:
        if self.branch == 0 and self.position >= FOLD:
            self.branch, self.hold_move = 1, JUMP
            self.snaps_made_at.append(self.position)
        else:
            self.hold_move = CREEP * abs(self.position - self._from)
        return Verdict.STABLE


def assert_one_snap_located(path: EquilibriumPath, move: float) -> tuple[float, float]:
    """The path made one snap, of `move` (m), its fold bracketed across FOLD to the path's tolerance
    (not the increment's 2.5 mm) and the first loss of stability there; the bracket (m)."""
    assert len(path.snaps) == 1
    low, high = (x / 1e3 for x in path.snaps[0]["fold_mm"])
    assert low < FOLD <= high and high - low <= SETTINGS.tolerance
    assert path.snaps[0]["move_mm"] == pytest.approx(move * 1e3, rel=1e-6)
    assert path.first_loss == pytest.approx((low, high))
    return low, high


def test_a_snap_is_made_from_its_fold_located_to_the_paths_tolerance():
    arch = SnappingArch()
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    path.follow()
    _, high = assert_one_snap_located(path, JUMP)
    assert arch.snaps_made_at[-1] == pytest.approx(high)  # the branch taken from just past the fold


def test_a_relative_bracket_locates_the_fold_to_its_share_of_the_folds_position():
    """numerics.du_tolerance_ratio: the DEM bisects a fold at 31 mm to 0.1 % of it (0.031 mm), not to the
    0.1 mm of `tolerance` alone, as the static engine does (`PathSettings.bracket`)."""
    relative = replace(SETTINGS, relative_tolerance=0.001)
    path = EquilibriumPath(SnappingArch(), relative)  # type: ignore[arg-type]
    path.follow()
    low, high = assert_one_snap_located(path, JUMP)
    assert high - low <= relative.relative_tolerance * high < SETTINGS.tolerance


def test_a_path_without_snaps_is_not_bisected():
    arch = SnappingArch()
    arch.branch = 1  # already on the last branch: every relaxation creeps
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    result = path.follow()
    assert path.snaps == [] and path.first_loss is None
    assert len(result.steps) == len(result.equilibria) < 25  # one relaxation an increment


class NearEquilibriumArch(SnappingArch):
    """Past FOLD on the first branch a hold from rest stops at once (slow and balanced: the DEM's
    near-equilibrium) though the static model moves the blocks JUMP; a hold that goes on snaps to
    the next branch, unless `stuck`."""

    def __init__(self, stuck: bool = False) -> None:
        super().__init__()
        self.stuck = stuck

    def static_distance(self) -> float | None:
        return JUMP if self.branch == 0 and self.position >= FOLD else 0.0

    def hold(self, from_rest: bool = True, **_: Any) -> Verdict:
        if self.branch == 0 and self.position >= FOLD and not from_rest and not self.stuck:
            self.branch, self.hold_move = 1, JUMP
            self.snaps_made_at.append(self.position)
        else:
            self.hold_move = CREEP * abs(self.position - self._from) if from_rest else 0.0
        return Verdict.STABLE


def test_a_near_equilibrium_the_static_model_moves_is_held_on_and_its_snap_located():
    arch = NearEquilibriumArch()
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    path.follow()
    assert path.relaxations["off_equilibrium"]  # held on where the hold alone said 'stable'
    assert_one_snap_located(path, JUMP)


def test_a_state_the_static_model_keeps_moving_is_unresolved_not_accepted():
    arch = NearEquilibriumArch(stuck=True)
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    result = path.follow()
    assert result.unresolved and not result.collapsed
    assert max(path.relaxations["delta_mm"]) < FOLD * 1e3  # nothing past the fold was accepted


SHORT_JUMP = 0.0012  # a short snap made during the move: 1.2 mm, more than 0.01 ring thickness (0.45 mm)


class MoveSnappingArch(SnappingArch):
    """Its blocks follow the support (CREEP x its position) and snap by SHORT_JUMP during the move that
    crosses FOLD, so the hold that follows finds them at rest: only the branch's trend tells the snap."""

    def path_positions(self) -> np.ndarray:
        return np.array([[CREEP * self.position + self.branch * SHORT_JUMP, 0.0, 0.0]])

    def move_support(self, target: float, speed_fraction: float) -> None:
        super().move_support(target, speed_fraction)
        if self.branch == 0 and self.position >= FOLD:
            self.branch = 1
            self.snaps_made_at.append(self.position)

    def hold(self, **_: Any) -> Verdict:
        self.hold_move = 0.0  # at rest already: the snap happened during the move
        return Verdict.STABLE


def test_a_snap_made_during_the_move_is_told_by_the_branchs_trend_and_located():
    arch = MoveSnappingArch()
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    path.follow()
    assert_one_snap_located(path, SHORT_JUMP)  # not the increment that hid it


def test_a_branch_followed_without_snaps_keeps_to_its_trend():
    arch = MoveSnappingArch()
    arch.branch = 1  # already on the last branch: the blocks follow the support smoothly
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    result = path.follow()
    assert path.snaps == [] and len(result.steps) == len(result.equilibria) < 25


EARLY_FOLD = 0.0004  # a fold inside the first increment (1 mm), where a branch is known by one state


class SoftFirstSnapArch(MoveSnappingArch):
    """A live load's path on a soft arch: the blocks follow the parameter (CREEP), snap by SHORT_JUMP at
    EARLY_FOLD during the first move, and a relaxation may move them as far as its increment allows over
    a small stiffness (reach unbounded), so only a prediction from the first state tells the snap: the
    static model's tangent (`branch_start`'s slope, CREEP), or none (`tangent` false)."""

    def __init__(self, tangent: bool) -> None:
        super().__init__()
        self.tangent = tangent

    def reach(self, increment: float) -> float:
        return float("inf")

    def branch_start(self) -> tuple[np.ndarray, np.ndarray | None]:
        return self.path_positions(), np.array([[CREEP, 0.0, 0.0]]) if self.tangent else None

    def move_support(self, target: float, speed_fraction: float) -> None:
        SnappingArch.move_support(self, target, speed_fraction)
        if self.branch == 0 and self.position >= EARLY_FOLD:
            self.branch = 1
            self.snaps_made_at.append(self.position)


@pytest.mark.parametrize("tangent", [True, False])
def test_a_snap_in_the_first_increment_is_told_by_the_tangent_at_the_first_state(tangent):
    """Without a prediction from the first state the snap hides in the first increment (the DEM's live-load
    path before the static model's tangent gave its trends a slope, docs/loads.md); with it, located."""
    arch = SoftFirstSnapArch(tangent)
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    path.follow()
    if not tangent:
        assert path.snaps == []
        return
    assert len(path.snaps) == 1
    low, high = (x / 1e3 for x in path.snaps[0]["fold_mm"])
    assert low < EARLY_FOLD <= high and high - low <= SETTINGS.tolerance
    assert path.snaps[0]["move_mm"] == pytest.approx(SHORT_JUMP * 1e3, rel=1e-6)


class CreepingAwayArch(SnappingArch):
    """Past FOLD no stable equilibrium is near (the static model's distance inf), yet every hold that may
    end at rest finds the blocks slower than its test: they leave only in a hold that lasts its whole
    time (still_speed 0), as a state past a fold leaves it exponentially slowly."""

    def static_distance(self) -> float | None:
        return float("inf") if self.position >= FOLD else 0.0

    def hold(self, still_speed: float | None = None, **_: Any) -> Verdict:
        self.hold_move = 0.0
        if self.position >= FOLD and still_speed == 0.0:
            return Verdict.RUNAWAY
        return Verdict.STABLE


def test_a_state_with_no_equilibrium_near_is_held_through_until_it_runs_away():
    arch = CreepingAwayArch()
    path = EquilibriumPath(arch, SETTINGS)  # type: ignore[arg-type]
    result = path.follow()
    assert result.collapsed and not result.unresolved
    assert result.du == pytest.approx(FOLD, abs=SETTINGS.tolerance)
    assert [delta for delta, move in path.relaxations["off_equilibrium"] if move is None]  # recorded as such
